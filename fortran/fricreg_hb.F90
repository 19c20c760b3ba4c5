! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_hb.F90 — module fricreg_hb_m: type fricreg_hb_driver, harmonic balance of a structure
! with Jenkins elements (fricreg_hb.h), and its procedures. Built with the drivers only
! (FRICREG_DRIVERS).
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_hb_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_ptr, c_funptr, &
                                         c_null_ptr, c_null_funptr, c_associated, c_funloc, &
                                         c_null_char
  use fricreg_c
  use fricreg_sim_c
  use fricreg_base_m, only: fricreg_object, fricreg_error_string, as_size
  implicit none
  private
  public :: fricreg_hb_driver

  !> Harmonic balance of a structure with 1-D Jenkins elements (fricreg_hb.h, docs/harmonic_balance.md):
  !> M, C, K (ndof, ndof) symmetric, J(m, ndof) in Fortran's order, the elements' coordinates'
  !> coefficients q(2H+1, m) (column i element i: q0, a_1, b_1, ..., a_H, b_H) and the
  !> displacements' x(2H+1, ndof); continuation points counted from 1.
  type, extends(fricreg_object) :: fricreg_hb_driver
    private
    integer(c_size_t) :: n = 0, m = 0, nc = 0 ! C has no size getters: kept from create
    integer(c_size_t) :: rows = 0 ! q's columns: m, 2 m with set_normal_elements, 3 m in 3-D
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
    procedure :: set_jenkins => hb_set_jenkins
    procedure :: set_jenkins_normal => hb_set_jenkins_normal
    procedure :: set_iwan_normal => hb_set_iwan_normal
    procedure :: set_jenkins_2d_normal => hb_set_jenkins_2d_normal
    procedure :: add_elements => hb_add_elements
    procedure :: clear_elements => hb_clear_elements
    procedure :: element_count => hb_element_count
    procedure, private :: hb_set_matrix_dense, hb_set_matrix_compressed
    generic :: set_matrix => hb_set_matrix_dense, hb_set_matrix_compressed
    procedure :: set_excitation => hb_set_excitation
    procedure :: set_newton => hb_set_newton
    procedure :: set_newton_solver => hb_set_newton_solver
    procedure :: set_receptance => hb_set_receptance
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
    procedure :: point_displacement => hb_point_displacement
    procedure :: peak => hb_peak
    procedure :: set_stability => hb_set_stability
    procedure :: set_stability_method => hb_set_stability_method
    procedure :: stability_method => hb_stability_method
    procedure :: stability => hb_stability
    procedure :: exponents => hb_exponents
    procedure :: truncation_error => hb_truncation_error
    procedure :: bifurcations => hb_bifurcations
    procedure :: bifurcation => hb_bifurcation
    procedure :: bifurcation_level => hb_bifurcation_level
    procedure :: nma => hb_nma
    procedure :: nma_points => hb_nma_points
    procedure :: nma_point => hb_nma_point
    procedure :: nma_continue => hb_nma_continue
    procedure :: nma_harmonic_energy => hb_nma_harmonic_energy
    procedure :: nma_modal_participation => hb_nma_modal_participation
    procedure :: nma_special_points => hb_nma_special_points
    procedure :: nma_special_point => hb_nma_special_point
    procedure, private :: hb_shape
    final :: hb_final
  end type

