! SPDX-License-Identifier: GPL-3.0-or-later
! test_laws.f90 — every law through module fricreg equals the C library's result, bit for bit.
!
! The C result is computed by C (law_reference.c: fricreg_law_eval called from C, point by
! point) on a grid of velocities, equilibrium forces, bounds and two eps; the Fortran side goes
! through the generic law_eval (scalar and array), the bind(C) fricreg_law_eval, and the F77
! entry points FRLAWE and FRLAWB. The grid crosses every zone of every law: slip both ways, the
! stick zone |v| < eps (and |v - xi| < eps/2 of (4)), v = 0 exactly, f_eq inside and beyond
! the bound, and mun = 0. A few points are also checked against the laws' formulas by hand.
program test_laws
  use fricreg
  use ftest
  implicit none
  interface
    subroutine fricreg_ref_law_grid(law, eps, n, v, f_eq, mun, f, status) bind(C)
      import :: c_int, c_double, c_size_t
      integer(c_int), value :: law
      real(c_double), value :: eps
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: v(*), f_eq(*), mun(*)
      real(c_double), intent(out) :: f(*)
      integer(c_int), intent(out) :: status(*)
    end subroutine
    subroutine frlawe(law, v, feq, mun, eps, f, stat)
      integer, intent(in) :: law
      double precision, intent(in) :: v, feq, mun, eps
      double precision, intent(inout) :: f
      integer, intent(out) :: stat
    end subroutine
    subroutine frlawb(law, eps, m, v, feq, mun, f, stat)
      integer, intent(in) :: law, m
      double precision, intent(in) :: eps, v(*), feq(*), mun(*)
      double precision, intent(inout) :: f(*)
      integer, intent(out) :: stat
    end subroutine
  end interface

  integer, parameter :: nv = 15, nfeq = 9, nmun = 4, n = nv * nfeq * nmun
  real(c_double), parameter :: epss(2) = [0.02_c_double, 0.3785_c_double]
  integer(c_int), parameter :: laws(6) = [FRICREG_LAW_COULOMB, FRICREG_LAW_FORCE_BALANCE, &
    FRICREG_LAW_KARNOPP, FRICREG_LAW_VELOCITY_LIMITED, FRICREG_LAW_TANH, FRICREG_LAW_QUINN]
  real(c_double) :: vs(nv), feqs(nfeq), muns(nmun)
  real(c_double) :: v(n), f_eq(n), mun(n), f_c(n), f_scalar(n), f_array(n), f_bind(n), &
                    f_f77(n), f_noeq(n), eps
  integer(c_int) :: status_c(n), status
  integer :: i, j, k, p, il, ie, stat
  character(len=48) :: where

  muns = [1.0_c_double, 0.5_c_double, 2.385_c_double, 0.0_c_double]
  feqs = [-3.1_c_double, -1.0_c_double, -0.7213_c_double, -1e-9_c_double, 0.0_c_double, &
          2.5e-3_c_double, 0.4471_c_double, 1.0_c_double, 5.25_c_double]
  do ie = 1, size(epss)
    eps = epss(ie)
    ! velocities: far slip, the edges of eps and eps/2, inside, 0, tiny
    vs = [-1.75_c_double, -eps, -0.75_c_double * eps, -0.5_c_double * eps, -0.1234_c_double * eps, &
          -1e-300_c_double, 0.0_c_double, 1e-17_c_double, 0.0371_c_double * eps, 0.5_c_double * eps, &
          0.61_c_double * eps, eps, 1.0000001_c_double * eps, 0.8125_c_double, 42.0_c_double]
    p = 0
    do k = 1, nmun
      do j = 1, nfeq
        do i = 1, nv
          p = p + 1
          v(p) = vs(i)
          f_eq(p) = feqs(j) * muns(k)
          mun(p) = muns(k)
        end do
      end do
    end do
    do il = 1, size(laws)
      write (where, '(a, i0, a, es10.3)') 'law ', laws(il), ', eps ', eps
      call fricreg_ref_law_grid(laws(il), eps, int(n, c_size_t), v, f_eq, mun, f_c, status_c)
      call check(all(status_c == FRICREG_OK), trim(where) // ': C evaluates the whole grid')
      do p = 1, n
        status = law_eval(laws(il), eps, v(p), f_eq(p), mun(p), f_scalar(p))
        call check_status(status, status_c(p), trim(where) // ': law_eval, scalar')
        status = fricreg_law_eval(laws(il), v(p), f_eq(p), mun(p), eps, f_bind(p))
        call check_status(status, status_c(p), trim(where) // ': fricreg_law_eval')
        call frlawe(int(laws(il)), v(p), f_eq(p), mun(p), eps, f_f77(p), stat)
        call check(stat == status_c(p), trim(where) // ': FRLAWE status')
      end do
      status = law_eval(laws(il), eps, v, f_eq, mun, f_array)
      call check_status(status, FRICREG_OK, trim(where) // ': law_eval, array')
      do p = 1, n
        call check_bits(f_scalar(p), f_c(p), trim(where) // ': law_eval scalar = C')
        call check_bits(f_array(p), f_c(p), trim(where) // ': law_eval array = C')
        call check_bits(f_bind(p), f_c(p), trim(where) // ': fricreg_law_eval = C')
        call check_bits(f_f77(p), f_c(p), trim(where) // ': FRLAWE = C')
      end do
      call frlawb(int(laws(il)), eps, n, v, f_eq, mun, f_f77, stat)
      call check(stat == FRICREG_OK, trim(where) // ': FRLAWB status')
      do p = 1, n
        call check_bits(f_f77(p), f_c(p), trim(where) // ': FRLAWB = C')
      end do
      ! Without f_eq: the laws that do not read it give the same forces; the others refuse.
      f_noeq = -99.0_c_double
      status = law_eval(laws(il), eps, v, mun=mun, f=f_noeq)
      status_c(1) = law_eval(laws(il), eps, v(7), mun=mun(7), f=f_scalar(7))
      if (any(laws(il) == [FRICREG_LAW_COULOMB, FRICREG_LAW_VELOCITY_LIMITED, &
                           FRICREG_LAW_TANH])) then
        call check_status(status, FRICREG_OK, trim(where) // ': no f_eq, array')
        call check_status(status_c(1), FRICREG_OK, trim(where) // ': no f_eq, scalar')
        do p = 1, n
          call check_bits(f_noeq(p), f_c(p), trim(where) // ': no f_eq = C')
        end do
      else
        call check_status(status, FRICREG_ENULL, trim(where) // ': no f_eq, array')
        call check_status(status_c(1), FRICREG_ENULL, trim(where) // ': no f_eq, scalar')
        call check(all(f_noeq == -99.0_c_double), trim(where) // ': f untouched on failure')
      end if
    end do
  end do

  ! By hand (include/fricreg.h, paper Eqs. (1)-(4)), mun = 2.385, eps = 0.02:
  eps = 0.02_c_double
  status = law_eval(FRICREG_LAW_COULOMB, eps, -0.3_c_double, 0.0_c_double, 2.385_c_double, f_c(1))
  call check_close(f_c(1), 2.385_c_double, 0.0_c_double, '(1) at v < 0 is +mun')
  ! (4) at v = 0 with |f_eq| < mun is force balance: f = f_eq exactly.
  status = law_eval(FRICREG_LAW_QUINN, eps, 0.0_c_double, 1.1925_c_double, 2.385_c_double, f_c(1))
  call check_close(f_c(1), 1.1925_c_double, 1e-15_c_double, '(4) at v = 0: f = f_eq')
  ! (4) in its zone: xi = (eps/2) sat(f_eq/mun) = 0.01 * 0.5 = 0.005;
  ! f = -(2 mun/eps)(v - xi) = -238.5 * (0.001 - 0.005) = 0.954.
  status = law_eval(FRICREG_LAW_QUINN, eps, 0.001_c_double, 1.1925_c_double, 2.385_c_double, &
                    f_c(1))
  call check_close(f_c(1), 0.954_c_double, 1e-13_c_double, '(4) in its linear zone')
  ! (3): f = -(mun/eps) v = -119.25 * 0.004 = -0.477.
  status = law_eval(FRICREG_LAW_VELOCITY_LIMITED, eps, 0.004_c_double, mun=2.385_c_double, &
                    f=f_c(1))
  call check_close(f_c(1), -0.477_c_double, 1e-13_c_double, '(3) in its linear zone')

  ! Errors: arrays of different sizes, and bad values, return the codes and write nothing.
  f_array(1:3) = 7.0_c_double
  status = law_eval(FRICREG_LAW_QUINN, eps, v(1:3), f_eq(1:3), mun(1:2), f_array(1:3))
  call check_status(status, FRICREG_ESIZE, 'law_eval: size(mun) /= size(v)')
  status = law_eval(FRICREG_LAW_QUINN, eps, v(1:3), f_eq(1:4), mun(1:3), f_array(1:3))
  call check_status(status, FRICREG_ESIZE, 'law_eval: size(f_eq) /= size(v)')
  status = law_eval(FRICREG_LAW_QUINN, eps, v(1:3), f_eq(1:3), mun(1:3), f_array(1:2))
  call check_status(status, FRICREG_ESIZE, 'law_eval: size(f) /= size(v)')
  status = law_eval(7_c_int, eps, v(1:3), f_eq(1:3), mun(1:3), f_array(1:3))
  call check_status(status, FRICREG_EINVAL, 'law_eval: unknown law 7')
  status = law_eval(FRICREG_LAW_QUINN, 0.0_c_double, v(1:3), f_eq(1:3), mun(1:3), f_array(1:3))
  call check_status(status, FRICREG_EINVAL, 'law_eval: eps = 0')
  status = law_eval(FRICREG_LAW_QUINN, eps, v(1), f_eq(1), -1.0_c_double, f_array(1))
  call check_status(status, FRICREG_EINVAL, 'law_eval: mun < 0')
  status = law_eval(FRICREG_LAW_QUINN, eps, ieee_nan(), f_eq(1), mun(1), f_array(1))
  call check_status(status, FRICREG_ENONFINITE, 'law_eval: v = NaN')
  call check(all(f_array(1:3) == 7.0_c_double), 'law_eval: f untouched on failure')
  call frlawe(99, v(1), f_eq(1), mun(1), eps, f_array(1), stat)
  call check(stat == FRICREG_EINVAL, 'FRLAWE: unknown law 99')
  call frlawb(int(FRICREG_LAW_QUINN), eps, -1, v, f_eq, mun, f_array, stat)
  call check(stat == FRICREG_EINVAL, 'FRLAWB: M = -1')
  call finish('test_laws')

contains

  real(c_double) function ieee_nan()
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    ieee_nan = ieee_value(1.0_c_double, ieee_quiet_nan)
  end function ieee_nan

end program test_laws
