! SPDX-License-Identifier: GPL-3.0-or-later
! test_fit.f90 — the identification of a modal Iwan joint (fricreg_fit.h) from Fortran: type
! fricreg_backbone_fit of module fricreg.
!
! Values. The backbone at a modal amplitude below macroslip against Segalman's closed form in
! R and S (../shared/notes/identification.md), written here: F_S = 2.385, K_T = 41.7,
! chi = -0.37, beta = 0.81, zeta0 = 0.0031, K0 = 17.3 at a = 0.3 phi_max. Noise-free levels of
! tests/fit/test_fit.c's joint (accelerations, sensor 0.37) with beta and K0 fixed: the four free
! parameters come back to 1e-6 from starts 10x off, each inside its interval. The failures: a
! getter before a run (FRICREG_EINVAL), arrays of different sizes (FRICREG_ESIZE).
!
! The HB model (set_model_hb, set_sensor_dof, set_model_modal_iwan): one unit mass on a unit
! spring with a Jenkins element kt = 1.7, mu N = 0.26 at H = 1, whose backbone is the describing
! function's closed form (tests/cli.sh's fit --model hb, tests/nma/test_hb_nma.c): delta = mun/kt,
! cos(beta) = 1 - 2 delta/a, omega^2 = 1 + kt/pi (beta - sin(2 beta)/2),
! zeta = 4 mun (a - delta)/(2 pi a^2 omega^2), at six amplitudes past the slip, measured at
! dof 1 (|X_1| = a for the unit mass). From the driver's values 2x off (kt 3.4, mu N 0.13) the
! fit recovers both to 1e-6; the arrays' sizes, counts from 0 and a dof beyond the driver's
! are refused, and the modal Iwan model comes back with its six parameters. With qsma = .true.
! (set_model_qsma) QSMA's closed form of the same oscillator (slipping, omega^2 = 1 + mun/a,
! zeta = 4 mun (a - mun/kt)/(2 pi (a + mun) a)) gives kt and mu N back to 1e-6 likewise.
program test_fit
  use fricreg
  use ftest
  implicit none
  type(fricreg_backbone_fit) :: fit
  type(fricreg_hb_driver) :: hb
  real(c_double), parameter :: truth(6) = [30.0_c_double, 3e5_c_double, 0.3_c_double, &
                                           0.5_c_double, 0.002_c_double, 8.4e5_c_double]
  real(c_double), parameter :: two_pi = 6.283185307179586_c_double
  real(c_double) :: p(6), q(6), a(1), f(1), z(1), df(6, 1), dz(6, 1), amp(8), fr(8), ze(8)
  real(c_double) :: sf(8), sz(8), cov(6, 6), lo(6), hi(6), c, pm, r, s, force, diss, w2, v
  real(c_double), parameter :: kt = 1.7_c_double, mun = 0.26_c_double, pi = two_pi / 2
  real(c_double), parameter :: ah(6) = [0.21_c_double, 0.33_c_double, 0.52_c_double, &
                                        0.86_c_double, 1.37_c_double, 2.2_c_double]
  real(c_double) :: fh(6), zh(6), qh(2), covh(2, 2), loh(2), hih(2), beta, dl
  integer, parameter :: el = FRICREG_HB_NMA_PARAM_ELEMENT
  integer :: i, j

  call check_status(fit%create(), FRICREG_OK, 'create')
  p = [2.385_c_double, 41.7_c_double, -0.37_c_double, 0.81_c_double, 0.0031_c_double, &
       17.3_c_double]
  c = p(4) + (p(3) + 1) / (p(3) + 2)
  pm = p(1) * (1 + p(4)) / (p(2) * c)
  r = p(1) * (p(3) + 1) / (pm**(p(3) + 2) * c)
  s = p(1) / pm * p(4) / c
  a(1) = 0.3_c_double * pm
  force = r * a(1)**(p(3) + 2) / (p(3) + 2) + a(1) * (r * (pm**(p(3) + 1) - a(1)**(p(3) + 1)) &
          / (p(3) + 1) + s)
  diss = 4 * r * a(1)**(p(3) + 3) / ((p(3) + 2) * (p(3) + 3))
  w2 = p(6) + force / a(1)
  call check_status(fit%eval(p, FRICREG_FIT_DISPLACEMENT, a, f, z, df, dz), FRICREG_OK, 'eval')
  call check_close(f(1), sqrt(w2) / two_pi, 1e-12_c_double * f(1), 'f: the closed form')
  call check_close(z(1), p(5) + diss / (two_pi * w2 * a(1)**2), 1e-12_c_double, &
                   'zeta: the closed form')
  call check(dz(FRICREG_FIT_ZETA0 + 1, 1) == 1.0_c_double, 'dzeta/dzeta0 = 1')

  call check_status(fit%params(q), FRICREG_EINVAL, 'params before a run')
  do i = 1, 8
    amp(i) = 0.37_c_double * 1.4085e-4_c_double * 0.03_c_double * 50.0_c_double**((i - 1) / 7.0) &
             * (two_pi * 165)**2
  end do
  call check_status(fit%eval(truth, FRICREG_FIT_ACCELERATION, amp, fr, ze), FRICREG_OK, 'levels')
  call check_status(fit%set_sensor(0.37_c_double), FRICREG_OK, 'set_sensor')
  call check_status(fit%eval(truth, FRICREG_FIT_ACCELERATION, amp, fr, ze), FRICREG_OK, 'levels')
  call check_status(fit%set_levels(FRICREG_FIT_ACCELERATION, amp, fr, ze(1:7)), FRICREG_ESIZE, &
                    'levels of different sizes')
  call check_status(fit%set_levels(FRICREG_FIT_ACCELERATION, amp, fr, ze), FRICREG_OK, &
                    'set_levels')
  sf = 5e-4_c_double * fr
  sz = 0.01_c_double * ze
  call check_status(fit%set_deviations(sf, sz), FRICREG_OK, 'set_deviations')
  call check_status(fit%set_fixed(FRICREG_FIT_BETA, truth(4)), FRICREG_OK, 'fix beta')
  call check_status(fit%set_fixed(FRICREG_FIT_K0, truth(6)), FRICREG_OK, 'fix K0')
  call check_status(fit%set_free(FRICREG_FIT_FS, 300.0_c_double, 0.0_c_double, huge(1.0_c_double)), &
                    FRICREG_OK, 'free F_S')
  call check_status(fit%set_free(FRICREG_FIT_KT, 3e4_c_double, 0.0_c_double, huge(1.0_c_double)), &
                    FRICREG_OK, 'free K_T')
  call check_status(fit%run(), FRICREG_OK, 'run')
  call check_status(fit%params(q), FRICREG_OK, 'params')
  call check_status(fit%covariance(cov, lo, hi), FRICREG_OK, 'covariance')
  do j = 1, 6
    call check_close(q(j), truth(j), 1e-6_c_double * truth(j), 'a parameter recovered')
    call check(lo(j) <= truth(j) .and. truth(j) <= hi(j), 'inside its interval')
  end do
  call check(cov(4, 4) == 0.0_c_double .and. cov(1, 1) > 0.0_c_double, 'fixed: no variance')
  call check_status(fit%value(FRICREG_FIT_NFREE, v), FRICREG_OK, 'value')
  call check(v == 4.0_c_double, 'four free parameters')

  ! ---- The HB model: the Jenkins oscillator's closed form, fitted from 2x off
  call check_status(hb%create(1, 1, 1), FRICREG_OK, 'hb create')
  call check_status(hb%set_stiffness(reshape([1.0_c_double], [1, 1])), FRICREG_OK, 'stiffness')
  call check_status(hb%set_elements(reshape([1.0_c_double], [1, 1]), [2 * kt], [mun / 2]), &
                    FRICREG_OK, 'the element, 2x off')
  call check_status(hb%set_newton(1e-12_c_double, 50), FRICREG_OK, 'set_newton')
  dl = mun / kt
  do i = 1, 6
    beta = acos(1 - 2 * dl / ah(i))
    w2 = 1 + kt / pi * (beta - sin(2 * beta) / 2)
    fh(i) = sqrt(w2) / two_pi
    zh(i) = 4 * mun * (ah(i) - dl) / (2 * pi * ah(i)**2 * w2)
  end do
  call check_status(fit%set_model_hb(hb, 1, [el, el], [1, 1], [1, 1], [1]), FRICREG_ESIZE, &
                    'set_model_hb: index of another size')
  call check_status(fit%set_model_hb(hb, 1, [el, el], [0, 0], [1, 1], [0, 1]), FRICREG_EINVAL, &
                    'set_model_hb: counted from 0')
  call check_status(fit%set_model_hb(hb, 1, [el, el], [1, 1], [1, 1], [1, 2]), FRICREG_OK, &
                    'set_model_hb')
  call check_status(fit%set_sensor_dof(2), FRICREG_EINVAL, 'set_sensor_dof: dof 2 of 1')
  call check_status(fit%set_sensor_dof(1), FRICREG_OK, 'set_sensor_dof')
  call check_status(fit%set_levels(FRICREG_FIT_DISPLACEMENT, ah, fh, zh), FRICREG_OK, &
                    'set_levels, HB')
  call check_status(fit%run(), FRICREG_OK, 'run, HB')
  call check_status(fit%params(q), FRICREG_ESIZE, 'params(6) of two')
  call check_status(fit%params(qh), FRICREG_OK, 'params, HB')
  call check_close(qh(1), kt, 1e-6_c_double * kt, 'kt recovered')
  call check_close(qh(2), mun, 1e-6_c_double * mun, 'mu N recovered')
  call check_status(fit%covariance(covh, loh, hih), FRICREG_OK, 'covariance, HB')
  call check(loh(1) <= qh(1) .and. qh(1) <= hih(1) .and. covh(2, 2) >= 0, 'interval, HB')
  call check_status(fit%value(FRICREG_FIT_NMARCH, v), FRICREG_OK, 'value NMARCH')
  call check(v >= 1.0_c_double, 'backbone marches counted')
  ! ---- QSMA's closed form of the same oscillator (slipping: omega^2 = 1 + mun/a, zeta =
  ! 4 mun (a - mun/kt)/(2 pi (a + mun) a)), fitted with qsma = .true. from 2x off
  do i = 1, 6
    fh(i) = sqrt(1 + mun / ah(i)) / two_pi
    zh(i) = 4 * mun * (ah(i) - dl) / (2 * pi * (ah(i) + mun) * ah(i))
  end do
  call check_status(fit%set_model_hb(hb, 1, [el, el], [1, 1], [1, 1], [1, 2], qsma=.true.), &
                    FRICREG_OK, 'set_model_hb, qsma')
  call check_status(fit%set_free(0, 2 * kt, 0.0_c_double, huge(1.0_c_double)), FRICREG_OK, &
                    'kt 2x off again')
  call check_status(fit%set_free(1, mun / 2, 0.0_c_double, huge(1.0_c_double)), FRICREG_OK, &
                    'mu N 2x off again')
  call check_status(fit%set_sensor_dof(1), FRICREG_EINVAL, 'set_sensor_dof: QSMA is modal')
  call check_status(fit%set_sensor(1.0_c_double), FRICREG_OK, 'modal amplitudes (not 0.37)')
  call check_status(fit%set_levels(FRICREG_FIT_DISPLACEMENT, ah, fh, zh), FRICREG_OK, &
                    'set_levels, QSMA')
  call check_status(fit%run(), FRICREG_OK, 'run, QSMA')
  call check_status(fit%params(qh), FRICREG_OK, 'params, QSMA')
  call check_close(qh(1), kt, 1e-6_c_double * kt, 'kt recovered by QSMA')
  call check_close(qh(2), mun, 1e-6_c_double * mun, 'mu N recovered by QSMA')
  call check_status(fit%set_model_modal_iwan(), FRICREG_OK, 'set_model_modal_iwan')
  call check_status(fit%set_sensor_dof(1), FRICREG_EINVAL, 'set_sensor_dof: modal Iwan')
  call check_status(fit%eval(truth, FRICREG_FIT_DISPLACEMENT, a, f, z), FRICREG_OK, &
                    'eval: six parameters again')
  call fit%destroy()
  call hb%destroy()
  call finish('test_fit')
end program test_fit
