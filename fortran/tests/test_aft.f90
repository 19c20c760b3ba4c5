! SPDX-License-Identifier: GPL-3.0-or-later
! test_aft.f90 — the AFT (fricreg_aft.h) from Fortran: the type fricreg_aft_workspace of
! module fricreg, against the closed form of tests/joint/test_aft.c.
!
! Values: kt = 2, mun = 3, u = 5 cos(theta): fa_1 = (kt A/pi)(t - sin t cos t) with
! cos t = 1 - 2 mun/(kt A) = 0.4, fb_1 = -(4 mun/pi)(1 - mun/(kt A)) = -(12/pi) 0.7;
! the Jacobian in Fortran's order, jac(i, j) = d f(i)/d u(j): stuck (mun = 30), kt on the
! harmonics' diagonal; against the exact path, the sampled one at N = 4096 to 1e-5.
program test_aft
  use fricreg
  use ftest
  implicit none
  type(fricreg_aft_workspace) :: a
  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  real(c_double) :: u(5), f(5), fs(5), jac(5, 5), t, bad(4)

  call check_status(a%create(2, 4096), FRICREG_OK, 'create')
  call check(a%harmonics() == 2 .and. a%samples() == 4096, 'harmonics and samples')
  u = [0.0_c_double, 5.0_c_double, 0.0_c_double, 0.0_c_double, 0.0_c_double]
  call check_status(a%jenkins_exact(2.0_c_double, 3.0_c_double, u, f, jac), FRICREG_OK, 'exact')
  t = acos(0.4_c_double)
  call check_close(f(2), 10.0_c_double / pi * (t - sin(t) * cos(t)), 1e-13_c_double, 'fa_1')
  call check_close(f(3), -12.0_c_double / pi * 0.7_c_double, 1e-13_c_double, 'fb_1')
  call check_status(a%jenkins_sampled(2.0_c_double, 3.0_c_double, u, fs), FRICREG_OK, 'sampled')
  call check(maxval(abs(fs - f)) < 1e-5_c_double, 'sampled against exact')
  u(3) = 0.5_c_double
  call check_status(a%jenkins_exact(2.0_c_double, 30.0_c_double, u, f, jac), FRICREG_OK, 'stuck')
  call check_close(jac(3, 3), 2.0_c_double, 1e-14_c_double, 'stuck tangent')
  call check(abs(jac(3, 2)) < 1e-14_c_double .and. abs(jac(2, 3)) < 1e-14_c_double, 'diagonal')
  call check_status(a%iwan_exact([2.0_c_double, 1.0_c_double], [30.0_c_double, 30.0_c_double], &
                    u, f, jac), FRICREG_OK, 'iwan exact')
  call check_close(jac(3, 3), 3.0_c_double, 1e-14_c_double, 'iwan stuck tangent')

  ! errors: a wrong shape (Fortran's check), a bad parameter (C's), each with a message
  call check_status(a%jenkins_exact(2.0_c_double, 3.0_c_double, bad, f), FRICREG_ESIZE, 'shape')
  call check(len(a%errmsg()) > 0, 'message of ESIZE')
  call check_status(a%jenkins_exact(0.0_c_double, 3.0_c_double, u, f), FRICREG_EINVAL, 'kt = 0')
  call check_status(a%create(0, 0), FRICREG_EINVAL, 'H = 0')
  call check(a%harmonics() == 2, 'a failed create keeps the old workspace')

  call a%destroy()
  call a%destroy()
  call finish('test_aft')
end program test_aft
