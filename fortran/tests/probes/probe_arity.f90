! SPDX-License-Identifier: GPL-3.0-or-later
! probe_arity.f90 — one argument too many for fricreg_ctx_set_law: must not compile.
program probe_arity
  use fricreg_c
  implicit none
  type(c_ptr) :: ctx
  integer(c_int) :: status
  status = fricreg_ctx_create(2_c_size_t, ctx)
  status = fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02_c_double, 0.02_c_double)
  call fricreg_ctx_free(ctx)
  print *, status
end program probe_arity
