! SPDX-License-Identifier: GPL-3.0-or-later
! test_disk_ctx.f90 — coupled 2-D contacts (fricreg_disk_ctx.h) from Fortran: the type
! fricreg_disk_context of module fricreg and the F77 entry points FRD*, against hand-worked
! values and against the C functions called through the generated bind(C) interfaces.
!
! Values: mun = 2, eps = 0.5, W = I; contact 1 at rest with f_eq = -a_free = (3, 4): saturated,
! f = (1.2, 1.6); contact 2 at v = (0.125, 0) with f_eq = (0, 3) (the inscribed disk: centre
! (-0.5, 0), radius 1.5; f_eq - 2a u = (-1, 3)): f = (-0.5, 0) + 1.5 (-0.5, 3)/sqrt(9.25);
! contact 3 slides at v = (1, 0): f = (-2, 0) (test_disk.f90 has the same numbers for one
! contact).
program test_disk_ctx
  use fricreg
  use ftest
  implicit none
  type(fricreg_disk_context) :: ctx
  real(c_double), parameter :: tol = 1e-15_c_double
  real(c_double) :: v(2, 3), a(2, 3), f(2, 3), f77(2, 3), w(2, 2, 3), mun(3)
  real(c_double) :: Wd(6, 6), T(6, 6), Tc(6, 6), T77(6, 6), A77(6, 6), bad(2, 2)
  integer(c_int) :: status
  integer(c_int64_t) :: h
  integer :: stat, i, j, code
  character(len=80) :: msg

  v = reshape([0.0_c_double, 0.0_c_double, 0.125_c_double, 0.0_c_double, 1.0_c_double, &
               0.0_c_double], [2, 3])
  a = reshape([-3.0_c_double, -4.0_c_double, 0.0_c_double, -3.0_c_double, 7.0_c_double, &
               7.0_c_double], [2, 3])
  mun = 2.0_c_double
  w = 0.0_c_double
  do i = 1, 3
    w(1, 1, i) = 1.0_c_double
    w(2, 2, i) = 1.0_c_double
  end do

  call check_status(ctx%create(3), FRICREG_OK, 'create')
  call check(ctx%size() == 3, 'size')
  call check_status(ctx%set_law(FRICREG_DISK_QUINN, 0.5_c_double), FRICREG_OK, 'set_law')
  call check_status(ctx%set_bounds(mun), FRICREG_OK, 'set_bounds')
  call check_status(ctx%set_coupling_blocks(w), FRICREG_OK, 'set_coupling_blocks')
  call check_status(ctx%eval(v, a, f), FRICREG_OK, 'eval')
  call check_close(f(1, 1), 1.2_c_double, tol, 'rest, saturated: x')
  call check_close(f(2, 1), 1.6_c_double, tol, 'rest, saturated: y')
  call check_close(f(1, 2), -0.5_c_double - 0.75_c_double / sqrt(9.25_c_double), tol, 'band: x')
  call check_close(f(2, 2), 4.5_c_double / sqrt(9.25_c_double), tol, 'band: y')
  call check(f(1, 3) == -2.0_c_double .and. f(2, 3) == 0.0_c_double, 'slides')

  ! A dense W: the type, the F77 entry points and C agree to the bit; the tangent in
  ! Fortran's order is C's row-major one transposed.
  do j = 1, 6
    do i = 1, 6
      Wd(i, j) = 0.1_c_double / (1.0_c_double + abs(i - j))
    end do
    Wd(j, j) = 1.0_c_double + 0.25_c_double * j
  end do
  v(:, 1) = [0.01_c_double, -0.02_c_double]
  call check_status(ctx%set_coupling_dense(Wd), FRICREG_OK, 'set_coupling_dense')
  call check_status(ctx%eval(v, a, f), FRICREG_OK, 'eval, dense')
  call check_status(ctx%tangent(df_dzdot=T), FRICREG_OK, 'tangent')
  status = fricreg_disk_ctx_tangent(ctx%handle(), 3_c_size_t, Tc)
  call check_status(status, FRICREG_OK, 'C tangent')
  call check(all(T == transpose(Tc)), 'tangent: Fortran order is C''s transposed')

  h = 0
  call frdcc(3, h, stat)
  call check(stat == FRICREG_OK .and. h /= 0, 'FRDCC')
  call frdlaw(h, FRICREG_DISK_QUINN, 0.5_c_double, stat)
  call frdbnd(h, 3, mun, stat)
  call frdcpd(h, 3, Wd, stat)
  call check(stat == FRICREG_OK, 'FRDCPD')
  call frdevl(h, 3, v, a, f77, stat)
  call check(stat == FRICREG_OK .and. all(f77 == f), 'FRDEVL: the type''s forces to the bit')
  call frdtng(h, 3, T77, A77, stat)
  call check(stat == FRICREG_OK .and. all(T77 == T), 'FRDTNG: the type''s tangent to the bit')
  call frdcpb(h, 3, w, stat)
  call check(stat == FRICREG_OK, 'FRDCPB')
  call frdlaw(h, FRICREG_DISK_QUINN_LENS, 0.5_c_double, stat)
  call check(stat == FRICREG_EINVAL, 'FRDLAW: the lens is refused')
  call frderr(h, code, msg, stat)
  call check(code == FRICREG_EINVAL .and. len_trim(msg) > 0, 'FRDERR')
  call frdcf(h, stat)
  call check(h == 0, 'FRDCF')

  ! Refusals: shapes, laws; f untouched on failure.
  f77 = -7.0_c_double
  call check_status(ctx%eval(v, a, f77(:, 1:2)), FRICREG_ESIZE, 'eval: f (2, 2)')
  call check_status(ctx%set_coupling_dense(bad), FRICREG_ESIZE, 'W 2 x 2 for 3 contacts')
  call check_status(ctx%set_coupling_blocks(w(:, :, 1:2)), FRICREG_ESIZE, 'w (2, 2, 2)')
  call check_status(ctx%set_law(FRICREG_DISK_COULOMB, 0.5_c_double), FRICREG_EINVAL, &
                    'set_law: coulomb refused')
  call check(ctx%errcode() == FRICREG_EINVAL .and. len(ctx%errmsg()) > 0, 'errmsg')
  a(1, 1) = ieee_nan()
  call check_status(ctx%eval(v, a, f77), FRICREG_ENONFINITE, 'eval: NaN')
  call check(all(f77 == -7.0_c_double), 'f untouched on failure')
  call ctx%destroy()
  call check_status(ctx%eval(v, a, f77), FRICREG_ENULL, 'eval after destroy')
  call finish('test_disk_ctx')

contains

  function ieee_nan() result(x)
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    real(c_double) :: x
    x = ieee_value(x, ieee_quiet_nan)
  end function ieee_nan
end program test_disk_ctx
