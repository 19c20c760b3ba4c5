! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_structure.F90 — module fricreg_structure_m: type fricreg_structure, a linear structure
! with friction contacts (fricreg_structure.h), and its procedures. Built with the drivers only
! (FRICREG_DRIVERS).
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_structure_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_ptr, c_funptr, &
                                         c_null_ptr, c_null_funptr, c_associated, c_loc, &
                                         c_funloc, c_int8_t, c_null_char
  use fricreg_c
  use fricreg_sim_c
  use fricreg_base_m, only: fricreg_object, fricreg_error_string, as_size
  implicit none
  private
  public :: fricreg_structure

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
    procedure :: add_elements => struct_add_elements
    procedure :: clear_elements => struct_clear_elements
    procedure :: element_count => struct_element_count
    procedure :: get_elements => struct_get_elements
    procedure :: set_jenkins => struct_set_jenkins
    procedure :: get_jenkins_state => struct_get_jenkins_state
    procedure :: set_jenkins_2d => struct_set_jenkins_2d
    procedure :: get_jenkins_2d_state => struct_get_jenkins_2d_state
    procedure :: set_iwan => struct_set_iwan
    procedure :: get_iwan_state => struct_get_iwan_state
    procedure :: set_jenkins_normal => struct_set_jenkins_normal
    procedure :: set_iwan_normal => struct_set_iwan_normal
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
    procedure, private :: struct_set_matrix_dense, struct_set_matrix_compressed
    generic :: set_matrix => struct_set_matrix_dense, struct_set_matrix_compressed
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
    procedure :: set_answer_rtol => struct_set_answer_rtol
    procedure :: set_error_companions => struct_set_error_companions
    procedure :: set_contact_solver => struct_set_contact_solver
    procedure :: contact_solver => struct_contact_solver
    procedure :: get_peak_displacement => struct_get_peak_displacement
    procedure :: get_peak_displacement_error => struct_get_peak_displacement_error
    procedure :: get_dissipation_error => struct_get_dissipation_error
    procedure :: get_jenkins_dissipation_error => struct_get_jenkins_dissipation_error
    procedure :: get_error_kind => struct_get_error_kind
    procedure :: get_value => struct_get_value
    procedure :: get_stat => struct_get_stat
    procedure :: warning_count => struct_warning_count
    procedure :: get_warning => struct_get_warning
    procedure :: save => struct_save
    procedure :: restore => struct_restore
    final :: struct_final
  end type

