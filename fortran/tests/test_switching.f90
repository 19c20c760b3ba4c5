! SPDX-License-Identifier: GPL-3.0-or-later
! test_switching.f90 — the switching functions through both Fortran layers: ctx%switching,
! ctx%switching_count, FRSWIT.
!
! Closed forms on the two blocks W = [[1, -1], [-1, 2]], law (4), mun = (0.5, 0.4),
! eps = 0.02, zdot = 0, a_free = (0.1, 0.1) (test_sparse_ctx.f90): both hold, f = (-0.3, -0.2),
! and f_eq,1 = -(a_1 + W_12 f_2)/W_11 = -0.3. So xi_1 = (eps/2)(-0.3/0.5) = -0.006: the zone's
! edges are at g(4, 1) = 0 - xi - eps/2 = -0.004 and g(5, 1) = 0.016; the saturation's
! g(6, 1) = min(-0.3 - 0.5, 0.5 min(0.4, 1.6)) = -0.8 and g(7, 1) = max(0.2, -0.2) = 0.2
! (a = (h - d)/h = 0.4, b = 1.6 with d = v - xi = 0.006, h = 0.01). The consistent law has no
! band or rest kink: g(1:3, :) = 1.
program test_switching
  use fricreg
  use ftest
  implicit none
  real(c_double), parameter :: tol = 1e-12_c_double
  real(c_double), parameter :: mun(2) = [0.5_c_double, 0.4_c_double], eps = 0.02_c_double
  real(c_double), parameter :: a_free(2) = [0.1_c_double, 0.1_c_double]
  real(c_double), parameter :: W(2, 2) = reshape([1.0_c_double, -1.0_c_double, -1.0_c_double, &
                                                  2.0_c_double], [2, 2])
  type(fricreg_context) :: ctx
  real(c_double) :: f(2), zdot(2), g(FRICREG_SWITCH_PER_CONTACT, 2)
  real(c_double) :: g77(2 * FRICREG_SWITCH_PER_CONTACT)
  integer(c_int64_t) :: h
  integer :: stat

  zdot = 0.0_c_double
  call check_status(ctx%create(2), FRICREG_OK, 'create(2)')
  call check(ctx%switching_count() == 2 * FRICREG_SWITCH_PER_CONTACT, 'switching_count')
  call check_status(ctx%set_law(FRICREG_LAW_QUINN, eps), FRICREG_OK, 'set_law')
  call check_status(ctx%set_coupling_dense(W), FRICREG_OK, 'set_coupling_dense')
  call check_status(ctx%set_bounds(mun), FRICREG_OK, 'set_bounds')
  call check_status(ctx%eval(zdot, a_free, f), FRICREG_OK, 'eval')
  call check_status(ctx%switching(zdot, a_free, g, f), FRICREG_OK, 'switching')
  call check_close(g(FRICREG_SWITCH_ZONE_HI + 1, 1), -0.004_c_double, tol, 'zone upper edge')
  call check_close(g(FRICREG_SWITCH_ZONE_LO + 1, 1), 0.016_c_double, tol, 'zone lower edge')
  call check_close(g(FRICREG_SWITCH_SAT_HI + 1, 1), -0.8_c_double, tol, 'saturation +')
  call check_close(g(FRICREG_SWITCH_SAT_LO + 1, 1), 0.2_c_double, tol, 'saturation -')
  call check(all(g(1:3, :) == 1.0_c_double), 'band and rest inert under the consistent law')
  ! a coupled W needs f; wrong shapes are refused, g kept
  g = -7.0_c_double
  call check_status(ctx%switching(zdot, a_free, g), FRICREG_ENULL, 'switching without f')
  call check_status(ctx%switching(zdot, a_free, g(:, 1:1), f), FRICREG_ESIZE, 'g of one column')
  call check(all(g == -7.0_c_double), 'g untouched on failure')
  ! F77 on a handle of the same C context
  h = fricreg_ptr_to_handle(ctx%handle())
  call frswit(h, 2, zdot, a_free, f, g77, 2 * FRICREG_SWITCH_PER_CONTACT, stat)
  call check(stat == FRICREG_OK .and. &
             abs(g77(FRICREG_SWITCH_ZONE_HI + 1) + 0.004_c_double) <= tol, 'FRSWIT')
  call frswit(h, 2, zdot, a_free, f, g77, 2 * FRICREG_SWITCH_PER_CONTACT - 1, stat)
  call check(stat == FRICREG_ESIZE, 'FRSWIT with NG too small')
  call ctx%destroy()
  call finish('test_switching')
end program test_switching
