! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_disk_ctx.F90 — module fricreg_disk_ctx_m: type fricreg_disk_context, m coupled 2-D
! contacts (fricreg_disk_ctx.h), and its procedures.
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_disk_ctx_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_ptr, c_null_ptr
  use fricreg_c
  use fricreg_base_m, only: fricreg_object, fricreg_error_string, as_size, is_pairs
  implicit none
  private
  public :: fricreg_disk_context

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

contains

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

end module fricreg_disk_ctx_m
