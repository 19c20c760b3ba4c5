! SPDX-License-Identifier: GPL-3.0-or-later
! probe_private.f90 — error_record is module fricreg's internal plumbing, private by default:
! `use fricreg, only: error_record` must not compile.
program probe_private
  use fricreg, only: fricreg_context, error_record
  implicit none
  type(fricreg_context) :: ctx
  print *, ctx%is_created()
end program probe_private
