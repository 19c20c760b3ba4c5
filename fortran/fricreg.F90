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
! What `use fricreg` gives:
!   - every constant of the C headers (FRICREG_OK, FRICREG_LAW_QUINN, ...), generated from
!     them at build time (module fricreg_constants), and the iso_c_binding kinds c_int,
!     c_double, c_size_t, c_int64_t, c_ptr;
!   - every C function by its C name, bound argument for argument (modules fricreg_c and
!     fricreg_sim_c: scalars by value, arrays dimension(*) with the count passed, handles as
!     type(c_ptr));
!   - the idiomatic layer below: type fricreg_context (and fricreg_simulation, with the
!     drivers), law_eval, fricreg_error_string, fricreg_version_string.
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
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_ptr, &
                                         c_funptr, c_char, c_null_ptr, c_null_funptr, &
                                         c_null_char, c_associated, c_funloc
  use fricreg_c
#ifdef FRICREG_HAVE_SIM
  use fricreg_sim_c
#endif
  implicit none
  public
  private :: error_record, fail, not_created, set_failed, check_size, as_size, message_of, &
             ctx_create, ctx_destroy, ctx_final, ctx_assign, ctx_is_created, ctx_handle, &
             ctx_size, ctx_set_law, ctx_set_bounds, ctx_set_coupling_diagonal, &
             ctx_set_coupling_dense, ctx_eval, ctx_get_stat, ctx_reset_stats, ctx_errcode, &
             ctx_errmsg, law_eval_scalar, law_eval_array

  !> A failure detected in Fortran (a size mismatch, an object not created), kept beside the
  !> C library's own record; `last` says which of the two is the more recent.
  type :: error_record
    integer(c_int) :: code = FRICREG_OK
    logical :: last = .false.
    character(len=:), allocatable :: msg
  end type

  !> m coupled contacts z'' = a_free + W f (Sec. 3.3): law, eps, bounds mun, coupling W.
  !> Holds a fricreg_ctx; see include/fricreg.h for the meaning of every setting.
  type :: fricreg_context
    private
    type(c_ptr) :: ptr = c_null_ptr
    integer(c_size_t) :: m = 0
    type(error_record) :: err
  contains
    procedure :: create => ctx_create
    procedure :: destroy => ctx_destroy
    procedure :: is_created => ctx_is_created
    procedure :: handle => ctx_handle
    procedure :: size => ctx_size
    procedure :: set_law => ctx_set_law
    procedure :: set_bounds => ctx_set_bounds
    procedure :: set_coupling_diagonal => ctx_set_coupling_diagonal
    procedure :: set_coupling_dense => ctx_set_coupling_dense
    procedure :: eval => ctx_eval
    procedure :: get_stat => ctx_get_stat
    procedure :: reset_stats => ctx_reset_stats
    procedure :: errcode => ctx_errcode
    procedure :: errmsg => ctx_errmsg
    procedure, private :: ctx_assign
    generic :: assignment(=) => ctx_assign
    final :: ctx_final
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

