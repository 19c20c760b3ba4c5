! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_c.f90 — module fricreg_c: thin bind(C) interfaces to every function of fricreg.h and
! of the core headers beside it (fricreg_disk.h, fricreg_stribeck.h).
!
! The interfaces are generated from the C prototypes at build time (gen_interfaces.cmake writes
! fricreg_h.inc, included below), so they cannot drift from the header: argument for argument,
! under the C names, scalars by value, arrays dimension(*) (the caller passes m, as in C), the
! context as type(c_ptr), size_t as integer(c_size_t), int64_t as integer(c_int64_t); every
! pointer argument but the handle is optional, and omitting it passes NULL. No checks are added
! here: this layer is the C API spelled in Fortran, and every docstring of include/fricreg.h
! applies unchanged (array lengths, units, valid ranges, status codes). The idiomatic layer is
! module fricreg.
!
! Public: the generated interfaces; every constant of module fricreg_constants (generated from
! the C headers); the iso_c_binding names a caller needs with them (listed below); and
! fricreg_c_string, fricreg_ptr_to_handle, fricreg_handle_to_ptr. Nothing else.
module fricreg_c
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_intptr_t, &
                                         c_ptr, c_funptr, c_char, c_null_ptr, c_null_char, &
                                         c_associated, c_f_pointer, c_loc, c_funloc
  use fricreg_constants
  implicit none
  private
  include 'fricreg_constants_public.inc'
  include 'fricreg_h_public.inc'
  public :: c_int, c_double, c_size_t, c_int64_t, c_intptr_t, c_ptr, c_funptr, c_char, &
            c_null_ptr, c_null_char, c_associated, c_f_pointer, c_loc, c_funloc
  public :: fricreg_c_string, fricreg_ptr_to_handle, fricreg_handle_to_ptr, fricreg_transpose
  public :: fricreg_f77_transposed_rows
  ! For module fricreg and the F77 entry points (module fricreg does not re-export them).
  public :: fricreg_free_fn, fricreg_errcode_fn, fricreg_errmsg_fn, fricreg_f77_created, &
            fricreg_f77_release, fricreg_f77_last_error, fricreg_f77_element_type, &
            fricreg_f77_element_rows

  interface
    include 'fricreg_h.inc'
  end interface

  ! What every C object type has besides its own calls: a release, and its last error.
  abstract interface
    subroutine fricreg_free_fn(handle) bind(C)
      import :: c_ptr
      type(c_ptr), value :: handle
    end subroutine
    function fricreg_errcode_fn(handle) bind(C)
      import :: c_int, c_ptr
      type(c_ptr), value :: handle
      integer(c_int) :: fricreg_errcode_fn
    end function
    function fricreg_errmsg_fn(handle) bind(C)
      import :: c_ptr
      type(c_ptr), value :: handle
      type(c_ptr) :: fricreg_errmsg_fn
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

  !> Transpose the m x m matrix a in place: C's row-major a(i*m + j) = A_ij becomes Fortran's
  !> column-major a(i, j) = A_ij (the tangent's layout in both Fortran layers).
  subroutine fricreg_transpose(a, m)
    integer(c_size_t), intent(in) :: m
    real(c_double), intent(inout) :: a(m, m)
    real(c_double) :: t
    integer(c_size_t) :: i, j
    do j = 1, m
      do i = j + 1, m
        t = a(i, j)
        a(i, j) = a(j, i)
        a(j, i) = t
      end do
    end do
  end subroutine fricreg_transpose

  ! ---- For the F77 entry points: handles as INTEGER*8 -----------------------------------------
  ! Statuses and codes are integer(c_int) here, never default INTEGER: the entry points are also
  ! compiled with -fdefault-integer-8 (libfricreg_fortran_ilp64) against this one module, and
  ! convert on assignment to their own STAT and CODE.

  !> The tangential rows a and normal rows b of elements with a normal law, in Fortran's order,
  !> transposed into at and bt (C's row-major), allocated here. Returns FRICREG_OK, or
  !> FRICREG_ENOMEM with nothing allocated, for STAT.
  integer(c_int) function fricreg_f77_transposed_rows(a, b, at, bt) result(stat)
    real(c_double), intent(in) :: a(:, :), b(:, :)
    real(c_double), allocatable, intent(out) :: at(:, :), bt(:, :)
    integer :: alloc
    allocate (at(size(a, 2), size(a, 1)), bt(size(b, 2), size(b, 1)), stat=alloc)
    if (alloc /= 0) then
      if (allocated(at)) deallocate (at)
      stat = FRICREG_ENOMEM
      return
    end if
    at = transpose(a)
    bt = transpose(b)
    stat = FRICREG_OK
  end function fricreg_f77_transposed_rows

  !> After a create that returned status with the new object p: h takes p only on success.
  !> Returns the status, for STAT.
  integer(c_int) function fricreg_f77_created(status, p, h) result(stat)
    integer(c_int), intent(in) :: status
    type(c_ptr), intent(in) :: p
    integer(c_int64_t), intent(inout) :: h
    stat = status
    if (status == FRICREG_OK) h = fricreg_ptr_to_handle(p)
  end function fricreg_f77_created

  !> The element type of F77 code itype (fricreg_element_at's index + 1) with ns sliders;
  !> c_null_ptr if there is none.
  !> (64-bit arguments: the F77 entries are compiled with 4- and 8-byte INTEGER, this once.)
  function fricreg_f77_element_type(itype, ns) result(t)
    integer(c_int64_t), intent(in) :: itype, ns
    type(c_ptr) :: t
    t = c_null_ptr
    if (itype < 1 .or. ns < 1) return
    t = fricreg_element_sliders(fricreg_element_at(int(itype - 1, c_size_t)), int(ns, c_size_t))
  end function fricreg_f77_element_type

  !> The element type of F77 code itype with ns sliders into t, and me elements' rows of
  !> j(me dim, ndof) (Fortran's order; dim the type's) transposed into jt(ndof, me dim), C's
  !> row-major J of the add_elements calls. FRICREG_EINVAL for a code or ns of no type, or
  !> me < 0; FRICREG_ENOMEM. (64-bit arguments, as fricreg_f77_element_type's.)
  integer(c_int) function fricreg_f77_element_rows(itype, ns, me, ndof, j, t, jt) result(stat)
    integer(c_int64_t), intent(in) :: itype, ns, me, ndof
    real(c_double), intent(in) :: j(*)
    type(c_ptr), intent(out) :: t
    real(c_double), allocatable, intent(out) :: jt(:, :)
    integer(c_int64_t) :: rows, nn, r, c
    integer :: alloc
    t = fricreg_f77_element_type(itype, ns)
    stat = FRICREG_EINVAL
    if (.not. c_associated(t) .or. me < 0) return
    rows = me * int(fricreg_element_dim(t), c_int64_t)
    nn = max(ndof, 0_c_int64_t)
    allocate (jt(nn, rows), stat=alloc)
    stat = FRICREG_ENOMEM
    if (alloc /= 0) return
    do c = 1, nn
      do r = 1, rows
        jt(c, r) = j(r + (c - 1) * rows)
      end do
    end do
    stat = FRICREG_OK
  end function fricreg_f77_element_rows

  !> Release the object of handle h with free (its C release; h = 0 does nothing) and set
  !> h = 0. Returns FRICREG_OK, for STAT.
  integer(c_int) function fricreg_f77_release(h, free) result(stat)
    integer(c_int64_t), intent(inout) :: h
    procedure(fricreg_free_fn) :: free
    call free(fricreg_handle_to_ptr(h))
    h = 0
    stat = FRICREG_OK
  end function fricreg_f77_release

  !> Code and message of the last failure of the object of handle h, read with its C errcode
  !> and errmsg; msg is blank-padded or truncated to its length. Returns FRICREG_OK, for STAT.
  integer(c_int) function fricreg_f77_last_error(h, errcode, errmsg, code, msg) result(stat)
    integer(c_int64_t), intent(in) :: h
    procedure(fricreg_errcode_fn) :: errcode
    procedure(fricreg_errmsg_fn) :: errmsg
    integer(c_int), intent(out) :: code
    character(len=*), intent(out) :: msg
    code = errcode(fricreg_handle_to_ptr(h))
    msg = fricreg_c_string(errmsg(fricreg_handle_to_ptr(h)))
    stat = FRICREG_OK
  end function fricreg_f77_last_error

end module fricreg_c
