! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_sim.F90 — module fricreg_sim_m: type fricreg_simulation, the paper's reference systems
! on a GSL ODE driver (fricreg_sim.h), its procedures, and fricreg_integrator_string and
! fricreg_integrator_id. Built with the drivers only (FRICREG_DRIVERS).
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_sim_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_ptr, c_funptr, &
                                         c_null_ptr, c_null_funptr, c_null_char, c_funloc
  use fricreg_c
  use fricreg_sim_c
  use fricreg_base_m, only: fricreg_object, fricreg_error_string, as_size
  implicit none
  private
  public :: fricreg_simulation
  public :: fricreg_integrator_string, fricreg_integrator_id

  !> One of the paper's reference systems on a GSL ODE driver (include/fricreg_sim.h).
  type, extends(fricreg_object) :: fricreg_simulation
  contains
    procedure :: create => sim_create
    procedure :: set_param => sim_set_param
    procedure :: set_law => sim_set_law
    procedure :: set_partition => sim_set_partition
    procedure :: set_integrator => sim_set_integrator
    procedure :: set_observer => sim_set_observer
    procedure :: set_warning_handler => sim_set_warning_handler
    procedure :: set_max_steps => sim_set_max_steps
    procedure :: set_kink_location => sim_set_kink_location
    procedure :: set_error_estimate => sim_set_error_estimate
    procedure :: set_answer_rtol => sim_set_answer_rtol
    procedure :: set_abs_tolerances => sim_set_abs_tolerances
    procedure :: get_abs_tolerances => sim_get_abs_tolerances
    procedure :: run => sim_run
    procedure :: run_cycles => sim_run_cycles
    procedure :: ndof => sim_ndof
    procedure :: ncontacts => sim_ncontacts
    procedure :: get_value => sim_get_value
    procedure :: get_stat => sim_get_stat
    procedure :: get_param => sim_get_param
    procedure :: get_state => sim_get_state
    procedure :: get_dissipation => sim_get_dissipation
    procedure :: get_dissipation_error => sim_get_dissipation_error
    procedure :: get_dissipation_error_kind => sim_get_dissipation_error_kind
    procedure :: get_stick_fraction => sim_get_stick_fraction
    procedure :: run_extrapolated => sim_run_extrapolated
    procedure :: get_extrapolation => sim_get_extrapolation
    procedure :: get_extrapolated_dissipation => sim_get_extrapolated_dissipation
    final :: sim_final
  end type

