! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_laws.F90 — module fricreg_laws_m: the law generics law_eval, disk_eval, stribeck_eval
! and stribeck_disk_eval (fricreg.h, fricreg_disk.h, fricreg_stribeck.h): one law at one or many
! contacts, no object.
! One of the modules of module fricreg (fricreg.F90), the one users `use`, which re-exports what
! callers need from here and whose header states the conventions every type follows.
module fricreg_laws_m
  use, intrinsic :: iso_c_binding, only: c_int, c_double
  use fricreg_c
  use fricreg_base_m, only: as_size, is_pairs
  implicit none
  private
  public :: law_eval, disk_eval, stribeck_eval, stribeck_disk_eval

  !> One friction law, C's fricreg_law_eval / fricreg_law_eval_batch:
  !>   status = law_eval(law, eps, v, f_eq, mun, f)
  !> with v, f_eq, mun, f all scalars or all rank-1 arrays of one size (else FRICREG_ESIZE),
  !> in the order of C's batch function. f_eq may be omitted (then pass mun= and f= by
  !> keyword) for the laws that do not read it: (1), (3) and tanh; for the others its absence
  !> is FRICREG_ENULL. f is written only on success.
  interface law_eval
    module procedure law_eval_scalar, law_eval_array
  end interface

  !> One 2-D friction law (FRICREG_DISK_*, include/fricreg_disk.h), C's fricreg_disk_eval /
  !> fricreg_disk_eval_batch, in the order of the batch function:
  !>   status = disk_eval(law, eps, v, f_eq, mun, f)
  !> one contact: v(2), f_eq(2), f(2) and a scalar mun; m contacts: v(2, m), f_eq(2, m),
  !> f(2, m) (column i is contact i: a (2, m) Fortran array is C's interleaved layout, passed
  !> with no copy) and mun(m). Any other shape is FRICREG_ESIZE. f_eq may be omitted (then
  !> pass mun= and f= by keyword) for FRICREG_DISK_COULOMB, which does not read it; for the
  !> others its absence is FRICREG_ENULL. f is written only on success.
  interface disk_eval
    module procedure disk_eval_one, disk_eval_batch
  end interface

  !> The Stribeck law at 1-D contacts (include/fricreg_stribeck.h), C's fricreg_stribeck_eval /
  !> fricreg_stribeck_eval_batch, in the order of the batch function:
  !>   status = stribeck_eval(eps, v, f_eq, fs, fk, vs, delta, f)
  !> with v, f_eq, fs, fk, vs, delta, f all scalars or all rank-1 arrays of one size m (else
  !> FRICREG_ESIZE): static bound fs >= kinetic force fk >= 0, Stribeck velocity vs > 0,
  !> exponent delta > 0, each contact its own. f is written only on success.
  interface stribeck_eval
    module procedure stribeck_eval_scalar, stribeck_eval_array
  end interface

  !> The 2-D Stribeck law, C's fricreg_stribeck_disk_eval / fricreg_stribeck_disk_eval_batch:
  !>   status = stribeck_disk_eval(eps, v, f_eq, fs, fk, vs, delta, f)
  !> one contact: v(2), f_eq(2), f(2) and scalar parameters; m contacts: v(2, m), f_eq(2, m),
  !> f(2, m) (column i is contact i, no copy) and fs(m), fk(m), vs(m), delta(m). Any other
  !> shape is FRICREG_ESIZE. f is written only on success.
  interface stribeck_disk_eval
    module procedure stribeck_disk_eval_one, stribeck_disk_eval_batch
  end interface

contains

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

  function disk_eval_one(law, eps, v, f_eq, mun, f) result(status)
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps, mun
    real(c_double), intent(in), contiguous :: v(:)
    real(c_double), intent(in), contiguous, optional :: f_eq(:)
    real(c_double), intent(inout), contiguous :: f(:)
    integer(c_int) :: status
    status = FRICREG_ESIZE
    if (size(v) /= 2 .or. size(f) /= 2) return
    if (present(f_eq)) then
      if (size(f_eq) /= 2) return
    end if
    status = fricreg_disk_eval(law, v, f_eq, mun, eps, f)
  end function disk_eval_one

  function disk_eval_batch(law, eps, v, f_eq, mun, f) result(status)
    integer(c_int), intent(in) :: law
    real(c_double), intent(in) :: eps
    real(c_double), intent(in), contiguous :: v(:, :), mun(:)
    real(c_double), intent(in), contiguous, optional :: f_eq(:, :)
    real(c_double), intent(inout), contiguous :: f(:, :)
    integer(c_int) :: status
    integer :: m
    m = size(mun)
    status = FRICREG_ESIZE
    if (.not. (is_pairs(v, m) .and. is_pairs(f, m))) return
    if (present(f_eq)) then
      if (.not. is_pairs(f_eq, m)) return
    end if
    status = fricreg_disk_eval_batch(law, eps, as_size(m), v, f_eq, mun, f)
  end function disk_eval_batch

  function stribeck_eval_scalar(eps, v, f_eq, fs, fk, vs, delta, f) result(status)
    real(c_double), intent(in) :: eps, v, f_eq, fs, fk, vs, delta
    real(c_double), intent(inout) :: f
    integer(c_int) :: status
    status = fricreg_stribeck_eval(v, f_eq, fs, fk, vs, delta, eps, f)
  end function stribeck_eval_scalar

  function stribeck_eval_array(eps, v, f_eq, fs, fk, vs, delta, f) result(status)
    real(c_double), intent(in) :: eps
    real(c_double), intent(in), contiguous :: v(:), f_eq(:), fs(:), fk(:), vs(:), delta(:)
    real(c_double), intent(inout), contiguous :: f(:)
    integer(c_int) :: status
    integer :: m
    m = size(v)
    status = FRICREG_ESIZE
    if (size(f_eq) /= m .or. size(fs) /= m .or. size(fk) /= m .or. size(vs) /= m .or. &
        size(delta) /= m .or. size(f) /= m) return
    status = fricreg_stribeck_eval_batch(eps, as_size(m), v, f_eq, fs, fk, vs, delta, f)
  end function stribeck_eval_array

  function stribeck_disk_eval_one(eps, v, f_eq, fs, fk, vs, delta, f) result(status)
    real(c_double), intent(in) :: eps, fs, fk, vs, delta
    real(c_double), intent(in), contiguous :: v(:), f_eq(:)
    real(c_double), intent(inout), contiguous :: f(:)
    integer(c_int) :: status
    status = FRICREG_ESIZE
    if (size(v) /= 2 .or. size(f_eq) /= 2 .or. size(f) /= 2) return
    status = fricreg_stribeck_disk_eval(v, f_eq, fs, fk, vs, delta, eps, f)
  end function stribeck_disk_eval_one

  function stribeck_disk_eval_batch(eps, v, f_eq, fs, fk, vs, delta, f) result(status)
    real(c_double), intent(in) :: eps
    real(c_double), intent(in), contiguous :: v(:, :), f_eq(:, :), fs(:), fk(:), vs(:), delta(:)
    real(c_double), intent(inout), contiguous :: f(:, :)
    integer(c_int) :: status
    integer :: m
    m = size(fs)
    status = FRICREG_ESIZE
    if (size(fk) /= m .or. size(vs) /= m .or. size(delta) /= m) return
    if (.not. (is_pairs(v, m) .and. is_pairs(f_eq, m) .and. &
               is_pairs(f, m))) return
    status = fricreg_stribeck_disk_eval_batch(eps, as_size(m), v, f_eq, fs, fk, vs, delta, f)
  end function stribeck_disk_eval_batch

end module fricreg_laws_m
