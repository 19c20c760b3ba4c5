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
!     fricreg_jenkins_elements, fricreg_iwan_elements, fricreg_aft_workspace, fricreg_simulation,
!     fricreg_exact_solution, fricreg_structure and fricreg_hb_driver (the last four with the
!     drivers), their
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
module fricreg
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_intptr_t, &
                                         c_ptr, c_funptr, c_char, c_null_ptr, c_null_funptr, &
                                         c_null_char, c_associated, c_f_pointer, c_loc, c_funloc, &
                                         c_int8_t
  use fricreg_c
#ifdef FRICREG_HAVE_SIM
  use fricreg_sim_c
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
  public :: fricreg_aft_workspace
#ifdef FRICREG_HAVE_SIM
  include 'fricreg_drivers_h_public.inc'
  public :: fricreg_sim_observer, fricreg_structure_observer, fricreg_warning_handler
  public :: fricreg_hb_monitor
  public :: fricreg_simulation, fricreg_exact_solution, fricreg_structure, &
            fricreg_integrator_string, fricreg_integrator_id
  public :: fricreg_hb_driver
#endif

  !> A failure detected in Fortran (a size mismatch, an object not created, or a C failure the
  !> C object does not record), kept beside the C library's own record; `last` says which of
  !> the two is the more recent.
  type :: error_record
    integer(c_int) :: code = FRICREG_OK
    logical :: last = .false.
    character(len=:), allocatable :: msg
  end type

  !> The parent of every object of this module: the C handle it owns, the C functions that
  !> release it and read its last error (set by each type's create, bound straight to the
  !> generated bind(C) interfaces), and the error record of failures found in Fortran.
  !> It gives its children destroy (safe twice), is_created, handle, errcode, errmsg and an
  !> assignment that cannot free one handle twice.
  type, abstract :: fricreg_object
    private
    type(c_ptr) :: ptr = c_null_ptr
    type(error_record) :: err
    procedure(fricreg_free_fn), pointer, nopass :: c_free => null()
    procedure(fricreg_errcode_fn), pointer, nopass :: c_errcode => null()
    procedure(fricreg_errmsg_fn), pointer, nopass :: c_errmsg => null()
  contains
    procedure :: destroy => object_destroy
    procedure :: is_created => object_is_created
    procedure :: handle => object_handle
    procedure :: errcode => object_errcode
    procedure :: errmsg => object_errmsg
    procedure, private :: object_assign
    generic :: assignment(=) => object_assign
    procedure, private :: adopt, ready, fail, record, unrecorded, check_size, check_square
  end type

  !> m coupled contacts z'' = a_free + W f (Sec. 3.3): law, eps, bounds mun, coupling W.
  !> Holds a fricreg_ctx; see include/fricreg.h for the meaning of every setting.
  type, extends(fricreg_object) :: fricreg_context
  contains
    procedure :: create => ctx_create
    procedure :: size => ctx_size
    procedure :: set_law => ctx_set_law
    procedure :: set_bounds => ctx_set_bounds
    procedure :: set_stribeck => ctx_set_stribeck
    procedure :: set_coupling_diagonal => ctx_set_coupling_diagonal
    procedure :: set_coupling_dense => ctx_set_coupling_dense
    procedure :: set_coupling_csr => ctx_set_coupling_csr
    procedure :: set_coupling_csc => ctx_set_coupling_csc
    procedure :: set_partition => ctx_set_partition
    procedure :: set_keep_tangent => ctx_set_keep_tangent
    procedure :: eval => ctx_eval
    procedure :: tangent => ctx_tangent
    procedure :: tangent_apply => ctx_tangent_apply
#ifdef FRICREG_HAVE_SIM
    procedure :: solve_step => ctx_solve_step
    procedure :: solve_step_csr => ctx_solve_step_csr
    procedure :: solve_step_csc => ctx_solve_step_csc
