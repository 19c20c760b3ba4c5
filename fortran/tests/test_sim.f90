! SPDX-License-Identifier: GPL-3.0-or-later
! test_sim.f90 — the ODE drivers through type fricreg_simulation (include/fricreg_sim.h), with
! the paper's numbers (shared/spec/paper.md): the unforced oscillator settles at -0.750090
! (Sec. 3.1.1; RK4, dt = 0.01, eps = 2 dt), and the chain dissipates D = 0.0105 per cycle
! (Sec. 3.2, Fig. 9; n = 32, a = 0.25, omega = 0.5, 4th cycle).
module step_counter
  use, intrinsic :: iso_c_binding
  implicit none
  real(c_double) :: last_t = -1.0_c_double, last_x = 0.0_c_double, last_v = 0.0_c_double, &
                    last_f = 0.0_c_double, last_f_eq = 0.0_c_double
  integer(c_size_t) :: seen_ndof = 0, seen_m = 0

contains

  !> A fricreg_sim_observer: counts its calls in the integer that user points to, keeps what
  !> it was given, and stops the run after 10 steps.
  function count_steps(user, t, ndof, x, v, m, f, f_eq) bind(C) result(stop_run)
    type(c_ptr), value :: user
    real(c_double), value :: t
    integer(c_size_t), value :: ndof
    real(c_double), intent(in) :: x(ndof), v(ndof)
    integer(c_size_t), value :: m
    real(c_double), intent(in) :: f(m), f_eq(m)
    integer(c_int) :: stop_run
    integer(c_int), pointer :: calls
    call c_f_pointer(user, calls)
    calls = calls + 1
    last_t = t
    last_x = x(1)
    last_v = v(1)
    last_f = f(1)
    last_f_eq = f_eq(1)
    seen_ndof = ndof
    seen_m = m
    stop_run = merge(1_c_int, 0_c_int, calls > 10)
  end function count_steps

end module step_counter

