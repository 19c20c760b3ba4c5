! SPDX-License-Identifier: GPL-3.0-or-later
! probe_type.f90 — m of fricreg_ctx_create (size_t) passed as a default integer: must not
! compile (a 4-byte value where C reads 8 bytes is the drift the generated interfaces prevent).
program probe_type
  use fricreg_c
  implicit none
  type(c_ptr) :: ctx
  integer(c_int) :: status
  status = fricreg_ctx_create(2, ctx)
  status = fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02_c_double)
  call fricreg_ctx_free(ctx)
  print *, status
end program probe_type
