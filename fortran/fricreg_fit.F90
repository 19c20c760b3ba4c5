! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_fit.F90 — module fricreg_fit_m: type fricreg_backbone_fit, the identification of a
! modal Iwan joint from a test's measured levels (fricreg_fit.h, docs/identification.md), and
! its procedures. Built with the drivers only (FRICREG_DRIVERS).
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_fit_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_null_ptr
  use fricreg_c
  use fricreg_sim_c
  use fricreg_base_m, only: fricreg_object, fricreg_error_string, as_size
  implicit none
  private
  public :: fricreg_backbone_fit

  !> The modal Iwan model (Segalman's four-parameter joint beside a linear modal stiffness K0
  !> and damping ratio zeta0) fitted to a mode's measured frequency and damping ratio at several
  !> levels (fricreg_fit.h). Parameters are indexed by FRICREG_FIT_FS .. FRICREG_FIT_K0 (0-based,
  !> as in C); parameter arrays have FRICREG_FIT_NPARAMS = 6 entries, p(FRICREG_FIT_FS + 1) the
  !> first. The covariance is (6, 6), symmetric; sensitivities are (6, n), column i level i.
  type, extends(fricreg_object) :: fricreg_backbone_fit
  contains
    procedure :: create => fit_create
    procedure :: set_levels => fit_set_levels
    procedure :: set_deviations => fit_set_deviations
    procedure :: set_sensor => fit_set_sensor
    procedure :: set_free => fit_set_free
    procedure :: set_fixed => fit_set_fixed
    procedure :: set_starts => fit_set_starts
    procedure :: run => fit_run
    procedure :: params => fit_params
    procedure :: covariance => fit_covariance
    procedure :: value => fit_value
    procedure :: eval => fit_eval
    procedure :: curve => fit_curve
    final :: fit_final
  end type

