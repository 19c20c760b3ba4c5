! SPDX-License-Identifier: GPL-3.0-or-later
! probe_public.f90 — what fortran/README.md says `use fricreg` gives, by name (the core part,
! which every build has): must compile. probe_private.f90 names an internal helper and must not.
program probe_public
  use fricreg, only: fricreg_object, fricreg_context, law_eval, fricreg_error_string, &
                     fricreg_version_string, fricreg_c_string, fricreg_ptr_to_handle, &
                     fricreg_handle_to_ptr, fricreg_ctx_create, fricreg_ctx_eval, &
                     fricreg_law_eval_batch, fricreg_strerror, FRICREG_OK, FRICREG_LAW_QUINN, &
                     disk_eval, stribeck_eval, stribeck_disk_eval, fricreg_disk_law_string, &
                     fricreg_disk_law_id, fricreg_law_string, fricreg_law_id, &
                     FRICREG_DISK_QUINN, fricreg_disk_eval_batch, &
                     FRICREG_STAT_SOLVES, FRICREG_HEADER_VERSION, c_int, c_double, c_size_t, &
                     c_int64_t, c_intptr_t, c_ptr, c_funptr, c_char, c_null_ptr, &
                     c_null_funptr, c_null_char, c_associated, c_f_pointer, c_loc, c_funloc
  implicit none
  type(fricreg_context) :: ctx
  print *, ctx%is_created(), FRICREG_OK
end program probe_public