contains

  ! ---- Simulations (fricreg_sim.h) ---------------------------------------------------------

  !> GSL's name of an integrator (FRICREG_INT_*), '' if unknown.
  function fricreg_integrator_string(integrator) result(name)
    integer(c_int), intent(in) :: integrator
    character(len=:), allocatable :: name
    name = fricreg_c_string(fricreg_integrator_name(integrator))
  end function fricreg_integrator_string

  !> The integrator (FRICREG_INT_*) with GSL's name, e.g. 'rk4' (trailing blanks ignored); 0
  !> if there is none.
  integer(c_int) function fricreg_integrator_id(name)
    character(len=*), intent(in) :: name
    fricreg_integrator_id = fricreg_integrator_from_name(trim(name) // c_null_char)
  end function fricreg_integrator_id

  !> A simulation of system (FRICREG_SYSTEM_*) with the paper's parameters, law (4), RK4,
  !> dt = 0.01 and the paper's eps rule. Replaces (and releases) any simulation self held.
  !> FRICREG_EINVAL for an unknown system; FRICREG_ENOMEM.
  function sim_create(self, system) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: system
    integer(c_int) :: status
    type(c_ptr) :: p
    character(len=32) :: buf
    p = c_null_ptr
    status = fricreg_sim_create(system, p)
    if (status /= FRICREG_OK) then
      write (buf, '(i0)') system
      status = self%fail(status, 'create: system ' // trim(buf) // ': ' // &
                         fricreg_error_string(status))
      return
    end if
    call self%adopt(p, fricreg_sim_free, fricreg_sim_errcode, fricreg_sim_errmsg)
  end function sim_create

  subroutine sim_final(self)
    type(fricreg_simulation), intent(inout) :: self
    call self%destroy()
  end subroutine sim_final

  !> One system parameter (FRICREG_PARAM_*); discards results. FRICREG_EINVAL for a parameter
  !> the system does not have or a value out of range; FRICREG_ENONFINITE.
  function sim_set_param(self, param, value) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: param
    real(c_double), intent(in) :: value
    integer(c_int) :: status
    status = self%ready('set_param', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_set_param(self%ptr, param, value))
  end function sim_set_param

  !> Law (FRICREG_LAW_*) and eps > 0; eps = 0 selects the paper's rule (2 dt, or 10 omega dt
  !> for the chain).
  function sim_set_law(self, law, eps) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps
    integer(c_int) :: status
    status = self%ready('set_law', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_set_law(self%ptr, law, eps))
  end function sim_set_law

  !> Partition of coupled contacts (FRICREG_PARTITION_*; C's fricreg_sim_set_partition).
  function sim_set_partition(self, partition) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: partition
    integer(c_int) :: status
    status = self%ready('set_partition', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_set_partition(self%ptr, partition))
  end function sim_set_partition

  !> Integrator (FRICREG_INT_*), step dt > 0, and rtol, atol (both omitted or 0: fixed step;
  !> rtol > 0 without atol: the absolute tolerances from eps, FRICREG_ATOL_FROM_EPS).
  function sim_set_integrator(self, integrator, dt, rtol, atol) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: integrator
    real(c_double), intent(in) :: dt
    real(c_double), intent(in), optional :: rtol, atol
    integer(c_int) :: status
    real(c_double) :: r, a
    ! FRICREG_ATOL_FROM_EPS of fricreg_sim.h (a double macro: gen_constants reads enums only);
    ! test_sim.f90 checks that an absent atol gives the rule's tolerances.
    real(c_double), parameter :: atol_from_eps = -1.0_c_double
    r = 0.0_c_double
    a = 0.0_c_double
    if (present(rtol)) r = rtol
    if (r > 0.0_c_double) a = atol_from_eps
    if (present(atol)) a = atol
    status = self%ready('set_integrator', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_set_integrator(self%ptr, integrator, dt, r, a))
  end function sim_set_integrator

  !> Install an observer (a bind(C) function with interface fricreg_sim_observer), called
  !> after every accepted step; user is passed back to it. With no observer, removes it.
  !> (The dummy's name is prefixed: gfortran gives a dummy of a bind(C) interface a binding
  !> label, which would clash with a caller's global name such as a module `observer`.)
  function sim_set_observer(self, fricreg_observer, user) result(status)
    class(fricreg_simulation), intent(inout) :: self
    procedure(fricreg_sim_observer), optional :: fricreg_observer
    type(c_ptr), intent(in), optional :: user
    integer(c_int) :: status
    type(c_funptr) :: fn
    type(c_ptr) :: u
    fn = c_null_funptr
    u = c_null_ptr
    if (present(fricreg_observer)) fn = c_funloc(fricreg_observer)
    if (present(user)) u = user
    status = self%ready('set_observer', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_set_observer(self%ptr, fn, u))
  end function sim_set_observer

  !> Route the simulation's warnings to a bind(C) subroutine with interface
  !> fricreg_warning_handler, called once per warning at the end of every run
  !> (fricreg_sim_set_warning_handler); user is passed back to it. With no handler, removes it.
  function sim_set_warning_handler(self, fricreg_handler, user) result(status)
    class(fricreg_simulation), intent(inout) :: self
    procedure(fricreg_warning_handler), optional :: fricreg_handler
    type(c_ptr), intent(in), optional :: user
    integer(c_int) :: status
    type(c_funptr) :: fn
    type(c_ptr) :: u
    fn = c_null_funptr
    u = c_null_ptr
    if (present(fricreg_handler)) fn = c_funloc(fricreg_handler)
    if (present(user)) u = user
    status = self%ready('set_warning_handler', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_set_warning_handler(self%ptr, fn, u))
  end function sim_set_warning_handler

  !> Bound the adaptive steps accepted in one forcing cycle (0: no bound; by default 10^4 for
  !> the laws that jump, 10^6 otherwise): a run that needs more returns FRICREG_EWORK
  !> (fricreg_sim_set_max_steps).
  function sim_set_max_steps(self, max_steps) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int64_t), intent(in) :: max_steps
    integer(c_int) :: status
    status = self%ready('set_max_steps', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_set_max_steps(self%ptr, max_steps))
  end function sim_set_max_steps

  !> Whether adaptive runs stop at the friction law's kinks and restart the stepper there
  !> (1, the default) or step over them (0) (fricreg_sim_set_kink_location).
  function sim_set_kink_location(self, on) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: on
    integer(c_int) :: status
    status = self%ready('set_kink_location', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_set_kink_location(self%ptr, on))
  end function sim_set_kink_location

  !> Whether runs estimate the error of D per cycle against eps -> 0: with companion runs at
  !> eps/2 and eps/4 (1, FRICREG_ESTIMATE_TWO_COMPANIONS), 1.6's one at eps/2 (2,
  !> FRICREG_ESTIMATE_ONE_COMPANION), or not (0, the default) (fricreg_sim_set_error_estimate).
  function sim_set_error_estimate(self, on) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: on
    integer(c_int) :: status
    status = self%ready('set_error_estimate', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_set_error_estimate(self%ptr, on))
  end function sim_set_error_estimate

  !> The answer tolerance rtol (finite, > 0; default 1e-2): FRICREG_WARN_ERROR_ESTIMATE where
  !> the last whole cycle's error estimate exceeds rtol |D| (and a round-off floor, 1e-12 of
  !> sum mun eps T), whatever its kind; kept across runs
  !> (fricreg_sim_set_answer_rtol). FRICREG_EINVAL otherwise, nothing changed. Since 1.8.
  function sim_set_answer_rtol(self, rtol) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(in) :: rtol
    integer(c_int) :: status
    status = self%ready('set_answer_rtol', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_set_answer_rtol(self%ptr, rtol))
  end function sim_set_answer_rtol

  !> An absolute tolerance per component of the state y = (x, v, D), size 2 ndof + 1: ndof
  !> positions, ndof velocities, then D; each finite and > 0; replaces set_integrator's atol
  !> until the next set_integrator (fricreg_sim_set_abs_tolerances).
  function sim_set_abs_tolerances(self, atol) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(in), contiguous :: atol(:)
    integer(c_int) :: status
    status = self%ready('set_abs_tolerances', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_set_abs_tolerances(self%ptr, &
                                           int(size(atol), c_size_t), atol))
  end function sim_set_abs_tolerances

  !> The absolute tolerances an adaptive run uses per component of y = (x, v, D), size
  !> 2 ndof + 1: the rule from eps (set_integrator with rtol and no atol), the one atol, or
  !> those of set_abs_tolerances; zeros for fixed steps (fricreg_sim_get_abs_tolerances).
  function sim_get_abs_tolerances(self, atol) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: atol(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    n = 2_c_size_t * fricreg_sim_ndof(self%ptr) + 1_c_size_t
    status = self%ready('get_abs_tolerances', 'simulation')
    if (status == FRICREG_OK) status = self%check_size('get_abs_tolerances', 'atol', size(atol), n)
    if (status == FRICREG_OK) status = self%unrecorded('get_abs_tolerances', &
                                           fricreg_sim_get_abs_tolerances(self%ptr, n, atol))
  end function sim_get_abs_tolerances

  !> Integrate from t = 0 to t_end > 0 (see fricreg_sim_run for the returns).
  function sim_run(self, t_end) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(in) :: t_end
    integer(c_int) :: status
    status = self%ready('run', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_run(self%ptr, t_end))
  end function sim_run

  !> Integrate `cycles` >= 1 whole forcing cycles.
  function sim_run_cycles(self, cycles) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer, intent(in) :: cycles
    integer(c_int) :: status
    status = self%ready('run_cycles', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_run_cycles(self%ptr, int(cycles, c_int)))
  end function sim_run_cycles

  !> Number of bodies: 1 (oscillator), n (chain), 2 (two blocks); 0 if not created.
  integer function sim_ndof(self)
    class(fricreg_simulation), intent(in) :: self
    sim_ndof = int(fricreg_sim_ndof(self%ptr))
  end function sim_ndof

  !> Number of contacts (equal to ndof in all three systems); 0 if not created.
  integer function sim_ncontacts(self)
    class(fricreg_simulation), intent(in) :: self
    sim_ncontacts = int(fricreg_sim_ncontacts(self%ptr))
  end function sim_ncontacts

  !> One quantity (FRICREG_VALUE_*) into value. FRICREG_EINVAL for an unknown one.
  function sim_get_value(self, which, value) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: which
    real(c_double), intent(inout) :: value
    integer(c_int) :: status
    status = self%ready('get_value', 'simulation')
    if (status == FRICREG_OK) &
      status = self%unrecorded('get_value', fricreg_sim_get_value(self%ptr, which, value))
  end function sim_get_value

  !> One integer counter of the last run (FRICREG_SIM_STAT_*) into value. FRICREG_EINVAL for
  !> an unknown counter.
  function sim_get_stat(self, which, value) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: which
    integer(c_int64_t), intent(inout) :: value
    integer(c_int) :: status
    status = self%ready('get_stat', 'simulation')
    if (status == FRICREG_OK) &
      status = self%unrecorded('get_stat', fricreg_sim_get_stat(self%ptr, which, value))
  end function sim_get_stat

  !> The value in use of a system parameter (FRICREG_PARAM_*): the paper's default or the
  !> value set. FRICREG_EINVAL for a parameter the system does not read.
  function sim_get_param(self, param, value) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: param
    real(c_double), intent(inout) :: value
    integer(c_int) :: status
    status = self%ready('get_param', 'simulation')
    if (status == FRICREG_OK) &
      status = self%unrecorded('get_param', fricreg_sim_get_param(self%ptr, param, value))
  end function sim_get_param

  !> State at the end of the last run (the initial state before one): x(ndof), v(ndof).
  function sim_get_state(self, x, v) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: x(:), v(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    n = fricreg_sim_ndof(self%ptr)
    status = self%ready('get_state', 'simulation')
    if (status == FRICREG_OK) status = self%check_size('get_state', 'x', size(x), n)
    if (status == FRICREG_OK) status = self%check_size('get_state', 'v', size(v), n)
    if (status == FRICREG_OK) &
      status = self%unrecorded('get_state', fricreg_sim_get_state(self%ptr, n, x, v))
  end function sim_get_state

  !> D per whole forcing cycle of the last run, D_k = -int sum_i w_i zdot_i f_i dt (w_i = 1/n
  !> for the chain, else 1): D is (re)allocated to the number of cycles completed.
  function sim_get_dissipation(self, D) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), allocatable, intent(inout) :: D(:)
    integer(c_int) :: status
    real(c_double) :: cycles
    real(c_double), allocatable :: tmp(:)
    cycles = 0.0_c_double
    status = self%ready('get_dissipation', 'simulation')
    if (status /= FRICREG_OK) return
    status = fricreg_sim_get_value(self%ptr, FRICREG_VALUE_CYCLES, cycles)
    if (status == FRICREG_OK) then
      allocate (tmp(max(1, int(cycles))))
      status = fricreg_sim_get_dissipation(self%ptr, int(cycles, c_size_t), tmp)
    end if
    status = self%unrecorded('get_dissipation', status)
    if (status == FRICREG_OK) D = tmp(1:int(cycles))
  end function sim_get_dissipation

  !> The error estimate of D per whole cycle of the last run (fricreg_sim_get_dissipation_error):
  !> err is (re)allocated to the number of cycles; FRICREG_EINVAL when the run made none.
  function sim_get_dissipation_error(self, err) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), allocatable, intent(inout) :: err(:)
    integer(c_int) :: status
    real(c_double) :: cycles
    real(c_double), allocatable :: tmp(:)
    cycles = 0.0_c_double
    status = self%ready('get_dissipation_error', 'simulation')
    if (status /= FRICREG_OK) return
    status = fricreg_sim_get_value(self%ptr, FRICREG_VALUE_CYCLES, cycles)
    if (status == FRICREG_OK) then
      allocate (tmp(max(1, int(cycles))))
      status = fricreg_sim_get_dissipation_error(self%ptr, int(cycles, c_size_t), tmp)
    end if
    status = self%unrecorded('get_dissipation_error', status)
    if (status == FRICREG_OK) err = tmp(1:int(cycles))
  end function sim_get_dissipation_error

  !> The kind of each whole cycle's error estimate of the last run
  !> (fricreg_sim_get_dissipation_error_kind): kinds is (re)allocated to the number of cycles,
  !> each FRICREG_EST_KIND_ASYMPTOTIC, _BOUND or _ASSUMED; FRICREG_EINVAL when the run made no
  !> estimate. Since 1.8.
  function sim_get_dissipation_error_kind(self, kinds) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), allocatable, intent(inout) :: kinds(:)
    integer(c_int) :: status
    real(c_double) :: cycles
    integer(c_int), allocatable :: tmp(:)
    cycles = 0.0_c_double
    status = self%ready('get_dissipation_error_kind', 'simulation')
    if (status /= FRICREG_OK) return
    status = fricreg_sim_get_value(self%ptr, FRICREG_VALUE_CYCLES, cycles)
    if (status == FRICREG_OK) then
      allocate (tmp(max(1, int(cycles))))
      status = fricreg_sim_get_dissipation_error_kind(self%ptr, int(cycles, c_size_t), tmp)
    end if
    status = self%unrecorded('get_dissipation_error_kind', status)
    if (status == FRICREG_OK) kinds = tmp(1:int(cycles))
  end function sim_get_dissipation_error_kind

  !> Per contact, the fraction of the last whole cycle with |zdot_i| < eps: frac(ncontacts).
  function sim_get_stick_fraction(self, frac) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: frac(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_sim_ncontacts(self%ptr)
    status = self%ready('get_stick_fraction', 'simulation')
    if (status == FRICREG_OK) status = self%check_size('get_stick_fraction', 'frac', size(frac), m)
    if (status == FRICREG_OK) status = self%unrecorded('get_stick_fraction', &
                                           fricreg_sim_get_stick_fraction(self%ptr, m, frac))
  end function sim_get_stick_fraction

  !> Run at eps, eps/2, …, eps/2^(levels-1) and extrapolate D to eps -> 0 with an error
  !> estimate (fricreg_sim_run_extrapolated: levels 2 … 8; order 0 … 4, the declared leading
  !> order used where none is observed, 0 meaning 1; optional, default 0). window (optional,
  !> default 0: the whole run): the finer levels over the last `window` cycles only, from
  !> level 0's state there (fricreg_sim_run_extrapolated_window; the estimates it cannot give
  !> are +infinity).
  function sim_run_extrapolated(self, t_end, levels, order, window) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(in) :: t_end
    integer, intent(in) :: levels
    integer, intent(in), optional :: order, window
    integer(c_int) :: status, declared, last
    declared = 0
    last = 0
    if (present(order)) declared = int(order, c_int)
    if (present(window)) last = int(window, c_int)
    status = self%ready('run_extrapolated', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_run_extrapolated_window(self%ptr, &
                                                    t_end, int(levels, c_int), declared, last))
  end function sim_run_extrapolated

  !> One quantity of the last extrapolated run (FRICREG_EXTRAP_*) into value. FRICREG_EINVAL
  !> for an unknown one or when none is held.
  function sim_get_extrapolation(self, which, value) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: which
    real(c_double), intent(inout) :: value
    integer(c_int) :: status
    status = self%ready('get_extrapolation', 'simulation')
    if (status == FRICREG_OK) status = self%unrecorded('get_extrapolation', &
                                           fricreg_sim_get_extrapolation(self%ptr, which, value))
  end function sim_get_extrapolation

  !> The extrapolated D per whole cycle and its error estimate: D and err are (re)allocated
  !> to the number of cycles completed. FRICREG_EINVAL when no extrapolation is held.
  function sim_get_extrapolated_dissipation(self, D, err) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), allocatable, intent(inout) :: D(:), err(:)
    integer(c_int) :: status
    real(c_double) :: cycles
    real(c_double), allocatable :: tmp(:), tmp_err(:)
    cycles = 0.0_c_double
    status = self%ready('get_extrapolated_dissipation', 'simulation')
    if (status /= FRICREG_OK) return
    status = fricreg_sim_get_value(self%ptr, FRICREG_VALUE_CYCLES, cycles)
    if (status == FRICREG_OK) then
      allocate (tmp(max(1, int(cycles))), tmp_err(max(1, int(cycles))))
      status = fricreg_sim_get_extrapolated_dissipation(self%ptr, int(cycles, c_size_t), tmp, &
                                                        tmp_err)
    end if
    status = self%unrecorded('get_extrapolated_dissipation', status)
    if (status == FRICREG_OK) then
      D = tmp(1:int(cycles))
      err = tmp_err(1:int(cycles))
    end if
  end function sim_get_extrapolated_dissipation

end module fricreg_sim_m
