! SPDX-License-Identifier: GPL-3.0-or-later
! test_stribeck_disk_ctx.f90 — Stribeck friction in the 2-D context from Fortran (1.3):
! dctx%set_stribeck of the idiomatic layer and the F77 entry point FRDSTR.
!  - three uncoupled contacts with isotropic blocks w_i I, eps = 0.04, one in the band, one
!    sliding, one at rest: the forces equal stribeck_disk_eval (C's batch law, tested against
!    closed forms in tests/law/test_stribeck.c) at f_eq = -a_free/w_i, bit for bit (what
!    tests/disk_ctx/test_stribeck_disk_ctx.c measures in C), through both layers;
!  - set_stribeck() with no argument (FRDSTR with M = 0) switches it off: disk_eval's
!    FRICREG_DISK_QUINN with the bounds of set_bounds, bit for bit;
!  - a wrong size is FRICREG_ESIZE with a message, some arrays omitted FRICREG_ENULL, fk > fs
!    FRICREG_EINVAL; the forces afterwards are unchanged.
program test_stribeck_disk_ctx
  use fricreg
  use ftest
  implicit none
  integer, parameter :: m = 3
  real(c_double), parameter :: eps = 0.04_c_double
  real(c_double), parameter :: wi(m) = [1.5_c_double, 0.5_c_double, 2.0_c_double]
  real(c_double), parameter :: mun(m) = [0.5_c_double, 0.625_c_double, 1.125_c_double]
  real(c_double), parameter :: fs(m) = [2.385_c_double, 1.25_c_double, 0.75_c_double]
  real(c_double), parameter :: fk(m) = [1.5_c_double, 1.0_c_double, 0.25_c_double]
  real(c_double), parameter :: vs(m) = [0.03_c_double, 0.2_c_double, 0.05_c_double]
  real(c_double), parameter :: delta(m) = [1.0_c_double, 2.0_c_double, 0.5_c_double]
  real(c_double), parameter :: fkbad(m) = [1.5_c_double, 3.5_c_double, 0.25_c_double]
  type(fricreg_disk_context) :: ctx
  real(c_double) :: zdot(2, m), a_free(2, m), feq(2, m), w(2, 2, m)
  real(c_double) :: f(2, m), want(2, m), quinn(2, m), before(2, m)
  integer(c_int64_t) :: h
  integer :: stat, i
  external :: frdcc, frdcpb, frdbnd, frdlaw, frdstr, frdevl, frdcf

  zdot = reshape([0.0125_c_double, -0.02_c_double, -0.3_c_double, 0.1_c_double, &
                  0.0_c_double, 0.0_c_double], [2, m])
  a_free = reshape([0.5_c_double, 0.25_c_double, -0.25_c_double, 1.0_c_double, &
                    3.0_c_double, -0.5_c_double], [2, m])
  w = 0.0_c_double
  do i = 1, m
    w(1, 1, i) = wi(i)
    w(2, 2, i) = wi(i)
    feq(:, i) = -a_free(:, i) / wi(i)
  end do
  call check_status(stribeck_disk_eval(eps, zdot, feq, fs, fk, vs, delta, want), FRICREG_OK, &
                    'stribeck_disk_eval')
  do i = 1, m
    call check_status(disk_eval(FRICREG_DISK_QUINN, eps, zdot(:, i), feq(:, i), mun(i), &
                                quinn(:, i)), FRICREG_OK, 'disk_eval')
  end do

  ! The idiomatic layer.
  call check_status(ctx%create(m), FRICREG_OK, 'create')
  call check_status(ctx%set_coupling_blocks(w), FRICREG_OK, 'set_coupling_blocks')
  call check_status(ctx%set_bounds(mun), FRICREG_OK, 'set_bounds')
  call check_status(ctx%set_law(FRICREG_DISK_QUINN, eps), FRICREG_OK, 'set_law')
  call check_status(ctx%set_stribeck(fs, fk, vs, delta), FRICREG_OK, 'set_stribeck')
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_OK, 'eval')
  call check_all(f, want, 'dctx%set_stribeck: the scalar 2-D Stribeck law')
  before = f
  call check_status(ctx%set_stribeck(fs(1:2), fk, vs, delta), FRICREG_ESIZE, 'size(fs) = 2')
  call check(ctx%errmsg() == 'set_stribeck: size(fs) = 2, expected 3', 'message: ' // ctx%errmsg())
  call check_status(ctx%set_stribeck(fs, fk, vs), FRICREG_ENULL, 'delta omitted')
  call check_status(ctx%set_stribeck(fs, fkbad, vs, delta), FRICREG_EINVAL, 'fk > fs')
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_OK, 'eval after the failures')
  call check_all(f, before, 'failed calls leave the context unchanged')
  call check_status(ctx%set_stribeck(), FRICREG_OK, 'set_stribeck(): off')
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_OK, 'eval, off')
  call check_all(f, quinn, 'off: FRICREG_DISK_QUINN with the bounds of set_bounds')
  call ctx%destroy()

  ! The F77 entry points.
  call frdcc(m, h, stat)
  call check_status(stat, FRICREG_OK, 'FRDCC')
  call frdcpb(h, m, w, stat)
  call check_status(stat, FRICREG_OK, 'FRDCPB')
  call frdbnd(h, m, mun, stat)
  call check_status(stat, FRICREG_OK, 'FRDBND')
  call frdlaw(h, FRICREG_DISK_QUINN, eps, stat)
  call check_status(stat, FRICREG_OK, 'FRDLAW')
  call frdstr(h, m, fs, fk, vs, delta, stat)
  call check_status(stat, FRICREG_OK, 'FRDSTR')
  call frdevl(h, m, zdot, a_free, f, stat)
  call check_status(stat, FRICREG_OK, 'FRDEVL')
  call check_all(f, want, 'FRDSTR: the scalar 2-D Stribeck law')
  call frdstr(h, m, fs, fkbad, vs, delta, stat)
  call check_status(stat, FRICREG_EINVAL, 'FRDSTR fk > fs')
  call frdstr(h, 2, fs, fk, vs, delta, stat)
  call check_status(stat, FRICREG_ESIZE, 'FRDSTR M = 2')
  call frdstr(h, 0, fs, fk, vs, delta, stat)
  call check_status(stat, FRICREG_OK, 'FRDSTR M = 0: off')
  call frdevl(h, m, zdot, a_free, f, stat)
  call check_all(f, quinn, 'FRDSTR M = 0: FRICREG_DISK_QUINN with the bounds of FRDBND')
  call frdcf(h, stat)
  call check_status(stat, FRICREG_OK, 'FRDCF')
  call finish('stribeck_disk_ctx')

contains

  subroutine check_all(got, expected, what)
    real(c_double), intent(in) :: got(:, :), expected(:, :)
    character(len=*), intent(in) :: what
    integer :: i, j
    do j = 1, size(got, 2)
      do i = 1, 2
        call check_bits(got(i, j), expected(i, j), what)
      end do
    end do
  end subroutine check_all
end program test_stribeck_disk_ctx
