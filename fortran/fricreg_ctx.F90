! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_ctx.F90 — module fricreg_ctx_m: type fricreg_context, m coupled contacts (fricreg.h),
! and its procedures; solve_step and its sparse forms with the drivers (FRICREG_HAVE_SIM).
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_ctx_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_ptr, c_null_ptr
  use fricreg_c
#ifdef FRICREG_HAVE_SIM
  use fricreg_sim_c
#endif
  use fricreg_base_m, only: fricreg_object, fricreg_error_string, as_size
  implicit none
  private
  public :: fricreg_context

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
    procedure :: solve_step_matrix => ctx_solve_step_matrix
#endif
    procedure :: switching => ctx_switching
    procedure :: switching_count => ctx_switching_count
    procedure :: stick_stiffness => ctx_stick_stiffness
    procedure :: get_stat => ctx_get_stat
    procedure :: reset_stats => ctx_reset_stats
    final :: ctx_final
  end type

contains

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

  !> solve_step with W and Weff in the storage format names (C's fricreg_ctx_solve_step_matrix):
  !> FRICREG_MATRIX_DENSE, w_values(m * m) and weff_values(m * m) the symmetric matrices (a
  !> W(m, m) array's elements in order), w_ptr ... weff_ind absent; or FRICREG_MATRIX_CSR or
  !> FRICREG_MATRIX_CSC plus (ior) the FRICREG_SPARSE_* flags, the arrays as solve_step_csr's
  !> or solve_step_csc's (w_ptr(m + 1), w_ind(nnz), w_values(nnz), the same for Weff). The same
  !> forces as those on the same matrices. FRICREG_ENULL if a compressed format lacks an index
  !> array; FRICREG_ESIZE unless the arrays have those sizes; FRICREG_EINVAL for a format both
  !> CSR and CSC, or dense with a sparse flag; the rest as solve_step's.
  function ctx_solve_step_matrix(self, zdot_start, zdot_pred, a_pred, format, w_values, &
                                 weff_values, c, tol, max_iter, f, w_ptr, w_ind, weff_ptr, &
                                 weff_ind, iterations, converged, flags) result(status)
    class(fricreg_context), intent(inout) :: self
    real(c_double), intent(in), contiguous :: zdot_start(:), zdot_pred(:), a_pred(:)
    integer(c_int), intent(in) :: format
    real(c_double), intent(in), contiguous :: w_values(:), weff_values(:)
    real(c_double), intent(in) :: c, tol
    integer, intent(in) :: max_iter
    real(c_double), intent(inout), contiguous :: f(:)
    integer(c_int64_t), intent(in), contiguous, optional :: w_ptr(:), w_ind(:), weff_ptr(:), &
                                                            weff_ind(:)
    integer, intent(out), optional :: iterations
    logical, intent(out), optional :: converged
    integer, intent(in), optional :: flags
    integer(c_int) :: status, info(2), how, layout
    integer(c_int64_t) :: unread(1)
    integer(c_size_t) :: m
    layout = iand(format, ior(FRICREG_MATRIX_CSR, FRICREG_MATRIX_CSC))
    if (layout == FRICREG_MATRIX_CSR .or. layout == FRICREG_MATRIX_CSC) then
      if (.not. (present(w_ptr) .and. present(w_ind) .and. present(weff_ptr) .and. &
                 present(weff_ind))) then
        status = self%fail(FRICREG_ENULL, 'solve_step_matrix: a compressed format needs ' // &
                           'w_ptr, w_ind, weff_ptr and weff_ind')
        return
      end if
      status = ctx_solve_step_compressed(self, layout == FRICREG_MATRIX_CSC, zdot_start, &
                                         zdot_pred, a_pred, iand(format, not(layout)), w_ptr, &
                                         w_ind, w_values, weff_ptr, weff_ind, weff_values, c, &
                                         tol, max_iter, f, iterations, converged, flags)
      return
    end if
    m = fricreg_ctx_size(self%ptr)
    how = 0
    if (present(flags)) how = int(flags, c_int)
    status = self%ready('solve_step_matrix', 'context')
    if (status == FRICREG_OK) status = self%check_size('solve_step_matrix', 'zdot_start', &
                                                       size(zdot_start), m)
    if (status == FRICREG_OK) status = self%check_size('solve_step_matrix', 'zdot_pred', &
                                                       size(zdot_pred), m)
    if (status == FRICREG_OK) status = self%check_size('solve_step_matrix', 'a_pred', &
                                                       size(a_pred), m)
    if (status == FRICREG_OK) status = self%check_size('solve_step_matrix', 'f', size(f), m)
    if (status == FRICREG_OK .and. layout == FRICREG_MATRIX_DENSE) &
      status = self%check_size('solve_step_matrix', 'w_values', size(w_values), m * m)
    if (status == FRICREG_OK .and. layout == FRICREG_MATRIX_DENSE) &
      status = self%check_size('solve_step_matrix', 'weff_values', size(weff_values), m * m)
    if (status /= FRICREG_OK) return
    unread = 0
    status = self%record(fricreg_ctx_solve_step_matrix(self%ptr, m, zdot_start, zdot_pred, &
                         a_pred, format, unread, unread, w_values, unread, unread, weff_values, &
                         c, tol, int(max_iter, c_int), how, f, info))
    if (status /= FRICREG_OK) return
    if (present(iterations)) iterations = int(info(1))
    if (present(converged)) converged = info(2) /= 0
  end function ctx_solve_step_matrix

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

end module fricreg_ctx_m
