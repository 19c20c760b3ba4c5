! SPDX-License-Identifier: GPL-3.0-or-later
! test_context.f90 — the context round trip through type fricreg_context: create, set, eval,
! destroy, against answers solved by hand.
!
! The coupled case is the two blocks of the paper's Sec. 3.3 (shared/spec/paper.md, "Reference
! system 3"): W = [[1, -1], [-1, 2]] (det 1, W^-1 = [[2, 1], [1, 1]]), mun = (0.5, 0.25), law (4)
! with eps = 0.02 (eps/2 = 0.01, 2 mun/eps = (50, 25)). At zdot = 0 both contacts are near-stick,
! f_eq = -W^-1 a_free, and law (4) at v = 0 is force balance: f = mun sat(f_eq/mun).
program test_context
  use fricreg
  use ftest
  implicit none
  real(c_double), parameter :: tol = 1e-14_c_double
  real(c_double), parameter :: W(2, 2) = reshape([1.0_c_double, -1.0_c_double, &
                                                   -1.0_c_double, 2.0_c_double], [2, 2])
  real(c_double), parameter :: mun(2) = [0.5_c_double, 0.25_c_double], eps = 0.02_c_double
  real(c_double), parameter :: a_free(2) = [-0.2385_c_double, 0.0917_c_double]
  type(fricreg_context) :: ctx, other
  real(c_double) :: f(2), f_eq(2), zdot(2), grid(3, 4)
  integer(c_int64_t) :: value
  integer(c_int) :: status

  call check(.not. ctx%is_created(), 'a new object holds no context')
  call check(ctx%errmsg() == '', 'a new object has no message')
  call check_status(ctx%create(2), FRICREG_OK, 'create(2)')
  call check(ctx%is_created() .and. ctx%size() == 2, 'size() is 2')
  call check_status(ctx%set_coupling_dense(W), FRICREG_OK, 'set_coupling_dense(W)')
  call check_status(ctx%set_bounds(mun), FRICREG_OK, 'set_bounds(mun)')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN, eps), FRICREG_OK, 'set_law(QUINN, 0.02)')
  ! The values below are the paper's joint f_eq of Sec. 3.3, not the consistent default's.
  call check_status(fricreg_ctx_set_partition(ctx%handle(), FRICREG_PARTITION_PAPER), &
                    FRICREG_OK, 'set_partition(PAPER)')

  ! Both near-stick at rest: f_eq = W^-1 (0.2385, -0.0917) = (0.477 - 0.0917, 0.2385 - 0.0917).
  zdot = 0.0_c_double
  call check_status(ctx%eval(zdot, a_free, f, f_eq), FRICREG_OK, 'eval at rest')
  call check_close(f_eq(1), 0.3853_c_double, tol, 'f_eq(1) = (W^-1 (-a_free))(1)')
  call check_close(f_eq(2), 0.1468_c_double, tol, 'f_eq(2) = (W^-1 (-a_free))(2)')
  call check_close(f(1), 0.3853_c_double, tol, 'f(1) = f_eq(1), inside the bound 0.5')
  call check_close(f(2), 0.1468_c_double, tol, 'f(2) = f_eq(2), inside the bound 0.25')
  call expect_stats(1_c_int64_t, 2_c_int64_t, 1_c_int64_t, 1_c_int64_t, 'after one eval')

  ! Contact 1 in (4)'s linear zone, same S: the factor is reused. xi1 = 0.01 * 0.3853/0.5
  ! = 0.007706, f1 = -50 (0.004 - 0.007706) = 0.1853; f2 = f_eq2 = 0.1468.
  zdot = [0.004_c_double, 0.0_c_double]
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_OK, 'eval in the linear zone, no f_eq')
  call check_close(f(1), 0.1853_c_double, 1e-13_c_double, 'f(1) in the linear zone of (4)')
  call check_close(f(2), 0.1468_c_double, tol, 'f(2) at rest')
  call expect_stats(2_c_int64_t, 4_c_int64_t, 1_c_int64_t, 2_c_int64_t, 'factor reused')

  ! Contact 2 slips (zdot2 = 0.5 > eps): f2 = -0.25, and contact 1 alone is near-stick (its
  ! factor is the held one with contact 2 removed, no new factorization):
  ! f_eq1 = -(a1 + W12 f2)/W11 = -(-0.2385 + 0.25) = -0.0115 = f1. f_eq2 is not computed (NaN).
  zdot = [0.0_c_double, 0.5_c_double]
  call check_status(ctx%eval(zdot, a_free, f, f_eq), FRICREG_OK, 'eval, contact 2 slipping')
  call check_close(f(2), -0.25_c_double, 0.0_c_double, 'f(2) = -mun2 sgn(zdot2)')
  call check_close(f_eq(1), -0.0115_c_double, tol, 'f_eq(1) with contact 2 slipping')
  call check_close(f(1), -0.0115_c_double, tol, 'f(1) = f_eq(1)')
  call check(f_eq(2) /= f_eq(2), 'f_eq(2) is NaN outside the near-stick set')
  call expect_stats(3_c_int64_t, 5_c_int64_t, 1_c_int64_t, 3_c_int64_t, 'new S, factor updated')
  call check_status(ctx%get_stat(FRICREG_STAT_FACTOR_UPDATES, value), FRICREG_OK, &
                    'get_stat(FACTOR_UPDATES)')
  call check(value == 1_c_int64_t, 'one contact removed from the factor')
  call ctx%reset_stats()
  call expect_stats(0_c_int64_t, 0_c_int64_t, 0_c_int64_t, 0_c_int64_t, 'after reset_stats')

  ! Arrays that are not contiguous (rows of a matrix) give the same answer; the compiler copies
  ! them in and out, and nothing else in the matrix changes.
  grid = -5.0_c_double
  grid(1, 1:2) = 0.0_c_double         ! zdot
  grid(2, 1:2) = a_free               ! a_free
  call check_status(ctx%eval(grid(1, 1:2), grid(2, 1:2), grid(3, 1:2), grid(3, 3:4)), &
                    FRICREG_OK, 'eval with strided arrays')
  call check_close(grid(3, 1), 0.3853_c_double, tol, 'strided f(1)')
  call check_close(grid(3, 2), 0.1468_c_double, tol, 'strided f(2)')
  call check_close(grid(3, 4), 0.1468_c_double, tol, 'strided f_eq(2)')
  call check(all(grid(1:2, 3:4) == -5.0_c_double), 'strided eval writes only its sections')

  ! Diagonal coupling W = diag(2, 4): f_eq = -a_free / w = (0.11925, -0.022925).
  call check_status(ctx%set_coupling_diagonal([2.0_c_double, 4.0_c_double]), FRICREG_OK, &
                    'set_coupling_diagonal')
  call ctx%reset_stats()
  zdot = 0.0_c_double
  call check_status(ctx%eval(zdot, a_free, f, f_eq), FRICREG_OK, 'eval, diagonal W')
  call check_close(f_eq(1), 0.11925_c_double, tol, 'diagonal f_eq(1)')
  call check_close(f_eq(2), -0.022925_c_double, tol, 'diagonal f_eq(2)')
  call check_close(f(2), -0.022925_c_double, tol, 'diagonal f(2)')
  call check_status(ctx%get_stat(FRICREG_STAT_FACTORIZATIONS, value), FRICREG_OK, 'get_stat')
  call check(value == 0, 'diagonal W needs no factorization')

  ! The bind(C) layer on the same context, through handle().
  call check(fricreg_ctx_size(ctx%handle()) == 2_c_size_t, 'fricreg_ctx_size(handle())')
  status = fricreg_ctx_eval(ctx%handle(), 2_c_size_t, zdot, a_free, f)
  call check_status(status, FRICREG_OK, 'fricreg_ctx_eval on handle()')
  call check_close(f(1), 0.11925_c_double, tol, 'fricreg_ctx_eval f(1)')

  ! Copies are not contexts: `other = ctx` leaves other empty and ctx working.
  other = ctx
  call check(.not. other%is_created(), 'assignment leaves the left side empty')
  call check_status(other%eval(zdot, a_free, f), FRICREG_ENULL, 'eval on the empty copy')
  call check(index(other%errmsg(), 'not created') > 0, 'message: ' // other%errmsg())
  call check(ctx%is_created(), 'the right side keeps its context')
  ctx = ctx
  call check(ctx%is_created(), 'ctx = ctx keeps the context')

  ! destroy, twice; then every call is FRICREG_ENULL, and create works again.
  call ctx%destroy()
  call check(.not. ctx%is_created() .and. ctx%size() == 0, 'destroy releases the context')
  call ctx%destroy()
  call check(.not. ctx%is_created(), 'a second destroy does nothing')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN, eps), FRICREG_ENULL, 'set_law after destroy')
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_ENULL, 'eval after destroy')
  call check_status(ctx%errcode(), FRICREG_ENULL, 'errcode after destroy')
  call check(ctx%errmsg() == 'eval: the context is not created (call create)', &
             'message after destroy: ' // ctx%errmsg())
  call check_status(ctx%create(3), FRICREG_OK, 'create again, m = 3')
  call check(ctx%size() == 3 .and. ctx%errcode() == FRICREG_OK .and. ctx%errmsg() == '', &
             'a new context starts with no error')
  call check_status(ctx%create(1), FRICREG_OK, 'create on a created object replaces it')
  call check(ctx%size() == 1, 'size() follows')
  call ctx%destroy()

  ! The final procedure releases a context that goes out of scope (a safety net only).
  call scoped()
  call finish('test_context')

contains

  subroutine expect_stats(evals, feq, fact, solves, what)
    integer(c_int64_t), intent(in) :: evals, feq, fact, solves
    character(len=*), intent(in) :: what
    integer(c_int64_t) :: got(4)
    integer(c_int) :: s1, s2, s3, s4
    got = -1
    s1 = ctx%get_stat(FRICREG_STAT_EVALS, got(1))
    s2 = ctx%get_stat(FRICREG_STAT_FEQ_CONTACTS, got(2))
    s3 = ctx%get_stat(FRICREG_STAT_FACTORIZATIONS, got(3))
    s4 = ctx%get_stat(FRICREG_STAT_SOLVES, got(4))
    call check(all([s1, s2, s3, s4] == FRICREG_OK), 'get_stat: ' // what)
    call check(all(got == [evals, feq, fact, solves]), 'counters ' // what)
  end subroutine expect_stats

  subroutine scoped()
    type(fricreg_context) :: local
    type(fricreg_context), allocatable :: heap
    call check_status(local%create(4), FRICREG_OK, 'a local context')
    allocate (heap)
    call check_status(heap%create(4), FRICREG_OK, 'an allocatable context')
    deallocate (heap) ! finalized here
  end subroutine scoped

end program test_context
