! SPDX-License-Identifier: GPL-3.0-or-later
! test_exact.f90 — the exact solution of the oscillator, Eq. (5) under (1)+(2), through type
! fricreg_exact_solution and the bind(C) layer (include/fricreg_exact.h), against closed forms:
! - unforced from (2.75, 0), mun = 1 (the paper's case, Sec. 3.1.1): x = 1 + 1.75 cos t while
!   sliding, one switch at t = pi into a stick at x = -0.75 (|f_eq| = 0.75 <= mun) for ever;
!   cycle 1 (T = 2 pi) slides 3.5, so D = (3.5, 0, 0) over t_end = 20 (3 whole cycles);
! - unforced from (-3.1, 0), mun = 0.731: half-cycles about the offset sgn(x) mun end at the
!   mirror points 1.638 (t = pi, a reversal) and -0.176 (t = 2 pi, a stick, |x| <= mun), so
!   D of cycle 1 = 0.731 (4.738 + 1.814) = 4.789512 (tests/exact/test_exact.c derives the same).
! The C test of the same cases is tests/exact/test_exact.c; the tolerances are a few ulps.
program test_exact
  use fricreg
  use ftest
  implicit none
  real(c_double), parameter :: pi = acos(-1.0_c_double), tol = 1e-14_c_double
  real(c_double), parameter :: sentinel = -777.125_c_double
  type(fricreg_exact_solution) :: ex, other
  real(c_double), allocatable :: times(:), D(:)
  logical, allocatable :: sticks(:)
  real(c_double), parameter :: sliding(4) = [0.2385_c_double, 1.0_c_double, 1.7318_c_double, &
                                              3.1_c_double]
  real(c_double) :: x, v, xc, vc, frac, t
  integer :: i

  ! ---- The paper's unforced case.
  call check_status(ex%solve(0.0_c_double, 1.0_c_double, 1.0_c_double, 2.75_c_double, &
                             0.0_c_double, 20.0_c_double), FRICREG_OK, 'solve, x0 = 2.75')
  call check(ex%is_created(), 'solve creates the solution')
  call check(ex%nswitches() == 1, 'one switch')
  call check_status(ex%switches(times, sticks), FRICREG_OK, 'switches')
  call check(size(times) == 1 .and. size(sticks) == 1, 'switches sized by nswitches()')
  call check_close(times(1), pi, tol, 'the switch is at t = pi')
  call check(sticks(1), 'the phase starting at pi is a stick')
  do i = 1, size(sliding)
    t = sliding(i)
    call check_status(ex%state(t, x, v), FRICREG_OK, 'state while sliding')
    call check_close(x, 1.0_c_double + 1.75_c_double * cos(t), tol, 'x = 1 + 1.75 cos t')
    call check_close(v, -1.75_c_double * sin(t), tol, 'v = -1.75 sin t')
  end do
  call check_status(ex%state(7.3519_c_double, x, v), FRICREG_OK, 'state at rest')
  call check_close(x, -0.75_c_double, tol, 'rest at x = -0.75')
  call check(v == 0.0_c_double, 'v = 0 at rest')
  call check(ex%ncycles() == 3, 'three whole cycles in t_end = 20')
  call check_status(ex%dissipation(D), FRICREG_OK, 'dissipation')
  call check(size(D) == 3, 'D sized by ncycles()')
  call check_close(D(1), 3.5_c_double, tol, 'D of cycle 1 = mun * 3.5')
  call check(D(2) == 0.0_c_double .and. D(3) == 0.0_c_double, 'no dissipation at rest')
  call check_status(ex%stick_fraction(0.0_c_double, 2.0_c_double * pi, frac), FRICREG_OK, &
                    'stick_fraction over cycle 1')
  call check_close(frac, 0.5_c_double, tol, 'at rest half of cycle 1')

  ! The bind(C) layer on the same object gives the same numbers, bit for bit.
  call check(fricreg_exact_nswitches(ex%handle()) == 1_c_size_t, 'fricreg_exact_nswitches')
  call check_status(fricreg_exact_state(ex%handle(), 1.7318_c_double, xc, vc), FRICREG_OK, &
                    'fricreg_exact_state on handle()')
  call check_status(ex%state(1.7318_c_double, x, v), FRICREG_OK, 'state at 1.7318')
  call check_bits(xc, x, 'x through both layers')
  call check_bits(vc, v, 'v through both layers')

  ! ---- Two half-cycles, mun = 0.731 (a reversal, then a stick).
  call check_status(ex%solve(0.0_c_double, 1.0_c_double, 0.731_c_double, -3.1_c_double, &
                             0.0_c_double, 4.0_c_double * pi + 0.5_c_double), FRICREG_OK, &
                    'solve again on the same object, x0 = -3.1')
  call check_status(ex%switches(times, sticks), FRICREG_OK, 'switches, mun = 0.731')
  call check(size(times) == 2, 'two switches')
  call check_close(times(1), pi, 1e-13_c_double, 'reversal at pi')
  call check_close(times(2), 2.0_c_double * pi, 2e-13_c_double, 'stick at 2 pi')
  call check(.not. sticks(1) .and. sticks(2), 'a slip, then a stick')
  call check_status(ex%state(times(1), x, v), FRICREG_OK, 'state at the reversal')
  call check_close(x, 1.638_c_double, 1e-13_c_double * 3.1_c_double, 'mirror point 1.638')
  call check_status(ex%state(4.0_c_double * pi, x, v), FRICREG_OK, 'state at rest')
  call check_close(x, -0.176_c_double, 1e-13_c_double * 3.1_c_double, 'rest at -0.176')
  call check_status(ex%dissipation(D), FRICREG_OK, 'dissipation, mun = 0.731')
  call check(size(D) == 2, 'two whole cycles')
  call check_close(D(1), 4.789512_c_double, 1e-13_c_double * 4.789512_c_double, &
                   'D of cycle 1 = 0.731 * 6.552')

  ! ---- Errors: C's codes, Fortran's messages (the C solver keeps none), outputs untouched.
  x = sentinel
  v = sentinel
  call check_status(ex%state(13.7_c_double, x, v), FRICREG_EINVAL, 'state beyond t_end')
  call check(x == sentinel .and. v == sentinel, 'x, v untouched on failure')
  call check_status(ex%errcode(), FRICREG_EINVAL, 'errcode after a bad t')
  call check(ex%errmsg() == 'state: ' // fricreg_error_string(FRICREG_EINVAL), &
             'message: ' // ex%errmsg())
  frac = sentinel
  call check_status(ex%stick_fraction(2.5_c_double, 1.5_c_double, frac), FRICREG_EINVAL, &
                    'stick_fraction, t1 < t0')
  call check(frac == sentinel, 'fraction untouched on failure')
  call check_status(ex%solve(0.0_c_double, 0.0_c_double, 1.0_c_double, 2.75_c_double, &
                             0.0_c_double, 20.0_c_double), FRICREG_EINVAL, 'solve, omega = 0')
  call check(ex%is_created() .and. ex%nswitches() == 2, 'a failed solve keeps the old solution')
  call check(index(ex%errmsg(), 'solve: ') == 1, 'message: ' // ex%errmsg())
  ! A run the C solver refuses carries its message (naming t_end), not the code's text only.
  call check_status(ex%solve(0.0_c_double, 1.0_c_double, 1.0_c_double, 2.75_c_double, &
                             0.0_c_double, 1e9_c_double), FRICREG_EINVAL, 'solve, 1e9 > 10^6 cycles')
  call check(index(ex%errmsg(), 'solve: ') == 1 .and. index(ex%errmsg(), 't_end') > 0, &
             'message: ' // ex%errmsg())

  ! ---- Not copied: `other = ex` leaves other empty; destroy twice; calls on an empty object.
  other = ex
  call check(.not. other%is_created() .and. ex%is_created(), 'assignment leaves lhs empty')
  call check_status(other%state(1.0_c_double, x, v), FRICREG_ENULL, 'state on the empty copy')
  call check(other%errmsg() == 'state: the solution is not created (call solve)', &
             'message: ' // other%errmsg())
  call ex%destroy()
  call ex%destroy()
  call check(.not. ex%is_created() .and. ex%nswitches() == 0 .and. ex%ncycles() == 0, &
             'destroy, twice, empties the object')
  call check_status(ex%dissipation(D), FRICREG_ENULL, 'dissipation after destroy')
  call check(size(D) == 2, 'D untouched on failure')
  deallocate (times, sticks, D) ! so that valgrind --leak-check sees no block of ours left
  call finish('test_exact')
end program test_exact
