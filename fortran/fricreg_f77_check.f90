! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_f77_check.f90 — FRCHK: was the caller compiled for this F77 library?
!
! The entry points FR* read their arguments by reference with the kinds this library was
! compiled with: default INTEGER (KIND 4; KIND 8 in libfricreg_fortran_ilp64, compiled with
! -fdefault-integer-8) and DOUBLE PRECISION = the C double (KIND 8). A caller compiled
! otherwise has its arguments misread and its STAT half written, with no error. FRCHK is the
! one entry point safe from any such build, so a legacy program can call it first:
!   - it reads 4 bytes of each INTEGER argument, and 8 only once it knows the caller's INTEGER
!     has 8 (a small kind number is the same in the first 4 bytes of a 4- or 8-byte INTEGER on
!     a little-endian machine; on a big-endian one an 8-byte INTEGER begins with 0);
!   - it writes STAT with the caller's width, never beyond the caller's INTEGER;
!   - it gives its diagnosis in MSG itself: after a mismatch no other entry point can be
!     called safely, not even FRSTRE (an 8-byte STAT written into a 4-byte INTEGER).
! Compiled into both libraries; kind(0) below is the library's own default INTEGER.

!> FRCHK(IKIND, RKIND, DKIND, MSG, STAT): whether this library can be called from code compiled
!> as the caller was. Pass KIND(0), KIND(0.0) and KIND(0.0D0) exactly so, from the calling
!> program unit (default INTEGER each). STAT = FRICREG_OK (MSG says which library matched) or
!> FRICREG_EINVAL, with MSG naming the mismatch and its fix: an INTEGER of the other variant
!> (link libfricreg_fortran_ilp64, or libfricreg_fortran), a DOUBLE PRECISION that is not the C
!> double (KIND 16 from -fdefault-real-8 without -fdefault-double-8), or an IKIND that is
!> neither 4 nor 8. RKIND is read only to name the flag in MSG: no entry point takes a REAL.
!> MSG is blank-padded or truncated to its length (256 characters hold every message).
subroutine frchk(ikind, rkind, dkind, msg, stat)
  use fricreg_c, only: c_int, c_double, FRICREG_OK, FRICREG_EINVAL
  use, intrinsic :: iso_c_binding, only: c_loc, c_f_pointer
  use, intrinsic :: iso_fortran_env, only: int32, int64
  implicit none
  integer(int32), intent(in) :: ikind(*), rkind(*), dkind(*) ! the caller's INTEGERs, as words
  character(len=*), intent(out) :: msg
  integer(int32), intent(inout), target :: stat(*)           ! the caller's INTEGER, as words
  integer, parameter :: lib_ikind = kind(0), lib_dkind = c_double
  integer :: width
  integer(int64) :: ik, rk, dk
  integer(c_int) :: status
  integer(int64), pointer :: stat8
  character(len=:), allocatable :: what

  width = caller_width(ikind)
  ik = caller_value(ikind, width)
  rk = caller_value(rkind, width)
  dk = caller_value(dkind, width)
  what = ''
  if (ik /= lib_ikind) call add(integer_mismatch(ik))
  if (dk /= lib_dkind) call add(double_mismatch(dk, rk))
  if (what == '') then
    status = FRICREG_OK
    msg = 'FRCHK: INTEGER KIND ' // str(ik) // ' and DOUBLE PRECISION KIND ' // str(dk) // &
          ' match ' // library_name()
  else
    status = FRICREG_EINVAL
    msg = 'FRCHK: ' // what
  end if
  if (width == 8) then
    call c_f_pointer(c_loc(stat(1)), stat8)
    stat8 = status
  else
    stat(1) = status
  end if

contains

  !> 8 if the caller's INTEGER holding its own kind reads as an 8-byte 8, else 4 (also for a
  !> value that is no kind: then only 4 bytes are written, which any INTEGER has).
  integer function caller_width(a)
    integer(int32), intent(in) :: a(*)
    caller_width = 4
    if (a(1) == 8) then
      caller_width = 8                      ! little-endian 8-byte 8 (or a 4-byte 8)
    else if (a(1) == 0) then
      if (transfer(a(1:2), 0_int64) == 8) caller_width = 8 ! big-endian 8-byte 8
    end if
  end function caller_width

  !> The caller's INTEGER a read with width bytes.
  integer(int64) function caller_value(a, width)
    integer(int32), intent(in) :: a(*)
    integer, intent(in) :: width
    if (width == 8) then
      caller_value = transfer(a(1:2), 0_int64)
    else
      caller_value = a(1)
    end if
  end function caller_value

  function integer_mismatch(k) result(s)
    integer(int64), intent(in) :: k
    character(len=:), allocatable :: s
    if (k == 8) then
      s = 'INTEGER is KIND 8 (-fdefault-integer-8): link libfricreg_fortran_ilp64, not ' // &
          library_name()
    else if (k == 4) then
      s = 'INTEGER is KIND 4, not -fdefault-integer-8: link libfricreg_fortran, not ' // &
          library_name()
    else
      s = 'IKIND = ' // str(k) // ' is not KIND(0) of a supported build (4 or 8)'
    end if
  end function integer_mismatch

  function double_mismatch(k, real_kind) result(s)
    integer(int64), intent(in) :: k, real_kind
    character(len=:), allocatable :: s
    s = 'DOUBLE PRECISION is KIND ' // str(k)
    if (k == 16 .and. real_kind == 8) then
      s = s // ' (-fdefault-real-8 without -fdefault-double-8): add -fdefault-double-8'
    else
      s = s // ', not the C double (KIND 8)'
    end if
  end function double_mismatch

  subroutine add(part)
    character(len=*), intent(in) :: part
    if (what == '') then
      what = part
    else
      what = what // '. ' // part
    end if
  end subroutine add

  function library_name() result(s)
    character(len=:), allocatable :: s
    if (lib_ikind == 8) then
      s = 'libfricreg_fortran_ilp64'
    else
      s = 'libfricreg_fortran'
    end if
  end function library_name

  function str(k) result(s)
    integer(int64), intent(in) :: k
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write (buf, '(i0)') k
    s = trim(buf)
  end function str

end subroutine frchk
