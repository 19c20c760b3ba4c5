! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_warnings_f77.f90 — module-free entry points for Fortran 77 callers: the warnings of a
! simulation (FRSIM*, fricreg_sim.h) and of a structure (FRST*, fricreg_structure.h), read back
! or routed to a handler of the caller's (fricreg_warning_handler of fricreg.h, the convention
! of SUNDIALS' error handler functions). Conventions as in fricreg_f77.f90: external
! subroutines, arguments by reference, INTEGER*8 handle H, INTEGER STAT last, nothing changed
! on failure; warning K counts from 1. Built only with the drivers (FRICREG_DRIVERS).
!
! A handler is the caller's EXTERNAL SUBROUTINE HANDLR(ICODE, MSG), INTEGER ICODE (a
! FRICREG_WARN_* code), CHARACTER*(*) MSG (the message, LEN(MSG) its length). C calls the
! bind(C) relay below, and the relay calls HANDLR, whose address C keeps as the handler's
! user_data: no storage is allocated, so nothing is left to free when the handler is replaced
! or removed or the object released, and there is no state beside the object's (one object per
! thread needs no lock). The address goes through a void* (transfer of a c_funptr to a c_ptr),
! which assumes that a function and a data pointer have one representation, as POSIX requires
! of dlsym's result; c_funloc of a procedure that is not interoperable, and c_f_procpointer
! back to one, are Fortran 2018 (18.2.3.5, 18.2.3.4).

!> The C warning handler of FRSIMH and FRSTWH: calls the caller's HANDLR, whose address user
!> holds, with ICODE = code as a default INTEGER of this build (8 bytes in
!> libfricreg_fortran_ilp64, which compiles this file with -fdefault-integer-8) and MSG a copy
!> of message, exactly its length. Not for callers: the entry points install it.
subroutine fricreg_f77_warning_relay(code, message, user) bind(C, name='fricreg_f77_warning_relay')
  use fricreg_c
  use, intrinsic :: iso_c_binding, only: c_null_funptr, c_f_procpointer
  implicit none
  integer(c_int), value :: code
  type(c_ptr), value :: message, user
  interface
    subroutine handlr(icode, msg)
      integer :: icode
      character(len=*) :: msg
    end subroutine handlr
  end interface
  procedure(handlr), pointer :: caller
  integer :: icode
  character(len=:), allocatable :: msg
  call c_f_procpointer(transfer(user, c_null_funptr), caller)
  ! Copies: an F77 handler may write to its arguments; C's message stays untouched.
  icode = code
  msg = fricreg_c_string(message)
  call caller(icode, msg)
end subroutine fricreg_f77_warning_relay

