! SPDX-License-Identifier: GPL-3.0-or-later
! test_errors.f90 — sizes that do not match the context, and bad values, return the error
! codes of include/fricreg.h, leave the outputs alone, and leave a message naming the argument.
! Size checks are made in Fortran before C is called, so a wrong size never reaches memory.
program test_errors
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
  use fricreg
  use ftest
  implicit none
  real(c_double), parameter :: sentinel = -777.125_c_double
  type(fricreg_context) :: ctx
  real(c_double) :: nan, inf, f(3), f_eq(3), two(2), W(2, 2), W3(3, 3), W23(2, 3)
  integer(c_int64_t) :: value

  nan = ieee_value(1.0_c_double, ieee_quiet_nan)
  inf = ieee_value(1.0_c_double, ieee_positive_inf)
  two = [0.0_c_double, 0.0_c_double]

  call check_status(ctx%create(0), FRICREG_EINVAL, 'create(0)')
  call check(ctx%errmsg() == 'create: m = 0 must be >= 1', 'message: ' // ctx%errmsg())
  call check_status(ctx%create(-3), FRICREG_EINVAL, 'create(-3)')
  call check_status(ctx%create(2**27), FRICREG_EINVAL, 'create(2**27), above 2**26')
  call check(.not. ctx%is_created(), 'no context after a failed create')
  call check_status(ctx%errcode(), FRICREG_EINVAL, 'errcode after a failed create')
  call check_status(ctx%create(2), FRICREG_OK, 'create(2)')

  ! Sizes: every array of every call.
  call check_status(ctx%set_bounds([1.0_c_double, 1.0_c_double, 1.0_c_double]), FRICREG_ESIZE, &
                    'set_bounds, 3 bounds for 2 contacts')
  call check(ctx%errmsg() == 'set_bounds: size(mun) = 3, expected 2', 'message: ' // ctx%errmsg())
  call check_status(ctx%errcode(), FRICREG_ESIZE, 'errcode after a size mismatch')
  call check_status(ctx%set_coupling_diagonal([1.0_c_double]), FRICREG_ESIZE, &
                    'set_coupling_diagonal, 1 weight for 2 contacts')
  W3 = 0.0_c_double
  W23 = 0.0_c_double
  call check_status(ctx%set_coupling_dense(W3), FRICREG_ESIZE, 'set_coupling_dense, 3 x 3')
  call check_status(ctx%set_coupling_dense(W23), FRICREG_ESIZE, 'set_coupling_dense, 2 x 3')
  call check(ctx%errmsg() == 'set_coupling_dense: size(W, 2) = 3, expected 2', &
             'message: ' // ctx%errmsg())
  f = sentinel
  f_eq = sentinel
  call check_status(ctx%eval(f(1:3), two, f(1:2)), FRICREG_ESIZE, 'eval, size(zdot) = 3')
  call check_status(ctx%eval(two, f(1:1), f(2:3)), FRICREG_ESIZE, 'eval, size(a_free) = 1')
  call check_status(ctx%eval(two, two, f), FRICREG_ESIZE, 'eval, size(f) = 3')
  call check_status(ctx%eval(two, two, f(1:2), f_eq), FRICREG_ESIZE, 'eval, size(f_eq) = 3')
  call check(ctx%errmsg() == 'eval: size(f_eq) = 3, expected 2', 'message: ' // ctx%errmsg())
  call check(all(f == sentinel) .and. all(f_eq == sentinel), 'outputs untouched on ESIZE')

  ! Bad values, found by the C library, with its messages (indices from 0).
  call check_status(ctx%set_law(0_c_int, 0.02_c_double), FRICREG_EINVAL, 'set_law, law 0')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN + 1_c_int, 0.02_c_double), FRICREG_EINVAL, &
                    'set_law, law 7')
  call check(index(ctx%errmsg(), 'unknown law 7') > 0, 'message: ' // ctx%errmsg())
  call check_status(ctx%errcode(), FRICREG_EINVAL, 'errcode follows the C failure')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN, 0.0_c_double), FRICREG_EINVAL, 'eps = 0')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN, -0.02_c_double), FRICREG_EINVAL, 'eps < 0')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN, nan), FRICREG_ENONFINITE, 'eps = NaN')
  call check_status(ctx%set_bounds([0.5_c_double, -0.25_c_double]), FRICREG_EINVAL, 'mun < 0')
  call check(index(ctx%errmsg(), 'mun[1]') > 0, 'message names mun[1]: ' // ctx%errmsg())
  call check_status(ctx%set_bounds([0.5_c_double, inf]), FRICREG_ENONFINITE, 'mun = Inf')
  call check_status(ctx%set_coupling_diagonal([1.0_c_double, 0.0_c_double]), FRICREG_EINVAL, &
                    'diagonal w = 0')
  W = reshape([1.0_c_double, -1.0_c_double, -0.5_c_double, 2.0_c_double], [2, 2])
  call check_status(ctx%set_coupling_dense(W), FRICREG_ENOTSYM, 'W not symmetric')
  W = reshape([1.0_c_double, 2.0_c_double, 2.0_c_double, 1.0_c_double], [2, 2])
  call check_status(ctx%set_coupling_dense(W), FRICREG_ENOTPSD, 'W indefinite')
  W(1, 1) = nan
  call check_status(ctx%set_coupling_dense(W), FRICREG_ENONFINITE, 'W with a NaN')
  call check_status(ctx%eval([nan, 0.0_c_double], two, f(1:2)), FRICREG_ENONFINITE, &
                    'eval, zdot NaN')
  call check_status(ctx%eval(two, [0.0_c_double, inf], f(1:2)), FRICREG_ENONFINITE, &
                    'eval, a_free Inf')
  call check(index(ctx%errmsg(), 'a_free[1]') > 0, 'message names a_free[1]: ' // ctx%errmsg())
  call check(all(f == sentinel), 'f untouched on ENONFINITE')
  value = -5
  call check_status(ctx%get_stat(6_c_int, value), FRICREG_EINVAL, 'get_stat, counter 6')
  call check(value == -5, 'value untouched')

  ! A size mismatch after a C failure is the newer message, and the reverse.
  call check_status(ctx%set_bounds([1.0_c_double]), FRICREG_ESIZE, 'set_bounds, 1 bound')
  call check(index(ctx%errmsg(), 'size(mun) = 1') > 0, 'newest message is Fortran''s')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN, -1.0_c_double), FRICREG_EINVAL, 'eps = -1')
  call check(index(ctx%errmsg(), 'eps') > 0 .and. ctx%errcode() == FRICREG_EINVAL, &
             'newest message is C''s: ' // ctx%errmsg())

  ! Redundant contacts: W = [[1, 1], [1, 1]] is semidefinite, and W_SS singular at rest.
  W = 1.0_c_double
  call check_status(ctx%set_coupling_dense(W), FRICREG_OK, 'W semidefinite and singular')
  call check_status(ctx%eval(two, [0.1_c_double, 0.1_c_double], f(1:2)), FRICREG_ESINGULAR, &
                    'eval, singular W_SS')
  call check(all(f == sentinel), 'f untouched on ESINGULAR')
  call ctx%destroy()
  call finish('test_errors')
end program test_errors
