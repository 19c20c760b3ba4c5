! SPDX-License-Identifier: GPL-3.0-or-later
! test_constants.f90 — the Fortran constants are the C headers' values.
!
! They are generated from the headers at build time (fortran/gen_constants.cmake), which stops
! on any enumerator it cannot read. This test guards the parse itself: the same names are
! compiled into C (constants_check.c, so each value is the C compiler's) and compared with
! module fricreg's parameters and with fricreg.fi's, one by one. A name missing on either side
! does not compile; a value read wrong fails here.
program test_constants
  use fricreg
  use ftest
  implicit none
  include 'constants_check.inc'
  interface
    integer(c_int) function fricreg_check_count() bind(C)
      import :: c_int
    end function
    integer(c_int) function fricreg_check_c_value(i) bind(C)
      import :: c_int
      integer(c_int), value :: i
    end function
    subroutine frchkf(v) ! generated fixed form: each name's value from INCLUDE 'fricreg.fi'
      integer, intent(out) :: v(*)
    end subroutine
  end interface
  integer :: f77_value(ncheck), i
  integer(c_int) :: c_value
  character(len=32) :: version

  call check(fricreg_check_count() == ncheck, 'C and Fortran check the same number of names')
  call frchkf(f77_value)
  do i = 1, ncheck
    c_value = fricreg_check_c_value(int(i, c_int))
    call check_status(module_value(i), c_value, 'module fricreg: ' // trim(check_name(i)))
    call check_status(int(f77_value(i), c_int), c_value, 'fricreg.fi: ' // trim(check_name(i)))
  end do
  ! A few by hand, from include/fricreg.h, in case the lists above were both empty.
  call check(ncheck > 20, 'more than 20 constants generated (fricreg.h alone has 22)')
  call check_status(FRICREG_OK, 0_c_int, 'FRICREG_OK')
  call check_status(FRICREG_ESIZE, 4_c_int, 'FRICREG_ESIZE')
  call check_status(FRICREG_LAW_QUINN, 6_c_int, 'FRICREG_LAW_QUINN')
  ! The library linked is the one whose headers generated the constants.
  call check_status(fricreg_version_number(), FRICREG_HEADER_VERSION, 'fricreg_version_number()')
  write (version, '(i0, ".", i0, ".", i0)') FRICREG_VERSION_MAJOR, FRICREG_VERSION_MINOR, &
    FRICREG_VERSION_PATCH
  call check(fricreg_version_string() == trim(version), 'fricreg_version_string() is ' // &
             trim(version))
  call check(fricreg_error_string(FRICREG_ESIZE) /= fricreg_error_string(FRICREG_EINVAL), &
             'fricreg_error_string tells codes apart')
  call finish('test_constants')
end program test_constants
