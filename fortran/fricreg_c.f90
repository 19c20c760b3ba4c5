! fricreg_c.f90 — module fricreg_c: thin bind(C) interfaces to every function of fricreg.h.
!
! One interface per C function, argument for argument: scalars by value, arrays as
! dimension(*) (the caller passes m, as in C), the context as type(c_ptr), size_t as
! integer(c_size_t), int64_t as integer(c_int64_t). No checks are added here: this layer is the
! C API spelled in Fortran, and every docstring of include/fricreg.h applies unchanged (array
! lengths, units, valid ranges, status codes). The idiomatic layer is module fricreg.
!
! Constants (status codes, laws, counters) come from module fricreg_constants, generated from
! the C headers at build time, and are re-exported here.
module fricreg_c
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_intptr_t, &
                                         c_ptr, c_funptr, c_char, c_null_ptr, c_null_char, &
                                         c_associated, c_f_pointer, c_loc, c_funloc
  use fricreg_constants
  implicit none
  ! Everything is public, the constants and the iso_c_binding names above included, so that
  ! `use fricreg_c` (or `use fricreg`) is all a caller needs.
  public

  interface
    ! ---- Version ------------------------------------------------------------------------
    !> Library version as major*10000 + minor*100 + patch (compare FRICREG_VERSION_NUMBER).
    function fricreg_version_number() bind(C, name='fricreg_version_number')
      import :: c_int
      integer(c_int) :: fricreg_version_number
    end function

    !> Version string, owned by the library (fricreg_c_string converts it).
    function fricreg_version() bind(C, name='fricreg_version')
      import :: c_ptr
      type(c_ptr) :: fricreg_version
    end function

    !> Fixed text of a status code, static storage (fricreg_c_string converts it).
    function fricreg_strerror(status) bind(C, name='fricreg_strerror')
      import :: c_int, c_ptr
      integer(c_int), value :: status
      type(c_ptr) :: fricreg_strerror
    end function

    ! ---- Friction laws ------------------------------------------------------------------
    !> One law at one contact; f written only on success. Eqs. (1)-(4).
    function fricreg_law_eval(law, v, f_eq, mun, eps, f) bind(C, name='fricreg_law_eval')
      import :: c_int, c_double
      integer(c_int), value :: law
      real(c_double), value :: v, f_eq, mun, eps
      real(c_double), intent(out) :: f
      integer(c_int) :: fricreg_law_eval
    end function

    !> One law over m contacts. f_eq may be absent (NULL) for laws (1), (3) and tanh.
    function fricreg_law_eval_batch(law, eps, m, v, f_eq, mun, f) &
        bind(C, name='fricreg_law_eval_batch')
      import :: c_int, c_double, c_size_t
      integer(c_int), value :: law
      real(c_double), value :: eps
      integer(c_size_t), value :: m
      real(c_double), intent(in) :: v(*), mun(*)
      real(c_double), intent(in), optional :: f_eq(*)
      real(c_double), intent(inout) :: f(*) ! intent(inout): f may alias v or f_eq in C
      integer(c_int) :: fricreg_law_eval_batch
    end function

    ! ---- Context ------------------------------------------------------------------------
    !> Create a context of m >= 1 contacts into ctx.
    function fricreg_ctx_create(m, ctx) bind(C, name='fricreg_ctx_create')
      import :: c_int, c_size_t, c_ptr
      integer(c_size_t), value :: m
      type(c_ptr), intent(out) :: ctx
      integer(c_int) :: fricreg_ctx_create
    end function

    !> Release a context; c_null_ptr does nothing.
    subroutine fricreg_ctx_free(ctx) bind(C, name='fricreg_ctx_free')
      import :: c_ptr
      type(c_ptr), value :: ctx
    end subroutine

    !> Number of contacts (0 for c_null_ptr).
    function fricreg_ctx_size(ctx) bind(C, name='fricreg_ctx_size')
      import :: c_size_t, c_ptr
      type(c_ptr), value :: ctx
      integer(c_size_t) :: fricreg_ctx_size
    end function

    function fricreg_ctx_set_law(ctx, law, eps) bind(C, name='fricreg_ctx_set_law')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: ctx
      integer(c_int), value :: law
      real(c_double), value :: eps
      integer(c_int) :: fricreg_ctx_set_law
    end function

    function fricreg_ctx_set_bounds(ctx, m, mun) bind(C, name='fricreg_ctx_set_bounds')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: ctx
      integer(c_size_t), value :: m
      real(c_double), intent(in) :: mun(*)
      integer(c_int) :: fricreg_ctx_set_bounds
    end function

    function fricreg_ctx_set_coupling_diagonal(ctx, m, w) &
        bind(C, name='fricreg_ctx_set_coupling_diagonal')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: ctx
      integer(c_size_t), value :: m
      real(c_double), intent(in) :: w(*)
      integer(c_int) :: fricreg_ctx_set_coupling_diagonal
    end function

    !> W is m x m row-major in C; being symmetric, a Fortran W(m, m) is passed as it is.
    function fricreg_ctx_set_coupling_dense(ctx, m, W) &
        bind(C, name='fricreg_ctx_set_coupling_dense')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: ctx
      integer(c_size_t), value :: m
      real(c_double), intent(in) :: W(*)
      integer(c_int) :: fricreg_ctx_set_coupling_dense
    end function

    !> Friction forces of all m contacts (Sec. 3.3). f_eq may be absent (NULL).
    function fricreg_ctx_eval(ctx, m, zdot, a_free, f, f_eq) bind(C, name='fricreg_ctx_eval')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: ctx
      integer(c_size_t), value :: m
      real(c_double), intent(in) :: zdot(*), a_free(*)
      real(c_double), intent(inout) :: f(*)             ! written only on success
      real(c_double), intent(inout), optional :: f_eq(*) ! written only on success
      integer(c_int) :: fricreg_ctx_eval
    end function

    !> Select the partition of coupled contacts (FRICREG_PARTITION_*).
    function fricreg_ctx_set_partition(ctx, partition) &
        bind(C, name='fricreg_ctx_set_partition')
      import :: c_int, c_ptr
      type(c_ptr), value :: ctx
      integer(c_int), value :: partition
      integer(c_int) :: fricreg_ctx_set_partition
    end function

    !> The stick zone's stiffness lambda (bound of dt*lambda for explicit steps).
    function fricreg_ctx_stick_stiffness(ctx, lambda) &
        bind(C, name='fricreg_ctx_stick_stiffness')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: ctx
      real(c_double), intent(inout) :: lambda ! written only on success
      integer(c_int) :: fricreg_ctx_stick_stiffness
    end function

    function fricreg_ctx_get_stat(ctx, which, value) bind(C, name='fricreg_ctx_get_stat')
      import :: c_int, c_int64_t, c_ptr
      type(c_ptr), value :: ctx
      integer(c_int), value :: which
      integer(c_int64_t), intent(inout) :: value ! written only on success
      integer(c_int) :: fricreg_ctx_get_stat
    end function

    subroutine fricreg_ctx_reset_stats(ctx) bind(C, name='fricreg_ctx_reset_stats')
      import :: c_ptr
      type(c_ptr), value :: ctx
    end subroutine

    function fricreg_ctx_errcode(ctx) bind(C, name='fricreg_ctx_errcode')
      import :: c_int, c_ptr
      type(c_ptr), value :: ctx
      integer(c_int) :: fricreg_ctx_errcode
    end function

    !> Last error message, owned by the context, valid until its next call.
    function fricreg_ctx_errmsg(ctx) bind(C, name='fricreg_ctx_errmsg')
      import :: c_ptr
      type(c_ptr), value :: ctx
      type(c_ptr) :: fricreg_ctx_errmsg
    end function

    !> Copy the last error message into buf(len), NUL-terminated; returns its full length.
    function fricreg_ctx_errmsg_copy(ctx, buf, len) bind(C, name='fricreg_ctx_errmsg_copy')
      import :: c_size_t, c_char, c_ptr
      type(c_ptr), value :: ctx
      character(kind=c_char), intent(inout) :: buf(*)
      integer(c_size_t), value :: len
      integer(c_size_t) :: fricreg_ctx_errmsg_copy
    end function

    !> Jacobian of the last evaluation's forces, each m*m, row-major: df_dzdot(i*m + j + 1) =
    !> d f_i/d zdot_j (an (m, m) array receives the transpose); an absent one is skipped.
    function fricreg_ctx_tangent(ctx, m, df_dzdot, df_dafree) bind(C, name='fricreg_ctx_tangent')
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: ctx
      integer(c_size_t), value :: m
      real(c_double), intent(inout), optional :: df_dzdot(*), df_dafree(*) ! on success
      integer(c_int) :: fricreg_ctx_tangent
    end function
  end interface

