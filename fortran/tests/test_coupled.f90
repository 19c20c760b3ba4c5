! SPDX-License-Identifier: GPL-3.0-or-later
! test_coupled.f90 — the 1.1 context additions through both Fortran layers: partition,
! stick-zone stiffness, the tangent (and its Fortran layout), and the law names.
!
! Closed forms, on the two blocks W = [[1, -1], [-1, 2]] (W^-1 = [[2, 1], [1, 1]]) with
! mun = (0.5, 0.4), eps = 0.02, law (4): at zdot = 0 with a_free = (0.1, 0.1) both contacts
! hold, f = -W^-1 a_free = (-0.3, -0.2), inside the bounds. Under the consistent law the free
! contacts give df/dzdot = -W^-1 diag(2 W_ii mun_i/eps) = -W^-1 diag(50, 80)
! = -[[100, 80], [50, 80]] (not symmetric: it shows the layout) and df/da_free = -W^-1.
! Stiffness: consistent max_i W_ii 2 mun_i/eps = 80; paper's: the largest eigenvalue of
! D^1/2 W D^1/2, D = diag(50, 40): [[50, -sqrt(2000)], [-sqrt(2000), 80]], 65 + sqrt(225 + 2000).
program test_coupled
  use fricreg
  use ftest
  implicit none
  real(c_double), parameter :: tol = 1e-12_c_double
  real(c_double), parameter :: W(2, 2) = reshape([1.0_c_double, -1.0_c_double, &
                                                   -1.0_c_double, 2.0_c_double], [2, 2])
  real(c_double), parameter :: mun(2) = [0.5_c_double, 0.4_c_double], eps = 0.02_c_double
  real(c_double), parameter :: a_free(2) = [0.1_c_double, 0.1_c_double]
  real(c_double), parameter :: dfdz(2, 2) = reshape([-100.0_c_double, -50.0_c_double, &
                                                     -80.0_c_double, -80.0_c_double], [2, 2])
  real(c_double), parameter :: dfda(2, 2) = reshape([-2.0_c_double, -1.0_c_double, &
                                                     -1.0_c_double, -1.0_c_double], [2, 2])
  type(fricreg_context) :: ctx
  real(c_double) :: f(2), zdot(2), jz(2, 2), ja(2, 2), wrong(2, 3), lambda
  integer(c_int64_t) :: h
  integer :: stat

  call check_status(ctx%create(2), FRICREG_OK, 'create(2)')
  call check_status(ctx%set_coupling_dense(W), FRICREG_OK, 'set_coupling_dense')
  call check_status(ctx%set_bounds(mun), FRICREG_OK, 'set_bounds')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN, eps), FRICREG_OK, 'set_law')
  jz = 7.0_c_double
  call check_status(ctx%tangent(jz), FRICREG_EINVAL, 'tangent before any eval')
  call check(all(jz == 7.0_c_double), 'tangent untouched on failure')

  zdot = 0.0_c_double
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_OK, 'eval')
  call check_close(f(1), -0.3_c_double, tol, 'f(1) = (-W^-1 a_free)(1)')
  call check_close(f(2), -0.2_c_double, tol, 'f(2) = (-W^-1 a_free)(2)')
  call check_status(ctx%tangent(jz, ja), FRICREG_OK, 'tangent')
  call check(maxval(abs(jz - dfdz)) <= tol * 100, 'df_dzdot(i, j) = d f_i / d zdot_j')
  call check(maxval(abs(ja - dfda)) <= tol, 'df_dafree = -W^-1')
  call check_status(ctx%tangent(df_dafree=ja), FRICREG_OK, 'tangent, one output')
  call check_status(ctx%tangent(wrong), FRICREG_ESIZE, 'tangent into a 2 x 3 array')
  call check(index(ctx%errmsg(), 'df_dzdot, 2') > 0, 'message: ' // ctx%errmsg())

  call check_status(ctx%stick_stiffness(lambda), FRICREG_OK, 'stick_stiffness, consistent')
  call check_close(lambda, 80.0_c_double, tol * 80, 'consistent: max W_ii 2 mun_i/eps')
  call check_status(ctx%set_partition(FRICREG_PARTITION_PAPER), FRICREG_OK, 'set_partition')
  call check_status(ctx%stick_stiffness(lambda), FRICREG_OK, 'stick_stiffness, paper')
  call check_close(lambda, 65.0_c_double + sqrt(2225.0_c_double), tol * 120, &
                   "paper's: the coupled eigenvalue")
  call check_status(ctx%set_partition(0_c_int), FRICREG_EINVAL, 'unknown partition')

  ! The law names, both ways.
  call check(fricreg_law_string(FRICREG_LAW_QUINN) == 'quinn', 'law name of (4)')
  call check(fricreg_law_string(99_c_int) == '', 'unknown law: empty name')
  call check(fricreg_law_id('force-balance  ') == FRICREG_LAW_FORCE_BALANCE, 'law id')
  call check(fricreg_law_id('Quinn') == 0, 'names are lower case')

  ! The same through the F77 entry points, on a handle of the same C context.
  h = fricreg_ptr_to_handle(ctx%handle())
  call frpart(h, int(FRICREG_PARTITION_CONSISTENT), stat)
  call check(stat == FRICREG_OK, 'FRPART')
  call freval(h, 2, zdot, a_free, f, jz(:, 1), stat)
  call check(stat == FRICREG_OK, 'FREVAL')
  jz = 0.0_c_double
  ja = 0.0_c_double
  call frtang(h, 2, jz, ja, stat)
  call check(stat == FRICREG_OK .and. maxval(abs(jz - dfdz)) <= tol * 100 .and. &
             maxval(abs(ja - dfda)) <= tol, 'FRTANG: column-major DFDZ(I, J) = dF_I/dZDOT_J')
  call frstif(h, lambda, stat)
  call check(stat == FRICREG_OK .and. abs(lambda - 80.0_c_double) <= tol * 80, 'FRSTIF')
  call frtang(h, 3, jz, ja, stat)
  call check(stat == FRICREG_ESIZE, 'FRTANG with M = 3')
  call ctx%destroy()
  call finish('test_coupled')
end program test_coupled
