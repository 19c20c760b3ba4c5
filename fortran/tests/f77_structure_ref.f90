! SPDX-License-Identifier: GPL-3.0-or-later
! f77_structure_ref.f90 — the reference of test_f77_structure.f: the same shear building
! stepped through the C API itself (bind(C) interfaces of fricreg_sim_c), given as dense
! row-major matrices built here from the storey data, independently of the F77 program's CSC
! arrays. Called from fixed-form code without an interface, so every argument has an explicit
! kind (INTEGER*8, DOUBLE PRECISION) and the ILP64 build of the test calls it unchanged.
!
! Storey i (1..ndof) has mass xm(i), a spring xk(i) and a dashpot xc(i) to storey i - 1 (the
! ground for i = 1); contact i (1..m = ndof - 1) slides between storeys i and i + 1,
! zdot_i = u'_(i+1) - u'_i. par: eps, dt_rec of the ground record ag(nag) (from t = 0), HHT
! alpha, Rayleigh a0 and a1, dt_rec of the load's record, Newton's tolerance, the load's
! record g(3) (from t = 0). The variants:
!   1  Newmark (1/4, 1/2), law (4), C from the dashpots, ground record, v0
!   2  HHT-alpha, law (4), Rayleigh C, ground record and a load p(ndof) g(t), Newton's tol
!   3  central difference, tanh law, no damping, ground record, v0
! Each runs to tend (fricreg_structure_run) and then nextra steps of dt
! (fricreg_structure_step), and returns the state, forces, dissipation, the eight
! FRICREG_SVALUE_* values and the five FRICREG_SSTAT_* counters; ist is the first failing
! status (0 if none).
subroutine stref(ivar, ndof, m, xm, xk, xc, xmun, p, par, nag, ag, v0, dt, tend, nextra, &
                 u, v, a, f, d, e, ns, ist)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: ivar, ndof, m, nag, nextra
  real(c_double), intent(in) :: xm(ndof), xk(ndof), xc(ndof), xmun(m), p(ndof), par(10), &
                                ag(nag), v0(ndof), dt, tend
  real(c_double), intent(out) :: u(ndof), v(ndof), a(ndof), f(m), d(m), e(8)
  integer(c_int64_t), intent(out) :: ns(5), ist
  real(c_double) :: mm(ndof * ndof), kk(ndof * ndof), cc(ndof * ndof), jj(m * ndof)
  real(c_double) :: r(ndof), u0(ndof)
  type(c_ptr) :: s
  integer(c_size_t) :: n, nc
  integer :: i, k, st
  integer(c_int) :: w

  n = int(ndof, c_size_t)
  nc = int(m, c_size_t)
  ! Row-major: entry (i, k) of an ndof x ndof matrix at (i - 1) * ndof + k.
  mm = 0
  kk = 0
  cc = 0
  do i = 1, int(ndof)
    mm((i - 1) * ndof + i) = xm(i)
    call storey(kk, xk, i)
    call storey(cc, xc, i)
  end do
  jj = 0
  do i = 1, int(m)
    jj((i - 1) * ndof + i) = -1
    jj((i - 1) * ndof + i + 1) = 1
  end do
  r = 1
  u0 = 0

  s = c_null_ptr
  ist = fricreg_structure_create(n, nc, s)
  if (ist /= 0) return
  st = 0
  call chk(fricreg_structure_set_mass(s, n, mm))
  call chk(fricreg_structure_set_stiffness(s, n, kk))
  call chk(fricreg_structure_set_contacts(s, nc, n, jj))
  call chk(fricreg_structure_set_bounds(s, nc, xmun))
  call chk(fricreg_structure_set_influence(s, n, r))
  call chk(fricreg_structure_set_ground_accel(s, 0.0_c_double, par(2), int(nag, c_size_t), ag))
  select case (ivar)
  case (1)
    call chk(fricreg_structure_set_damping(s, n, cc))
    call chk(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, par(1)))
    call chk(fricreg_structure_set_newmark(s, 0.25_c_double, 0.5_c_double))
    call chk(fricreg_structure_set_initial(s, n, u0, v0))
  case (2)
    call chk(fricreg_structure_set_rayleigh(s, par(4), par(5)))
    call chk(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, par(1)))
    call chk(fricreg_structure_set_load(s, n, p, 0.0_c_double, par(6), 3_c_size_t, par(8:10)))
    call chk(fricreg_structure_set_hht(s, par(3)))
    call chk(fricreg_structure_set_newton(s, par(7), 60_c_int))
  case (3)
    call chk(fricreg_structure_set_law(s, FRICREG_LAW_TANH, par(1)))
    call chk(fricreg_structure_set_central_difference(s))
    call chk(fricreg_structure_set_initial(s, n, u0, v0))
  end select
  call chk(fricreg_structure_run(s, dt, tend))
  do k = 1, int(nextra)
    call chk(fricreg_structure_step(s, dt))
  end do
  call chk(fricreg_structure_get_state(s, n, u, v, a))
  call chk(fricreg_structure_get_forces(s, nc, f))
  call chk(fricreg_structure_get_dissipation(s, nc, d))
  do w = 0, 7
    call chk(fricreg_structure_get_value(s, w, e(w + 1)))
  end do
  do w = 0, 4
    call chk(fricreg_structure_get_stat(s, w, ns(w + 1)))
  end do
  call fricreg_structure_free(s)
  ist = st

contains

  !> Add storey i's element of stiffness (or damping) x(i), between storeys i - 1 and i, to the
  !> row-major matrix b.
  subroutine storey(b, x, i)
    real(c_double), intent(inout) :: b(:)
    real(c_double), intent(in) :: x(:)
    integer, intent(in) :: i
    b((i - 1) * ndof + i) = b((i - 1) * ndof + i) + x(i)
    if (i > 1) then
      b((i - 2) * ndof + i - 1) = b((i - 2) * ndof + i - 1) + x(i)
      b((i - 2) * ndof + i) = b((i - 2) * ndof + i) - x(i)
      b((i - 1) * ndof + i - 1) = b((i - 1) * ndof + i - 1) - x(i)
    end if
  end subroutine storey

  !> Keep the first failure.
  subroutine chk(status)
    integer(c_int), intent(in) :: status
    if (st == 0) st = status
  end subroutine chk

end subroutine stref
