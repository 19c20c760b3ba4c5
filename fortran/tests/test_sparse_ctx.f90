! SPDX-License-Identifier: GPL-3.0-or-later
! test_sparse_ctx.f90 — a sparse W and the tangent's product through both Fortran layers:
! ctx%set_coupling_csc, ctx%set_coupling_csr, ctx%tangent_apply, FRCPLC, FRCPLR, FRTAPP.
!
! Closed forms on the two blocks W = [[1, -1], [-1, 2]] (W^-1 = [[2, 1], [1, 1]]), as in
! test_coupled.f90: mun = (0.5, 0.4), eps = 0.02, law (4), zdot = 0, a_free = (0.1, 0.1): both
! contacts hold, f = -W^-1 a_free = (-0.3, -0.2); df/dzdot = -W^-1 diag(50, 80)
! = [[-100, -80], [-50, -80]], df/da_free = -W^-1. For dzdot = (1, 2), dafree = (0.5, -1):
! df = (-100 - 160, -50 - 160) + (-(1 - 1), -(0.5 - 1)) = (-260, -209.5).
! W is given as Fortran holds it, one-based CSC of its upper triangle: colptr = (1, 2, 4),
! rowind = (1, 1, 2), values = (1, -1, 2); and as zero-based CSR, whole.
program test_sparse_ctx
  use fricreg
  use ftest
  implicit none
  real(c_double), parameter :: tol = 1e-12_c_double
  real(c_double), parameter :: mun(2) = [0.5_c_double, 0.4_c_double], eps = 0.02_c_double
  real(c_double), parameter :: a_free(2) = [0.1_c_double, 0.1_c_double]
  integer(c_int64_t), parameter :: colptr(3) = [1_c_int64_t, 2_c_int64_t, 4_c_int64_t]
  integer(c_int64_t), parameter :: rowind(3) = [1_c_int64_t, 1_c_int64_t, 2_c_int64_t]
  real(c_double), parameter :: upper(3) = [1.0_c_double, -1.0_c_double, 2.0_c_double]
  integer(c_int64_t), parameter :: rowptr(3) = [0_c_int64_t, 2_c_int64_t, 4_c_int64_t]
  integer(c_int64_t), parameter :: colind(4) = [0_c_int64_t, 1_c_int64_t, 0_c_int64_t, &
                                                1_c_int64_t]
  real(c_double), parameter :: whole(4) = [1.0_c_double, -1.0_c_double, -1.0_c_double, &
                                           2.0_c_double]
  real(c_double), parameter :: dz(2) = [1.0_c_double, 2.0_c_double]
  real(c_double), parameter :: da(2) = [0.5_c_double, -1.0_c_double]
  real(c_double), parameter :: want(2) = [-260.0_c_double, -209.5_c_double]
  type(fricreg_context) :: ctx
  real(c_double) :: f(2), feq(2), df(2), zdot(2), asym(4)
  integer(c_int64_t) :: h, short(2)
  integer :: stat

  zdot = 0.0_c_double
  call check_status(ctx%create(2), FRICREG_OK, 'create(2)')
  call check_status(ctx%set_coupling_csc(FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_UPPER, &
                                         colptr, rowind, upper), FRICREG_OK, &
                    'set_coupling_csc, one-based upper triangle')
  call check_status(ctx%set_bounds(mun), FRICREG_OK, 'set_bounds')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN, eps), FRICREG_OK, 'set_law')
  call check_status(ctx%eval(zdot, a_free, f, feq), FRICREG_OK, 'eval')
  call check_close(f(1), -0.3_c_double, tol, 'f(1) = (-W^-1 a_free)(1)')
  call check_close(f(2), -0.2_c_double, tol, 'f(2) = (-W^-1 a_free)(2)')
  call check_status(ctx%tangent_apply(dz, da, df), FRICREG_OK, 'tangent_apply')
  call check_close(df(1), want(1), tol * 300, 'df(1) = (J dz + J_a da)(1)')
  call check_close(df(2), want(2), tol * 300, 'df(2) = (J dz + J_a da)(2)')
  call check_status(ctx%tangent_apply(dafree=da, df=df), FRICREG_OK, 'tangent_apply, dafree')
  call check_close(df(1), 0.0_c_double, tol, 'df(1) = (-W^-1 da)(1) = 0')
  call check_close(df(2), 0.5_c_double, tol, 'df(2) = (-W^-1 da)(2)')

  ! The same W as zero-based CSR, whole: the same forces.
  call check_status(ctx%set_coupling_csr(FRICREG_SPARSE_ZERO_BASED, rowptr, colind, whole), &
                    FRICREG_OK, 'set_coupling_csr, zero-based whole')
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_OK, 'eval after set_coupling_csr')
  call check_close(f(1), -0.3_c_double, tol, 'csr: f(1)')
  call check_close(f(2), -0.2_c_double, tol, 'csr: f(2)')

  ! Refusals, each recorded, the coupling kept.
  short = [1_c_int64_t, 1_c_int64_t]
  call check_status(ctx%set_coupling_csc(FRICREG_SPARSE_ONE_BASED, colptr, short, upper), &
                    FRICREG_ESIZE, 'rowind shorter than nnz')
  call check(index(ctx%errmsg(), 'rowind') > 0, 'message: ' // ctx%errmsg())
  call check_status(ctx%set_coupling_csr(0_c_int, short, colind, whole), FRICREG_ESIZE, &
                    'rowptr of 2 elements')
  call check_status(ctx%set_coupling_csr(FRICREG_SPARSE_UPPER + FRICREG_SPARSE_LOWER, rowptr, &
                                         colind, whole), FRICREG_EINVAL, 'both triangles')
  asym = whole
  asym(2) = -0.5_c_double
  call check_status(ctx%set_coupling_csr(0_c_int, rowptr, colind, asym), FRICREG_ENOTSYM, &
                    'not symmetric')
  call check_status(ctx%tangent_apply(dz, da, df(1:1)), FRICREG_ESIZE, 'df of 1 element')
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_OK, 'eval after the refusals')
  call check_close(f(1), -0.3_c_double, tol, 'kept: f(1)')

  ! The F77 entry points on a handle of the same C context.
  h = fricreg_ptr_to_handle(ctx%handle())
  call frcplc(h, 2, int(FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_UPPER), colptr, rowind, &
              upper, stat)
  call check(stat == FRICREG_OK, 'FRCPLC')
  call freval(h, 2, zdot, a_free, f, feq, stat)
  call check(stat == FRICREG_OK .and. abs(f(1) + 0.3_c_double) <= tol, 'FREVAL after FRCPLC')
  call frtapp(h, 2, dz, da, df, stat)
  call check(stat == FRICREG_OK .and. maxval(abs(df - want)) <= tol * 300, 'FRTAPP')
  call frcplr(h, 2, 0, rowptr, colind, whole, stat)
  call check(stat == FRICREG_OK, 'FRCPLR')
  call frcplr(h, 3, 0, rowptr, colind, whole, stat)
  call check(stat == FRICREG_ESIZE, 'FRCPLR with M = 3')
  call frtapp(h, 3, dz, da, df, stat)
  call check(stat == FRICREG_ESIZE, 'FRTAPP with M = 3')
  call ctx%destroy()
  call finish('test_sparse_ctx')
end program test_sparse_ctx