contains

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

  !> Elements of the type called name (fricreg_element_lookup; ns sliders for an Iwan type,
  !> default 1) beside those the structure holds, of any types (fricreg_structure_add_elements):
  !> element i's dim components (the type's: tangential, then the normal one) on rows
  !> (i-1) dim + 1 .. i dim of J(me dim, ndof) in Fortran's order, its parameters params(:, i)
  !> in the type's layout (fricreg_element.h); me = size(params, 2). Every element, the held
  !> ones too, starts again at rest. FRICREG_EINVAL for an unknown name or ns; FRICREG_ESIZE
  !> unless params has the type's nparams rows and J is (me dim, ndof); C's codes.
  function struct_add_elements(self, name, J, params, ns) result(status)
    class(fricreg_structure), intent(inout) :: self
    character(len=*), intent(in) :: name
    real(c_double), intent(in) :: J(:, :)
    real(c_double), intent(in), contiguous :: params(:, :)
    integer, intent(in), optional :: ns
    integer(c_int) :: status
    type(c_ptr) :: t
    integer :: n
    real(c_double), allocatable :: Jc(:, :) ! J transposed: C's row-major J
    n = 1
    if (present(ns)) n = ns
    status = self%ready('add_elements', 'structure')
    if (status /= FRICREG_OK) return
    t = c_null_ptr
    if (n >= 1) t = fricreg_element_sliders(fricreg_element_lookup(trim(name) // c_null_char), &
                                            int(n, c_size_t))
    if (.not. c_associated(t)) then
      status = self%fail(FRICREG_EINVAL, 'add_elements: no element type "' // trim(name) // &
                         '" with that many sliders')
      return
    end if
    status = self%check_size('add_elements', 'params, 1', size(params, 1), &
                             fricreg_element_nparams(t))
    if (status == FRICREG_OK) status = self%check_size('add_elements', 'J, 1', size(J, 1), &
                                                       int(size(params, 2), c_size_t) * &
                                                       int(fricreg_element_dim(t), c_size_t))
    if (status == FRICREG_OK) status = self%check_size('add_elements', 'J, 2', size(J, 2), self%n)
    if (status == FRICREG_OK) allocate (Jc, source=transpose(J))
    if (status == FRICREG_OK) status = self%record( &
                                       fricreg_structure_add_elements(self%ptr, t, &
                                                                      int(size(params, 2), &
                                                                          c_size_t), &
                                                                      self%n, Jc, params))
  end function struct_add_elements

  !> Remove every element (fricreg_structure_clear_elements).
  function struct_clear_elements(self) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int) :: status
    status = self%ready('clear_elements', 'structure')
    if (status == FRICREG_OK) status = self%record(fricreg_structure_clear_elements(self%ptr))
  end function struct_clear_elements

  !> The number of elements held, of all types (fricreg_structure_element_count; 0 before
  !> create).
  integer function struct_element_count(self)
    class(fricreg_structure), intent(in) :: self
    struct_element_count = 0
    if (c_associated(self%ptr)) struct_element_count = int(fricreg_structure_element_count(self%ptr))
  end function struct_element_count

  !> The elements' forces f(sum dim_i), states state(sum nstate_i) and dissipations D(me), in
  !> the order added (fricreg_structure_get_elements); each optional, at least one given; me =
  !> element_count(). FRICREG_ESIZE if D is not of size me; FRICREG_ENULL if none is given.
  function struct_get_elements(self, f, state, D) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous, optional :: f(:), state(:), D(:)
    integer(c_int) :: status
    integer(c_size_t) :: me
    status = self%ready('get_elements', 'structure')
    if (status /= FRICREG_OK) return
    me = fricreg_structure_element_count(self%ptr)
    if (present(D)) status = self%check_size('get_elements', 'D', size(D), me)
    if (status == FRICREG_OK) status = self%unrecorded('get_elements', &
                                                       fricreg_structure_get_elements(self%ptr, &
                                                                                      me, f, &
                                                                                      state, D))
  end function struct_get_elements

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

  !> Iwan elements with a normal load and lift-off (fricreg_structure_set_iwan_normal): rows of
  !> Je(me, ndof) and Jn(me, ndof) in Fortran's order, ns = size(k, 1) sliders each, slider s of
  !> element i a spring k(s, i) bounded by mu(s, i) N, N = max(0, n0 + kn g), g = (Jn u)_i;
  !> me = size(Je, 1). FRICREG_ESIZE unless Je and Jn have one shape with ndof columns, k and mu
  !> are (ns, me) arrays of one shape and n0, kn have me entries; C's codes otherwise. Since 1.7.
  function struct_set_iwan_normal(self, Je, Jn, k, mu, n0, kn) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: Je(:, :), Jn(:, :)
    real(c_double), intent(in), contiguous :: k(:, :), mu(:, :), n0(:), kn(:)
    integer(c_int) :: status
    integer(c_size_t) :: me
    character(len=*), parameter :: who = 'set_iwan_normal'
    real(c_double), allocatable :: Jec(:, :), Jnc(:, :) ! transposed: C's row-major Je, Jn
    me = int(size(Je, 1), c_size_t)
    status = self%ready(who, 'structure')
    if (status == FRICREG_OK) status = self%check_size(who, 'Je, 2', size(Je, 2), self%n)
    if (status == FRICREG_OK) status = self%check_size(who, 'Jn, 1', size(Jn, 1), me)
    if (status == FRICREG_OK) status = self%check_size(who, 'Jn, 2', size(Jn, 2), self%n)
    if (status == FRICREG_OK) status = self%check_size(who, 'k, 2', size(k, 2), me)
    if (status == FRICREG_OK) status = self%check_size(who, 'mu, 1', size(mu, 1), &
                                                       int(size(k, 1), c_size_t))
    if (status == FRICREG_OK) status = self%check_size(who, 'mu, 2', size(mu, 2), me)
    if (status == FRICREG_OK) status = self%check_size(who, 'n0', size(n0), me)
    if (status == FRICREG_OK) status = self%check_size(who, 'kn', size(kn), me)
    if (status == FRICREG_OK) allocate (Jec, source=transpose(Je))
    if (status == FRICREG_OK) allocate (Jnc, source=transpose(Jn))
    if (status == FRICREG_OK) status = self%record( &
                                       fricreg_structure_set_iwan_normal(self%ptr, me, self%n, &
                                                                         Jec, Jnc, &
                                                                         int(size(k, 1), &
                                                                             c_size_t), &
                                                                         k, mu, n0, kn))
  end function struct_set_iwan_normal

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
  !> nnz entries ptr says (fricreg_object's check_sparse), else a recorded failure.
  function struct_compressed(self, what, ptr_name, ind_name, flags, n, ptr, ind, values) &
      result(status)
    class(fricreg_structure), intent(inout) :: self
    character(len=*), intent(in) :: what, ptr_name, ind_name
    integer(c_int), intent(in) :: flags
    integer(c_size_t), intent(in) :: n
    integer(c_int64_t), intent(in) :: ptr(:), ind(:)
    real(c_double), intent(in) :: values(:)
    integer(c_int) :: status
    status = self%ready(what, 'structure')
    if (status == FRICREG_OK) &
      status = self%check_sparse(what, ptr_name, ind_name, flags, n, ptr, ind, values)
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

  !> One setter of every model matrix, in any storage (C's fricreg_structure_set_matrix), a
  !> generic of two forms told apart by their arguments:
  !>   st%set_matrix(which, values)                          dense values(:, :)
  !>   st%set_matrix(which, format, ptr, ind, values, flags) compressed, values(:)
  !> which: FRICREG_MASS, FRICREG_STIFFNESS, FRICREG_DAMPING or FRICREG_CONTACTS. Each call is
  !> the older setter of that matrix and storage (set_mass, set_contacts, set_mass_csc,
  !> set_contacts_csr, ...): the same checks and results, C's message naming set_matrix.
  !> Dense: values in Fortran's natural shape, (ndof, ndof) for M, K, C (symmetric: passed as
  !> they are, as set_mass) or J(m, ndof) (passed transposed, as set_contacts).
  !> FRICREG_ESIZE unless values has that shape; C's codes (FRICREG_EINVAL for an unknown which,
  !> with no size checked here).
  function struct_set_matrix_dense(self, which, values) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int), intent(in) :: which
    real(c_double), intent(in), contiguous :: values(:, :)
    integer(c_int) :: status
    character(len=*), parameter :: fn = 'set_matrix'
    real(c_double), allocatable :: Jc(:, :) ! J transposed: C's row-major J
    status = self%ready(fn, 'structure')
    if (status /= FRICREG_OK) return
    if (which == FRICREG_CONTACTS) then
      status = self%check_size(fn, 'values, 1', size(values, 1), self%m)
      if (status == FRICREG_OK) status = self%check_size(fn, 'values, 2', size(values, 2), self%n)
      if (status == FRICREG_OK) allocate (Jc, source=transpose(values))
      if (status == FRICREG_OK) status = self%record(fricreg_structure_set_matrix(self%ptr, &
                                                     which, self%m, self%n, &
                                                     FRICREG_MATRIX_DENSE, values=Jc))
    else if (which >= FRICREG_MASS .and. which <= FRICREG_DAMPING) then
      status = self%check_square(fn, 'values', values, self%n)
      if (status == FRICREG_OK) status = self%record(fricreg_structure_set_matrix(self%ptr, &
                                                     which, self%n, self%n, &
                                                     FRICREG_MATRIX_DENSE, values=values))
    else ! C refuses which before reading anything
      status = self%record(fricreg_structure_set_matrix(self%ptr, which, self%n, self%n, &
                                                        FRICREG_MATRIX_DENSE, values=values))
    end if
  end function struct_set_matrix_dense

  !> The compressed form of set_matrix: format FRICREG_MATRIX_CSR (ptr(nrows + 1) row pointers,
  !> ind(nnz) columns) or FRICREG_MATRIX_CSC (ptr(ndof + 1) column pointers, ind(nnz) rows),
  !> of kind c_int64_t, values(nnz); nrows ndof, or m for J. flags (fricreg_sparse_flags) as
  !> set_mass_csr: absent, FRICREG_SPARSE_ONE_BASED; C is given ior(format, flags). A
  !> symmetric M, K or C may be given by one triangle (+ FRICREG_SPARSE_LOWER or _UPPER), J not.
  !> FRICREG_ESIZE unless ptr has its n + 1 elements and ind and values at least nnz;
  !> FRICREG_EINVAL for a format that is neither (a dense matrix is values(:, :)), and C's codes
  !> (FRICREG_EINVAL for an unknown which or both formats, with no size checked here).
  function struct_set_matrix_compressed(self, which, format, ptr, ind, values, flags) &
      result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int), intent(in) :: which, format
    integer(c_int64_t), intent(in), contiguous :: ptr(:), ind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int), intent(in), optional :: flags
    integer(c_int) :: status, f, layout
    integer(c_size_t) :: nrows
    character(len=*), parameter :: fn = 'set_matrix'
    character(len=64) :: buf
    f = ior(format, struct_sparse_flags(flags))
    layout = iand(f, ior(FRICREG_MATRIX_CSR, FRICREG_MATRIX_CSC))
    status = self%ready(fn, 'structure')
    if (status /= FRICREG_OK) return
    if (layout == FRICREG_MATRIX_DENSE) then
      write (buf, '(a, i0)') 'set_matrix: format = ', format
      status = self%fail(FRICREG_EINVAL, trim(buf) // ' is neither FRICREG_MATRIX_CSR nor ' // &
                         'FRICREG_MATRIX_CSC (a dense matrix is values(:, :))')
      return
    end if
    nrows = merge(self%m, self%n, which == FRICREG_CONTACTS)
    if (which >= FRICREG_MASS .and. which <= FRICREG_CONTACTS .and. &
        layout /= ior(FRICREG_MATRIX_CSR, FRICREG_MATRIX_CSC)) then
      if (layout == FRICREG_MATRIX_CSR) then
        status = self%check_sparse(fn, 'ptr', 'ind', f, nrows, ptr, ind, values)
      else
        status = self%check_sparse(fn, 'ptr', 'ind', f, self%n, ptr, ind, values)
      end if
    end if ! else C refuses which or format before reading anything
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_matrix(self%ptr, &
                                                   which, nrows, self%n, f, ptr, ind, values))
  end function struct_set_matrix_compressed

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
  !> the asymptotic range, a safe bound (the kind, get_error_kind: asymptotic or bound);
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

  !> The answer tolerance rtol (finite, > 0; default 1e-2): FRICREG_WARN_ERROR_ESTIMATE where
  !> the largest peak's estimate exceeds rtol times the largest peak, or the dissipations'
  !> summed estimate rtol times their summed magnitudes, whatever the kinds; kept across runs
  !> (fricreg_structure_set_answer_rtol). FRICREG_EINVAL otherwise, nothing changed. Since 1.8.
  function struct_set_answer_rtol(self, rtol) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(in) :: rtol
    integer(c_int) :: status
    status = self%ready('set_answer_rtol', 'structure')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_answer_rtol(self%ptr, rtol))
  end function struct_set_answer_rtol

  !> Where the error estimate's companions sit: FRICREG_COMPANIONS_AUTO (2, the default since
  !> 1.9: the coarser screen, confirmed by the finer where it would warn or fails; which gave the
  !> estimate: get_value(FRICREG_SVALUE_COMPANIONS_USED, x), what the screen said:
  !> FRICREG_SVALUE_SCREEN_PEAK_ERR and FRICREG_SVALUE_SCREEN_DISS_ERR),
  !> FRICREG_COMPANIONS_FINER (0: eps/2 at dt/2, eps/4 at dt/4; 1.8's default) or
  !> FRICREG_COMPANIONS_COARSER (1: 2 eps at 2 dt, 4 eps at 4 dt, about 0.75x the run's cost;
  !> fixed steps need calls spanning 4 dt) (fricreg_structure_set_error_companions). A change
  !> ends the estimate made until the next set_initial. FRICREG_EINVAL if which is not 0, 1 or
  !> 2, nothing changed. Since 1.8; 2 since 1.9.
  function struct_set_error_companions(self, which) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int), intent(in) :: which
    integer(c_int) :: status
    status = self%ready('set_error_companions', 'structure')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_set_error_companions(self%ptr, which))
  end function struct_set_error_companions
  !> How Newmark / HHT-alpha steps solve their near-stick block
  !> (fricreg_structure_set_contact_solver): FRICREG_CONTACT_SOLVER_AUTO (the default: dense for
  !> now), _DENSE (a factor of the block of J K_eff^-1 J^T) or _SPARSE (one sparse factor of
  !> K_eff + J^T T J). FRICREG_EINVAL for another value, nothing changed. Since 1.8.
  function struct_set_contact_solver(self, solver) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer, intent(in) :: solver
    integer(c_int) :: status
    status = self%ready('set_contact_solver', 'structure')
    if (status == FRICREG_OK) status = self%record(fricreg_structure_set_contact_solver(self%ptr, &
                                                     int(solver, c_int)))
  end function struct_set_contact_solver

  !> The near-stick block's solver of the next step, FRICREG_CONTACT_SOLVER_DENSE or _SPARSE
  !> (the automatic choice resolved; fricreg_structure_get_contact_solver). Since 1.8.
  function struct_contact_solver(self, solver) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer, intent(inout) :: solver
    integer(c_int) :: status, k
    status = self%ready('get_contact_solver', 'structure')
    k = 0
    if (status == FRICREG_OK) &
      status = self%record(fricreg_structure_get_contact_solver(self%ptr, k))
    if (status == FRICREG_OK) solver = int(k)
  end function struct_contact_solver

  !> The peak displacements max |u_i| since set_initial, peak(ndof) (length units): every fixed
  !> step's end and the turning points inside it, every adaptive run_ode call's end
  !> (fricreg_structure_get_peak_displacement).
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

  !> The error estimate of each joint element's dissipation, err(me) (energy units; +Inf where
  !> a companion failed), me = size(err) the number of elements set,
  !> fricreg_structure_get_jenkins_dissipation_error. FRICREG_EINVAL without an estimate;
  !> FRICREG_ESIZE. Since 1.7.
  function struct_get_jenkins_dissipation_error(self, err) result(status)
    class(fricreg_structure), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: err(:)
    integer(c_int) :: status
    status = self%ready('get_jenkins_dissipation_error', 'structure')
    if (status /= FRICREG_OK) return
    status = self%unrecorded('get_jenkins_dissipation_error', &
                             fricreg_structure_get_jenkins_dissipation_error(self%ptr, &
                                                                             size(err, &
                                                                                  kind=c_size_t), &
                                                                             err))
  end function struct_get_jenkins_dissipation_error

  !> The kind of each error estimate of quantity (FRICREG_EST_PEAK_DISPLACEMENT: kinds(ndof),
  !> FRICREG_EST_DISSIPATION: kinds(m), FRICREG_EST_ELEMENT_DISSIPATION: kinds(me), me the
  !> number of joint elements set), each FRICREG_EST_KIND_ASYMPTOTIC, _BOUND or _ASSUMED,
  !> parallel to the *_error getters' err (fricreg_structure_get_error_kind). FRICREG_EINVAL for
  !> an unknown quantity or without an estimate; FRICREG_ESIZE. Since 1.8.
  function struct_get_error_kind(self, quantity, kinds) result(status)
    class(fricreg_structure), intent(inout) :: self
    integer(c_int), intent(in) :: quantity
    integer(c_int), intent(inout), contiguous :: kinds(:)
    integer(c_int) :: status
    status = self%ready('get_error_kind', 'structure')
    if (status /= FRICREG_OK) return
    status = self%unrecorded('get_error_kind', &
                             fricreg_structure_get_error_kind(self%ptr, quantity, &
                                                              size(kinds, kind=c_size_t), kinds))
  end function struct_get_error_kind

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

end module fricreg_structure_m
