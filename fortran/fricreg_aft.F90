! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_aft.F90 — module fricreg_aft_m: type fricreg_aft_workspace, the AFT of Jenkins and Iwan
! elements (fricreg_aft.h), and its procedures.
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_aft_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_null_ptr
  use fricreg_c
  use fricreg_base_m, only: fricreg_object, fricreg_error_string, as_size
  implicit none
  private
  public :: fricreg_aft_workspace

  !> The AFT of 1-D Jenkins and Iwan elements (fricreg_aft.h, docs/aft.md): from the
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

contains

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

end module fricreg_aft_m
