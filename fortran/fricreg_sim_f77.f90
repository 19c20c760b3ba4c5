! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_sim_f77.f90 — module-free entry points for Fortran 77 callers: the ODE drivers of
! the reference systems (fricreg_sim.h). Conventions as in fricreg_f77.f90: external
! subroutines, arguments by reference, INTEGER*8 handle H, INTEGER STAT last, DOUBLE PRECISION
! reals, nothing changed on failure. Built only with the drivers (FRICREG_DRIVERS).

!> FRSIMC(SYSTEM, H, STAT): create a simulation of SYSTEM (FRICREG_SYSTEM_*) into H, with the
!> paper's parameters, law (4), RK4, dt = 0.01 and the paper's eps (fricreg_sim_create).
subroutine frsimc(system, h, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer, intent(in) :: system
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  type(c_ptr) :: p
  p = c_null_ptr
  stat = fricreg_f77_created(fricreg_sim_create(int(system, c_int), p), p, h)
end subroutine frsimc

!> FRSIMF(H, STAT): release the simulation H and set H = 0; H = 0 does nothing.
subroutine frsimf(h, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  stat = fricreg_f77_release(h, fricreg_sim_free)
end subroutine frsimf

!> FRSIMP(H, PARAM, VALUE, STAT): one system parameter (FRICREG_PARAM_*).
subroutine frsimp(h, param, value, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: param
  double precision, intent(in) :: value
  integer, intent(out) :: stat
  stat = int(fricreg_sim_set_param(fricreg_handle_to_ptr(h), int(param, c_int), value))
end subroutine frsimp

!> FRSIML(H, LAW, EPS, STAT): law and eps (0: the paper's rule).
subroutine frsiml(h, law, eps, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: law
  double precision, intent(in) :: eps
  integer, intent(out) :: stat
  stat = int(fricreg_sim_set_law(fricreg_handle_to_ptr(h), int(law, c_int), eps))
end subroutine frsiml

!> FRSIMI(H, INTEG, DT, RTOL, ATOL, STAT): integrator (FRICREG_INT_*) and step control
!> (RTOL = ATOL = 0: fixed step DT).
subroutine frsimi(h, integ, dt, rtol, atol, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: integ
  double precision, intent(in) :: dt, rtol, atol
  integer, intent(out) :: stat
  stat = int(fricreg_sim_set_integrator(fricreg_handle_to_ptr(h), int(integ, c_int), dt, &
                                        rtol, atol))
end subroutine frsimi

!> FRSIMR(H, TEND, STAT): integrate from t = 0 to TEND (fricreg_sim_run).
subroutine frsimr(h, tend, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  double precision, intent(in) :: tend
  integer, intent(out) :: stat
  stat = int(fricreg_sim_run(fricreg_handle_to_ptr(h), tend))
end subroutine frsimr

!> FRSIMY(H, NCYC, STAT): integrate NCYC whole forcing cycles (fricreg_sim_run_cycles).
subroutine frsimy(h, ncyc, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: ncyc
  integer, intent(out) :: stat
  stat = int(fricreg_sim_run_cycles(fricreg_handle_to_ptr(h), int(ncyc, c_int)))
end subroutine frsimy

!> FRSIMN(H, NDOF, M, STAT): number of bodies NDOF and of contacts M.
subroutine frsimn(h, ndof, m, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: ndof, m, stat
  type(c_ptr) :: p
  p = fricreg_handle_to_ptr(h)
  if (.not. c_associated(p)) then
    stat = int(FRICREG_ENULL)
    return
  end if
  ndof = int(fricreg_sim_ndof(p))
  m = int(fricreg_sim_ncontacts(p))
  stat = int(FRICREG_OK)
end subroutine frsimn

!> FRSIMV(H, WHICH, VALUE, STAT): one quantity (FRICREG_VALUE_*) into VALUE.
subroutine frsimv(h, which, value, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: which
  double precision, intent(inout) :: value
  integer, intent(out) :: stat
  stat = int(fricreg_sim_get_value(fricreg_handle_to_ptr(h), int(which, c_int), value))
end subroutine frsimv

!> FRSIMX(H, NDOF, X, V, STAT): state X(NDOF), V(NDOF) at the end of the last run.
subroutine frsimx(h, ndof, x, v, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: ndof
  double precision, intent(inout) :: x(*), v(*)
  integer, intent(out) :: stat
  stat = int(fricreg_sim_get_state(fricreg_handle_to_ptr(h), int(ndof, c_size_t), x, v))
end subroutine frsimx

!> FRSIMD(H, NCYC, D, STAT): dissipation D(NCYC) of each whole cycle; NCYC must be the number
!> completed (FRSIMV with FRICREG_VALUE_CYCLES).
subroutine frsimd(h, ncyc, d, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: ncyc
  double precision, intent(inout) :: d(*)
  integer, intent(out) :: stat
  stat = int(fricreg_sim_get_dissipation(fricreg_handle_to_ptr(h), int(ncyc, c_size_t), d))
end subroutine frsimd

!> FRSIMS(H, M, FRAC, STAT): per contact, the stick fraction FRAC(M) of the last whole cycle.
subroutine frsims(h, m, frac, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(inout) :: frac(*)
  integer, intent(out) :: stat
  stat = int(fricreg_sim_get_stick_fraction(fricreg_handle_to_ptr(h), int(m, c_size_t), frac))
end subroutine frsims

!> FRSIME(H, CODE, MSG, STAT): status CODE and message MSG of the simulation's last failed call.
subroutine frsime(h, code, msg, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: code
  character(len=*), intent(out) :: msg
  integer, intent(out) :: stat
  integer(c_int) :: last
  stat = fricreg_f77_last_error(h, fricreg_sim_errcode, fricreg_sim_errmsg, last, msg)
  code = last
end subroutine frsime