!> FRSIMW(H, N, STAT): judge the simulation's checks now and give the number N of warnings
!> they raise (fricreg_sim_warning_count; a handler hears the new ones). FRICREG_ENULL for
!> H = 0, N unchanged.
subroutine frsimw(h, n, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(inout) :: n
  integer, intent(out) :: stat
  type(c_ptr) :: p
  p = fricreg_handle_to_ptr(h)
  if (.not. c_associated(p)) then
    stat = int(FRICREG_ENULL)
    return
  end if
  n = int(fricreg_sim_warning_count(p))
  stat = int(FRICREG_OK)
end subroutine frsimw

!> FRSIMG(H, K, ICODE, MSG, STAT): warning K, 1 <= K <= N of the last FRSIMW (one-based), its
!> code ICODE (FRICREG_WARN_*; FRWARN names it) and its message MSG, blank-padded or truncated
!> (fricreg_sim_get_warning, _warning_message). FRICREG_ENULL for H = 0; FRICREG_EINVAL for
!> K out of range; ICODE and MSG unchanged on failure.
subroutine frsimg(h, k, icode, msg, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: k
  integer, intent(inout) :: icode
  character(len=*), intent(inout) :: msg
  integer, intent(out) :: stat
  type(c_ptr) :: p
  integer(c_int) :: code
  p = fricreg_handle_to_ptr(h)
  if (.not. c_associated(p)) then
    stat = int(FRICREG_ENULL)
    return
  end if
  if (k < 1) then ! k - 1 must not reach size_t as a huge index
    stat = int(FRICREG_EINVAL)
    return
  end if
  code = FRICREG_WARN_NONE
  stat = int(fricreg_sim_get_warning(p, int(k - 1, c_size_t), code, len=0_c_size_t))
  if (stat /= FRICREG_OK) return
  icode = code
  msg = fricreg_c_string(fricreg_sim_warning_message(p, int(k - 1, c_size_t)))
end subroutine frsimg

!> FRSIMH(H, HANDLR, STAT): route the simulation's warnings to the caller's EXTERNAL
!> SUBROUTINE HANDLR(ICODE, MSG): at the end of every run (FRSIMR, FRSIMY) HANDLR is called
!> once for each warning raised since the run began, and FRSIMW calls it for new ones only
!> (fricreg_sim_set_warning_handler). HANDLR may call FRSIMW, FRSIMG and the getters, but must
!> not run, set or free the simulation. Replaces a handler installed before; FRSIMO removes
!> it. FRICREG_ENULL for H = 0; FRICREG_EINVAL from inside a handler or an observer.
subroutine frsimh(h, handlr, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  interface
    subroutine handlr(icode, msg)
      integer :: icode
      character(len=*) :: msg
    end subroutine handlr
  end interface
  integer, intent(out) :: stat
  procedure(fricreg_warning_handler), bind(C, name='fricreg_f77_warning_relay') :: relay
  stat = int(fricreg_sim_set_warning_handler(fricreg_handle_to_ptr(h), c_funloc(relay), &
                                             transfer(c_funloc(handlr), c_null_ptr)))
end subroutine frsimh

!> FRSIMO(H, STAT): remove the simulation's warning handler (none: nothing happens); its
!> warnings are then only read back with FRSIMW and FRSIMG. FRICREG_ENULL for H = 0;
!> FRICREG_EINVAL from inside a handler or an observer.
subroutine frsimo(h, stat)
  use fricreg_c
  use fricreg_sim_c
  use, intrinsic :: iso_c_binding, only: c_null_funptr
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: stat
  stat = int(fricreg_sim_set_warning_handler(fricreg_handle_to_ptr(h), c_null_funptr, &
                                             c_null_ptr))
end subroutine frsimo

!> FRSTWN(H, N, STAT): judge the structure's checks now and give the number N of warnings they
!> raise (fricreg_structure_warning_count; a handler hears the new ones; a loop of FRSTSP
!> steps calls it to have them judged). FRICREG_ENULL for H = 0, N unchanged.
subroutine frstwn(h, n, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(inout) :: n
  integer, intent(out) :: stat
  type(c_ptr) :: p
  p = fricreg_handle_to_ptr(h)
  if (.not. c_associated(p)) then
    stat = int(FRICREG_ENULL)
    return
  end if
  n = int(fricreg_structure_warning_count(p))
  stat = int(FRICREG_OK)
end subroutine frstwn

!> FRSTWG(H, K, ICODE, MSG, STAT): warning K, 1 <= K <= N of the last FRSTWN (one-based), its
!> code ICODE (FRICREG_WARN_*; FRWARN names it) and its message MSG (SI units), blank-padded or
!> truncated (fricreg_structure_get_warning, _warning_message). FRICREG_ENULL for H = 0;
!> FRICREG_EINVAL for K out of range; ICODE and MSG unchanged on failure.
subroutine frstwg(h, k, icode, msg, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: k
  integer, intent(inout) :: icode
  character(len=*), intent(inout) :: msg
  integer, intent(out) :: stat
  type(c_ptr) :: p
  integer(c_int) :: code
  p = fricreg_handle_to_ptr(h)
  if (.not. c_associated(p)) then
    stat = int(FRICREG_ENULL)
    return
  end if
  if (k < 1) then ! k - 1 must not reach size_t as a huge index
    stat = int(FRICREG_EINVAL)
    return
  end if
  code = FRICREG_WARN_NONE
  stat = int(fricreg_structure_get_warning(p, int(k - 1, c_size_t), code, len=0_c_size_t))
  if (stat /= FRICREG_OK) return
  icode = code
  msg = fricreg_c_string(fricreg_structure_warning_message(p, int(k - 1, c_size_t)))
end subroutine frstwg

!> FRSTWH(H, HANDLR, STAT): route the structure's warnings to the caller's EXTERNAL
!> SUBROUTINE HANDLR(ICODE, MSG): at the end of every FRSTTE and FRSTOD HANDLR is called once
!> for each warning not given to it since the last FRSTU0 (or since it was installed), and
!> FRSTWN calls it for new ones; FRSTSP judges nothing
!> (fricreg_structure_set_warning_handler). HANDLR may call FRSTWN, FRSTWG and the getters,
!> but must not step, set or free the structure. Replaces a handler installed before; FRSTWO
!> removes it. FRICREG_ENULL for H = 0; FRICREG_EINVAL from inside a handler or an observer.
subroutine frstwh(h, handlr, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  interface
    subroutine handlr(icode, msg)
      integer :: icode
      character(len=*) :: msg
    end subroutine handlr
  end interface
  integer, intent(out) :: stat
  procedure(fricreg_warning_handler), bind(C, name='fricreg_f77_warning_relay') :: relay
  stat = int(fricreg_structure_set_warning_handler(fricreg_handle_to_ptr(h), c_funloc(relay), &
                                                   transfer(c_funloc(handlr), c_null_ptr)))
end subroutine frstwh

!> FRSTWO(H, STAT): remove the structure's warning handler (none: nothing happens); its
!> warnings are then only read back with FRSTWN and FRSTWG. FRICREG_ENULL for H = 0;
!> FRICREG_EINVAL from inside a handler or an observer.
subroutine frstwo(h, stat)
  use fricreg_c
  use fricreg_sim_c
  use, intrinsic :: iso_c_binding, only: c_null_funptr
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: stat
  stat = int(fricreg_structure_set_warning_handler(fricreg_handle_to_ptr(h), c_null_funptr, &
                                                   c_null_ptr))
end subroutine frstwo
