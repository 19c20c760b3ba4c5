! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_element.F90 — module fricreg_element_m: type fricreg_element, one element type of
! fricreg_element.h (the per-point kernel of host codes, docs/hosts.md), and its procedures.
! One of the modules of module fricreg (fricreg.F90), which re-exports it.
module fricreg_element_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_null_ptr, &
                                         c_associated, c_char, c_null_char
  use fricreg_c
  implicit none
  private
  public :: fricreg_element

  !> An element type (fricreg_element.h): a constant table of the library, so nothing to
  !> release. The parameters and state are the caller's arrays. Matrices are Fortran's:
  !> dfdu(a, c) = df(a)/du(c), dfdp(a, j) = df(a)/dp(j) (transposed from C's row order).
  !> Every procedure that can fail returns a status and writes nothing then; errmsg says why.
  type :: fricreg_element
    type(c_ptr), private :: t = c_null_ptr
    character(len=:), allocatable, private :: msg
  contains
    procedure :: lookup => el_lookup
    procedure :: name => el_name
    procedure :: dim => el_dim
    procedure :: nparams => el_nparams
    procedure :: nstate => el_nstate
    procedure :: init => el_init
    procedure :: eval => el_eval
    procedure :: energy => el_energy
    procedure :: errmsg => el_errmsg
  end type

contains

  !> The type called name (fricreg_element_lookup), with ns sliders for an Iwan type (default
  !> 1). FRICREG_EINVAL for an unknown name or ns out of range; the object keeps its type then.
  function el_lookup(self, name, ns) result(status)
    class(fricreg_element), intent(inout) :: self
    character(len=*), intent(in) :: name
    integer, intent(in), optional :: ns
    integer(c_int) :: status
    type(c_ptr) :: t
    integer :: n
    n = 1
    if (present(ns)) n = ns
    t = c_null_ptr
    if (n >= 1) t = fricreg_element_sliders(fricreg_element_lookup(trim(name) // c_null_char), &
                                            int(n, c_size_t))
    if (.not. c_associated(t)) then
      status = FRICREG_EINVAL
      self%msg = 'lookup: no element type "' // trim(name) // '" with that many sliders'
      return
    end if
    self%t = t
    status = FRICREG_OK
  end function el_lookup

  !> The type's name ('' before lookup).
  function el_name(self) result(name)
    class(fricreg_element), intent(in) :: self
    character(len=:), allocatable :: name
    name = ''
    if (c_associated(self%t)) name = fricreg_c_string(fricreg_element_name(self%t))
  end function el_name

  !> Components of u and f: 1, 2 or 3 (0 before lookup).
  integer function el_dim(self)
    class(fricreg_element), intent(in) :: self
    el_dim = int(fricreg_element_dim(self%t))
  end function el_dim

  !> Number of parameters (0 before lookup).
  integer function el_nparams(self)
    class(fricreg_element), intent(in) :: self
    el_nparams = int(fricreg_element_nparams(self%t))
  end function el_nparams

  !> Number of state variables (0 before lookup).
  integer function el_nstate(self)
    class(fricreg_element), intent(in) :: self
    el_nstate = int(fricreg_element_nstate(self%t))
  end function el_nstate

  !> The failure's message from fricreg_element_explain on the same inputs; its status.
  function el_explained(self, fn, params, state, u) result(status)
    class(fricreg_element), intent(inout) :: self
    character(len=*), intent(in) :: fn
    real(c_double), intent(in), contiguous :: params(:)
    real(c_double), intent(in), contiguous, optional :: state(:), u(:)
    integer(c_int) :: status
    character(kind=c_char, len=256) :: buf
    status = fricreg_element_explain(self%t, params, state, u, buf, int(len(buf), c_size_t))
    self%msg = fn // ': ' // fricreg_c_string_of(buf)
  end function el_explained

  !> The characters of buf before its NUL.
  function fricreg_c_string_of(buf) result(text)
    character(kind=c_char, len=*), intent(in) :: buf
    character(len=:), allocatable :: text
    integer :: k
    k = index(buf, c_null_char)
    if (k == 0) k = len(buf) + 1
    text = buf(1:k - 1)
  end function fricreg_c_string_of

  !> Whether the type is set and params has nparams numbers (else a status and message).
  function el_ready(self, fn, params) result(status)
    class(fricreg_element), intent(inout) :: self
    character(len=*), intent(in) :: fn
    real(c_double), intent(in) :: params(:)
    integer(c_int) :: status
    status = FRICREG_OK
    if (.not. c_associated(self%t)) then
      status = FRICREG_ENULL
      self%msg = fn // ': no element type (call lookup first)'
    else if (size(params) /= self%nparams()) then
      status = FRICREG_ESIZE
      self%msg = fn // ': params must have nparams numbers'
    end if
  end function el_ready

  !> state(nstate) of an element at rest (every slider at 0), the parameters checked.
  !> FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function el_init(self, params, state) result(status)
    class(fricreg_element), intent(inout) :: self
    real(c_double), intent(in), contiguous :: params(:)
    real(c_double), intent(inout), contiguous :: state(:)
    integer(c_int) :: status
    integer :: nst
    nst = self%nstate()
    status = el_ready(self, 'init', params)
    if (status == FRICREG_OK .and. size(state) /= nst) then
      status = FRICREG_ESIZE
      self%msg = 'init: state must have nstate numbers'
    end if
    if (status /= FRICREG_OK) return
    status = fricreg_element_init(self%t, params, state)
    if (status /= FRICREG_OK) status = el_explained(self, 'init', params)
  end function el_init

  !> The force f(dim), the tangent dfdu(dim, dim) and dfdp(dim, nparams) if present, and the
  !> new state state_out(nstate) at u(dim) from state_in(nstate) (fricreg_element_eval).
  !> state_out may be the same array as state_in. Written only on success.
  !> FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function el_eval(self, params, state_in, u, f, state_out, dfdu, dfdp) result(status)
    class(fricreg_element), intent(inout) :: self
    real(c_double), intent(in), contiguous :: params(:), state_in(:), u(:)
    real(c_double), intent(inout), contiguous :: f(:), state_out(:)
    real(c_double), intent(inout), contiguous, optional :: dfdu(:, :), dfdp(:, :)
    integer(c_int) :: status
    real(c_double), allocatable :: tu(:), tp(:)
    integer :: d, np, nst, a
    status = el_ready(self, 'eval', params)
    if (status /= FRICREG_OK) return
    d = self%dim()
    np = self%nparams()
    nst = self%nstate()
    if (size(state_in) /= nst .or. size(state_out) /= nst .or. size(u) /= d .or. &
        size(f) /= d) status = FRICREG_ESIZE
    if (present(dfdu)) then
      if (size(dfdu, 1) /= d .or. size(dfdu, 2) /= d) status = FRICREG_ESIZE
    end if
    if (present(dfdp)) then
      if (size(dfdp, 1) /= d .or. size(dfdp, 2) /= np) status = FRICREG_ESIZE
    end if
    if (status /= FRICREG_OK) then
      self%msg = 'eval: sizes: u, f (dim), state (nstate), dfdu (dim, dim), dfdp (dim, nparams)'
      return
    end if
    allocate (tu(d * d), tp(d * np))
    if (present(dfdu) .and. present(dfdp)) then
      status = fricreg_element_eval(self%t, params, state_in, u, f, tu, tp, state_out)
    else if (present(dfdu)) then
      status = fricreg_element_eval(self%t, params, state_in, u, f, tu, state_out=state_out)
    else if (present(dfdp)) then
      status = fricreg_element_eval(self%t, params, state_in, u, f, dfdp=tp, state_out=state_out)
    else
      status = fricreg_element_eval(self%t, params, state_in, u, f, state_out=state_out)
    end if
    if (status /= FRICREG_OK) then
      status = el_explained(self, 'eval', params, state_in, u)
      return
    end if
    ! C's row-major (a, c) sits at c + d (a - 1): Fortran's transpose
    do a = 1, d
      if (present(dfdu)) dfdu(a, :) = tu(d * (a - 1) + 1:d * a)
      if (present(dfdp)) dfdp(a, :) = tp(np * (a - 1) + 1:np * a)
    end do
  end function el_eval

  !> The energies of the increment eval makes on the same inputs (fricreg_element_energy):
  !> dissipated, what the sliders dissipate, and stored, what the springs hold at its end.
  !> Written only on success. FRICREG_ESIZE; FRICREG_EINVAL; FRICREG_ENONFINITE.
  function el_energy(self, params, state_in, u, dissipated, stored) result(status)
    class(fricreg_element), intent(inout) :: self
    real(c_double), intent(in), contiguous :: params(:), state_in(:), u(:)
    real(c_double), intent(inout) :: dissipated, stored
    integer(c_int) :: status
    ! a type without state still needs an array to pass: C asks state_in not NULL
    real(c_double) :: none(1)
    integer :: d, nst
    status = el_ready(self, 'energy', params)
    if (status /= FRICREG_OK) return
    d = self%dim()
    nst = self%nstate()
    if (size(state_in) /= nst .or. size(u) /= d) then
      status = FRICREG_ESIZE
      self%msg = 'energy: sizes: u (dim), state_in (nstate)'
      return
    end if
    none = 0
    if (size(state_in) > 0) then
      status = fricreg_element_energy(self%t, params, state_in, u, dissipated, stored)
    else
      status = fricreg_element_energy(self%t, params, none, u, dissipated, stored)
    end if
    if (status /= FRICREG_OK) status = el_explained(self, 'energy', params, state_in, u)
  end function el_energy

  !> The message of the last failed call ('' if none failed).
  function el_errmsg(self) result(msg)
    class(fricreg_element), intent(in) :: self
    character(len=:), allocatable :: msg
    msg = ''
    if (allocated(self%msg)) msg = self%msg
  end function el_errmsg

end module fricreg_element_m