#ifdef FRICREG_HAVE_SIM
  private :: sim_create, sim_destroy, sim_final, sim_assign, sim_is_created, sim_handle, &
             sim_set_param, sim_set_law, sim_set_integrator, sim_set_observer, sim_run, &
             sim_run_cycles, sim_ndof, sim_ncontacts, sim_get_value, sim_get_state, &
             sim_get_dissipation, sim_get_stick_fraction, sim_errcode, sim_errmsg

  !> One of the paper's reference systems on a GSL ODE driver (include/fricreg_sim.h).
  type :: fricreg_simulation
    private
    type(c_ptr) :: ptr = c_null_ptr
    type(error_record) :: err
  contains
    procedure :: create => sim_create
    procedure :: destroy => sim_destroy
    procedure :: is_created => sim_is_created
    procedure :: handle => sim_handle
    procedure :: set_param => sim_set_param
    procedure :: set_law => sim_set_law
    procedure :: set_integrator => sim_set_integrator
    procedure :: set_observer => sim_set_observer
    procedure :: run => sim_run
    procedure :: run_cycles => sim_run_cycles
    procedure :: ndof => sim_ndof
    procedure :: ncontacts => sim_ncontacts
    procedure :: get_value => sim_get_value
    procedure :: get_state => sim_get_state
    procedure :: get_dissipation => sim_get_dissipation
    procedure :: get_stick_fraction => sim_get_stick_fraction
    procedure :: errcode => sim_errcode
    procedure :: errmsg => sim_errmsg
    procedure, private :: sim_assign
    generic :: assignment(=) => sim_assign
    final :: sim_final
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

  !> Version "MAJOR.MINOR.PATCH" of the library linked (FRICREG_VERSION_STRING: the headers').
  function fricreg_version_string() result(text)
    character(len=:), allocatable :: text
    text = fricreg_c_string(fricreg_version())
  end function fricreg_version_string

  ! ---- Helpers -----------------------------------------------------------------------------

  !> Records a failure found on the Fortran side and returns its code.
  function fail(err, code, msg) result(status)
    type(error_record), intent(inout) :: err
    integer(c_int), intent(in) :: code
    character(len=*), intent(in) :: msg
    integer(c_int) :: status
    err%code = code
    err%msg = msg
    err%last = .true.
    status = code
  end function fail

  function not_created(err, what, kind) result(status)
    type(error_record), intent(inout) :: err
    character(len=*), intent(in) :: what, kind
    integer(c_int) :: status
    status = fail(err, FRICREG_ENULL, what // ': the ' // kind // ' is not created (call create)')
  end function not_created

  !> After a C call: a failure there is now the most recent one.
  subroutine set_failed(err, status)
    type(error_record), intent(inout) :: err
    integer(c_int), intent(in) :: status
    if (status /= FRICREG_OK) err%last = .false.
  end subroutine set_failed

  !> FRICREG_OK if n == expected, else a recorded FRICREG_ESIZE naming the array.
  function check_size(err, what, array, n, expected) result(status)
    type(error_record), intent(inout) :: err
    character(len=*), intent(in) :: what, array
    integer, intent(in) :: n
    integer(c_size_t), intent(in) :: expected
    integer(c_int) :: status
    character(len=64) :: buf
    status = FRICREG_OK
    if (int(n, c_size_t) /= expected) then
      write (buf, '(a, i0, a, i0)') ') = ', n, ', expected ', expected
      status = fail(err, FRICREG_ESIZE, what // ': size(' // array // trim(buf))
    end if
  end function check_size

  pure function as_size(n) result(m)
    integer, intent(in) :: n
    integer(c_size_t) :: m
    m = int(n, c_size_t)
  end function as_size

  function message_of(err, c_code, c_msg) result(msg)
    type(error_record), intent(in) :: err
    integer(c_int), intent(in) :: c_code
    type(c_ptr), intent(in) :: c_msg
    character(len=:), allocatable :: msg
    if (err%last .or. (c_code == FRICREG_OK .and. err%code /= FRICREG_OK)) then
      msg = err%msg
    else
      msg = fricreg_c_string(c_msg)
    end if
  end function message_of

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
      status = fail(self%err, FRICREG_EINVAL, 'create: m = ' // trim(buf) // ' must be >= 1')
      return
    end if
    status = fricreg_ctx_create(as_size(m), p)
    if (status /= FRICREG_OK) then
      status = fail(self%err, status, 'create: m = ' // trim(buf) // ': ' // &
                    fricreg_error_string(status))
      return
    end if
    call fricreg_ctx_free(self%ptr)
    self%ptr = p
    self%m = fricreg_ctx_size(p)
    self%err = error_record()
  end function ctx_create

  !> Release the C context. Safe to call twice, and on an object never created.
  subroutine ctx_destroy(self)
    class(fricreg_context), intent(inout) :: self
    call fricreg_ctx_free(self%ptr) ! fricreg_ctx_free(NULL) does nothing
    self%ptr = c_null_ptr
    self%m = 0
  end subroutine ctx_destroy

  subroutine ctx_final(self)
    type(fricreg_context), intent(inout) :: self
    call ctx_destroy(self)
  end subroutine ctx_final

  !> `lhs = rhs`: contexts cannot be copied; lhs is released and left empty.
  subroutine ctx_assign(lhs, rhs)
    class(fricreg_context), intent(inout) :: lhs
    class(fricreg_context), intent(in) :: rhs
    if (c_associated(lhs%ptr, rhs%ptr)) return ! a = a
    call ctx_destroy(lhs)
    lhs%err = error_record()
  end subroutine ctx_assign

  logical function ctx_is_created(self)
    class(fricreg_context), intent(in) :: self
    ctx_is_created = c_associated(self%ptr)
  end function ctx_is_created

  !> The C handle (fricreg_ctx *), for the bind(C) functions; still owned by self.
  type(c_ptr) function ctx_handle(self)
    class(fricreg_context), intent(in) :: self
    ctx_handle = self%ptr
  end function ctx_handle

  !> Number of contacts m (0 if not created).
  integer function ctx_size(self)
    class(fricreg_context), intent(in) :: self
    ctx_size = int(self%m)
  end function ctx_size

  !> Law (enum fricreg_law: FRICREG_LAW_*) and eps > 0 (velocity units).
  !> FRICREG_EINVAL for an unknown law or eps <= 0; FRICREG_ENONFINITE.
  function ctx_set_law(self, law, eps) result(status)
    class(fricreg_context), intent(inout) :: self
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps
    integer(c_int) :: status
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'set_law', 'context')
      return
    end if
    status = fricreg_ctx_set_law(self%ptr, law, eps)
    call set_failed(self%err, status)
  end function ctx_set_law

  !> Friction bounds mun(m) = mu_i N_i >= 0. FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function ctx_set_bounds(self, mun) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: mun(:)
    integer(c_int) :: status
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'set_bounds', 'context')
      return
    end if
    status = check_size(self%err, 'set_bounds', 'mun', size(mun), self%m)
    if (status /= FRICREG_OK) return
    status = fricreg_ctx_set_bounds(self%ptr, self%m, mun)
    call set_failed(self%err, status)
  end function ctx_set_bounds

  !> Uncoupled contacts, W = diag(w), w(m) > 0 (inverse effective masses).
  function ctx_set_coupling_diagonal(self, w) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: w(:)
    integer(c_int) :: status
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'set_coupling_diagonal', 'context')
      return
    end if
    status = check_size(self%err, 'set_coupling_diagonal', 'w', size(w), self%m)
    if (status /= FRICREG_OK) return
    status = fricreg_ctx_set_coupling_diagonal(self%ptr, self%m, w)
    call set_failed(self%err, status)
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
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'set_coupling_dense', 'context')
      return
    end if
    status = check_size(self%err, 'set_coupling_dense', 'W, 1', size(W, 1), self%m)
    if (status == FRICREG_OK) &
      status = check_size(self%err, 'set_coupling_dense', 'W, 2', size(W, 2), self%m)
    if (status /= FRICREG_OK) return
    status = fricreg_ctx_set_coupling_dense(self%ptr, self%m, W)
    call set_failed(self%err, status)
  end function ctx_set_coupling_dense

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
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'eval', 'context')
      return
    end if
    status = check_size(self%err, 'eval', 'zdot', size(zdot), self%m)
    if (status == FRICREG_OK) status = check_size(self%err, 'eval', 'a_free', size(a_free), self%m)
    if (status == FRICREG_OK) status = check_size(self%err, 'eval', 'f', size(f), self%m)
    if (status == FRICREG_OK .and. present(f_eq)) &
      status = check_size(self%err, 'eval', 'f_eq', size(f_eq), self%m)
    if (status /= FRICREG_OK) return
    status = fricreg_ctx_eval(self%ptr, self%m, zdot, a_free, f, f_eq)
    call set_failed(self%err, status)
  end function ctx_eval

  !> One counter (FRICREG_STAT_*) into value. FRICREG_EINVAL for an unknown counter.
  function ctx_get_stat(self, which, value) result(status)
    class(fricreg_context), intent(inout) :: self
    integer(c_int), intent(in) :: which
    integer(c_int64_t), intent(inout) :: value
    integer(c_int) :: status
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'get_stat', 'context')
      return
    end if
    status = fricreg_ctx_get_stat(self%ptr, which, value)
    if (status /= FRICREG_OK) status = fail(self%err, status, 'get_stat: ' // &
                                            fricreg_error_string(status))
  end function ctx_get_stat

  subroutine ctx_reset_stats(self)
    class(fricreg_context), intent(inout) :: self
    call fricreg_ctx_reset_stats(self%ptr) ! does nothing on NULL
  end subroutine ctx_reset_stats

  !> Status of the last failed call on this object (FRICREG_OK if none).
  integer(c_int) function ctx_errcode(self)
    class(fricreg_context), intent(in) :: self
    ctx_errcode = fricreg_ctx_errcode(self%ptr)
    if (self%err%last .or. ctx_errcode == FRICREG_OK) then
      if (self%err%code /= FRICREG_OK) ctx_errcode = self%err%code
    end if
  end function ctx_errcode

  !> Message of the last failed call, naming the argument, contact or value ('' if none).
  function ctx_errmsg(self) result(msg)
    class(fricreg_context), intent(in) :: self
    character(len=:), allocatable :: msg
    if (c_associated(self%ptr)) then
      msg = message_of(self%err, fricreg_ctx_errcode(self%ptr), fricreg_ctx_errmsg(self%ptr))
    else if (self%err%code /= FRICREG_OK) then
      msg = self%err%msg
    else
      msg = ''
    end if
  end function ctx_errmsg

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
    status = fricreg_sim_create(system, p)
    if (status /= FRICREG_OK) then
      write (buf, '(i0)') system
      status = fail(self%err, status, 'create: system ' // trim(buf) // ': ' // &
                    fricreg_error_string(status))
      return
    end if
    call fricreg_sim_free(self%ptr)
    self%ptr = p
    self%err = error_record()
  end function sim_create

  !> Release the simulation. Safe to call twice.
  subroutine sim_destroy(self)
    class(fricreg_simulation), intent(inout) :: self
    call fricreg_sim_free(self%ptr)
    self%ptr = c_null_ptr
  end subroutine sim_destroy

  subroutine sim_final(self)
    type(fricreg_simulation), intent(inout) :: self
    call sim_destroy(self)
  end subroutine sim_final

  !> `lhs = rhs`: simulations cannot be copied; lhs is released and left empty.
  subroutine sim_assign(lhs, rhs)
    class(fricreg_simulation), intent(inout) :: lhs
    class(fricreg_simulation), intent(in) :: rhs
    if (c_associated(lhs%ptr, rhs%ptr)) return ! a = a
    call sim_destroy(lhs)
    lhs%err = error_record()
  end subroutine sim_assign

  logical function sim_is_created(self)
    class(fricreg_simulation), intent(in) :: self
    sim_is_created = c_associated(self%ptr)
  end function sim_is_created

  !> The C handle (fricreg_sim *), for the bind(C) functions; still owned by self.
  type(c_ptr) function sim_handle(self)
    class(fricreg_simulation), intent(in) :: self
    sim_handle = self%ptr
  end function sim_handle

  !> One system parameter (FRICREG_PARAM_*); discards results. FRICREG_EINVAL for a parameter
  !> the system does not have or a value out of range; FRICREG_ENONFINITE.
  function sim_set_param(self, param, value) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: param
    real(c_double), intent(in) :: value
    integer(c_int) :: status
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'set_param', 'simulation')
      return
    end if
    status = fricreg_sim_set_param(self%ptr, param, value)
    call set_failed(self%err, status)
  end function sim_set_param

  !> Law (FRICREG_LAW_*) and eps > 0; eps = 0 selects the paper's rule (2 dt, or 10 omega dt
  !> for the chain).
  function sim_set_law(self, law, eps) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps
    integer(c_int) :: status
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'set_law', 'simulation')
      return
    end if
    status = fricreg_sim_set_law(self%ptr, law, eps)
    call set_failed(self%err, status)
  end function sim_set_law

  !> Integrator (FRICREG_INT_*), step dt > 0, and rtol, atol (both omitted or 0: fixed step).
  function sim_set_integrator(self, integrator, dt, rtol, atol) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer(c_int), intent(in) :: integrator
    real(c_double), intent(in) :: dt
    real(c_double), intent(in), optional :: rtol, atol
    integer(c_int) :: status
    real(c_double) :: r, a
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'set_integrator', 'simulation')
      return
    end if
    r = 0.0_c_double
    a = 0.0_c_double
    if (present(rtol)) r = rtol
    if (present(atol)) a = atol
    status = fricreg_sim_set_integrator(self%ptr, integrator, dt, r, a)
    call set_failed(self%err, status)
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
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'set_observer', 'simulation')
      return
    end if
    fn = c_null_funptr
    u = c_null_ptr
    if (present(fricreg_observer)) fn = c_funloc(fricreg_observer)
    if (present(user)) u = user
    status = fricreg_sim_set_observer(self%ptr, fn, u)
    call set_failed(self%err, status)
  end function sim_set_observer

  !> Integrate from t = 0 to t_end > 0 (see fricreg_sim_run for the returns).
  function sim_run(self, t_end) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(in) :: t_end
    integer(c_int) :: status
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'run', 'simulation')
      return
    end if
    status = fricreg_sim_run(self%ptr, t_end)
    call set_failed(self%err, status)
  end function sim_run

  !> Integrate `cycles` >= 1 whole forcing cycles.
  function sim_run_cycles(self, cycles) result(status)
    class(fricreg_simulation), intent(inout) :: self
    integer, intent(in) :: cycles
    integer(c_int) :: status
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'run_cycles', 'simulation')
      return
    end if
    status = fricreg_sim_run_cycles(self%ptr, int(cycles, c_int))
    call set_failed(self%err, status)
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
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'get_value', 'simulation')
      return
    end if
    status = fricreg_sim_get_value(self%ptr, which, value)
    if (status /= FRICREG_OK) status = fail(self%err, status, 'get_value: ' // &
                                            fricreg_error_string(status))
  end function sim_get_value

  !> State at the end of the last run (the initial state before one): x(ndof), v(ndof).
  function sim_get_state(self, x, v) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: x(:), v(:)
    integer(c_int) :: status
    integer(c_size_t) :: n
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'get_state', 'simulation')
      return
    end if
    n = fricreg_sim_ndof(self%ptr)
    status = check_size(self%err, 'get_state', 'x', size(x), n)
    if (status == FRICREG_OK) status = check_size(self%err, 'get_state', 'v', size(v), n)
    if (status /= FRICREG_OK) return
    status = fricreg_sim_get_state(self%ptr, n, x, v)
    if (status /= FRICREG_OK) status = fail(self%err, status, 'get_state: ' // &
                                            fricreg_error_string(status))
  end function sim_get_state

  !> D per whole forcing cycle of the last run, D_k = -int sum_i w_i zdot_i f_i dt (w_i = 1/n
  !> for the chain, else 1): D is (re)allocated to the number of cycles completed.
  function sim_get_dissipation(self, D) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), allocatable, intent(inout) :: D(:)
    integer(c_int) :: status
    real(c_double) :: cycles
    real(c_double), allocatable :: tmp(:)
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'get_dissipation', 'simulation')
      return
    end if
    cycles = 0.0_c_double
    status = fricreg_sim_get_value(self%ptr, FRICREG_VALUE_CYCLES, cycles)
    if (status == FRICREG_OK) then
      allocate (tmp(max(1, int(cycles))))
      status = fricreg_sim_get_dissipation(self%ptr, int(cycles, c_size_t), tmp)
    end if
    if (status /= FRICREG_OK) then
      status = fail(self%err, status, 'get_dissipation: ' // fricreg_error_string(status))
      return
    end if
    D = tmp(1:int(cycles))
  end function sim_get_dissipation

  !> Per contact, the fraction of the last whole cycle with |zdot_i| < eps: frac(ncontacts).
  function sim_get_stick_fraction(self, frac) result(status)
    class(fricreg_simulation), intent(inout) :: self
    real(c_double), intent(inout), contiguous :: frac(:)
    integer(c_int) :: status
    integer(c_size_t) :: m
    if (.not. c_associated(self%ptr)) then
      status = not_created(self%err, 'get_stick_fraction', 'simulation')
      return
    end if
    m = fricreg_sim_ncontacts(self%ptr)
    status = check_size(self%err, 'get_stick_fraction', 'frac', size(frac), m)
    if (status /= FRICREG_OK) return
    status = fricreg_sim_get_stick_fraction(self%ptr, m, frac)
    if (status /= FRICREG_OK) status = fail(self%err, status, 'get_stick_fraction: ' // &
                                            fricreg_error_string(status))
  end function sim_get_stick_fraction

  integer(c_int) function sim_errcode(self)
    class(fricreg_simulation), intent(in) :: self
    sim_errcode = fricreg_sim_errcode(self%ptr)
    if (self%err%last .or. sim_errcode == FRICREG_OK) then
      if (self%err%code /= FRICREG_OK) sim_errcode = self%err%code
    end if
  end function sim_errcode

  !> Message of the last failed call: names the parameter, time or contact ('' if none).
  function sim_errmsg(self) result(msg)
    class(fricreg_simulation), intent(in) :: self
    character(len=:), allocatable :: msg
    if (c_associated(self%ptr)) then
      msg = message_of(self%err, fricreg_sim_errcode(self%ptr), fricreg_sim_errmsg(self%ptr))
    else if (self%err%code /= FRICREG_OK) then
      msg = self%err%msg
    else
      msg = ''
    end if
  end function sim_errmsg
#endif

end module fricreg
