! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_f77.f90 — module-free entry points for Fortran 77 callers: laws (1-D, 2-D, Stribeck)
! and contexts.
!
! Plain external subroutines (no module, no interface needed), every argument by reference,
! names of at most six characters, and an INTEGER status STAT last (FRICREG_OK = 0 or a
! FRICREG_E* code; INCLUDE 'fricreg.fi' for the names). Written in free form here but callable
! from fixed-form code compiled with -std=legacy: the compiler mangles these names as it does
! its own (frctxc_ for gfortran). Argument types:
!   INTEGER            M, LAW, WHICH, CODE, STAT (default integer kind: 4 bytes, or 8 in
!                      libfricreg_fortran_ilp64, which compiles this file with
!                      -fdefault-integer-8; FRCHK tells a caller which it needs)
!   INTEGER*8          H, a handle holding the C pointer (0: none)
!   DOUBLE PRECISION   every real scalar and array
!   CHARACTER*(*)      MSG, TEXT: blank-padded, truncated to the caller's length
! Arrays are passed with their length M and checked against the context by the C library
! (FRICREG_ESIZE). On failure no argument is changed. See fortran/README.md for the table.
!
! Generated, not here: the entry points that are one C call (FRLAWE, FRLAW, FRBND, FRSTRC, FRCPLG,
! FRCPLD, FRCPLR, FRCPLC, FREVAL, FRSTAT, FRPART, FRSTIF, FRTAPP, FRSWIT, FRDLAW, FRDBND, FRDSTR,
! FRDCPB, FRDCPD, FRDCSR, FRDCSC, FRDEVL) are a line each, with their doc comments, in the table
! fricreg_f77.txt, which fortran/gen_f77.cmake turns into fricreg_f77_generated.f90 at build time;
! those below have logic of their own.

!> FRVERS(NUM, TEXT, STAT): the library's version number and string.
subroutine frvers(num, text, stat)
  use fricreg_c
  implicit none
  integer, intent(out) :: num, stat
  character(len=*), intent(out) :: text
  num = int(fricreg_version_number())
  text = fricreg_c_string(fricreg_version())
  stat = FRICREG_OK
end subroutine frvers

