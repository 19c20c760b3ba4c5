! SPDX-License-Identifier: GPL-3.0-or-later
! test_structure_jenkins.f90 — Jenkins elements through type(fricreg_structure) (set_jenkins,
! get_jenkins_state, set_jenkins_2d, get_jenkins_2d_state):
!   - one mass (2.385 kg) on 217.3 N/m and a stuck element (kt 200 N/m, mu N 1e30 N) under a
!     constant load P = -0.731 x 2.385 N: the spring 417.3 N/m, whose average-acceleration
!     Newmark solution is u_n = (P/k)(1 - cos(W n dt)), W = (2/dt) atan(w dt/2): at dt = 0.01 s,
!     u(1.37 s) = -0.00113279590437900 m (tests/cli.sh's), the element's force kt u;
!   - the element slipping (mu N = 0.05 N): it dissipates, and the energy balance closes; the
!     error estimate of its dissipation (get_jenkins_dissipation_error) is the C call's;
!   - Fortran's size checks (FRICREG_ESIZE naming the array) and C's refusals (kt <= 0);
!   - an Iwan element of two sliders (set_iwan, get_iwan_state) is two Jenkins elements on
!     copies of its row: the same run to rounding; those copies added as a "jenkins" and a
!     one-slider "iwan" element (add_elements, get_elements): set_jenkins's run bit for bit;
!   - a stuck, closed lift-off element (set_jenkins_normal, get_normal_forces): N = n0 + kn u;
!     an Iwan element of two stuck sliders with the same normal law (set_iwan_normal) runs the
!     same to rounding;
!   - a stuck 2-D element on two uncoupled masses is the spring kt on each axis: the closed form
!     above on both;
!   - a stuck, closed 3-D contact element (set_jenkins_2d_normal) on three uncoupled masses,
!     kt = kn = 200 N/m: the same closed form on x, y, and on z with the load P + n0 (the preload
!     n0 pushes back), N = n0 + kn u_z.
program test_structure_jenkins
  use fricreg
  use ftest
  implicit none
  type(fricreg_structure) :: st
  real(c_double) :: u(1), f(1), w(1), D(1), D2(2), residual, input, jenkins, De(1), Dc(1)
  real(c_double) :: u2(1), w2(2, 1), fj(2), wj(2), Dj(2), fm(2), sm(2), Dm(2)
  real(c_double), parameter :: Je(1, 1) = reshape([1.0_c_double], [1, 1])
  type(fricreg_structure) :: st2, st3
  real(c_double) :: u3(3), f3(2, 1), N3(1)
  real(c_double), parameter :: Jt3(2, 3) = reshape([1.0_c_double, 0.0_c_double, 0.0_c_double, &
                                                    1.0_c_double, 0.0_c_double, 0.0_c_double], &
                                                   [2, 3])
  real(c_double), parameter :: Jn3(1, 3) = reshape([0.0_c_double, 0.0_c_double, 1.0_c_double], &
                                                   [1, 3])
  real(c_double) :: uv(2), f2(2, 1), w2d(2, 1)
  real(c_double), parameter :: Je2(2, 2) = reshape([1.0_c_double, 0.0_c_double, 0.0_c_double, &
                                                    1.0_c_double], [2, 2])

  call check_status(st%create(1, 1), FRICREG_OK, 'create 1, 1')
  call check_status(st%set_mass(reshape([2.385_c_double], [1, 1])), FRICREG_OK, 'set_mass')
  call check_status(st%set_stiffness(reshape([217.3_c_double], [1, 1])), FRICREG_OK, &
                    'set_stiffness')
  call check_status(st%set_contacts(Je), FRICREG_OK, 'set_contacts')
  call check_status(st%set_bounds([0.0_c_double]), FRICREG_OK, 'set_bounds 0')
  call check_status(st%set_load([-0.731_c_double * 2.385_c_double]), FRICREG_OK, 'set_load')

  ! ---- stuck: the spring kt ----------------------------------------------------------------
  call check_status(st%set_jenkins(Je, [200.0_c_double], [1e30_c_double]), FRICREG_OK, &
                    'set_jenkins stuck')
  call check_status(st%run(0.01_c_double, 1.37_c_double), FRICREG_OK, 'run stuck')
  call check_status(st%get_state(u=u), FRICREG_OK, 'get_state')
  call check_close(u(1), -0.00113279590437900_c_double, 2e-15_c_double, 'u(1.37) closed form')
  call check_status(st%get_jenkins_state(f=f, w=w, D=D), FRICREG_OK, 'get_jenkins_state')
  call check_close(f(1), 200.0_c_double * u(1), 1e-15_c_double, 'f = kt u')
  call check(w(1) == 0.0_c_double .and. D(1) == 0.0_c_double, 'the slider did not move')

  ! ---- slipping: the elements dissipate, the balance closes ----------------------------------
  call check_status(st%set_jenkins(Je, [200.0_c_double], [0.05_c_double]), FRICREG_OK, &
                    'set_jenkins slipping')
  call check_status(st%set_initial([0.0_c_double], [0.0_c_double]), FRICREG_OK, 'set_initial')
  call check_status(st%run(0.01_c_double, 1.37_c_double), FRICREG_OK, 'run slipping')
  call check_status(st%get_jenkins_state(D=D), FRICREG_OK, 'get_jenkins_state D')
  call check_status(st%get_value(FRICREG_SVALUE_JENKINS, jenkins), FRICREG_OK, 'jenkins value')
  call check_status(st%get_value(FRICREG_SVALUE_RESIDUAL, residual), FRICREG_OK, 'residual')
  call check_status(st%get_value(FRICREG_SVALUE_INPUT, input), FRICREG_OK, 'input')
  call check(D(1) > 0.0_c_double .and. D(1) == jenkins, 'the element dissipated')
  call check(abs(residual) <= 1e-9_c_double * abs(input), 'the balance closes')
  ! the error estimate of its dissipation (get_jenkins_dissipation_error): the C call's, bit for
  ! bit, positive and finite; none before a step; Fortran's size is C's me
  call check_status(st%set_error_estimate(FRICREG_ESTIMATE_TWO_COMPANIONS), FRICREG_OK, &
                    'set_error_estimate')
  call check_status(st%set_initial([0.0_c_double], [0.0_c_double]), FRICREG_OK, 'set_initial')
  call check_status(st%get_jenkins_dissipation_error(De), FRICREG_EINVAL, 'no estimate yet')
  call check_status(st%run(0.01_c_double, 1.37_c_double), FRICREG_OK, 'run with the estimate')
  call check_status(st%get_jenkins_dissipation_error(De), FRICREG_OK, &
                    'get_jenkins_dissipation_error')
  call check_status(fricreg_structure_get_jenkins_dissipation_error(st%ptr, 1_c_size_t, Dc), &
                    FRICREG_OK, 'the C call')
  call check(De(1) == Dc(1) .and. De(1) > 0.0_c_double .and. De(1) < huge(De), &
             'the estimate: positive, finite, the C call''s')
  call check_status(st%get_jenkins_dissipation_error(D2), FRICREG_ESIZE, 'err of 2')
  call check_status(st%set_error_estimate(FRICREG_ESTIMATE_OFF), FRICREG_OK, 'estimate off')

  ! ---- refusals --------------------------------------------------------------------------------
  call check_status(st%set_jenkins(Je, [200.0_c_double, 1.0_c_double], [0.05_c_double]), &
                    FRICREG_ESIZE, 'kt of 2 entries')
  call check(index(st%errmsg(), 'kt') > 0, 'the message names kt')
  call check_status(st%set_jenkins(Je, [-1.0_c_double], [0.05_c_double]), FRICREG_EINVAL, &
                    'kt < 0')
  call check_status(st%get_jenkins_state(f=f, D=D2), FRICREG_ESIZE, &
                    'f and D differ in size')
  call check_status(st%get_jenkins_state(), FRICREG_ENULL, 'no output')

  ! ---- Iwan elements: two sliders are two Jenkins elements on copies of the row --------------
  call check_status(st%set_iwan(Je, reshape([150.0_c_double, 50.0_c_double], [2, 1]), &
                                reshape([0.03_c_double, 0.05_c_double], [2, 1])), FRICREG_OK, &
                    'set_iwan')
  call check_status(st%set_initial([0.0_c_double], [0.0_c_double]), FRICREG_OK, 'set_initial')
  call check_status(st%run(0.01_c_double, 1.37_c_double), FRICREG_OK, 'run Iwan')
  call check_status(st%get_state(u=u), FRICREG_OK, 'get_state Iwan')
  call check_status(st%get_iwan_state(f=f, w=w2, D=D), FRICREG_OK, 'get_iwan_state')
  call check_status(st%get_iwan_state(D=D2(1:1)), FRICREG_OK, 'get_iwan_state D alone')
  call check(D2(1) == D(1), 'D alone is D')
  call check_status(st%set_jenkins(reshape([1.0_c_double, 1.0_c_double], [2, 1]), &
                                   [150.0_c_double, 50.0_c_double], &
                                   [0.03_c_double, 0.05_c_double]), FRICREG_OK, &
                    'set_jenkins copies')
  call check_status(st%set_initial([0.0_c_double], [0.0_c_double]), FRICREG_OK, 'set_initial')
  call check_status(st%run(0.01_c_double, 1.37_c_double), FRICREG_OK, 'run copies')
  call check_status(st%get_state(u=u2), FRICREG_OK, 'get_state copies')
  call check_status(st%get_jenkins_state(f=fj, w=wj, D=Dj), FRICREG_OK, 'get_jenkins_state')
  call check_close(u(1), u2(1), 1e-14_c_double, 'Iwan = Jenkins copies: u')
  call check_close(f(1), fj(1) + fj(2), 1e-14_c_double, 'Iwan = Jenkins copies: f')
  call check_close(w2(2, 1), wj(2), 1e-14_c_double, 'Iwan = Jenkins copies: w')
  call check_close(D(1), Dj(1) + Dj(2), 1e-14_c_double, 'Iwan = Jenkins copies: D')
  call check(D(1) > 0.0_c_double, 'the Iwan element dissipated')
  call check_status(st%set_iwan(Je, reshape([150.0_c_double, 50.0_c_double], [2, 1]), &
                                reshape([0.03_c_double], [1, 1])), FRICREG_ESIZE, &
                    'phi of 1 slider')
  call check(index(st%errmsg(), 'phi') > 0, 'the message names phi')

  ! ---- add_elements: the copies as a Jenkins element and a one-slider Iwan element, added one
  ! after the other: set_jenkins's run bit for bit (the same kernel, the same coordinates) -------
  call check_status(st%clear_elements(), FRICREG_OK, 'clear_elements')
  call check(st%element_count() == 0, 'none held')
  call check_status(st%add_elements('jenkins', Je, reshape([150.0_c_double, 0.03_c_double], &
                                                           [2, 1])), FRICREG_OK, 'add jenkins')
  call check_status(st%add_elements('iwan', Je, reshape([50.0_c_double, 0.05_c_double], [2, 1]), &
                                    ns=1), FRICREG_OK, 'add iwan')
  call check(st%element_count() == 2, 'two held')
  call check_status(st%set_initial([0.0_c_double], [0.0_c_double]), FRICREG_OK, 'set_initial')
  call check_status(st%run(0.01_c_double, 1.37_c_double), FRICREG_OK, 'run the mix')
  call check_status(st%get_state(u=u), FRICREG_OK, 'get_state mix')
  call check_status(st%get_elements(f=fm, state=sm, D=Dm), FRICREG_OK, 'get_elements')
  call check(u(1) == u2(1) .and. all(fm == fj) .and. all(sm == wj) .and. all(Dm == Dj), &
             'the mix is set_jenkins''s copies bit for bit')
  call check_status(st%add_elements('no such', Je, reshape([1.0_c_double, 0.1_c_double], &
                                                           [2, 1])), FRICREG_EINVAL, 'unknown type')
  call check(index(st%errmsg(), 'no such') > 0, 'the message names the type')
  call check_status(st%add_elements('jenkins', Je, reshape([1.0_c_double], [1, 1])), &
                    FRICREG_ESIZE, 'params of 1 row')
  call check_status(st%get_elements(D=Dm(1:1)), FRICREG_ESIZE, 'D of 1')
  call check(st%element_count() == 2, 'still two')

  ! ---- lift-off: stuck and closed, the springs kt and kn and the force -n0 -------------------
  ! one mass, Je = Jn = 1: K 217.3 + 200 + 100 under P - n0; N = n0 + kn u stays > 0 (u
  ! peaks near 2 (P - n0)/517.3 = -0.0145)
  call check_status(st%set_jenkins_normal(Je, Je, [200.0_c_double], [1e20_c_double], &
                                          [2.0_c_double], [100.0_c_double]), FRICREG_OK, &
                    'set_jenkins_normal')
  call check_status(st%set_initial([0.0_c_double], [0.0_c_double]), FRICREG_OK, 'set_initial')
  call check_status(st%run(0.01_c_double, 1.37_c_double), FRICREG_OK, 'run lift-off')
  call check_status(st%get_state(u=u), FRICREG_OK, 'get_state lift-off')
  call check_status(st%get_normal_forces(D), FRICREG_OK, 'get_normal_forces')
  call check_close(D(1), 2.0_c_double + 100.0_c_double * u(1), 1e-13_c_double, 'N = n0 + kn u')
  call check(D(1) > 0.0_c_double, 'closed')
  call check_status(st%set_jenkins_normal(Je, reshape([1.0_c_double, 1.0_c_double], [2, 1]), &
                                          [200.0_c_double], [0.3_c_double], [0.5_c_double], &
                                          [100.0_c_double]), FRICREG_ESIZE, 'Jn of 2 rows')
  call check(index(st%errmsg(), 'Jn') > 0, 'the message names Jn')
  ! the same stuck, closed run by an Iwan element of two sliders (150 + 50 N/m, set_iwan_normal)
  call check_status(st%set_iwan_normal(Je, Je, reshape([150.0_c_double, 50.0_c_double], [2, 1]), &
                                       reshape([1e20_c_double, 1e20_c_double], [2, 1]), &
                                       [2.0_c_double], [100.0_c_double]), FRICREG_OK, &
                    'set_iwan_normal')
  call check_status(st%set_initial([0.0_c_double], [0.0_c_double]), FRICREG_OK, 'set_initial')
  call check_status(st%run(0.01_c_double, 1.37_c_double), FRICREG_OK, 'run Iwan lift-off')
  call check_status(st%get_state(u=u2), FRICREG_OK, 'get_state Iwan lift-off')
  call check_close(u2(1), u(1), 1e-13_c_double, 'Iwan lift-off: the Jenkins run')
  call check_status(st%get_normal_forces(D), FRICREG_OK, 'get_normal_forces Iwan')
  call check_close(D(1), 2.0_c_double + 100.0_c_double * u2(1), 1e-13_c_double, &
                   'Iwan: N = n0 + kn u')
  call check_status(st%set_iwan_normal(Je, Je, reshape([150.0_c_double, 50.0_c_double], [2, 1]), &
                                       reshape([0.3_c_double], [1, 1]), [2.0_c_double], &
                                       [100.0_c_double]), FRICREG_ESIZE, 'mu (1, 1)')
  call check(index(st%errmsg(), 'mu, 1') > 0, 'the message names mu')

  ! ---- 2-D elements: two uncoupled masses as above, one stuck 2-D element on both ----------
  ! (set_jenkins_2d, get_jenkins_2d_state): each axis is the spring kt, the same closed form
  call check_status(st2%create(2, 1), FRICREG_OK, 'create 2, 1')
  call check_status(st2%set_mass(reshape([2.385_c_double, 0.0_c_double, 0.0_c_double, &
                                          2.385_c_double], [2, 2])), FRICREG_OK, 'set_mass 2')
  call check_status(st2%set_stiffness(reshape([217.3_c_double, 0.0_c_double, 0.0_c_double, &
                                               217.3_c_double], [2, 2])), FRICREG_OK, &
                    'set_stiffness 2')
  call check_status(st2%set_contacts(reshape([1.0_c_double, 0.0_c_double], [1, 2])), &
                    FRICREG_OK, 'set_contacts 2')
  call check_status(st2%set_bounds([0.0_c_double]), FRICREG_OK, 'set_bounds 2')
  call check_status(st2%set_load([-0.731_c_double * 2.385_c_double, &
                                  -0.731_c_double * 2.385_c_double]), FRICREG_OK, 'set_load 2')
  call check_status(st2%set_jenkins_2d(Je2, [200.0_c_double], [1e30_c_double]), FRICREG_OK, &
                    'set_jenkins_2d stuck')
  call check_status(st2%run(0.01_c_double, 1.37_c_double), FRICREG_OK, 'run 2-D stuck')
  call check_status(st2%get_state(u=uv), FRICREG_OK, 'get_state 2-D')
  call check_close(uv(1), -0.00113279590437900_c_double, 2e-15_c_double, '2-D: u_x closed form')
  call check_close(uv(2), -0.00113279590437900_c_double, 2e-15_c_double, '2-D: u_y closed form')
  call check_status(st2%get_jenkins_2d_state(f=f2, w=w2d, D=D), FRICREG_OK, &
                    'get_jenkins_2d_state')
  call check_close(f2(1, 1), 200.0_c_double * uv(1), 1e-15_c_double, '2-D: f_x = kt u_x')
  call check_close(f2(2, 1), 200.0_c_double * uv(2), 1e-15_c_double, '2-D: f_y = kt u_y')
  call check(all(w2d == 0.0_c_double) .and. D(1) == 0.0_c_double, '2-D: the slider did not move')
  call check_status(st2%set_jenkins_2d(Je2(1:1, :), [200.0_c_double], [0.05_c_double]), &
                    FRICREG_ESIZE, 'Je2 of 1 row')
  call check(index(st2%errmsg(), 'Je, 1') > 0, 'the message names Je')
  call check_status(st2%get_jenkins_2d_state(f=f2, D=D2), FRICREG_ESIZE, &
                    'f and D differ in elements')
  call check_status(st2%get_jenkins_state(f=f), FRICREG_EINVAL, &
                    'the 1-D getter refuses 2-D f')
  call check_status(st%get_jenkins_2d_state(D=D), FRICREG_EINVAL, &
                    'the 2-D getter refuses 1-D elements')
  call st2%destroy()

  ! ---- 3-D contact: three uncoupled masses, one stuck and closed element (x, y, n) ---------
  call check_status(st3%create(3, 1), FRICREG_OK, 'create 3, 1')
  call check_status(st3%set_mass(2.385_c_double * eye3()), FRICREG_OK, 'set_mass 3')
  call check_status(st3%set_stiffness(217.3_c_double * eye3()), FRICREG_OK, 'set_stiffness 3')
  call check_status(st3%set_contacts(reshape([1.0_c_double, 0.0_c_double, 0.0_c_double], &
                                             [1, 3])), FRICREG_OK, 'set_contacts 3')
  call check_status(st3%set_bounds([0.0_c_double]), FRICREG_OK, 'set_bounds 3')
  call check_status(st3%set_load([-0.731_c_double * 2.385_c_double, &
                                  -0.731_c_double * 2.385_c_double, &
                                  -0.731_c_double * 2.385_c_double + 5.0_c_double]), &
                    FRICREG_OK, 'set_load 3')
  call check_status(st3%set_jenkins_2d_normal(Jt3, Jn3, [200.0_c_double], [1e20_c_double], &
                                              [5.0_c_double], [200.0_c_double]), FRICREG_OK, &
                    'set_jenkins_2d_normal stuck')
  call check_status(st3%run(0.01_c_double, 1.37_c_double), FRICREG_OK, 'run 3-D stuck')
  call check_status(st3%get_state(u=u3), FRICREG_OK, 'get_state 3-D')
  call check_close(u3(1), -0.00113279590437900_c_double, 2e-15_c_double, '3-D: u_x closed form')
  call check_close(u3(2), -0.00113279590437900_c_double, 2e-15_c_double, '3-D: u_y closed form')
  call check_close(u3(3), -0.00113279590437900_c_double, 2e-14_c_double, '3-D: u_z closed form')
  call check_status(st3%get_jenkins_2d_state(f=f3), FRICREG_OK, 'get_jenkins_2d_state 3-D')
  call check_close(f3(1, 1), 200.0_c_double * u3(1), 1e-15_c_double, '3-D: f_x = kt u_x')
  call check_status(st3%get_normal_forces(N3), FRICREG_OK, 'get_normal_forces 3-D')
  call check_close(N3(1), 5.0_c_double + 200.0_c_double * u3(3), 1e-14_c_double, &
                   '3-D: N = n0 + kn u_z')
  call check_status(st3%set_jenkins_2d_normal(Jn3, Jn3, [200.0_c_double], [0.3_c_double], &
                                              [5.0_c_double], [200.0_c_double]), FRICREG_ESIZE, &
                    'Je of 1 row')
  call check(index(st3%errmsg(), 'Je, 1') > 0, 'the message names Je')
  call check_status(st3%set_jenkins_2d_normal(Jt3, Jn3, [200.0_c_double], [0.3_c_double], &
                                              [5.0_c_double], [0.0_c_double]), FRICREG_EINVAL, &
                    'kn = 0')
  call st3%destroy()
  call finish('test_structure_jenkins')

contains

  pure function eye3() result(a)
    real(c_double) :: a(3, 3)
    integer :: i
    a = 0.0_c_double
    do i = 1, 3
      a(i, i) = 1.0_c_double
    end do
  end function eye3
end program test_structure_jenkins
