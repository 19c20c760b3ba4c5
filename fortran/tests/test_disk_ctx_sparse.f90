! SPDX-License-Identifier: GPL-3.0-or-later
! test_disk_ctx_sparse.f90 — a sparse W in the 2-D context from Fortran: the type-bound
! set_coupling_csr and set_coupling_csc of fricreg_disk_context and the F77 entry points
! FRDCSR, FRDCSC, against the dense setter on the same W and against the 1-D context.
!
! Values: a chain of m = 40 contacts, W = W1 (x) I2 with W1 = 2.385 tridiag(-1, 2, -1), given by
! one-based compressed rows (Fortran's indices) whole, by its upper triangle in compressed
! columns, and dense; every contact at rest or in the band along x, a_free along x with a few
! targets beyond their bounds. The same W gives the same forces to the bit through every
! setter (the context holds W by blocks whatever the setter), the F77 entry points the type's,
! the x components the 1-D context's (dense W1) to its rounding and the y components 0.
program test_disk_ctx_sparse
  use fricreg
  use ftest
  implicit none
  integer, parameter :: m = 40, n = 2 * m
  real(c_double), parameter :: w1 = 2.385_c_double, eps = 1e-3_c_double
  type(fricreg_disk_context) :: csr, csc, dense
  type(fricreg_context) :: one
  integer(c_int64_t) :: rowptr(n + 1), colind(3 * n), colptr(n + 1), rowind(2 * n)
  real(c_double) :: values(3 * n), upper(2 * n), Wd(n, n), W1d(m, m), mun(m)
  real(c_double) :: zdot(2, m), a_free(2, m), f(2, m), fc(2, m), fd(2, m), f77(2, m)
  real(c_double) :: z1(m), a1(m), f1(m), goal(m)
  integer(c_int64_t) :: h
  integer :: i, r, e, stat

  ! W1 (x) I2 by rows, one-based and whole; its upper triangle by columns (column c holds
  ! rows c - 2 and c: the CSC of an upper triangle).
  e = 0
  do r = 1, n
    rowptr(r) = e + 1
    if (r > 2) call entry(colind, values, e, r - 2, -w1)
    call entry(colind, values, e, r, 2.0_c_double * w1)
    if (r + 2 <= n) call entry(colind, values, e, r + 2, -w1)
  end do
  rowptr(n + 1) = e + 1
  e = 0
  do r = 1, n
    colptr(r) = e + 1
    if (r > 2) call entry(rowind, upper, e, r - 2, -w1)
    call entry(rowind, upper, e, r, 2.0_c_double * w1)
  end do
  colptr(n + 1) = e + 1
  Wd = 0.0_c_double
  W1d = 0.0_c_double
  do r = 1, n
    do e = rowptr(r), rowptr(r + 1) - 1
      Wd(r, colind(e)) = values(e)
    end do
  end do
  do i = 1, m
    W1d(i, i) = 2.0_c_double * w1
    if (i < m) W1d(i, i + 1) = -w1
    if (i < m) W1d(i + 1, i) = -w1
    mun(i) = 0.5_c_double + 0.025_c_double * i
    goal(i) = mun(i) * merge(1.3_c_double, 0.7_c_double * sin(1.7_c_double * i), mod(i, 9) == 0)
    z1(i) = merge(0.0_c_double, eps * 0.3_c_double * cos(2.1_c_double * i), mod(i, 3) /= 0)
  end do
  a1 = -matmul(W1d, goal)
  zdot = 0.0_c_double
  a_free = 0.0_c_double
  zdot(1, :) = z1
  a_free(1, :) = a1

  call setup(csr)
  call check_status(csr%set_coupling_csr(FRICREG_SPARSE_ONE_BASED, rowptr, colind, values), &
                    FRICREG_OK, 'set_coupling_csr, one-based')
  call setup(csc)
  call check_status(csc%set_coupling_csc(ior(FRICREG_SPARSE_ONE_BASED, FRICREG_SPARSE_UPPER), &
                                         colptr, rowind, upper), FRICREG_OK, &
                    'set_coupling_csc, upper triangle')
  call setup(dense)
  call check_status(dense%set_coupling_dense(Wd), FRICREG_OK, 'set_coupling_dense')
  call check_status(csr%eval(zdot, a_free, f), FRICREG_OK, 'eval, CSR')
  call check_status(csc%eval(zdot, a_free, fc), FRICREG_OK, 'eval, CSC')
  call check_status(dense%eval(zdot, a_free, fd), FRICREG_OK, 'eval, dense')
  call check(all(f == fc) .and. all(f == fd), 'CSR, CSC and dense: the same forces to the bit')
  call check(all(f(2, :) == 0.0_c_double), 'collinear: f_y = 0')

  call check_status(one%create(m), FRICREG_OK, '1-D create')
  call check_status(one%set_law(FRICREG_LAW_QUINN, eps), FRICREG_OK, '1-D set_law')
  call check_status(one%set_bounds(mun), FRICREG_OK, '1-D set_bounds')
  call check_status(one%set_coupling_dense(W1d), FRICREG_OK, '1-D set_coupling_dense')
  call check_status(one%eval(z1, a1, f1), FRICREG_OK, '1-D eval')
  call check(maxval(abs(f(1, :) - f1) / mun) <= 1e-12_c_double, &
             'x components: the 1-D context''s forces')

  ! F77: FRDCSR, FRDCSC, the type's numbers to the bit.
  h = 0
  call frdcc(m, h, stat)
  call frdlaw(h, FRICREG_DISK_QUINN, eps, stat)
  call frdbnd(h, m, mun, stat)
  call frdcsr(h, m, FRICREG_SPARSE_ONE_BASED, rowptr, colind, values, stat)
  call check(stat == FRICREG_OK, 'FRDCSR')
  call frdevl(h, m, zdot, a_free, f77, stat)
  call check(stat == FRICREG_OK .and. all(f77 == f), 'FRDCSR, FRDEVL: the type''s forces')
  call frdcsc(h, m, ior(FRICREG_SPARSE_ONE_BASED, FRICREG_SPARSE_UPPER), colptr, rowind, upper, &
              stat)
  call check(stat == FRICREG_OK, 'FRDCSC')
  call frdevl(h, m, zdot, a_free, f77, stat)
  call check(stat == FRICREG_OK .and. all(f77 == f), 'FRDCSC, FRDEVL: the type''s forces')
  call frdcsr(h, m, FRICREG_SPARSE_ZERO_BASED, rowptr, colind, values, stat)
  call check(stat == FRICREG_EINVAL, 'FRDCSR: one-based arrays read as zero-based refused')
  call frdcf(h, stat)

  ! Refusals: arrays too short for rowptr's entries (caught here, before C reads them), the
  ! wrong base (C's), and a W that is not symmetric; the context keeps its W and its state
  ! (csc, with the same W and one evaluation behind it, is the control).
  call check_status(csr%set_coupling_csr(FRICREG_SPARSE_ONE_BASED, rowptr(1:n), colind, values), &
                    FRICREG_ESIZE, 'rowptr of 2m entries')
  call check_status(csr%set_coupling_csr(FRICREG_SPARSE_ONE_BASED, rowptr, colind(1:10), values), &
                    FRICREG_ESIZE, 'colind shorter than nnz')
  call check_status(csr%set_coupling_csr(FRICREG_SPARSE_ZERO_BASED, rowptr, colind, values), &
                    FRICREG_EINVAL, 'one-based arrays read as zero-based')
  values(2) = values(2) + 1.0_c_double
  call check_status(csr%set_coupling_csr(FRICREG_SPARSE_ONE_BASED, rowptr, colind, values), &
                    FRICREG_ENOTSYM, 'not symmetric')
  call check(csr%errcode() == FRICREG_ENOTSYM .and. len(csr%errmsg()) > 0, 'errmsg')
  call check_status(csr%eval(zdot, a_free, fc), FRICREG_OK, 'eval after refusals')
  call check_status(csc%eval(zdot, a_free, fd), FRICREG_OK, 'eval, CSC again')
  call check(all(fc == fd), 'refusals change nothing: the forces of the same history without them')
  call csr%destroy()
  call check_status(csr%set_coupling_csr(FRICREG_SPARSE_ONE_BASED, rowptr, colind, values), &
                    FRICREG_ENULL, 'after destroy')
  call csc%destroy()
  call dense%destroy()
  call one%destroy()
  call finish('test_disk_ctx_sparse')

contains

  subroutine entry(ind, val, e, index, value)
    integer(c_int64_t), intent(inout) :: ind(:)
    real(c_double), intent(inout) :: val(:)
    integer, intent(inout) :: e
    integer, intent(in) :: index
    real(c_double), intent(in) :: value
    e = e + 1
    ind(e) = index
    val(e) = value
  end subroutine entry

  subroutine setup(ctx)
    type(fricreg_disk_context), intent(inout) :: ctx
    call check_status(ctx%create(m), FRICREG_OK, 'create')
    call check_status(ctx%set_law(FRICREG_DISK_QUINN, eps), FRICREG_OK, 'set_law')
    call check_status(ctx%set_bounds(mun), FRICREG_OK, 'set_bounds')
  end subroutine setup
end program test_disk_ctx_sparse
