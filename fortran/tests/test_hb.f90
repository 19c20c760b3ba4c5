! SPDX-License-Identifier: GPL-3.0-or-later
! test_hb.f90 — harmonic balance (fricreg_hb.h) from Fortran: the type fricreg_hb_driver of
! module fricreg.
!
! Values: one mass m = 2 on a spring k = 3 and a Jenkins element kt = 1.5 that never slips
! (mun = 1e6), Rayleigh C = 0.02 K = 0.06, forced by 0.5 cos(Omega t): a linear oscillator of
! stiffness 4.5 whose response X = 0.5/(d + i c), d = 4.5 - 2 Omega^2, c = 0.06 Omega, gives
! a_1 = 0.5 d/(d^2 + c^2), b_1 = 0.5 c/(d^2 + c^2) (X_h = a_h - i b_h, fricreg_hb.h) and the RMS
! |X|/sqrt(2) (closed form), largest where d|X|/dOmega = 0: Omega^2 = (4.5 - 0.06^2/4)/2,
! Omega = 1.49984999250, RMS 3.92856743987 (the located peak, hb%peak). A two-mass chain with a slipping element, J in Fortran's order:
! the type's solution equals the C functions' (called through bind(C), J transposed by hand)
! bit for bit, and so does the truncation error's estimate. set_jenkins and set_jenkins_normal,
! the structure's names, give set_elements' and set_normal_elements' solutions bit for bit
! (set_iwan_normal with one slider too, with two halves of the slider to 1e-12);
! set_matrix dense gives set_mass's and set_stiffness's bit for bit, compressed (a sparse model)
! to Newton's tolerance; which = FRICREG_CONTACTS, 0 and a dense format with values(:) refused.
! add_elements of a jenkins_normal gives set_normal_elements' solution bit for bit;
! set_jenkins_2d_normal (Je(2, 2) in Fortran's order, q with 3 columns) equals C's function
! called through bind(C) with Je's rows by hand, bit for bit.
program test_hb
  use fricreg
  use ftest
  implicit none
  type(fricreg_hb_driver) :: hb, chain
  type(c_ptr) :: p
  real(c_double), parameter :: w = 1.2_c_double
  real(c_double) :: lev, q(7, 1), x(7, 1), d, c, rms(1), omega, big, big2, qc(7, 1), q2(7, 1), bad(5, 1)
  real(c_double) :: lam(2, 2), lam3(2, 3)
  real(c_double) :: M2(2, 2), K2(2, 2), J2(1, 2), Jrow(2), Jn2(1, 2), qn(7, 2), pw, pr
  real(c_double) :: ec(2), ea(2), et(2), eat(2), qn2(7, 2), q3(7, 3), q3c(7, 3), Je2(2, 2)
  type(fricreg_hb_driver) :: sparse
  integer :: k, btype, bpoint, method
  real(c_double) :: mu
  logical :: stable

  call check_status(hb%create(1, 1, 3), FRICREG_OK, 'create')
  call check(hb%ndof() == 1 .and. hb%nelements() == 1 .and. hb%harmonics() == 3, 'sizes')
  call check_status(hb%set_mass(reshape([2.0_c_double], [1, 1])), FRICREG_OK, 'set_mass')
  call check_status(hb%set_stiffness(reshape([3.0_c_double], [1, 1])), FRICREG_OK, 'set_stiffness')
  call check_status(hb%set_rayleigh(0.0_c_double, 0.02_c_double), FRICREG_OK, 'set_rayleigh')
  call check_status(hb%set_elements(reshape([1.0_c_double], [1, 1]), [1.5_c_double], &
                                    [1e6_c_double]), FRICREG_OK, 'set_elements')
  call check_status(hb%set_excitation([0.5_c_double], [0.0_c_double]), FRICREG_OK, 'excitation')
  call check_status(hb%solve(w, q), FRICREG_OK, 'solve')
  d = 4.5_c_double - 2.0_c_double * w * w
  c = 0.06_c_double * w
  call check_close(q(2, 1), 0.5_c_double * d / (d * d + c * c), 1e-12_c_double, 'a_1')
  call check_close(q(3, 1), 0.5_c_double * c / (d * d + c * c), 1e-12_c_double, 'b_1')
  call check(maxval(abs(q(4:, 1))) < 1e-12_c_double, 'no higher harmonics')
  call check_status(hb%displacement(x), FRICREG_OK, 'displacement')
  call check(maxval(abs(x - q)) < 1e-14_c_double, 'x = q (J = 1)')

  ! the branch from 0.5 to 3: every point's RMS in closed form
  call check_status(hb%continue(0.5_c_double, 3.0_c_double), FRICREG_OK, 'continue')
  call check(hb%points() >= 20, 'points')
  big = 0.0_c_double
  big2 = 0.0_c_double
  do k = 1, hb%points()
    call check_status(hb%point(k, omega, rms), FRICREG_OK, 'point')
    d = 4.5_c_double - 2.0_c_double * omega * omega
    c = 0.06_c_double * omega
    big = max(big, abs(rms(1) * sqrt(2.0_c_double) * sqrt(d * d + c * c) / 0.5_c_double - 1.0_c_double))
    call check_status(hb%point_displacement(k, x), FRICREG_OK, 'point_displacement')
    big2 = max(big2, abs(x(2, 1) - 0.5_c_double * d / (d * d + c * c)) * sqrt(d * d + c * c), &
               abs(x(3, 1) - 0.5_c_double * c / (d * d + c * c)) * sqrt(d * d + c * c))
  end do
  call check(big < 1e-8_c_double, 'RMS along the branch against the closed form')
  call check(big2 < 1e-8_c_double, 'a_1, b_1 along the branch against the closed form')
  call check_status(hb%point_displacement(-1, x), FRICREG_EINVAL, 'point_displacement -1')
  call check_status(hb%point_displacement(0, q2), FRICREG_OK, 'point_displacement 0')
  call check_status(hb%displacement(x), FRICREG_OK, 'displacement after the branch')
  call check(all(x == q2), 'point 0 is the last solution')
  call check_status(hb%point(1, omega, rms), FRICREG_OK, 'first point')
  call check_close(omega, 0.5_c_double, 1e-15_c_double, 'the branch starts at omega0')
  call check_status(hb%point(hb%points(), omega, rms), FRICREG_OK, 'last point')
  call check_close(omega, 3.0_c_double, 1e-15_c_double, 'the branch ends at omega1')
  call check_status(hb%peak(1, pw, pr), FRICREG_OK, 'peak')
  call check_close(pw, 1.49984999250_c_double, 1e-8_c_double, 'the peak''s omega, closed form')
  call check_close(pr, 3.92856743987_c_double, 4e-8_c_double, 'the peak''s RMS, closed form')
  call check_status(hb%peak(0, pw, pr), FRICREG_EINVAL, 'peak of dof 0')
  call check_status(hb%peak(2, pw, pr), FRICREG_EINVAL, 'peak of dof 2 of 1')
  ! Hill's stability: linear (the element stuck), so every multiplier has modulus
  ! exp(-c/(2m) 2 pi/omega) = exp(-0.015 2 pi/omega), stable, and no bifurcation
  call check_status(hb%stability(1, stable, mu), FRICREG_EINVAL, 'stability while off')
  call check_status(hb%set_stability(.true.), FRICREG_OK, 'set_stability')
  call check_status(hb%continue(0.5_c_double, 3.0_c_double), FRICREG_OK, 'continue with stability')
  call check_status(hb%stability(hb%points(), stable, mu), FRICREG_OK, 'stability of the last point')
  call check(stable, 'the last point is stable')
  call check_close(mu, exp(-0.015_c_double * 2.0_c_double * acos(-1.0_c_double) / 3.0_c_double), &
                   1e-9_c_double, 'mu_max, closed form')
  call check_status(hb%stability(0, stable, mu), FRICREG_OK, 'stability of the last solution')
  ! its two exponents: Re lambda = -c/(2m) = -0.015 each
  call check_status(hb%exponents(0, lam), FRICREG_OK, 'exponents of the last solution')
  call check_close(lam(1, 1), -0.015_c_double, 1e-9_c_double, 'Re lambda 1, closed form')
  call check_close(lam(1, 2), -0.015_c_double, 1e-9_c_double, 'Re lambda 2, closed form')
  call check_status(hb%exponents(0, lam3), FRICREG_ESIZE, 'exponents(2, 3) of 1 dof')
  call check_status(hb%exponents(-1, lam), FRICREG_EINVAL, 'exponents of point -1')
  ! by the exact monodromy (the automatic choice for a Jenkins element), then by Hill's method:
  ! the same closed form
  call check_status(hb%stability_method(method), FRICREG_OK, 'stability_method')
  call check(method == FRICREG_HB_STABILITY_MONODROMY, 'the monodromy for a Jenkins element')
  call check_status(hb%set_newton_solver(7), FRICREG_EINVAL, 'set_newton_solver 7')
  call check_status(hb%set_newton_solver(FRICREG_HB_NEWTON_DENSE), FRICREG_OK, &
                    'set_newton_solver dense')
  call check_status(hb%set_receptance(7), FRICREG_EINVAL, 'set_receptance 7')
  call check_status(hb%set_receptance(FRICREG_HB_RECEPTANCE_LU), FRICREG_OK, 'set_receptance LU')
  call check_status(hb%set_stability_method(7), FRICREG_EINVAL, 'set_stability_method 7')
  call check_status(hb%set_stability_method(FRICREG_HB_STABILITY_HILL), FRICREG_OK, &
                    'set_stability_method Hill')
  call check_status(hb%stability_method(method), FRICREG_OK, 'stability_method Hill')
  call check(method == FRICREG_HB_STABILITY_HILL, 'Hill''s method chosen')
  call check_status(hb%solve(3.0_c_double, q), FRICREG_OK, 'solve by Hill''s method')
  call check_status(hb%stability(0, stable, mu), FRICREG_OK, 'Hill''s stability')
  call check_close(mu, exp(-0.015_c_double * 2.0_c_double * acos(-1.0_c_double) / 3.0_c_double), &
                   1e-9_c_double, 'Hill''s mu_max, closed form')
  call check_status(hb%stability(-1, stable, mu), FRICREG_EINVAL, 'stability of k = -1')
  call check(hb%bifurcations() == 0, 'no bifurcation on a linear branch')
  call check_status(hb%bifurcation(1, btype, omega, bpoint, rms), FRICREG_EINVAL, 'bifurcation 1 of 0')
  call check_status(hb%bifurcation_level(1, lev), FRICREG_EINVAL, 'bifurcation_level 1 of 0')
  ! the branch in the level at w: linear, every point's RMS lambda 0.5/(sqrt(2) |d + i c|)
  call check_status(hb%continue_level(w, 0.5_c_double, 2.0_c_double), FRICREG_OK, 'continue_level')
  d = 4.5_c_double - 2.0_c_double * w * w
  c = 0.06_c_double * w
  big = 0.0_c_double
  do k = 1, hb%points()
    call check_status(hb%point(k, omega, rms), FRICREG_OK, 'level point')
    call check_status(hb%point_level(k, lev), FRICREG_OK, 'point_level')
    big = max(big, abs(rms(1) * sqrt(2.0_c_double) * sqrt(d * d + c * c) / (0.5_c_double * lev) &
                       - 1.0_c_double))
  end do
  call check(big < 1e-9_c_double .and. omega == w .and. lev == 2.0_c_double, &
             'RMS along the level branch against the closed form')
  call check_status(hb%point_level(0, lev), FRICREG_EINVAL, 'point_level 0')

  ! errors: Fortran's shape checks, C's refusals, each with a message
  call check_status(hb%solve(w, bad), FRICREG_ESIZE, 'q of the wrong shape')
  call check(len(hb%errmsg()) > 0, 'message of ESIZE')
  call check_status(hb%point(0, omega, rms), FRICREG_EINVAL, 'point 0')
  call check_status(hb%set_rayleigh(-1.0_c_double, 0.0_c_double), FRICREG_EINVAL, 'a0 < 0')
  call check_status(hb%create(1, 0, 3), FRICREG_EINVAL, 'm = 0')
  call check(hb%harmonics() == 3, 'a failed create keeps the old driver')
  call hb%destroy()
  call hb%destroy()

  ! J in Fortran's order: the type against C's functions with J's rows by hand
  M2 = reshape([1.0_c_double, 0.0_c_double, 0.0_c_double, 2.0_c_double], [2, 2])
  K2 = reshape([5.0_c_double, -2.0_c_double, -2.0_c_double, 3.0_c_double], [2, 2])
  J2(1, :) = [1.0_c_double, -1.0_c_double]
  Jrow = [1.0_c_double, -1.0_c_double]
  call check_status(chain%create(2, 1, 3), FRICREG_OK, 'chain create')
  call check_status(chain%set_mass(M2), FRICREG_OK, 'chain M')
  call check_status(chain%set_stiffness(K2), FRICREG_OK, 'chain K')
  call check_status(chain%set_rayleigh(0.05_c_double, 0.0_c_double), FRICREG_OK, 'chain C')
  call check_status(chain%set_elements(J2, [4.0_c_double], [0.1_c_double]), FRICREG_OK, 'chain J')
  call check_status(chain%set_excitation([1.0_c_double, 0.0_c_double], [0.0_c_double, 0.0_c_double]), &
                    FRICREG_OK, 'chain excitation')
  call check_status(chain%solve(1.1_c_double, q2), FRICREG_OK, 'chain solve')
  p = c_null_ptr
  call check_status(fricreg_hb_create(2_c_size_t, 1_c_size_t, 3_c_int, p), FRICREG_OK, 'C create')
  call check_status(fricreg_hb_set_mass(p, 2_c_size_t, M2), FRICREG_OK, 'C M')
  call check_status(fricreg_hb_set_stiffness(p, 2_c_size_t, K2), FRICREG_OK, 'C K')
  call check_status(fricreg_hb_set_rayleigh(p, 0.05_c_double, 0.0_c_double), FRICREG_OK, 'C C')
  call check_status(fricreg_hb_set_elements(p, 1_c_size_t, 2_c_size_t, Jrow, [4.0_c_double], &
                                            [0.1_c_double]), FRICREG_OK, 'C J')
  call check_status(fricreg_hb_set_excitation(p, 2_c_size_t, [1.0_c_double, 0.0_c_double], &
                                              [0.0_c_double, 0.0_c_double]), FRICREG_OK, 'C p')
  call check_status(fricreg_hb_solve(p, 1.1_c_double, 7_c_size_t, q=qc), FRICREG_OK, 'C solve')
  call check_status(fricreg_hb_truncation_error(p, -1_c_size_t, 2_c_size_t, ec, ea), FRICREG_OK, &
                    'C truncation_error')
  call fricreg_hb_free(p)
  call check(all(q2 == qc), 'the type equals C bit for bit')
  ! the truncation error's estimate of the last solution (k = 0): C's, bit for bit; an element
  ! that slips gives harmonics beyond H = 3, so an estimate above rounding
  call check_status(chain%truncation_error(0, et, eat), FRICREG_OK, 'truncation_error')
  call check(all(et == ec) .and. all(eat == ea), 'the estimate equals C''s bit for bit')
  call check(minval(et) > 1e-9_c_double, 'a slipping element: an estimate above rounding')
  call check_status(chain%truncation_error(0, et), FRICREG_OK, 'truncation_error without amplitudes')
  call check(all(et == ec), 'the same without amplitudes')
  call check_status(chain%truncation_error(-1, et), FRICREG_EINVAL, 'truncation_error of k = -1')
  call check_status(chain%truncation_error(0, rms), FRICREG_ESIZE, 'rms_error of the wrong size')
  call check(abs(q2(2, 1)) + abs(q2(3, 1)) > 0.1_c_double / 4.0_c_double, 'the element slips')
  ! an Iwan element of one slider is the Jenkins element, to the bit; k and phi are (ns, m)
  call check_status(chain%set_iwan(J2, reshape([4.0_c_double], [1, 1]), &
                                   reshape([0.1_c_double], [1, 1])), FRICREG_OK, 'set_iwan')
  call check_status(chain%solve(1.1_c_double, qc), FRICREG_OK, 'Iwan solve')
  call check(all(q2 == qc), 'one slider equals the Jenkins element bit for bit')
  call check_status(chain%set_iwan(J2, reshape([4.0_c_double, 1.0_c_double], [2, 1]), &
                                   reshape([0.1_c_double], [1, 1])), FRICREG_ESIZE, 'phi (1, 1)')
  ! lift-off with kn = 0: the Jenkins element of mun = mu N0 on u's harmonics (the preload only
  ! moves the mean); q has two columns, u then g
  Jn2(1, :) = [0.0_c_double, 1.0_c_double]
  call check_status(chain%set_normal_elements(J2, Jn2, [4.0_c_double], [0.2_c_double], &
                                              [0.5_c_double], [0.0_c_double]), FRICREG_OK, &
                    'set_normal_elements')
  call check_status(chain%solve(1.1_c_double, qc), FRICREG_ESIZE, 'q with m columns')
  call check_status(chain%solve(1.1_c_double, qn), FRICREG_OK, 'lift-off solve')
  ! (each solved to Newton's 1e-10 of the scale, along its own continuation in the level)
  call check(maxval(abs(qn(2:7, 1) - q2(2:7, 1))) <= 1e-9_c_double * maxval(abs(q2)), &
             'kn = 0 is the Jenkins element of mun = mu N0')
  call check_status(chain%set_normal_elements(J2, Jn2, [4.0_c_double], [-0.2_c_double], &
                                              [0.5_c_double], [0.0_c_double]), FRICREG_EINVAL, &
                    'mu < 0')
  call check_status(chain%set_normal_elements(J2, J2, [4.0_c_double], [0.2_c_double], &
                                              [0.5_c_double, 1.0_c_double], [0.0_c_double]), &
                    FRICREG_ESIZE, 'n0(2)')
  call check_status(chain%set_elements(J2, [4.0_c_double], [0.1_c_double]), FRICREG_OK, &
                    'back to Jenkins elements')
  call check_status(chain%solve(1.1_c_double, qc), FRICREG_OK, 'Jenkins solve again')
  call check(all(q2 == qc), 'back to m columns, the Jenkins solution bit for bit')
  ! the structure's names: the same elements, the same solutions bit for bit, C's messages
  ! naming them
  call check_status(chain%set_jenkins_normal(J2, Jn2, [4.0_c_double], [0.2_c_double], &
                                             [0.5_c_double], [0.0_c_double]), FRICREG_OK, &
                    'set_jenkins_normal')
  call check_status(chain%solve(1.1_c_double, qn2), FRICREG_OK, 'set_jenkins_normal solve')
  call check(all(qn2 == qn), 'set_jenkins_normal is set_normal_elements bit for bit')
  ! by type: add_elements of a jenkins_normal (its rows t, n in J(2, ndof), params kt, mu, kn,
  ! n0, gap) is the setter bit for bit
  call check_status(chain%clear_elements(), FRICREG_OK, 'clear_elements')
  call check(chain%element_count() == 0, 'no elements after clear')
  call check_status(chain%add_elements('jenkins_normal', reshape([J2(1, :), Jn2(1, :)], [2, 2], &
                                                                 order=[2, 1]), &
                                       reshape([4.0_c_double, 0.2_c_double, 0.0_c_double, &
                                                0.5_c_double], [4, 1])), FRICREG_ESIZE, &
                    'add_elements with 4 parameters of 5')
  call check_status(chain%add_elements('jenkins_normal', reshape([J2(1, :), Jn2(1, :)], [2, 2], &
                                                                 order=[2, 1]), &
                                       reshape([4.0_c_double, 0.2_c_double, 0.0_c_double, &
                                                0.5_c_double, 0.0_c_double], [5, 1])), &
                    FRICREG_OK, 'add_elements jenkins_normal')
  call check(chain%element_count() == 1, 'one element added')
  call check_status(chain%solve(1.1_c_double, qn2), FRICREG_OK, 'add_elements solve')
  call check(all(qn2 == qn), 'add_elements is set_normal_elements bit for bit')
  ! Iwan elements with lift-off: one slider is the Jenkins element bit for bit, two halves of
  ! it (kt/2, mu/2 each) it to rounding; k and mu are (ns, m)
  call check_status(chain%set_iwan_normal(J2, Jn2, reshape([4.0_c_double], [1, 1]), &
                                          reshape([0.2_c_double], [1, 1]), [0.5_c_double], &
                                          [0.0_c_double]), FRICREG_OK, 'set_iwan_normal ns = 1')
  call check_status(chain%solve(1.1_c_double, qn2), FRICREG_OK, 'set_iwan_normal solve')
  call check(all(qn2 == qn), 'set_iwan_normal of one slider is set_normal_elements bit for bit')
  call check_status(chain%set_iwan_normal(J2, Jn2, reshape([2.0_c_double, 2.0_c_double], [2, 1]), &
                                          reshape([0.1_c_double, 0.1_c_double], [2, 1]), &
                                          [0.5_c_double], [0.0_c_double]), FRICREG_OK, &
                    'set_iwan_normal ns = 2')
  call check_status(chain%solve(1.1_c_double, qn2), FRICREG_OK, 'set_iwan_normal ns = 2 solve')
  call check(maxval(abs(qn2 - qn)) <= 1e-12_c_double * maxval(abs(qn)), &
             'two half sliders are the Jenkins element')
  call check_status(chain%set_iwan_normal(J2, Jn2, reshape([2.0_c_double, 2.0_c_double], [2, 1]), &
                                          reshape([0.1_c_double], [1, 1]), [0.5_c_double], &
                                          [0.0_c_double]), FRICREG_ESIZE, 'set_iwan_normal: mu (1, 1)')
  call check(index(chain%errmsg(), 'mu') > 0, 'message: ' // chain%errmsg())
  ! the 3-D contact element: x on J2's row, y on dof 2, normal Jn2; against C's function with
  ! Je's rows by hand (row-major: x's row, then y's)
  Je2(1, :) = J2(1, :)
  Je2(2, :) = [0.0_c_double, 1.0_c_double]
  call check_status(chain%set_jenkins_2d_normal(Je2, Jn2, [4.0_c_double], [0.2_c_double], &
                                                [0.5_c_double], [0.3_c_double]), FRICREG_OK, &
                    'set_jenkins_2d_normal')
  call check_status(chain%solve(1.1_c_double, qn2), FRICREG_ESIZE, 'q with 2 m columns')
  call check_status(chain%solve(1.1_c_double, q3), FRICREG_OK, '3-D solve')
  p = c_null_ptr
  call check_status(fricreg_hb_create(2_c_size_t, 1_c_size_t, 3_c_int, p), FRICREG_OK, 'C create')
  call check_status(fricreg_hb_set_mass(p, 2_c_size_t, M2), FRICREG_OK, 'C M')
  call check_status(fricreg_hb_set_stiffness(p, 2_c_size_t, K2), FRICREG_OK, 'C K')
  call check_status(fricreg_hb_set_rayleigh(p, 0.05_c_double, 0.0_c_double), FRICREG_OK, 'C C')
  call check_status(fricreg_hb_set_jenkins_2d_normal(p, 1_c_size_t, 2_c_size_t, &
                                                     [1.0_c_double, -1.0_c_double, &
                                                      0.0_c_double, 1.0_c_double], &
                                                     [0.0_c_double, 1.0_c_double], [4.0_c_double], &
                                                     [0.2_c_double], [0.5_c_double], &
                                                     [0.3_c_double]), FRICREG_OK, 'C 3-D')
  call check_status(fricreg_hb_set_excitation(p, 2_c_size_t, [1.0_c_double, 0.0_c_double], &
                                              [0.0_c_double, 0.0_c_double]), FRICREG_OK, 'C p')
  call check_status(fricreg_hb_solve(p, 1.1_c_double, 21_c_size_t, q=q3c), FRICREG_OK, 'C solve')
  call fricreg_hb_free(p)
  call check(all(q3 == q3c), 'the 3-D element: the type equals C bit for bit')
  call check(maxval(abs(q3(2:7, 2))) > 1e-3_c_double, 'the element moves on y')
  call check_status(chain%set_jenkins_2d_normal(J2, Jn2, [4.0_c_double], [0.2_c_double], &
                                                [0.5_c_double], [0.3_c_double]), FRICREG_ESIZE, &
                    'set_jenkins_2d_normal: Je (1, 2)')
  call check(index(chain%errmsg(), 'Je') > 0, 'message: ' // chain%errmsg())
  call check_status(chain%set_jenkins_normal(J2, Jn2, [4.0_c_double], [-0.2_c_double], &
                                             [0.5_c_double], [0.0_c_double]), FRICREG_EINVAL, &
                    'set_jenkins_normal: mu < 0')
  call check(index(chain%errmsg(), 'set_jenkins_normal: ') == 1, 'message: ' // chain%errmsg())
  call check_status(chain%set_jenkins(J2, [4.0_c_double], [0.1_c_double]), FRICREG_OK, &
                    'set_jenkins')
  call check_status(chain%solve(1.1_c_double, qc), FRICREG_OK, 'set_jenkins solve')
  call check(all(q2 == qc), 'set_jenkins is set_elements bit for bit')
  call check_status(chain%set_jenkins(J2, [-4.0_c_double], [0.1_c_double]), FRICREG_EINVAL, &
                    'set_jenkins: kt < 0')
  call check(index(chain%errmsg(), 'set_jenkins: ') == 1, 'message: ' // chain%errmsg())
  call check_status(chain%set_jenkins(J2, [4.0_c_double, 1.0_c_double], [0.1_c_double]), &
                    FRICREG_ESIZE, 'set_jenkins: kt(2)')
  ! set_matrix, dense: set_mass's and set_stiffness's path, bit for bit
  call check_status(chain%set_matrix(FRICREG_MASS, M2), FRICREG_OK, 'set_matrix(FRICREG_MASS, M)')
  call check_status(chain%set_matrix(FRICREG_STIFFNESS, K2), FRICREG_OK, &
                    'set_matrix(FRICREG_STIFFNESS, K)')
  call check_status(chain%solve(1.1_c_double, qc), FRICREG_OK, 'set_matrix dense solve')
  call check(all(q2 == qc), 'set_matrix dense is set_mass, set_stiffness bit for bit')
  ! refusals, the model kept: J is not the driver's matrix, which = 0, values(:) as dense
  call check_status(chain%set_matrix(FRICREG_CONTACTS, M2), FRICREG_EINVAL, &
                    'set_matrix(FRICREG_CONTACTS)')
  call check(index(chain%errmsg(), 'set_matrix: which = 4 is not a model matrix') == 1, &
             'message: ' // chain%errmsg())
  call check_status(chain%set_matrix(0_c_int, FRICREG_MATRIX_CSC, [1_c_int64_t, 2_c_int64_t, &
                                     3_c_int64_t], [1_c_int64_t, 2_c_int64_t], &
                                     [1.0_c_double, 2.0_c_double]), FRICREG_EINVAL, &
                    'set_matrix(which = 0, CSC)')
  call check(index(chain%errmsg(), 'set_matrix: which = 0 is not a model matrix') == 1, &
             'message: ' // chain%errmsg())
  call check_status(chain%set_matrix(FRICREG_MASS, FRICREG_MATRIX_DENSE, [1_c_int64_t], &
                                     [1_c_int64_t], [1.0_c_double, 2.0_c_double]), &
                    FRICREG_EINVAL, 'set_matrix(FRICREG_MATRIX_DENSE, values(:))')
  call check_status(chain%set_matrix(FRICREG_MASS, bad), FRICREG_ESIZE, 'set_matrix(M (5, 1))')
  call check_status(chain%set_matrix(FRICREG_MASS, FRICREG_MATRIX_CSC, [1_c_int64_t, &
                                     2_c_int64_t, 3_c_int64_t], [1_c_int64_t], [1.0_c_double]), &
                    FRICREG_ESIZE, 'set_matrix(FRICREG_MASS, CSC), rowind shorter than nnz')
  call check_status(chain%solve(1.1_c_double, qc), FRICREG_OK, 'solve after the refusals')
  call check(all(q2 == qc), 'the refusals changed nothing')
  ! set_matrix, compressed: M diagonal (flags absent, one-based), K by its lower triangle's
  ! columns; the model sparse, its solution the dense one's to Newton's tolerance
  call check_status(sparse%create(2, 1, 3), FRICREG_OK, 'sparse create')
  call check_status(sparse%set_matrix(FRICREG_MASS, FRICREG_MATRIX_CSC, [1_c_int64_t, &
                                      2_c_int64_t, 3_c_int64_t], [1_c_int64_t, 2_c_int64_t], &
                                      [1.0_c_double, 2.0_c_double]), FRICREG_OK, &
                    'set_matrix(FRICREG_MASS, CSC)')
  call check_status(sparse%set_matrix(FRICREG_STIFFNESS, FRICREG_MATRIX_CSC, [1_c_int64_t, &
                                      3_c_int64_t, 4_c_int64_t], [1_c_int64_t, 2_c_int64_t, &
                                      2_c_int64_t], [5.0_c_double, -2.0_c_double, 3.0_c_double], &
                                      FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_LOWER), &
                    FRICREG_OK, 'set_matrix(FRICREG_STIFFNESS, CSC lower)')
  call check_status(sparse%set_rayleigh(0.05_c_double, 0.0_c_double), FRICREG_OK, 'sparse C')
  call check_status(sparse%set_jenkins(J2, [4.0_c_double], [0.1_c_double]), FRICREG_OK, &
                    'sparse J')
  call check_status(sparse%set_excitation([1.0_c_double, 0.0_c_double], &
                                          [0.0_c_double, 0.0_c_double]), FRICREG_OK, 'sparse p')
  call check_status(sparse%solve(1.1_c_double, qc), FRICREG_OK, 'sparse solve')
  call check(maxval(abs(qc - q2)) <= 1e-9_c_double * maxval(abs(q2)), &
             'set_matrix compressed: the dense solution to Newton''s tolerance')
  call sparse%destroy()
  call chain%destroy()
  call finish('test_hb')
end program test_hb
