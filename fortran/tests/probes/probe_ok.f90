! SPDX-License-Identifier: GPL-3.0-or-later
! probe_ok.f90 — calls of the generated interfaces that are right: must compile. The probes
! probe_arity.f90 and probe_type.f90 differ from it in one argument each and must not.
program probe_ok
  use fricreg_c
  implicit none
  type(c_ptr) :: ctx
  integer(c_int) :: status
  status = fricreg_ctx_create(2_c_size_t, ctx)
  status = fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02_c_double)
  call fricreg_ctx_free(ctx)
  print *, status
end program probe_ok