contains

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
    status = hb_jenkins(self, 'set_elements', J, kt, mun)
  end function hb_set_elements

  !> set_elements under the structure's name (fricreg_structure%set_jenkins: the same
  !> arguments), binding C's fricreg_hb_set_jenkins, whose messages name set_jenkins. Since 1.7.
  function hb_set_jenkins(self, J, kt, mun) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: J(:, :)
    real(c_double), intent(in), contiguous :: kt(:), mun(:)
    integer(c_int) :: status
    status = hb_jenkins(self, 'set_jenkins', J, kt, mun)
  end function hb_set_jenkins

  !> set_elements and set_jenkins, fn their name: the shapes checked, J transposed for C.
  function hb_jenkins(self, fn, J, kt, mun) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    character(len=*), intent(in) :: fn
    real(c_double), intent(in) :: J(:, :)
    real(c_double), intent(in), contiguous :: kt(:), mun(:)
    integer(c_int) :: status
    real(c_double), allocatable :: Jc(:, :) ! J transposed: C's row-major J
    status = self%hb_shape(fn, 'J', J, self%m, self%n)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'kt', kt, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'mun', mun, self%m, 0_c_size_t)
    if (status /= FRICREG_OK) return
    allocate (Jc, source=transpose(J))
    if (fn == 'set_jenkins') then
      status = self%record(fricreg_hb_set_jenkins(self%ptr, self%m, self%n, Jc, kt, mun))
    else
      status = self%record(fricreg_hb_set_elements(self%ptr, self%m, self%n, Jc, kt, mun))
    end if
    if (status == FRICREG_OK) self%rows = self%m
  end function hb_jenkins

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
    status = hb_jenkins_normal(self, 'set_normal_elements', Jt, Jn, kt, mu, n0, kn)
  end function hb_set_normal_elements

  !> set_normal_elements under the structure's name (fricreg_structure%set_jenkins_normal: the
  !> same arguments), binding C's fricreg_hb_set_jenkins_normal, whose messages name
  !> set_jenkins_normal. Since 1.7.
  function hb_set_jenkins_normal(self, Jt, Jn, kt, mu, n0, kn) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: Jt(:, :), Jn(:, :)
    real(c_double), intent(in), contiguous :: kt(:), mu(:), n0(:), kn(:)
    integer(c_int) :: status
    status = hb_jenkins_normal(self, 'set_jenkins_normal', Jt, Jn, kt, mu, n0, kn)
  end function hb_set_jenkins_normal

  !> set_normal_elements and set_jenkins_normal, fn their name: the shapes checked, Jt and Jn
  !> transposed for C.
  function hb_jenkins_normal(self, fn, Jt, Jn, kt, mu, n0, kn) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    character(len=*), intent(in) :: fn
    real(c_double), intent(in) :: Jt(:, :), Jn(:, :)
    real(c_double), intent(in), contiguous :: kt(:), mu(:), n0(:), kn(:)
    integer(c_int) :: status
    real(c_double), allocatable :: Jtc(:, :), Jnc(:, :) ! transposed: C's row-major Jt, Jn
    status = self%hb_shape(fn, 'Jt', Jt, self%m, self%n)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'Jn', Jn, self%m, self%n)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'kt', kt, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'mu', mu, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'n0', n0, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'kn', kn, self%m, 0_c_size_t)
    if (status /= FRICREG_OK) return
    allocate (Jtc, source=transpose(Jt))
    allocate (Jnc, source=transpose(Jn))
    if (fn == 'set_jenkins_normal') then
      status = self%record(fricreg_hb_set_jenkins_normal(self%ptr, self%m, self%n, Jtc, Jnc, &
                                                         kt, mu, n0, kn))
    else
      status = self%record(fricreg_hb_set_normal_elements(self%ptr, self%m, self%n, Jtc, Jnc, &
                                                          kt, mu, n0, kn))
    end if
    if (status == FRICREG_OK) self%rows = 2 * self%m
  end function hb_jenkins_normal

  !> Iwan elements under a normal load with lift-off instead (fricreg_hb_set_iwan_normal):
  !> Jt(m, ndof), Jn(m, ndof) as set_normal_elements's; element i's ns sliders have the
  !> stiffnesses k(:, i) > 0 and friction coefficients mu(:, i) >= 0, k and mu (ns, m); n0(m),
  !> kn(m) >= 0 the normal law. q has 2 m columns, as set_normal_elements's, which is the case
  !> ns = 1. FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_EINVAL; FRICREG_ENOMEM. Since 1.7.
  function hb_set_iwan_normal(self, Jt, Jn, k, mu, n0, kn) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: Jt(:, :), Jn(:, :)
    real(c_double), intent(in), contiguous :: k(:, :), mu(:, :), n0(:), kn(:)
    integer(c_int) :: status
    character(len=*), parameter :: fn = 'set_iwan_normal'
    real(c_double), allocatable :: Jtc(:, :), Jnc(:, :) ! transposed: C's row-major Jt, Jn
    status = self%hb_shape(fn, 'Jt', Jt, self%m, self%n)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'Jn', Jn, self%m, self%n)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'k', k, int(size(k, 1), c_size_t), &
                                                     self%m)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'mu', mu, int(size(k, 1), c_size_t), &
                                                     self%m)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'n0', n0, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'kn', kn, self%m, 0_c_size_t)
    if (status /= FRICREG_OK) return
    allocate (Jtc, source=transpose(Jt))
    allocate (Jnc, source=transpose(Jn))
    status = self%record(fricreg_hb_set_iwan_normal(self%ptr, self%m, self%n, Jtc, Jnc, &
                                                    int(size(k, 1), c_size_t), k, mu, n0, kn))
    if (status == FRICREG_OK) self%rows = 2 * self%m
  end function hb_set_iwan_normal

  !> 3-D contact elements instead (fricreg_hb_set_jenkins_2d_normal, the structure's
  !> set_jenkins_2d_normal's arguments): element i's tangential rows 2i-1 (x) and 2i (y) of
  !> Je(2 m, ndof) and its normal row i of Jn(m, ndof), both in Fortran's order; kt(m) > 0,
  !> mu(m) >= 0, n0(m), kn(m) >= 0. q then has 3 m columns: 3i - 2 element i's ux, 3i - 1 its
  !> uy, 3i its g. FRICREG_ESIZE; FRICREG_ENONFINITE; FRICREG_EINVAL; FRICREG_ENOMEM. Since 1.7.
  function hb_set_jenkins_2d_normal(self, Je, Jn, kt, mu, n0, kn) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    real(c_double), intent(in) :: Je(:, :), Jn(:, :)
    real(c_double), intent(in), contiguous :: kt(:), mu(:), n0(:), kn(:)
    integer(c_int) :: status
    character(len=*), parameter :: fn = 'set_jenkins_2d_normal'
    real(c_double), allocatable :: Jec(:, :), Jnc(:, :) ! transposed: C's row-major Je, Jn
    status = self%hb_shape(fn, 'Je', Je, 2 * self%m, self%n)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'Jn', Jn, self%m, self%n)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'kt', kt, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'mu', mu, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'n0', n0, self%m, 0_c_size_t)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'kn', kn, self%m, 0_c_size_t)
    if (status /= FRICREG_OK) return
    allocate (Jec, source=transpose(Je))
    allocate (Jnc, source=transpose(Jn))
    status = self%record(fricreg_hb_set_jenkins_2d_normal(self%ptr, self%m, self%n, Jec, Jnc, &
                                                          kt, mu, n0, kn))
    if (status == FRICREG_OK) self%rows = 3 * self%m
  end function hb_set_jenkins_2d_normal

  !> Elements of the type called name (fricreg_element_lookup; ns sliders for an Iwan type,
  !> default 1) beside those the driver holds, of any types (fricreg_hb_add_elements: HB's own
  !> AFTs for jenkins, iwan, jenkins_normal, iwan_normal, contact_3d, their gap 0; the march of
  !> its eval for any other): element i's dim rows (the type's: tangential, then the normal
  !> one) (i-1) dim + 1 .. i dim of J(me dim, ndof) in Fortran's order, its parameters
  !> params(:, i) in the type's layout; me = size(params, 2). q's
  !> columns are the rows of the elements in the order added. FRICREG_EINVAL for an unknown
  !> name or ns; FRICREG_ESIZE unless params has the type's nparams rows and J is (me dim,
  !> ndof); C's codes. Since 1.8.
  function hb_add_elements(self, name, J, params, ns) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    character(len=*), intent(in) :: name
    real(c_double), intent(in) :: J(:, :)
    real(c_double), intent(in), contiguous :: params(:, :)
    integer, intent(in), optional :: ns
    integer(c_int) :: status
    character(len=*), parameter :: fn = 'add_elements'
    type(c_ptr) :: t
    integer :: n
    integer(c_size_t) :: me, rows
    real(c_double), allocatable :: Jc(:, :) ! J transposed: C's row-major J
    n = 1
    if (present(ns)) n = ns
    status = self%ready(fn, 'HB driver')
    if (status /= FRICREG_OK) return
    t = c_null_ptr
    if (n >= 1) t = fricreg_element_sliders(fricreg_element_lookup(trim(name) // c_null_char), &
                                            int(n, c_size_t))
    if (.not. c_associated(t)) then
      status = self%fail(FRICREG_EINVAL, fn // ': no element type "' // trim(name) // &
                         '" with that many sliders')
      return
    end if
    me = int(size(params, 2), c_size_t)
    rows = me * int(fricreg_element_dim(t), c_size_t)
    status = self%hb_shape(fn, 'params', params, fricreg_element_nparams(t), me)
    if (status == FRICREG_OK) status = self%hb_shape(fn, 'J', J, rows, self%n)
    if (status /= FRICREG_OK) return
    if (fricreg_hb_element_count(self%ptr) == 0) self%rows = 0 ! q's columns: the held rows
    allocate (Jc, source=transpose(J))
    status = self%record(fricreg_hb_add_elements(self%ptr, t, me, self%n, Jc, params))
    if (status == FRICREG_OK) self%rows = self%rows + rows
  end function hb_add_elements

  !> Remove every element (fricreg_hb_clear_elements). Since 1.8.
  function hb_clear_elements(self) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer(c_int) :: status
    status = self%ready('clear_elements', 'HB driver')
    if (status == FRICREG_OK) status = self%record(fricreg_hb_clear_elements(self%ptr))
    if (status == FRICREG_OK) self%rows = self%m
  end function hb_clear_elements

  !> The number of elements held, of all types (fricreg_hb_element_count; 0 before create).
  !> Since 1.8.
  integer function hb_element_count(self)
    class(fricreg_hb_driver), intent(in) :: self
    hb_element_count = 0
    if (c_associated(self%ptr)) hb_element_count = int(fricreg_hb_element_count(self%ptr))
  end function hb_element_count

  !> One setter of M, K and C, in any storage (C's fricreg_hb_set_matrix), a generic of two
  !> forms, as fricreg_structure's set_matrix (the contacts aside: J is set with the elements):
  !>   hb%set_matrix(which, values)                          dense values(ndof, ndof)
  !>   hb%set_matrix(which, format, ptr, ind, values, flags) compressed, values(:)
  !> which: FRICREG_MASS, FRICREG_STIFFNESS or FRICREG_DAMPING (replaces Rayleigh damping).
  !> Dense: each the set_mass, set_stiffness or set_damping of the same numbers (symmetric:
  !> passed as they are); the same checks and results, C's message naming set_matrix.
  !> FRICREG_ESIZE unless values is ndof x ndof; C's codes (FRICREG_EINVAL for FRICREG_CONTACTS
  !> or an unknown which, with no size checked here).
  function hb_set_matrix_dense(self, which, values) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer(c_int), intent(in) :: which
    real(c_double), intent(in), contiguous :: values(:, :)
    integer(c_int) :: status
    status = self%ready('set_matrix', 'HB driver')
    if (status == FRICREG_OK .and. which >= FRICREG_MASS .and. which <= FRICREG_DAMPING) &
      status = self%hb_shape('set_matrix', 'values', values, self%n, self%n)
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_matrix(self%ptr, which, &
                                                   self%n, self%n, FRICREG_MATRIX_DENSE, &
                                                   values=values))
  end function hb_set_matrix_dense

  !> The compressed form of set_matrix, which makes the model sparse (C's
  !> fricreg_hb_set_mass_csc): format FRICREG_MATRIX_CSR or FRICREG_MATRIX_CSC, ptr(ndof + 1)
  !> and ind(nnz) of kind c_int64_t, values(nnz), flags (fricreg_sparse_flags; absent,
  !> FRICREG_SPARSE_ONE_BASED; + FRICREG_SPARSE_LOWER or _UPPER for one triangle); C is given
  !> ior(format, flags). FRICREG_ESIZE unless ptr has ndof + 1 elements and ind and values at
  !> least nnz; FRICREG_EINVAL for a format that is neither (a dense matrix is values(:, :)),
  !> and C's codes (FRICREG_EINVAL for FRICREG_CONTACTS, an unknown which or both formats,
  !> with no size checked here; FRICREG_ENOTSYM; ...).
  function hb_set_matrix_compressed(self, which, format, ptr, ind, values, flags) &
      result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer(c_int), intent(in) :: which, format
    integer(c_int64_t), intent(in), contiguous :: ptr(:), ind(:)
    real(c_double), intent(in), contiguous :: values(:)
    integer(c_int), intent(in), optional :: flags
    integer(c_int) :: status, f, layout
    character(len=64) :: buf
    f = ior(format, FRICREG_SPARSE_ONE_BASED)
    if (present(flags)) f = ior(format, flags)
    layout = iand(f, ior(FRICREG_MATRIX_CSR, FRICREG_MATRIX_CSC))
    status = self%ready('set_matrix', 'HB driver')
    if (status /= FRICREG_OK) return
    if (layout == FRICREG_MATRIX_DENSE) then
      write (buf, '(a, i0)') 'set_matrix: format = ', format
      status = self%fail(FRICREG_EINVAL, trim(buf) // ' is neither FRICREG_MATRIX_CSR nor ' // &
                         'FRICREG_MATRIX_CSC (a dense matrix is values(:, :))')
      return
    end if
    if (which >= FRICREG_MASS .and. which <= FRICREG_DAMPING .and. &
        layout /= ior(FRICREG_MATRIX_CSR, FRICREG_MATRIX_CSC)) &
      status = self%check_sparse('set_matrix', 'ptr', 'ind', f, self%n, ptr, ind, values)
    ! else C refuses which or format before reading anything
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_matrix(self%ptr, which, &
                                                   self%n, self%n, f, ptr, ind, values))
  end function hb_set_matrix_compressed

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

  !> How Newton's matrix is solved (fricreg_hb_set_newton_solver): FRICREG_HB_NEWTON_AUTO (the
  !> default: by its capacitance from nq = 512 where few rows are off the diagonal), _DENSE
  !> (1.9's LU) or _CAPACITANCE. FRICREG_EINVAL for another value; FRICREG_ENOMEM. Since 1.10.
  function hb_set_newton_solver(self, solver) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: solver
    integer(c_int) :: status
    status = self%ready('set_newton_solver', 'HB driver')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_set_newton_solver(self%ptr, int(solver, c_int)))
  end function hb_set_newton_solver

  !> How D_h's receptances are solved (fricreg_hb_set_receptance): FRICREG_HB_RECEPTANCE_AUTO
  !> (the default: through the modes of (K, M) from 200 dofs where the damping is Rayleigh's),
  !> _LU (1.9's) or _MODES. FRICREG_EINVAL for another value. Since 1.10.
  function hb_set_receptance(self, method) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: method
    integer(c_int) :: status
    status = self%ready('set_receptance', 'HB driver')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_set_receptance(self%ptr, int(method, c_int)))
  end function hb_set_receptance

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

  !> The displacements' coefficients x(2H+1, ndof) of point k (1 <= k <= points()),
  !> recomputed from its unknowns, or with k = 0 of the last solution
  !> (fricreg_hb_point_displacement). Its statuses; FRICREG_EINVAL for k < 0; FRICREG_ESIZE.
  function hb_point_displacement(self, k, x) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: k
    real(c_double), intent(inout), contiguous :: x(:, :)
    integer(c_int) :: status
    integer(c_size_t) :: idx
    status = self%hb_shape('point_displacement', 'x', x, self%nc, self%n)
    if (status == FRICREG_OK .and. k < 0) status = self%fail(FRICREG_EINVAL, &
      'point_displacement: k must be >= 0 (0: the last solution)')
    if (status /= FRICREG_OK) return
    idx = -1_c_size_t ! FRICREG_HB_SOLUTION, (size_t)-1
    if (k > 0) idx = as_size(k - 1)
    status = self%record(fricreg_hb_point_displacement(self%ptr, idx, self%n, self%nc, x))
  end function hb_point_displacement

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

  !> Compute each solution's stability from now on (enable .true.), or stop
  !> (fricreg_hb_set_stability), by the method of set_stability_method. FRICREG_EINVAL (Hill's
  !> method in force with too many coefficients); FRICREG_ENOMEM.
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

  !> How the stability of the next solutions is computed (fricreg_hb_set_stability_method):
  !> FRICREG_HB_STABILITY_AUTO (the default: the exact monodromy where the elements are piecewise
  !> linear, condensed onto their dofs where they touch few, Hill's method otherwise), _HILL,
  !> _MONODROMY or _CONDENSED (since 1.9). FRICREG_EINVAL for another value. Since 1.8.
  function hb_set_stability_method(self, method) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: method
    integer(c_int) :: status
    status = self%ready('set_stability_method', 'HB driver')
    if (status == FRICREG_OK) status = self%record(fricreg_hb_set_stability_method(self%ptr, &
                                                     int(method, c_int)))
  end function hb_set_stability_method

  !> The method that computes the next solution's stability, FRICREG_HB_STABILITY_HILL,
  !> _MONODROMY or _CONDENSED (the automatic choice resolved; fricreg_hb_get_stability_method).
  !> Since 1.8.
  function hb_stability_method(self, method) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(inout) :: method
    integer(c_int) :: status, m
    status = self%ready('get_stability_method', 'HB driver')
    m = 0
    if (status == FRICREG_OK) status = self%record(fricreg_hb_get_stability_method(self%ptr, m))
    if (status == FRICREG_OK) method = int(m)
  end function hb_stability_method

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

  !> The Floquet exponents of point k (1 <= k <= points()), or with k = 0 of the last solution
  !> (fricreg_hb_point_exponents): exponents(2, 2 ndof), (Re, Im) of each in rad/s, the
  !> multipliers exp(2 pi lambda / Omega). FRICREG_EINVAL for stability off, k out of range or
  !> no solution; FRICREG_ESIZE.
  function hb_exponents(self, k, exponents) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: k
    real(c_double), intent(inout), contiguous :: exponents(:, :)
    integer(c_int) :: status
    integer(c_size_t) :: idx
    status = self%hb_shape('point_exponents', 'exponents', exponents, 2_c_size_t, 2 * self%n)
    if (status == FRICREG_OK .and. k < 0) status = self%fail(FRICREG_EINVAL, &
      'point_exponents: k must be >= 0 (0: the last solution)')
    if (status /= FRICREG_OK) return
    idx = -1_c_size_t ! FRICREG_HB_SOLUTION, (size_t)-1
    if (k > 0) idx = as_size(k - 1)
    status = self%record(fricreg_hb_point_exponents(self%ptr, idx, 2 * self%n, exponents))
  end function hb_exponents

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

  !> The backbone of mode `mode` (1 <= mode <= ndof) from the modal amplitude a0 to a1 by
  !> pseudo-arclength continuation, through its folds in the amplitude (an internal
  !> resonance), npoints stored at equal arclength (fricreg_hb_nma_continue); damping as nma's.
  !> Its statuses.
  function hb_nma_continue(self, mode, a0, a1, npoints, damping) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: mode, npoints
    real(c_double), intent(in) :: a0, a1
    integer(c_int), intent(in), optional :: damping
    integer(c_int) :: status, d
    d = FRICREG_HB_NMA_DAMPING_MATRIX
    if (present(damping)) d = damping
    status = self%ready('nma_continue', 'HB driver')
    if (status == FRICREG_OK .and. (mode < 1 .or. npoints < 0)) &
      status = self%fail(FRICREG_EINVAL, 'nma_continue: mode must be >= 1 (Fortran counts '// &
                         'from 1), npoints >= 0')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_nma_continue(self%ptr, as_size(mode - 1), d, a0, a1, &
                                                   as_size(npoints)))
  end function hb_nma_continue

  !> The share of each harmonic in the kinetic energy of point i (1 <= i <= nma_points()) of the
  !> last backbone: fraction(h + 1) harmonic h's, h = 0..H (size H + 1; fraction(1), the mean's,
  !> is 0), adding up to 1 (fricreg_hb_nma_harmonic_energy). Its statuses.
  function hb_nma_harmonic_energy(self, i, fraction) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: i
    real(c_double), intent(inout), contiguous :: fraction(:)
    integer(c_int) :: status
    status = self%ready('nma_harmonic_energy', 'HB driver')
    if (status == FRICREG_OK .and. i < 1) &
      status = self%fail(FRICREG_EINVAL, 'nma_harmonic_energy: i must be >= 1 (Fortran counts '// &
                         'from 1)')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_nma_harmonic_energy(self%ptr, as_size(i - 1), &
                                                          as_size(size(fraction)), fraction))
  end function hb_nma_harmonic_energy

  !> The share of each linear mode of the structure with its elements stuck in harmonic
  !> `harmonic` (0..H; 0 the mean) of the displacements at point i (1 <= i <= nma_points()):
  !> fraction(r) mode r's (size ndof, mode 1 the lowest), adding up to 1; dense models and
  !> sparse ones up to 256 dofs (fricreg_hb_nma_modal_participation). Its statuses.
  function hb_nma_modal_participation(self, i, harmonic, fraction) result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: i, harmonic
    real(c_double), intent(inout), contiguous :: fraction(:)
    integer(c_int) :: status
    status = self%ready('nma_modal_participation', 'HB driver')
    if (status == FRICREG_OK .and. i < 1) &
      status = self%fail(FRICREG_EINVAL, 'nma_modal_participation: i must be >= 1 (Fortran '// &
                         'counts from 1)')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_nma_modal_participation(self%ptr, as_size(i - 1), &
                                                              int(harmonic, c_int), &
                                                              as_size(size(fraction)), fraction))
  end function hb_nma_modal_participation

  !> Number of special points of the last backbone, its folds and crossings in one list (0 if
  !> none; fricreg_hb_nma_special_points).
  integer function hb_nma_special_points(self)
    class(fricreg_hb_driver), intent(in) :: self
    hb_nma_special_points = int(fricreg_hb_nma_special_points(self%ptr))
  end function hb_nma_special_points

  !> Special point i (1 <= i <= nma_special_points()) of the last backbone, in the branch's
  !> order: its type (FRICREG_HB_NMA_FOLD, where the amplitude turns, or FRICREG_HB_NMA_CROSSING,
  !> where a harmonic k omega crosses another stuck linear mode's frequency), the modal amplitude,
  !> the backbone's omega (rad/s) and damping ratio zeta there, the harmonic k (1 for a fold) and
  !> the mode (from 1, as nma's mode: the mode crossed, or the backbone's own for a fold)
  !> (fricreg_hb_nma_special_point). FRICREG_EINVAL for i out of range.
  function hb_nma_special_point(self, i, type, amplitude, omega, zeta, harmonic, mode) &
      result(status)
    class(fricreg_hb_driver), intent(inout) :: self
    integer, intent(in) :: i
    integer, intent(inout) :: type, harmonic, mode
    real(c_double), intent(inout) :: amplitude, omega, zeta
    integer(c_int) :: status, t, k
    integer(c_size_t) :: r
    status = self%ready('nma_special_point', 'HB driver')
    if (status == FRICREG_OK .and. i < 1) &
      status = self%fail(FRICREG_EINVAL, 'nma_special_point: i must be >= 1 (Fortran counts '// &
                         'from 1)')
    if (status == FRICREG_OK) &
      status = self%record(fricreg_hb_nma_special_point(self%ptr, as_size(i - 1), t, amplitude, &
                                                        omega, zeta, k, r))
    if (status == FRICREG_OK) then
      type = int(t)
      harmonic = int(k)
      mode = int(r) + 1
    end if
  end function hb_nma_special_point

end module fricreg_hb_m
