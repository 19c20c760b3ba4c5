! SPDX-License-Identifier: GPL-3.0-or-later
! ftest.f90 — the few checks the Fortran tests share. A test program calls check* for each
! expectation and finish at the end, which exits with status 1 if any failed.
module ftest
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_int64_t
  implicit none
  private
  public :: check, check_status, check_close, check_bits, finish
  integer :: failures = 0, checks = 0

contains

  subroutine check(ok, what)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    checks = checks + 1
    if (.not. ok) then
      failures = failures + 1
      write (*, '(a, a)') 'FAIL: ', what
    end if
  end subroutine check

  subroutine check_status(got, expected, what)
    integer(c_int), intent(in) :: got, expected
    character(len=*), intent(in) :: what
    character(len=64) :: buf
    write (buf, '(a, i0, a, i0, a)') ' (status ', got, ', expected ', expected, ')'
    call check(got == expected, what // trim(buf))
  end subroutine check_status

  subroutine check_close(got, expected, tol, what)
    real(c_double), intent(in) :: got, expected, tol
    character(len=*), intent(in) :: what
    character(len=96) :: buf
    write (buf, '(a, es24.16, a, es24.16, a)') ' (', got, ' vs ', expected, ')'
    call check(abs(got - expected) <= tol, what // trim(buf))
  end subroutine check_close

  !> got and expected are the same double, bit for bit (so 0 and -0 differ, and NaN = NaN).
  subroutine check_bits(got, expected, what)
    real(c_double), intent(in) :: got, expected
    character(len=*), intent(in) :: what
    character(len=96) :: buf
    write (buf, '(a, es24.16, a, es24.16, a)') ' (', got, ' vs ', expected, ')'
    call check(transfer(got, 0_c_int64_t) == transfer(expected, 0_c_int64_t), what // trim(buf))
  end subroutine check_bits

  subroutine finish(name)
    character(len=*), intent(in) :: name
    write (*, '(a, a, i0, a, i0, a)') name, ': ', checks - failures, ' passed, ', failures, &
      ' failed'
    if (failures > 0) error stop 1
  end subroutine finish

end module ftest
