! SPDX-License-Identifier: GPL-3.0-or-later
! test_hb_nma.f90 — nonlinear modes (fricreg_hb_nma, fricreg_hb_nma_continue) from Fortran:
! hb%nma, hb%nma_points, hb%nma_point, hb%nma_continue, hb%nma_harmonic_energy,
! hb%nma_modal_participation, hb%nma_special_points, hb%nma_special_point of the type
! fricreg_hb_driver.
!
! Values: the oscillator m = 1, k = 1 with one Jenkins element kt = 2, mu N = 3 at H = 1 (the
! C suite's tests/nma/test_hb_nma.c derives its closed form): stuck for a <= 1.5, omega^2 = 3,
! zeta = 0; beyond, with cos(beta) = 1 - 3/a, omega^2 = 1 + (2/pi)(beta - sin(2 beta)/2) and
! zeta = 12 (a - 1.5) / (2 pi a^2 omega^2).
program test_hb_nma
  use fricreg
  use ftest
  implicit none
  type(fricreg_hb_driver) :: hb
  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  real(c_double) :: a, omega, zeta, beta, w2, z, x(3, 1), bad(3, 2), e(4), p(2), w1, sums
  integer :: i, k, r, t, n

  call check_status(hb%create(1, 1, 1), FRICREG_OK, 'create')
  call check_status(hb%set_stiffness(reshape([1.0_c_double], [1, 1])), FRICREG_OK, 'stiffness')
  call check_status(hb%set_elements(reshape([1.0_c_double], [1, 1]), [2.0_c_double], &
                                    [3.0_c_double]), FRICREG_OK, 'set_elements')
  call check_status(hb%nma(1, 0.5_c_double, 200.0_c_double, 10), FRICREG_OK, 'nma')
  call check(hb%nma_points() == 10, 'ten points')
  do i = 1, hb%nma_points()
    call check_status(hb%nma_point(i, a, omega, zeta, x), FRICREG_OK, 'nma_point')
    w2 = 3.0_c_double
    z = 0.0_c_double
    if (a > 1.5_c_double) then
      beta = acos(1.0_c_double - 3.0_c_double / a)
      w2 = 1.0_c_double + 2.0_c_double / pi * (beta - 0.5_c_double * sin(2.0_c_double * beta))
      z = 12.0_c_double * (a - 1.5_c_double) / (2.0_c_double * pi * a * a * w2)
    end if
    call check_close(omega * omega, w2, 1e-9_c_double * w2, 'omega^2, closed form')
    call check_close(zeta, z, 1e-9_c_double * max(z, 1e-3_c_double), 'zeta, closed form')
    call check_close(x(2, 1), a, 1e-9_c_double * a, 'x = a cos(theta)')
  end do
  call check_status(hb%nma_point(1, a, omega, zeta), FRICREG_OK, 'nma_point without x')
  call check_close(omega, sqrt(3.0_c_double), 1e-12_c_double, 'the stuck mode')
  call check_status(hb%nma_point(0, a, omega, zeta), FRICREG_EINVAL, 'point 0')
  call check_status(hb%nma_point(11, a, omega, zeta), FRICREG_EINVAL, 'point 11 of 10')
  call check_status(hb%nma_point(1, a, omega, zeta, bad), FRICREG_ESIZE, 'x(3, 2)')
  call check_status(hb%nma(0, 0.5_c_double, 2.0_c_double, 4), FRICREG_EINVAL, 'mode 0')
  call check_status(hb%nma(2, 0.5_c_double, 2.0_c_double, 4), FRICREG_EINVAL, 'mode 2 of 1')
  call check_status(hb%nma(1, 2.0_c_double, 2.0_c_double, 4), FRICREG_EINVAL, 'a0 = a1')
  call check_status(hb%nma(1, 0.5_c_double, 2.0_c_double, 4, FRICREG_HB_NMA_DAMPING_MODAL), &
                    FRICREG_OK, 'modal damping')
  call check(hb%nma_points() == 4, 'four points')

  ! The backbone by arclength: no fold on this one, each stored point a solution
  call check_status(hb%nma_continue(1, 0.5_c_double, 200.0_c_double, 10), FRICREG_OK, &
                    'nma_continue')
  call check(hb%nma_points() == 10 .and. hb%nma_special_points() == 0, &
             'ten points, no fold (no other mode to cross)')
  do i = 1, hb%nma_points()
    call check_status(hb%nma_point(i, a, omega, zeta), FRICREG_OK, 'nma_point, continued')
    w2 = 3.0_c_double
    if (a > 1.5_c_double) then
      beta = acos(1.0_c_double - 3.0_c_double / a)
      w2 = 1.0_c_double + 2.0_c_double / pi * (beta - 0.5_c_double * sin(2.0_c_double * beta))
    end if
    call check_close(omega * omega, w2, 1e-9_c_double * w2, 'omega^2 continued, closed form')
  end do
  call check_status(hb%nma_special_point(1, t, a, omega, zeta, k, r), FRICREG_EINVAL, &
                    'special point 1 of 0')
  call hb%destroy()

  ! tests/nma/test_hb_nma_fold.c's two masses (k1 = 1, kc = 0.25, k2 = 0.2; kt = 10, mu N = 1 on
  ! dof 2) at H = 3: 3 omega near the second mode (3:1), an S in a(omega) with two folds
  call check_status(hb%create(2, 1, 3), FRICREG_OK, 'create, two masses')
  call check_status(hb%set_stiffness(reshape([1.25_c_double, -0.25_c_double, -0.25_c_double, &
                                              0.45_c_double], [2, 2])), FRICREG_OK, 'K')
  call check_status(hb%set_elements(reshape([0.0_c_double, 1.0_c_double], [1, 2]), &
                                    [10.0_c_double], [1.0_c_double]), FRICREG_OK, 'element')
  call check_status(hb%nma_continue(1, 0.05_c_double, 1e4_c_double, 60), FRICREG_OK, &
                    'nma_continue through the folds')
  ! (3 omega stays above the second stuck mode's 3.2337, so its special points are the folds)
  call check(hb%nma_special_points() == 2, 'two special points: the folds')
  call check_status(hb%nma_special_point(1, t, a, omega, zeta, k, r), FRICREG_OK, 'fold 1')
  call check(t == FRICREG_HB_NMA_FOLD .and. k == 1 .and. r == 1, 'fold 1: harmonic 1, mode 1')
  call check_close(a, 4.4324_c_double, 2e-3_c_double * 4.4324_c_double, 'fold 1 amplitude')
  call check_status(hb%nma_special_point(2, t, a, omega, zeta, k, r), FRICREG_OK, 'fold 2')
  call check(t == FRICREG_HB_NMA_FOLD, 'fold 2: a fold')
  call check_close(a, 4.4168_c_double, 2e-3_c_double * 4.4168_c_double, 'fold 2 amplitude')
  call check_status(hb%nma_special_point(0, t, a, omega, zeta, k, r), FRICREG_EINVAL, &
                    'special point 0')
  call check_status(hb%nma_special_point(3, t, a, omega, zeta, k, r), FRICREG_EINVAL, &
                    'special point 3 of 2')
  ! what each point is made of: the harmonics' shares of the kinetic energy add up to 1 (the
  ! mean's is 0); the first point, stuck, is the linear mode 1 (tests/nma/test_hb_nma_energy.c);
  ! 3 omega stays above the second stuck mode's 3.2337, so no crossing
  sums = 0.0_c_double
  do i = 1, hb%nma_points()
    call check_status(hb%nma_harmonic_energy(i, e), FRICREG_OK, 'nma_harmonic_energy')
    sums = max(sums, abs(sum(e) - 1.0_c_double))
  end do
  call check(sums <= 1e-12_c_double, 'the shares add up to 1')
  call check_status(hb%nma_harmonic_energy(1, e), FRICREG_OK, 'nma_harmonic_energy, point 1')
  call check(e(1) == 0.0_c_double .and. abs(e(2) - 1.0_c_double) <= 1e-12_c_double, &
             'point 1: the fundamental')
  call check_status(hb%nma_modal_participation(1, 1, p), FRICREG_OK, 'nma_modal_participation')
  call check_close(p(1), 1.0_c_double, 1e-12_c_double, 'point 1: mode 1')
  call check_status(hb%nma_harmonic_energy(1, e(1:3)), FRICREG_ESIZE, 'energy, size 3')
  call check_status(hb%nma_modal_participation(1, 4, p), FRICREG_EINVAL, 'harmonic 4 of 3')
  call check_status(hb%nma_harmonic_energy(0, e), FRICREG_EINVAL, 'energy, point 0')
  call hb%destroy()

  ! with kt = 11 the second stuck mode, omega_2^2 = 6.35 + sqrt(5.1^2 + 0.25^2), lies in 3
  ! omega's range along the backbone: one crossing, 3 omega = omega_2 there, after the S's folds
  ! (tests/nma/test_hb_nma_energy.c): the last special point
  call check_status(hb%create(2, 1, 3), FRICREG_OK, 'create, kt = 11')
  call check_status(hb%set_stiffness(reshape([1.25_c_double, -0.25_c_double, -0.25_c_double, &
                                              0.45_c_double], [2, 2])), FRICREG_OK, 'K, kt = 11')
  call check_status(hb%set_elements(reshape([0.0_c_double, 1.0_c_double], [1, 2]), &
                                    [11.0_c_double], [1.0_c_double]), FRICREG_OK, 'element 11')
  call check_status(hb%nma_continue(1, 0.05_c_double, 1e3_c_double, 100), FRICREG_OK, &
                    'nma_continue, kt = 11')
  n = hb%nma_special_points()
  call check(n >= 3, 'the folds and one crossing')
  call check_status(hb%nma_special_point(n, t, a, omega, zeta, k, r), FRICREG_OK, 'crossing')
  call check(t == FRICREG_HB_NMA_CROSSING, 'the last: a crossing')
  z = a
  do i = 1, n - 1
    call check_status(hb%nma_special_point(i, t, a, omega, zeta, k, r), FRICREG_OK, 'fold')
    call check(t == FRICREG_HB_NMA_FOLD .and. a < z, 'a fold, before the crossing')
  end do
  call check_status(hb%nma_special_point(n, t, a, omega, zeta, k, r), FRICREG_OK, 'crossing')
  w1 = sqrt(6.35_c_double + sqrt(5.1_c_double**2 + 0.25_c_double**2))
  call check(k == 3 .and. r == 2, 'harmonic 3, mode 2')
  call check_close(3.0_c_double * omega, w1, 1e-12_c_double * w1, '3 omega = omega_2')
  call hb%destroy()
  call finish('test_hb_nma')
end program test_hb_nma
