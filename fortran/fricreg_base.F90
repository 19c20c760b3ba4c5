! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_base.F90 — module fricreg_base_m: what the object modules share: their parent type
! fricreg_object (the C handle, its release and the error record), the string helpers
! (fricreg_error_string, ...) and the array helpers as_size and is_pairs.
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_base_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_int64_t, c_ptr, &
                                         c_null_ptr, c_null_char, c_associated
  use fricreg_c
  implicit none
  private
  public :: fricreg_object
  public :: fricreg_error_string, fricreg_warning_string, fricreg_version_string, &
            fricreg_law_string, fricreg_law_id, fricreg_disk_law_string, fricreg_disk_law_id
  ! For the object modules only: module fricreg does not re-export them.
  public :: as_size, is_pairs

  !> A failure detected in Fortran (a size mismatch, an object not created, or a C failure the
  !> C object does not record), kept beside the C library's own record; `last` says which of
  !> the two is the more recent.
  type :: error_record
    integer(c_int) :: code = FRICREG_OK
    logical :: last = .false.
    character(len=:), allocatable :: msg
  end type

  !> The parent of every object of module fricreg: the C handle it owns, the C functions that
  !> release it and read its last error (set by each type's create, bound straight to the
  !> generated bind(C) interfaces), and the error record of failures found in Fortran.
  !> It gives its children destroy (safe twice), is_created, handle, errcode, errmsg and an
  !> assignment that cannot free one handle twice.
  type, abstract :: fricreg_object
    private
    ! ptr is public, and the helpers below, for the object modules (fricreg_ctx.F90, ...), which
    ! extend this type in modules of their own: Fortran has no access between "private" and
    ! "public". Callers have handle() and is_created(); these are not part of the interface.
    type(c_ptr), public :: ptr = c_null_ptr
    type(error_record) :: err
    procedure(fricreg_free_fn), pointer, nopass :: c_free => null()
    procedure(fricreg_errcode_fn), pointer, nopass :: c_errcode => null()
    procedure(fricreg_errmsg_fn), pointer, nopass :: c_errmsg => null()
  contains
    procedure :: destroy => object_destroy
    procedure :: is_created => object_is_created
    procedure :: handle => object_handle
    procedure :: errcode => object_errcode
    procedure :: errmsg => object_errmsg
    procedure, private :: object_assign
    generic :: assignment(=) => object_assign
    procedure, non_overridable :: adopt, ready, fail, record, unrecorded, check_size, &
                                  check_square, check_sparse
  end type