#endif
    procedure :: switching => ctx_switching
    procedure :: switching_count => ctx_switching_count
    procedure :: stick_stiffness => ctx_stick_stiffness
    procedure :: get_stat => ctx_get_stat
    procedure :: reset_stats => ctx_reset_stats
    final :: ctx_final
  end type

  !> m coupled 2-D contacts z'' = a_free + W f, W of order 2m with 2x2 blocks per contact
  !> (fricreg_disk_ctx.h): law (FRICREG_DISK_QUINN or FRICREG_DISK_FORCE_BALANCE), eps,
  !> bounds, coupling. Vectors are (2, m) arrays, column i contact i (C's interleaved layout).
  type, extends(fricreg_object) :: fricreg_disk_context
  contains
    procedure :: create => dctx_create
    procedure :: size => dctx_size
    procedure :: set_law => dctx_set_law
    procedure :: set_bounds => dctx_set_bounds
    procedure :: set_stribeck => dctx_set_stribeck
    procedure :: set_coupling_blocks => dctx_set_coupling_blocks
    procedure :: set_coupling_dense => dctx_set_coupling_dense
    procedure :: set_coupling_csr => dctx_set_coupling_csr
    procedure :: set_coupling_csc => dctx_set_coupling_csc
    procedure, private :: check_compressed
    procedure :: eval => dctx_eval
    procedure :: tangent => dctx_tangent
    final :: dctx_final
  end type

  !> n Jenkins elements (a spring kt in series with a Coulomb slider of bound mun), 1-D or 2-D,
  !> with trial/commit (fricreg_jenkins.h, docs/joints.md). Vectors are (dim, n) arrays, column
  !> i element i (C's interleaved layout, passed with no copy); tangents (dim, dim, n), each
  !> block symmetric, so Fortran's order is C's.
  type, extends(fricreg_object) :: fricreg_jenkins_elements
  contains
    procedure :: create => jk_create
    procedure :: size => jk_size
    procedure :: dim => jk_dim
    procedure :: set_params => jk_set_params
    procedure :: set_normal => jk_set_normal
    procedure :: trial => jk_trial
    procedure :: trial_normal => jk_trial_normal
    procedure :: commit => jk_commit
    procedure :: reset => jk_reset
    procedure :: get_slider => jk_get_slider
    final :: jk_final
  end type

  !> n Iwan elements of ns parallel Jenkins sliders each, 1-D or 2-D, with user sliders or
  !> Segalman's four-parameter model, a normal load with lift-off and trial/commit
  !> (fricreg_iwan.h, docs/joints.md). Slider parameters are (ns, n) arrays, column e element
  !> e; vectors (dim, n); tangents (dim, dim, n), each block symmetric; slider positions
  !> (dim, ns, n). All are C's layouts, passed with no copy.
  type, extends(fricreg_object) :: fricreg_iwan_elements
  contains
    procedure :: create => iw_create
    procedure :: size => iw_size
    procedure :: sliders => iw_sliders
    procedure :: dim => iw_dim
    procedure :: set_params => iw_set_params
    procedure :: get_params => iw_get_params
    procedure :: set_segalman => iw_set_segalman
    procedure :: set_normal => iw_set_normal
    procedure :: trial => iw_trial
    procedure :: trial_normal => iw_trial_normal
    procedure :: commit => iw_commit
    procedure :: reset => iw_reset
    procedure :: get_slider => iw_get_slider
    final :: iw_final
  end type

  !> The AFT of 1-D Jenkins and Iwan elements (fricreg_aft.h, docs/joints.md): from the
  !> Fourier coefficients u(2H+1) = (u0, a_1, b_1, ..., a_H, b_H) of a periodic displacement,
  !> those of the stabilized hysteresis force, f(2H+1), and their Jacobian in Fortran's order,
  !> jac(i, j) = d f(i) / d u(j), exact or sampled at N points.
  type, extends(fricreg_object) :: fricreg_aft_workspace
  contains
    procedure :: create => aft_create
    procedure :: harmonics => aft_harmonics
    procedure :: samples => aft_samples
    procedure :: jenkins_exact => aft_jenkins_exact
    procedure :: jenkins_sampled => aft_jenkins_sampled
    procedure :: iwan_exact => aft_iwan_exact
    procedure :: iwan_sampled => aft_iwan_sampled
    procedure, private :: aft_check
    final :: aft_final
  end type

  !> One friction law, C's fricreg_law_eval / fricreg_law_eval_batch:
  !>   status = law_eval(law, eps, v, f_eq, mun, f)
  !> with v, f_eq, mun, f all scalars or all rank-1 arrays of one size (else FRICREG_ESIZE),
  !> in the order of C's batch function. f_eq may be omitted (then pass mun= and f= by
  !> keyword) for the laws that do not read it: (1), (3) and tanh; for the others its absence
  !> is FRICREG_ENULL. f is written only on success.
  interface law_eval
    module procedure law_eval_scalar, law_eval_array
  end interface

  !> One 2-D friction law (FRICREG_DISK_*, include/fricreg_disk.h), C's fricreg_disk_eval /
  !> fricreg_disk_eval_batch, in the order of the batch function:
  !>   status = disk_eval(law, eps, v, f_eq, mun, f)
  !> one contact: v(2), f_eq(2), f(2) and a scalar mun; m contacts: v(2, m), f_eq(2, m),
  !> f(2, m) (column i is contact i: a (2, m) Fortran array is C's interleaved layout, passed
  !> with no copy) and mun(m). Any other shape is FRICREG_ESIZE. f_eq may be omitted (then
  !> pass mun= and f= by keyword) for FRICREG_DISK_COULOMB, which does not read it; for the
  !> others its absence is FRICREG_ENULL. f is written only on success.
  interface disk_eval
    module procedure disk_eval_one, disk_eval_batch
  end interface

  !> The Stribeck law at 1-D contacts (include/fricreg_stribeck.h), C's fricreg_stribeck_eval /
  !> fricreg_stribeck_eval_batch, in the order of the batch function:
  !>   status = stribeck_eval(eps, v, f_eq, fs, fk, vs, delta, f)
  !> with v, f_eq, fs, fk, vs, delta, f all scalars or all rank-1 arrays of one size m (else
  !> FRICREG_ESIZE): static bound fs >= kinetic force fk >= 0, Stribeck velocity vs > 0,
  !> exponent delta > 0, each contact its own. f is written only on success.
  interface stribeck_eval
    module procedure stribeck_eval_scalar, stribeck_eval_array
  end interface

  !> The 2-D Stribeck law, C's fricreg_stribeck_disk_eval / fricreg_stribeck_disk_eval_batch:
  !>   status = stribeck_disk_eval(eps, v, f_eq, fs, fk, vs, delta, f)
  !> one contact: v(2), f_eq(2), f(2) and scalar parameters; m contacts: v(2, m), f_eq(2, m),
  !> f(2, m) (column i is contact i, no copy) and fs(m), fk(m), vs(m), delta(m). Any other
  !> shape is FRICREG_ESIZE. f is written only on success.
  interface stribeck_disk_eval
    module procedure stribeck_disk_eval_one, stribeck_disk_eval_batch
  end interface

#ifdef FRICREG_HAVE_SIM
  !> One of the paper's reference systems on a GSL ODE driver (include/fricreg_sim.h).
  type, extends(fricreg_object) :: fricreg_simulation
  contains
    procedure :: create => sim_create
    procedure :: set_param => sim_set_param
    procedure :: set_law => sim_set_law
    procedure :: set_partition => sim_set_partition
    procedure :: set_integrator => sim_set_integrator
    procedure :: set_observer => sim_set_observer
    procedure :: set_warning_handler => sim_set_warning_handler
    procedure :: set_max_steps => sim_set_max_steps
    procedure :: set_kink_location => sim_set_kink_location
    procedure :: set_error_estimate => sim_set_error_estimate
    procedure :: set_abs_tolerances => sim_set_abs_tolerances
    procedure :: get_abs_tolerances => sim_get_abs_tolerances
    procedure :: run => sim_run
    procedure :: run_cycles => sim_run_cycles
    procedure :: ndof => sim_ndof
    procedure :: ncontacts => sim_ncontacts
    procedure :: get_value => sim_get_value
    procedure :: get_stat => sim_get_stat
    procedure :: get_param => sim_get_param
    procedure :: get_state => sim_get_state
    procedure :: get_dissipation => sim_get_dissipation
    procedure :: get_dissipation_error => sim_get_dissipation_error
    procedure :: get_stick_fraction => sim_get_stick_fraction
    procedure :: run_extrapolated => sim_run_extrapolated
    procedure :: get_extrapolation => sim_get_extrapolation
    procedure :: get_extrapolated_dissipation => sim_get_extrapolated_dissipation
    final :: sim_final
  end type

  !> The exact solution of the oscillator, Eq. (5), under (1)+(2) (include/fricreg_exact.h):
  !> its switching times, state in closed form, and dissipation per cycle.
  type, extends(fricreg_object) :: fricreg_exact_solution
  contains
    procedure :: solve => exact_solve
    procedure :: state => exact_state
    procedure :: nswitches => exact_nswitches
    procedure :: switches => exact_switches
    procedure :: ncycles => exact_ncycles
    procedure :: dissipation => exact_dissipation
    procedure :: stick_fraction => exact_stick_fraction
    final :: exact_final
  end type

  !> A linear structure with friction contacts (include/fricreg_structure.h):
  !>   M u'' + C u' + K u = p(t) - M r a_g(t) + J^T f,   zdot = J u',
  !> integrated by Newmark, HHT-alpha (Newton on the exact tangent), central difference or a
  !> GSL stepper. Every matrix is a Fortran array in its natural shape: M, K, C (ndof, ndof);
  !> J (m, ndof) with J(i, k) = d zdot_i / d u'_k (transposed for C here). Units are the
  !> caller's, consistent (kg, N/m, N s/m, m, s, N); eps is a velocity.
  type, extends(fricreg_object) :: fricreg_structure
    private
    integer(c_size_t) :: n = 0, m = 0 ! C has no size getters: kept from create
  contains
    procedure :: create => struct_create
    procedure :: ndof => struct_ndof
    procedure :: ncontacts => struct_ncontacts
    procedure :: set_mass => struct_set_mass
    procedure :: set_stiffness => struct_set_stiffness
    procedure :: set_damping => struct_set_damping
    procedure :: set_rayleigh => struct_set_rayleigh
    procedure :: set_contacts => struct_set_contacts
    procedure :: set_jenkins => struct_set_jenkins
    procedure :: get_jenkins_state => struct_get_jenkins_state
    procedure :: set_jenkins_2d => struct_set_jenkins_2d
    procedure :: get_jenkins_2d_state => struct_get_jenkins_2d_state
    procedure :: set_iwan => struct_set_iwan
    procedure :: get_iwan_state => struct_get_iwan_state
    procedure :: set_jenkins_normal => struct_set_jenkins_normal
    procedure :: set_jenkins_2d_normal => struct_set_jenkins_2d_normal
    procedure :: get_normal_forces => struct_get_normal_forces
    procedure :: set_mass_csr => struct_set_mass_csr
    procedure :: set_mass_csc => struct_set_mass_csc
    procedure :: set_stiffness_csr => struct_set_stiffness_csr
    procedure :: set_stiffness_csc => struct_set_stiffness_csc
    procedure :: set_damping_csr => struct_set_damping_csr
    procedure :: set_damping_csc => struct_set_damping_csc
    procedure :: set_contacts_csr => struct_set_contacts_csr
    procedure :: set_contacts_csc => struct_set_contacts_csc
    procedure :: set_bounds => struct_set_bounds
    procedure :: set_law => struct_set_law
    procedure :: set_influence => struct_set_influence
    procedure :: set_ground_accel => struct_set_ground_accel
    procedure :: set_load => struct_set_load
    procedure :: set_initial => struct_set_initial
    procedure :: set_newmark => struct_set_newmark
    procedure :: set_hht => struct_set_hht
    procedure :: set_central_difference => struct_set_central_difference
    procedure :: set_newton => struct_set_newton
    procedure :: set_observer => struct_set_observer
    procedure :: set_warning_handler => struct_set_warning_handler
    procedure :: set_max_steps => struct_set_max_steps
    procedure :: step => struct_step
    procedure :: run => struct_run
    procedure :: run_ode => struct_run_ode
    procedure :: set_ode_abs_tolerances => struct_set_ode_abs_tolerances
    procedure :: get_ode_abs_tolerances => struct_get_ode_abs_tolerances
    procedure :: get_state => struct_get_state
    procedure :: get_forces => struct_get_forces
    procedure :: get_dissipation => struct_get_dissipation
    procedure :: set_error_estimate => struct_set_error_estimate
    procedure :: get_peak_displacement => struct_get_peak_displacement
    procedure :: get_peak_displacement_error => struct_get_peak_displacement_error
    procedure :: get_dissipation_error => struct_get_dissipation_error
    procedure :: get_value => struct_get_value
    procedure :: get_stat => struct_get_stat
    procedure :: warning_count => struct_warning_count
    procedure :: get_warning => struct_get_warning
    procedure :: save => struct_save
    procedure :: restore => struct_restore
    final :: struct_final
  end type

  !> Harmonic balance of a structure with 1-D Jenkins elements (fricreg_hb.h, docs/joints.md):
  !> M, C, K (ndof, ndof) symmetric, J(m, ndof) in Fortran's order, the elements' coordinates'
  !> coefficients q(2H+1, m) (column i element i: q0, a_1, b_1, ..., a_H, b_H) and the
  !> displacements' x(2H+1, ndof); continuation points counted from 1.
  type, extends(fricreg_object) :: fricreg_hb_driver
    private
    integer(c_size_t) :: n = 0, m = 0, nc = 0 ! C has no size getters: kept from create
    integer(c_size_t) :: rows = 0 ! q's columns: m, or 2 m with set_normal_elements
  contains
    procedure :: create => hb_create
    procedure :: ndof => hb_ndof
    procedure :: nelements => hb_nelements
    procedure :: harmonics => hb_harmonics
    procedure :: set_mass => hb_set_mass
    procedure :: set_stiffness => hb_set_stiffness
    procedure :: set_damping => hb_set_damping
    procedure :: set_rayleigh => hb_set_rayleigh
    procedure :: set_elements => hb_set_elements
    procedure :: set_iwan => hb_set_iwan
    procedure :: set_normal_elements => hb_set_normal_elements
    procedure :: set_excitation => hb_set_excitation
    procedure :: set_newton => hb_set_newton
    procedure :: set_continuation => hb_set_continuation
    procedure :: set_monitor => hb_set_monitor
    procedure :: set_max_iterations => hb_set_max_iterations
    procedure :: solve => hb_solve
    procedure :: displacement => hb_displacement
    procedure :: continue => hb_continue
    procedure :: continue_level => hb_continue_level
    procedure :: points => hb_points
    procedure :: point => hb_point
    procedure :: point_level => hb_point_level
    procedure :: peak => hb_peak
    procedure :: set_stability => hb_set_stability
    procedure :: stability => hb_stability
    procedure :: truncation_error => hb_truncation_error
    procedure :: bifurcations => hb_bifurcations
    procedure :: bifurcation => hb_bifurcation
    procedure :: bifurcation_level => hb_bifurcation_level
    procedure :: nma => hb_nma
    procedure :: nma_points => hb_nma_points
    procedure :: nma_point => hb_nma_point
    procedure, private :: hb_shape
    final :: hb_final
  end type
#endif

contains

  ! ---- Strings -----------------------------------------------------------------------------

  !> Fixed English text of a status code (C's fricreg_strerror).
  function fricreg_error_string(status) result(text)
    integer(c_int), intent(in) :: status
    character(len=:), allocatable :: text
    text = fricreg_c_string(fricreg_strerror(status))
  end function fricreg_error_string

  !> Short fixed name of a warning code (FRICREG_WARN_*: 'eps_large', ...; C's
  !> fricreg_warning_name), 'unknown' if unknown. Since 1.6.
  function fricreg_warning_string(code) result(text)
    integer(c_int), intent(in) :: code
    character(len=:), allocatable :: text
    text = fricreg_c_string(fricreg_warning_name(code))
  end function fricreg_warning_string

  !> Version "MAJOR.MINOR.PATCH" of the library linked (FRICREG_VERSION_STRING: the headers').
  function fricreg_version_string() result(text)
    character(len=:), allocatable :: text
    text = fricreg_c_string(fricreg_version())
  end function fricreg_version_string

  !> The name of a law (FRICREG_LAW_*: 'coulomb', ..., 'quinn'; C's fricreg_law_name), '' if
  !> unknown.
  function fricreg_law_string(law) result(name)
    integer(c_int), intent(in) :: law
    character(len=:), allocatable :: name
    name = fricreg_c_string(fricreg_law_name(law))
  end function fricreg_law_string

  !> The law (FRICREG_LAW_*) named name (trailing blanks ignored), 0 if there is none.
  integer(c_int) function fricreg_law_id(name)
    character(len=*), intent(in) :: name
    fricreg_law_id = fricreg_law_from_name(trim(name) // c_null_char)
  end function fricreg_law_id

  !> The name of a 2-D law (FRICREG_DISK_*: 'coulomb', ..., 'quinn-nested'; C's
  !> fricreg_disk_law_name), '' if unknown.
  function fricreg_disk_law_string(law) result(name)
    integer(c_int), intent(in) :: law
    character(len=:), allocatable :: name
    name = fricreg_c_string(fricreg_disk_law_name(law))
  end function fricreg_disk_law_string

  !> The 2-D law (FRICREG_DISK_*) named name (trailing blanks ignored), 0 if there is none.
  integer(c_int) function fricreg_disk_law_id(name)
    character(len=*), intent(in) :: name
    fricreg_disk_law_id = fricreg_disk_law_from_name(trim(name) // c_null_char)
  end function fricreg_disk_law_id

  pure function as_size(n) result(m)
    integer, intent(in) :: n
    integer(c_size_t) :: m
    m = int(n, c_size_t)
  end function as_size

  ! ---- fricreg_object: the handle and the error plumbing -----------------------------------

  !> Take ownership of the new handle p (released with free; errcode and errmsg read its last
  !> error, absent where the C object keeps none), releasing the one held before.
  subroutine adopt(self, p, free, errcode, errmsg)
    class(fricreg_object), intent(inout) :: self
    type(c_ptr), intent(in) :: p
    procedure(fricreg_free_fn) :: free
    procedure(fricreg_errcode_fn), optional :: errcode
    procedure(fricreg_errmsg_fn), optional :: errmsg
    call self%destroy()
    self%ptr = p
    self%c_free => free
    nullify (self%c_errcode, self%c_errmsg)
    if (present(errcode)) self%c_errcode => errcode
    if (present(errmsg)) self%c_errmsg => errmsg
    self%err = error_record()
  end subroutine adopt

  !> Release the C object. Safe to call twice, and on an object never created.
  subroutine object_destroy(self)
    class(fricreg_object), intent(inout) :: self
    if (c_associated(self%ptr) .and. associated(self%c_free)) call self%c_free(self%ptr)
    self%ptr = c_null_ptr
  end subroutine object_destroy

  !> `lhs = rhs`: objects cannot be copied (C has no clone); lhs is released and left empty,
  !> so no handle is ever owned twice.
  subroutine object_assign(lhs, rhs)
    class(fricreg_object), intent(inout) :: lhs
    class(fricreg_object), intent(in) :: rhs
    if (c_associated(lhs%ptr, rhs%ptr)) return ! a = a
    call lhs%destroy()
    lhs%err = error_record()
  end subroutine object_assign

  logical function object_is_created(self)
    class(fricreg_object), intent(in) :: self
    object_is_created = c_associated(self%ptr)
  end function object_is_created

  !> The C handle (fricreg_ctx *, fricreg_sim *, ...), for the bind(C) functions; still owned
  !> by self.
  type(c_ptr) function object_handle(self)
    class(fricreg_object), intent(in) :: self
    object_handle = self%ptr
  end function object_handle

  !> Status of the last failed call on this object (FRICREG_OK if none).
  integer(c_int) function object_errcode(self)
    class(fricreg_object), intent(in) :: self
    object_errcode = FRICREG_OK
    if (c_associated(self%ptr) .and. associated(self%c_errcode)) &
      object_errcode = self%c_errcode(self%ptr)
    if (self%err%last .or. object_errcode == FRICREG_OK) then
      if (self%err%code /= FRICREG_OK) object_errcode = self%err%code
    end if
  end function object_errcode

  !> Message of the last failed call, naming the argument, contact or value ('' if none): the
  !> more recent of the Fortran record and the C object's.
  function object_errmsg(self) result(msg)
    class(fricreg_object), intent(in) :: self
    character(len=:), allocatable :: msg
    logical :: c_has_one
    c_has_one = .false.
    if (c_associated(self%ptr) .and. associated(self%c_errcode)) &
      c_has_one = self%c_errcode(self%ptr) /= FRICREG_OK .and. associated(self%c_errmsg)
    if (c_has_one .and. .not. self%err%last) then
      msg = fricreg_c_string(self%c_errmsg(self%ptr))
    else if (self%err%code /= FRICREG_OK) then
      msg = self%err%msg
    else
      msg = ''
    end if
  end function object_errmsg

  !> Records a failure found on the Fortran side and returns its code.
  function fail(self, code, msg) result(status)
    class(fricreg_object), intent(inout) :: self
    integer(c_int), intent(in) :: code
    character(len=*), intent(in) :: msg
    integer(c_int) :: status
    self%err%code = code
    self%err%msg = msg
    self%err%last = .true.
    status = code
  end function fail

  !> FRICREG_OK if the object holds a C object, else a recorded FRICREG_ENULL for call `what`
  !> saying which object (noun) and what makes one (maker, default 'create').
  function ready(self, what, noun, maker) result(status)
    class(fricreg_object), intent(inout) :: self
    character(len=*), intent(in) :: what, noun
    character(len=*), intent(in), optional :: maker
    integer(c_int) :: status
    status = FRICREG_OK
    if (c_associated(self%ptr)) return
    if (present(maker)) then
      status = self%fail(FRICREG_ENULL, what // ': the ' // noun // ' is not created (call ' // &
                         maker // ')')
    else
      status = self%fail(FRICREG_ENULL, what // ': the ' // noun // ' is not created (call create)')
    end if
  end function ready

  !> After a C call that records its failures: a failure there is now the most recent one.
  function record(self, status) result(same)
    class(fricreg_object), intent(inout) :: self
    integer(c_int), intent(in) :: status
    integer(c_int) :: same
    if (status /= FRICREG_OK) self%err%last = .false.
    same = status
  end function record

  !> After a C call that does not record (a getter on a const object, the exact solver): the
  !> failure is recorded here, with the code's text.
  function unrecorded(self, what, status) result(same)
    class(fricreg_object), intent(inout) :: self
    character(len=*), intent(in) :: what
    integer(c_int), intent(in) :: status
    integer(c_int) :: same
    same = status
    if (status /= FRICREG_OK) same = self%fail(status, what // ': ' // fricreg_error_string(status))
  end function unrecorded

  !> FRICREG_OK if n == expected, else a recorded FRICREG_ESIZE naming the array.
  function check_size(self, what, array, n, expected) result(status)
    class(fricreg_object), intent(inout) :: self
    character(len=*), intent(in) :: what, array
    integer, intent(in) :: n
    integer(c_size_t), intent(in) :: expected
    integer(c_int) :: status
    character(len=64) :: buf
    status = FRICREG_OK
    if (int(n, c_size_t) /= expected) then
      write (buf, '(a, i0, a, i0)') ') = ', n, ', expected ', expected
      status = self%fail(FRICREG_ESIZE, what // ': size(' // array // trim(buf))
    end if
  end function check_size

  !> FRICREG_OK if a is expected x expected, else a recorded FRICREG_ESIZE naming the array
  !> and the dimension. Takes the array itself: shape(a) would be a temporary at each call.
  function check_square(self, what, array, a, expected) result(status)
    class(fricreg_object), intent(inout) :: self
    character(len=*), intent(in) :: what, array
    real(c_double), intent(in) :: a(:, :)
    integer(c_size_t), intent(in) :: expected
    integer(c_int) :: status
    status = self%check_size(what, array // ', 1', size(a, 1), expected)
    if (status == FRICREG_OK) status = self%check_size(what, array // ', 2', size(a, 2), expected)
  end function check_square

  ! ---- Laws --------------------------------------------------------------------------------

  function law_eval_scalar(law, eps, v, f_eq, mun, f) result(status)
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps, v, mun
    real(c_double), intent(in), optional :: f_eq
    real(c_double), intent(inout) :: f
    integer(c_int) :: status
    real(c_double) :: v1(1), mun1(1), f1(1)
    if (present(f_eq)) then
      status = fricreg_law_eval(law, v, f_eq, mun, eps, f)
    else ! let C decide whether this law needs f_eq: its batch function takes f_eq = NULL
      v1(1) = v
      mun1(1) = mun
      status = fricreg_law_eval_batch(law, eps, 1_c_size_t, v1, mun=mun1, f=f1)
      if (status == FRICREG_OK) f = f1(1)
    end if
  end function law_eval_scalar

  function law_eval_array(law, eps, v, f_eq, mun, f) result(status)
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps
    real(c_double), intent(in), contiguous :: v(:), mun(:)
    real(c_double), intent(in), contiguous, optional :: f_eq(:)
    real(c_double), intent(inout), contiguous :: f(:)
    integer(c_int) :: status
    integer :: n
    n = size(v)
    status = FRICREG_ESIZE
    if (size(mun) /= n .or. size(f) /= n) return
    if (present(f_eq)) then
      if (size(f_eq) /= n) return
    end if
    status = fricreg_law_eval_batch(law, eps, as_size(n), v, f_eq, mun, f)
  end function law_eval_array

  !> Whether a holds m 2-D vectors, as (2, m).
  pure logical function is_pairs(a, m)
    real(c_double), intent(in) :: a(:, :)
    integer, intent(in) :: m
    is_pairs = size(a, 1) == 2 .and. size(a, 2) == m
  end function is_pairs

  function disk_eval_one(law, eps, v, f_eq, mun, f) result(status)
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps, mun
    real(c_double), intent(in), contiguous :: v(:)
    real(c_double), intent(in), contiguous, optional :: f_eq(:)
    real(c_double), intent(inout), contiguous :: f(:)
    integer(c_int) :: status
    status = FRICREG_ESIZE
    if (size(v) /= 2 .or. size(f) /= 2) return
    if (present(f_eq)) then
      if (size(f_eq) /= 2) return
    end if
    status = fricreg_disk_eval(law, v, f_eq, mun, eps, f)
  end function disk_eval_one

  function disk_eval_batch(law, eps, v, f_eq, mun, f) result(status)
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps
    real(c_double), intent(in), contiguous :: v(:, :), mun(:)
    real(c_double), intent(in), contiguous, optional :: f_eq(:, :)
    real(c_double), intent(inout), contiguous :: f(:, :)
    integer(c_int) :: status
    integer :: m
    m = size(mun)
    status = FRICREG_ESIZE
    if (.not. (is_pairs(v, m) .and. is_pairs(f, m))) return
    if (present(f_eq)) then
      if (.not. is_pairs(f_eq, m)) return
    end if
    status = fricreg_disk_eval_batch(law, eps, as_size(m), v, f_eq, mun, f)
  end function disk_eval_batch

  function stribeck_eval_scalar(eps, v, f_eq, fs, fk, vs, delta, f) result(status)
    real(c_double), intent(in) :: eps, v, f_eq, fs, fk, vs, delta
    real(c_double), intent(inout) :: f
    integer(c_int) :: status
    status = fricreg_stribeck_eval(v, f_eq, fs, fk, vs, delta, eps, f)
  end function stribeck_eval_scalar

  function stribeck_eval_array(eps, v, f_eq, fs, fk, vs, delta, f) result(status)
    real(c_double), intent(in) :: eps
    real(c_double), intent(in), contiguous :: v(:), f_eq(:), fs(:), fk(:), vs(:), delta(:)
    real(c_double), intent(inout), contiguous :: f(:)
    integer(c_int) :: status
    integer :: m
    m = size(v)
    status = FRICREG_ESIZE
    if (size(f_eq) /= m .or. size(fs) /= m .or. size(fk) /= m .or. size(vs) /= m .or. &
        size(delta) /= m .or. size(f) /= m) return
    status = fricreg_stribeck_eval_batch(eps, as_size(m), v, f_eq, fs, fk, vs, delta, f)
  end function stribeck_eval_array

  function stribeck_disk_eval_one(eps, v, f_eq, fs, fk, vs, delta, f) result(status)
    real(c_double), intent(in) :: eps, fs, fk, vs, delta
    real(c_double), intent(in), contiguous :: v(:), f_eq(:)
    real(c_double), intent(inout), contiguous :: f(:)
    integer(c_int) :: status
    status = FRICREG_ESIZE
    if (size(v) /= 2 .or. size(f_eq) /= 2 .or. size(f) /= 2) return
    status = fricreg_stribeck_disk_eval(v, f_eq, fs, fk, vs, delta, eps, f)
  end function stribeck_disk_eval_one

  function stribeck_disk_eval_batch(eps, v, f_eq, fs, fk, vs, delta, f) result(status)
    real(c_double), intent(in) :: eps
    real(c_double), intent(in), contiguous :: v(:, :), f_eq(:, :), fs(:), fk(:), vs(:), delta(:)
    real(c_double), intent(inout), contiguous :: f(:, :)
    integer(c_int) :: status
    integer :: m
    m = size(fs)
    status = FRICREG_ESIZE
    if (size(fk) /= m .or. size(vs) /= m .or. size(delta) /= m) return
    if (.not. (is_pairs(v, m) .and. is_pairs(f_eq, m) .and. &
               is_pairs(f, m))) return
    status = fricreg_stribeck_disk_eval_batch(eps, as_size(m), v, f_eq, fs, fk, vs, delta, f)
  end function stribeck_disk_eval_batch

  ! ---- Context -----------------------------------------------------------------------------

  !> Create the C context for m >= 1 contacts, with its defaults: law (4) Quinn, eps = 1e-3,
  !> mun = 1, W = I. An object that already held a context gets the new one and releases the
  !> old (on failure it keeps the old). FRICREG_EINVAL for m < 1 or m > 2**26; FRICREG_ENOMEM.
  function ctx_create(self, m) result(status)
    class(fricreg_context), intent(inout) :: self
    integer, intent(in) :: m
    integer(c_int) :: status
    type(c_ptr) :: p
    character(len=32) :: buf
    write (buf, '(i0)') m
    if (m < 1) then
      status = self%fail(FRICREG_EINVAL, 'create: m = ' // trim(buf) // ' must be >= 1')
      return
    end if
    p = c_null_ptr
    status = fricreg_ctx_create(as_size(m), p)
    if (status /= FRICREG_OK) then
      status = self%fail(status, 'create: m = ' // trim(buf) // ': ' // &
                         fricreg_error_string(status))
      return
    end if
    call self%adopt(p, fricreg_ctx_free, fricreg_ctx_errcode, fricreg_ctx_errmsg)
  end function ctx_create

  subroutine ctx_final(self)
    type(fricreg_context), intent(inout) :: self
    call self%destroy()
  end subroutine ctx_final

  !> Number of contacts m (0 if not created).
  integer function ctx_size(self)
    class(fricreg_context), intent(in) :: self
    ctx_size = int(fricreg_ctx_size(self%ptr))
  end function ctx_size

  !> Law (enum fricreg_law: FRICREG_LAW_*) and eps > 0 (velocity units).
  !> FRICREG_EINVAL for an unknown law or eps <= 0; FRICREG_ENONFINITE.
  function ctx_set_law(self, law, eps) result(status)
    class(fricreg_context), intent(inout) :: self
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps
    integer(c_int) :: status
    status = self%ready('set_law', 'context')
    if (status == FRICREG_OK) status = self%record(fricreg_ctx_set_law(self%ptr, law, eps))
  end function ctx_set_law

  !> Friction bounds mun(m) = mu_i N_i >= 0. FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function ctx_set_bounds(self, mun) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: mun(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_ctx_size(self%ptr)
    status = self%ready('set_bounds', 'context')
    if (status == FRICREG_OK) status = self%check_size('set_bounds', 'mun', size(mun), m)
    if (status == FRICREG_OK) status = self%record(fricreg_ctx_set_bounds(self%ptr, m, mun))
  end function ctx_set_bounds

  !> Static > kinetic (Stribeck) friction, C's fricreg_ctx_set_stribeck (fricreg_stribeck.h):
  !> fs(m) static bounds mu_s N, fk(m) kinetic mu_k N in [0, fs], vs(m) > 0 Stribeck
  !> velocities, delta(m) > 0 exponents; selects law (4) with the context's eps. With all four
  !> omitted it switches Stribeck friction off (C's m = 0): law (4) with the bounds of
  !> set_bounds. set_bounds, or set_law with another law, also switch it off.
  !> FRICREG_ESIZE if a given array's size is not m; FRICREG_ENULL if some, not all, are
  !> omitted; FRICREG_EINVAL (fk > fs, fk < 0, vs <= 0, delta <= 0); FRICREG_ENONFINITE.
  function ctx_set_stribeck(self, fs, fk, vs, delta) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous, optional :: fs(:), fk(:), vs(:), delta(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_ctx_size(self%ptr)
    status = self%ready('set_stribeck', 'context')
    if (status /= FRICREG_OK) return
    if (.not. (present(fs) .or. present(fk) .or. present(vs) .or. present(delta))) then
      status = self%record(fricreg_ctx_set_stribeck(self%ptr, 0_c_size_t))
      return
    end if
    if (present(fs)) status = self%check_size('set_stribeck', 'fs', size(fs), m)
    if (status == FRICREG_OK .and. present(fk)) &
      status = self%check_size('set_stribeck', 'fk', size(fk), m)
    if (status == FRICREG_OK .and. present(vs)) &
      status = self%check_size('set_stribeck', 'vs', size(vs), m)
    if (status == FRICREG_OK .and. present(delta)) &
      status = self%check_size('set_stribeck', 'delta', size(delta), m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_ctx_set_stribeck(self%ptr, m, fs, fk, vs, delta))
  end function ctx_set_stribeck

  !> Uncoupled contacts, W = diag(w), w(m) > 0 (inverse effective masses).
  function ctx_set_coupling_diagonal(self, w) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: w(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_ctx_size(self%ptr)
    status = self%ready('set_coupling_diagonal', 'context')
    if (status == FRICREG_OK) status = self%check_size('set_coupling_diagonal', 'w', size(w), m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_ctx_set_coupling_diagonal(self%ptr, m, w))
  end function ctx_set_coupling_diagonal

  !> Coupled contacts: the Delassus matrix W(m, m), symmetric positive semidefinite. C reads
  !> W row-major; W being symmetric, row-major and Fortran's column-major order hold the same
  !> numbers, so W is passed as it is (a W that is not symmetric is FRICREG_ENOTSYM, never
  !> silently transposed). Copied; FRICREG_ESIZE unless W is m x m; FRICREG_ENOTPSD;
  !> FRICREG_ENONFINITE; FRICREG_ENOMEM.
  function ctx_set_coupling_dense(self, W) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: W(:, :)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_ctx_size(self%ptr)
    status = self%ready('set_coupling_dense', 'context')
    if (status == FRICREG_OK) status = self%check_square('set_coupling_dense', 'W', W, m)
    if (status == FRICREG_OK) status = self%record(fricreg_ctx_set_coupling_dense(self%ptr, m, W))
  end function ctx_set_coupling_dense

  !> FRICREG_OK if the compressed arrays ptr(m + 1), ind and values hold the nnz = ptr(m + 1) -
  !> base entries they describe (base 1 with FRICREG_SPARSE_ONE_BASED in flags, else 0), else a
  !> recorded FRICREG_ESIZE naming the short array: C reads nnz of each, which it cannot check.
  !> A ptr(m + 1) below base is left to C (FRICREG_EINVAL).
  function ctx_check_compressed(self, what, names, flags, ptr, ind, values) result(status)
    class(fricreg_context), intent(inout) :: self
    character(len=*), intent(in) :: what, names(3)
    integer(c_int), intent(in) :: flags
    integer(c_int64_t), intent(in) :: ptr(:), ind(:)
    real(c_double), intent(in) :: values(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    integer(c_int64_t) :: nnz
    character(len=64) :: buf
    m = fricreg_ctx_size(self%ptr)
    status = self%check_size(what, names(1), size(ptr), m + 1)
    if (status /= FRICREG_OK) return
    nnz = ptr(m + 1) - merge(1_c_int64_t, 0_c_int64_t, iand(flags, FRICREG_SPARSE_ONE_BASED) /= 0)
    if (int(size(ind), c_int64_t) < nnz) then
      write (buf, '(a, i0, a, i0)') ') = ', size(ind), ', expected at least ', nnz
      status = self%fail(FRICREG_ESIZE, what // ': size(' // names(2) // trim(buf))
    else if (int(size(values), c_int64_t) < nnz) then
      write (buf, '(a, i0, a, i0)') ') = ', size(values), ', expected at least ', nnz
      status = self%fail(FRICREG_ESIZE, what // ': size(' // names(3) // trim(buf))
    end if
  end function ctx_check_compressed

  !> Coupled contacts: a sparse symmetric positive semidefinite W in compressed sparse rows
  !> (C's fricreg_ctx_set_coupling_csr): rowptr(m + 1), colind(nnz) of kind c_int64_t,
  !> values(nnz); flags from fricreg_sparse_flags (FRICREG_SPARSE_ONE_BASED for Fortran's
  !> indices, FRICREG_SPARSE_UPPER or _LOWER for one triangle). Duplicates are summed. Copied.
  !> FRICREG_ESIZE unless rowptr has m + 1 elements and colind and values at least nnz;
  !> FRICREG_EINVAL (flags, pointers, indices); FRICREG_ENONFINITE; FRICREG_ENOTSYM;
  !> FRICREG_ENOTPSD; FRICREG_ENOMEM. On failure the context keeps its coupling.
  function ctx_set_coupling_csr(self, flags, rowptr, colind, values) result(status)
    class(fricreg_context), intent(inout) :: self
    integer(c_int), intent(in) :: flags
    integer(c_int64_t), intent(in), contiguous :: rowptr(:), colind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int) :: status
    character(len=6), parameter :: names(3) = [character(len=6) :: 'rowptr', 'colind', 'values']
    status = self%ready('set_coupling_csr', 'context')
    if (status == FRICREG_OK) status = ctx_check_compressed(self, 'set_coupling_csr', &
      names, flags, rowptr, colind, values)
    if (status == FRICREG_OK) status = self%record(fricreg_ctx_set_coupling_csr(self%ptr, &
      fricreg_ctx_size(self%ptr), flags, rowptr, colind, values))
  end function ctx_set_coupling_csr

  !> Coupled contacts: a sparse W in compressed sparse columns (C's
  !> fricreg_ctx_set_coupling_csc), what a Fortran code usually holds: colptr(m + 1),
  !> rowind(nnz) of kind c_int64_t, values(nnz), flags as set_coupling_csr (one-based:
  !> FRICREG_SPARSE_ONE_BASED). W being symmetric, its CSC arrays are its CSR arrays, the
  !> upper triangle of one the lower of the other. The statuses of set_coupling_csr.
  function ctx_set_coupling_csc(self, flags, colptr, rowind, values) result(status)
    class(fricreg_context), intent(inout) :: self
    integer(c_int), intent(in) :: flags
    integer(c_int64_t), intent(in), contiguous :: colptr(:), rowind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int) :: status
    character(len=6), parameter :: names(3) = [character(len=6) :: 'colptr', 'rowind', 'values']
    status = self%ready('set_coupling_csc', 'context')
    if (status == FRICREG_OK) status = ctx_check_compressed(self, 'set_coupling_csc', &
      names, flags, colptr, rowind, values)
    if (status == FRICREG_OK) status = self%record(fricreg_ctx_set_coupling_csc(self%ptr, &
      fricreg_ctx_size(self%ptr), flags, colptr, rowind, values))
  end function ctx_set_coupling_csc

  !> How coupled contacts are partitioned: FRICREG_PARTITION_CONSISTENT (default) or
  !> FRICREG_PARTITION_PAPER (C's fricreg_ctx_set_partition). FRICREG_EINVAL if unknown.
  function ctx_set_partition(self, partition) result(status)
    class(fricreg_context), intent(inout) :: self
    integer(c_int), intent(in) :: partition
    integer(c_int) :: status
    status = self%ready('set_partition', 'context')
    if (status == FRICREG_OK) status = self%record(fricreg_ctx_set_partition(self%ptr, partition))
  end function ctx_set_partition

  !> Whether eval keeps what tangent needs (C's fricreg_ctx_set_keep_tangent): .true. (the
  !> default), or .false. for a caller that never asks for the tangent (an explicit
  !> integrator), which spares eval two stores per contact. While off, tangent returns
  !> FRICREG_EINVAL; after turning it back on, tangent works from the next successful eval.
  !> f and f_eq are the same to the bit either way. Discards the last eval's tangent.
  function ctx_set_keep_tangent(self, keep) result(status)
    class(fricreg_context), intent(inout) :: self
    logical, intent(in) :: keep
    integer(c_int) :: status
    status = self%ready('set_keep_tangent', 'context')
    if (status == FRICREG_OK) status = &
      self%record(fricreg_ctx_set_keep_tangent(self%ptr, merge(1_c_int, 0_c_int, keep)))
  end function ctx_set_keep_tangent

  !> The stick zone's stiffness lambda (1/time): a fixed explicit step dt is stable there when
  !> dt*lambda is within the stepper's real-axis bound (C's fricreg_ctx_stick_stiffness).
  !> lambda is written only on success. FRICREG_ENOMEM.
  function ctx_stick_stiffness(self, lambda) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(inout) :: lambda
    integer(c_int) :: status
    status = self%ready('stick_stiffness', 'context')
    if (status == FRICREG_OK) status = self%record(fricreg_ctx_stick_stiffness(self%ptr, lambda))
  end function ctx_stick_stiffness

  !> Friction forces f(m) of all contacts, z'' = a_free + W f, with the context's law
  !> (Sec. 3.3): zdot(m) relative velocities, a_free(m) free accelerations (with f = 0).
  !> f_eq(m), optional: f_eq on the near-stick set, NaN elsewhere. No allocation, and no copy
  !> of contiguous arrays. f and f_eq are written only on success.
  !> FRICREG_ESIZE unless every array has m elements; FRICREG_ENONFINITE; FRICREG_ESINGULAR.
  function ctx_eval(self, zdot, a_free, f, f_eq) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: zdot(:), a_free(:)
    real(c_double), intent(inout), contiguous :: f(:)
    real(c_double), intent(inout), contiguous, optional :: f_eq(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_ctx_size(self%ptr)
    status = self%ready('eval', 'context')
    if (status == FRICREG_OK) status = self%check_size('eval', 'zdot', size(zdot), m)
    if (status == FRICREG_OK) status = self%check_size('eval', 'a_free', size(a_free), m)
    if (status == FRICREG_OK) status = self%check_size('eval', 'f', size(f), m)
    if (status == FRICREG_OK .and. present(f_eq)) &
      status = self%check_size('eval', 'f_eq', size(f_eq), m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_ctx_eval(self%ptr, m, zdot, a_free, f, f_eq))
  end function ctx_eval

  !> The Jacobian of the forces of the last successful eval (C's fricreg_ctx_tangent), in
  !> Fortran's order: df_dzdot(i, j) = d f_i / d zdot_j (force per velocity) and
  !> df_dafree(i, j) = d f_i / d a_free_j (mass), each (m, m) and optional. Written only on
  !> success. FRICREG_ESIZE unless each is m x m; FRICREG_EINVAL if there is no evaluation to
  !> differentiate (none yet, or a setter since).
  function ctx_tangent(self, df_dzdot, df_dafree) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(inout), contiguous, optional :: df_dzdot(:, :), df_dafree(:, :)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_ctx_size(self%ptr)
    status = self%ready('tangent', 'context')
    if (status == FRICREG_OK .and. present(df_dzdot)) &
      status = self%check_square('tangent', 'df_dzdot', df_dzdot, m)
    if (status == FRICREG_OK .and. present(df_dafree)) &
      status = self%check_square('tangent', 'df_dafree', df_dafree, m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_ctx_tangent(self%ptr, m, df_dzdot, df_dafree))
    if (status /= FRICREG_OK) return
    if (present(df_dzdot)) call fricreg_transpose(df_dzdot, m)
    if (present(df_dafree)) call fricreg_transpose(df_dafree, m)
  end function ctx_tangent

  !> The tangent of the last successful eval times a direction (C's
  !> fricreg_ctx_tangent_apply): df(m) = (df/dzdot) dzdot + (df/da_free) dafree, without the
  !> m x m tangent (large sparse W, Newton-Krylov). dzdot(m) and dafree(m) are optional (absent:
  !> zero); df is written only on success. FRICREG_ESIZE unless every array has m elements;
  !> FRICREG_ENONFINITE (a direction not finite, or df beyond double's range); FRICREG_EINVAL
  !> if there is no evaluation to differentiate.
  function ctx_tangent_apply(self, dzdot, dafree, df) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous, optional :: dzdot(:), dafree(:)
    real(c_double), intent(inout), contiguous :: df(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_ctx_size(self%ptr)
    status = self%ready('tangent_apply', 'context')
    if (status == FRICREG_OK .and. present(dzdot)) &
      status = self%check_size('tangent_apply', 'dzdot', size(dzdot), m)
    if (status == FRICREG_OK .and. present(dafree)) &
      status = self%check_size('tangent_apply', 'dafree', size(dafree), m)
    if (status == FRICREG_OK) status = self%check_size('tangent_apply', 'df', size(df), m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_ctx_tangent_apply(self%ptr, m, dzdot, dafree, df))
  end function ctx_tangent_apply

#ifdef FRICREG_HAVE_SIM
  !> The forces of one implicit step of the caller's own integrator (C's fricreg_ctx_solve_step,
  !> fricreg_structure.h): Newton with the stick guess, the stop at zdot = 0 and the line
  !> search on G(f) = f - F(zdot(f), a_free(f)), zdot(f) = zdot_pred + c Weff f and
  !> a_free(f) = a_pred - (W - Weff) f. W(m, m) = J M^-1 J^T and Weff(m, m) = J K_eff^-1 J^T
  !> are symmetric, so Fortran's arrays are passed as they are. f(m) in: the guess, out: the
  !> forces; iterations and converged (optional) say how it went. flags: 0 (default) or
  !> FRICREG_STEP_PLAIN. FRICREG_ESIZE unless every array has m (or m x m) elements; the C
  !> function's codes otherwise (not converging is FRICREG_OK with converged false).
  function ctx_solve_step(self, zdot_start, zdot_pred, a_pred, W, Weff, c, tol, max_iter, f, &
                          iterations, converged, flags) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: zdot_start(:), zdot_pred(:), a_pred(:)
    real(c_double), intent(in), contiguous :: W(:, :), Weff(:, :)
    real(c_double), intent(in) :: c, tol
    integer, intent(in) :: max_iter
    real(c_double), intent(inout), contiguous :: f(:)
    integer, intent(out), optional :: iterations
    logical, intent(out), optional :: converged
    integer, intent(in), optional :: flags
    integer(c_int) :: status, info(2), how
    integer(c_size_t) :: m
    m = fricreg_ctx_size(self%ptr)
    how = 0
    if (present(flags)) how = int(flags, c_int)
    status = self%ready('solve_step', 'context')
    if (status == FRICREG_OK) status = self%check_size('solve_step', 'zdot_start', size(zdot_start), m)
    if (status == FRICREG_OK) status = self%check_size('solve_step', 'zdot_pred', size(zdot_pred), m)
    if (status == FRICREG_OK) status = self%check_size('solve_step', 'a_pred', size(a_pred), m)
    if (status == FRICREG_OK) status = self%check_square('solve_step', 'W', W, m)
    if (status == FRICREG_OK) status = self%check_square('solve_step', 'Weff', Weff, m)
    if (status == FRICREG_OK) status = self%check_size('solve_step', 'f', size(f), m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_ctx_solve_step(self%ptr, m, zdot_start, zdot_pred, a_pred, &
                                                  W, Weff, c, tol, int(max_iter, c_int), how, &
                                                  f, info))
    if (status /= FRICREG_OK) return
    if (present(iterations)) iterations = int(info(1))
    if (present(converged)) converged = info(2) /= 0
  end function ctx_solve_step

  !> solve_step with W and Weff in compressed sparse rows (C's fricreg_ctx_solve_step_csr):
  !> O(nnz) per call where the dense one reads m x m arrays; the same forces on the same
  !> matrices. sparse_flags from fricreg_sparse_flags for both (FRICREG_SPARSE_ONE_BASED for
  !> Fortran's indices, _UPPER or _LOWER for one triangle); w_rowptr(m + 1), w_colind(nnz),
  !> w_values(nnz) and weff_rowptr(m + 1), weff_colind(nnz_eff), weff_values(nnz_eff), the
  !> indices of kind c_int64_t. A later call with the same index arrays reuses the step's
  !> solver. The other arguments and the statuses as solve_step's; FRICREG_ESIZE unless the
  !> pointer arrays have m + 1 elements and the others at least nnz; FRICREG_EINVAL (flags,
  !> pointers, indices) as set_coupling_csr.
  function ctx_solve_step_csr(self, zdot_start, zdot_pred, a_pred, sparse_flags, w_rowptr, &
                              w_colind, w_values, weff_rowptr, weff_colind, weff_values, c, &
                              tol, max_iter, f, iterations, converged, flags) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: zdot_start(:), zdot_pred(:), a_pred(:)
    integer(c_int), intent(in) :: sparse_flags
    integer(c_int64_t), intent(in), contiguous :: w_rowptr(:), w_colind(:), weff_rowptr(:), &
                                                  weff_colind(:)
    real(c_double), intent(in), contiguous :: w_values(:), weff_values(:)
    real(c_double), intent(in) :: c, tol
    integer, intent(in) :: max_iter
    real(c_double), intent(inout), contiguous :: f(:)
    integer, intent(out), optional :: iterations
    logical, intent(out), optional :: converged
    integer, intent(in), optional :: flags
    integer(c_int) :: status
    status = ctx_solve_step_compressed(self, .false., zdot_start, zdot_pred, a_pred, &
                                       sparse_flags, w_rowptr, w_colind, w_values, &
                                       weff_rowptr, weff_colind, weff_values, c, tol, &
                                       max_iter, f, iterations, converged, flags)
  end function ctx_solve_step_csr

  !> solve_step with W and Weff in compressed sparse columns (C's fricreg_ctx_solve_step_csc),
  !> what a Fortran code usually holds: w_colptr(m + 1), w_rowind(nnz), w_values(nnz) and the
  !> same for Weff; being symmetric, their CSC arrays are their CSR arrays, the upper triangle
  !> of one the lower of the other. Arguments and statuses as solve_step_csr's.
  function ctx_solve_step_csc(self, zdot_start, zdot_pred, a_pred, sparse_flags, w_colptr, &
                              w_rowind, w_values, weff_colptr, weff_rowind, weff_values, c, &
                              tol, max_iter, f, iterations, converged, flags) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: zdot_start(:), zdot_pred(:), a_pred(:)
    integer(c_int), intent(in) :: sparse_flags
    integer(c_int64_t), intent(in), contiguous :: w_colptr(:), w_rowind(:), weff_colptr(:), &
                                                  weff_rowind(:)
    real(c_double), intent(in), contiguous :: w_values(:), weff_values(:)
    real(c_double), intent(in) :: c, tol
    integer, intent(in) :: max_iter
    real(c_double), intent(inout), contiguous :: f(:)
    integer, intent(out), optional :: iterations
    logical, intent(out), optional :: converged
    integer, intent(in), optional :: flags
    integer(c_int) :: status
    status = ctx_solve_step_compressed(self, .true., zdot_start, zdot_pred, a_pred, &
                                       sparse_flags, w_colptr, w_rowind, w_values, &
                                       weff_colptr, weff_rowind, weff_values, c, tol, &
                                       max_iter, f, iterations, converged, flags)
  end function ctx_solve_step_csc

  !> The two above: the shapes checked (ctx_check_compressed, as the coupling setters'), then
  !> the C call by rows or by columns.
  function ctx_solve_step_compressed(self, by_columns, zdot_start, zdot_pred, a_pred, &
                                     sparse_flags, w_ptr, w_ind, w_values, weff_ptr, weff_ind, &
                                     weff_values, c, tol, max_iter, f, iterations, converged, &
                                     flags) result(status)
    class(fricreg_context), intent(inout) :: self
    logical, intent(in) :: by_columns
    real(c_double), intent(in), contiguous :: zdot_start(:), zdot_pred(:), a_pred(:)
    integer(c_int), intent(in) :: sparse_flags
    integer(c_int64_t), intent(in), contiguous :: w_ptr(:), w_ind(:), weff_ptr(:), weff_ind(:)
    real(c_double), intent(in), contiguous :: w_values(:), weff_values(:)
    real(c_double), intent(in) :: c, tol
    integer, intent(in) :: max_iter
    real(c_double), intent(inout), contiguous :: f(:)
    integer, intent(out), optional :: iterations
    logical, intent(out), optional :: converged
    integer, intent(in), optional :: flags
    integer(c_int) :: status, info(2), how
    integer(c_size_t) :: m
    character(len=14) :: what
    character(len=11) :: wnames(3), enames(3)
    if (by_columns) then
      what = 'solve_step_csc'
      wnames = [character(len=11) :: 'w_colptr', 'w_rowind', 'w_values']
      enames = [character(len=11) :: 'weff_colptr', 'weff_rowind', 'weff_values']
    else
      what = 'solve_step_csr'
      wnames = [character(len=11) :: 'w_rowptr', 'w_colind', 'w_values']
      enames = [character(len=11) :: 'weff_rowptr', 'weff_colind', 'weff_values']
    end if
    m = fricreg_ctx_size(self%ptr)
    how = 0
    if (present(flags)) how = int(flags, c_int)
    status = self%ready(what, 'context')
    if (status == FRICREG_OK) status = self%check_size(what, 'zdot_start', size(zdot_start), m)
    if (status == FRICREG_OK) status = self%check_size(what, 'zdot_pred', size(zdot_pred), m)
    if (status == FRICREG_OK) status = self%check_size(what, 'a_pred', size(a_pred), m)
    if (status == FRICREG_OK) status = self%check_size(what, 'f', size(f), m)
    if (status == FRICREG_OK) status = ctx_check_compressed(self, what, wnames, sparse_flags, &
                                                            w_ptr, w_ind, w_values)
    if (status == FRICREG_OK) status = ctx_check_compressed(self, what, enames, sparse_flags, &
                                                            weff_ptr, weff_ind, weff_values)
    if (status /= FRICREG_OK) return
    if (by_columns) then
      status = self%record(fricreg_ctx_solve_step_csc(self%ptr, m, zdot_start, zdot_pred, &
                           a_pred, sparse_flags, w_ptr, w_ind, w_values, weff_ptr, weff_ind, &
                           weff_values, c, tol, int(max_iter, c_int), how, f, info))
    else
      status = self%record(fricreg_ctx_solve_step_csr(self%ptr, m, zdot_start, zdot_pred, &
                           a_pred, sparse_flags, w_ptr, w_ind, w_values, weff_ptr, weff_ind, &
                           weff_values, c, tol, int(max_iter, c_int), how, f, info))
    end if
    if (status /= FRICREG_OK) return
    if (present(iterations)) iterations = int(info(1))
    if (present(converged)) converged = info(2) /= 0
  end function ctx_solve_step_compressed
#endif

  !> The switching functions (C's fricreg_ctx_switching): g(k + 1, i) is component k
  !> (FRICREG_SWITCH_BAND_HI ... FRICREG_SWITCH_SAT_LO) of contact i, a signed distance to a
  !> kink of its law, +1 where the law has no such kink; g is (FRICREG_SWITCH_PER_CONTACT, m).
  !> zdot(m) and a_free(m) as for eval; f(m) the forces eval gave there, read only with a
  !> coupled W and a law that reads f_eq (optional otherwise). g is written only on success.
  !> FRICREG_ESIZE unless the arrays have those shapes; FRICREG_ENULL if f is needed and
  !> absent; FRICREG_ENONFINITE.
  function ctx_switching(self, zdot, a_free, g, f) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: zdot(:), a_free(:)
    real(c_double), intent(inout), contiguous :: g(:, :)
    real(c_double), intent(in), contiguous, optional :: f(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_ctx_size(self%ptr)
    status = self%ready('switching', 'context')
    if (status == FRICREG_OK) status = self%check_size('switching', 'zdot', size(zdot), m)
    if (status == FRICREG_OK) status = self%check_size('switching', 'a_free', size(a_free), m)
    if (status == FRICREG_OK .and. present(f)) &
      status = self%check_size('switching', 'f', size(f), m)
    if (status == FRICREG_OK) status = self%check_size('switching', 'g, 1', size(g, 1), &
                                                       int(FRICREG_SWITCH_PER_CONTACT, c_size_t))
    if (status == FRICREG_OK) status = self%check_size('switching', 'g, 2', size(g, 2), m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_ctx_switching(self%ptr, m, zdot, a_free, f, g, &
                                                 int(size(g), c_size_t)))
  end function ctx_switching

  !> The number of switching functions, FRICREG_SWITCH_PER_CONTACT * m (0 before create).
  integer function ctx_switching_count(self)
    class(fricreg_context), intent(in) :: self
    ctx_switching_count = int(fricreg_ctx_switching_count(self%ptr))
  end function ctx_switching_count

  !> One counter (FRICREG_STAT_*) into value. FRICREG_EINVAL for an unknown counter.
  function ctx_get_stat(self, which, value) result(status)
    class(fricreg_context), intent(inout) :: self
    integer(c_int), intent(in) :: which
    integer(c_int64_t), intent(inout) :: value
    integer(c_int) :: status
    status = self%ready('get_stat', 'context')
    if (status == FRICREG_OK) &
      status = self%unrecorded('get_stat', fricreg_ctx_get_stat(self%ptr, which, value))
  end function ctx_get_stat

  subroutine ctx_reset_stats(self)
    class(fricreg_context), intent(inout) :: self
    call fricreg_ctx_reset_stats(self%ptr) ! does nothing on NULL
  end subroutine ctx_reset_stats

  ! ---- 2-D contexts (fricreg_disk_ctx.h) ----------------------------------------------------

  !> Create the C context for m >= 1 two-dimensional contacts, with its defaults (law
  !> FRICREG_DISK_QUINN, eps = 1e-3, mun = 1, W = I). An object that held one gets the new one
  !> and releases the old (on failure it keeps the old). FRICREG_EINVAL for m < 1 or too large;
  !> FRICREG_ENOMEM.
  function dctx_create(self, m) result(status)
    class(fricreg_disk_context), intent(inout) :: self
    integer, intent(in) :: m
    integer(c_int) :: status
    type(c_ptr) :: p
    character(len=32) :: buf
    write (buf, '(i0)') m
    if (m < 1) then
      status = self%fail(FRICREG_EINVAL, 'create: m = ' // trim(buf) // ' must be >= 1')
      return
    end if
    p = c_null_ptr
    status = fricreg_disk_ctx_create(as_size(m), p)
    if (status /= FRICREG_OK) then
      status = self%fail(status, 'create: m = ' // trim(buf) // ': ' // &
                         fricreg_error_string(status))
      return
    end if
    call self%adopt(p, fricreg_disk_ctx_free, fricreg_disk_ctx_errcode, fricreg_disk_ctx_errmsg)
  end function dctx_create

  subroutine dctx_final(self)
    type(fricreg_disk_context), intent(inout) :: self
    call self%destroy()
  end subroutine dctx_final

  !> Number of contacts m (0 if not created).
  integer function dctx_size(self)
    class(fricreg_disk_context), intent(in) :: self
    dctx_size = int(fricreg_disk_ctx_size(self%ptr))
  end function dctx_size

  !> Law (FRICREG_DISK_QUINN or FRICREG_DISK_FORCE_BALANCE) and eps (velocity units).
  !> FRICREG_EINVAL for another law or eps out of [DBL_MIN, 1e250]; FRICREG_ENONFINITE.
  function dctx_set_law(self, law, eps) result(status)
    class(fricreg_disk_context), intent(inout) :: self
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps
    integer(c_int) :: status
    status = self%ready('set_law', 'context')
    if (status == FRICREG_OK) status = self%record(fricreg_disk_ctx_set_law(self%ptr, law, eps))
  end function dctx_set_law

  !> Friction bounds mun(m). FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function dctx_set_bounds(self, mun) result(status)
    class(fricreg_disk_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: mun(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_disk_ctx_size(self%ptr)
    status = self%ready('set_bounds', 'context')
    if (status == FRICREG_OK) status = self%check_size('set_bounds', 'mun', size(mun), m)
    if (status == FRICREG_OK) status = self%record(fricreg_disk_ctx_set_bounds(self%ptr, m, mun))
  end function dctx_set_bounds

  !> Static > kinetic (Stribeck) friction, C's fricreg_disk_ctx_set_stribeck
  !> (fricreg_stribeck.h): fs(m) static bounds mu_s N (at most 1e250), fk(m) kinetic mu_k N in
  !> [0, fs], vs(m) > 0 Stribeck velocities, delta(m) > 0 exponents; selects FRICREG_DISK_QUINN
  !> with the context's eps. With all four omitted it switches Stribeck friction off (C's
  !> m = 0): the bounds of set_bounds. set_bounds, or set_law with the force balance, also
  !> switch it off. FRICREG_ESIZE if a given array's size is not m; FRICREG_ENULL if some, not
  !> all, are omitted; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function dctx_set_stribeck(self, fs, fk, vs, delta) result(status)
    class(fricreg_disk_context), intent(inout) :: self
    real(c_double), intent(in), contiguous, optional :: fs(:), fk(:), vs(:), delta(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_disk_ctx_size(self%ptr)
    status = self%ready('set_stribeck', 'context')
    if (status /= FRICREG_OK) return
    if (.not. (present(fs) .or. present(fk) .or. present(vs) .or. present(delta))) then
      status = self%record(fricreg_disk_ctx_set_stribeck(self%ptr, 0_c_size_t))
      return
    end if
    if (present(fs)) status = self%check_size('set_stribeck', 'fs', size(fs), m)
    if (status == FRICREG_OK .and. present(fk)) &
      status = self%check_size('set_stribeck', 'fk', size(fk), m)
    if (status == FRICREG_OK .and. present(vs)) &
      status = self%check_size('set_stribeck', 'vs', size(vs), m)
    if (status == FRICREG_OK .and. present(delta)) &
      status = self%check_size('set_stribeck', 'delta', size(delta), m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_disk_ctx_set_stribeck(self%ptr, m, fs, fk, vs, delta))
  end function dctx_set_stribeck

  !> Block diagonal W: w(2, 2, m), w(:, :, i) contact i's symmetric positive definite block
  !> (symmetric, so Fortran's order is C's; a block that is not is FRICREG_ENOTSYM).
  !> FRICREG_ESIZE unless w is (2, 2, m); FRICREG_ENOTPSD; FRICREG_ENONFINITE.
  function dctx_set_coupling_blocks(self, w) result(status)
    class(fricreg_disk_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: w(:, :, :)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_disk_ctx_size(self%ptr)
    status = self%ready('set_coupling_blocks', 'context')
    if (status == FRICREG_OK .and. (size(w, 1) /= 2 .or. size(w, 2) /= 2)) &
      status = self%fail(FRICREG_ESIZE, 'set_coupling_blocks: w must be (2, 2, m)')
    if (status == FRICREG_OK) status = self%check_size('set_coupling_blocks', 'w, 3', &
                                                        size(w, 3), m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_disk_ctx_set_coupling_blocks(self%ptr, m, w))
  end function dctx_set_coupling_blocks

  !> Coupled contacts: W(2m, 2m), symmetric positive semidefinite with positive definite 2x2
  !> diagonal blocks, contact i at rows and columns 2i-1, 2i (symmetric: passed as it is).
  !> FRICREG_ESIZE unless 2m x 2m; FRICREG_ENOTSYM; FRICREG_ENOTPSD; FRICREG_ENONFINITE.
  function dctx_set_coupling_dense(self, W) result(status)
    class(fricreg_disk_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: W(:, :)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_disk_ctx_size(self%ptr)
    status = self%ready('set_coupling_dense', 'context')
    if (status == FRICREG_OK) status = self%check_square('set_coupling_dense', 'W', W, 2 * m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_disk_ctx_set_coupling_dense(self%ptr, m, W))
  end function dctx_set_coupling_dense

  !> Sparse W of order 2m (C's fricreg_disk_ctx_set_coupling_csr): flags (FRICREG_SPARSE_*:
  !> FRICREG_SPARSE_ONE_BASED for Fortran's indices, a triangle), rowptr(2m + 1), colind and
  !> values (at least nnz = rowptr(2m + 1) - base each), indices integer(c_int64_t).
  !> FRICREG_ESIZE unless rowptr is 2m + 1 long and colind and values hold nnz; then C's
  !> statuses (FRICREG_EINVAL, FRICREG_ENONFINITE, FRICREG_ENOTSYM, FRICREG_ENOTPSD, ...).
  function dctx_set_coupling_csr(self, flags, rowptr, colind, values) result(status)
    class(fricreg_disk_context), intent(inout) :: self
    integer(c_int), intent(in) :: flags
    integer(c_int64_t), intent(in), contiguous :: rowptr(:), colind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_disk_ctx_size(self%ptr)
    status = self%check_compressed('set_coupling_csr', 'rowptr', 'colind', flags, rowptr, &
                                   size(colind), size(values))
    if (status == FRICREG_OK) status = self%record(fricreg_disk_ctx_set_coupling_csr( &
                                                   self%ptr, m, flags, rowptr, colind, values))
  end function dctx_set_coupling_csr

  !> Sparse W by compressed columns (C's fricreg_disk_ctx_set_coupling_csc): as
  !> set_coupling_csr with colptr(2m + 1) and rowind.
  function dctx_set_coupling_csc(self, flags, colptr, rowind, values) result(status)
    class(fricreg_disk_context), intent(inout) :: self
    integer(c_int), intent(in) :: flags
    integer(c_int64_t), intent(in), contiguous :: colptr(:), rowind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_disk_ctx_size(self%ptr)
    status = self%check_compressed('set_coupling_csc', 'colptr', 'rowind', flags, colptr, &
                                   size(rowind), size(values))
    if (status == FRICREG_OK) status = self%record(fricreg_disk_ctx_set_coupling_csc( &
                                                   self%ptr, m, flags, colptr, rowind, values))
  end function dctx_set_coupling_csc

  !> The Fortran side's checks of a compressed W: a created context, ptr(2m + 1), and index and
  !> value arrays that hold the nnz entries ptr says (C reads that many; a ptr that C refuses
  !> is left to C).
  function check_compressed(self, what, ptr_name, ind_name, flags, ptr, nind, nval) result(status)
    class(fricreg_disk_context), intent(inout) :: self
    character(len=*), intent(in) :: what, ptr_name, ind_name
    integer(c_int), intent(in) :: flags
    integer(c_int64_t), intent(in) :: ptr(:)
    integer, intent(in) :: nind, nval
    integer(c_int) :: status
    integer(c_int64_t) :: nnz
    character(len=96) :: buf
    status = self%ready(what, 'context')
    if (status == FRICREG_OK) &
      status = self%check_size(what, ptr_name, size(ptr), 2 * fricreg_disk_ctx_size(self%ptr) + 1)
    if (status /= FRICREG_OK) return
    nnz = ptr(size(ptr)) - merge(1_c_int64_t, 0_c_int64_t, iand(flags, FRICREG_SPARSE_ONE_BASED) /= 0)
    if (nnz > int(min(nind, nval), c_int64_t)) then
      write (buf, '(a, i0, a, i0, a, i0)') ': ', nnz, ' entries, size(' // ind_name // ') = ', &
        nind, ', size(values) = ', nval
      status = self%fail(FRICREG_ESIZE, what // trim(buf))
    end if
  end function check_compressed

  !> Friction forces f(2, m) from zdot(2, m) and a_free(2, m) (C's fricreg_disk_ctx_eval).
  !> f is written only on success. FRICREG_ESIZE unless each is (2, m); FRICREG_ENONFINITE;
  !> FRICREG_EINVAL; FRICREG_ESINGULAR.
  function dctx_eval(self, zdot, a_free, f) result(status)
    class(fricreg_disk_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: zdot(:, :), a_free(:, :)
    real(c_double), intent(inout), contiguous :: f(:, :)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_disk_ctx_size(self%ptr)
    status = self%ready('eval', 'context')
    if (status == FRICREG_OK .and. .not. (is_pairs(zdot, int(m)) .and. &
        is_pairs(a_free, int(m)) .and. is_pairs(f, int(m)))) &
      status = self%fail(FRICREG_ESIZE, 'eval: zdot, a_free and f must be (2, m)')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_disk_ctx_eval(self%ptr, m, zdot, a_free, f))
  end function dctx_eval

  !> The Jacobian of the last successful eval's forces in Fortran's order, (2m, 2m) each and
  !> optional: df_dzdot(2i-1+a, 2j-1+b) = d f(1+a, i) / d zdot(1+b, j), likewise df_dafree.
  !> Written only on success. FRICREG_ESIZE; FRICREG_EINVAL (no evaluation to differentiate);
  !> FRICREG_ESINGULAR; FRICREG_ENONFINITE.
  function dctx_tangent(self, df_dzdot, df_dafree) result(status)
    class(fricreg_disk_context), intent(inout) :: self
    real(c_double), intent(inout), contiguous, optional :: df_dzdot(:, :), df_dafree(:, :)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_disk_ctx_size(self%ptr)
    status = self%ready('tangent', 'context')
    if (status == FRICREG_OK .and. present(df_dzdot)) &
      status = self%check_square('tangent', 'df_dzdot', df_dzdot, 2 * m)
    if (status == FRICREG_OK .and. present(df_dafree)) &
      status = self%check_square('tangent', 'df_dafree', df_dafree, 2 * m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_disk_ctx_tangent(self%ptr, m, df_dzdot, df_dafree))
    if (status /= FRICREG_OK) return
    if (present(df_dzdot)) call fricreg_transpose(df_dzdot, 2 * m)
    if (present(df_dafree)) call fricreg_transpose(df_dafree, 2 * m)
  end function dctx_tangent

  ! ---- Jenkins elements (fricreg_jenkins.h) ------------------------------------------------

  !> Create n >= 1 Jenkins elements of dimension dim (1 or 2), with kt = mun = 1 and the
  !> sliders at 0. An object that held some gets the new ones and releases the old (on failure
  !> it keeps the old). FRICREG_EINVAL for dim not 1 or 2, or n < 1; FRICREG_ENOMEM.
  function jk_create(self, dim, n) result(status)
    class(fricreg_jenkins_elements), intent(inout) :: self
    integer, intent(in) :: dim, n
    integer(c_int) :: status
    type(c_ptr) :: p
    character(len=64) :: buf
    write (buf, '(a, i0, a, i0)') 'create: dim = ', dim, ', n = ', n
    if (n < 1) then
      status = self%fail(FRICREG_EINVAL, trim(buf) // ': n must be >= 1')
      return
    end if
    p = c_null_ptr
    status = fricreg_jenkins_create(int(dim, c_int), as_size(n), p)
    if (status /= FRICREG_OK) then
      status = self%fail(status, trim(buf) // ': ' // fricreg_error_string(status))
      return
    end if
    call self%adopt(p, fricreg_jenkins_free, fricreg_jenkins_errcode, fricreg_jenkins_errmsg)
  end function jk_create

  subroutine jk_final(self)
    type(fricreg_jenkins_elements), intent(inout) :: self
    call self%destroy()
  end subroutine jk_final

  !> Number of elements n (0 if not created).
  integer function jk_size(self)
    class(fricreg_jenkins_elements), intent(in) :: self
    jk_size = int(fricreg_jenkins_size(self%ptr))
  end function jk_size

  !> Dimension of the elements, 1 or 2 (0 if not created).
  integer function jk_dim(self)
    class(fricreg_jenkins_elements), intent(in) :: self
    jk_dim = int(fricreg_jenkins_dim(self%ptr))
  end function jk_dim

  !> Whether a is (dim, n) for the object's dim and n.
  logical function jk_shaped(self, a)
    class(fricreg_jenkins_elements), intent(in) :: self
    real(c_double), intent(in) :: a(:, :)
    integer :: d, n
    d = self%dim()
    n = self%size()
    jk_shaped = size(a, 1) == d .and. size(a, 2) == n
  end function jk_shaped

  !> Stiffnesses kt(n) > 0 and slip bounds mun(n) >= 0 (a pending trial is discarded).
  !> FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function jk_set_params(self, kt, mun) result(status)
    class(fricreg_jenkins_elements), intent(inout) :: self
    real(c_double), intent(in), contiguous :: kt(:), mun(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    n = fricreg_jenkins_size(self%ptr)
    status = self%ready('set_params', 'Jenkins elements')
    if (status == FRICREG_OK) status = self%check_size('set_params', 'kt', size(kt), n)
    if (status == FRICREG_OK) status = self%check_size('set_params', 'mun', size(mun), n)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_jenkins_set_params(self%ptr, n, kt, mun))
  end function jk_set_params

  !> Trial forces f(dim, n) at displacements u(dim, n) from the committed sliders, and, if
  !> present, the consistent tangents dfdu(dim, dim, n); the committed state does not change.
  !> Written only on success. FRICREG_ESIZE; FRICREG_ENONFINITE.
  function jk_trial(self, u, f, dfdu) result(status)
    class(fricreg_jenkins_elements), intent(inout) :: self
    real(c_double), intent(in), contiguous :: u(:, :)
    real(c_double), intent(inout), contiguous :: f(:, :)
    real(c_double), intent(inout), contiguous, optional :: dfdu(:, :, :)
    integer(c_int) :: status
    integer(c_size_t) :: n
    integer :: d
    n = fricreg_jenkins_size(self%ptr)
    status = self%ready('trial', 'Jenkins elements')
    if (status == FRICREG_OK .and. .not. (jk_shaped(self, u) .and. jk_shaped(self, f))) &
      status = self%fail(FRICREG_ESIZE, 'trial: u and f must be (dim, n)')
    if (status == FRICREG_OK .and. present(dfdu)) then
      d = self%dim()
      if (size(dfdu, 1) /= d .or. size(dfdu, 2) /= d .or. &
          size(dfdu, 3) /= int(n)) &
        status = self%fail(FRICREG_ESIZE, 'trial: dfdu must be (dim, dim, n)')
    end if
    if (status == FRICREG_OK) status = self%record(fricreg_jenkins_trial(self%ptr, n, u, f, dfdu))
  end function jk_trial

  !> Normal laws: friction coefficients mu(n) >= 0, preloads n0(n) (negative: open at g = 0)
  !> and normal stiffnesses kn(n) >= 0; the bound is mu max(0, n0 + kn g). kt is kept.
  !> FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function jk_set_normal(self, mu, n0, kn) result(status)
    class(fricreg_jenkins_elements), intent(inout) :: self
    real(c_double), intent(in), contiguous :: mu(:), n0(:), kn(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    n = fricreg_jenkins_size(self%ptr)
    status = self%ready('set_normal', 'Jenkins elements')
    if (status == FRICREG_OK) status = self%check_size('set_normal', 'mu', size(mu), n)
    if (status == FRICREG_OK) status = self%check_size('set_normal', 'n0', size(n0), n)
    if (status == FRICREG_OK) status = self%check_size('set_normal', 'kn', size(kn), n)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_jenkins_set_normal(self%ptr, n, mu, n0, kn))
  end function jk_set_normal

  !> Trial forces f(dim, n) at tangential displacements u(dim, n) and normal displacements
  !> g(n) (positive pressing), with lift-off; if present, the normal forces nf(n), the tangents
  !> dfdu(dim, dim, n) and df/dg dfdg(dim, n). Written only on success. FRICREG_ESIZE;
  !> FRICREG_ENONFINITE.
  function jk_trial_normal(self, u, g, f, nf, dfdu, dfdg) result(status)
    class(fricreg_jenkins_elements), intent(inout) :: self
    real(c_double), intent(in), contiguous :: u(:, :), g(:)
    real(c_double), intent(inout), contiguous :: f(:, :)
    real(c_double), intent(inout), contiguous, optional :: nf(:), dfdu(:, :, :), dfdg(:, :)
    integer(c_int) :: status
    integer(c_size_t) :: n
    integer :: nd, ne
    n = fricreg_jenkins_size(self%ptr)
    nd = self%dim()
    ne = self%size()
    status = self%ready('trial_normal', 'Jenkins elements')
    if (status == FRICREG_OK .and. .not. (jk_shaped(self, u) .and. jk_shaped(self, f))) &
      status = self%fail(FRICREG_ESIZE, 'trial_normal: u and f must be (dim, n)')
    if (status == FRICREG_OK) status = self%check_size('trial_normal', 'g', size(g), n)
    if (status == FRICREG_OK .and. present(nf)) &
      status = self%check_size('trial_normal', 'nf', size(nf), n)
    if (status == FRICREG_OK .and. present(dfdu)) then
      if (size(dfdu, 1) /= nd .or. size(dfdu, 2) /= nd .or. size(dfdu, 3) /= ne) &
        status = self%fail(FRICREG_ESIZE, 'trial_normal: dfdu must be (dim, dim, n)')
    end if
    if (status == FRICREG_OK .and. present(dfdg)) then
      if (.not. jk_shaped(self, dfdg)) &
        status = self%fail(FRICREG_ESIZE, 'trial_normal: dfdg must be (dim, n)')
    end if
    if (status == FRICREG_OK) status = self%record( &
      fricreg_jenkins_trial_normal(self%ptr, n, u, g, f, nf, dfdu, dfdg))
  end function jk_trial_normal

  !> The last trial's sliders become the committed state.
  function jk_commit(self) result(status)
    class(fricreg_jenkins_elements), intent(inout) :: self
    integer(c_int) :: status
    status = self%ready('commit', 'Jenkins elements')
    if (status == FRICREG_OK) status = self%record(fricreg_jenkins_commit(self%ptr))
  end function jk_commit

  !> Every slider back at 0, committed and trial; kt and mun kept.
  function jk_reset(self) result(status)
    class(fricreg_jenkins_elements), intent(inout) :: self
    integer(c_int) :: status
    status = self%ready('reset', 'Jenkins elements')
    if (status == FRICREG_OK) status = self%record(fricreg_jenkins_reset(self%ptr))
  end function jk_reset

  !> The committed slider positions w(dim, n). FRICREG_ESIZE.
  function jk_get_slider(self, w) result(status)
    class(fricreg_jenkins_elements), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: w(:, :)
    integer(c_int) :: status
    status = self%ready('get_slider', 'Jenkins elements')
    if (status == FRICREG_OK .and. .not. jk_shaped(self, w)) &
      status = self%fail(FRICREG_ESIZE, 'get_slider: w must be (dim, n)')
    if (status == FRICREG_OK) status = self%record( &
      fricreg_jenkins_get_slider(self%ptr, fricreg_jenkins_size(self%ptr), w))
  end function jk_get_slider

  ! ---- Iwan elements (fricreg_iwan.h) ------------------------------------------------------

  !> Create n >= 1 Iwan elements of ns >= 1 sliders, dimension dim (1 or 2), each slider
  !> k = phi = 1/ns, no normal law, the sliders at 0. An object that held some gets the new ones
  !> and releases the old (on failure it keeps the old). FRICREG_EINVAL for dim not 1 or 2,
  !> n < 1 or ns < 1; FRICREG_ENOMEM.
  function iw_create(self, dim, n, ns) result(status)
    class(fricreg_iwan_elements), intent(inout) :: self
    integer, intent(in) :: dim, n, ns
    integer(c_int) :: status
    type(c_ptr) :: p
    character(len=80) :: buf
    write (buf, '(a, i0, a, i0, a, i0)') 'create: dim = ', dim, ', n = ', n, ', ns = ', ns
    if (n < 1 .or. ns < 1) then
      status = self%fail(FRICREG_EINVAL, trim(buf) // ': n and ns must be >= 1')
      return
    end if
    p = c_null_ptr
    status = fricreg_iwan_create(int(dim, c_int), as_size(n), as_size(ns), p)
    if (status /= FRICREG_OK) then
      status = self%fail(status, trim(buf) // ': ' // fricreg_error_string(status))
      return
    end if
    call self%adopt(p, fricreg_iwan_free, fricreg_iwan_errcode, fricreg_iwan_errmsg)
  end function iw_create

  subroutine iw_final(self)
    type(fricreg_iwan_elements), intent(inout) :: self
    call self%destroy()
  end subroutine iw_final

  !> Number of elements n (0 if not created).
  integer function iw_size(self)
    class(fricreg_iwan_elements), intent(in) :: self
    iw_size = int(fricreg_iwan_size(self%ptr))
  end function iw_size

  !> Sliders per element ns (0 if not created).
  integer function iw_sliders(self)
    class(fricreg_iwan_elements), intent(in) :: self
    iw_sliders = int(fricreg_iwan_sliders(self%ptr))
  end function iw_sliders

  !> Dimension of the elements, 1 or 2 (0 if not created).
  integer function iw_dim(self)
    class(fricreg_iwan_elements), intent(in) :: self
    iw_dim = int(fricreg_iwan_dim(self%ptr))
  end function iw_dim

  !> Whether a is (rows, cols).
  pure logical function iw_shaped(a, rows, cols)
    real(c_double), intent(in) :: a(:, :)
    integer, intent(in) :: rows, cols
    iw_shaped = size(a, 1) == rows .and. size(a, 2) == cols
  end function iw_shaped

  !> Slider stiffnesses k(ns, n) > 0 and slip forces phi(ns, n) >= 0 (a pending trial is
  !> discarded). FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function iw_set_params(self, k, phi) result(status)
    class(fricreg_iwan_elements), intent(inout) :: self
    real(c_double), intent(in), contiguous :: k(:, :), phi(:, :)
    integer(c_int) :: status
    integer :: ns, ne
    ns = self%sliders()
    ne = self%size()
    status = self%ready('set_params', 'Iwan elements')
    if (status == FRICREG_OK .and. .not. (iw_shaped(k, ns, ne) .and. &
                                          iw_shaped(phi, ns, ne))) &
      status = self%fail(FRICREG_ESIZE, 'set_params: k and phi must be (ns, n)')
    if (status == FRICREG_OK) status = self%record(fricreg_iwan_set_params(self%ptr, &
      fricreg_iwan_size(self%ptr), fricreg_iwan_sliders(self%ptr), k, phi))
  end function iw_set_params

  !> The sliders' stiffnesses k(ns, n) and slip forces phi(ns, n). FRICREG_ESIZE.
  function iw_get_params(self, k, phi) result(status)
    class(fricreg_iwan_elements), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: k(:, :), phi(:, :)
    integer(c_int) :: status
    integer :: ns, ne
    ns = self%sliders()
    ne = self%size()
    status = self%ready('get_params', 'Iwan elements')
    if (status == FRICREG_OK .and. .not. (iw_shaped(k, ns, ne) .and. &
                                          iw_shaped(phi, ns, ne))) &
      status = self%fail(FRICREG_ESIZE, 'get_params: k and phi must be (ns, n)')
    if (status == FRICREG_OK) status = self%record(fricreg_iwan_get_params(self%ptr, &
      fricreg_iwan_size(self%ptr), fricreg_iwan_sliders(self%ptr), k, phi))
  end function iw_get_params

  !> Segalman's four-parameter model per element, fs(n) > 0, kt(n) > 0, -1 < chi(n) <= 1,
  !> beta(n) >= 0, on the geometric grid whose smallest breakpoint is resolution phi_max
  !> (0 < resolution < 1). FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function iw_set_segalman(self, fs, kt, chi, beta, resolution) result(status)
    class(fricreg_iwan_elements), intent(inout) :: self
    real(c_double), intent(in), contiguous :: fs(:), kt(:), chi(:), beta(:)
    real(c_double), intent(in) :: resolution
    integer(c_int) :: status
    integer(c_size_t) :: n
    n = fricreg_iwan_size(self%ptr)
    status = self%ready('set_segalman', 'Iwan elements')
    if (status == FRICREG_OK) status = self%check_size('set_segalman', 'fs', size(fs), n)
    if (status == FRICREG_OK) status = self%check_size('set_segalman', 'kt', size(kt), n)
    if (status == FRICREG_OK) status = self%check_size('set_segalman', 'chi', size(chi), n)
    if (status == FRICREG_OK) status = self%check_size('set_segalman', 'beta', size(beta), n)
    if (status == FRICREG_OK) status = self%record( &
      fricreg_iwan_set_segalman(self%ptr, n, fs, kt, chi, beta, resolution))
  end function iw_set_segalman

  !> Normal laws: preloads n0(n) > 0 and normal stiffnesses kn(n) >= 0; the slip forces scale
  !> as phi max(0, n0 + kn g)/n0. FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function iw_set_normal(self, n0, kn) result(status)
    class(fricreg_iwan_elements), intent(inout) :: self
    real(c_double), intent(in), contiguous :: n0(:), kn(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    n = fricreg_iwan_size(self%ptr)
    status = self%ready('set_normal', 'Iwan elements')
    if (status == FRICREG_OK) status = self%check_size('set_normal', 'n0', size(n0), n)
    if (status == FRICREG_OK) status = self%check_size('set_normal', 'kn', size(kn), n)
    if (status == FRICREG_OK) status = self%record(fricreg_iwan_set_normal(self%ptr, n, n0, kn))
  end function iw_set_normal

  !> Whether a is (rows, rows, cols).
  pure logical function iw_cube_shaped(a, rows, cols)
    real(c_double), intent(in) :: a(:, :, :)
    integer, intent(in) :: rows, cols
    iw_cube_shaped = size(a, 1) == rows .and. size(a, 2) == rows .and. size(a, 3) == cols
  end function iw_cube_shaped

  !> Trial forces f(dim, n) at displacements u(dim, n) from the committed sliders, and, if
  !> present, the consistent tangents dfdu(dim, dim, n). Written only on success.
  !> FRICREG_ESIZE; FRICREG_ENONFINITE.
  function iw_trial(self, u, f, dfdu) result(status)
    class(fricreg_iwan_elements), intent(inout) :: self
    real(c_double), intent(in), contiguous :: u(:, :)
    real(c_double), intent(inout), contiguous :: f(:, :)
    real(c_double), intent(inout), contiguous, optional :: dfdu(:, :, :)
    integer(c_int) :: status
    integer :: nd, ne
    nd = self%dim()
    ne = self%size()
    status = self%ready('trial', 'Iwan elements')
    if (status == FRICREG_OK .and. .not. (iw_shaped(u, nd, ne) .and. &
                                          iw_shaped(f, nd, ne))) &
      status = self%fail(FRICREG_ESIZE, 'trial: u and f must be (dim, n)')
    if (status == FRICREG_OK .and. present(dfdu)) then
      if (.not. iw_cube_shaped(dfdu, nd, ne)) &
        status = self%fail(FRICREG_ESIZE, 'trial: dfdu must be (dim, dim, n)')
    end if
    if (status == FRICREG_OK) status = self%record( &
      fricreg_iwan_trial(self%ptr, fricreg_iwan_size(self%ptr), u, f, dfdu))
  end function iw_trial

  !> Trial forces f(dim, n) at tangential displacements u(dim, n) and normal displacements
  !> g(n) (positive pressing), with lift-off; if present, the normal forces nf(n), the tangents
  !> dfdu(dim, dim, n) and df/dg dfdg(dim, n). Written only on success. FRICREG_ESIZE;
  !> FRICREG_ENONFINITE.
  function iw_trial_normal(self, u, g, f, nf, dfdu, dfdg) result(status)
    class(fricreg_iwan_elements), intent(inout) :: self
    real(c_double), intent(in), contiguous :: u(:, :), g(:)
    real(c_double), intent(inout), contiguous :: f(:, :)
    real(c_double), intent(inout), contiguous, optional :: nf(:), dfdu(:, :, :), dfdg(:, :)
    integer(c_int) :: status
    integer :: nd, ne
    integer(c_size_t) :: n
    n = fricreg_iwan_size(self%ptr)
    nd = self%dim()
    ne = self%size()
    status = self%ready('trial_normal', 'Iwan elements')
    if (status == FRICREG_OK .and. .not. (iw_shaped(u, nd, ne) .and. &
                                          iw_shaped(f, nd, ne))) &
      status = self%fail(FRICREG_ESIZE, 'trial_normal: u and f must be (dim, n)')
    if (status == FRICREG_OK) status = self%check_size('trial_normal', 'g', size(g), n)
    if (status == FRICREG_OK .and. present(nf)) &
      status = self%check_size('trial_normal', 'nf', size(nf), n)
    if (status == FRICREG_OK .and. present(dfdu)) then
      if (.not. iw_cube_shaped(dfdu, nd, ne)) &
        status = self%fail(FRICREG_ESIZE, 'trial_normal: dfdu must be (dim, dim, n)')
    end if
    if (status == FRICREG_OK .and. present(dfdg)) then
      if (.not. iw_shaped(dfdg, nd, ne)) &
        status = self%fail(FRICREG_ESIZE, 'trial_normal: dfdg must be (dim, n)')
    end if
    if (status == FRICREG_OK) status = self%record( &
      fricreg_iwan_trial_normal(self%ptr, n, u, g, f, nf, dfdu, dfdg))
  end function iw_trial_normal

  !> The last trial's sliders become the committed state.
  function iw_commit(self) result(status)
    class(fricreg_iwan_elements), intent(inout) :: self
    integer(c_int) :: status
    status = self%ready('commit', 'Iwan elements')
    if (status == FRICREG_OK) status = self%record(fricreg_iwan_commit(self%ptr))
  end function iw_commit

  !> Every slider back at 0, committed and trial; parameters and normal laws kept.
  function iw_reset(self) result(status)
    class(fricreg_iwan_elements), intent(inout) :: self
    integer(c_int) :: status
    status = self%ready('reset', 'Iwan elements')
    if (status == FRICREG_OK) status = self%record(fricreg_iwan_reset(self%ptr))
  end function iw_reset

  !> The committed slider positions w(dim, ns, n). FRICREG_ESIZE.
  function iw_get_slider(self, w) result(status)
    class(fricreg_iwan_elements), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: w(:, :, :)
    integer(c_int) :: status
    integer :: nd, ns, ne
    nd = self%dim()
    ns = self%sliders()
    ne = self%size()
    status = self%ready('get_slider', 'Iwan elements')
    if (status == FRICREG_OK .and. (size(w, 1) /= nd .or. size(w, 2) /= ns .or. &
                                    size(w, 3) /= ne)) &
      status = self%fail(FRICREG_ESIZE, 'get_slider: w must be (dim, ns, n)')
    if (status == FRICREG_OK) status = self%record(fricreg_iwan_get_slider(self%ptr, &
      fricreg_iwan_size(self%ptr), fricreg_iwan_sliders(self%ptr), w))
  end function iw_get_slider

  ! ---- AFT (fricreg_aft.h) -----------------------------------------------------------------

  !> Create a workspace for harmonics 0..H (1 <= H <= FRICREG_AFT_MAX_HARMONICS) and N samples
  !> (0: the exact path only; else a power of two, 2H + 2 <= N <= FRICREG_AFT_MAX_SAMPLES). An
  !> object that held one gets the new one and releases the old (on failure it keeps the old).
  !> FRICREG_EINVAL; FRICREG_ENOMEM.
  function aft_create(self, harmonics, samples) result(status)
    class(fricreg_aft_workspace), intent(inout) :: self
    integer, intent(in) :: harmonics, samples
    integer(c_int) :: status
    type(c_ptr) :: p
    character(len=64) :: buf
    write (buf, '(a, i0, a, i0)') 'create: H = ', harmonics, ', N = ', samples
    if (samples < 0) then
      status = self%fail(FRICREG_EINVAL, trim(buf) // ': N must be >= 0')
      return
    end if
    p = c_null_ptr
    status = fricreg_aft_create(int(harmonics, c_int), as_size(samples), p)
    if (status /= FRICREG_OK) then
      status = self%fail(status, trim(buf) // ': ' // fricreg_error_string(status))
      return
    end if
    call self%adopt(p, fricreg_aft_free, fricreg_aft_errcode, fricreg_aft_errmsg)
  end function aft_create

  subroutine aft_final(self)
    type(fricreg_aft_workspace), intent(inout) :: self
    call self%destroy()
  end subroutine aft_final

  !> Number of harmonics H (0 if not created).
  integer function aft_harmonics(self)
    class(fricreg_aft_workspace), intent(in) :: self
    aft_harmonics = int(fricreg_aft_harmonics(self%ptr))
  end function aft_harmonics

  !> Number of samples N (0 if none, or not created).
  integer function aft_samples(self)
    class(fricreg_aft_workspace), intent(in) :: self
    aft_samples = int(fricreg_aft_samples(self%ptr))
  end function aft_samples

  !> The shapes every evaluation shares: u(2H+1), f(2H+1), jac(2H+1, 2H+1) if present.
  function aft_check(self, what, u, f, jac) result(status)
    class(fricreg_aft_workspace), intent(inout) :: self
    character(len=*), intent(in) :: what
    real(c_double), intent(in) :: u(:), f(:)
    real(c_double), intent(in), optional :: jac(:, :)
    integer(c_int) :: status
    integer(c_size_t) :: n
    n = 2 * int(fricreg_aft_harmonics(self%ptr), c_size_t) + 1
    status = self%ready(what, 'AFT workspace')
    if (status == FRICREG_OK) status = self%check_size(what, 'u', size(u), n)
    if (status == FRICREG_OK) status = self%check_size(what, 'f', size(f), n)
    if (status == FRICREG_OK .and. present(jac)) &
      status = self%check_square(what, 'jac', jac, n)
  end function aft_check

  !> Exact AFT of one Jenkins element of stiffness kt > 0 and bound mun >= 0: f(2H+1) and, if
  !> present, jac(2H+1, 2H+1), written only on success. FRICREG_ESIZE; FRICREG_EINVAL;
  !> FRICREG_ENONFINITE; FRICREG_EINTEGRATOR (GSL's root solver did not converge).
  function aft_jenkins_exact(self, kt, mun, u, f, jac) result(status)
    class(fricreg_aft_workspace), intent(inout) :: self
    real(c_double), intent(in) :: kt, mun
    real(c_double), intent(in), contiguous :: u(:)
    real(c_double), intent(inout), contiguous :: f(:)
    real(c_double), intent(inout), contiguous, optional :: jac(:, :)
    integer(c_int) :: status
    status = self%aft_check('jenkins_exact', u, f, jac)
    if (status == FRICREG_OK) status = self%record(fricreg_aft_jenkins_exact(self%ptr, kt, mun, &
                                                    int(size(u), c_size_t), u, f, jac))
    if (status == FRICREG_OK .and. present(jac)) call fricreg_transpose(jac, int(size(u), c_size_t))
  end function aft_jenkins_exact

  !> Sampled AFT of one Jenkins element, as jenkins_exact (FRICREG_EINVAL also for N = 0).
  function aft_jenkins_sampled(self, kt, mun, u, f, jac) result(status)
    class(fricreg_aft_workspace), intent(inout) :: self
    real(c_double), intent(in) :: kt, mun
    real(c_double), intent(in), contiguous :: u(:)
    real(c_double), intent(inout), contiguous :: f(:)
    real(c_double), intent(inout), contiguous, optional :: jac(:, :)
    integer(c_int) :: status
    status = self%aft_check('jenkins_sampled', u, f, jac)
    if (status == FRICREG_OK) status = self%record(fricreg_aft_jenkins_sampled(self%ptr, kt, &
                                                    mun, int(size(u), c_size_t), u, f, jac))
    if (status == FRICREG_OK .and. present(jac)) call fricreg_transpose(jac, int(size(u), c_size_t))
  end function aft_jenkins_sampled

  !> Exact AFT of one Iwan element of sliders k(ns) > 0, phi(ns) >= 0, as jenkins_exact.
  function aft_iwan_exact(self, k, phi, u, f, jac) result(status)
    class(fricreg_aft_workspace), intent(inout) :: self
    real(c_double), intent(in), contiguous :: k(:), phi(:), u(:)
    real(c_double), intent(inout), contiguous :: f(:)
    real(c_double), intent(inout), contiguous, optional :: jac(:, :)
    integer(c_int) :: status
    status = self%aft_check('iwan_exact', u, f, jac)
    if (status == FRICREG_OK) &
      status = self%check_size('iwan_exact', 'phi', size(phi), int(size(k), c_size_t))
    if (status == FRICREG_OK) status = self%record(fricreg_aft_iwan_exact(self%ptr, &
                                 int(size(k), c_size_t), k, phi, int(size(u), c_size_t), u, f, jac))
    if (status == FRICREG_OK .and. present(jac)) call fricreg_transpose(jac, int(size(u), c_size_t))
  end function aft_iwan_exact

  !> Sampled AFT of one Iwan element, as iwan_exact (FRICREG_EINVAL also for N = 0).
  function aft_iwan_sampled(self, k, phi, u, f, jac) result(status)
    class(fricreg_aft_workspace), intent(inout) :: self
    real(c_double), intent(in), contiguous :: k(:), phi(:), u(:)
    real(c_double), intent(inout), contiguous :: f(:)
    real(c_double), intent(inout), contiguous, optional :: jac(:, :)
    integer(c_int) :: status
    status = self%aft_check('iwan_sampled', u, f, jac)
    if (status == FRICREG_OK) &
      status = self%check_size('iwan_sampled', 'phi', size(phi), int(size(k), c_size_t))
    if (status == FRICREG_OK) status = self%record(fricreg_aft_iwan_sampled(self%ptr, &
                                 int(size(k), c_size_t), k, phi, int(size(u), c_size_t), u, f, jac))
    if (status == FRICREG_OK .and. present(jac)) call fricreg_transpose(jac, int(size(u), c_size_t))
  end function aft_iwan_sampled

#ifdef FRICREG_HAVE_SIM
  ! ---- Simulations (fricreg_sim.h) ---------------------------------------------------------

  !> GSL's name of an integrator (FRICREG_INT_*), '' if unknown.
  function fricreg_integrator_string(integrator) result(name)
    integer(c_int), intent(in) :: integrator
    character(len=:), allocatable :: name
    name = fricreg_c_string(fricreg_integrator_name(integrator))
  end function fricreg_integrator_string

  !> The integrator (FRICREG_INT_*) with GSL's name, e.g. 'rk4' (trailing blanks ignored); 0
  !> if there is none.
  integer(c_int) function fricreg_integrator_id(name)
    character(len=*), intent(in) :: name
    fricreg_integrator_id = fricreg_integrator_from_name(trim(name) // c_null_char)
  end function fricreg_integrator_id

  !> A simulation of system (FRICREG_SYSTEM_*) with the paper's parameters, law (4), RK4,
  !> dt = 0.01 and the paper's eps rule. Replaces (and releases) any simulation self held.
  !> FRICREG_EINVAL for an unknown system; FRICREG_ENOMEM.
  function sim_create(self, system) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: system
    integer(c_int) :: status
    type(c_ptr) :: p
    character(len=32) :: buf
    p = c_null_ptr
    status = fricreg_sim_create(system, p)
    if (status /= FRICREG_OK) then
      write (buf, '(i0)') system
      status = self%fail(status, 'create: system ' // trim(buf) // ': ' // &
                         fricreg_error_string(status))
      return
    end if
    call self%adopt(p, fricreg_sim_free, fricreg_sim_errcode, fricreg_sim_errmsg)
  end function sim_create

  subroutine sim_final(self)
    type(fricreg_simulation), intent(inout) :: self
    call self%destroy()
  end subroutine sim_final

  !> One system parameter (FRICREG_PARAM_*); discards results. FRICREG_EINVAL for a parameter
  !> the system does not have or a value out of range; FRICREG_ENONFINITE.
  function sim_set_param(self, param, value) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: param
    real(c_double), intent(in) :: value
    integer(c_int) :: status
    status = self%ready('set_param', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_set_param(self%ptr, param, value))
  end function sim_set_param

  !> Law (FRICREG_LAW_*) and eps > 0; eps = 0 selects the paper's rule (2 dt, or 10 omega dt
  !> for the chain).
  function sim_set_law(self, law, eps) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps
    integer(c_int) :: status
    status = self%ready('set_law', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_set_law(self%ptr, law, eps))
  end function sim_set_law

  !> Partition of coupled contacts (FRICREG_PARTITION_*; C's fricreg_sim_set_partition).
  function sim_set_partition(self, partition) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: partition
    integer(c_int) :: status
    status = self%ready('set_partition', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_set_partition(self%ptr, partition))
  end function sim_set_partition

  !> Integrator (FRICREG_INT_*), step dt > 0, and rtol, atol (both omitted or 0: fixed step;
  !> rtol > 0 without atol: the absolute tolerances from eps, FRICREG_ATOL_FROM_EPS).
  function sim_set_integrator(self, integrator, dt, rtol, atol) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: integrator
    real(c_double), intent(in) :: dt
    real(c_double), intent(in), optional :: rtol, atol
    integer(c_int) :: status
    real(c_double) :: r, a
    ! FRICREG_ATOL_FROM_EPS of fricreg_sim.h (a double macro: gen_constants reads enums only);
    ! test_sim.f90 checks that an absent atol gives the rule's tolerances.
    real(c_double), parameter :: atol_from_eps = -1.0_c_double
    r = 0.0_c_double
    a = 0.0_c_double
    if (present(rtol)) r = rtol
    if (r > 0.0_c_double) a = atol_from_eps
    if (present(atol)) a = atol
    status = self%ready('set_integrator', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_set_integrator(self%ptr, integrator, dt, r, a))
  end function sim_set_integrator

  !> Install an observer (a bind(C) function with interface fricreg_sim_observer), called
  !> after every accepted step; user is passed back to it. With no observer, removes it.
  !> (The dummy's name is prefixed: gfortran gives a dummy of a bind(C) interface a binding
  !> label, which would clash with a caller's global name such as a module `observer`.)
  function sim_set_observer(self, fricreg_observer, user) result(status)
    class(fricreg_simulation), intent(inout) :: self
    procedure(fricreg_sim_observer), optional :: fricreg_observer
    type(c_ptr), intent(in), optional :: user
    integer(c_int) :: status
    type(c_funptr) :: fn
    type(c_ptr) :: u
    fn = c_null_funptr
    u = c_null_ptr
    if (present(fricreg_observer)) fn = c_funloc(fricreg_observer)
    if (present(user)) u = user
    status = self%ready('set_observer', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_set_observer(self%ptr, fn, u))
  end function sim_set_observer

  !> Route the simulation's warnings to a bind(C) subroutine with interface
  !> fricreg_warning_handler, called once per warning at the end of every run
  !> (fricreg_sim_set_warning_handler); user is passed back to it. With no handler, removes it.
  function sim_set_warning_handler(self, fricreg_handler, user) result(status)
    class(fricreg_simulation), intent(inout) :: self
    procedure(fricreg_warning_handler), optional :: fricreg_handler
    type(c_ptr), intent(in), optional :: user
    integer(c_int) :: status
    type(c_funptr) :: fn
    type(c_ptr) :: u
    fn = c_null_funptr
    u = c_null_ptr
    if (present(fricreg_handler)) fn = c_funloc(fricreg_handler)
    if (present(user)) u = user
    status = self%ready('set_warning_handler', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_set_warning_handler(self%ptr, fn, u))
  end function sim_set_warning_handler

  !> Bound the adaptive steps accepted in one forcing cycle (0: no bound; by default 10^4 for
  !> the laws that jump, 10^6 otherwise): a run that needs more returns FRICREG_EWORK
  !> (fricreg_sim_set_max_steps).
  function sim_set_max_steps(self, max_steps) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int64_t), intent(in) :: max_steps
    integer(c_int) :: status
    status = self%ready('set_max_steps', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_set_max_steps(self%ptr, max_steps))
  end function sim_set_max_steps

  !> Whether adaptive runs stop at the friction law's kinks and restart the stepper there
  !> (1, the default) or step over them (0) (fricreg_sim_set_kink_location).
  function sim_set_kink_location(self, on) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: on
    integer(c_int) :: status
    status = self%ready('set_kink_location', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_set_kink_location(self%ptr, on))
  end function sim_set_kink_location

  !> Whether runs estimate the error of D per cycle against eps -> 0: with companion runs at
  !> eps/2 and eps/4 (1, FRICREG_ESTIMATE_TWO_COMPANIONS), 1.6's one at eps/2 (2,
  !> FRICREG_ESTIMATE_ONE_COMPANION), or not (0, the default) (fricreg_sim_set_error_estimate).
  function sim_set_error_estimate(self, on) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: on
    integer(c_int) :: status
    status = self%ready('set_error_estimate', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_set_error_estimate(self%ptr, on))
  end function sim_set_error_estimate

  !> An absolute tolerance per component of the state y = (x, v, D), size 2 ndof + 1: ndof
  !> positions, ndof velocities, then D; each finite and > 0; replaces set_integrator's atol
  !> until the next set_integrator (fricreg_sim_set_abs_tolerances).
  function sim_set_abs_tolerances(self, atol) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(in), contiguous :: atol(:)
    integer(c_int) :: status
    status = self%ready('set_abs_tolerances', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_set_abs_tolerances(self%ptr, &
                                           int(size(atol), c_size_t), atol))
  end function sim_set_abs_tolerances

  !> The absolute tolerances an adaptive run uses per component of y = (x, v, D), size
  !> 2 ndof + 1: the rule from eps (set_integrator with rtol and no atol), the one atol, or
  !> those of set_abs_tolerances; zeros for fixed steps (fricreg_sim_get_abs_tolerances).
  function sim_get_abs_tolerances(self, atol) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: atol(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    n = 2_c_size_t * fricreg_sim_ndof(self%ptr) + 1_c_size_t
    status = self%ready('get_abs_tolerances', 'simulation')
    if (status == FRICREG_OK) status = self%check_size('get_abs_tolerances', 'atol', size(atol), n)
    if (status == FRICREG_OK) status = self%unrecorded('get_abs_tolerances', &
                                           fricreg_sim_get_abs_tolerances(self%ptr, n, atol))
  end function sim_get_abs_tolerances

  !> Integrate from t = 0 to t_end > 0 (see fricreg_sim_run for the returns).
  function sim_run(self, t_end) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(in) :: t_end
    integer(c_int) :: status
    status = self%ready('run', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_run(self%ptr, t_end))
  end function sim_run

  !> Integrate `cycles` >= 1 whole forcing cycles.
  function sim_run_cycles(self, cycles) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer, intent(in) :: cycles
    integer(c_int) :: status
    status = self%ready('run_cycles', 'simulation')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_sim_run_cycles(self%ptr, int(cycles, c_int)))
  end function sim_run_cycles

  !> Number of bodies: 1 (oscillator), n (chain), 2 (two blocks); 0 if not created.
  integer function sim_ndof(self)
    class(fricreg_simulation), intent(in) :: self
    sim_ndof = int(fricreg_sim_ndof(self%ptr))
  end function sim_ndof

  !> Number of contacts (equal to ndof in all three systems); 0 if not created.
  integer function sim_ncontacts(self)
    class(fricreg_simulation), intent(in) :: self
    sim_ncontacts = int(fricreg_sim_ncontacts(self%ptr))
  end function sim_ncontacts

  !> One quantity (FRICREG_VALUE_*) into value. FRICREG_EINVAL for an unknown one.
  function sim_get_value(self, which, value) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: which
    real(c_double), intent(inout) :: value
    integer(c_int) :: status
    status = self%ready('get_value', 'simulation')
    if (status == FRICREG_OK) &
      status = self%unrecorded('get_value', fricreg_sim_get_value(self%ptr, which, value))
  end function sim_get_value

  !> One integer counter of the last run (FRICREG_SIM_STAT_*) into value. FRICREG_EINVAL for
  !> an unknown counter.
  function sim_get_stat(self, which, value) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: which
    integer(c_int64_t), intent(inout) :: value
    integer(c_int) :: status
    status = self%ready('get_stat', 'simulation')
    if (status == FRICREG_OK) &
      status = self%unrecorded('get_stat', fricreg_sim_get_stat(self%ptr, which, value))
  end function sim_get_stat

  !> The value in use of a system parameter (FRICREG_PARAM_*): the paper's default or the
  !> value set. FRICREG_EINVAL for a parameter the system does not read.
  function sim_get_param(self, param, value) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: param
    real(c_double), intent(inout) :: value
    integer(c_int) :: status
    status = self%ready('get_param', 'simulation')
    if (status == FRICREG_OK) &
      status = self%unrecorded('get_param', fricreg_sim_get_param(self%ptr, param, value))
  end function sim_get_param

  !> State at the end of the last run (the initial state before one): x(ndof), v(ndof).
  function sim_get_state(self, x, v) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: x(:), v(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    n = fricreg_sim_ndof(self%ptr)
    status = self%ready('get_state', 'simulation')
    if (status == FRICREG_OK) status = self%check_size('get_state', 'x', size(x), n)
    if (status == FRICREG_OK) status = self%check_size('get_state', 'v', size(v), n)
    if (status == FRICREG_OK) &
      status = self%unrecorded('get_state', fricreg_sim_get_state(self%ptr, n, x, v))
  end function sim_get_state

  !> D per whole forcing cycle of the last run, D_k = -int sum_i w_i zdot_i f_i dt (w_i = 1/n
  !> for the chain, else 1): D is (re)allocated to the number of cycles completed.
  function sim_get_dissipation(self, D) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), allocatable, intent(inout) :: D(:)
    integer(c_int) :: status
    real(c_double) :: cycles
    real(c_double), allocatable :: tmp(:)
    cycles = 0.0_c_double
    status = self%ready('get_dissipation', 'simulation')
    if (status /= FRICREG_OK) return
    status = fricreg_sim_get_value(self%ptr, FRICREG_VALUE_CYCLES, cycles)
    if (status == FRICREG_OK) then
      allocate (tmp(max(1, int(cycles))))
      status = fricreg_sim_get_dissipation(self%ptr, int(cycles, c_size_t), tmp)
    end if
    status = self%unrecorded('get_dissipation', status)
    if (status == FRICREG_OK) D = tmp(1:int(cycles))
  end function sim_get_dissipation

  !> The error estimate of D per whole cycle of the last run (fricreg_sim_get_dissipation_error):
  !> err is (re)allocated to the number of cycles; FRICREG_EINVAL when the run made none.
  function sim_get_dissipation_error(self, err) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), allocatable, intent(inout) :: err(:)
    integer(c_int) :: status
    real(c_double) :: cycles
    real(c_double), allocatable :: tmp(:)
    cycles = 0.0_c_double
    status = self%ready('get_dissipation_error', 'simulation')
    if (status /= FRICREG_OK) return
    status = fricreg_sim_get_value(self%ptr, FRICREG_VALUE_CYCLES, cycles)
    if (status == FRICREG_OK) then
      allocate (tmp(max(1, int(cycles))))
      status = fricreg_sim_get_dissipation_error(self%ptr, int(cycles, c_size_t), tmp)
    end if
    status = self%unrecorded('get_dissipation_error', status)
    if (status == FRICREG_OK) err = tmp(1:int(cycles))
  end function sim_get_dissipation_error

  !> Per contact, the fraction of the last whole cycle with |zdot_i| < eps: frac(ncontacts).
  function sim_get_stick_fraction(self, frac) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: frac(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    m = fricreg_sim_ncontacts(self%ptr)
    status = self%ready('get_stick_fraction', 'simulation')
    if (status == FRICREG_OK) status = self%check_size('get_stick_fraction', 'frac', size(frac), m)
    if (status == FRICREG_OK) status = self%unrecorded('get_stick_fraction', &
                                           fricreg_sim_get_stick_fraction(self%ptr, m, frac))
  end function sim_get_stick_fraction

  !> Run at eps, eps/2, …, eps/2^(levels-1) and extrapolate D to eps -> 0 with an error
  !> estimate (fricreg_sim_run_extrapolated: levels 2 … 8; order 0 … 4, the declared leading
  !> order used where none is observed, 0 meaning 1; optional, default 0). window (optional,
  !> default 0: the whole run): the finer levels over the last `window` cycles only, from
  !> level 0's state there (fricreg_sim_run_extrapolated_window; the estimates it cannot give
  !> are +infinity).
  function sim_run_extrapolated(self, t_end, levels, order, window) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(in) :: t_end
    integer, intent(in) :: levels
    integer, intent(in), optional :: order, window
    integer(c_int) :: status, declared, last
    declared = 0
    last = 0
    if (present(order)) declared = int(order, c_int)
    if (present(window)) last = int(window, c_int)
    status = self%ready('run_extrapolated', 'simulation')
    if (status == FRICREG_OK) status = self%record(fricreg_sim_run_extrapolated_window(self%ptr, &
                                                    t_end, int(levels, c_int), declared, last))
  end function sim_run_extrapolated

  !> One quantity of the last extrapolated run (FRICREG_EXTRAP_*) into value. FRICREG_EINVAL
  !> for an unknown one or when none is held.
  function sim_get_extrapolation(self, which, value) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: which
    real(c_double), intent(inout) :: value
    integer(c_int) :: status
    status = self%ready('get_extrapolation', 'simulation')
    if (status == FRICREG_OK) status = self%unrecorded('get_extrapolation', &
                                           fricreg_sim_get_extrapolation(self%ptr, which, value))
  end function sim_get_extrapolation

  !> The extrapolated D per whole cycle and its error estimate: D and err are (re)allocated
  !> to the number of cycles completed. FRICREG_EINVAL when no extrapolation is held.
  function sim_get_extrapolated_dissipation(self, D, err) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), allocatable, intent(inout) :: D(:), err(:)
    integer(c_int) :: status
    real(c_double) :: cycles
    real(c_double), allocatable :: tmp(:), tmp_err(:)
    cycles = 0.0_c_double
    status = self%ready('get_extrapolated_dissipation', 'simulation')
    if (status /= FRICREG_OK) return
    status = fricreg_sim_get_value(self%ptr, FRICREG_VALUE_CYCLES, cycles)
    if (status == FRICREG_OK) then
      allocate (tmp(max(1, int(cycles))), tmp_err(max(1, int(cycles))))
      status = fricreg_sim_get_extrapolated_dissipation(self%ptr, int(cycles, c_size_t), tmp, &
                                                        tmp_err)
    end if
    status = self%unrecorded('get_extrapolated_dissipation', status)
    if (status == FRICREG_OK) then
      D = tmp(1:int(cycles))
      err = tmp_err(1:int(cycles))
    end if
  end function sim_get_extrapolated_dissipation

  ! ---- Exact solution of the oscillator (fricreg_exact.h) ----------------------------------
  ! Failures of solve carry the C solver's message; its getters record none (const in C).

  !> Solve Eq. (5) under (1)+(2), x'' + x = f + a sin(omega t), from x(0) = x0, x'(0) = v0
  !> over 0 <= t <= t_end (nondimensional, as in the paper). Replaces (and releases) any
  !> solution self held; on failure keeps it, and errmsg names the argument or value.
  !> FRICREG_EINVAL (omega <= 0, mun < 0, t_end <= 0 or above 10^6 cycles);
  !> FRICREG_ENONFINITE; FRICREG_ENOMEM; FRICREG_EINTEGRATOR.
  function exact_solve(self, a, omega, mun, x0, v0, t_end) result(status)
    class(fricreg_exact_solution), intent(inout) :: self
    real(c_double), intent(in) :: a, omega, mun, x0, v0, t_end
    integer(c_int) :: status
    type(c_ptr) :: p
    p = c_null_ptr
    status = self%unrecorded('solve', fricreg_exact_create(a, omega, mun, x0, v0, p))
    if (status /= FRICREG_OK) return
    status = fricreg_exact_run(p, t_end)
    if (status == FRICREG_OK) then
      call self%adopt(p, fricreg_exact_free, fricreg_exact_errcode, fricreg_exact_errmsg)
    else
      status = self%fail(status, 'solve: ' // fricreg_c_string(fricreg_exact_errmsg(p)))
      call fricreg_exact_free(p)
    end if
  end function exact_solve

  subroutine exact_final(self)
    type(fricreg_exact_solution), intent(inout) :: self
    call self%destroy()
  end subroutine exact_final

  !> Position x and velocity v at time t, 0 <= t <= t_end, in closed form.
  !> FRICREG_EINVAL if t is outside [0, t_end].
  function exact_state(self, t, x, v) result(status)
    class(fricreg_exact_solution), intent(inout) :: self
    real(c_double), intent(in) :: t
    real(c_double), intent(inout) :: x, v
    integer(c_int) :: status
    status = self%ready('state', 'solution', 'solve')
    if (status == FRICREG_OK) &
      status = self%unrecorded('state', fricreg_exact_state(self%ptr, t, x, v))
  end function exact_state

  !> Number of switches (phase changes after t = 0) up to t_end; 0 if not solved.
  integer function exact_nswitches(self)
    class(fricreg_exact_solution), intent(in) :: self
    exact_nswitches = int(fricreg_exact_nswitches(self%ptr))
  end function exact_nswitches

  !> Switching times, increasing, into times (reallocated to nswitches()); with sticks,
  !> sticks(k) is .true. where the phase starting at times(k) is a stick, .false. for a slip.
  function exact_switches(self, times, sticks) result(status)
    class(fricreg_exact_solution), intent(inout) :: self
    real(c_double), allocatable, intent(inout) :: times(:)
    logical, allocatable, intent(inout), optional :: sticks(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    real(c_double), allocatable :: t(:)
    integer(c_int), allocatable :: s(:)
    n = fricreg_exact_nswitches(self%ptr)
    allocate (t(max(1_c_size_t, n)), s(max(1_c_size_t, n)))
    status = self%ready('switches', 'solution', 'solve')
    if (status == FRICREG_OK) &
      status = self%unrecorded('switches', fricreg_exact_switches(self%ptr, n, t, s))
    if (status /= FRICREG_OK) return
    times = t(1:n)
    if (present(sticks)) sticks = s(1:n) /= 0
  end function exact_switches

  !> Number of whole forcing cycles 2 pi/omega in [0, t_end]; 0 if not solved.
  integer function exact_ncycles(self)
    class(fricreg_exact_solution), intent(in) :: self
    exact_ncycles = int(fricreg_exact_ncycles(self%ptr))
  end function exact_ncycles

  !> Dissipation D_k = -int x' f dt of each whole cycle, mun times the distance slid in it:
  !> D is (re)allocated to ncycles().
  function exact_dissipation(self, D) result(status)
    class(fricreg_exact_solution), intent(inout) :: self
    real(c_double), allocatable, intent(inout) :: D(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    real(c_double), allocatable :: tmp(:)
    n = fricreg_exact_ncycles(self%ptr)
    allocate (tmp(max(1_c_size_t, n)))
    status = self%ready('dissipation', 'solution', 'solve')
    if (status == FRICREG_OK) &
      status = self%unrecorded('dissipation', fricreg_exact_dissipation(self%ptr, n, tmp))
    if (status == FRICREG_OK) D = tmp(1:n)
  end function exact_dissipation

  !> Fraction of time at rest within [t0, t1], 0 <= t0 < t1 <= t_end, into fraction.
  !> FRICREG_EINVAL for a bad interval.
  function exact_stick_fraction(self, t0, t1, fraction) result(status)
    class(fricreg_exact_solution), intent(inout) :: self
    real(c_double), intent(in) :: t0, t1
    real(c_double), intent(inout) :: fraction
    integer(c_int) :: status
    status = self%ready('stick_fraction', 'solution', 'solve')
    if (status == FRICREG_OK) status = self%unrecorded('stick_fraction', &
                                       fricreg_exact_stick_fraction(self%ptr, t0, t1, fraction))
  end function exact_stick_fraction

  ! ---- Linear structure with friction contacts (fricreg_structure.h) ----------------------
  ! Setters and runs record their failures in the C object (errmsg names the argument, entry,
  ! time or contact, counting from 0); the getters, const in C, are recorded here.

  !> A structure of ndof >= 1 degrees of freedom and m >= 1 contacts, with C's defaults
  !> (M = I, C = K = 0, J unset, mun = 1, law (4) with eps = 1e-3, average-acceleration
  !> Newmark). Replaces (and releases) any structure self held; on failure keeps it.
  !> FRICREG_EINVAL for ndof or m < 1 or above 2**15; FRICREG_ENOMEM.
  function struct_create(self, ndof, m) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer, intent(in) :: ndof, m
    integer(c_int) :: status
    type(c_ptr) :: p
    character(len=64) :: buf
    write (buf, '(a, i0, a, i0)') 'create: ndof = ', ndof, ', m = ', m
    if (ndof < 1 .or. m < 1) then
      status = self%fail(FRICREG_EINVAL, trim(buf) // ': both must be >= 1')
      return
    end if
    p = c_null_ptr
    status = fricreg_structure_create(as_size(ndof), as_size(m), p)
    if (status /= FRICREG_OK) then
      status = self%fail(status, trim(buf) // ': ' // fricreg_error_string(status))
      return
    end if
    call self%adopt(p, fricreg_structure_free, fricreg_structure_errcode, &
                    fricreg_structure_errmsg)
    self%n = as_size(ndof)
    self%m = as_size(m)
  end function struct_create

  subroutine struct_final(self)
    type(fricreg_structure), intent(inout) :: self
    call self%destroy()
  end subroutine struct_final

  !> Degrees of freedom (0 if not created).
  integer function struct_ndof(self)
    class(fricreg_structure), intent(in) :: self
    struct_ndof = 0
    if (c_associated(self%ptr)) struct_ndof = int(self%n)
  end function struct_ndof

  !> Friction contacts (0 if not created).
  integer function struct_ncontacts(self)
    class(fricreg_structure), intent(in) :: self
    struct_ncontacts = 0
    if (c_associated(self%ptr)) struct_ncontacts = int(self%m)
  end function struct_ncontacts

  !> FRICREG_OK if self is created and the square matrix A is ndof x ndof.
  function struct_square(self, what, name, A) result(status)
    class(fricreg_structure), intent(inout) :: self
    character(len=*), intent(in) :: what, name
    real(c_double), intent(in) :: A(:, :)
    integer(c_int) :: status
    status = self%ready(what, 'structure')
    if (status == FRICREG_OK) status = self%check_square(what, name, A, self%n)
  end function struct_square

  !> FRICREG_OK if self is created and the vector x has n entries.
  function struct_vector(self, what, name, x, n) result(status)
    class(fricreg_structure), intent(inout) :: self
    character(len=*), intent(in) :: what, name
    real(c_double), intent(in) :: x(:)
    integer(c_size_t), intent(in) :: n
    integer(c_int) :: status
    status = self%ready(what, 'structure')
    if (status == FRICREG_OK) status = self%check_size(what, name, size(x), n)
  end function struct_vector

  !> Mass matrix M(ndof, ndof), symmetric positive definite (C reads it row-major: for a
  !> symmetric matrix the same numbers; a non-symmetric one is FRICREG_ENOTSYM, never
  !> transposed). FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_ENOTSYM; FRICREG_ENOTPSD.
  function struct_set_mass(self, M) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in), contiguous :: M(:, :)
    integer(c_int) :: status
    status = struct_square(self, 'set_mass', 'M', M)
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_mass(self%ptr, self%n, M))
  end function struct_set_mass

  !> Stiffness matrix K(ndof, ndof), symmetric (may be singular). FRICREG_ESIZE;
  !> FRICREG_ENONFINITE; FRICREG_ENOTSYM.
  function struct_set_stiffness(self, K) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in), contiguous :: K(:, :)
    integer(c_int) :: status
    status = struct_square(self, 'set_stiffness', 'K', K)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_stiffness(self%ptr, self%n, K))
  end function struct_set_stiffness

  !> Damping matrix C(ndof, ndof), symmetric; replaces Rayleigh damping. FRICREG_ESIZE;
  !> FRICREG_ENONFINITE; FRICREG_ENOTSYM.
  function struct_set_damping(self, C) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in), contiguous :: C(:, :)
    integer(c_int) :: status
    status = struct_square(self, 'set_damping', 'C', C)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_damping(self%ptr, self%n, C))
  end function struct_set_damping

  !> Rayleigh damping C = a0 M + a1 K (a0 in 1/s, a1 in s, both >= 0). FRICREG_EINVAL;
  !> FRICREG_ENONFINITE.
  function struct_set_rayleigh(self, a0, a1) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: a0, a1
    integer(c_int) :: status
    status = self%ready('set_rayleigh', 'structure')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_rayleigh(self%ptr, a0, a1))
  end function struct_set_rayleigh

  !> Contact matrix J(m, ndof) in Fortran's order, J(i, k) = d zdot_i / d u'_k (passed
  !> transposed to C, which reads J row-major). FRICREG_ESIZE unless J is m x ndof;
  !> FRICREG_ENONFINITE; FRICREG_EINVAL if a row is zero (C's message counts from 0).
  function struct_set_contacts(self, J) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: J(:, :)
    integer(c_int) :: status
    real(c_double), allocatable :: Jc(:, :) ! J transposed: C's row-major J
    status = self%ready('set_contacts', 'structure')
    if (status == FRICREG_OK) status = self%check_size('set_contacts', 'J, 1', size(J, 1), self%m)
    if (status == FRICREG_OK) status = self%check_size('set_contacts', 'J, 2', size(J, 2), self%n)
    if (status == FRICREG_OK) allocate (Jc, source=transpose(J))
    if (status == FRICREG_OK) status = self%record( &
                                       fricreg_structure_set_contacts(self%ptr, self%m, self%n, &
                                                                      Jc))
  end function struct_set_contacts

  !> Jenkins elements on the rows of Je(me, ndof) in Fortran's order (fricreg_structure_set_jenkins:
  !> element i sees q_i = (Je u)_i, a spring kt(i) in series with a slider of bound mun(i));
  !> me = size(Je, 1), 0 removes them. FRICREG_ESIZE unless Je has ndof columns and kt, mun
  !> me entries; C's codes (FRICREG_EINVAL for a zero row, kt <= 0 or mun < 0, ...).
  function struct_set_jenkins(self, Je, kt, mun) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: Je(:, :)
    real(c_double), intent(in), contiguous :: kt(:), mun(:)
    integer(c_int) :: status
    integer(c_size_t) :: me
    real(c_double), allocatable :: Jec(:, :) ! Je transposed: C's row-major Je
    me = int(size(Je, 1), c_size_t)
    status = self%ready('set_jenkins', 'structure')
    if (status == FRICREG_OK) status = self%check_size('set_jenkins', 'Je, 2', size(Je, 2), self%n)
    if (status == FRICREG_OK) status = self%check_size('set_jenkins', 'kt', size(kt), me)
    if (status == FRICREG_OK) status = self%check_size('set_jenkins', 'mun', size(mun), me)
    if (status == FRICREG_OK) allocate (Jec, source=transpose(Je))
    if (status == FRICREG_OK) status = self%record( &
                                       fricreg_structure_set_jenkins(self%ptr, me, self%n, &
                                                                     Jec, kt, mun))
  end function struct_set_jenkins

  !> The Jenkins elements' forces f(me), committed slider positions w(me) and dissipation
  !> D(me) (fricreg_structure_get_jenkins_state); each optional, at least one given, all of
  !> one size me, the number of elements set. FRICREG_ESIZE; FRICREG_ENULL if none is given.
  function struct_get_jenkins_state(self, f, w, D) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous, optional :: f(:), w(:), D(:)
    integer(c_int) :: status
    integer :: me
    status = self%ready('get_jenkins_state', 'structure')
    if (status /= FRICREG_OK) return
    me = -1
    if (present(f)) me = size(f)
    if (present(w)) then
      if (me >= 0 .and. size(w) /= me) me = -2
      if (me == -1) me = size(w)
    end if
    if (present(D)) then
      if (me >= 0 .and. size(D) /= me) me = -2
      if (me == -1) me = size(D)
    end if
    if (me == -2) then
      status = self%fail(FRICREG_ESIZE, 'get_jenkins_state: f, w and D differ in size')
      return
    end if
    status = self%unrecorded('get_jenkins_state', &
                             fricreg_structure_get_jenkins_state(self%ptr, &
                                                                 int(max(me, 0), c_size_t), &
                                                                 f, w, D))
  end function struct_get_jenkins_state

  !> 2-D Jenkins elements (fricreg_structure_set_jenkins_2d): element i on rows 2i-1 and 2i of
  !> Je(2 me, ndof) in Fortran's order, q_i = ((Je u)(2i-1), (Je u)(2i)), a spring kt(i) in
  !> series with an isotropic slider of bound mun(i) (|f_i| <= mun(i)); me = size(kt), 0
  !> removes them. FRICREG_ESIZE unless Je is (2 size(kt), ndof) and mun has size(kt) entries;
  !> C's codes (FRICREG_EINVAL for a zero row, kt <= 0 or mun < 0, ...).
  function struct_set_jenkins_2d(self, Je, kt, mun) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: Je(:, :)
    real(c_double), intent(in), contiguous :: kt(:), mun(:)
    integer(c_int) :: status
    integer(c_size_t) :: me
    real(c_double), allocatable :: Jec(:, :) ! Je transposed: C's row-major Je
    me = int(size(kt), c_size_t)
    status = self%ready('set_jenkins_2d', 'structure')
    if (status == FRICREG_OK) status = self%check_size('set_jenkins_2d', 'Je, 1', size(Je, 1), &
                                                       2 * me)
    if (status == FRICREG_OK) status = self%check_size('set_jenkins_2d', 'Je, 2', size(Je, 2), &
                                                       self%n)
    if (status == FRICREG_OK) status = self%check_size('set_jenkins_2d', 'mun', size(mun), me)
    if (status == FRICREG_OK) allocate (Jec, source=transpose(Je))
    if (status == FRICREG_OK) status = self%record( &
                                       fricreg_structure_set_jenkins_2d(self%ptr, me, self%n, &
                                                                        Jec, kt, mun))
  end function struct_set_jenkins_2d

  !> The 2-D Jenkins elements' forces f(2, me), committed slider positions w(2, me) (element
  !> i's (x, y) in column i) and dissipation D(me) (fricreg_structure_get_jenkins_2d_state);
  !> each optional, at least one given, all of me elements. FRICREG_ESIZE (sizes, or f or w
  !> without 2 rows); FRICREG_ENULL if none is given; FRICREG_EINVAL for 1-D elements.
  function struct_get_jenkins_2d_state(self, f, w, D) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous, optional :: f(:, :), w(:, :), D(:)
    integer(c_int) :: status
    integer :: me
    status = self%ready('get_jenkins_2d_state', 'structure')
    if (status /= FRICREG_OK) return
    me = -1
    if (present(f)) then
      me = size(f, 2)
      if (size(f, 1) /= 2) me = -2
    end if
    if (present(w)) then
      if (me >= 0 .and. size(w, 2) /= me) me = -2
      if (me == -1) me = size(w, 2)
      if (size(w, 1) /= 2) me = -2
    end if
    if (present(D)) then
      if (me >= 0 .and. size(D) /= me) me = -2
      if (me == -1) me = size(D)
    end if
    if (me == -2) then
      status = self%fail(FRICREG_ESIZE, &
                         'get_jenkins_2d_state: f and w must be (2, me) and D (me)')
      return
    end if
    status = self%unrecorded('get_jenkins_2d_state', &
                             fricreg_structure_get_jenkins_2d_state(self%ptr, &
                                                                    int(max(me, 0), c_size_t), &
                                                                    f, w, D))
  end function struct_get_jenkins_2d_state

  !> Iwan elements on the rows of Je(me, ndof) in Fortran's order (fricreg_structure_set_iwan:
  !> element i sees q_i = (Je u)_i, ns sliders in parallel, slider s a spring k(s, i) in series
  !> with a slider of slip force phi(s, i)); me = size(Je, 1), 0 removes them, ns = size(k, 1).
  !> FRICREG_ESIZE unless Je has ndof columns and k, phi are (ns, me) arrays of one shape; C's
  !> codes (FRICREG_EINVAL for a zero row, ns = 0, k <= 0 or phi < 0, ...).
  function struct_set_iwan(self, Je, k, phi) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: Je(:, :)
    real(c_double), intent(in), contiguous :: k(:, :), phi(:, :)
    integer(c_int) :: status
    integer(c_size_t) :: me
    real(c_double), allocatable :: Jec(:, :) ! Je transposed: C's row-major Je
    me = int(size(Je, 1), c_size_t)
    status = self%ready('set_iwan', 'structure')
    if (status == FRICREG_OK) status = self%check_size('set_iwan', 'Je, 2', size(Je, 2), self%n)
    if (status == FRICREG_OK) status = self%check_size('set_iwan', 'k, 2', size(k, 2), me)
    if (status == FRICREG_OK) status = self%check_size('set_iwan', 'phi, 1', size(phi, 1), &
                                                       int(size(k, 1), c_size_t))
    if (status == FRICREG_OK) status = self%check_size('set_iwan', 'phi, 2', size(phi, 2), me)
    if (status == FRICREG_OK) allocate (Jec, source=transpose(Je))
    if (status == FRICREG_OK) status = self%record( &
                                       fricreg_structure_set_iwan(self%ptr, me, self%n, &
                                                                  Jec, &
                                                                  int(size(k, 1), c_size_t), &
                                                                  k, phi))
  end function struct_set_iwan

  !> The elements' forces f(me), committed slider positions w(ns, me) and dissipation D(me)
  !> (fricreg_structure_get_iwan_state); each optional, at least one given. me is the number
  !> of elements set (size(f), size(D) or size(w, 2)), ns their sliders (size(w, 1); with w
  !> absent, the elements' own). FRICREG_ESIZE; FRICREG_ENULL if none is given.
  function struct_get_iwan_state(self, f, w, D) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous, optional :: f(:), w(:, :), D(:)
    integer(c_int) :: status
    integer :: me, ns
    status = self%ready('get_iwan_state', 'structure')
    if (status /= FRICREG_OK) return
    me = -1
    ns = -1
    if (present(f)) me = size(f)
    if (present(w)) then
      if (me >= 0 .and. size(w, 2) /= me) me = -2
      if (me == -1) me = size(w, 2)
      ns = size(w, 1)
    end if
    if (present(D)) then
      if (me >= 0 .and. size(D) /= me) me = -2
      if (me == -1) me = size(D)
    end if
    if (me == -2) then
      status = self%fail(FRICREG_ESIZE, 'get_iwan_state: f, w and D differ in elements')
      return
    end if
    if (.not. present(w)) then
      status = self%unrecorded('get_iwan_state', &
                               fricreg_structure_get_jenkins_state(self%ptr, &
                                                                   int(max(me, 0), c_size_t), &
                                                                   f=f, D=D))
      return
    end if
    status = self%unrecorded('get_iwan_state', &
                             fricreg_structure_get_iwan_state(self%ptr, &
                                                              int(max(me, 0), c_size_t), &
                                                              int(ns, c_size_t), f, w, D))
  end function struct_get_iwan_state

  !> Jenkins elements with a normal load and lift-off on the rows of Je(me, ndof) and
  !> Jn(me, ndof) in Fortran's order (fricreg_structure_set_jenkins_normal: N = max(0, n0 + kn g),
  !> g = (Jn u)_i, bound mu N); me = size(Je, 1). FRICREG_ESIZE unless Je and Jn have one shape
  !> with ndof columns and kt, mu, n0, kn me entries; C's codes otherwise.
  function struct_set_jenkins_normal(self, Je, Jn, kt, mu, n0, kn) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: Je(:, :), Jn(:, :)
    real(c_double), intent(in), contiguous :: kt(:), mu(:), n0(:), kn(:)
    integer(c_int) :: status
    integer(c_size_t) :: me
    character(len=*), parameter :: who = 'set_jenkins_normal'
    real(c_double), allocatable :: Jec(:, :), Jnc(:, :) ! transposed: C's row-major Je, Jn
    me = int(size(Je, 1), c_size_t)
    status = self%ready(who, 'structure')
    if (status == FRICREG_OK) status = self%check_size(who, 'Je, 2', size(Je, 2), self%n)
    if (status == FRICREG_OK) status = self%check_size(who, 'Jn, 1', size(Jn, 1), me)
    if (status == FRICREG_OK) status = self%check_size(who, 'Jn, 2', size(Jn, 2), self%n)
    if (status == FRICREG_OK) status = self%check_size(who, 'kt', size(kt), me)
    if (status == FRICREG_OK) status = self%check_size(who, 'mu', size(mu), me)
    if (status == FRICREG_OK) status = self%check_size(who, 'n0', size(n0), me)
    if (status == FRICREG_OK) status = self%check_size(who, 'kn', size(kn), me)
    if (status == FRICREG_OK) allocate (Jec, source=transpose(Je))
    if (status == FRICREG_OK) allocate (Jnc, source=transpose(Jn))
    if (status == FRICREG_OK) status = self%record( &
                                       fricreg_structure_set_jenkins_normal(self%ptr, me, &
                                                                            self%n, &
                                                                            Jec, &
                                                                            Jnc, kt, &
                                                                            mu, n0, kn))
  end function struct_set_jenkins_normal

  !> 3-D contact elements: 2-D Jenkins elements with a normal load and lift-off
  !> (fricreg_structure_set_jenkins_2d_normal): element i's tangential rows 2i-1 (x) and 2i (y)
  !> of Je(2 me, ndof) and its normal row i of Jn(me, ndof), both in Fortran's order;
  !> N = max(0, n0 + kn g), g = (Jn u)_i, |f_i| <= mu N; me = size(Jn, 1). FRICREG_ESIZE unless
  !> Je is (2 me, ndof), Jn (me, ndof) and kt, mu, n0, kn have me entries; C's codes otherwise.
  !> Since 1.7.
  function struct_set_jenkins_2d_normal(self, Je, Jn, kt, mu, n0, kn) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: Je(:, :), Jn(:, :)
    real(c_double), intent(in), contiguous :: kt(:), mu(:), n0(:), kn(:)
    integer(c_int) :: status
    integer(c_size_t) :: me
    character(len=*), parameter :: who = 'set_jenkins_2d_normal'
    real(c_double), allocatable :: Jec(:, :), Jnc(:, :) ! transposed: C's row-major Je, Jn
    me = int(size(Jn, 1), c_size_t)
    status = self%ready(who, 'structure')
    if (status == FRICREG_OK) status = self%check_size(who, 'Je, 1', size(Je, 1), 2 * me)
    if (status == FRICREG_OK) status = self%check_size(who, 'Je, 2', size(Je, 2), self%n)
    if (status == FRICREG_OK) status = self%check_size(who, 'Jn, 2', size(Jn, 2), self%n)
    if (status == FRICREG_OK) status = self%check_size(who, 'kt', size(kt), me)
    if (status == FRICREG_OK) status = self%check_size(who, 'mu', size(mu), me)
    if (status == FRICREG_OK) status = self%check_size(who, 'n0', size(n0), me)
    if (status == FRICREG_OK) status = self%check_size(who, 'kn', size(kn), me)
    if (status == FRICREG_OK) allocate (Jec, source=transpose(Je))
    if (status == FRICREG_OK) allocate (Jnc, source=transpose(Jn))
    if (status == FRICREG_OK) status = self%record( &
                                       fricreg_structure_set_jenkins_2d_normal(self%ptr, me, &
                                                                               self%n, Jec, &
                                                                               Jnc, kt, mu, &
                                                                               n0, kn))
  end function struct_set_jenkins_2d_normal

  !> The normal forces N(me) of set_jenkins_normal's elements
  !> (fricreg_structure_get_normal_forces). FRICREG_ESIZE; FRICREG_EINVAL without a normal law.
  function struct_get_normal_forces(self, N) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: N(:)
    integer(c_int) :: status
    status = self%ready('get_normal_forces', 'structure')
    if (status /= FRICREG_OK) return
    status = self%unrecorded('get_normal_forces', &
                             fricreg_structure_get_normal_forces(self%ptr, &
                                                                 int(size(N), c_size_t), N))
  end function struct_get_normal_forces

  ! The compressed sparse setters (fricreg_structure.h, since 1.6): the arrays as a Fortran code
  ! holds them, indices integer(c_int64_t), flags from enum fricreg_sparse_flags, optional and
  ! FRICREG_SPARSE_ONE_BASED when absent (what Fortran's indices count from). A compressed
  ! matrix states its rows and columns itself, so J's arrays go to C as they are.

  !> flags, or FRICREG_SPARSE_ONE_BASED when absent.
  integer(c_int) function struct_sparse_flags(flags)
    integer(c_int), intent(in), optional :: flags
    struct_sparse_flags = FRICREG_SPARSE_ONE_BASED
    if (present(flags)) struct_sparse_flags = flags
  end function struct_sparse_flags

  !> FRICREG_OK if self is created, ptr has n + 1 elements and ind and values hold at least the
  !> nnz = ptr(n + 1) - base entries ptr says (base 1 with FRICREG_SPARSE_ONE_BASED in flags,
  !> else 0), else a recorded FRICREG_ESIZE naming the array: C reads nnz of each, which it
  !> cannot check. ptr_name and ind_name name the first two arrays in the message; a
  !> ptr(n + 1) below base is left to C (FRICREG_EINVAL).
  function struct_compressed(self, what, ptr_name, ind_name, flags, n, ptr, ind, values) &
      result(status)
    class(fricreg_structure), intent(inout) :: self
    character(len=*), intent(in) :: what, ptr_name, ind_name
    integer(c_int), intent(in) :: flags
    integer(c_size_t), intent(in) :: n
    integer(c_int64_t), intent(in) :: ptr(:), ind(:)
    real(c_double), intent(in) :: values(:)
    integer(c_int) :: status
    integer(c_int64_t) :: nnz
    character(len=64) :: buf
    status = self%ready(what, 'structure')
    if (status == FRICREG_OK) status = self%check_size(what, ptr_name, size(ptr), n + 1)
    if (status /= FRICREG_OK) return
    nnz = ptr(n + 1) - merge(1_c_int64_t, 0_c_int64_t, iand(flags, FRICREG_SPARSE_ONE_BASED) /= 0)
    if (int(size(ind), c_int64_t) < nnz) then
      write (buf, '(a, i0, a, i0)') ') = ', size(ind), ', expected at least ', nnz
      status = self%fail(FRICREG_ESIZE, what // ': size(' // ind_name // trim(buf))
    else if (int(size(values), c_int64_t) < nnz) then
      write (buf, '(a, i0, a, i0)') ') = ', size(values), ', expected at least ', nnz
      status = self%fail(FRICREG_ESIZE, what // ': size(values' // trim(buf))
    end if
  end function struct_compressed

  !> Mass matrix M (ndof x ndof) from compressed sparse rows (C's
  !> fricreg_structure_set_mass_csr): rowptr(ndof + 1), colind(nnz) of kind c_int64_t,
  !> values(nnz) (mass units), nnz = rowptr(ndof + 1) - base. flags (fricreg_sparse_flags,
  !> combined with +): absent, FRICREG_SPARSE_ONE_BASED (rowptr(1) = 1, indices 1..ndof);
  !> FRICREG_SPARSE_ZERO_BASED for C's; with FRICREG_SPARSE_UPPER or _LOWER, M given by that
  !> triangle and its diagonal, else whole (then symmetric to 1e-12 of the rows' scales, as
  !> set_mass). Duplicates are summed. Positive definite. Copied.
  !> FRICREG_ESIZE unless rowptr has ndof + 1 elements and colind and values at least nnz;
  !> FRICREG_EINVAL (flags, rowptr not starting at the base or decreasing, an index out of range,
  !> an entry outside the triangle given; the message names the array and the entry, counting
  !> from 0); FRICREG_ENONFINITE; FRICREG_ENOTSYM; FRICREG_ENOTPSD; FRICREG_ENOMEM. On failure
  !> the structure keeps its M.
  function struct_set_mass_csr(self, rowptr, colind, values, flags) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int64_t), intent(in), contiguous :: rowptr(:), colind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int), intent(in), optional :: flags
    integer(c_int) :: status, f
    f = struct_sparse_flags(flags)
    status = struct_compressed(self, 'set_mass_csr', 'rowptr', 'colind', f, &
                               self%n, rowptr, colind, values)
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_mass_csr(self%ptr, &
                                                   self%n, f, rowptr, colind, values))
  end function struct_set_mass_csr

  !> Mass matrix M from compressed sparse columns (C's fricreg_structure_set_mass_csc), what a
  !> Fortran code usually holds: colptr(ndof + 1), rowind(nnz) of kind c_int64_t, values(nnz),
  !> flags as set_mass_csr (absent: one-based, whole). M being symmetric, its CSC arrays are
  !> its CSR arrays, the lower triangle of one the upper of the other:
  !> flags = FRICREG_SPARSE_ONE_BASED + FRICREG_SPARSE_LOWER for the lower triangle's columns.
  !> The statuses of set_mass_csr.
  function struct_set_mass_csc(self, colptr, rowind, values, flags) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int64_t), intent(in), contiguous :: colptr(:), rowind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int), intent(in), optional :: flags
    integer(c_int) :: status, f
    f = struct_sparse_flags(flags)
    status = struct_compressed(self, 'set_mass_csc', 'colptr', 'rowind', f, &
                               self%n, colptr, rowind, values)
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_mass_csc(self%ptr, &
                                                   self%n, f, colptr, rowind, values))
  end function struct_set_mass_csc

  !> Stiffness matrix K (ndof x ndof, force per length) from compressed sparse rows (C's
  !> fricreg_structure_set_stiffness_csr): rowptr(ndof + 1), colind(nnz), values(nnz) and
  !> flags as set_mass_csr (absent: one-based, whole); symmetric, need not be definite.
  !> FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE; FRICREG_ENOTSYM; FRICREG_ENOMEM.
  function struct_set_stiffness_csr(self, rowptr, colind, values, flags) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int64_t), intent(in), contiguous :: rowptr(:), colind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int), intent(in), optional :: flags
    integer(c_int) :: status, f
    f = struct_sparse_flags(flags)
    status = struct_compressed(self, 'set_stiffness_csr', 'rowptr', 'colind', f, &
                               self%n, rowptr, colind, values)
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_stiffness_csr( &
                                                   self%ptr, self%n, f, rowptr, colind, values))
  end function struct_set_stiffness_csr

  !> Stiffness matrix K from compressed sparse columns (C's
  !> fricreg_structure_set_stiffness_csc): colptr(ndof + 1), rowind(nnz), values(nnz), flags as
  !> set_mass_csc. The statuses of set_stiffness_csr.
  function struct_set_stiffness_csc(self, colptr, rowind, values, flags) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int64_t), intent(in), contiguous :: colptr(:), rowind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int), intent(in), optional :: flags
    integer(c_int) :: status, f
    f = struct_sparse_flags(flags)
    status = struct_compressed(self, 'set_stiffness_csc', 'colptr', 'rowind', f, &
                               self%n, colptr, rowind, values)
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_stiffness_csc( &
                                                   self%ptr, self%n, f, colptr, rowind, values))
  end function struct_set_stiffness_csc

  !> Damping matrix C (ndof x ndof, force per velocity) from compressed sparse rows (C's
  !> fricreg_structure_set_damping_csr), as set_stiffness_csr; replaces Rayleigh damping.
  !> FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE; FRICREG_ENOTSYM; FRICREG_ENOMEM.
  function struct_set_damping_csr(self, rowptr, colind, values, flags) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int64_t), intent(in), contiguous :: rowptr(:), colind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int), intent(in), optional :: flags
    integer(c_int) :: status, f
    f = struct_sparse_flags(flags)
    status = struct_compressed(self, 'set_damping_csr', 'rowptr', 'colind', f, &
                               self%n, rowptr, colind, values)
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_damping_csr( &
                                                   self%ptr, self%n, f, rowptr, colind, values))
  end function struct_set_damping_csr

  !> Damping matrix C from compressed sparse columns (C's fricreg_structure_set_damping_csc):
  !> colptr(ndof + 1), rowind(nnz), values(nnz), flags as set_mass_csc; replaces Rayleigh
  !> damping. The statuses of set_damping_csr.
  function struct_set_damping_csc(self, colptr, rowind, values, flags) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int64_t), intent(in), contiguous :: colptr(:), rowind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int), intent(in), optional :: flags
    integer(c_int) :: status, f
    f = struct_sparse_flags(flags)
    status = struct_compressed(self, 'set_damping_csc', 'colptr', 'rowind', f, &
                               self%n, colptr, rowind, values)
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_damping_csc( &
                                                   self%ptr, self%n, f, colptr, rowind, values))
  end function struct_set_damping_csc

  !> Contact matrix J (m x ndof, J(i, k) = d zdot_i / d u'_k) from compressed sparse rows (C's
  !> fricreg_structure_set_contacts_csr): rowptr(m + 1), colind(nnz) of kind c_int64_t (columns
  !> 1..ndof when one-based), values(nnz). flags: absent or FRICREG_SPARSE_ONE_BASED, or
  !> FRICREG_SPARSE_ZERO_BASED (J is not symmetric: a triangle flag is FRICREG_EINVAL). Each
  !> row must hold a nonzero value. Copied. FRICREG_ESIZE unless rowptr has m + 1 elements and
  !> colind and values at least nnz; FRICREG_EINVAL (flags, pointers, indices, a zero row, C's
  !> message counting from 0); FRICREG_ENONFINITE; FRICREG_ENOMEM. On failure J is kept.
  function struct_set_contacts_csr(self, rowptr, colind, values, flags) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int64_t), intent(in), contiguous :: rowptr(:), colind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int), intent(in), optional :: flags
    integer(c_int) :: status, f
    f = struct_sparse_flags(flags)
    status = struct_compressed(self, 'set_contacts_csr', 'rowptr', 'colind', f, &
                               self%m, rowptr, colind, values)
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_contacts_csr( &
                                                   self%ptr, self%m, self%n, f, rowptr, colind, &
                                                   values))
  end function struct_set_contacts_csr

  !> Contact matrix J (m x ndof) from compressed sparse columns (C's
  !> fricreg_structure_set_contacts_csc), the CSC of a Fortran J(m, ndof): colptr(ndof + 1),
  !> rowind(nnz) (contacts 1..m when one-based), values(nnz), flags as set_contacts_csr. The
  !> statuses of set_contacts_csr, colptr having ndof + 1 elements.
  function struct_set_contacts_csc(self, colptr, rowind, values, flags) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int64_t), intent(in), contiguous :: colptr(:), rowind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int), intent(in), optional :: flags
    integer(c_int) :: status, f
    f = struct_sparse_flags(flags)
    status = struct_compressed(self, 'set_contacts_csc', 'colptr', 'rowind', f, &
                               self%n, colptr, rowind, values)
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_contacts_csc( &
                                                   self%ptr, self%m, self%n, f, colptr, rowind, &
                                                   values))
  end function struct_set_contacts_csc

  !> Friction bounds mun(m) = mu_i N_i >= 0 (force units); may change between steps.
  !> FRICREG_ESIZE; FRICREG_EINVAL if one is negative; FRICREG_ENONFINITE.
  function struct_set_bounds(self, mun) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in), contiguous :: mun(:)
    integer(c_int) :: status
    status = struct_vector(self, 'set_bounds', 'mun', mun, self%m)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_bounds(self%ptr, self%m, mun))
  end function struct_set_bounds

  !> Law (FRICREG_LAW_*) and eps > 0 (velocity units). FRICREG_EINVAL; FRICREG_ENONFINITE.
  function struct_set_law(self, law, eps) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps
    integer(c_int) :: status
    status = self%ready('set_law', 'structure')
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_law(self%ptr, law, eps))
  end function struct_set_law

  !> Influence vector r(ndof) of the ground acceleration (load -M r a_g; default r = 1 at
  !> every degree of freedom). FRICREG_ESIZE; FRICREG_ENONFINITE.
  function struct_set_influence(self, r) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in), contiguous :: r(:)
    integer(c_int) :: status
    status = struct_vector(self, 'set_influence', 'r', r, self%n)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_influence(self%ptr, self%n, r))
  end function struct_set_influence

  !> Ground acceleration record ag(:) (e.g. m/s**2) at times t0 + (k - 1) dt_rec, k = 1, ...,
  !> size(ag) >= 2, linear between samples and zero outside; t0 defaults to 0. An empty ag
  !> removes the ground motion. Read at step ends (see C's fricreg_structure_set_ground_accel).
  !> FRICREG_EINVAL if size(ag) is 1 or dt_rec <= 0; FRICREG_ENONFINITE; FRICREG_ENOMEM.
  function struct_set_ground_accel(self, ag, dt_rec, t0) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in), contiguous :: ag(:)
    real(c_double), intent(in) :: dt_rec
    real(c_double), intent(in), optional :: t0
    integer(c_int) :: status
    real(c_double) :: start
    start = 0.0_c_double
    if (present(t0)) start = t0
    status = self%ready('set_ground_accel', 'structure')
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_ground_accel( &
                                       self%ptr, start, dt_rec, as_size(size(ag)), ag))
  end function struct_set_ground_accel

  !> External load p(t) = p(ndof) g(t) (force units). Without g, a constant load (g = 1);
  !> with g, a record like set_ground_accel's at t0 + (k - 1) dt_rec (dt_rec then required,
  !> t0 default 0). FRICREG_ESIZE; FRICREG_EINVAL (size(g) = 1, dt_rec <= 0 or absent with g);
  !> FRICREG_ENONFINITE; FRICREG_ENOMEM.
  function struct_set_load(self, p, g, dt_rec, t0) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in), contiguous :: p(:)
    real(c_double), intent(in), contiguous, optional :: g(:)
    real(c_double), intent(in), optional :: dt_rec, t0
    integer(c_int) :: status
    real(c_double) :: start, step
    start = 0.0_c_double
    step = 0.0_c_double
    if (present(t0)) start = t0
    if (present(dt_rec)) step = dt_rec
    status = struct_vector(self, 'set_load', 'p', p, self%n)
    if (status /= FRICREG_OK) return
    if (.not. present(g)) then
      status = self%record(fricreg_structure_set_load(self%ptr, self%n, p, start, step, &
                                                      0_c_size_t))
    else if (.not. present(dt_rec)) then
      status = self%fail(FRICREG_EINVAL, 'set_load: g given without dt_rec')
    else
      status = self%record(fricreg_structure_set_load(self%ptr, self%n, p, start, step, &
                                                      as_size(size(g)), g))
    end if
  end function struct_set_load

  !> Restart at t = 0 from u0(ndof) and v0(ndof), each zero if absent; clears the energy
  !> balance, the dissipation and the counters. FRICREG_ESIZE; FRICREG_ENONFINITE.
  function struct_set_initial(self, u0, v0) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in), contiguous, optional :: u0(:), v0(:)
    integer(c_int) :: status
    real(c_double), allocatable :: u(:), v(:)
    status = self%ready('set_initial', 'structure')
    if (status /= FRICREG_OK) return
    allocate (u(self%n), v(self%n))
    u = 0.0_c_double
    v = 0.0_c_double
    if (present(u0)) then
      status = self%check_size('set_initial', 'u0', size(u0), self%n)
      if (status /= FRICREG_OK) return
      u = u0
    end if
    if (present(v0)) then
      status = self%check_size('set_initial', 'v0', size(v0), self%n)
      if (status /= FRICREG_OK) return
      v = v0
    end if
    status = self%record(fricreg_structure_set_initial(self%ptr, self%n, u, v))
  end function struct_set_initial

  !> Newmark's method, beta in (0, 1/2] (default 1/4), gamma in [1/2, 1] (default 1/2):
  !> average acceleration if both are absent. FRICREG_EINVAL; FRICREG_ENONFINITE.
  function struct_set_newmark(self, beta, gamma) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in), optional :: beta, gamma
    integer(c_int) :: status
    real(c_double) :: b, g
    b = 0.25_c_double
    g = 0.5_c_double
    if (present(beta)) b = beta
    if (present(gamma)) g = gamma
    status = self%ready('set_newmark', 'structure')
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_newmark(self%ptr, b, g))
  end function struct_set_newmark

  !> HHT-alpha with -1/3 <= alpha <= 0. FRICREG_EINVAL; FRICREG_ENONFINITE.
  function struct_set_hht(self, alpha) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: alpha
    integer(c_int) :: status
    status = self%ready('set_hht', 'structure')
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_hht(self%ptr, alpha))
  end function struct_set_hht

  !> Explicit central difference (each step refused with FRICREG_ESTEP beyond its bounds).
  function struct_set_central_difference(self) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int) :: status
    status = self%ready('set_central_difference', 'structure')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_central_difference(self%ptr))
  end function struct_set_central_difference

  !> Newton's tolerance 0 < tol < 1 (default 1e-10) and 1 <= max_iter <= 1000 (default 50);
  !> an absent one is set to its default. FRICREG_EINVAL; FRICREG_ENONFINITE.
  function struct_set_newton(self, tol, max_iter) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in), optional :: tol
    integer, intent(in), optional :: max_iter
    integer(c_int) :: status
    real(c_double) :: t
    integer(c_int) :: n
    t = 1e-10_c_double
    n = 50
    if (present(tol)) t = tol
    if (present(max_iter)) n = int(max_iter, c_int)
    status = self%ready('set_newton', 'structure')
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_newton(self%ptr, t, n))
  end function struct_set_newton

  !> Install an observer of run and run_ode (a bind(C) function with interface
  !> fricreg_structure_observer), called after every step; user is passed back to it. With no
  !> observer, removes it (fricreg_structure_set_observer).
  function struct_set_observer(self, fricreg_observer, user) result(status)
    class(fricreg_structure), intent(inout) :: self
    procedure(fricreg_structure_observer), optional :: fricreg_observer
    type(c_ptr), intent(in), optional :: user
    integer(c_int) :: status
    type(c_funptr) :: fn
    type(c_ptr) :: u
    fn = c_null_funptr
    u = c_null_ptr
    if (present(fricreg_observer)) fn = c_funloc(fricreg_observer)
    if (present(user)) u = user
    status = self%ready('set_observer', 'structure')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_observer(self%ptr, fn, u))
  end function struct_set_observer

  !> Route the structure's warnings to a bind(C) subroutine with interface
  !> fricreg_warning_handler, called once per warning at the end of run and run_ode, and by
  !> warning_count for new ones (fricreg_structure_set_warning_handler); user is passed back
  !> to it. With no handler, removes it.
  function struct_set_warning_handler(self, fricreg_handler, user) result(status)
    class(fricreg_structure), intent(inout) :: self
    procedure(fricreg_warning_handler), optional :: fricreg_handler
    type(c_ptr), intent(in), optional :: user
    integer(c_int) :: status
    type(c_funptr) :: fn
    type(c_ptr) :: u
    fn = c_null_funptr
    u = c_null_ptr
    if (present(fricreg_handler)) fn = c_funloc(fricreg_handler)
    if (present(user)) u = user
    status = self%ready('set_warning_handler', 'structure')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_warning_handler(self%ptr, fn, u))
  end function struct_set_warning_handler

  !> Bound the adaptive steps accepted by one run_ode call (0: no bound; by default 10^4 for the
  !> laws that jump, 10^6 otherwise): a call that needs more returns FRICREG_EWORK
  !> (fricreg_structure_set_max_steps).
  function struct_set_max_steps(self, max_steps) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int64_t), intent(in) :: max_steps
    integer(c_int) :: status
    status = self%ready('set_max_steps', 'structure')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_max_steps(self%ptr, max_steps))
  end function struct_set_max_steps

  !> One step of dt > 0 with the selected scheme. FRICREG_EINVAL (dt, J never set);
  !> FRICREG_ENONFINITE; FRICREG_ESINGULAR; FRICREG_ESTEP; FRICREG_EDIVERGED. On failure the
  !> state is unchanged.
  function struct_step(self, dt) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: dt
    integer(c_int) :: status
    status = self%ready('step', 'structure')
    if (status == FRICREG_OK) status = self%record(fricreg_structure_step(self%ptr, dt))
  end function struct_step

  !> Steps of dt from the current time to t_end, the last one shortened to land on it. The
  !> codes of step, and FRICREG_EINVAL if t_end is not ahead; on failure the state is that of
  !> the last successful step.
  function struct_run(self, dt, t_end) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: dt, t_end
    integer(c_int) :: status
    status = self%ready('run', 'structure')
    if (status == FRICREG_OK) status = self%record(fricreg_structure_run(self%ptr, dt, t_end))
  end function struct_run

  !> Integrate to t_end with a GSL stepper (FRICREG_INT_*): fixed steps dt when rtol and atol
  !> are absent or 0, else adaptive with dt the first step (see C's fricreg_structure_run_ode);
  !> rtol > 0 without atol: the absolute tolerances from eps, FRICREG_ATOL_FROM_EPS (since 1.6;
  !> before, an absent atol was 0: pass atol = 0 for that).
  !> FRICREG_EINVAL; FRICREG_ENONFINITE; FRICREG_ESTEP; FRICREG_ESINGULAR; FRICREG_EDIVERGED;
  !> FRICREG_EINTEGRATOR; FRICREG_EWORK; FRICREG_ENOMEM.
  function struct_run_ode(self, integrator, dt, t_end, rtol, atol) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int), intent(in) :: integrator
    real(c_double), intent(in) :: dt, t_end
    real(c_double), intent(in), optional :: rtol, atol
    integer(c_int) :: status
    real(c_double) :: r, a
    ! FRICREG_ATOL_FROM_EPS of fricreg_sim.h, as in sim_set_integrator;
    ! test_structure_type.f90 checks that an absent atol gives the rule's tolerances.
    real(c_double), parameter :: atol_from_eps = -1.0_c_double
    r = 0.0_c_double
    a = 0.0_c_double
    if (present(rtol)) r = rtol
    if (r > 0.0_c_double) a = atol_from_eps
    if (present(atol)) a = atol
    status = self%ready('run_ode', 'structure')
    if (status == FRICREG_OK) status = self%record( &
                                       fricreg_structure_run_ode(self%ptr, integrator, dt, r, a, &
                                                                 t_end))
  end function struct_run_ode

  !> An absolute tolerance per component of run_ode's state y = (u, v, W_in, E_visc, D), size
  !> 2 ndof + 2 + m: ndof displacements, ndof velocities, the input work, the viscous and each
  !> contact's dissipation; each finite and > 0. Every later adaptive run_ode uses them in place
  !> of its atol; a size-0 atol removes them (fricreg_structure_set_ode_abs_tolerances).
  !> FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_EINVAL; FRICREG_ENOMEM. Since 1.6.
  function struct_set_ode_abs_tolerances(self, atol) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in), contiguous :: atol(:)
    integer(c_int) :: status
    real(c_double) :: none(1)
    status = self%ready('set_ode_abs_tolerances', 'structure')
    if (status /= FRICREG_OK) return
    if (size(atol) == 0) then ! C takes n = 0 with any pointer; an empty array may have none
      none = 0.0_c_double
      status = self%record(fricreg_structure_set_ode_abs_tolerances(self%ptr, 0_c_size_t, none))
    else
      status = self%record(fricreg_structure_set_ode_abs_tolerances(self%ptr, &
                                                                    int(size(atol), c_size_t), atol))
    end if
  end function struct_set_ode_abs_tolerances

  !> The absolute tolerances of the last adaptive run_ode per component of
  !> y = (u, v, W_in, E_visc, D), size 2 ndof + 2 + m: those set, the one atol, or the rule from
  !> eps (zeros before any adaptive run_ode; fricreg_structure_get_ode_abs_tolerances).
  !> FRICREG_ESIZE. Since 1.6.
  function struct_get_ode_abs_tolerances(self, atol) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: atol(:)
    integer(c_int) :: status
    status = struct_vector(self, 'get_ode_abs_tolerances', 'atol', atol, &
                           2_c_size_t * self%n + 2_c_size_t + self%m)
    if (status == FRICREG_OK) status = self%unrecorded('get_ode_abs_tolerances', &
                                       fricreg_structure_get_ode_abs_tolerances(self%ptr, &
                                       int(size(atol), c_size_t), atol))
  end function struct_get_ode_abs_tolerances

  !> The state now: u(ndof), v(ndof), a(ndof), each optional (at least one). Written only on
  !> success. FRICREG_ESIZE; FRICREG_ENULL if all three are absent.
  function struct_get_state(self, u, v, a) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous, optional :: u(:), v(:), a(:)
    integer(c_int) :: status
    status = self%ready('get_state', 'structure')
    if (status == FRICREG_OK .and. present(u)) &
      status = self%check_size('get_state', 'u', size(u), self%n)
    if (status == FRICREG_OK .and. present(v)) &
      status = self%check_size('get_state', 'v', size(v), self%n)
    if (status == FRICREG_OK .and. present(a)) &
      status = self%check_size('get_state', 'a', size(a), self%n)
    if (status == FRICREG_OK) &
      status = self%unrecorded('get_state', fricreg_structure_get_state(self%ptr, self%n, u, v, a))
  end function struct_get_state

  !> Save everything the run carries from one step to the next (fricreg_structure_save) into
  !> blob, (re)allocated to the checkpoint's length in bytes, for restore into a structure set
  !> up the same way, in this build on this machine (a file: write it with
  !> access='stream', form='unformatted'). FRICREG_EINVAL (from the observer; more than 64
  !> coupled contacts); FRICREG_ENOMEM.
  function struct_save(self, blob) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int8_t), allocatable, target, intent(inout) :: blob(:)
    integer(c_int) :: status
    integer(c_size_t) :: len
    integer :: stat
    status = self%ready('save', 'structure')
    if (status /= FRICREG_OK) return
    len = 0
    status = self%record(fricreg_structure_save(self%ptr, c_null_ptr, len))
    if (status /= FRICREG_OK) return
    if (allocated(blob)) deallocate(blob)
    allocate(blob(len), stat=stat)
    if (stat /= 0) then
      status = self%fail(FRICREG_ENOMEM, 'save: no memory for the checkpoint')
      return
    end if
    status = self%record(fricreg_structure_save(self%ptr, c_loc(blob), len))
  end function struct_save

  !> Restore a checkpoint of save (fricreg_structure_restore): the run continues bit for bit as
  !> the saved one would. FRICREG_EINVAL (not a checkpoint, truncated, corrupted, another build
  !> or another model: the message names the first difference); the set-up's statuses.
  function struct_restore(self, blob) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int8_t), intent(in), target, contiguous :: blob(:)
    integer(c_int) :: status
    status = self%ready('restore', 'structure')
    if (status /= FRICREG_OK) return
    if (size(blob) == 0) then
      status = self%fail(FRICREG_EINVAL, 'restore: the checkpoint is empty')
      return
    end if
    status = self%record(fricreg_structure_restore(self%ptr, c_loc(blob), &
                                                   int(size(blob), c_size_t)))
  end function struct_restore

  !> Friction forces f(m) of the current state (force units). FRICREG_ESIZE.
  function struct_get_forces(self, f) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: f(:)
    integer(c_int) :: status
    status = struct_vector(self, 'get_forces', 'f', f, self%m)
    if (status == FRICREG_OK) &
      status = self%unrecorded('get_forces', fricreg_structure_get_forces(self%ptr, self%m, f))
  end function struct_get_forces

  !> Energy dissipated by each contact since set_initial, D(m) (energy units). FRICREG_ESIZE.
  function struct_get_dissipation(self, D) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: D(:)
    integer(c_int) :: status
    status = struct_vector(self, 'get_dissipation', 'D', D, self%m)
    if (status == FRICREG_OK) status = self%unrecorded('get_dissipation', &
                                       fricreg_structure_get_dissipation(self%ptr, self%m, D))
  end function struct_get_dissipation

  !> Estimate the error of the peak displacements and of each contact's dissipation against
  !> eps -> 0 or not (0, the default): on = FRICREG_ESTIMATE_TWO_COMPANIONS (1) from companion
  !> structures at eps/2 and eps/4 stepped alongside at half and a quarter of the step (or an
  !> adaptive run's tolerances/16 and /256), the observed order's Richardson estimate or, out of
  !> the asymptotic range, a safe bound with FRICREG_WARN_NOT_ASYMPTOTIC;
  !> FRICREG_ESTIMATE_ONE_COMPANION (2), 1.6's err = 3 |q - q_companion|
  !> (fricreg_structure_set_error_estimate: made at the first step after set_initial, fed the
  !> setters of bounds, law, records, Newton and max_steps; another setter ends it).
  !> FRICREG_EINVAL if on is not 0, 1 or 2. Since 1.6; two companions since 1.7.
  function struct_set_error_estimate(self, on) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int), intent(in) :: on
    integer(c_int) :: status
    status = self%ready('set_error_estimate', 'structure')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_error_estimate(self%ptr, on))
  end function struct_set_error_estimate

  !> The peak displacements max |u_i| since set_initial, peak(ndof) (length units), sampled at
  !> every fixed step's end and every run_ode call's end (fricreg_structure_get_peak_displacement).
  !> FRICREG_ESIZE. Since 1.6.
  function struct_get_peak_displacement(self, peak) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: peak(:)
    integer(c_int) :: status
    status = struct_vector(self, 'get_peak_displacement', 'peak', peak, self%n)
    if (status == FRICREG_OK) status = self%unrecorded('get_peak_displacement', &
                                       fricreg_structure_get_peak_displacement(self%ptr, &
                                                                               self%n, peak))
  end function struct_get_peak_displacement

  !> The error estimate of each peak displacement, err(ndof) (length units; +Inf where the
  !> companion failed), fricreg_structure_get_peak_displacement_error. FRICREG_EINVAL without
  !> an estimate (off, no step since set_initial with it on, ended by a setter); FRICREG_ESIZE.
  !> Since 1.6.
  function struct_get_peak_displacement_error(self, err) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: err(:)
    integer(c_int) :: status
    status = struct_vector(self, 'get_peak_displacement_error', 'err', err, self%n)
    if (status == FRICREG_OK) status = self%unrecorded('get_peak_displacement_error', &
                                       fricreg_structure_get_peak_displacement_error(self%ptr, &
                                                                                     self%n, err))
  end function struct_get_peak_displacement_error

  !> The error estimate of each contact's dissipation, err(m) (energy units; +Inf where the
  !> companion failed), fricreg_structure_get_dissipation_error. FRICREG_EINVAL without an
  !> estimate; FRICREG_ESIZE. Since 1.6.
  function struct_get_dissipation_error(self, err) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: err(:)
    integer(c_int) :: status
    status = struct_vector(self, 'get_dissipation_error', 'err', err, self%m)
    if (status == FRICREG_OK) status = self%unrecorded('get_dissipation_error', &
                                       fricreg_structure_get_dissipation_error(self%ptr, &
                                                                               self%m, err))
  end function struct_get_dissipation_error

  !> One quantity (FRICREG_SVALUE_*: time, energies, the balance's residual) into value.
  !> FRICREG_EINVAL for an unknown one.
  function struct_get_value(self, which, value) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int), intent(in) :: which
    real(c_double), intent(inout) :: value
    integer(c_int) :: status
    status = self%ready('get_value', 'structure')
    if (status == FRICREG_OK) status = self%unrecorded('get_value', &
                                       fricreg_structure_get_value(self%ptr, which, value))
  end function struct_get_value

  !> One counter (FRICREG_SSTAT_*: steps, Newton iterations, max, failures, line-search cuts)
  !> into value. FRICREG_EINVAL for an unknown one.
  function struct_get_stat(self, which, value) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int), intent(in) :: which
    integer(c_int64_t), intent(inout) :: value
    integer(c_int) :: status
    status = self%ready('get_stat', 'structure')
    if (status == FRICREG_OK) status = self%unrecorded('get_stat', &
                                       fricreg_structure_get_stat(self%ptr, which, value))
  end function struct_get_stat

  !> Judge the checks of plausibility now and return how many warnings they raise (C's
  !> fricreg_structure_warning_count: the thresholds, in SI units, are in its docstring and in
  !> docs/structural.md "Warnings"); 0 if not created. Read them with get_warning. Since 1.6.
  integer function struct_warning_count(self)
    class(fricreg_structure), intent(inout) :: self
    struct_warning_count = 0
    if (c_associated(self%ptr)) &
      struct_warning_count = int(fricreg_structure_warning_count(self%ptr))
  end function struct_warning_count

  !> Warning k, 1 <= k <= warning_count() (one-based, as Fortran counts): its code
  !> (FRICREG_WARN_*) and its message. FRICREG_ENULL if not created; FRICREG_EINVAL if k is
  !> out of range (code FRICREG_WARN_NONE, message ''). Since 1.6.
  function struct_get_warning(self, k, code, message) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer, intent(in) :: k
    integer(c_int), intent(out) :: code
    character(len=:), allocatable, intent(out) :: message
    integer(c_int) :: status
    code = FRICREG_WARN_NONE
    message = ''
    status = self%ready('get_warning', 'structure')
    if (status /= FRICREG_OK) return
    if (k < 1) then
      status = self%unrecorded('get_warning', FRICREG_EINVAL)
      return
    end if
    status = self%unrecorded('get_warning', fricreg_structure_get_warning(self%ptr, &
                             int(k - 1, c_size_t), code, len=0_c_size_t))
    if (status == FRICREG_OK) &
      message = fricreg_c_string(fricreg_structure_warning_message(self%ptr, int(k - 1, c_size_t)))
  end function struct_get_warning

  ! ---- Harmonic balance (fricreg_hb.h) -----------------------------------------------------

  !> Create a driver for ndof >= 1 degrees of freedom, m >= 1 Jenkins elements and harmonics
  !> 1 <= H <= FRICREG_HB_MAX_HARMONICS. An object that held one gets the new one and releases
  !> the old (on failure it keeps the old). FRICREG_EINVAL; FRICREG_ENOMEM.
  function hb_create(self, ndof, m, harmonics) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: ndof, m, harmonics
    integer(c_int) :: status
    type(c_ptr) :: p
    character(len=80) :: buf
    write (buf, '(a, i0, a, i0, a, i0)') 'create: ndof = ', ndof, ', m = ', m, ', H = ', harmonics
    if (ndof < 1 .or. m < 1) then
      status = self%fail(FRICREG_EINVAL, trim(buf) // ': ndof and m must be >= 1')
      return
    end if
    p = c_null_ptr
    status = fricreg_hb_create(as_size(ndof), as_size(m), int(harmonics, c_int), p)
    if (status /= FRICREG_OK) then
      status = self%fail(status, trim(buf) // ': ' // fricreg_error_string(status))
      return
    end if
    call self%adopt(p, fricreg_hb_free, fricreg_hb_errcode, fricreg_hb_errmsg)
    self%n = as_size(ndof)
    self%m = as_size(m)
    self%rows = self%m
    self%nc = 2 * as_size(harmonics) + 1
  end function hb_create

  subroutine hb_final(self)
    type(fricreg_hb_driver), intent(inout) :: self
    call self%destroy()
  end subroutine hb_final

  !> Degrees of freedom (0 if not created).
  integer function hb_ndof(self)
    class(fricreg_hb_driver), intent(in) :: self
    hb_ndof = 0
    if (c_associated(self%ptr)) hb_ndof = int(self%n)
  end function hb_ndof

  !> Jenkins elements (0 if not created).
  integer function hb_nelements(self)
    class(fricreg_hb_driver), intent(in) :: self
    hb_nelements = 0
    if (c_associated(self%ptr)) hb_nelements = int(self%m)
  end function hb_nelements

  !> Harmonics H (0 if not created).
  integer function hb_harmonics(self)
    class(fricreg_hb_driver), intent(in) :: self
    hb_harmonics = 0
    if (c_associated(self%ptr)) hb_harmonics = int((self%nc - 1) / 2)
  end function hb_harmonics

  !> FRICREG_OK if self is created and a (rank 1 or 2) has the extents (n1, n2), else a
  !> recorded failure. Takes the array itself: shape(a) would be a temporary at each call.
  function hb_shape(self, what, name, a, n1, n2) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    character(len=*), intent(in) :: what, name
    real(c_double), intent(in) :: a(..)
    integer(c_size_t), intent(in) :: n1, n2
    integer(c_int) :: status
    status = self%ready(what, 'HB driver')
    if (status == FRICREG_OK) status = self%check_size(what, name // ', 1', size(a, 1), n1)
    if (status == FRICREG_OK .and. rank(a) > 1) &
      status = self%check_size(what, name // ', 2', size(a, 2), n2)
  end function hb_shape

  !> Mass matrix M(ndof, ndof), symmetric (the same numbers in C's row order).
  !> FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_ENOTSYM.
  function hb_set_mass(self, M) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in), contiguous :: M(:, :)
    integer(c_int) :: status
    status = self%hb_shape('set_mass', 'M', M, self%n, self%n)
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_mass(self%ptr, self%n, M))
  end function hb_set_mass

  !> Stiffness matrix K(ndof, ndof), symmetric and nonsingular. As set_mass.
  function hb_set_stiffness(self, K) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in), contiguous :: K(:, :)
    integer(c_int) :: status
    status = self%hb_shape('set_stiffness', 'K', K, self%n, self%n)
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_stiffness(self%ptr, self%n, K))
  end function hb_set_stiffness

  !> Damping matrix C(ndof, ndof), symmetric; replaces Rayleigh damping. As set_mass.
  function hb_set_damping(self, C) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in), contiguous :: C(:, :)
    integer(c_int) :: status
    status = self%hb_shape('set_damping', 'C', C, self%n, self%n)
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_damping(self%ptr, self%n, C))
  end function hb_set_damping

  !> Rayleigh damping C = a0 M + a1 K (a0 in 1/s, a1 in s, both >= 0). FRICREG_EINVAL;
  !> FRICREG_ENONFINITE.
  function hb_set_rayleigh(self, a0, a1) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: a0, a1
    integer(c_int) :: status
    status = self%ready('set_rayleigh', 'HB driver')
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_rayleigh(self%ptr, a0, a1))
  end function hb_set_rayleigh

  !> The elements: J(m, ndof) in Fortran's order (row i gives element i's relative
  !> displacement; passed transposed to C, which reads it row-major), stiffnesses kt(m) > 0
  !> and slip forces mun(m) >= 0. FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_EINVAL.
  function hb_set_elements(self, J, kt, mun) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: J(:, :)
    real(c_double), intent(in), contiguous :: kt(:), mun(:)
    integer(c_int) :: status
    real(c_double), allocatable :: Jc(:, :) ! J transposed: C's row-major J
    status = self%hb_shape('set_elements', 'J', J, self%m, self%n)
    if (status == FRICREG_OK) status = self%hb_shape('set_elements', 'kt', kt, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape('set_elements', 'mun', mun, self%m, 0_c_size_t)
    if (status == FRICREG_OK) allocate (Jc, source=transpose(J))
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_elements(self%ptr, self%m, &
                                                     self%n, Jc, kt, mun))
    if (status == FRICREG_OK) self%rows = self%m
  end function hb_set_elements

  !> Iwan elements instead: J(m, ndof) as set_elements; element i's ns sliders have the
  !> stiffnesses k(:, i) > 0 and slip forces phi(:, i) >= 0, k and phi (ns, m) (C's row-major
  !> k[m ns], the same numbers); set_elements is the case ns = 1 and each replaces the other.
  !> FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_EINVAL; FRICREG_ENOMEM.
  function hb_set_iwan(self, J, k, phi) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: J(:, :)
    real(c_double), intent(in), contiguous :: k(:, :), phi(:, :)
    integer(c_int) :: status
    real(c_double), allocatable :: Jc(:, :) ! J transposed: C's row-major J
    status = self%hb_shape('set_iwan', 'J', J, self%m, self%n)
    if (status == FRICREG_OK) status = self%hb_shape('set_iwan', 'k', k, &
                                                     int(size(k, 1), c_size_t), self%m)
    if (status == FRICREG_OK) status = self%hb_shape('set_iwan', 'phi', phi, &
                                                     int(size(k, 1), c_size_t), self%m)
    if (status == FRICREG_OK) allocate (Jc, source=transpose(J))
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_iwan(self%ptr, self%m, &
                                                     self%n, Jc, &
                                                     int(size(k, 1), c_size_t), k, phi))
    if (status == FRICREG_OK) self%rows = self%m
  end function hb_set_iwan

  !> Jenkins elements under a normal load with lift-off instead (fricreg_hb_set_normal_elements):
  !> Jt(m, ndof), Jn(m, ndof) as set_elements's J (tangential and normal rows, g positive
  !> pressing), kt(m) > 0, mu(m) >= 0, n0(m) the preloads, kn(m) >= 0; the normal force
  !> max(0, N0 + kn g), the slip bound mu N. q then has 2 m columns: column 2i - 1 element i's
  !> u, column 2i its g. Each element setter replaces the others. FRICREG_ESIZE;
  !> FRICREG_ENONFINITE; FRICREG_EINVAL; FRICREG_ENOMEM.
  function hb_set_normal_elements(self, Jt, Jn, kt, mu, n0, kn) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: Jt(:, :), Jn(:, :)
    real(c_double), intent(in), contiguous :: kt(:), mu(:), n0(:), kn(:)
    integer(c_int) :: status
    character(len=*), parameter :: fn = 'set_normal_elements'
    real(c_double), allocatable :: Jtc(:, :), Jnc(:, :) ! transposed: C's row-major Jt, Jn
    status = self%hb_shape(fn, 'Jt', Jt, self%m, self%n)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'Jn', Jn, self%m, self%n)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'kt', kt, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'mu', mu, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'n0', n0, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'kn', kn, self%m, 0_c_size_t)
    if (status == FRICREG_OK) allocate (Jtc, source=transpose(Jt))
    if (status == FRICREG_OK) allocate (Jnc, source=transpose(Jn))
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_set_normal_elements(self%ptr, self%m, self%n, &
                                                          Jtc, Jnc, kt, mu, &
                                                          n0, kn))
    if (status == FRICREG_OK) self%rows = 2 * self%m
  end function hb_set_normal_elements

  !> The excitation of the fundamental, p(t) = pc cos(Omega t) + ps sin(Omega t): pc(ndof),
  !> ps(ndof), force units. FRICREG_ESIZE; FRICREG_ENONFINITE.
  function hb_set_excitation(self, pc, ps) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in), contiguous :: pc(:), ps(:)
    integer(c_int) :: status
    status = self%hb_shape('set_excitation', 'pc', pc, self%n, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape('set_excitation', 'ps', ps, self%n, 0_c_size_t)
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_excitation(self%ptr, self%n, &
                                                     pc, ps))
  end function hb_set_excitation

  !> Newton's tolerance and iteration bound (fricreg_hb_set_newton). FRICREG_EINVAL;
  !> FRICREG_ENONFINITE.
  function hb_set_newton(self, tol, max_iter) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: tol
    integer, intent(in) :: max_iter
    integer(c_int) :: status
    status = self%ready('set_newton', 'HB driver')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_set_newton(self%ptr, tol, int(max_iter, c_int)))
  end function hb_set_newton

  !> Install a monitor (a bind(C) function with interface fricreg_hb_monitor), called before
  !> every Newton step of every solve; user is passed back to it. With no monitor, removes it
  !> (fricreg_hb_set_monitor). A nonzero return stops the call with FRICREG_EWORK, the points
  !> reached kept; from the monitor only the getters may be called (FRICREG_EINVAL).
  function hb_set_monitor(self, fricreg_monitor, user) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    procedure(fricreg_hb_monitor), optional :: fricreg_monitor
    type(c_ptr), intent(in), optional :: user
    integer(c_int) :: status
    type(c_funptr) :: fn
    type(c_ptr) :: u
    fn = c_null_funptr
    u = c_null_ptr
    if (present(fricreg_monitor)) fn = c_funloc(fricreg_monitor)
    if (present(user)) u = user
    status = self%ready('set_monitor', 'HB driver')
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_monitor(self%ptr, fn, u))
  end function hb_set_monitor

  !> Bound the Newton steps of one solving call at total (0: no bound, the default;
  !> fricreg_hb_set_max_iterations); a call that needs more returns FRICREG_EWORK.
  !> FRICREG_EINVAL if total < 0 or called from the monitor.
  function hb_set_max_iterations(self, total) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer(c_int64_t), intent(in) :: total
    integer(c_int) :: status
    status = self%ready('set_max_iterations', 'HB driver')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_set_max_iterations(self%ptr, total))
  end function hb_set_max_iterations

  !> The continuation's step control (fricreg_hb_set_continuation). FRICREG_EINVAL;
  !> FRICREG_ENONFINITE; FRICREG_ENOMEM.
  function hb_set_continuation(self, ds, ds_min, ds_max, max_points) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: ds, ds_min, ds_max
    integer, intent(in) :: max_points
    integer(c_int) :: status
    status = self%ready('set_continuation', 'HB driver')
    if (status == FRICREG_OK .and. max_points < 0) &
      status = self%fail(FRICREG_EINVAL, 'set_continuation: max_points must be >= 1')
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_continuation(self%ptr, ds, &
                                                     ds_min, ds_max, as_size(max_points)))
  end function hb_set_continuation

  !> Solve at the frequency omega into q(2H+1, m) (2 m columns with set_normal_elements), from
  !> the guess q0 (same shape) or, absent,
  !> the linear response. The statuses of fricreg_hb_solve; FRICREG_ESIZE.
  function hb_solve(self, omega, q, q0) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: omega
    real(c_double), intent(inout), contiguous :: q(:, :)
    real(c_double), intent(in), contiguous, optional :: q0(:, :)
    integer(c_int) :: status
    status = self%hb_shape('solve', 'q', q, self%nc, self%rows)
    if (status == FRICREG_OK .and. present(q0)) &
      status = self%hb_shape('solve', 'q0', q0, self%nc, self%rows)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_solve(self%ptr, omega, self%nc * self%rows, q0, q))
  end function hb_solve

  !> The displacements' coefficients of the last solution, x(2H+1, ndof) (column k dof k).
  !> The statuses of fricreg_hb_displacement; FRICREG_ESIZE.
  function hb_displacement(self, x) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: x(:, :)
    integer(c_int) :: status
    status = self%hb_shape('displacement', 'x', x, self%nc, self%n)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_displacement(self%ptr, self%n, self%nc, x))
  end function hb_displacement

  !> Follow the response from omega0 to omega1 (fricreg_hb_continue), from the guess q0(2H+1,
  !> m) at omega0 or, absent, the linear response. Its statuses; FRICREG_ESIZE.
  function hb_continue(self, omega0, omega1, q0) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: omega0, omega1
    real(c_double), intent(in), contiguous, optional :: q0(:, :)
    integer(c_int) :: status
    status = self%ready('continue', 'HB driver')
    if (status == FRICREG_OK .and. present(q0)) &
      status = self%hb_shape('continue', 'q0', q0, self%nc, self%rows)
    if (status == FRICREG_OK) status = self%record(fricreg_hb_continue(self%ptr, omega0, omega1, &
                                                     self%nc * self%rows, q0))
  end function hb_continue

  !> Follow the response at the frequency omega from the excitation level level0 to level1
  !> (the excitation times λ; fricreg_hb_continue_level), from the guess q0(2H+1, m) at level0
  !> or, absent, the stuck response. Its statuses; FRICREG_ESIZE.
  function hb_continue_level(self, omega, level0, level1, q0) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: omega, level0, level1
    real(c_double), intent(in), contiguous, optional :: q0(:, :)
    integer(c_int) :: status
    status = self%ready('continue_level', 'HB driver')
    if (status == FRICREG_OK .and. present(q0)) &
      status = self%hb_shape('continue_level', 'q0', q0, self%nc, self%rows)
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_continue_level(self%ptr, omega, level0, level1, &
                                                     self%nc * self%rows, q0))
  end function hb_continue_level

  !> Number of points of the last continuation (0 if none).
  integer function hb_points(self)
    class(fricreg_hb_driver), intent(in) :: self
    hb_points = int(fricreg_hb_points(self%ptr))
  end function hb_points

  !> Point k (1 <= k <= points()): its frequency omega and the RMS of each dof, rms(ndof).
  !> FRICREG_EINVAL for k out of range; FRICREG_ESIZE.
  function hb_point(self, k, omega, rms) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: k
    real(c_double), intent(inout) :: omega
    real(c_double), intent(inout), contiguous :: rms(:)
    integer(c_int) :: status
    status = self%hb_shape('point', 'rms', rms, self%n, 0_c_size_t)
    if (status == FRICREG_OK .and. k < 1) &
      status = self%fail(FRICREG_EINVAL, 'point: k must be >= 1 (Fortran counts from 1)')
    if (status == FRICREG_OK) status = self%record(fricreg_hb_point(self%ptr, as_size(k - 1), &
                                                     omega, self%n, rms))
  end function hb_point

  !> The excitation level λ of point k (1 <= k <= points()): a level branch's parameter, 1 on
  !> an Ω branch (fricreg_hb_point_level). FRICREG_EINVAL for k out of range.
  function hb_point_level(self, k, level) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: k
    real(c_double), intent(inout) :: level
    integer(c_int) :: status
    status = self%ready('point_level', 'HB driver')
    if (status == FRICREG_OK .and. k < 1) &
      status = self%fail(FRICREG_EINVAL, 'point_level: k must be >= 1 (Fortran counts from 1)')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_point_level(self%ptr, as_size(k - 1), level))
  end function hb_point_level

  !> The largest RMS of dof `dof` (1 <= dof <= ndof) along the last continuation's branch,
  !> located between its points (fricreg_hb_peak): its frequency omega and that RMS.
  !> FRICREG_EINVAL for dof out of range or no branch.
  function hb_peak(self, dof, omega, rms) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: dof
    real(c_double), intent(inout) :: omega, rms
    integer(c_int) :: status
    status = self%ready('peak', 'HB driver')
    if (status == FRICREG_OK .and. dof < 1) &
      status = self%fail(FRICREG_EINVAL, 'peak: dof must be >= 1 (Fortran counts from 1)')
    if (status == FRICREG_OK) status = self%record(fricreg_hb_peak(self%ptr, as_size(dof - 1), &
                                                     omega, rms))
  end function hb_peak

  !> Compute each solution's stability by Hill's method from now on (enable .true.), or stop
  !> (fricreg_hb_set_stability). FRICREG_EINVAL (a sparse model, or too many coefficients);
  !> FRICREG_ENOMEM.
  function hb_set_stability(self, enable) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    logical, intent(in) :: enable
    integer(c_int) :: status
    integer(c_int) :: on
    on = 0
    if (enable) on = 1
    status = self%ready('set_stability', 'HB driver')
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_stability(self%ptr, on))
  end function hb_set_stability

  !> The stability of point k (1 <= k <= points()), or with k = 0 of the last solution
  !> (fricreg_hb_point_stability): stable, and the largest |Floquet multiplier| mu_max.
  !> FRICREG_EINVAL for stability off, k out of range or no solution.
  function hb_stability(self, k, stable, mu_max) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: k
    logical, intent(inout) :: stable
    real(c_double), intent(inout) :: mu_max
    integer(c_int) :: status, flag
    integer(c_size_t) :: idx
    status = self%ready('point_stability', 'HB driver')
    if (status == FRICREG_OK .and. k < 0) &
      status = self%fail(FRICREG_EINVAL, 'point_stability: k must be >= 0 (0: the last solution)')
    if (status /= FRICREG_OK) return
    idx = -1_c_size_t ! FRICREG_HB_SOLUTION, (size_t)-1
    if (k > 0) idx = as_size(k - 1)
    flag = 0
    status = self%record(fricreg_hb_point_stability(self%ptr, idx, flag, mu_max))
    if (status == FRICREG_OK) stable = flag /= 0
  end function hb_stability

  !> The estimate of each dof's error from truncating at H harmonics, rms_error(ndof), and of
  !> its fundamental's amplitude, amplitude_error(ndof) (optional), at point k (1 <= k <=
  !> points()) or with k = 0 of the last solution (fricreg_hb_truncation_error: one solve at
  !> 2H + 1). FRICREG_EINVAL for k out of range, no solution or H > 19; FRICREG_ESIZE; the
  !> statuses of the solve at 2H + 1.
  function hb_truncation_error(self, k, rms_error, amplitude_error) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: k
    real(c_double), intent(inout), contiguous :: rms_error(:)
    real(c_double), intent(inout), contiguous, optional :: amplitude_error(:)
    integer(c_int) :: status
    integer(c_size_t) :: idx
    status = self%hb_shape('truncation_error', 'rms_error', rms_error, self%n, 0_c_size_t)
    if (status == FRICREG_OK .and. present(amplitude_error)) status = &
      self%hb_shape('truncation_error', 'amplitude_error', amplitude_error, self%n, 0_c_size_t)
    if (status == FRICREG_OK .and. k < 0) status = self%fail(FRICREG_EINVAL, &
      'truncation_error: k must be >= 0 (0: the last solution)')
    if (status /= FRICREG_OK) return
    idx = -1_c_size_t ! FRICREG_HB_SOLUTION, (size_t)-1
    if (k > 0) idx = as_size(k - 1)
    status = self%record(fricreg_hb_truncation_error(self%ptr, idx, self%n, rms_error, &
                                                     amplitude_error))
  end function hb_truncation_error

  !> The number of bifurcations the last continuation located (fricreg_hb_bifurcations).
  integer function hb_bifurcations(self)
    class(fricreg_hb_driver), intent(in) :: self
    hb_bifurcations = int(fricreg_hb_bifurcations(self%ptr))
  end function hb_bifurcations

  !> Bifurcation i (1 <= i <= bifurcations()): its type (FRICREG_HB_TP, _BP, _PD, _NS), its
  !> frequency omega, the point (from 1) it follows, and the RMS of each dof, rms(ndof)
  !> (fricreg_hb_bifurcation). FRICREG_EINVAL for i out of range; FRICREG_ESIZE.
  function hb_bifurcation(self, i, type, omega, point, rms) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: i
    integer, intent(inout) :: type, point
    real(c_double), intent(inout) :: omega
    real(c_double), intent(inout), contiguous :: rms(:)
    integer(c_int) :: status, t
    integer(c_size_t) :: k
    status = self%hb_shape('bifurcation', 'rms', rms, self%n, 0_c_size_t)
    if (status == FRICREG_OK .and. i < 1) &
      status = self%fail(FRICREG_EINVAL, 'bifurcation: i must be >= 1 (Fortran counts from 1)')
    if (status /= FRICREG_OK) return
    t = 0
    k = 0
    status = self%record(fricreg_hb_bifurcation(self%ptr, as_size(i - 1), t, omega, k, self%n, &
                                                rms))
    if (status == FRICREG_OK) then
      type = int(t)
      point = int(k) + 1
    end if
  end function hb_bifurcation

  !> The excitation level λ of bifurcation i (1 <= i <= bifurcations()), 1 on an Ω branch
  !> (fricreg_hb_bifurcation_level). FRICREG_EINVAL for i out of range.
  function hb_bifurcation_level(self, i, level) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: i
    real(c_double), intent(inout) :: level
    integer(c_int) :: status
    status = self%ready('bifurcation_level', 'HB driver')
    if (status == FRICREG_OK .and. i < 1) &
      status = self%fail(FRICREG_EINVAL, &
                         'bifurcation_level: i must be >= 1 (Fortran counts from 1)')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_bifurcation_level(self%ptr, as_size(i - 1), level))
  end function hb_bifurcation_level

  !> The backbone of mode `mode` (1 <= mode <= ndof, by increasing linearized frequency) at
  !> npoints modal amplitudes from a0 to a1 (fricreg_hb_nma: the extended periodic motion
  !> concept); damping one of FRICREG_HB_NMA_DAMPING_MATRIX (absent) or _MODAL. Its statuses.
  function hb_nma(self, mode, a0, a1, npoints, damping) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: mode, npoints
    real(c_double), intent(in) :: a0, a1
    integer(c_int), intent(in), optional :: damping
    integer(c_int) :: status, d
    d = FRICREG_HB_NMA_DAMPING_MATRIX
    if (present(damping)) d = damping
    status = self%ready('nma', 'HB driver')
    if (status == FRICREG_OK .and. (mode < 1 .or. npoints < 0)) &
      status = self%fail(FRICREG_EINVAL, 'nma: mode must be >= 1 (Fortran counts from 1), '// &
                         'npoints >= 0')
    if (status == FRICREG_OK) status = self%record(fricreg_hb_nma(self%ptr, as_size(mode - 1), d, &
                                                     a0, a1, as_size(npoints)))
  end function hb_nma

  !> Number of points of the last backbone (0 if none).
  integer function hb_nma_points(self)
    class(fricreg_hb_driver), intent(in) :: self
    hb_nma_points = int(fricreg_hb_nma_points(self%ptr))
  end function hb_nma_points

  !> Point i (1 <= i <= nma_points()) of the last backbone: its modal amplitude, natural
  !> frequency omega (rad/s), damping ratio zeta and, if present, the displacements'
  !> coefficients x(2H+1, ndof) (column k dof k), fricreg_hb_nma_point. Its statuses;
  !> FRICREG_ESIZE.
  function hb_nma_point(self, i, amplitude, omega, zeta, x) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: i
    real(c_double), intent(inout) :: amplitude, omega, zeta
    real(c_double), intent(inout), contiguous, optional :: x(:, :)
    integer(c_int) :: status
    status = self%ready('nma_point', 'HB driver')
    if (status == FRICREG_OK .and. present(x)) &
      status = self%hb_shape('nma_point', 'x', x, self%nc, self%n)
    if (status == FRICREG_OK .and. i < 1) &
      status = self%fail(FRICREG_EINVAL, 'nma_point: i must be >= 1 (Fortran counts from 1)')
    if (status == FRICREG_OK) status = self%record(fricreg_hb_nma_point(self%ptr, as_size(i - 1), &
                                                     amplitude, omega, zeta, self%n, self%nc, x))
  end function hb_nma_point
#endif

end module fricreg
