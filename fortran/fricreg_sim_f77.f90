! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_sim_f77.f90 — module-free entry points for Fortran 77 callers: the ODE drivers of
! the reference systems (fricreg_sim.h). Conventions as in fricreg_f77.f90: external
! subroutines, arguments by reference, INTEGER*8 handle H, INTEGER STAT last, DOUBLE PRECISION
! reals, nothing changed on failure. Built only with the drivers (FRICREG_DRIVERS).
!
! Generated, not here: the entry points that are one C call (FRSIMP, FRSIML, FRSIMI, FRSIMR,
! FRSIMY, FRSIMV, FRSIMX, FRSIMD, FRSIMS, FRSIMT, FRSIMA) are a line each, with their doc comments, in
! the table fricreg_sim_f77.txt, which fortran/gen_f77.cmake turns into
! fricreg_sim_f77_generated.f90 at build time; those below have logic of their own (FRSIMK:
! C's ints copied into the caller's INTEGER).

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

!> FRSIMK(H, NCYC, KINDS, STAT): the kind KINDS(NCYC) of each whole cycle's error estimate of
!> the last run, FRICREG_EST_KIND_ASYMPTOTIC, _BOUND or _ASSUMED (C's
!> fricreg_sim_get_dissipation_error_kind; C's ints copied into the caller's INTEGER, of any
!> size); NCYC must be the number completed. FRICREG_EINVAL when the run made no estimate;
!> FRICREG_ESIZE for another NCYC; KINDS written only on success. Since 1.8.
subroutine frsimk(h, ncyc, kinds, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: ncyc
  integer, intent(inout) :: kinds(*)
  integer, intent(out) :: stat
  integer(c_int), allocatable :: tmp(:)
  integer :: astat
  allocate (tmp(max(ncyc, 1)), stat=astat)
  if (astat /= 0) then
    stat = int(FRICREG_ENOMEM)
    return
  end if
  ! a negative count reaches C as 0, a size it refuses, not as a huge one
  stat = int(fricreg_sim_get_dissipation_error_kind(fricreg_handle_to_ptr(h), &
                                                    int(max(ncyc, 0), c_size_t), tmp))
  if (stat == FRICREG_OK .and. ncyc > 0) kinds(1:ncyc) = int(tmp(1:ncyc))
end subroutine frsimk
