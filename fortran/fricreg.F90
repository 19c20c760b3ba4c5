! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg.F90 — module fricreg: the Fortran interface of fricreg.
!
!   use fricreg
!   type(fricreg_context) :: ctx
!   integer(c_int) :: status
!   status = ctx%create(2)
!   status = ctx%set_law(FRICREG_LAW_QUINN, 0.02_c_double)
!   status = ctx%eval(zdot, a_free, f, f_eq)        ! assumed-shape real(c_double) arrays
!   if (status /= FRICREG_OK) print '(a)', ctx%errmsg()
!   call ctx%destroy()
!
! The module is private by default. What `use fricreg` gives (the public lists below):
!   - every constant of the C headers (FRICREG_OK, FRICREG_LAW_QUINN, ...), generated from
!     them at build time (module fricreg_constants);
!   - every C function by its C name, with an interface generated from its prototype
!     (modules fricreg_c and fricreg_sim_c: scalars by value, arrays dimension(*) with the
!     count passed, handles as type(c_ptr), omitted pointer arguments passed as NULL), the
!     abstract interfaces fricreg_sim_observer, fricreg_structure_observer and
!     fricreg_warning_handler, and
!     fricreg_c_string, fricreg_ptr_to_handle,
!     fricreg_handle_to_ptr;
!   - the iso_c_binding names used with them: c_int, c_double, c_size_t, c_int64_t,
!     c_intptr_t, c_ptr, c_funptr, c_char, c_null_ptr, c_null_funptr, c_null_char,
!     c_associated, c_f_pointer, c_loc, c_funloc;
!   - the idiomatic layer below: the types fricreg_context, fricreg_disk_context,
!     fricreg_jenkins_elements, fricreg_iwan_elements, fricreg_element (an element type of
!     fricreg_element.h: no C object behind it), fricreg_aft_workspace, fricreg_simulation,
!     fricreg_exact_solution, fricreg_structure, fricreg_hb_driver and fricreg_backbone_fit (the
!     last five with the drivers), their
!     common parent fricreg_object, the generics law_eval, disk_eval, stribeck_eval and
!     stribeck_disk_eval, and fricreg_error_string, fricreg_warning_string, fricreg_version_string,
!     fricreg_law_string, fricreg_law_id, fricreg_disk_law_string, fricreg_disk_law_id,
!     fricreg_integrator_string, fricreg_integrator_id.
!
! Conventions of the idiomatic layer:
!   - Every procedure that can fail is a function returning a status, integer(c_int):
!     FRICREG_OK or one of the FRICREG_E* codes, as in C (SUNDIALS' Fortran interface does
!     the same). On failure the arguments are left unchanged, which is why output arrays are
!     intent(inout).
!   - Arrays are assumed-shape real(c_double) with the contiguous attribute. A contiguous
!     actual argument (a whole array, a(:, j), a(i:k)) reaches C with no copy; a non-contiguous
!     one (a(j, :), a(1:n:2)) is copied in (and out, for outputs) by the compiler at the call.
!   - Sizes are checked against the object before C is called: a mismatch returns
!     FRICREG_ESIZE, with a message naming the array, and never touches memory.
!   - Messages are character(len=:), allocatable. Indices in the C library's messages count
!     from 0 (contact 0 is the first).
!   - Objects hold a C handle. Release it with destroy (safe to call twice); a final
!     procedure releases it too when a local object goes out of scope or an allocatable one is
!     deallocated, but the standard does not finalize what is alive at program end, so call
!     destroy. Objects cannot be copied (the C library has no clone): `b = a` releases b's
!     handle and leaves b empty; calls on an empty object return FRICREG_ENULL.
!   - One object must not be used from two threads at once; separate objects may.
!
! Its source is one file per object, each a module of its own that this one uses and re-exports
! (modules fricreg_<file>_m): fricreg_base.F90 (fricreg_object, its error record, the string
! helpers), fricreg_laws.F90 (the law generics), fricreg_ctx.F90, fricreg_disk_ctx.F90,
! fricreg_jenkins.F90, fricreg_iwan.F90, fricreg_element.F90, fricreg_aft.F90 and, with the
! drivers, fricreg_sim.F90, fricreg_exact.F90, fricreg_structure.F90, fricreg_hb.F90 and
! fricreg_fit.F90. Callers use this module only:
! the names of those are not an interface, nor are fricreg_object's component ptr and its
! helper bindings (adopt, ready, fail, ...), public for the object modules alone.
module fricreg
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_intptr_t, &
                                         c_ptr, c_funptr, c_char, c_null_ptr, c_null_funptr, &
                                         c_null_char, c_associated, c_f_pointer, c_loc, c_funloc
  use fricreg_c
#ifdef FRICREG_HAVE_SIM
  use fricreg_sim_c
#endif
  use fricreg_base_m
  use fricreg_laws_m
  use fricreg_ctx_m
  use fricreg_disk_ctx_m
  use fricreg_jenkins_m
  use fricreg_iwan_m
  use fricreg_element_m
  use fricreg_aft_m
#ifdef FRICREG_HAVE_SIM
  use fricreg_sim_m
  use fricreg_exact_m
  use fricreg_structure_m
  use fricreg_hb_m
  use fricreg_fit_m
#endif
  implicit none
  private

  ! ---- Public: the C layer, re-exported (lists generated from the headers) ------------------
  include 'fricreg_constants_public.inc'
  include 'fricreg_h_public.inc'
  public :: c_int, c_double, c_size_t, c_int64_t, c_intptr_t, c_ptr, c_funptr, c_char, &
            c_null_ptr, c_null_funptr, c_null_char, c_associated, c_f_pointer, c_loc, c_funloc
  public :: fricreg_c_string, fricreg_ptr_to_handle, fricreg_handle_to_ptr, fricreg_transpose
  ! ---- Public: the idiomatic layer ------------------------------------------------------------
  public :: fricreg_object, fricreg_context, law_eval, fricreg_error_string, &
            fricreg_warning_string, fricreg_version_string, fricreg_law_string, fricreg_law_id
  public :: disk_eval, stribeck_eval, stribeck_disk_eval, fricreg_disk_law_string, &
            fricreg_disk_law_id
  public :: fricreg_disk_context, fricreg_jenkins_elements, fricreg_iwan_elements
  public :: fricreg_element
  public :: fricreg_aft_workspace
#ifdef FRICREG_HAVE_SIM
  include 'fricreg_drivers_h_public.inc'
  public :: fricreg_sim_observer, fricreg_structure_observer, fricreg_warning_handler
  public :: fricreg_hb_monitor
  public :: fricreg_simulation, fricreg_exact_solution, fricreg_structure, &
            fricreg_integrator_string, fricreg_integrator_id
  public :: fricreg_hb_driver, fricreg_backbone_fit
#endif

end module fricreg
