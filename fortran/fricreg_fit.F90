! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_fit.F90 — module fricreg_fit_m: type fricreg_backbone_fit, the identification of a
! modal Iwan joint, or of a harmonic-balance model's nonlinear mode, from a test's measured
! levels (fricreg_fit.h, docs/identification.md), and its procedures. Built with the drivers only (FRICREG_DRIVERS).
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_fit_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_null_ptr
  use fricreg_c
  use fricreg_sim_c
  use fricreg_base_m, only: fricreg_object, fricreg_error_string, as_size
  use fricreg_hb_m, only: fricreg_hb_driver
  implicit none
  private
  public :: fricreg_backbone_fit

  !> The modal Iwan model (Segalman's four-parameter joint beside a linear modal stiffness K0
  !> and damping ratio zeta0), or with set_model_hb a nonlinear mode of a harmonic-balance
  !> driver, fitted to a mode's measured frequency and damping ratio at several levels
  !> (fricreg_fit.h). Parameters are indexed by which = FRICREG_FIT_FS .. FRICREG_FIT_K0
  !> (0-based, as in C; an HB model's 0 .. np - 1 in the order set_model_hb describes them);
  !> parameter arrays have np entries (FRICREG_FIT_NPARAMS = 6, or set_model_hb's), p(which + 1)
  !> parameter which. The covariance is (np, np), symmetric; sensitivities are (np, n), column i
  !> level i.
  type, extends(fricreg_object) :: fricreg_backbone_fit
    private
    integer :: np = FRICREG_FIT_NPARAMS ! the model's parameter count (C has no getter)
    integer(c_size_t) :: ndof = 0       ! an HB model's driver's sizes, for set_sensor_dof
    integer(c_int) :: harmonics = 0
  contains
    procedure :: create => fit_create
    procedure :: set_model_hb => fit_set_model_hb
    procedure :: set_model_modal_iwan => fit_set_model_modal_iwan
    procedure :: set_sensor_dof => fit_set_sensor_dof
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
    call modal_iwan_sizes(self)
  end function fit_create

  subroutine modal_iwan_sizes(self)
    class(fricreg_backbone_fit), intent(inout) :: self
    self%np = FRICREG_FIT_NPARAMS
    self%ndof = 0
    self%harmonics = 0
  end subroutine modal_iwan_sizes

  !> Fit mode `mode` (from 1, as hb%nma) of the driver hb instead (fricreg_fit_set_model_hb:
  !> its EPMC backbone), its np = size(kind) parameters (1 to 16) described by kind(np),
  !> first(np), count(np), index(np): kind FRICREG_HB_NMA_PARAM_ELEMENT, the value shared by
  !> the elements first .. first + count - 1 (counted from 1, in the order the driver holds
  !> them) at index of each one's layout (from 1: the row of hb%add_elements' params, jenkins
  !> 1 kt, 2 mu N); or FRICREG_HB_NMA_PARAM_DAMPING, index 1 Rayleigh's a0, 2 a1 (first and
  !> count ignored). damping FRICREG_HB_NMA_DAMPING_MATRIX (absent) or _MODAL. Fortran counts
  !> from 1 here; which of set_free, set_fixed stays C's, 0 .. np - 1. hb is borrowed: keep it
  !> alive and unused while the fit uses it (the fit's calls change its values). qsma .true.:
  !> its quasi-static modal analysis instead (fricreg_fit_set_model_qsma; damping ignored, the
  !> levels modal). FRICREG_ESIZE if the arrays differ in size; FRICREG_EINVAL (a count from 0,
  !> C's refusals); FRICREG_ENOMEM.
  function fit_set_model_hb(self, hb, mode, kind, first, count, index, damping, qsma) &
    result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    class(fricreg_hb_driver), intent(in) :: hb
    integer, intent(in) :: mode, kind(:), first(:), count(:), index(:)
    integer(c_int), intent(in), optional :: damping
    logical, intent(in), optional :: qsma
    integer(c_int) :: status, d
    integer(c_int), allocatable :: ck(:)
    integer(c_size_t), allocatable :: cf(:), cc(:), ci(:)
    integer :: np, j
    logical :: element
    np = size(kind)
    d = FRICREG_HB_NMA_DAMPING_MATRIX
    if (present(damping)) d = damping
    status = self%ready('set_model_hb', 'fit')
    if (status == FRICREG_OK .and. .not. hb%is_created()) &
      status = self%fail(FRICREG_ENULL, 'set_model_hb: the HB driver is not created')
    if (status == FRICREG_OK .and. (size(first) /= np .or. size(count) /= np .or. &
                                    size(index) /= np)) &
      status = self%fail(FRICREG_ESIZE, 'set_model_hb: kind, first, count and index must ' // &
                         'have one size (np)')
    if (status == FRICREG_OK .and. mode < 1) &
      status = self%fail(FRICREG_EINVAL, 'set_model_hb: mode must be >= 1 (Fortran counts from 1)')
    if (status /= FRICREG_OK) return
    allocate (ck(max(np, 1)), cf(max(np, 1)), cc(max(np, 1)), ci(max(np, 1)))
    ck = 0
    cf = 0
    cc = 0
    ci = 0
    do j = 1, np
      element = kind(j) == FRICREG_HB_NMA_PARAM_ELEMENT
      if (element .and. (first(j) < 1 .or. count(j) < 1 .or. index(j) < 1) .or. &
          .not. element .and. index(j) < 0) then
        status = self%fail(FRICREG_EINVAL, 'set_model_hb: an element''s first, count and ' // &
                           'index must be >= 1 (Fortran counts from 1)')
        return
      end if
      ck(j) = int(kind(j), c_int)
      if (element) then
        cf(j) = as_size(first(j) - 1)
        cc(j) = as_size(count(j))
        ci(j) = as_size(index(j) - 1)
      else
        ci(j) = as_size(index(j)) ! damping: 1 a0, 2 a1 as in C
      end if
    end do
    if (present(qsma)) then
      if (qsma) then
        status = self%record(fricreg_fit_set_model_qsma(self%ptr, hb%ptr, as_size(mode - 1), &
                                                        as_size(np), ck, cf, cc, ci))
      else
        status = self%record(fricreg_fit_set_model_hb(self%ptr, hb%ptr, as_size(mode - 1), d, &
                                                      as_size(np), ck, cf, cc, ci))
      end if
    else
      status = self%record(fricreg_fit_set_model_hb(self%ptr, hb%ptr, as_size(mode - 1), d, &
                                                    as_size(np), ck, cf, cc, ci))
    end if
    if (status /= FRICREG_OK) return
    self%np = np
    self%ndof = as_size(hb%ndof())
    self%harmonics = int(hb%harmonics(), c_int)
  end function fit_set_model_hb

  !> The modal Iwan model again (fricreg_fit_set_model_modal_iwan): its six parameters with
  !> their defaults, 32 starts; the levels, deviations and sensor value kept.
  function fit_set_model_modal_iwan(self) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    integer(c_int) :: status
    status = self%ready('set_model_modal_iwan', 'fit')
    if (status == FRICREG_OK) status = self%record(fricreg_fit_set_model_modal_iwan(self%ptr))
    if (status == FRICREG_OK) call modal_iwan_sizes(self)
  end function fit_set_model_modal_iwan

  !> An HB model's levels measured at dof `dof` (from 1) of its driver: |X_1,dof| times omega^kind
  !> (fricreg_fit_set_sensor_dof, the driver's sizes from set_model_hb); set_sensor makes them
  !> modal again. FRICREG_EINVAL for the modal Iwan model or a dof outside 1 .. ndof.
  function fit_set_sensor_dof(self, dof) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    integer, intent(in) :: dof
    integer(c_int) :: status
    status = self%ready('set_sensor_dof', 'fit')
    if (status == FRICREG_OK .and. dof < 1) &
      status = self%fail(FRICREG_EINVAL, 'set_sensor_dof: dof must be >= 1 (Fortran counts ' // &
                         'from 1)')
    if (status == FRICREG_OK) status = self%record(fricreg_fit_set_sensor_dof(self%ptr, &
      self%ndof, self%harmonics, as_size(dof - 1)))
  end function fit_set_sensor_dof

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

  !> The fitted parameters p(np) (np 6, or set_model_hb's). FRICREG_ESIZE; FRICREG_EINVAL if no
  !> run has succeeded.
  function fit_params(self, p) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: p(:)
    integer(c_int) :: status
    status = self%ready('params', 'fit')
    if (status == FRICREG_OK) status = self%check_size('params', 'p', size(p), as_size(self%np))
    if (status == FRICREG_OK) status = self%unrecorded('params', &
      fricreg_fit_get_params(self%ptr, as_size(self%np), p))
  end function fit_params

  !> The covariance cov(np, np) and the 95 % intervals lower(np), upper(np). FRICREG_ESIZE;
  !> FRICREG_EINVAL if no run has succeeded.
  function fit_covariance(self, cov, lower, upper) result(status)
    class(fricreg_backbone_fit), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: cov(:, :), lower(:), upper(:)
    integer(c_int) :: status
    status = self%ready('covariance', 'fit')
    if (status == FRICREG_OK .and. (size(cov, 1) /= self%np .or. size(cov, 2) /= self%np .or. &
                                    size(lower) /= self%np .or. size(upper) /= self%np)) &
      status = self%fail(FRICREG_ESIZE, 'covariance: cov must be (np, np), lower and upper ' // &
                         '(np), np the model''s parameters')
    if (status == FRICREG_OK) status = self%unrecorded('covariance', &
      fricreg_fit_get_covariance(self%ptr, as_size(self%np), cov, lower, upper))
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

  !> The model's backbone at amplitude(n) of kind for parameters p(np): freq_hz(n), zeta(n) and,
  !> where given, the sensitivities dfreq_dp(np, n), dzeta_dp(np, n) (column i: level i); an HB
  !> model's driver is left at p. FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
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
    if (status == FRICREG_OK .and. (size(p) /= self%np .or. size(freq_hz) /= n &
                                    .or. size(zeta) /= n)) &
      status = self%fail(FRICREG_ESIZE, 'eval: p must be (np), freq_hz and zeta (n)')
    if (status == FRICREG_OK .and. present(dfreq_dp)) then
      if (size(dfreq_dp, 1) /= self%np .or. size(dfreq_dp, 2) /= n) &
        status = self%fail(FRICREG_ESIZE, 'eval: dfreq_dp must be (np, n)')
    end if
    if (status == FRICREG_OK .and. present(dzeta_dp)) then
      if (size(dzeta_dp, 1) /= self%np .or. size(dzeta_dp, 2) /= n) &
        status = self%fail(FRICREG_ESIZE, 'eval: dzeta_dp must be (np, n)')
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