contains

  ! ---- Strings -----------------------------------------------------------------------------

  !> Fixed English text of a status code (C's fricreg_strerror).
  function fricreg_error_string(status) result(text)
    integer(c_int), intent(in) :: status
    character(len=:), allocatable :: text
    text = fricreg_c_string(fricreg_strerror(status))
  end function fricreg_error_string

  !> Short fixed name of a warning code (FRICREG_WARN_*: 'eps_large', ...; C's
  !> fricreg_warning_name), 'unknown' if unknown. Since 1.6.
  function fricreg_warning_string(code) result(text)
    integer(c_int), intent(in) :: code
    character(len=:), allocatable :: text
    text = fricreg_c_string(fricreg_warning_name(code))
  end function fricreg_warning_string

  !> Version "MAJOR.MINOR.PATCH" of the library linked (FRICREG_VERSION_STRING: the headers').
  function fricreg_version_string() result(text)
    character(len=:), allocatable :: text
    text = fricreg_c_string(fricreg_version())
  end function fricreg_version_string

  !> The name of a law (FRICREG_LAW_*: 'coulomb', ..., 'quinn'; C's fricreg_law_name), '' if
  !> unknown.
  function fricreg_law_string(law) result(name)
    integer(c_int), intent(in) :: law
    character(len=:), allocatable :: name
    name = fricreg_c_string(fricreg_law_name(law))
  end function fricreg_law_string

  !> The law (FRICREG_LAW_*) named name (trailing blanks ignored), 0 if there is none.
  integer(c_int) function fricreg_law_id(name)
    character(len=*), intent(in) :: name
    fricreg_law_id = fricreg_law_from_name(trim(name) // c_null_char)
  end function fricreg_law_id

  !> The name of a 2-D law (FRICREG_DISK_*: 'coulomb', ..., 'quinn-nested'; C's
  !> fricreg_disk_law_name), '' if unknown.
  function fricreg_disk_law_string(law) result(name)
    integer(c_int), intent(in) :: law
    character(len=:), allocatable :: name
    name = fricreg_c_string(fricreg_disk_law_name(law))
  end function fricreg_disk_law_string

  !> The 2-D law (FRICREG_DISK_*) named name (trailing blanks ignored), 0 if there is none.
  integer(c_int) function fricreg_disk_law_id(name)
    character(len=*), intent(in) :: name
    fricreg_disk_law_id = fricreg_disk_law_from_name(trim(name) // c_null_char)
  end function fricreg_disk_law_id

  pure function as_size(n) result(m)
    integer, intent(in) :: n
    integer(c_size_t) :: m
    m = int(n, c_size_t)
  end function as_size

  !> Whether a holds m 2-D vectors, as (2, m).
  pure logical function is_pairs(a, m)
    real(c_double), intent(in) :: a(:, :)
    integer, intent(in) :: m
    is_pairs = size(a, 1) == 2 .and. size(a, 2) == m
  end function is_pairs

  ! ---- fricreg_object: the handle and the error plumbing -----------------------------------

  !> Take ownership of the new handle p (released with free; errcode and errmsg read its last
  !> error, absent where the C object keeps none), releasing the one held before.
  subroutine adopt(self, p, free, errcode, errmsg)
    class(fricreg_object), intent(inout) :: self
    type(c_ptr), intent(in) :: p
    procedure(fricreg_free_fn) :: free
    procedure(fricreg_errcode_fn), optional :: errcode
    procedure(fricreg_errmsg_fn), optional :: errmsg
    call self%destroy()
    self%ptr = p
    self%c_free => free
    nullify (self%c_errcode, self%c_errmsg)
    if (present(errcode)) self%c_errcode => errcode
    if (present(errmsg)) self%c_errmsg => errmsg
    self%err = error_record()
  end subroutine adopt

  !> Release the C object. Safe to call twice, and on an object never created.
  subroutine object_destroy(self)
    class(fricreg_object), intent(inout) :: self
    if (c_associated(self%ptr) .and. associated(self%c_free)) call self%c_free(self%ptr)
    self%ptr = c_null_ptr
  end subroutine object_destroy

  !> `lhs = rhs`: objects cannot be copied (C has no clone); lhs is released and left empty,
  !> so no handle is ever owned twice.
  subroutine object_assign(lhs, rhs)
    class(fricreg_object), intent(inout) :: lhs
    class(fricreg_object), intent(in) :: rhs
    if (c_associated(lhs%ptr, rhs%ptr)) return ! a = a
    call lhs%destroy()
    lhs%err = error_record()
  end subroutine object_assign

  logical function object_is_created(self)
    class(fricreg_object), intent(in) :: self
    object_is_created = c_associated(self%ptr)
  end function object_is_created

  !> The C handle (fricreg_ctx *, fricreg_sim *, ...), for the bind(C) functions; still owned
  !> by self.
  type(c_ptr) function object_handle(self)
    class(fricreg_object), intent(in) :: self
    object_handle = self%ptr
  end function object_handle

  !> Status of the last failed call on this object (FRICREG_OK if none).
  integer(c_int) function object_errcode(self)
    class(fricreg_object), intent(in) :: self
    object_errcode = FRICREG_OK
    if (c_associated(self%ptr) .and. associated(self%c_errcode)) &
      object_errcode = self%c_errcode(self%ptr)
    if (self%err%last .or. object_errcode == FRICREG_OK) then
      if (self%err%code /= FRICREG_OK) object_errcode = self%err%code
    end if
  end function object_errcode

  !> Message of the last failed call, naming the argument, contact or value ('' if none): the
  !> more recent of the Fortran record and the C object's.
  function object_errmsg(self) result(msg)
    class(fricreg_object), intent(in) :: self
    character(len=:), allocatable :: msg
    logical :: c_has_one
    c_has_one = .false.
    if (c_associated(self%ptr) .and. associated(self%c_errcode)) &
      c_has_one = self%c_errcode(self%ptr) /= FRICREG_OK .and. associated(self%c_errmsg)
    if (c_has_one .and. .not. self%err%last) then
      msg = fricreg_c_string(self%c_errmsg(self%ptr))
    else if (self%err%code /= FRICREG_OK) then
      msg = self%err%msg
    else
      msg = ''
    end if
  end function object_errmsg

  !> Records a failure found on the Fortran side and returns its code.
  function fail(self, code, msg) result(status)
    class(fricreg_object), intent(inout) :: self
    integer(c_int), intent(in) :: code
    character(len=*), intent(in) :: msg
    integer(c_int) :: status
    self%err%code = code
    self%err%msg = msg
    self%err%last = .true.
    status = code
  end function fail

  !> FRICREG_OK if the object holds a C object, else a recorded FRICREG_ENULL for call `what`
  !> saying which object (noun) and what makes one (maker, default 'create').
  function ready(self, what, noun, maker) result(status)
    class(fricreg_object), intent(inout) :: self
    character(len=*), intent(in) :: what, noun
    character(len=*), intent(in), optional :: maker
    integer(c_int) :: status
    status = FRICREG_OK
    if (c_associated(self%ptr)) return
    if (present(maker)) then
      status = self%fail(FRICREG_ENULL, what // ': the ' // noun // ' is not created (call ' // &
                         maker // ')')
    else
      status = self%fail(FRICREG_ENULL, what // ': the ' // noun // ' is not created (call create)')
    end if
  end function ready

  !> After a C call that records its failures: a failure there is now the most recent one.
  function record(self, status) result(same)
    class(fricreg_object), intent(inout) :: self
    integer(c_int), intent(in) :: status
    integer(c_int) :: same
    if (status /= FRICREG_OK) self%err%last = .false.
    same = status
  end function record

  !> After a C call that does not record (a getter on a const object, the exact solver): the
  !> failure is recorded here, with the code's text.
  function unrecorded(self, what, status) result(same)
    class(fricreg_object), intent(inout) :: self
    character(len=*), intent(in) :: what
    integer(c_int), intent(in) :: status
    integer(c_int) :: same
    same = status
    if (status /= FRICREG_OK) same = self%fail(status, what // ': ' // fricreg_error_string(status))
  end function unrecorded

  !> FRICREG_OK if n == expected, else a recorded FRICREG_ESIZE naming the array.
  function check_size(self, what, array, n, expected) result(status)
    class(fricreg_object), intent(inout) :: self
    character(len=*), intent(in) :: what, array
    integer, intent(in) :: n
    integer(c_size_t), intent(in) :: expected
    integer(c_int) :: status
    character(len=64) :: buf
    status = FRICREG_OK
    if (int(n, c_size_t) /= expected) then
      write (buf, '(a, i0, a, i0)') ') = ', n, ', expected ', expected
      status = self%fail(FRICREG_ESIZE, what // ': size(' // array // trim(buf))
    end if
  end function check_size

  !> FRICREG_OK if a is expected x expected, else a recorded FRICREG_ESIZE naming the array
  !> and the dimension. Takes the array itself: shape(a) would be a temporary at each call.
  function check_square(self, what, array, a, expected) result(status)
    class(fricreg_object), intent(inout) :: self
    character(len=*), intent(in) :: what, array
    real(c_double), intent(in) :: a(:, :)
    integer(c_size_t), intent(in) :: expected
    integer(c_int) :: status
    status = self%check_size(what, array // ', 1', size(a, 1), expected)
    if (status == FRICREG_OK) status = self%check_size(what, array // ', 2', size(a, 2), expected)
  end function check_square

  !> FRICREG_OK if ptr has n + 1 elements and ind and values hold at least the
  !> nnz = ptr(n + 1) - base entries ptr says (base 1 with FRICREG_SPARSE_ONE_BASED in flags,
  !> else 0), else a recorded FRICREG_ESIZE naming the array: C reads nnz of each, which it
  !> cannot check. ptr_name and ind_name name the first two arrays in the message; a
  !> ptr(n + 1) below base is left to C (FRICREG_EINVAL).
  function check_sparse(self, what, ptr_name, ind_name, flags, n, ptr, ind, values) &
      result(status)
    class(fricreg_object), intent(inout) :: self
    character(len=*), intent(in) :: what, ptr_name, ind_name
    integer(c_int), intent(in) :: flags
    integer(c_size_t), intent(in) :: n
    integer(c_int64_t), intent(in) :: ptr(:), ind(:)
    real(c_double), intent(in) :: values(:)
    integer(c_int) :: status
    integer(c_int64_t) :: nnz
    character(len=64) :: buf
    status = self%check_size(what, ptr_name, size(ptr), n + 1)
    if (status /= FRICREG_OK) return
    nnz = ptr(n + 1) - merge(1_c_int64_t, 0_c_int64_t, iand(flags, FRICREG_SPARSE_ONE_BASED) /= 0)
    if (int(size(ind), c_int64_t) < nnz) then
      write (buf, '(a, i0, a, i0)') ') = ', size(ind), ', expected at least ', nnz
      status = self%fail(FRICREG_ESIZE, what // ': size(' // ind_name // trim(buf))
    else if (int(size(values), c_int64_t) < nnz) then
      write (buf, '(a, i0, a, i0)') ') = ', size(values), ', expected at least ', nnz
      status = self%fail(FRICREG_ESIZE, what // ': size(values' // trim(buf))
    end if
  end function check_sparse

end module fricreg_base_m