contains

  !> A Fortran copy of the NUL-terminated C string at p ("" for c_null_ptr).
  function fricreg_c_string(p) result(s)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: s
    character(kind=c_char), pointer :: chars(:)
    integer(c_size_t) :: n, extent(1)
    integer :: i
    interface
      function c_strlen(s) bind(C, name='strlen') ! the C library's
        import :: c_size_t, c_ptr
        type(c_ptr), value :: s
        integer(c_size_t) :: c_strlen
      end function
    end interface
    if (.not. c_associated(p)) then
      s = ''
      return
    end if
    n = c_strlen(p)
    extent(1) = n
    call c_f_pointer(p, chars, extent)
    allocate(character(len=n) :: s)
    do i = 1, int(n)
      s(i:i) = chars(i)
    end do
  end function fricreg_c_string

  !> The C pointer p as an integer handle, for Fortran 77 callers (INTEGER*8 holds it).
  pure function fricreg_ptr_to_handle(p) result(h)
    type(c_ptr), intent(in) :: p
    integer(c_int64_t) :: h
    h = int(transfer(p, 0_c_intptr_t), c_int64_t)
  end function fricreg_ptr_to_handle

  !> The C pointer held in the integer handle h (0 gives c_null_ptr).
  pure function fricreg_handle_to_ptr(h) result(p)
    integer(c_int64_t), intent(in) :: h
    type(c_ptr) :: p
    p = transfer(int(h, c_intptr_t), c_null_ptr)
  end function fricreg_handle_to_ptr

end module fricreg_c
