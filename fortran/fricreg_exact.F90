! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_exact.F90 — module fricreg_exact_m: type fricreg_exact_solution, the exact solution of
! the oscillator (fricreg_exact.h), and its procedures. Built with the drivers only
! (FRICREG_DRIVERS).
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_exact_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_null_ptr
  use fricreg_c
  use fricreg_sim_c
  use fricreg_base_m, only: fricreg_object
  implicit none
  private
  public :: fricreg_exact_solution

  !> The exact solution of the oscillator, Eq. (5), under (1)+(2) (include/fricreg_exact.h):
  !> its switching times, state in closed form, and dissipation per cycle.
  type, extends(fricreg_object) :: fricreg_exact_solution
  contains
    procedure :: solve => exact_solve
    procedure :: state => exact_state
    procedure :: nswitches => exact_nswitches
    procedure :: switches => exact_switches
    procedure :: ncycles => exact_ncycles
    procedure :: dissipation => exact_dissipation
    procedure :: stick_fraction => exact_stick_fraction
    final :: exact_final
  end type

contains

  ! ---- Exact solution of the oscillator (fricreg_exact.h) ----------------------------------
  ! Failures of solve carry the C solver's message; its getters record none (const in C).

  !> Solve Eq. (5) under (1)+(2), x'' + x = f + a sin(omega t), from x(0) = x0, x'(0) = v0
  !> over 0 <= t <= t_end (nondimensional, as in the paper). Replaces (and releases) any
  !> solution self held; on failure keeps it, and errmsg names the argument or value.
  !> FRICREG_EINVAL (omega <= 0, mun < 0, t_end <= 0 or above 10^6 cycles);
  !> FRICREG_ENONFINITE; FRICREG_ENOMEM; FRICREG_EINTEGRATOR.
  function exact_solve(self, a, omega, mun, x0, v0, t_end) result(status)
    class(fricreg_exact_solution), intent(inout) :: self
    real(c_double), intent(in) :: a, omega, mun, x0, v0, t_end
    integer(c_int) :: status
    type(c_ptr) :: p
    p = c_null_ptr
    status = self%unrecorded('solve', fricreg_exact_create(a, omega, mun, x0, v0, p))
    if (status /= FRICREG_OK) return
    status = fricreg_exact_run(p, t_end)
    if (status == FRICREG_OK) then
      call self%adopt(p, fricreg_exact_free, fricreg_exact_errcode, fricreg_exact_errmsg)
    else
      status = self%fail(status, 'solve: ' // fricreg_c_string(fricreg_exact_errmsg(p)))
      call fricreg_exact_free(p)
    end if
  end function exact_solve

  subroutine exact_final(self)
    type(fricreg_exact_solution), intent(inout) :: self
    call self%destroy()
  end subroutine exact_final

  !> Position x and velocity v at time t, 0 <= t <= t_end, in closed form.
  !> FRICREG_EINVAL if t is outside [0, t_end].
  function exact_state(self, t, x, v) result(status)
    class(fricreg_exact_solution), intent(inout) :: self
    real(c_double), intent(in) :: t
    real(c_double), intent(inout) :: x, v
    integer(c_int) :: status
    status = self%ready('state', 'solution', 'solve')
    if (status == FRICREG_OK) &
      status = self%unrecorded('state', fricreg_exact_state(self%ptr, t, x, v))
  end function exact_state

  !> Number of switches (phase changes after t = 0) up to t_end; 0 if not solved.
  integer function exact_nswitches(self)
    class(fricreg_exact_solution), intent(in) :: self
    exact_nswitches = int(fricreg_exact_nswitches(self%ptr))
  end function exact_nswitches

  !> Switching times, increasing, into times (reallocated to nswitches()); with sticks,
  !> sticks(k) is .true. where the phase starting at times(k) is a stick, .false. for a slip.
  function exact_switches(self, times, sticks) result(status)
    class(fricreg_exact_solution), intent(inout) :: self
    real(c_double), allocatable, intent(inout) :: times(:)
    logical, allocatable, intent(inout), optional :: sticks(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    real(c_double), allocatable :: t(:)
    integer(c_int), allocatable :: s(:)
    n = fricreg_exact_nswitches(self%ptr)
    allocate (t(max(1_c_size_t, n)), s(max(1_c_size_t, n)))
    status = self%ready('switches', 'solution', 'solve')
    if (status == FRICREG_OK) &
      status = self%unrecorded('switches', fricreg_exact_switches(self%ptr, n, t, s))
    if (status /= FRICREG_OK) return
    times = t(1:n)
    if (present(sticks)) sticks = s(1:n) /= 0
  end function exact_switches

  !> Number of whole forcing cycles 2 pi/omega in [0, t_end]; 0 if not solved.
  integer function exact_ncycles(self)
    class(fricreg_exact_solution), intent(in) :: self
    exact_ncycles = int(fricreg_exact_ncycles(self%ptr))
  end function exact_ncycles

  !> Dissipation D_k = -int x' f dt of each whole cycle, mun times the distance slid in it:
  !> D is (re)allocated to ncycles().
  function exact_dissipation(self, D) result(status)
    class(fricreg_exact_solution), intent(inout) :: self
    real(c_double), allocatable, intent(inout) :: D(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    real(c_double), allocatable :: tmp(:)
    n = fricreg_exact_ncycles(self%ptr)
    allocate (tmp(max(1_c_size_t, n)))
    status = self%ready('dissipation', 'solution', 'solve')
    if (status == FRICREG_OK) &
      status = self%unrecorded('dissipation', fricreg_exact_dissipation(self%ptr, n, tmp))
    if (status == FRICREG_OK) D = tmp(1:n)
  end function exact_dissipation

  !> Fraction of time at rest within [t0, t1], 0 <= t0 < t1 <= t_end, into fraction.
  !> FRICREG_EINVAL for a bad interval.
  function exact_stick_fraction(self, t0, t1, fraction) result(status)
    class(fricreg_exact_solution), intent(inout) :: self
    real(c_double), intent(in) :: t0, t1
    real(c_double), intent(inout) :: fraction
    integer(c_int) :: status
    status = self%ready('stick_fraction', 'solution', 'solve')
    if (status == FRICREG_OK) status = self%unrecorded('stick_fraction', &
                                       fricreg_exact_stick_fraction(self%ptr, t0, t1, fraction))
  end function exact_stick_fraction

end module fricreg_exact_m
