! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_iwan.F90 — module fricreg_iwan_m: type fricreg_iwan_elements, n Iwan elements
! (fricreg_iwan.h), and its procedures.
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_iwan_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_null_ptr
  use fricreg_c
  use fricreg_base_m, only: fricreg_object, fricreg_error_string, as_size
  implicit none
  private
  public :: fricreg_iwan_elements

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

contains

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

end module fricreg_iwan_m
