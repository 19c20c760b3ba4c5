! SPDX-License-Identifier: GPL-3.0-or-later
! test_stribeck_ctx.f90 — Stribeck friction in the context from Fortran (1.3): ctx%set_stribeck
! of the idiomatic layer and the F77 entry point FRSTRC.
!  - three uncoupled contacts, W = diag(1.5, 0.5, 2), law (4) at eps = 0.04, one in the band,
!    one sliding, one at rest: the forces equal stribeck_eval (C's batch law, tested against
!    closed forms in tests/law/test_stribeck.c) at f_eq = -a_free/W_ii, bit for bit (the C
!    library's contract for a diagonal W), through both layers;
!  - set_stribeck() with no argument (FRSTRC with M = 0) switches it off: law_eval's law (4)
!    with the bounds of set_bounds, bit for bit;
!  - a wrong size is FRICREG_ESIZE with a message, some arrays omitted FRICREG_ENULL, fk > fs
!    FRICREG_EINVAL; the forces afterwards are unchanged.
program test_stribeck_ctx
  use fricreg
  use ftest
  implicit none
  integer, parameter :: m = 3
  real(c_double), parameter :: eps = 0.04_c_double
  real(c_double), parameter :: w(m) = [1.5_c_double, 0.5_c_double, 2.0_c_double]
  real(c_double), parameter :: mun(m) = [0.5_c_double, 0.625_c_double, 1.125_c_double]
  real(c_double), parameter :: fs(m) = [2.385_c_double, 1.25_c_double, 0.75_c_double]
  real(c_double), parameter :: fk(m) = [1.5_c_double, 1.25_c_double, 0.25_c_double]
  real(c_double), parameter :: vs(m) = [0.03_c_double, 0.2_c_double, 0.05_c_double]
  real(c_double), parameter :: delta(m) = [1.0_c_double, 2.0_c_double, 0.5_c_double]
  real(c_double), parameter :: zdot(m) = [0.0125_c_double, -0.3_c_double, 0.0_c_double]
  real(c_double), parameter :: a_free(m) = [0.5_c_double, -0.25_c_double, 3.0_c_double]
  real(c_double), parameter :: fkbad(m) = [1.5_c_double, 3.5_c_double, 0.25_c_double]
  type(fricreg_context) :: ctx
  real(c_double) :: f(m), want(m), law4(m), before(m), feq(m)
  integer(c_int64_t) :: h
  integer :: stat
  external :: frctxc, frcplg, frbnd, frlaw, frstrc, freval, frctxf

  feq = -a_free / w
  call check_status(stribeck_eval(eps, zdot, feq, fs, fk, vs, delta, want), FRICREG_OK, &
                    'stribeck_eval')
  call check_status(law_eval(FRICREG_LAW_QUINN, eps, zdot, feq, mun, law4), FRICREG_OK, &
                    'law_eval')

  ! The idiomatic layer.
  call check_status(ctx%create(m), FRICREG_OK, 'create')
  call check_status(ctx%set_coupling_diagonal(w), FRICREG_OK, 'set_coupling_diagonal')
  call check_status(ctx%set_bounds(mun), FRICREG_OK, 'set_bounds')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN, eps), FRICREG_OK, 'set_law')
  call check_status(ctx%set_stribeck(fs, fk, vs, delta), FRICREG_OK, 'set_stribeck')
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_OK, 'eval')
  call check_all(f, want, 'ctx%set_stribeck: the scalar Stribeck law')
  before = f
  call check_status(ctx%set_stribeck(fs(1:2), fk, vs, delta), FRICREG_ESIZE, 'size(fs) = 2')
  call check(ctx%errmsg() == 'set_stribeck: size(fs) = 2, expected 3', 'message: ' // ctx%errmsg())
  call check_status(ctx%set_stribeck(fs, fk, vs), FRICREG_ENULL, 'delta omitted')
  call check_status(ctx%set_stribeck(fs, fkbad, vs, delta), FRICREG_EINVAL, 'fk > fs')
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_OK, 'eval after the failures')
  call check_all(f, before, 'failed calls leave the context unchanged')
  call check_status(ctx%set_stribeck(), FRICREG_OK, 'set_stribeck(): off')
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_OK, 'eval, off')
  call check_all(f, law4, 'off: law (4) with the bounds of set_bounds')
  call ctx%destroy()

  ! The F77 entry points.
  call frctxc(m, h, stat)
  call check_status(stat, FRICREG_OK, 'FRCTXC')
  call frcplg(h, m, w, stat)
  call check_status(stat, FRICREG_OK, 'FRCPLG')
  call frbnd(h, m, mun, stat)
  call check_status(stat, FRICREG_OK, 'FRBND')
  call frlaw(h, FRICREG_LAW_QUINN, eps, stat)
  call check_status(stat, FRICREG_OK, 'FRLAW')
  call frstrc(h, m, fs, fk, vs, delta, stat)
  call check_status(stat, FRICREG_OK, 'FRSTRC')
  call freval(h, m, zdot, a_free, f, feq, stat)
  call check_status(stat, FRICREG_OK, 'FREVAL')
  call check_all(f, want, 'FRSTRC: the scalar Stribeck law')
  call frstrc(h, m, fs, fkbad, vs, delta, stat)
  call check_status(stat, FRICREG_EINVAL, 'FRSTRC fk > fs')
  call frstrc(h, 2, fs, fk, vs, delta, stat)
  call check_status(stat, FRICREG_ESIZE, 'FRSTRC M = 2')
  call frstrc(h, 0, fs, fk, vs, delta, stat)
  call check_status(stat, FRICREG_OK, 'FRSTRC M = 0: off')
  call freval(h, m, zdot, a_free, f, feq, stat)
  call check_all(f, law4, 'FRSTRC M = 0: law (4) with the bounds of FRBND')
  call frctxf(h, stat)
  call check_status(stat, FRICREG_OK, 'FRCTXF')
  call finish('stribeck_ctx')

contains

  subroutine check_all(got, expected, what)
    real(c_double), intent(in) :: got(:), expected(:)
    character(len=*), intent(in) :: what
    integer :: i
    do i = 1, size(got)
      call check_bits(got(i), expected(i), what)
    end do
  end subroutine check_all
end program test_stribeck_ctx
