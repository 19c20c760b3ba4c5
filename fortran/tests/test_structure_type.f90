! SPDX-License-Identifier: GPL-3.0-or-later
! test_structure_type.f90 — type(fricreg_structure), the idiomatic layer over
! include/fricreg_structure.h:
!   - J in Fortran's order J(m, ndof): the two storeys of test_structure.f90 under a static
!     load stick with J^T f = -p, f = (-(p1 + p2), -p2) = (-0.319, 0.412), which a J passed
!     untransposed would not give;
!   - a three-DOF frame with two contacts (J 2 x 3), Rayleigh damping, ground motion and a
!     load record, run by HHT-alpha and by GSL's RK4 through the type and through the C API
!     (the thin layer): every number equal bit for bit, the same calls reaching the same C;
!   - its failures: sizes checked in Fortran (FRICREG_ESIZE naming the array, nothing
!     written), an object not created (FRICREG_ENULL), C's own refusals with C's message;
!   - its warnings (warning_count, get_warning): a ground record typed in g raises ground_peak;
!     a handler (set_warning_handler, a bind(C) subroutine) hears it once, message and all;
!   - an observer (a bind(C) function with interface fricreg_structure_observer) that stops
!     the run after 10 of its 100 steps, and the bound on run_ode's adaptive steps;
!   - the error estimate (set_error_estimate, get_peak_displacement, get_peak_displacement_error,
!     get_dissipation_error) on the frame's two runs, equal bit for bit to the C API's.
module step_watch
  use, intrinsic :: iso_c_binding
  implicit none
  real(c_double) :: watched_t = -1.0_c_double
  integer(c_size_t) :: watched_ndof = 0, watched_m = 0
  integer(c_int) :: heard_code = 0
  character(len=:), allocatable :: heard_message

contains

  !> A fricreg_structure_observer: counts its calls in the integer user points to, keeps t and
  !> the sizes, and stops the run after 10 steps.
  function stop_after_ten(user, t, ndof, u, v, m, f) bind(C) result(stop_run)
    type(c_ptr), value :: user
    real(c_double), value :: t
    integer(c_size_t), value :: ndof
    real(c_double), intent(in) :: u(ndof), v(ndof)
    integer(c_size_t), value :: m
    real(c_double), intent(in) :: f(m)
    integer(c_int) :: stop_run
    integer(c_int), pointer :: calls
    call c_f_pointer(user, calls)
    calls = calls + 1
    watched_t = t
    watched_ndof = ndof
    watched_m = m
    stop_run = merge(1_c_int, 0_c_int, calls >= 10)
  end function stop_after_ten

  !> A fricreg_warning_handler: counts its calls in the integer user points to, and keeps the
  !> code and message of ground_peak.
  subroutine hear_warning(code, message, user) bind(C)
    use fricreg, only: fricreg_c_string, FRICREG_WARN_GROUND_PEAK
    integer(c_int), value :: code
    type(c_ptr), value :: message
    type(c_ptr), value :: user
    integer(c_int), pointer :: heard
    call c_f_pointer(user, heard)
    heard = heard + 1
    if (code /= FRICREG_WARN_GROUND_PEAK) return
    heard_code = code
    heard_message = fricreg_c_string(message)
  end subroutine hear_warning

end module step_watch

