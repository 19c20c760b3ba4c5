! SPDX-License-Identifier: GPL-3.0-or-later
! test_structure.f90 — the linear structure with friction (include/fricreg_structure.h) through
! the thin bind(C) layer, with C's numbers (tests/structure/test_structure.c): two storeys hold
! a static load, J^T f = -p, so f = (-(p1 + p2), -p2) = (-0.319, 0.412) with no motion; and the paper's
! unforced oscillator as a structure (M = K = J = 1) sticks at -0.75 within eps^2/2, and at
! the paper's -0.750090 through run_ode with RK4.
! J is m x ndof row-major in C: a Fortran caller with J(m, ndof) passes transpose(J).
program test_structure
  use fricreg_c
  use fricreg_sim_c
  use ftest
  implicit none
  type(c_ptr) :: s
  real(c_double) :: M(2, 2), K(2, 2), J(2, 2), mun(2), p(2), u(2), v(2), f(2), x(1), value
  real(c_double) :: one(1), zero(1), dt
  integer(c_int64_t) :: count
  character(kind=c_char) :: buf(64)

  M = reshape([1.7_c_double, 0.0_c_double, 0.0_c_double, 0.9_c_double], [2, 2])
  K = reshape([30.2_c_double, -12.1_c_double, -12.1_c_double, 12.1_c_double], [2, 2])
  ! J(i, k) = d zdot_i / d u'_k: ground slip of storey 1, inter-storey slip
  J = reshape([1.0_c_double, -1.0_c_double, 0.0_c_double, 1.0_c_double], [2, 2])
  mun = [0.5_c_double, 0.6_c_double]
  p = [0.731_c_double, -0.412_c_double]

  call check_status(fricreg_structure_create(2_c_size_t, 2_c_size_t, s), FRICREG_OK, 'create')
  call check_status(fricreg_structure_set_mass(s, 2_c_size_t, M), FRICREG_OK, 'set_mass')
  call check_status(fricreg_structure_set_stiffness(s, 2_c_size_t, K), FRICREG_OK, 'set_stiffness')
  call check_status(fricreg_structure_set_contacts(s, 2_c_size_t, 2_c_size_t, transpose(J)), &
                    FRICREG_OK, 'set_contacts(transpose(J))')
  call check_status(fricreg_structure_set_bounds(s, 2_c_size_t, mun), FRICREG_OK, 'set_bounds')
  call check_status(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 0.013_c_double), FRICREG_OK, &
                    'set_law')
  call check_status(fricreg_structure_set_load(s, 2_c_size_t, p, 0.0_c_double, 0.0_c_double, &
                    0_c_size_t), FRICREG_OK, 'constant load, g absent')
  call check_status(fricreg_structure_run(s, 0.01_c_double, 1.0_c_double), FRICREG_OK, 'run')
  call check_status(fricreg_structure_get_state(s, 2_c_size_t, u=u, v=v), FRICREG_OK, &
                    'get_state without a')
  call check(all(abs(u) <= 1e-15_c_double) .and. all(abs(v) <= 1e-15_c_double), 'no motion')
  call check_status(fricreg_structure_get_forces(s, 2_c_size_t, f), FRICREG_OK, 'get_forces')
  call check_close(f(1), -0.319_c_double, 1e-13_c_double, 'f1 = -(p1 + p2)')
  call check_close(f(2), 0.412_c_double, 1e-13_c_double, 'f2 = -p2')
  call check_status(fricreg_structure_get_stat(s, FRICREG_SSTAT_STEPS, count), FRICREG_OK, &
                    'get_stat')
  call check(count == 100, '100 steps')
  call check_status(fricreg_structure_set_hht(s, -0.5_c_double), FRICREG_EINVAL, 'alpha < -1/3')
  call check(fricreg_structure_errcode(s) == FRICREG_EINVAL, 'errcode kept')
  call check(fricreg_structure_errmsg_copy(s, buf, 64_c_size_t) > 0, 'a message')
  call fricreg_structure_free(s)

  ! The paper's unforced oscillator, Eq. (5): law (4), eps = 2 dt.
  dt = 1e-3_c_double
  one = 1.0_c_double
  zero = 0.0_c_double
  call check_status(fricreg_structure_create(1_c_size_t, 1_c_size_t, s), FRICREG_OK, 'create 1')
  call check_status(fricreg_structure_set_stiffness(s, 1_c_size_t, one), FRICREG_OK, 'K = 1')
  call check_status(fricreg_structure_set_contacts(s, 1_c_size_t, 1_c_size_t, one), FRICREG_OK, &
                    'J = 1')
  call check_status(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 2 * dt), FRICREG_OK, 'law')
  call check_status(fricreg_structure_set_initial(s, 1_c_size_t, [2.75_c_double], zero), &
                    FRICREG_OK, 'x0 = 2.75')
  call check_status(fricreg_structure_run(s, dt, 6.0_c_double), FRICREG_OK, 'run to t = 6')
  call check_status(fricreg_structure_get_state(s, 1_c_size_t, u=x), FRICREG_OK, 'get_state u')
  call check_close(x(1), -0.75_c_double, 0.5_c_double * (2 * dt)**2, 'rests at -0.75')
  call check_status(fricreg_structure_get_value(s, FRICREG_SVALUE_FRICTION, value), FRICREG_OK, &
                    'get_value')
  call check_close(value, 3.5_c_double, 0.5_c_double * (2 * dt)**2, 'D = mun * 3.5')

  ! The same through GSL's classical RK4 at the paper's dt = 0.01, eps = 0.02: -0.750090.
  call check_status(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 0.02_c_double), FRICREG_OK, &
                    'law, eps = 0.02')
  call check_status(fricreg_structure_set_initial(s, 1_c_size_t, [2.75_c_double], zero), &
                    FRICREG_OK, 'restart')
  call check_status(fricreg_structure_run_ode(s, FRICREG_INT_RK4, 0.01_c_double, 0.0_c_double, &
                    0.0_c_double, 20.0_c_double), FRICREG_OK, 'run_ode rk4')
  call check_status(fricreg_structure_get_state(s, 1_c_size_t, u=x), FRICREG_OK, 'get_state')
  call check_close(x(1), -0.750090_c_double, 5e-7_c_double, 'paper: -0.750090')
  call check_status(fricreg_structure_set_central_difference(s), FRICREG_OK, 'central')
  call check_status(fricreg_structure_step(s, 0.01_c_double), FRICREG_ESTEP, &
                    'central difference refuses dt 2 mun/eps = 1')
  call fricreg_structure_free(s)

  call finish('structure')
end program test_structure
