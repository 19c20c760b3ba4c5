! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_sim_c.f90 — module fricreg_sim_c: thin bind(C) interfaces to every function of the
! public headers beside fricreg.h: fricreg_sim.h (the GSL ODE drivers of the paper's three
! reference systems), fricreg_exact.h (the exact solution of the oscillator),
! fricreg_structure.h (a linear structure with friction), and any header
! added to the library's public list later.
!
! As in module fricreg_c, the interfaces are generated from the C prototypes at build time
! (fricreg_drivers_h.inc): argument for argument, scalars by value, arrays
! dimension(*), the simulation or solution as type(c_ptr), size_t as integer(c_size_t),
! omitted pointer arguments passed as NULL; the docstrings of include/fricreg_sim.h and
! include/fricreg_exact.h apply unchanged. The idiomatic layer is types fricreg_simulation and
! fricreg_exact_solution in module fricreg. Built only with the drivers (FRICREG_DRIVERS).
!
! Public: the generated interfaces and the abstract interfaces fricreg_sim_observer,
! fricreg_structure_observer and fricreg_warning_handler.
module fricreg_sim_c
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_ptr, &
                                         c_funptr, c_char
  implicit none
  private
  include 'fricreg_drivers_h_public.inc'
  public :: fricreg_sim_observer, fricreg_structure_observer, fricreg_warning_handler
  public :: fricreg_hb_monitor

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
    !> A structure's observer (fricreg_structure_observer): called after every step of run
    !> and every GSL step of run_ode with the displacements u, velocities v and the m friction
    !> forces f at time t, valid during the call only. Return 0 to go on, nonzero to stop the
    !> run there. Write it as a bind(C) function and pass it to the structure's set_observer.
    function fricreg_structure_observer(user, t, ndof, u, v, m, f) bind(C) result(stop_run)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: user
      real(c_double), value :: t
      integer(c_size_t), value :: ndof
      real(c_double), intent(in) :: u(ndof), v(ndof)
      integer(c_size_t), value :: m
      real(c_double), intent(in) :: f(m)
      integer(c_int) :: stop_run
    end function
    !> A warning handler (fricreg_warning_handler of fricreg.h): called once for each warning
    !> of a run, with its code (FRICREG_WARN_*), its message as a C string (fricreg_c_string
    !> converts it; valid during the call only) and user as given to set_warning_handler.
    !> Write it as a bind(C) subroutine and pass it to the simulation's or the structure's
    !> set_warning_handler.
    subroutine fricreg_warning_handler(code, message, user) bind(C)
      import :: c_int, c_ptr
      integer(c_int), value :: code
      type(c_ptr), value :: message
      type(c_ptr), value :: user
    end subroutine
    !> A harmonic-balance driver's monitor (fricreg_hb_monitor of fricreg_hb.h): called before
    !> every Newton step of a solve with the steps taken in this call so far, the continued
    !> parameter (Omega, the level or the modal amplitude) and the largest residual entry over
    !> Newton's bound. Return 0 to go on, nonzero to stop the call (FRICREG_EWORK). Write it as
    !> a bind(C) function and pass it to the driver's set_monitor.
    function fricreg_hb_monitor(user, iterations, parameter, residual) bind(C) result(stop_solve)
      import :: c_int, c_int64_t, c_double, c_ptr
      type(c_ptr), value :: user
      integer(c_int64_t), value :: iterations
      real(c_double), value :: parameter, residual
      integer(c_int) :: stop_solve
    end function
  end interface

  interface
    include 'fricreg_drivers_h.inc'
  end interface

end module fricreg_sim_c
