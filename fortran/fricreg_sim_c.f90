! fricreg_sim_c.f90 — module fricreg_sim_c: thin bind(C) interfaces to every function of
! fricreg_sim.h (the GSL ODE drivers of the paper's three reference systems) and of
! fricreg_structure.h (a linear structure with friction).
!
! As in module fricreg_c: argument for argument, scalars by value, arrays dimension(*), the
! simulation as type(c_ptr), size_t as integer(c_size_t); the docstrings of
! include/fricreg_sim.h apply unchanged. The idiomatic layer is type fricreg_simulation in
! module fricreg. Built only with the drivers (FRICREG_DRIVERS).
module fricreg_sim_c
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_funptr, c_char, &
                                         c_int64_t
  implicit none
  public

  abstract interface
    !> An observer (fricreg_sim_observer): called after every accepted step, and once at t = 0,
    !> with the ndof body positions x and velocities v and the m contact forces f and f_eq
    !> (NaN where not computed), valid during the call only. Return 0 to go on, nonzero to
    !> stop the run early. Write it as a bind(C) function and pass it to set_observer.
    function fricreg_sim_observer(user, t, ndof, x, v, m, f, f_eq) bind(C) result(stop_run)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: user
      real(c_double), value :: t
      integer(c_size_t), value :: ndof
      real(c_double), intent(in) :: x(ndof), v(ndof)
      integer(c_size_t), value :: m
      real(c_double), intent(in) :: f(m), f_eq(m)
      integer(c_int) :: stop_run
    end function
  end interface

  interface
    !> GSL's name of an integrator, static storage; c_null_ptr if unknown.
    function fricreg_integrator_name(integrator) bind(C, name='fricreg_integrator_name')
      import :: c_int, c_ptr
      integer(c_int), value :: integrator
      type(c_ptr) :: fricreg_integrator_name
    end function

    !> The integrator named name (NUL-terminated: 'rk4'//c_null_char), or 0.
    function fricreg_integrator_from_name(name) bind(C, name='fricreg_integrator_from_name')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: name(*)
      integer(c_int) :: fricreg_integrator_from_name
    end function

    function fricreg_sim_create(system, sim) bind(C, name='fricreg_sim_create')
      import :: c_int, c_ptr
      integer(c_int), value :: system
      type(c_ptr), intent(out) :: sim
      integer(c_int) :: fricreg_sim_create
    end function

    subroutine fricreg_sim_free(sim) bind(C, name='fricreg_sim_free')
      import :: c_ptr
      type(c_ptr), value :: sim
    end subroutine

    function fricreg_sim_set_param(sim, param, value) bind(C, name='fricreg_sim_set_param')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: sim
      integer(c_int), value :: param
      real(c_double), value :: value
      integer(c_int) :: fricreg_sim_set_param
    end function

    function fricreg_sim_set_law(sim, law, eps) bind(C, name='fricreg_sim_set_law')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: sim
      integer(c_int), value :: law
      real(c_double), value :: eps
      integer(c_int) :: fricreg_sim_set_law
    end function

    function fricreg_sim_set_partition(sim, partition) &
        bind(C, name='fricreg_sim_set_partition')
      import :: c_int, c_ptr
      type(c_ptr), value :: sim
      integer(c_int), value :: partition
      integer(c_int) :: fricreg_sim_set_partition
    end function

    function fricreg_sim_set_integrator(sim, integrator, dt, rtol, atol) &
        bind(C, name='fricreg_sim_set_integrator')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: sim
      integer(c_int), value :: integrator
      real(c_double), value :: dt, rtol, atol
      integer(c_int) :: fricreg_sim_set_integrator
    end function

    !> fn = c_funloc(an observer), or c_null_funptr to remove it; user is passed back.
    function fricreg_sim_set_observer(sim, fn, user) bind(C, name='fricreg_sim_set_observer')
      import :: c_int, c_ptr, c_funptr
      type(c_ptr), value :: sim
      type(c_funptr), value :: fn
      type(c_ptr), value :: user
      integer(c_int) :: fricreg_sim_set_observer
    end function

    function fricreg_sim_run(sim, t_end) bind(C, name='fricreg_sim_run')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: sim
      real(c_double), value :: t_end
      integer(c_int) :: fricreg_sim_run
    end function

    function fricreg_sim_run_cycles(sim, cycles) bind(C, name='fricreg_sim_run_cycles')
      import :: c_int, c_ptr
      type(c_ptr), value :: sim
      integer(c_int), value :: cycles
      integer(c_int) :: fricreg_sim_run_cycles
    end function

    function fricreg_sim_ndof(sim) bind(C, name='fricreg_sim_ndof')
      import :: c_size_t, c_ptr
      type(c_ptr), value :: sim
      integer(c_size_t) :: fricreg_sim_ndof
    end function

    function fricreg_sim_ncontacts(sim) bind(C, name='fricreg_sim_ncontacts')
      import :: c_size_t, c_ptr
      type(c_ptr), value :: sim
      integer(c_size_t) :: fricreg_sim_ncontacts
    end function

    function fricreg_sim_get_value(sim, which, value) bind(C, name='fricreg_sim_get_value')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: sim
      integer(c_int), value :: which
      real(c_double), intent(inout) :: value ! written only on success
      integer(c_int) :: fricreg_sim_get_value
    end function

    function fricreg_sim_get_state(sim, ndof, x, v) bind(C, name='fricreg_sim_get_state')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: sim
      integer(c_size_t), value :: ndof
      real(c_double), intent(inout) :: x(*), v(*) ! written only on success
      integer(c_int) :: fricreg_sim_get_state
    end function

    function fricreg_sim_get_dissipation(sim, ncycles, D) &
        bind(C, name='fricreg_sim_get_dissipation')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: sim
      integer(c_size_t), value :: ncycles
      real(c_double), intent(inout) :: D(*)
      integer(c_int) :: fricreg_sim_get_dissipation
    end function

    function fricreg_sim_get_stick_fraction(sim, m, frac) &
        bind(C, name='fricreg_sim_get_stick_fraction')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: sim
      integer(c_size_t), value :: m
      real(c_double), intent(inout) :: frac(*)
      integer(c_int) :: fricreg_sim_get_stick_fraction
    end function

    function fricreg_sim_errcode(sim) bind(C, name='fricreg_sim_errcode')
      import :: c_int, c_ptr
      type(c_ptr), value :: sim
      integer(c_int) :: fricreg_sim_errcode
    end function

    !> Last error message, owned by sim (fricreg_c_string converts it).
    function fricreg_sim_errmsg(sim) bind(C, name='fricreg_sim_errmsg')
      import :: c_ptr
      type(c_ptr), value :: sim
      type(c_ptr) :: fricreg_sim_errmsg
    end function

    !> Copy the last error message into buf(len), NUL-terminated; returns its full length.
    function fricreg_sim_errmsg_copy(sim, buf, len) bind(C, name='fricreg_sim_errmsg_copy')
      import :: c_size_t, c_char, c_ptr
      type(c_ptr), value :: sim
      character(kind=c_char), intent(inout) :: buf(*)
      integer(c_size_t), value :: len
      integer(c_size_t) :: fricreg_sim_errmsg_copy
    end function

    ! ---- fricreg_structure.h: a linear structure with friction (Newmark, HHT-alpha) ----
    ! Matrices are row-major in C: M, C and K are symmetric (pass them as they are); J is
    ! m x ndof row-major, i.e. a Fortran Jt(ndof, m) array, the transpose of J(m, ndof).

    function fricreg_structure_create(ndof, m, s) bind(C, name='fricreg_structure_create')
      import :: c_int, c_size_t, c_ptr
      integer(c_size_t), value :: ndof, m
      type(c_ptr), intent(out) :: s
      integer(c_int) :: fricreg_structure_create
    end function

    subroutine fricreg_structure_free(s) bind(C, name='fricreg_structure_free')
      import :: c_ptr
      type(c_ptr), value :: s
    end subroutine

    function fricreg_structure_set_mass(s, ndof, M) &
        bind(C, name='fricreg_structure_set_mass')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      integer(c_size_t), value :: ndof
      real(c_double), intent(in) :: M(*)
      integer(c_int) :: fricreg_structure_set_mass
    end function

    function fricreg_structure_set_stiffness(s, ndof, K) &
        bind(C, name='fricreg_structure_set_stiffness')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      integer(c_size_t), value :: ndof
      real(c_double), intent(in) :: K(*)
      integer(c_int) :: fricreg_structure_set_stiffness
    end function

    function fricreg_structure_set_damping(s, ndof, C) &
        bind(C, name='fricreg_structure_set_damping')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      integer(c_size_t), value :: ndof
      real(c_double), intent(in) :: C(*)
      integer(c_int) :: fricreg_structure_set_damping
    end function

    function fricreg_structure_set_rayleigh(s, a0, a1) &
        bind(C, name='fricreg_structure_set_rayleigh')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), value :: a0, a1
      integer(c_int) :: fricreg_structure_set_rayleigh
    end function

    function fricreg_structure_set_contacts(s, m, ndof, J) &
        bind(C, name='fricreg_structure_set_contacts')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      integer(c_size_t), value :: m, ndof
      real(c_double), intent(in) :: J(*) ! J(i*ndof + k), i.e. a Fortran Jt(ndof, m)
      integer(c_int) :: fricreg_structure_set_contacts
    end function

    function fricreg_structure_set_bounds(s, m, mun) bind(C, name='fricreg_structure_set_bounds')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      integer(c_size_t), value :: m
      real(c_double), intent(in) :: mun(*)
      integer(c_int) :: fricreg_structure_set_bounds
    end function

    function fricreg_structure_set_law(s, law, eps) bind(C, name='fricreg_structure_set_law')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int), value :: law
      real(c_double), value :: eps
      integer(c_int) :: fricreg_structure_set_law
    end function

    function fricreg_structure_set_influence(s, ndof, r) &
        bind(C, name='fricreg_structure_set_influence')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      integer(c_size_t), value :: ndof
      real(c_double), intent(in) :: r(*)
      integer(c_int) :: fricreg_structure_set_influence
    end function

    !> Ground acceleration record: n samples ag(n) every dt_rec from t0 (n = 0 removes it).
    function fricreg_structure_set_ground_accel(s, t0, dt_rec, n, ag) &
        bind(C, name='fricreg_structure_set_ground_accel')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      real(c_double), value :: t0, dt_rec
      integer(c_size_t), value :: n
      real(c_double), intent(in), optional :: ag(*)
      integer(c_int) :: fricreg_structure_set_ground_accel
    end function

    !> Load p(ndof) times the record g(n) (n = 0, g absent: constant load).
    function fricreg_structure_set_load(s, ndof, p, t0, dt_rec, n, g) &
        bind(C, name='fricreg_structure_set_load')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      integer(c_size_t), value :: ndof
      real(c_double), intent(in) :: p(*)
      real(c_double), value :: t0, dt_rec
      integer(c_size_t), value :: n
      real(c_double), intent(in), optional :: g(*)
      integer(c_int) :: fricreg_structure_set_load
    end function

    function fricreg_structure_set_initial(s, ndof, u0, v0) &
        bind(C, name='fricreg_structure_set_initial')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      integer(c_size_t), value :: ndof
      real(c_double), intent(in) :: u0(*), v0(*)
      integer(c_int) :: fricreg_structure_set_initial
    end function

    function fricreg_structure_set_newmark(s, beta, gamma) &
        bind(C, name='fricreg_structure_set_newmark')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), value :: beta, gamma
      integer(c_int) :: fricreg_structure_set_newmark
    end function

    function fricreg_structure_set_hht(s, alpha) bind(C, name='fricreg_structure_set_hht')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), value :: alpha
      integer(c_int) :: fricreg_structure_set_hht
    end function

    function fricreg_structure_set_central_difference(s) &
        bind(C, name='fricreg_structure_set_central_difference')
      import :: c_int, c_ptr
      type(c_ptr), value :: s
      integer(c_int) :: fricreg_structure_set_central_difference
    end function

    function fricreg_structure_set_newton(s, tol, max_iter) &
        bind(C, name='fricreg_structure_set_newton')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), value :: tol
      integer(c_int), value :: max_iter
      integer(c_int) :: fricreg_structure_set_newton
    end function

    function fricreg_structure_step(s, dt) bind(C, name='fricreg_structure_step')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), value :: dt
      integer(c_int) :: fricreg_structure_step
    end function

    function fricreg_structure_run(s, dt, t_end) bind(C, name='fricreg_structure_run')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), value :: dt, t_end
      integer(c_int) :: fricreg_structure_run
    end function

    !> integrator: FRICREG_INT_*; rtol = atol = 0 for fixed steps.
    function fricreg_structure_run_ode(s, integrator, dt, rtol, atol, t_end) &
        bind(C, name='fricreg_structure_run_ode')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int), value :: integrator
      real(c_double), value :: dt, rtol, atol, t_end
      integer(c_int) :: fricreg_structure_run_ode
    end function

    !> Any of u, v, a may be absent (not all three); each written only on success.
    function fricreg_structure_get_state(s, ndof, u, v, a) &
        bind(C, name='fricreg_structure_get_state')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      integer(c_size_t), value :: ndof
      real(c_double), intent(inout), optional :: u(*), v(*), a(*)
      integer(c_int) :: fricreg_structure_get_state
    end function

    function fricreg_structure_get_forces(s, m, f) bind(C, name='fricreg_structure_get_forces')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      integer(c_size_t), value :: m
      real(c_double), intent(inout) :: f(*)
      integer(c_int) :: fricreg_structure_get_forces
    end function

    function fricreg_structure_get_dissipation(s, m, D) &
        bind(C, name='fricreg_structure_get_dissipation')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      integer(c_size_t), value :: m
      real(c_double), intent(inout) :: D(*)
      integer(c_int) :: fricreg_structure_get_dissipation
    end function

    !> One quantity FRICREG_SVALUE_* (time, energies).
    function fricreg_structure_get_value(s, which, value) &
        bind(C, name='fricreg_structure_get_value')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int), value :: which
      real(c_double), intent(inout) :: value
      integer(c_int) :: fricreg_structure_get_value
    end function

    !> One counter FRICREG_SSTAT_* (steps, Newton iterations and failures).
    function fricreg_structure_get_stat(s, which, value) &
        bind(C, name='fricreg_structure_get_stat')
      import :: c_int, c_int64_t, c_ptr
      type(c_ptr), value :: s
      integer(c_int), value :: which
      integer(c_int64_t), intent(inout) :: value
      integer(c_int) :: fricreg_structure_get_stat
    end function

    function fricreg_structure_errcode(s) bind(C, name='fricreg_structure_errcode')
      import :: c_int, c_ptr
      type(c_ptr), value :: s
      integer(c_int) :: fricreg_structure_errcode
    end function

    !> Last error message, owned by s (fricreg_c_string converts it).
    function fricreg_structure_errmsg(s) bind(C, name='fricreg_structure_errmsg')
      import :: c_ptr
      type(c_ptr), value :: s
      type(c_ptr) :: fricreg_structure_errmsg
    end function

    !> Copy the last error message into buf(len), NUL-terminated; returns its full length.
    function fricreg_structure_errmsg_copy(s, buf, len) &
        bind(C, name='fricreg_structure_errmsg_copy')
      import :: c_size_t, c_char, c_ptr
      type(c_ptr), value :: s
      character(kind=c_char), intent(inout) :: buf(*)
      integer(c_size_t), value :: len
      integer(c_size_t) :: fricreg_structure_errmsg_copy
    end function
  end interface

end module fricreg_sim_c
