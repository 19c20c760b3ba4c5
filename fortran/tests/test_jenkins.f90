! SPDX-License-Identifier: GPL-3.0-or-later
! test_jenkins.f90 — Jenkins elements (fricreg_jenkins.h) from Fortran: the type
! fricreg_jenkins_elements of module fricreg, against hand-worked values.
!
! Values: kt = 2, mun = 0.75. 1-D: u = 0.25 sticks (f = 0.5, tangent 2); u = 1 slides
! (f = 0.75, tangent 0, slider 1 - 0.75/2 = 0.625 once committed). 2-D: u = (3, 4) from the
! slider at 0 slides: f_tr = (6, 8), |f_tr| = 10, f = 0.75 (0.6, 0.8) = (0.45, 0.6), tangent
! (mun/|u|)(I - n n^T) = 0.15 [[0.64, -0.48], [-0.48, 0.36]], slider (3, 4) - f/2 =
! (2.775, 3.7).
program test_jenkins
  use fricreg
  use ftest
  implicit none
  type(fricreg_jenkins_elements) :: j1, j2
  real(c_double), parameter :: tol = 1e-14_c_double
  real(c_double) :: u1(1, 2), f1(1, 2), t1(1, 1, 2), w1(1, 2)
  real(c_double) :: u2(2, 1), f2(2, 1), t2(2, 2, 1), w2(2, 1), bad(2, 2)

  call check_status(j1%create(1, 2), FRICREG_OK, 'create 1-D')
  call check(j1%size() == 2 .and. j1%dim() == 1, 'size and dim')
  call check_status(j1%set_params([2.0_c_double, 2.0_c_double], [0.75_c_double, 0.75_c_double]), &
                    FRICREG_OK, 'set_params')
  u1(1, :) = [0.25_c_double, 1.0_c_double]
  call check_status(j1%trial(u1, f1, t1), FRICREG_OK, 'trial 1-D')
  call check(f1(1, 1) == 0.5_c_double .and. t1(1, 1, 1) == 2.0_c_double, 'stick')
  call check(f1(1, 2) == 0.75_c_double .and. t1(1, 1, 2) == 0.0_c_double, 'slip')
  call check_status(j1%get_slider(w1), FRICREG_OK, 'get_slider before commit')
  call check(all(w1 == 0.0_c_double), 'trial keeps the committed sliders')
  call check_status(j1%commit(), FRICREG_OK, 'commit')
  call check_status(j1%get_slider(w1), FRICREG_OK, 'get_slider')
  call check_close(w1(1, 2), 0.625_c_double, tol, 'committed slider')
  call check_status(j1%reset(), FRICREG_OK, 'reset')
  call check_status(j1%get_slider(w1), FRICREG_OK, 'get_slider after reset')
  call check(all(w1 == 0.0_c_double), 'reset')

  call check_status(j2%create(2, 1), FRICREG_OK, 'create 2-D')
  call check_status(j2%set_params([2.0_c_double], [0.75_c_double]), FRICREG_OK, 'set_params 2-D')
  u2(:, 1) = [3.0_c_double, 4.0_c_double]
  call check_status(j2%trial(u2, f2, t2), FRICREG_OK, 'trial 2-D')
  call check_close(f2(1, 1), 0.45_c_double, tol, 'f x')
  call check_close(f2(2, 1), 0.6_c_double, tol, 'f y')
  call check_close(t2(1, 1, 1), 0.096_c_double, tol, 'tangent xx')
  call check_close(t2(1, 2, 1), -0.072_c_double, tol, 'tangent xy')
  call check_close(t2(2, 2, 1), 0.054_c_double, tol, 'tangent yy')
  call check_status(j2%commit(), FRICREG_OK, 'commit 2-D')
  call check_status(j2%get_slider(w2), FRICREG_OK, 'get_slider 2-D')
  call check_close(w2(1, 1), 2.775_c_double, tol, 'slider x')
  call check_close(w2(2, 1), 3.7_c_double, tol, 'slider y')

  ! errors: a wrong shape (Fortran's check), a bad parameter (C's), each with a message
  call check_status(j2%trial(bad, f2), FRICREG_ESIZE, 'trial, wrong shape')
  call check(len(j2%errmsg()) > 0, 'message of ESIZE')
  call check_status(j2%set_params([0.0_c_double], [0.75_c_double]), FRICREG_EINVAL, 'kt = 0')
  call check(index(j2%errmsg(), 'kt') > 0, 'message names kt')
  call check_status(j2%set_params([2.0_c_double], [-1.0_c_double]), FRICREG_EINVAL, 'mun < 0')
  call check_status(j1%create(3, 1), FRICREG_EINVAL, 'dim 3')
  call check(j1%size() == 2, 'a failed create keeps the old elements')

  call j1%destroy()
  call j1%destroy()
  call j2%destroy()
  call check_status(j2%commit(), FRICREG_ENULL, 'commit after destroy')
  call finish('test_jenkins')
end program test_jenkins
