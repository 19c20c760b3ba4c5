! SPDX-License-Identifier: GPL-3.0-or-later
! test_solve_step.f90 — the user's own implicit step on a context through the module:
! ctx%solve_step, ctx%solve_step_csr, ctx%solve_step_csc, ctx%solve_step_matrix (C's
! fricreg_ctx_solve_step, _csr, _csc, _matrix).
!
! The closed form of test_f77_structure.f's FRCSTP, on two uncoupled contacts: W = diag(2, 2),
! Weff = diag(1, 1), c = 0.005, law (4) with eps = 1e-3 and mun = 1, zdot_pred = 0,
! a_pred = (0.3, -0.3), from f = (-1, 1). The safeguarded Newton stops at zdot = 0 and solves
! the band's linear piece (1 + c k) Weff f = -a_pred - k zdot_pred, k = 2 mun W / eps = 4000:
! f = (-0.3, 0.3) / 21. Then a coupled pair, W = [[2, 0.5], [0.5, 2]], Weff = W / 2: the sparse
! calls must give the dense call's forces bit for bit (the C tests' promise), one-based CSC of
! the upper triangle as a Fortran code holds it, and zero-based CSR whole.
program test_solve_step
  use fricreg
  use ftest
  implicit none
  real(c_double), parameter :: c = 0.005_c_double, tol = 1e-12_c_double
  real(c_double), parameter :: zs(2) = [0.001_c_double, -0.001_c_double]
  real(c_double), parameter :: zp(2) = 0.0_c_double
  real(c_double), parameter :: ap(2) = [0.3_c_double, -0.3_c_double]
  real(c_double), parameter :: f0(2) = [-1.0_c_double, 1.0_c_double]
  ! one-based CSC of the upper triangle and zero-based CSR whole, of the coupled pair's pattern
  integer(c_int64_t), parameter :: colptr(3) = [1_c_int64_t, 2_c_int64_t, 4_c_int64_t]
  integer(c_int64_t), parameter :: rowind(3) = [1_c_int64_t, 1_c_int64_t, 2_c_int64_t]
  integer(c_int64_t), parameter :: rowptr(3) = [0_c_int64_t, 2_c_int64_t, 4_c_int64_t]
  integer(c_int64_t), parameter :: colind(4) = [0_c_int64_t, 1_c_int64_t, 0_c_int64_t, &
                                                1_c_int64_t]
  integer(c_int64_t), parameter :: short(2) = [0_c_int64_t, 2_c_int64_t]
  type(fricreg_context) :: ctx
  real(c_double) :: W(2, 2), Weff(2, 2), f(2), fd(2), wu(3), weu(3), ww(4), wew(4)
  integer :: iterations
  logical :: converged

  call check_status(ctx%create(2), FRICREG_OK, 'create(2)')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN, 1e-3_c_double), FRICREG_OK, 'set_law')
  call check_status(ctx%set_bounds([1.0_c_double, 1.0_c_double]), FRICREG_OK, 'set_bounds')

  ! Uncoupled: the band's closed form.
  W = reshape([2.0_c_double, 0.0_c_double, 0.0_c_double, 2.0_c_double], [2, 2])
  Weff = W / 2
  call check_status(ctx%set_coupling_dense(W), FRICREG_OK, 'set_coupling_dense, uncoupled')
  f = f0
  call check_status(ctx%solve_step(zs, zp, ap, W, Weff, c, tol, 50, f, iterations, converged), &
                    FRICREG_OK, 'solve_step, uncoupled')
  call check(converged .and. iterations <= 3, 'solve_step converged within 3 iterations')
  call check_close(f(1), -0.3_c_double / 21, 1e-14_c_double, 'f(1) = -0.3 / 21, the band')
  call check_close(f(2), 0.3_c_double / 21, 1e-14_c_double, 'f(2) = 0.3 / 21, the band')
  f = f0
  call check_status(ctx%solve_step(zs, zp, ap, W, Weff, c, tol, 50, f, iterations, converged, &
                                   FRICREG_STEP_PLAIN), FRICREG_OK, 'solve_step, plain')
  call check(.not. converged .and. iterations == 50, 'plain Newton jumps: not converged in 50')

  ! Coupled: the sparse calls give the dense call's forces bit for bit.
  W = reshape([2.0_c_double, 0.5_c_double, 0.5_c_double, 2.0_c_double], [2, 2])
  Weff = W / 2
  wu = [W(1, 1), W(1, 2), W(2, 2)]
  weu = wu / 2
  ww = [W(1, 1), W(1, 2), W(2, 1), W(2, 2)]
  wew = ww / 2
  call check_status(ctx%set_coupling_dense(W), FRICREG_OK, 'set_coupling_dense, coupled')
  fd = f0
  call check_status(ctx%solve_step(zs, zp, ap, W, Weff, c, tol, 50, fd, converged=converged), &
                    FRICREG_OK, 'solve_step, coupled')
  call check(converged, 'solve_step, coupled: converged')
  f = f0
  call check_status(ctx%solve_step_csc(zs, zp, ap, &
                                       int(FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_UPPER, &
                                           c_int), colptr, rowind, wu, colptr, rowind, weu, c, &
                                       tol, 50, f), FRICREG_OK, 'solve_step_csc')
  call check_bits(f(1), fd(1), 'solve_step_csc: f(1) bit for bit')
  call check_bits(f(2), fd(2), 'solve_step_csc: f(2) bit for bit')
  f = f0
  call check_status(ctx%solve_step_csr(zs, zp, ap, int(FRICREG_SPARSE_ZERO_BASED, c_int), &
                                       rowptr, colind, ww, rowptr, colind, wew, c, tol, 50, f), &
                    FRICREG_OK, 'solve_step_csr')
  call check_bits(f(1), fd(1), 'solve_step_csr: f(1) bit for bit')
  call check_bits(f(2), fd(2), 'solve_step_csr: f(2) bit for bit')

  f = f0
  call check_status(ctx%solve_step_matrix(zs, zp, ap, int(FRICREG_MATRIX_CSC + &
                                          FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_UPPER, &
                                          c_int), wu, weu, c, tol, 50, f, colptr, rowind, &
                                          colptr, rowind), FRICREG_OK, 'solve_step_matrix, CSC')
  call check_bits(f(1), fd(1), 'solve_step_matrix CSC: f(1) bit for bit')
  call check_bits(f(2), fd(2), 'solve_step_matrix CSC: f(2) bit for bit')
  f = f0
  call check_status(ctx%solve_step_matrix(zs, zp, ap, int(FRICREG_MATRIX_DENSE, c_int), ww, &
                                          wew, c, tol, 50, f), FRICREG_OK, &
                    'solve_step_matrix, dense')
  call check_bits(f(1), fd(1), 'solve_step_matrix dense: f(1) bit for bit')
  call check_bits(f(2), fd(2), 'solve_step_matrix dense: f(2) bit for bit')

  ! Refusals: the forces kept.
  f = f0
  call check_status(ctx%solve_step_csr(zs, zp, ap, int(FRICREG_SPARSE_ZERO_BASED, c_int), &
                                       short, colind, ww, rowptr, colind, wew, c, tol, 50, f), &
                    FRICREG_ESIZE, 'solve_step_csr, a row pointer array of 2 for m = 2')
  call check_status(ctx%solve_step_csr(zs, zp, ap, int(FRICREG_SPARSE_ONE_BASED, c_int), &
                                       rowptr, colind, ww, rowptr, colind, wew, c, tol, 50, f), &
                    FRICREG_EINVAL, 'solve_step_csr, zero-based pointers called one-based')
  call check_status(ctx%solve_step_matrix(zs, zp, ap, int(FRICREG_MATRIX_CSR, c_int), ww, wew, &
                                          c, tol, 50, f), FRICREG_ENULL, &
                    'solve_step_matrix, CSR without its index arrays')
  call check_status(ctx%solve_step_matrix(zs, zp, ap, int(FRICREG_MATRIX_DENSE, c_int), wu, &
                                          wew, c, tol, 50, f), FRICREG_ESIZE, &
                    'solve_step_matrix, dense W of 3 elements for m = 2')
  call check_status(ctx%solve_step_matrix(zs, zp, ap, int(FRICREG_MATRIX_CSR + &
                                          FRICREG_MATRIX_CSC, c_int), ww, wew, c, tol, 50, f), &
                    FRICREG_EINVAL, 'solve_step_matrix, both CSR and CSC')
  call check(all(f == f0), 'refused: f unchanged')
  call ctx%destroy()
  call finish('test_solve_step')
end program test_solve_step