program test_structure_type
  use fricreg
  use ftest
  use step_watch
  implicit none
  type(fricreg_structure) :: st
  real(c_double) :: M2(2, 2), K2(2, 2), J2(2, 2), f2(2), u2(2), v2(2)
  real(c_double) :: M(3, 3), K(3, 3), J(2, 3), mun(2), p(3), ag(200), g(50), u(3), v(3)
  real(c_double), parameter :: a0 = 0.0731_c_double, a1 = 0.00213_c_double
  real(c_double), parameter :: dt = 0.0137_c_double, t_end = 2.385_c_double
  integer(c_int64_t) :: count
  integer(c_int), target :: calls, heard
  real(c_double) :: t_now
  integer :: i, nwarn
  integer(c_int) :: wcode
  character(len=:), allocatable :: wmsg
  logical :: found
  real(c_double) :: tol8(8)

  ! ---- The static load: J(i, k) = d zdot_i / d u'_k, ground slip and inter-storey slip ----
  M2 = reshape([1.7_c_double, 0.0_c_double, 0.0_c_double, 0.9_c_double], [2, 2])
  K2 = reshape([30.2_c_double, -12.1_c_double, -12.1_c_double, 12.1_c_double], [2, 2])
  J2 = reshape([1.0_c_double, -1.0_c_double, 0.0_c_double, 1.0_c_double], [2, 2])
  call check_status(st%create(2, 2), FRICREG_OK, 'create 2, 2')
  call check(st%ndof() == 2 .and. st%ncontacts() == 2, 'ndof, ncontacts')
  call check_status(st%set_mass(M2), FRICREG_OK, 'set_mass')
  call check_status(st%set_stiffness(K2), FRICREG_OK, 'set_stiffness')
  call check_status(st%set_contacts(J2), FRICREG_OK, 'set_contacts(J)')
  call check_status(st%set_bounds([0.5_c_double, 0.6_c_double]), FRICREG_OK, 'set_bounds')
  call check_status(st%set_law(FRICREG_LAW_QUINN, 0.013_c_double), FRICREG_OK, 'set_law')
  call check_status(st%set_load([0.731_c_double, -0.412_c_double]), FRICREG_OK, 'constant load')
  call check_status(st%run(0.01_c_double, 1.0_c_double), FRICREG_OK, 'run')
  call check_status(st%get_state(u=u2, v=v2), FRICREG_OK, 'get_state u, v')
  call check(all(abs(u2) <= 1e-15_c_double) .and. all(abs(v2) <= 1e-15_c_double), 'no motion')
  call check_status(st%get_forces(f2), FRICREG_OK, 'get_forces')
  call check_close(f2(1), -0.319_c_double, 1e-13_c_double, 'f1 = -(p1 + p2)')
  call check_close(f2(2), 0.412_c_double, 1e-13_c_double, 'f2 = -p2')
  call check_status(st%get_stat(FRICREG_SSTAT_STEPS, count), FRICREG_OK, 'get_stat')
  call check(count == 100, '100 steps')

  ! ---- An observer that stops the run after 10 of its 100 steps; run_ode's bound -------------
  calls = 0
  call check_status(st%set_observer(stop_after_ten, c_loc(calls)), FRICREG_OK, 'set_observer')
  call check_status(st%run(0.01_c_double, 2.0_c_double), FRICREG_OK, 'a run the observer stops')
  call check(calls == 10, 'the observer saw 10 steps')
  call check(watched_ndof == 2 .and. watched_m == 2, 'the observer saw 2 DOFs and 2 contacts')
  call check_status(st%get_value(FRICREG_SVALUE_TIME, t_now), FRICREG_OK, 'get_value time')
  call check_close(t_now, watched_t, 0.0_c_double, 'the run stopped where the observer did')
  call check_close(t_now, 1.1_c_double, 1e-12_c_double, 'at t = 1 + 10 dt')
  call check_status(st%set_observer(), FRICREG_OK, 'remove the observer')
  call check_status(st%set_max_steps(-1_c_int64_t), FRICREG_EINVAL, 'set_max_steps -1')
  call check_status(st%set_max_steps(0_c_int64_t), FRICREG_OK, 'set_max_steps 0: no bound')

  ! ---- run_ode with rtol and no atol: the absolute tolerances from eps -----------------------
  ! y = (u(2), v(2), W_in, E_visc, D(2)): v_1 is read by contact 1 (row (1, 0), sum |J| = 1)
  ! and contact 2 (row (-1, 1), sum 2), v_2 by contact 2: both 1e-3 eps / 2 = 6.5e-6 (below
  ! the cap rtol = 1e-4), no relative part; the rest rtol.
  call check_status(st%get_ode_abs_tolerances(tol8), FRICREG_OK, 'get_ode_abs_tolerances')
  call check(all(tol8 == 0.0_c_double), 'zeros before an adaptive run_ode')
  call check_status(st%run_ode(FRICREG_INT_RKF45, 0.01_c_double, 1.2_c_double, &
                               rtol=1e-4_c_double), FRICREG_OK, 'run_ode rkf45, rtol only')
  call check_status(st%get_ode_abs_tolerances(tol8), FRICREG_OK, 'get_ode_abs_tolerances')
  call check(all(tol8 == [1e-4_c_double, 1e-4_c_double, 1e-3_c_double * 0.013_c_double / 2, &
                          1e-3_c_double * 0.013_c_double / 2, 1e-4_c_double, 1e-4_c_double, &
                          1e-4_c_double, 1e-4_c_double]), 'the rule from eps and J')
  call check_status(st%get_ode_abs_tolerances(tol8(1:7)), FRICREG_ESIZE, 'atol of 7')
  call check_status(st%set_ode_abs_tolerances(tol8(1:7)), FRICREG_ESIZE, 'set atol of 7')
  call check_status(st%set_ode_abs_tolerances([(1e-7_c_double * i, i = 1, 8)]), FRICREG_OK, &
                    'set_ode_abs_tolerances')
  call check_status(st%get_ode_abs_tolerances(tol8), FRICREG_OK, 'get the set ones')
  call check(all(tol8 == [(1e-7_c_double * i, i = 1, 8)]), 'the set ones')
  call check_status(st%set_ode_abs_tolerances(tol8(1:0)), FRICREG_OK, 'size 0 removes them')
  call check_status(st%get_ode_abs_tolerances(tol8), FRICREG_OK, 'get after removal')
  call check(tol8(3) == 1e-3_c_double * 0.013_c_double / 2, 'the rule again')
  call check_status(st%run_ode(FRICREG_INT_RKF45, 0.01_c_double, 1.3_c_double, &
                               rtol=1e-4_c_double, atol=1e-5_c_double), FRICREG_OK, &
                    'run_ode rkf45, rtol and atol')
  call check_status(st%get_ode_abs_tolerances(tol8), FRICREG_OK, 'get the one atol')
  call check(all(tol8 == 1e-5_c_double), 'one atol in every component')

  ! ---- A frame of three DOFs and two contacts, against the C API ----------------------------
  M = reshape([2.31_c_double, 0.17_c_double, 0.0_c_double, 0.17_c_double, 1.43_c_double, &
               -0.08_c_double, 0.0_c_double, -0.08_c_double, 0.87_c_double], [3, 3])
  K = reshape([41.3_c_double, -17.9_c_double, 0.0_c_double, -17.9_c_double, 29.6_c_double, &
               -11.7_c_double, 0.0_c_double, -11.7_c_double, 11.7_c_double], [3, 3])
  ! contact 1: DOF 1 on the ground; contact 2: DOF 3 against DOF 1 (J is 2 x 3, not square)
  J = reshape([1.0_c_double, -1.0_c_double, 0.0_c_double, 0.0_c_double, 0.0_c_double, &
               1.0_c_double], [2, 3])
  mun = [0.437_c_double, 0.291_c_double]
  p = [0.12_c_double, -0.07_c_double, 0.05_c_double]
  ag = [(3.1_c_double * sin(0.0617_c_double * i) * sin(0.0047_c_double * i), i = 1, 200)]
  g = [(cos(0.21_c_double * i), i = 1, 50)]
  ! ---- Warnings: a ground record typed in g (peak 0.2457, below 0.05 g = 0.49 m/s^2) --------
  call check_status(st%set_ground_accel([0.2457_c_double, 0.2457_c_double], 0.01_c_double), &
                    FRICREG_OK, 'a ground record in g')
  heard = 0
  call check_status(st%set_warning_handler(hear_warning, c_loc(heard)), FRICREG_OK, &
                    'set_warning_handler')
  nwarn = st%warning_count()
  call check(heard == nwarn, 'the handler hears every warning judged')
  call check(heard_code == FRICREG_WARN_GROUND_PEAK .and. &
             index(heard_message, '0.2457 m/s^2') > 0, 'it hears ground_peak: ' // heard_message)
  call check(st%warning_count() == nwarn .and. heard == nwarn, 'once')
  call check_status(st%set_warning_handler(), FRICREG_OK, 'set_warning_handler(): removed')
  call check(nwarn >= 1, 'the record in g raises a warning')
  found = .false.
  do i = 1, nwarn
    call check_status(st%get_warning(i, wcode, wmsg), FRICREG_OK, 'get_warning')
    call check(len(wmsg) > 0, 'a message')
    if (wcode == FRICREG_WARN_GROUND_PEAK) found = index(wmsg, '0.2457 m/s^2') > 0
  end do
  call check(found, 'ground_peak, naming the peak')
  call check(fricreg_warning_string(FRICREG_WARN_GROUND_PEAK) == 'ground_peak', 'its name')
  call check_status(st%get_warning(0, wcode, wmsg), FRICREG_EINVAL, 'get_warning(0)')
  call check(wcode == FRICREG_WARN_NONE .and. len(wmsg) == 0, 'no warning 0')
  call check_status(st%get_warning(nwarn + 1, wcode, wmsg), FRICREG_EINVAL, 'beyond the count')
  deallocate (wmsg, heard_message) ! they outlive the program: released by hand (LeakSanitizer)

  call check_status(st%create(3, 2), FRICREG_OK, 'create 3, 2 (replaces the first)')
  call check(st%ndof() == 3 .and. st%ncontacts() == 2, 'ndof 3, ncontacts 2')
  call check_status(st%set_mass(M), FRICREG_OK, 'set_mass 3')
  call check_status(st%set_stiffness(K), FRICREG_OK, 'set_stiffness 3')
  call check_status(st%set_rayleigh(a0, a1), FRICREG_OK, 'set_rayleigh')
  call check_status(st%set_contacts(J), FRICREG_OK, 'set_contacts 2 x 3')
  call check_status(st%set_bounds(mun), FRICREG_OK, 'set_bounds 2')
  call check_status(st%set_law(FRICREG_LAW_QUINN, 0.0213_c_double), FRICREG_OK, 'set_law')
  call check_status(st%set_influence([1.0_c_double, 1.0_c_double, 0.5_c_double]), FRICREG_OK, &
                    'set_influence')
  call check_status(st%set_ground_accel(ag, 0.0123_c_double), FRICREG_OK, 'ground, t0 = 0')
  call check_status(st%set_load(p, g, 0.05_c_double, 0.1_c_double), FRICREG_OK, 'load record')
  call check_status(st%set_initial(v0=[0.0_c_double, 0.31_c_double, -0.17_c_double]), &
                    FRICREG_OK, 'set_initial, u0 absent')
  call check_status(st%set_hht(-0.07_c_double), FRICREG_OK, 'set_hht')
  call check_status(st%set_newton(tol=1e-11_c_double), FRICREG_OK, 'set_newton, tol only')
  call check_status(st%get_dissipation_error(mun), FRICREG_EINVAL, 'no estimate yet')
  call check_status(st%set_error_estimate(3_c_int), FRICREG_EINVAL, 'set_error_estimate 3')
  call check_status(st%set_error_estimate(1_c_int), FRICREG_OK, 'set_error_estimate')
  call check_status(st%run(dt, t_end), FRICREG_OK, 'run HHT')
  call compare_with_c(.false.)
  call check_status(st%set_newmark(), FRICREG_OK, 'set_newmark, defaults')
  call check_status(st%set_initial(), FRICREG_OK, 'set_initial, at rest')
  call check_status(st%run_ode(FRICREG_INT_RK4, 0.002_c_double, 1.5_c_double), FRICREG_OK, &
                    'run_ode rk4')
  call compare_with_c(.true.)

  ! ---- Failures ----------------------------------------------------------------------------
  u = [1.5_c_double, 2.5_c_double, 3.5_c_double]
  call check_status(st%set_mass(M2), FRICREG_ESIZE, 'set_mass 2 x 2 for 3 DOFs')
  call check(st%errmsg() == 'set_mass: size(M, 1) = 2, expected 3', 'message: ' // st%errmsg())
  call check(st%errcode() == FRICREG_ESIZE, 'errcode ESIZE')
  call check_status(st%set_contacts(transpose(J)), FRICREG_ESIZE, 'J given as 3 x 2')
  call check(st%errmsg() == 'set_contacts: size(J, 1) = 3, expected 2', 'message: ' // st%errmsg())
  call check_status(st%get_state(u=u, v=v2), FRICREG_ESIZE, 'get_state, v of 2')
  call check(all(u == [1.5_c_double, 2.5_c_double, 3.5_c_double]), 'u untouched on failure')
  call check_status(st%get_state(), FRICREG_ENULL, 'get_state, nothing asked')
  call check_status(st%set_hht(-0.5_c_double), FRICREG_EINVAL, 'alpha < -1/3')
  call check(st%errcode() == FRICREG_EINVAL, 'errcode EINVAL')
  call check(index(st%errmsg(), 'alpha') > 0, 'C message names alpha: ' // st%errmsg())
  call check_status(st%set_load(p, g), FRICREG_EINVAL, 'load record without dt_rec')
  call check(st%errmsg() == 'set_load: g given without dt_rec', 'message: ' // st%errmsg())
  call check_status(st%set_ground_accel(ag(1:1), 0.01_c_double), FRICREG_EINVAL, 'one sample')
  call check_status(st%set_ground_accel(ag(1:0), 0.01_c_double), FRICREG_OK, 'no ground motion')
  call check_status(st%get_value(99_c_int, u(1)), FRICREG_EINVAL, 'unknown value')
  call check(u(1) == 1.5_c_double, 'value untouched on failure')
  call st%destroy()
  call st%destroy()
  call check(.not. st%is_created() .and. st%ndof() == 0, 'destroyed twice, empty')
  call check_status(st%run(dt, t_end), FRICREG_ENULL, 'run after destroy')
  call check(st%errmsg() == 'run: the structure is not created (call create)', &
             'message: ' // st%errmsg())
  call check_status(st%create(0, 2), FRICREG_EINVAL, 'create 0 DOFs')
  call check(st%errmsg() == 'create: ndof = 0, m = 2: both must be >= 1', 'message: ' // st%errmsg())

  call finish('structure_type')

contains

  !> The frame's run repeated through the C API with the same calls: every number the same.
  subroutine compare_with_c(gsl)
    logical, intent(in) :: gsl
    type(c_ptr) :: s
    real(c_double) :: uf(3), vf(3), af(3), uc(3), vc(3), ac(3), ff(2), fc(2), Df(2), Dc(2)
    real(c_double) :: wf, wc, pf(3), pc(3), pef(3), pec(3), Def(2), Dec(2)
    integer(c_int) :: kf(3), kc(3)
    integer(c_int64_t) :: nf, nc
    integer(c_int) :: which
    integer :: solver
    character(len=8) :: tag
    tag = merge('rk4     ', 'hht     ', gsl)
    call check_status(fricreg_structure_create(3_c_size_t, 2_c_size_t, s), FRICREG_OK, 'C create')
    call check_status(fricreg_structure_set_mass(s, 3_c_size_t, M), FRICREG_OK, 'C mass')
    call check_status(fricreg_structure_set_stiffness(s, 3_c_size_t, K), FRICREG_OK, 'C K')
    call check_status(fricreg_structure_set_rayleigh(s, a0, a1), FRICREG_OK, 'C rayleigh')
    call check_status(fricreg_structure_set_contacts(s, 2_c_size_t, 3_c_size_t, transpose(J)), &
                      FRICREG_OK, 'C contacts')
    call check_status(fricreg_structure_set_bounds(s, 2_c_size_t, mun), FRICREG_OK, 'C bounds')
    call check_status(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 0.0213_c_double), &
                      FRICREG_OK, 'C law')
    call check_status(fricreg_structure_set_error_estimate(s, 1_c_int), FRICREG_OK, 'C estimate')
    call check_status(fricreg_structure_set_influence(s, 3_c_size_t, [1.0_c_double, &
                      1.0_c_double, 0.5_c_double]), FRICREG_OK, 'C influence')
    call check_status(fricreg_structure_set_ground_accel(s, 0.0_c_double, 0.0123_c_double, &
                      200_c_size_t, ag), FRICREG_OK, 'C ground')
    call check_status(fricreg_structure_set_load(s, 3_c_size_t, p, 0.1_c_double, 0.05_c_double, &
                      50_c_size_t, g), FRICREG_OK, 'C load')
    if (gsl) then
      call check_status(fricreg_structure_set_initial(s, 3_c_size_t, [0.0_c_double, &
                        0.0_c_double, 0.0_c_double], [0.0_c_double, 0.0_c_double, &
                        0.0_c_double]), FRICREG_OK, 'C initial')
      call check_status(fricreg_structure_run_ode(s, FRICREG_INT_RK4, 0.002_c_double, &
                        0.0_c_double, 0.0_c_double, 1.5_c_double), FRICREG_OK, 'C run_ode')
    else
      call check_status(fricreg_structure_set_initial(s, 3_c_size_t, [0.0_c_double, &
                        0.0_c_double, 0.0_c_double], [0.0_c_double, 0.31_c_double, &
                        -0.17_c_double]), FRICREG_OK, 'C initial')
      call check_status(fricreg_structure_set_hht(s, -0.07_c_double), FRICREG_OK, 'C hht')
      call check_status(fricreg_structure_set_newton(s, 1e-11_c_double, 50_c_int), FRICREG_OK, &
                        'C newton')
      call check_status(fricreg_structure_run(s, dt, t_end), FRICREG_OK, 'C run')
    end if
    call check_status(st%get_state(uf, vf, af), FRICREG_OK, 'get_state ' // tag)
    call check_status(fricreg_structure_get_state(s, 3_c_size_t, uc, vc, ac), FRICREG_OK, &
                      'C get_state')
    call check_status(st%get_forces(ff), FRICREG_OK, 'get_forces ' // tag)
    call check_status(fricreg_structure_get_forces(s, 2_c_size_t, fc), FRICREG_OK, 'C forces')
    call check_status(st%get_dissipation(Df), FRICREG_OK, 'get_dissipation ' // tag)
    call check_status(fricreg_structure_get_dissipation(s, 2_c_size_t, Dc), FRICREG_OK, 'C D')
    call check(all(Df > 0.0_c_double), trim(tag) // ': both contacts slid')
    do i = 1, 3
      call check_bits(uf(i), uc(i), trim(tag) // ': u')
      call check_bits(vf(i), vc(i), trim(tag) // ': v')
      call check_bits(af(i), ac(i), trim(tag) // ': a')
    end do
    do i = 1, 2
      call check_bits(ff(i), fc(i), trim(tag) // ': f')
      call check_bits(Df(i), Dc(i), trim(tag) // ': D')
    end do
    call check_status(st%get_peak_displacement(pf), FRICREG_OK, 'get_peak_displacement ' // tag)
    call check_status(fricreg_structure_get_peak_displacement(s, 3_c_size_t, pc), FRICREG_OK, &
                      'C peak')
    call check_status(st%get_peak_displacement_error(pef), FRICREG_OK, 'peak error ' // tag)
    call check_status(fricreg_structure_get_peak_displacement_error(s, 3_c_size_t, pec), &
                      FRICREG_OK, 'C peak error')
    call check_status(st%get_dissipation_error(Def), FRICREG_OK, 'dissipation error ' // tag)
    call check_status(fricreg_structure_get_dissipation_error(s, 2_c_size_t, Dec), FRICREG_OK, &
                      'C dissipation error')
    call check_status(st%get_dissipation_error(pef), FRICREG_ESIZE, 'dissipation error of 3')
    call check(all(Def > 0.0_c_double .and. Def < 0.1_c_double * Df), &
               trim(tag) // ': D estimates finite, above 0, below 10% of D')
    do i = 1, 3
      call check_bits(pf(i), pc(i), trim(tag) // ': peak')
      call check_bits(pef(i), pec(i), trim(tag) // ': peak error')
    end do
    do i = 1, 2
      call check_bits(Def(i), Dec(i), trim(tag) // ': D error')
    end do
    ! the estimates' kinds, the same as C's; an unknown quantity and a wrong size refused
    call check_status(st%get_error_kind(FRICREG_EST_PEAK_DISPLACEMENT, kf), FRICREG_OK, &
                      'get_error_kind peaks ' // tag)
    call check_status(fricreg_structure_get_error_kind(s, FRICREG_EST_PEAK_DISPLACEMENT, &
                                                       3_c_size_t, kc), FRICREG_OK, 'C kinds')
    call check(all(kf == kc), trim(tag) // ': peak kinds as C''s')
    call check_status(st%get_error_kind(FRICREG_EST_DISSIPATION, kf(1:2)), FRICREG_OK, &
                      'get_error_kind dissipations ' // tag)
    call check_status(fricreg_structure_get_error_kind(s, FRICREG_EST_DISSIPATION, 2_c_size_t, &
                                                       kc), FRICREG_OK, 'C D kinds')
    call check(all(kf(1:2) == kc(1:2)), trim(tag) // ': D kinds as C''s')
    call check(all(kf(1:2) == FRICREG_EST_KIND_ASYMPTOTIC .or. &
                   kf(1:2) == FRICREG_EST_KIND_BOUND), trim(tag) // ': two companions')
    call check_status(st%get_error_kind(FRICREG_EST_DISSIPATION, kf), FRICREG_ESIZE, &
                      'kinds of 3 contacts')
    call check_status(st%get_error_kind(0_c_int, kf), FRICREG_EINVAL, 'kinds of quantity 0')
    ! the answer tolerance: at 1e-15 the estimates exceed it (a warning), at 1 they do not
    call check_status(st%set_answer_rtol(-1.0_c_double), FRICREG_EINVAL, 'set_answer_rtol -1')
    call check(index(st%errmsg(), 'set_answer_rtol') > 0, 'message: ' // st%errmsg())
    call check_status(st%set_answer_rtol(1e-15_c_double), FRICREG_OK, 'set_answer_rtol 1e-15')
    call check(count_code(FRICREG_WARN_ERROR_ESTIMATE) >= 1, trim(tag) // ': 1e-15 warns')
    call check_status(st%set_answer_rtol(1.0_c_double), FRICREG_OK, 'set_answer_rtol 1')
    call check(count_code(FRICREG_WARN_ERROR_ESTIMATE) == 0, trim(tag) // ': 1 does not')
    call check_status(st%set_answer_rtol(1e-2_c_double), FRICREG_OK, 'set_answer_rtol back')
    ! the companions' place: 3 refused, the estimate kept; the CPU seconds they took
    call check_status(st%set_error_companions(3_c_int), FRICREG_EINVAL, 'set_error_companions 3')
    call check_status(st%get_dissipation_error(Def), FRICREG_OK, 'kept after a refusal ' // tag)
    call check_status(st%get_value(FRICREG_SVALUE_COMPANION_CPU, wf), FRICREG_OK, 'companion cpu')
    call check_status(fricreg_structure_get_value(s, FRICREG_SVALUE_COMPANION_CPU, wc), &
                      FRICREG_OK, 'C companion cpu')
    call check(wf > 0.0_c_double .and. wc > 0.0_c_double, trim(tag) // ': companions took time')
    ! which companions gave the estimate (the default, auto: the coarser or the finer), as C reads
    call check_status(st%get_value(FRICREG_SVALUE_COMPANIONS_USED, wf), FRICREG_OK, 'used')
    call check_status(fricreg_structure_get_value(s, FRICREG_SVALUE_COMPANIONS_USED, wc), &
                      FRICREG_OK, 'C used')
    call check(wf == wc .and. (wf == FRICREG_COMPANIONS_FINER .or. &
                               wf == FRICREG_COMPANIONS_COARSER), trim(tag) // ': companions used')
    ! the near-stick block's solver: refused outside the enum (unchanged), read back resolved
    solver = -1
    call check_status(st%contact_solver(solver), FRICREG_OK, 'contact_solver')
    call check(solver == FRICREG_CONTACT_SOLVER_DENSE, trim(tag) // ': auto reads dense')
    call check_status(st%set_contact_solver(FRICREG_CONTACT_SOLVER_SPARSE), FRICREG_OK, &
                      'set_contact_solver sparse')
    call check_status(st%set_contact_solver(7), FRICREG_EINVAL, 'set_contact_solver 7')
    call check(index(st%errmsg(), 'set_contact_solver') > 0, 'message: ' // st%errmsg())
    call check_status(st%contact_solver(solver), FRICREG_OK, 'contact_solver sparse')
    call check(solver == FRICREG_CONTACT_SOLVER_SPARSE, trim(tag) // ': sparse kept')
    call check_status(st%set_contact_solver(FRICREG_CONTACT_SOLVER_AUTO), FRICREG_OK, &
                      'set_contact_solver back')
    do which = FRICREG_SVALUE_TIME, FRICREG_SVALUE_INITIAL
      call check_status(st%get_value(which, wf), FRICREG_OK, 'get_value')
      call check_status(fricreg_structure_get_value(s, which, wc), FRICREG_OK, 'C get_value')
      call check_bits(wf, wc, trim(tag) // ': an energy-balance value')
    end do
    do which = FRICREG_SSTAT_STEPS, FRICREG_SSTAT_LINE_SEARCH_CUTS
      call check_status(st%get_stat(which, nf), FRICREG_OK, 'get_stat')
      call check_status(fricreg_structure_get_stat(s, which, nc), FRICREG_OK, 'C get_stat')
      call check(nf == nc, trim(tag) // ': a counter')
    end do
    call fricreg_structure_free(s)
  end subroutine compare_with_c

  !> How many of st's warnings, judged now, have the code `code`.
  integer function count_code(code)
    integer(c_int), intent(in) :: code
    integer(c_int) :: c
    character(len=:), allocatable :: message
    integer :: k
    count_code = 0
    do k = 1, st%warning_count()
      if (st%get_warning(k, c, message) == FRICREG_OK) then
        if (c == code) count_code = count_code + 1
      end if
    end do
  end function count_code

end program test_structure_type
