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

!> FRLAWE(LAW, V, FEQ, MUN, EPS, F, STAT): one law at one contact (fricreg_law_eval).
subroutine frlawe(law, v, feq, mun, eps, f, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: law
  double precision, intent(in) :: v, feq, mun, eps
  double precision, intent(inout) :: f
  integer, intent(out) :: stat
  stat = int(fricreg_law_eval(int(law, c_int), v, feq, mun, eps, f))
end subroutine frlawe

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

!> FRLAW(H, LAW, EPS, STAT): select the law and eps (fricreg_ctx_set_law).
subroutine frlaw(h, law, eps, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: law
  double precision, intent(in) :: eps
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_set_law(fricreg_handle_to_ptr(h), int(law, c_int), eps))
end subroutine frlaw

!> FRBND(H, M, MUN, STAT): friction bounds MUN(M) (fricreg_ctx_set_bounds).
subroutine frbnd(h, m, mun, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(in) :: mun(*)
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_set_bounds(fricreg_handle_to_ptr(h), int(m, c_size_t), mun))
end subroutine frbnd

!> FRSTRC(H, M, FS, FK, VS, DELTA, STAT): Stribeck friction in the context, each of FS, FK, VS,
!> DELTA of length M (fricreg_ctx_set_stribeck); M = 0 switches it off (the arrays are not
!> read: pass any).
subroutine frstrc(h, m, fs, fk, vs, delta, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(in) :: fs(*), fk(*), vs(*), delta(*)
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_set_stribeck(fricreg_handle_to_ptr(h), int(m, c_size_t), fs, fk, vs, &
                                      delta))
end subroutine frstrc

!> FRCPLG(H, M, W, STAT): diagonal coupling W(M) (fricreg_ctx_set_coupling_diagonal).
subroutine frcplg(h, m, w, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(in) :: w(*)
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_set_coupling_diagonal(fricreg_handle_to_ptr(h), int(m, c_size_t), w))
end subroutine frcplg

!> FRCPLD(H, M, W, STAT): dense symmetric coupling W(M, M), leading dimension M
!> (fricreg_ctx_set_coupling_dense; symmetric, so Fortran's column order is C's row order).
subroutine frcpld(h, m, w, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(in) :: w(*)
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_set_coupling_dense(fricreg_handle_to_ptr(h), int(m, c_size_t), w))
end subroutine frcpld

!> FRCPLR(H, M, FLAGS, ROWPTR, COLIND, VALUES, STAT): sparse symmetric coupling W in compressed
!> sparse rows, INTEGER*8 ROWPTR(M + 1) and COLIND(NNZ), VALUES(NNZ), NNZ = ROWPTR(M + 1) - base
!> (fricreg_ctx_set_coupling_csr; FLAGS: FRICREG_SPARSE_ONE_BASED, _UPPER, _LOWER).
subroutine frcplr(h, m, flags, rowptr, colind, values, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h, rowptr(*), colind(*)
  integer, intent(in) :: m, flags
  double precision, intent(in) :: values(*)
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_set_coupling_csr(fricreg_handle_to_ptr(h), int(m, c_size_t), &
                                          int(flags, c_int), rowptr, colind, values))
end subroutine frcplr

!> FRCPLC(H, M, FLAGS, COLPTR, ROWIND, VALUES, STAT): the same in compressed sparse columns,
!> what Fortran codes hold: one-based INTEGER*8 COLPTR(M + 1) and ROWIND(NNZ) with
!> FLAGS = FRICREG_SPARSE_ONE_BASED (fricreg_ctx_set_coupling_csc).
subroutine frcplc(h, m, flags, colptr, rowind, values, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h, colptr(*), rowind(*)
  integer, intent(in) :: m, flags
  double precision, intent(in) :: values(*)
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_set_coupling_csc(fricreg_handle_to_ptr(h), int(m, c_size_t), &
                                          int(flags, c_int), colptr, rowind, values))
end subroutine frcplc

!> FREVAL(H, M, ZDOT, AFREE, F, FEQ, STAT): friction forces F(M) and FEQ(M) (NaN outside the
!> near-stick set) from velocities ZDOT(M) and free accelerations AFREE(M) (fricreg_ctx_eval).
subroutine freval(h, m, zdot, afree, f, feq, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(in) :: zdot(*), afree(*)
  double precision, intent(inout) :: f(*), feq(*)
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_eval(fricreg_handle_to_ptr(h), int(m, c_size_t), zdot, afree, f, feq))
end subroutine freval

!> FRSTAT(H, WHICH, VALUE, STAT): counter WHICH (FRICREG_STAT_*) into INTEGER*8 VALUE.
subroutine frstat(h, which, value, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: which
  integer(c_int64_t), intent(inout) :: value
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_get_stat(fricreg_handle_to_ptr(h), int(which, c_int), value))
end subroutine frstat

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

!> FRPART(H, PART, STAT): the partition of coupled contacts, FRICREG_PARTITION_CONSISTENT or
!> FRICREG_PARTITION_PAPER (fricreg_ctx_set_partition).
subroutine frpart(h, part, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: part
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_set_partition(fricreg_handle_to_ptr(h), int(part, c_int)))
end subroutine frpart

!> FRSTIF(H, LAMBDA, STAT): the stick zone's stiffness LAMBDA (1/time) that bounds a fixed
!> explicit step: DT*LAMBDA within the stepper's real-axis bound (fricreg_ctx_stick_stiffness).
subroutine frstif(h, lambda, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  double precision, intent(inout) :: lambda
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_stick_stiffness(fricreg_handle_to_ptr(h), lambda))
end subroutine frstif

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

!> FRTAPP(H, M, DZ, DA, DF, STAT): the last FREVAL's tangent times a direction,
!> DF(M) = (dF/dZDOT) DZ(M) + (dF/dAFREE) DA(M), without the (M, M) tangent
!> (fricreg_ctx_tangent_apply; pass zeros for a direction not wanted). Written only on success.
subroutine frtapp(h, m, dz, da, df, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(in) :: dz(*), da(*)
  double precision, intent(inout) :: df(*)
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_tangent_apply(fricreg_handle_to_ptr(h), int(m, c_size_t), dz, da, df))
end subroutine frtapp

!> FRSWIT(H, M, ZDOT, AFREE, F, G, NG, STAT): the switching functions G(NG) of velocities
!> ZDOT(M), free accelerations AFREE(M) and the forces F(M) FREVAL gave there (read with a
!> coupled W): G(FRICREG_SWITCH_PER_CONTACT*(I-1) + K + 1) is component K of contact I, a
!> signed distance to a kink of its law, +1 where it has none; NG >=
!> FRICREG_SWITCH_PER_CONTACT*M (fricreg_ctx_switching). Written only on success.
subroutine frswit(h, m, zdot, afree, f, g, ng, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m, ng
  double precision, intent(in) :: zdot(*), afree(*), f(*)
  double precision, intent(inout) :: g(*)
  integer, intent(out) :: stat
  stat = int(fricreg_ctx_switching(fricreg_handle_to_ptr(h), int(m, c_size_t), zdot, afree, f, &
                                   g, int(max(ng, 0), c_size_t)))
end subroutine frswit

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

!> FRDLAW(H, LAW, EPS, STAT): the 2-D law (FRICREG_DISK_QUINN or FRICREG_DISK_FORCE_BALANCE)
!> and eps (fricreg_disk_ctx_set_law).
subroutine frdlaw(h, law, eps, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: law
  double precision, intent(in) :: eps
  integer, intent(out) :: stat
  stat = int(fricreg_disk_ctx_set_law(fricreg_handle_to_ptr(h), int(law, c_int), eps))
end subroutine frdlaw

!> FRDBND(H, M, MUN, STAT): friction bounds MUN(M) (fricreg_disk_ctx_set_bounds).
subroutine frdbnd(h, m, mun, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(in) :: mun(*)
  integer, intent(out) :: stat
  stat = int(fricreg_disk_ctx_set_bounds(fricreg_handle_to_ptr(h), int(m, c_size_t), mun))
end subroutine frdbnd

!> FRDSTR(H, M, FS, FK, VS, DELTA, STAT): Stribeck friction in the 2-D context H, each of FS,
!> FK, VS, DELTA of length M (fricreg_disk_ctx_set_stribeck); M = 0 switches it off (the arrays
!> are not read: pass any).
subroutine frdstr(h, m, fs, fk, vs, delta, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(in) :: fs(*), fk(*), vs(*), delta(*)
  integer, intent(out) :: stat
  stat = int(fricreg_disk_ctx_set_stribeck(fricreg_handle_to_ptr(h), int(m, c_size_t), fs, fk, &
                                           vs, delta))
end subroutine frdstr

!> FRDCPB(H, M, W, STAT): block diagonal coupling W(2, 2, M), W(:, :, I) contact I's symmetric
!> positive definite block (fricreg_disk_ctx_set_coupling_blocks).
subroutine frdcpb(h, m, w, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(in) :: w(*)
  integer, intent(out) :: stat
  stat = int(fricreg_disk_ctx_set_coupling_blocks(fricreg_handle_to_ptr(h), int(m, c_size_t), w))
end subroutine frdcpb

!> FRDCPD(H, M, W, STAT): dense symmetric coupling W(2M, 2M), leading dimension 2M
!> (fricreg_disk_ctx_set_coupling_dense).
subroutine frdcpd(h, m, w, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(in) :: w(*)
  integer, intent(out) :: stat
  stat = int(fricreg_disk_ctx_set_coupling_dense(fricreg_handle_to_ptr(h), int(m, c_size_t), w))
end subroutine frdcpd

!> FRDCSR(H, M, FLAGS, ROWPTR, COLIND, VALUES, STAT): sparse symmetric coupling of order 2M by
!> compressed rows, ROWPTR(2M + 1) and COLIND(NNZ) INTEGER*8 (integer(c_int64_t)), VALUES(NNZ),
!> FLAGS the FRICREG_SPARSE_* constants (FRICREG_SPARSE_ONE_BASED for Fortran's indices)
!> (fricreg_disk_ctx_set_coupling_csr).
subroutine frdcsr(h, m, flags, rowptr, colind, values, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m, flags
  integer(c_int64_t), intent(in) :: rowptr(*), colind(*)
  double precision, intent(in) :: values(*)
  integer, intent(out) :: stat
  stat = int(fricreg_disk_ctx_set_coupling_csr(fricreg_handle_to_ptr(h), int(m, c_size_t), &
                                               int(flags, c_int), rowptr, colind, values))
end subroutine frdcsr

!> FRDCSC(H, M, FLAGS, COLPTR, ROWIND, VALUES, STAT): the same by compressed columns
!> (fricreg_disk_ctx_set_coupling_csc).
subroutine frdcsc(h, m, flags, colptr, rowind, values, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m, flags
  integer(c_int64_t), intent(in) :: colptr(*), rowind(*)
  double precision, intent(in) :: values(*)
  integer, intent(out) :: stat
  stat = int(fricreg_disk_ctx_set_coupling_csc(fricreg_handle_to_ptr(h), int(m, c_size_t), &
                                               int(flags, c_int), colptr, rowind, values))
end subroutine frdcsc

!> FRDEVL(H, M, ZDOT, AFREE, F, STAT): friction forces F(2, M) from velocities ZDOT(2, M) and
!> free accelerations AFREE(2, M), column I contact I (fricreg_disk_ctx_eval).
subroutine frdevl(h, m, zdot, afree, f, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m
  double precision, intent(in) :: zdot(*), afree(*)
  double precision, intent(inout) :: f(*)
  integer, intent(out) :: stat
  stat = int(fricreg_disk_ctx_eval(fricreg_handle_to_ptr(h), int(m, c_size_t), zdot, afree, f))
end subroutine frdevl

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
