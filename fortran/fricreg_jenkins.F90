! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_jenkins.F90 — module fricreg_jenkins_m: type fricreg_jenkins_elements, n Jenkins
! elements (fricreg_jenkins.h), and its procedures.
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_jenkins_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_null_ptr
  use fricreg_c
  use fricreg_base_m, only: fricreg_object, fricreg_error_string, as_size
  implicit none
  private
  public :: fricreg_jenkins_elements

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

contains

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

end module fricreg_jenkins_m
