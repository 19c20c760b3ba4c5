! SPDX-License-Identifier: GPL-3.0-or-later
! test_iwan.f90 — Iwan elements (fricreg_iwan.h) and the Jenkins elements' normal load with
! lift-off (fricreg_jenkins.h) from Fortran: the types fricreg_iwan_elements and
! fricreg_jenkins_elements of module fricreg, against hand-worked values.
!
! Values. Iwan, 1-D, one element of sliders k = (2, 1), phi = (0.5, 1.5): at u = 0.5 slider 1
! slips (2 * 0.5 > 0.5, force 0.5) and slider 2 sticks (0.5): f = 1, tangent 1; committed, the
! sliders sit at (0.5 - 0.5/2, 0) = (0.25, 0). Normal law n0 = 2, kn = 4: at g = -1,
! N0 + kn g = -2 < 0, separated: f = 0, N = 0. At g = 0.5, N = 4, the slip forces double to
! (1, 3); from the committed sliders at u = 1 slider 1 slips (2 * 0.75 > 1: force 1,
! df/dg = 0.5 * 4/2 = 1) and slider 2 sticks (force 1): f = 2, df/du = 1, df/dg = 1.
! Segalman, F_S = 2, K_T = 10, chi = -0.5, beta = 0, ns = 3: the sliders' stiffnesses sum to
! K_T and their slip forces to F_S. Jenkins, kt = 2, mu = 0.5, n0 = 1, kn = 2: at u = 1 and
! g = 0.5, N = 2, the bound 1 < kt u = 2: f = 1, df/du = 0, df/dg = mu kn = 1.
program test_iwan
  use fricreg
  use ftest
  implicit none
  type(fricreg_iwan_elements) :: iw, seg
  type(fricreg_jenkins_elements) :: jk
  real(c_double), parameter :: tol = 1e-14_c_double
  real(c_double) :: u(1, 1), f(1, 1), t(1, 1, 1), tg(1, 1), nf(1), g(1), w(1, 2, 1)
  real(c_double) :: k(2, 1), phi(2, 1), ks(3, 1), phis(3, 1), bad(3, 1)

  call check_status(iw%create(1, 1, 2), FRICREG_OK, 'create')
  call check(iw%size() == 1 .and. iw%sliders() == 2 .and. iw%dim() == 1, 'size, sliders, dim')
  k(:, 1) = [2.0_c_double, 1.0_c_double]
  phi(:, 1) = [0.5_c_double, 1.5_c_double]
  call check_status(iw%set_params(k, phi), FRICREG_OK, 'set_params')
  u = 0.5_c_double
  call check_status(iw%trial(u, f, t), FRICREG_OK, 'trial')
  call check_close(f(1, 1), 1.0_c_double, tol, 'f: one slider slipping, one stuck')
  call check_close(t(1, 1, 1), 1.0_c_double, tol, 'tangent: the stuck slider')
  call check_status(iw%commit(), FRICREG_OK, 'commit')
  call check_status(iw%get_slider(w), FRICREG_OK, 'get_slider')
  call check_close(w(1, 1, 1), 0.25_c_double, tol, 'slider 1')
  call check_close(w(1, 2, 1), 0.0_c_double, tol, 'slider 2')

  call check_status(iw%set_normal([2.0_c_double], [4.0_c_double]), FRICREG_OK, 'set_normal')
  u = 1.0_c_double
  g = -1.0_c_double
  call check_status(iw%trial_normal(u, g, f, nf, t, tg), FRICREG_OK, 'trial_normal separated')
  call check(f(1, 1) == 0.0_c_double .and. nf(1) == 0.0_c_double .and. &
             t(1, 1, 1) == 0.0_c_double .and. tg(1, 1) == 0.0_c_double, 'separated: all 0')
  g = 0.5_c_double
  call check_status(iw%trial_normal(u, g, f, nf, t, tg), FRICREG_OK, 'trial_normal')
  call check_close(nf(1), 4.0_c_double, tol, 'N')
  call check_close(f(1, 1), 2.0_c_double, tol, 'f at twice the preload')
  call check_close(t(1, 1, 1), 1.0_c_double, tol, 'df/du')
  call check_close(tg(1, 1), 1.0_c_double, tol, 'df/dg')

  call check_status(seg%create(1, 1, 3), FRICREG_OK, 'create Segalman')
  call check_status(seg%set_segalman([2.0_c_double], [10.0_c_double], [-0.5_c_double], &
                                     [0.0_c_double], 1e-4_c_double), FRICREG_OK, 'set_segalman')
  call check_status(seg%get_params(ks, phis), FRICREG_OK, 'get_params')
  call check_close(sum(ks), 10.0_c_double, 1e-13_c_double, 'K_T')
  call check_close(sum(phis), 2.0_c_double, 1e-13_c_double, 'F_S')

  call check_status(jk%create(1, 1), FRICREG_OK, 'create Jenkins')
  call check_status(jk%set_params([2.0_c_double], [1.0_c_double]), FRICREG_OK, 'set_params')
  call check_status(jk%set_normal([0.5_c_double], [1.0_c_double], [2.0_c_double]), FRICREG_OK, &
                    'Jenkins set_normal')
  g = 0.5_c_double
  call check_status(jk%trial_normal(u, g, f, nf, t, tg), FRICREG_OK, 'Jenkins trial_normal')
  call check_close(f(1, 1), 1.0_c_double, tol, 'Jenkins f = mu N')
  call check_close(nf(1), 2.0_c_double, tol, 'Jenkins N')
  call check(t(1, 1, 1) == 0.0_c_double, 'Jenkins df/du sliding')
  call check_close(tg(1, 1), 1.0_c_double, tol, 'Jenkins df/dg = mu kn')
  g = -1.0_c_double
  call check_status(jk%trial_normal(u, g, f), FRICREG_OK, 'Jenkins separated')
  call check(f(1, 1) == 0.0_c_double, 'Jenkins separated: f = 0')

  ! errors: wrong shapes (Fortran's check), bad parameters (C's), each with a message
  call check_status(iw%set_params(bad, bad), FRICREG_ESIZE, 'set_params, wrong shape')
  call check(len(iw%errmsg()) > 0, 'message of ESIZE')
  call check_status(iw%set_params(k, -phi), FRICREG_EINVAL, 'phi < 0')
  call check(index(iw%errmsg(), 'phi') > 0, 'message names phi')
  call check_status(seg%set_segalman([2.0_c_double], [10.0_c_double], [-1.0_c_double], &
                                     [0.0_c_double], 1e-4_c_double), FRICREG_EINVAL, 'chi = -1')
  call check_status(iw%set_normal([0.0_c_double], [4.0_c_double]), FRICREG_EINVAL, 'n0 = 0')
  call check_status(jk%set_normal([-0.5_c_double], [1.0_c_double], [2.0_c_double]), &
                    FRICREG_EINVAL, 'mu < 0')
  call check_status(iw%trial_normal(u, [1.0_c_double, 2.0_c_double], f), FRICREG_ESIZE, &
                    'g of the wrong size')
  call check_status(iw%create(1, 1, 0), FRICREG_EINVAL, 'ns = 0')
  call check(iw%sliders() == 2, 'a failed create keeps the old elements')

  call iw%destroy()
  call iw%destroy()
  call seg%destroy()
  call jk%destroy()
  call check_status(iw%commit(), FRICREG_ENULL, 'commit after destroy')
  call finish('test_iwan')
end program test_iwan
