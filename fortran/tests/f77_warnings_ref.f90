! SPDX-License-Identifier: GPL-3.0-or-later
! f77_warnings_ref.f90 — the reference of test_f77_warnings.f: the warnings of the object behind
! an F77 handle read through the C API itself (bind(C) interfaces of fricreg_sim_c), by its
! *_warning_count and its *_get_warning into a C buffer, not by the F77 entry points' path
! (*_warning_message). Called from fixed-form code without an interface, so every argument has
! an explicit kind and the ILP64 build of the test calls it unchanged.
!
! iobj 1: h is a simulation; 2: a structure. n is C's count; for 1 <= k <= n, icode is warning
! k's code, msg its message (blank-padded) and mlen the message's length (strlen); ist is C's
! status of get_warning (FRICREG_OK if k is out of range: nothing read).
subroutine wref(iobj, h, k, n, icode, msg, mlen, ist)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: iobj, h, k
  integer(c_int64_t), intent(out) :: n, icode, mlen, ist
  character(len=*), intent(out) :: msg
  character(kind=c_char) :: buf(256)
  type(c_ptr) :: p
  integer(c_int) :: code
  integer :: i
  p = fricreg_handle_to_ptr(h)
  code = FRICREG_WARN_NONE
  ist = FRICREG_OK
  buf = c_null_char
  if (iobj == 1) then
    n = int(fricreg_sim_warning_count(p), c_int64_t)
    if (k >= 1 .and. k <= n) &
      ist = fricreg_sim_get_warning(p, int(k - 1, c_size_t), code, buf, 256_c_size_t)
  else
    n = int(fricreg_structure_warning_count(p), c_int64_t)
    if (k >= 1 .and. k <= n) &
      ist = fricreg_structure_get_warning(p, int(k - 1, c_size_t), code, buf, 256_c_size_t)
  end if
  icode = code
  msg = ''
  mlen = 0
  do i = 1, size(buf)
    if (buf(i) == c_null_char) exit
    mlen = i
    if (i <= len(msg)) msg(i:i) = buf(i)
  end do
end subroutine wref