program test_sim
  use fricreg
  use ftest
  use step_counter
  implicit none
  type(fricreg_simulation) :: sim
  real(c_double), allocatable :: D(:), Derr(:)
  integer(c_int), allocatable :: kinds(:)
  real(c_double) :: x(1), v(1), x2(2), value, frac(32), atol3(3)
  integer(c_int), target :: calls
  integer(c_int64_t) :: count
  type(c_ptr) :: p
  integer :: i

  call check(fricreg_integrator_string(FRICREG_INT_RK4) == 'rk4', 'integrator 2 is rk4')
  call check(fricreg_integrator_string(99_c_int) == '', 'integrator 99 has no name')
  call check(fricreg_integrator_id('msbdf') == FRICREG_INT_MSBDF, 'msbdf is FRICREG_INT_MSBDF')
  call check(fricreg_integrator_id('central-imex') == FRICREG_INT_CENTRAL_IMEX, &
             'central-imex is FRICREG_INT_CENTRAL_IMEX')
  call check(fricreg_integrator_id('rk4  ') == FRICREG_INT_RK4, 'trailing blanks ignored')
  call check(fricreg_integrator_id('euler') == 0, 'no integrator euler')

  ! The unforced oscillator, Eq. (5), as the paper ran it.
  call check_status(sim%create(FRICREG_SYSTEM_OSCILLATOR), FRICREG_OK, 'create oscillator')
  call check(sim%ndof() == 1 .and. sim%ncontacts() == 1, 'one body, one contact')
  call check_status(sim%set_integrator(FRICREG_INT_RK4, 0.01_c_double), FRICREG_OK, &
                    'RK4, dt = 0.01, fixed')
  call check_status(sim%set_law(FRICREG_LAW_QUINN, 0.0_c_double), FRICREG_OK, 'law (4), eps 2dt')
  call check_status(sim%get_value(FRICREG_VALUE_EPS, value), FRICREG_OK, 'get_value(EPS)')
  call check_close(value, 0.02_c_double, 0.0_c_double, 'eps = 2 dt')
  call check_status(sim%run(20.0_c_double), FRICREG_OK, 'run to t = 20')
  call check_status(sim%get_state(x, v), FRICREG_OK, 'get_state')
  call check_close(x(1), -0.750090_c_double, 5e-7_c_double, 'rest position, paper -0.750090')
  call check_close(v(1), 0.0_c_double, 1e-15_c_double, 'at rest')
  call check_status(sim%get_dissipation(D), FRICREG_OK, 'get_dissipation')
  call check(size(D) == 3, 'three whole cycles of 2 pi in t = 20')
  ! The energy lost sliding from 2.75 to -0.75 (mun = 1, all in the first cycle): 1.75 * 2.
  call check_close(D(1), 3.5_c_double, 1e-4_c_double, 'D, first cycle = 3.5')
  ! 1.1: integer counters and the parameters in use. RK4, dt = 0.01, t = 20: 1000 calls of
  ! two steps, 3 of them shortened to end a cycle (3 cycles): 2 * (1000 + 3) = 2006 steps
  ! (test_sim_api.c counts the same grid), 4 right-hand sides each.
  call check_status(sim%get_stat(FRICREG_SIM_STAT_STEPS, count), FRICREG_OK, 'get_stat(STEPS)')
  call check(count == 2006_c_int64_t, 'steps on the grid of 2 dt with 3 cycle ends')
  call check_status(sim%get_stat(FRICREG_SIM_STAT_RHS_EVALS, count), FRICREG_OK, 'RHS_EVALS')
  call check(count == 4_c_int64_t * 2006_c_int64_t, '4 right-hand sides per fixed RK4 step')
  call check_status(sim%get_stat(77_c_int, count), FRICREG_EINVAL, 'unknown counter')
  call check_status(sim%get_param(FRICREG_PARAM_X0, value), FRICREG_OK, 'get_param(X0)')
  call check_close(value, 2.75_c_double, 0.0_c_double, "the paper's x0")
  call check_status(sim%get_param(FRICREG_PARAM_K, value), FRICREG_EINVAL, 'no K here')
  call check_status(sim%set_partition(FRICREG_PARTITION_PAPER), FRICREG_OK, 'set_partition')
  call check_status(sim%run(20.0_c_double), FRICREG_OK, 'rerun: one contact, either partition')

  ! The bind(C) layer sees the same simulation.
  call check_status(fricreg_sim_get_state(sim%handle(), 1_c_size_t, x, v), FRICREG_OK, &
                    'fricreg_sim_get_state on handle()')
  call check_close(x(1), -0.750090_c_double, 5e-7_c_double, 'same state through bind(C)')

  ! An observer, a bind(C) function of this program, counts the steps and stops the run.
  calls = 0
  p = c_loc(calls)
  call check_status(sim%set_observer(count_steps, p), FRICREG_OK, 'set_observer')
  call check_status(sim%run(20.0_c_double), FRICREG_OK, 'a run stopped by the observer')
  call check(calls == 11, 'the observer ran at t = 0 and after 10 steps')
  call check(seen_ndof == 1 .and. seen_m == 1, 'the observer saw one body and one contact')
  call check_status(sim%get_value(FRICREG_VALUE_TIME, value), FRICREG_OK, 'get_value(TIME)')
  call check_close(value, last_t, 0.0_c_double, 'the run stopped where the observer did')
  ! Sliding from rest at 2.75: x = 1 + 1.75 cos t (the paper's exact solution), f = -1.
  call check_close(last_x, 1.0_c_double + 1.75_c_double * cos(last_t), 1e-6_c_double, &
                   'the observer saw x(t) = 1 + 1.75 cos t')
  call check_close(last_v, -1.75_c_double * sin(last_t), 1e-6_c_double, 'and v(t)')
  call check_close(last_f, 1.0_c_double, 0.0_c_double, 'and f = +mun (sliding back)')
  call check(last_f_eq /= last_f_eq, 'and f_eq not computed while sliding (NaN)')
  call check_status(sim%set_observer(), FRICREG_OK, 'remove the observer')

  ! Errors.
  call check_status(sim%get_state(x2, x2), FRICREG_ESIZE, 'get_state, 2 for 1 body')
  call check(sim%errmsg() == 'get_state: size(x) = 2, expected 1', 'message: ' // sim%errmsg())
  call check_status(sim%set_param(FRICREG_PARAM_K, 2.0_c_double), FRICREG_EINVAL, &
                    'the oscillator has no K')
  call check(index(sim%errmsg(), 'not a parameter') > 0, 'message: ' // sim%errmsg())
  call check_status(sim%set_integrator(FRICREG_INT_RK4, 0.0_c_double), FRICREG_EINVAL, 'dt = 0')
  call check_status(sim%run(-1.0_c_double), FRICREG_EINVAL, 't_end < 0')
  call check_status(sim%get_value(99_c_int, value), FRICREG_EINVAL, 'get_value(99)')
  call check_status(sim%set_law(FRICREG_LAW_QUINN, 1e-5_c_double), FRICREG_OK, 'eps = 1e-5')
  call check_status(sim%run(1.0_c_double), FRICREG_ESTEP, 'dt 0.01 too large for eps 1e-5')
  call check_status(sim%errcode(), FRICREG_ESTEP, 'errcode ESTEP')
  call check(index(sim%errmsg(), 'stick zone') > 0, 'message names the stick zone: ' // sim%errmsg())

  ! Extrapolation in eps on the sticking oscillator (a = 2, omega = 0.5, from rest at the
  ! origin): order 2 observed; D on cycle 3 within its estimate of the exact solution's
  ! 10.410028667845459 (fricreg-sim exact --a 2 --omega 0.5 --x0 0 --cycles 3).
  call check_status(sim%set_param(FRICREG_PARAM_A, 2.0_c_double), FRICREG_OK, 'a = 2')
  call check_status(sim%set_param(FRICREG_PARAM_OMEGA, 0.5_c_double), FRICREG_OK, 'omega = 0.5')
  call check_status(sim%set_param(FRICREG_PARAM_X0, 0.0_c_double), FRICREG_OK, 'x0 = 0')
  call check_status(sim%set_law(FRICREG_LAW_QUINN, 0.04_c_double), FRICREG_OK, 'eps = 0.04')
  call check_status(sim%set_integrator(FRICREG_INT_RK8PD, 1e-3_c_double, 1e-11_c_double, &
                                       1e-11_c_double), FRICREG_OK, 'rk8pd, 1e-11')
  call check_status(sim%get_extrapolated_dissipation(D, Derr), FRICREG_EINVAL, &
                    'no extrapolation before a run')
  call check_status(sim%run_extrapolated(3 * 4 * acos(-1.0_c_double), 3), FRICREG_OK, &
                    'run_extrapolated, 3 cycles, 3 levels')
  call check_status(sim%get_extrapolation(FRICREG_EXTRAP_ORDER, value), FRICREG_OK, 'ORDER')
  call check_close(value, 2.0_c_double, 0.0_c_double, 'order 2 observed')
  call check_status(sim%get_extrapolated_dissipation(D, Derr), FRICREG_OK, &
                    'get_extrapolated_dissipation')
  call check(size(D) == 3 .and. size(Derr) == 3, 'three cycles extrapolated')
  call check(abs(D(3) - 10.410028667845459_c_double) <= Derr(3), 'within its estimate')
  call check(Derr(3) < 1e-7_c_double, 'estimate below 1e-7')
  call check_status(sim%run_extrapolated(1.0_c_double, 9), FRICREG_EINVAL, 'levels 9')
  call check(index(sim%errmsg(), 'levels') > 0, 'message: ' // sim%errmsg())
  ! A window of the last 2 of 3 cycles: cycle 1 is level 0's (estimate +infinity), so is the
  ! window's first; cycle 3 is extrapolated (tests/sim/test_extrapolate_window.c measures it).
  call check_status(sim%run_extrapolated(3 * 4 * acos(-1.0_c_double), 3, window=2), FRICREG_OK, &
                    'run_extrapolated, window 2')
  call check_status(sim%get_extrapolated_dissipation(D, Derr), FRICREG_OK, 'window: dissipation')
  call check(Derr(1) > huge(Derr(1)) .and. Derr(2) > huge(Derr(2)), 'not extrapolated: +infinity')
  call check(Derr(3) <= huge(Derr(3)), 'cycle 3 extrapolated, a finite estimate')
  call check_status(sim%run_extrapolated(1.0_c_double, 2, window=-1), FRICREG_EINVAL, 'window -1')
  call check(index(sim%errmsg(), 'window') > 0, 'message: ' // sim%errmsg())
  ! The error estimate of a plain run bounds its distance to the extrapolation above.
  call check_status(sim%get_dissipation_error(Derr), FRICREG_EINVAL, 'no estimate made')
  call check_status(sim%set_error_estimate(3_c_int), FRICREG_EINVAL, 'set_error_estimate 3')
  call check_status(sim%set_error_estimate(FRICREG_ESTIMATE_TWO_COMPANIONS), FRICREG_OK, &
                    'set_error_estimate two companions')
  call check_status(sim%run_cycles(3), FRICREG_OK, 'run_cycles with an estimate')
  call check_status(sim%get_dissipation(D), FRICREG_OK, 'estimated: dissipation')
  call check_status(sim%get_dissipation_error(Derr), FRICREG_OK, 'get_dissipation_error')
  call check(size(Derr) == 3, 'three estimates')
  call check(abs(D(3) - 10.410028667845459_c_double) <= Derr(3), 'D within its error estimate')
  call check(Derr(3) <= 10 * abs(D(3) - 10.410028667845459_c_double), 'estimate within 10x')
  ! Each estimate's kind (get_dissipation_error_kind), and the answer tolerance's setter.
  call check_status(sim%get_dissipation_error_kind(kinds), FRICREG_OK, 'get_dissipation_error_kind')
  call check(size(kinds) == 3, 'three kinds')
  call check(all(kinds == FRICREG_EST_KIND_ASYMPTOTIC .or. kinds == FRICREG_EST_KIND_BOUND), &
             'kinds asymptotic or bound with two companions')
  call check_status(sim%set_answer_rtol(0.0_c_double), FRICREG_EINVAL, 'set_answer_rtol 0')
  call check(index(sim%errmsg(), 'set_answer_rtol') > 0, 'message: ' // sim%errmsg())
  call check_status(sim%set_answer_rtol(1e-12_c_double), FRICREG_OK, 'set_answer_rtol 1e-12')
  call check(fricreg_sim_warning_count(sim%handle()) == 1, 'the estimate above 1e-12 of D warns')
  call check_status(sim%set_answer_rtol(0.1_c_double), FRICREG_OK, 'set_answer_rtol 0.1')
  call check(fricreg_sim_warning_count(sim%handle()) == 0, 'nor above 10%')
  call check_status(sim%set_error_estimate(FRICREG_ESTIMATE_ONE_COMPANION), FRICREG_OK, &
                    'set_error_estimate one companion')
  call check_status(sim%run_cycles(3), FRICREG_OK, 'run_cycles with one companion')
  call check_status(sim%get_dissipation_error_kind(kinds), FRICREG_OK, 'kinds: one companion')
  call check(all(kinds == FRICREG_EST_KIND_ASSUMED), 'one companion: kind assumed')
  call check_status(sim%set_error_estimate(FRICREG_ESTIMATE_OFF), FRICREG_OK, 'estimate off')
  call check_status(sim%run_cycles(1), FRICREG_OK, 'run_cycles without an estimate')
  call check_status(sim%get_dissipation_error_kind(kinds), FRICREG_EINVAL, 'no kinds without')

  ! The chain of Sec. 3.2, the paper's defaults: D per cycle converges to 0.0105.
  call check_status(sim%create(FRICREG_SYSTEM_CHAIN), FRICREG_OK, 'create chain (replaces)')
  call check(sim%ndof() == 32, 'n = 32 blocks')
  call check_status(sim%set_kink_location(2_c_int), FRICREG_EINVAL, 'set_kink_location 2')
  call check_status(sim%set_kink_location(1_c_int), FRICREG_OK, 'set_kink_location 1')
  ! Absolute tolerances per component of (x, v, D): the rule from eps when atol is absent
  ! (velocities min(1e-3 eps, rtol), x and D rtol), the caller's, and their errors.
  call check_status(sim%create(FRICREG_SYSTEM_OSCILLATOR), FRICREG_OK, 'create (tolerances)')
  call check_status(sim%set_law(FRICREG_LAW_QUINN, 2.385e-4_c_double), FRICREG_OK, 'eps')
  call check_status(sim%set_integrator(FRICREG_INT_MSBDF, 0.01_c_double, 1e-6_c_double), &
                    FRICREG_OK, 'msbdf, rtol only')
  call check_status(sim%get_abs_tolerances(atol3), FRICREG_OK, 'get_abs_tolerances')
  call check_close(atol3(2), 2.385e-7_c_double, 1e-15_c_double, 'velocity: 1e-3 eps')
  call check_close(atol3(1), 1e-6_c_double, 1e-15_c_double, 'position: rtol')
  call check_status(sim%get_abs_tolerances(frac(1:2)), FRICREG_ESIZE, 'get_abs_tolerances, 2')
  call check_status(sim%set_abs_tolerances([1e-6_c_double, 1e-9_c_double, 1e-6_c_double]), &
                    FRICREG_OK, 'set_abs_tolerances')
  call check_status(sim%get_abs_tolerances(atol3), FRICREG_OK, 'get_abs_tolerances, set')
  call check_close(atol3(2), 1e-9_c_double, 0.0_c_double, 'velocity: the caller''s')
  call check_status(sim%set_abs_tolerances([1e-6_c_double, 0.0_c_double, 1e-6_c_double]), &
                    FRICREG_EINVAL, 'set_abs_tolerances, 0')
  call check(index(sim%errmsg(), 'atol(2)') > 0 .or. index(sim%errmsg(), 'atol[1]') > 0, &
             'message: ' // sim%errmsg())
  call check_status(sim%set_abs_tolerances(frac(1:2)), FRICREG_ESIZE, 'set_abs_tolerances, 2')
  call check_status(sim%run_cycles(1), FRICREG_OK, 'one adaptive cycle')
  call check_status(sim%create(FRICREG_SYSTEM_CHAIN), FRICREG_OK, 'create chain again')
  call check_status(sim%run_cycles(4), FRICREG_OK, 'four cycles')
  call check_status(sim%get_dissipation(D), FRICREG_OK, 'get_dissipation, chain')
  call check(size(D) == 4, 'four values of D')
  call check(abs(D(4) / 0.0105_c_double - 1.0_c_double) < 0.01_c_double, 'D(4) within 1% of 0.0105')
  call check_status(sim%get_stick_fraction(frac), FRICREG_OK, 'get_stick_fraction')
  call check(all(frac >= 0.0_c_double .and. frac <= 1.0_c_double), 'fractions in [0, 1]')
  call check_status(sim%get_stick_fraction(frac(1:31)), FRICREG_ESIZE, 'stick fraction, 31')
  write (*, '(a, 4f10.6)') 'chain D per cycle:', (D(i), i = 1, 4)

  call sim%destroy()
  call sim%destroy()
  call check_status(sim%run(1.0_c_double), FRICREG_ENULL, 'run after destroy')
  call check(sim%ndof() == 0, 'ndof 0 after destroy')
  deallocate (D, Derr, kinds) ! the main program's arrays are never freed: LeakSanitizer would report it
  call finish('test_sim')

end program test_sim