contains

  ! ---- Identification (fricreg_fit.h) -------------------------------------------------------

  !> Create a fit with no levels (every parameter free, starts from the levels, sensor 1, 32
  !> starts). An object that held one gets the new one and releases the old. FRICREG_ENOMEM.
  function fit_create(self) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    integer(c_int) :: status
    type(c_ptr) :: p
    p = c_null_ptr
    status = fricreg_fit_create(p)
    if (status /= FRICREG_OK) then
      status = self%fail(status, 'create: ' // fricreg_error_string(status))
      return
    end if
    call self%adopt(p, fricreg_fit_free, fricreg_fit_errcode, fricreg_fit_errmsg)
  end function fit_create

  subroutine fit_final(self)
    type(fricreg_backbone_fit), intent(inout) :: self
    call self%destroy()
  end subroutine fit_final

  !> The measured levels: amplitude(n) > 0 of kind (FRICREG_FIT_DISPLACEMENT, _VELOCITY,
  !> _ACCELERATION) at the sensor, freq_hz(n) > 0 (Hz), zeta(n) > 0; the deviations are
  !> forgotten. FRICREG_ESIZE if the arrays differ in size; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function fit_set_levels(self, kind, amplitude, freq_hz, zeta) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    integer, intent(in) :: kind
    real(c_double), intent(in), contiguous :: amplitude(:), freq_hz(:), zeta(:)
    integer(c_int) :: status
    status = self%ready('set_levels', 'fit')
    if (status == FRICREG_OK) &
      status = self%check_size('set_levels', 'freq_hz', size(freq_hz), as_size(size(amplitude)))
    if (status == FRICREG_OK) &
      status = self%check_size('set_levels', 'zeta', size(zeta), as_size(size(amplitude)))
    if (status == FRICREG_OK) status = self%record(fricreg_fit_set_levels(self%ptr, &
      as_size(size(amplitude)), int(kind, c_int), amplitude, freq_hz, zeta))
  end function fit_set_levels

  !> The levels' standard deviations sd_freq_hz(n), sd_zeta(n) > 0 (absolute). FRICREG_ESIZE;
  !> FRICREG_EINVAL; FRICREG_ENONFINITE.
  function fit_set_deviations(self, sd_freq_hz, sd_zeta) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    real(c_double), intent(in), contiguous :: sd_freq_hz(:), sd_zeta(:)
    integer(c_int) :: status
    status = self%ready('set_deviations', 'fit')
    if (status == FRICREG_OK) status = self%check_size('set_deviations', 'sd_zeta', &
                                                       size(sd_zeta), as_size(size(sd_freq_hz)))
    if (status == FRICREG_OK) status = self%record(fricreg_fit_set_deviations(self%ptr, &
      as_size(size(sd_freq_hz)), sd_freq_hz, sd_zeta))
  end function fit_set_deviations

  !> The mass-normalized mode shape's value s /= 0 at the sensor. FRICREG_EINVAL;
  !> FRICREG_ENONFINITE.
  function fit_set_sensor(self, s) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    real(c_double), intent(in) :: s
    integer(c_int) :: status
    status = self%ready('set_sensor', 'fit')
    if (status == FRICREG_OK) status = self%record(fricreg_fit_set_sensor(self%ptr, s))
  end function fit_set_sensor

  !> Parameter which free, from start (NaN: from the levels) within (lower, upper) (use
  !> ieee_value or huge() for none). FRICREG_EINVAL; FRICREG_ENONFINITE.
  function fit_set_free(self, which, start, lower, upper) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    integer, intent(in) :: which
    real(c_double), intent(in) :: start, lower, upper
    integer(c_int) :: status
    status = self%ready('set_free', 'fit')
    if (status == FRICREG_OK) status = self%record(fricreg_fit_set_free(self%ptr, &
      int(which, c_int), start, lower, upper))
  end function fit_set_free

  !> Parameter which fixed at value. FRICREG_EINVAL; FRICREG_ENONFINITE.
  function fit_set_fixed(self, which, value) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    integer, intent(in) :: which
    real(c_double), intent(in) :: value
    integer(c_int) :: status
    status = self%ready('set_fixed', 'fit')
    if (status == FRICREG_OK) status = self%record(fricreg_fit_set_fixed(self%ptr, &
      int(which, c_int), value))
  end function fit_set_fixed

  !> The number of starts, 1 to 1000. FRICREG_EINVAL.
  function fit_set_starts(self, nstarts) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    integer, intent(in) :: nstarts
    integer(c_int) :: status
    status = self%ready('set_starts', 'fit')
    if (status == FRICREG_OK .and. nstarts < 1) &
      status = self%fail(FRICREG_EINVAL, 'set_starts: nstarts must be >= 1')
    if (status == FRICREG_OK) status = self%record(fricreg_fit_set_starts(self%ptr, &
      as_size(nstarts)))
  end function fit_set_starts

  !> Fit the free parameters to the levels (fricreg_fit_run): FRICREG_OK, or nothing reported
  !> as a fit and FRICREG_EINVAL (too few levels, a parameter at its bound, ...),
  !> FRICREG_ESINGULAR (the levels do not determine the parameters), FRICREG_EWORK,
  !> FRICREG_ENOMEM; errmsg says which and why.
  function fit_run(self) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    integer(c_int) :: status
    status = self%ready('run', 'fit')
    if (status == FRICREG_OK) status = self%record(fricreg_fit_run(self%ptr))
  end function fit_run

  !> The fitted parameters p(6). FRICREG_ESIZE; FRICREG_EINVAL if no run has succeeded.
  function fit_params(self, p) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: p(:)
    integer(c_int) :: status
    status = self%ready('params', 'fit')
    if (status == FRICREG_OK) status = self%check_size('params', 'p', size(p), &
                                                       as_size(FRICREG_FIT_NPARAMS))
    if (status == FRICREG_OK) status = self%unrecorded('params', &
      fricreg_fit_get_params(self%ptr, as_size(FRICREG_FIT_NPARAMS), p))
  end function fit_params

  !> The covariance cov(6, 6) and the 95 % intervals lower(6), upper(6). FRICREG_ESIZE;
  !> FRICREG_EINVAL if no run has succeeded.
  function fit_covariance(self, cov, lower, upper) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: cov(:, :), lower(:), upper(:)
    integer(c_int) :: status
    status = self%ready('covariance', 'fit')
    if (status == FRICREG_OK .and. (size(cov, 1) /= FRICREG_FIT_NPARAMS .or. &
                                    size(cov, 2) /= FRICREG_FIT_NPARAMS .or. &
                                    size(lower) /= FRICREG_FIT_NPARAMS .or. &
                                    size(upper) /= FRICREG_FIT_NPARAMS)) &
      status = self%fail(FRICREG_ESIZE, 'covariance: cov must be (6, 6), lower and upper (6)')
    if (status == FRICREG_OK) status = self%unrecorded('covariance', &
      fricreg_fit_get_covariance(self%ptr, as_size(FRICREG_FIT_NPARAMS), cov, lower, upper))
  end function fit_covariance

  !> One number of the fit (FRICREG_FIT_COST, ..._NFEV, ...) into v. FRICREG_EINVAL.
  function fit_value(self, which, v) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    integer, intent(in) :: which
    real(c_double), intent(out) :: v
    integer(c_int) :: status
    v = 0
    status = self%ready('value', 'fit')
    if (status == FRICREG_OK) status = self%unrecorded('value', &
      fricreg_fit_get_value(self%ptr, int(which, c_int), v))
  end function fit_value

  !> The model's backbone at amplitude(n) of kind for parameters p(6): freq_hz(n), zeta(n) and,
  !> where given, the sensitivities dfreq_dp(6, n), dzeta_dp(6, n) (column i: level i).
  !> FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function fit_eval(self, p, kind, amplitude, freq_hz, zeta, dfreq_dp, dzeta_dp) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    real(c_double), intent(in), contiguous :: p(:), amplitude(:)
    integer, intent(in) :: kind
    real(c_double), intent(inout), contiguous :: freq_hz(:), zeta(:)
    real(c_double), intent(inout), contiguous, optional :: dfreq_dp(:, :), dzeta_dp(:, :)
    integer(c_int) :: status
    integer :: n
    n = size(amplitude)
    status = self%ready('eval', 'fit')
    if (status == FRICREG_OK .and. (size(p) /= FRICREG_FIT_NPARAMS .or. size(freq_hz) /= n &
                                    .or. size(zeta) /= n)) &
      status = self%fail(FRICREG_ESIZE, 'eval: p must be (6), freq_hz and zeta (n)')
    if (status == FRICREG_OK .and. present(dfreq_dp)) then
      if (size(dfreq_dp, 1) /= FRICREG_FIT_NPARAMS .or. size(dfreq_dp, 2) /= n) &
        status = self%fail(FRICREG_ESIZE, 'eval: dfreq_dp must be (6, n)')
    end if
    if (status == FRICREG_OK .and. present(dzeta_dp)) then
      if (size(dzeta_dp, 1) /= FRICREG_FIT_NPARAMS .or. size(dzeta_dp, 2) /= n) &
        status = self%fail(FRICREG_ESIZE, 'eval: dzeta_dp must be (6, n)')
    end if
    if (status == FRICREG_OK) status = self%record(fricreg_fit_eval(self%ptr, p, &
      int(kind, c_int), as_size(n), amplitude, freq_hz, zeta, dfreq_dp=dfreq_dp, &
      dzeta_dp=dzeta_dp))
  end function fit_eval

  !> The fitted backbone at amplitude(n) of the levels' kind, freq_hz(n), zeta(n), and their
  !> standard deviations sd_freq_hz(n), sd_zeta(n) (the delta method). FRICREG_ESIZE;
  !> FRICREG_EINVAL if no run has succeeded or an amplitude is refused.
  function fit_curve(self, amplitude, freq_hz, zeta, sd_freq_hz, sd_zeta) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    real(c_double), intent(in), contiguous :: amplitude(:)
    real(c_double), intent(inout), contiguous :: freq_hz(:), zeta(:), sd_freq_hz(:), sd_zeta(:)
    integer(c_int) :: status
    integer :: n
    n = size(amplitude)
    status = self%ready('curve', 'fit')
    if (status == FRICREG_OK .and. (size(freq_hz) /= n .or. size(zeta) /= n .or. &
                                    size(sd_freq_hz) /= n .or. size(sd_zeta) /= n)) &
      status = self%fail(FRICREG_ESIZE, 'curve: every array must be (n)')
    if (status == FRICREG_OK) status = self%record(fricreg_fit_curve(self%ptr, as_size(n), &
      amplitude, freq_hz, zeta, sd_freq_hz, sd_zeta))
  end function fit_curve

end module fricreg_fit_m
