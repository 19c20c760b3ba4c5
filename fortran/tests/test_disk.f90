! SPDX-License-Identifier: GPL-3.0-or-later
! test_disk.f90 — the 2-D laws (fricreg_disk.h) and the Stribeck laws (fricreg_stribeck.h)
! through module fricreg's generated bind(C) interfaces, against hand-worked values.
!
! Values (mun = 2, eps = 0.5 unless said):
!  - v = 0, f_eq = (0.3, 0.4): inside the disk, f = f_eq exactly; f_eq = (3, 4): f = (1.2, 1.6).
!  - v = (1, 0) >= eps: sliding, f = (-2, 0).
!  - v = (0.125, 0), f_eq = (0, 3), the default law (the inscribed disk: centre (-0.5, 0),
!    radius 1.5; f_eq - w = (-1, 3)): f = (-0.5, 0) + 1.5 (-0.5, 3)/sqrt(9.25).
!  - Stribeck fs = 2.5, fk = 1.5, vs = 0.2, delta = 2, eps = 0.05 at v = 0.4:
!    f = -(1.5 + exp(-4)); at v = 0 with f_eq = 2.5 (= fs): held, f = 2.5.
! A (2, m) Fortran array is C's interleaved v[2*i], v[2*i + 1].
program test_disk
  use fricreg
  use ftest
  implicit none
  real(c_double) :: f(2), fb(2, 3), v(2, 3), g(2, 3), mun(3), fs1
  real(c_double), parameter :: tol = 1e-15_c_double
  integer(c_int) :: status

  status = fricreg_disk_eval(FRICREG_DISK_QUINN, [0.0_c_double, 0.0_c_double], &
                             [0.3_c_double, 0.4_c_double], 2.0_c_double, 0.5_c_double, f)
  call check_status(status, FRICREG_OK, 'disk: v = 0 inside')
  call check(f(1) == 0.3_c_double .and. f(2) == 0.4_c_double, 'disk: exact stick inside')
  status = fricreg_disk_eval(FRICREG_DISK_QUINN, [0.0_c_double, 0.0_c_double], &
                             [3.0_c_double, 4.0_c_double], 2.0_c_double, 0.5_c_double, f)
  call check_close(f(1), 1.2_c_double, tol, 'disk: v = 0 saturated, x')
  call check_close(f(2), 1.6_c_double, tol, 'disk: v = 0 saturated, y')
  status = fricreg_disk_eval(FRICREG_DISK_QUINN, [0.125_c_double, 0.0_c_double], &
                             [0.0_c_double, 3.0_c_double], 2.0_c_double, 0.5_c_double, f)
  call check_close(f(1), -0.5_c_double - 0.75_c_double / sqrt(9.25_c_double), tol, &
                   'disk: band, x')
  call check_close(f(2), 4.5_c_double / sqrt(9.25_c_double), tol, 'disk: band, y')

  ! The batch: columns are contacts.
  v = reshape([0.0_c_double, 0.0_c_double, 1.0_c_double, 0.0_c_double, &
               0.125_c_double, 0.0_c_double], [2, 3])
  g = reshape([3.0_c_double, 4.0_c_double, 7.0_c_double, 7.0_c_double, &
               0.0_c_double, 3.0_c_double], [2, 3])
  mun = 2.0_c_double
  status = fricreg_disk_eval_batch(FRICREG_DISK_QUINN, 0.5_c_double, 3_c_size_t, v, g, mun, fb)
  call check_status(status, FRICREG_OK, 'disk batch')
  call check_close(fb(1, 1), 1.2_c_double, tol, 'disk batch: contact 1')
  call check(fb(1, 2) == -2.0_c_double .and. fb(2, 2) == 0.0_c_double, &
             'disk batch: contact 2 slides')
  call check_close(fb(2, 3), 4.5_c_double / sqrt(9.25_c_double), tol, 'disk batch: contact 3')
  ! f_eq omitted (NULL) is refused by a law that reads it, and f left alone
  fb = -7.0_c_double
  status = fricreg_disk_eval_batch(FRICREG_DISK_QUINN, 0.5_c_double, 3_c_size_t, v, mun=mun, &
                                   f=fb)
  call check_status(status, FRICREG_ENULL, 'disk batch without f_eq')
  call check(all(fb == -7.0_c_double), 'disk batch: f untouched on failure')
  call check(fricreg_c_string(fricreg_disk_law_name(FRICREG_DISK_QUINN_LENS)) == 'quinn-lens', &
             'disk law name')

  ! Stribeck, 1-D and 2-D
  status = fricreg_stribeck_eval(0.4_c_double, 7.0_c_double, 2.5_c_double, 1.5_c_double, &
                                 0.2_c_double, 2.0_c_double, 0.05_c_double, fs1)
  call check_status(status, FRICREG_OK, 'stribeck')
  call check_close(fs1, -(1.5_c_double + exp(-4.0_c_double)), tol, 'stribeck: kinetic curve')
  status = fricreg_stribeck_eval(0.0_c_double, 2.5_c_double, 2.5_c_double, 1.5_c_double, &
                                 0.2_c_double, 2.0_c_double, 0.05_c_double, fs1)
  call check(fs1 == 2.5_c_double, 'stribeck: held at f_eq = fs')
  status = fricreg_stribeck_eval(0.0_c_double, 2.5_c_double, 1.5_c_double, 2.5_c_double, &
                                 0.2_c_double, 2.0_c_double, 0.05_c_double, fs1)
  call check_status(status, FRICREG_EINVAL, 'stribeck: fk > fs refused')
  status = fricreg_stribeck_disk_eval([0.0_c_double, 0.24_c_double], &
                                      [4.0_c_double, 1.0_c_double], 2.5_c_double, 1.5_c_double, &
                                      0.2_c_double, 2.0_c_double, &
                                      0.05_c_double, f)
  call check_status(status, FRICREG_OK, 'stribeck disk')
  call check(f(1) == 0.0_c_double, 'stribeck disk: opposes v, x')
  call check_close(f(2), -(1.5_c_double + exp(-1.44_c_double)), 1e-14_c_double, &
                   'stribeck disk: kinetic curve at |v| = 0.24')
  call finish('disk')
end program test_disk
