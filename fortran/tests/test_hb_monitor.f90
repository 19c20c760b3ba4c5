! SPDX-License-Identifier: GPL-3.0-or-later
! test_hb_monitor.f90 — a harmonic-balance driver's monitor and work bound from Fortran:
! hb%set_monitor with a bind(C) function of interface fricreg_hb_monitor, hb%set_max_iterations.
!
! The oscillator of test_hb.f90 with an element that slips (mun = 0.1): Newton takes several
! steps. The monitor counts its calls and sees the step count 1, 2, ... and Omega; told to stop
! at its 2nd call, the solve returns FRICREG_EWORK after exactly 2 calls with q untouched; with
! no monitor, the solution equals the watched one bit for bit; a bound of 1 step stops it, 0
! lifts the bound.
module hb_monitor_counter
  use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_ptr
  implicit none
  integer :: calls = 0, stop_at = 0
  logical :: in_order = .true.
  real(c_double) :: last_parameter = -1.0_c_double
contains
  function count_steps(user, iterations, parameter, residual) bind(C) result(stop_solve)
    type(c_ptr), value :: user
    integer(c_int64_t), value :: iterations
    real(c_double), value :: parameter, residual
    integer(c_int) :: stop_solve
    calls = calls + 1
    if (iterations /= calls .or. .not. (residual >= 0.0_c_double)) in_order = .false.
    last_parameter = parameter
    stop_solve = 0
    if (calls == stop_at) stop_solve = 1
  end function count_steps
end module hb_monitor_counter

program test_hb_monitor
  use fricreg
  use ftest
  use hb_monitor_counter
  implicit none
  type(fricreg_hb_driver) :: hb
  real(c_double), parameter :: w = 1.2_c_double
  real(c_double) :: q(7, 1), qw(7, 1), q0(7, 1)

  call check_status(hb%create(1, 1, 3), FRICREG_OK, 'create')
  call check_status(hb%set_mass(reshape([2.0_c_double], [1, 1])), FRICREG_OK, 'set_mass')
  call check_status(hb%set_stiffness(reshape([3.0_c_double], [1, 1])), FRICREG_OK, 'set_stiffness')
  call check_status(hb%set_rayleigh(0.0_c_double, 0.02_c_double), FRICREG_OK, 'set_rayleigh')
  call check_status(hb%set_elements(reshape([1.0_c_double], [1, 1]), [1.5_c_double], &
                                    [0.1_c_double]), FRICREG_OK, 'set_elements')
  call check_status(hb%set_excitation([0.5_c_double], [0.0_c_double]), FRICREG_OK, 'excitation')
  q0 = 0.0_c_double ! Newton from the stuck response: its steps are the monitor's calls

  call check_status(hb%set_monitor(count_steps), FRICREG_OK, 'set_monitor')
  call check_status(hb%solve(w, qw, q0), FRICREG_OK, 'watched solve')
  call check(calls >= 2 .and. in_order, 'the monitor saw the steps 1, 2, ... in order')
  call check_close(last_parameter, 1.0_c_double, 0.0_c_double, 'a solve with a guess: level 1')

  calls = 0
  stop_at = 2
  q = -7.0_c_double
  call check_status(hb%solve(w, q, q0), FRICREG_EWORK, 'stopped at the second step')
  call check(calls == 2, 'two monitor calls')
  call check(all(q == -7.0_c_double), 'stopped: q untouched')
  call check(index(hb%errmsg(), 'stopped by the monitor') > 0, 'the message says why')

  call check_status(hb%set_monitor(), FRICREG_OK, 'monitor removed')
  calls = 0
  call check_status(hb%solve(w, q, q0), FRICREG_OK, 'unwatched solve')
  call check(calls == 0, 'no monitor call')
  call check(all(q == qw), 'unwatched: the watched solution bit for bit')

  call check_status(hb%set_max_iterations(1_c_int64_t), FRICREG_OK, 'set_max_iterations(1)')
  call check_status(hb%solve(w, q, q0), FRICREG_EWORK, 'one step is not enough')
  call check_status(hb%set_max_iterations(-1_c_int64_t), FRICREG_EINVAL, 'a negative bound')
  call check_status(hb%set_max_iterations(0_c_int64_t), FRICREG_OK, 'no bound')
  call check_status(hb%solve(w, q, q0), FRICREG_OK, 'unbounded again')
  call check(all(q == qw), 'unbounded: the same solution bit for bit')
  call hb%destroy()
  call finish('test_hb_monitor')
end program test_hb_monitor
