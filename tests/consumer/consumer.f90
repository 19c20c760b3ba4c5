! SPDX-License-Identifier: GPL-3.0-or-later
! consumer.f90 — a user's Fortran program built against an installed fricreg only
! (tests/install.sh): module fricreg from the compiler-tagged include folder.
program consumer
  use, intrinsic :: iso_c_binding, only: c_double, c_int
  use fricreg
  implicit none
  real(c_double) :: f
  integer(c_int) :: status
  f = 0.0_c_double
  ! (4) at rest equals (2): f = f_eq inside the bound.
  status = law_eval(FRICREG_LAW_QUINN, 0.02_c_double, 0.0_c_double, 0.2385_c_double, &
                    0.731_c_double, f)
  if (status /= FRICREG_OK .or. f /= 0.2385_c_double) then
    print '(a, es24.17)', 'consumer.f90: law (4) gave ', f
    error stop 1
  end if
  print '(a)', 'consumer.f90: OK'
end program consumer