!> FRSTRE(CODE, MSG, STAT): fixed English text of status code CODE.
subroutine frstre(code, msg, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: code
  character(len=*), intent(out) :: msg
  integer, intent(out) :: stat
  msg = fricreg_c_string(fricreg_strerror(int(code, c_int)))
  stat = FRICREG_OK
end subroutine frstre

!> FRWARN(CODE, NAME, STAT): short fixed name of warning code CODE (FRICREG_WARN_*: 'eps_large',
!> ...; 'unknown' if unknown), blank-padded or truncated (fricreg_warning_name).
subroutine frwarn(code, name, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: code
  character(len=*), intent(out) :: name
  integer, intent(out) :: stat
  name = fricreg_c_string(fricreg_warning_name(int(code, c_int)))
  stat = FRICREG_OK
end subroutine frwarn

!> FRLAWB(LAW, EPS, M, V, FEQ, MUN, F, STAT): one law over M contacts
!> (fricreg_law_eval_batch). FEQ(M) is always read and validated, even by the laws that do not
!> use it: pass zeros there.
subroutine frlawb(law, eps, m, v, feq, mun, f, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: law, m
  double precision, intent(in) :: eps, v(*), feq(*), mun(*)
  double precision, intent(inout) :: f(*)
  integer, intent(out) :: stat
  if (m < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_law_eval_batch(int(law, c_int), eps, int(m, c_size_t), v, feq, mun, f))
end subroutine frlawb

!> FRDISK(LAW, EPS, M, V, FEQ, MUN, F, STAT): one 2-D law (FRICREG_DISK_*) over M contacts
!> (fricreg_disk_eval_batch): V(2, M), FEQ(2, M) and F(2, M), column I contact I (C's
!> interleaved layout), MUN(M). FEQ is always read and validated, even by
!> FRICREG_DISK_COULOMB, which does not use it: pass zeros there.
subroutine frdisk(law, eps, m, v, feq, mun, f, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: law, m
  double precision, intent(in) :: eps, v(*), feq(*), mun(*)
  double precision, intent(inout) :: f(*)
  integer, intent(out) :: stat
  if (m < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_disk_eval_batch(int(law, c_int), eps, int(m, c_size_t), v, feq, mun, f))
end subroutine frdisk

!> FRSTRB(EPS, M, V, FEQ, FS, FK, VS, DELTA, F, STAT): the Stribeck law over M 1-D contacts
!> (fricreg_stribeck_eval_batch), every array of length M, each contact its own static bound
!> FS, kinetic force FK <= FS, Stribeck velocity VS > 0 and exponent DELTA > 0.
subroutine frstrb(eps, m, v, feq, fs, fk, vs, delta, f, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: m
  double precision, intent(in) :: eps, v(*), feq(*), fs(*), fk(*), vs(*), delta(*)
  double precision, intent(inout) :: f(*)
  integer, intent(out) :: stat
  if (m < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_stribeck_eval_batch(eps, int(m, c_size_t), v, feq, fs, fk, vs, delta, f))
end subroutine frstrb

!> FRSTRD(EPS, M, V, FEQ, FS, FK, VS, DELTA, F, STAT): the 2-D Stribeck law over M contacts
!> (fricreg_stribeck_disk_eval_batch): V(2, M), FEQ(2, M), F(2, M) as for FRDISK; FS, FK,
!> VS, DELTA of length M as for FRSTRB.
subroutine frstrd(eps, m, v, feq, fs, fk, vs, delta, f, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: m
  double precision, intent(in) :: eps, v(*), feq(*), fs(*), fk(*), vs(*), delta(*)
  double precision, intent(inout) :: f(*)
  integer, intent(out) :: stat
  if (m < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_stribeck_disk_eval_batch(eps, int(m, c_size_t), v, feq, fs, fk, vs, &
                                              delta, f))
end subroutine frstrd

!> FRCTXC(M, H, STAT): create a context of M contacts into handle H (fricreg_ctx_create).
subroutine frctxc(m, h, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: m
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  type(c_ptr) :: p
  if (m < 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  p = c_null_ptr
  stat = fricreg_f77_created(fricreg_ctx_create(int(m, c_size_t), p), p, h)
end subroutine frctxc

!> FRCTXF(H, STAT): release the context H and set H = 0; H = 0 does nothing.
subroutine frctxf(h, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  stat = fricreg_f77_release(h, fricreg_ctx_free)
end subroutine frctxf

!> FRRSTS(H, STAT): set the counters to zero.
subroutine frrsts(h, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: stat
  call fricreg_ctx_reset_stats(fricreg_handle_to_ptr(h))
  stat = int(FRICREG_OK)
end subroutine frrsts

!> FRERRM(H, CODE, MSG, STAT): status CODE and message MSG of the context's last failed call
!> (FRICREG_OK and blanks if none; 'NULL context' for H = 0).
subroutine frerrm(h, code, msg, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: code
  character(len=*), intent(out) :: msg
  integer, intent(out) :: stat
  integer(c_int) :: last
  stat = fricreg_f77_last_error(h, fricreg_ctx_errcode, fricreg_ctx_errmsg, last, msg)
  code = last
end subroutine frerrm

!> FRTANG(H, M, DFDZ, DFDA, STAT): the Jacobian of the last FREVAL's forces, column-major
!> DFDZ(I, J) = dF_I/dZDOT_J and DFDA(I, J) = dF_I/dAFREE_J, each (M, M) with leading
!> dimension M (fricreg_ctx_tangent, transposed from C's row order). Written only on success.
subroutine frtang(h, m, dfdz, dfda, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(inout) :: dfdz(*), dfda(*)
  integer, intent(out) :: stat
  integer(c_size_t) :: n
  n = int(max(m, 0), c_size_t)
  stat = int(fricreg_ctx_tangent(fricreg_handle_to_ptr(h), int(m, c_size_t), dfdz, dfda))
  if (stat /= FRICREG_OK) return
  call fricreg_transpose(dfdz, n)
  call fricreg_transpose(dfda, n)
end subroutine frtang

! ---- 2-D contexts (fricreg_disk_ctx.h): handles of their own, never mixed with FRCTXC's ------

!> FRDCC(M, H, STAT): create a context of M two-dimensional contacts into handle H
!> (fricreg_disk_ctx_create).
subroutine frdcc(m, h, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: m
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  type(c_ptr) :: p
  if (m < 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  p = c_null_ptr
  stat = fricreg_f77_created(fricreg_disk_ctx_create(int(m, c_size_t), p), p, h)
end subroutine frdcc

!> FRDCF(H, STAT): release the 2-D context H and set H = 0; H = 0 does nothing.
subroutine frdcf(h, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  stat = fricreg_f77_release(h, fricreg_disk_ctx_free)
end subroutine frdcf

!> FRDTNG(H, M, DFDZ, DFDA, STAT): the Jacobian of the last FRDEVL's forces, column-major
!> (2M, 2M) each, DFDZ(2I-1+A, 2J-1+B) = dF(1+A, I)/dZDOT(1+B, J), likewise DFDA
!> (fricreg_disk_ctx_tangent, transposed from C's row order). Written only on success.
subroutine frdtng(h, m, dfdz, dfda, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(inout) :: dfdz(*), dfda(*)
  integer, intent(out) :: stat
  integer(c_size_t) :: n
  n = 2 * int(max(m, 0), c_size_t)
  stat = int(fricreg_disk_ctx_tangent(fricreg_handle_to_ptr(h), int(m, c_size_t), dfdz, dfda))
  if (stat /= FRICREG_OK) return
  call fricreg_transpose(dfdz, n)
  call fricreg_transpose(dfda, n)
end subroutine frdtng

!> FRDERR(H, CODE, MSG, STAT): status CODE and message MSG of the 2-D context's last failed
!> call (FRICREG_OK and blanks if none; 'NULL context' for H = 0).
subroutine frderr(h, code, msg, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: code
  character(len=*), intent(out) :: msg
  integer, intent(out) :: stat
  integer(c_int) :: last
  stat = fricreg_f77_last_error(h, fricreg_disk_ctx_errcode, fricreg_disk_ctx_errmsg, last, msg)
  code = last
end subroutine frderr
