! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_element_f77.f90 — module-free entry points for Fortran 77 hosts: the element types
! of fricreg_element.h, named by an integer code, with the parameters and state in the
! caller's arrays (docs/hosts.md shows a FRIC-shaped routine built on FRELEV).
! Conventions of fricreg_f77.f90: external subroutines, every argument by reference, INTEGER
! STAT last (the C status, FRICREG_OK = 0), DOUBLE PRECISION reals, nothing written on failure.
!
! A type is its code ITYPE, fixed forever (new types get new codes; fricreg.fi names them
! FRICREG_ELEMENT_JENKINS, ... as C's enum fricreg_element_code), and its number of sliders NS
! (1 but for the Iwan types):
!   1 jenkins   2 jenkins_2d   3 contact_3d   4 iwan   5 iwan_normal   6 jenkins_3d
!   7 jenkins_normal   8 iwan_2d   9 iwan_3d   10 spring   11 dahl
! (ITYPE - 1 is fricreg_element_at's index). A code out of range or an NS the type does not
! take is FRICREG_EINVAL.
!
! Layouts: U, F (IDIM); PARAMS (NPAR); STATE (NSTATE); the tangents are Fortran's:
! DFDU(IDIM, IDIM) with DFDU(A, C) = dF(A)/dU(C), DFDP(IDIM, NPAR) with DFDP(A, J) =
! dF(A)/dPARAMS(J) (transposed here from C's row order). F77 has no optional argument: every
! output array is written.
!
!   call                                                        C function
!   FRELSZ(ITYPE, NS, IDIM, NPAR, NSTATE, STAT)                 fricreg_element_dim, _nparams,
!                                                               _nstate
!   FRELIN(ITYPE, NS, PARAMS, STATE, STAT)                      fricreg_element_init
!   FRELEV(ITYPE, NS, PARAMS, STATEI, U, F, DFDU, DFDP, STATEO, STAT)   fricreg_element_eval
!   FRELEN(ITYPE, NS, PARAMS, STATEI, U, DISS, STORED, STAT)    fricreg_element_energy
!   FRELMS(ITYPE, NS, PARAMS, STATEI, U, MSG, STAT)             fricreg_element_explain
!   FRELSG(NS, FS, KT, CHI, BETA, RES, K, PHI, STAT)            fricreg_element_segalman
! STATEO must be an array of its own: Fortran forbids one array as two arguments when one of
! them is written (C's fricreg_element_eval allows it).

!> FRELSZ(ITYPE, NS, IDIM, NPAR, NSTATE, STAT): the sizes of type ITYPE with NS sliders.
subroutine frelsz(itype, ns, idim, npar, nstate, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: itype, ns
  integer, intent(out) :: idim, npar, nstate, stat
  type(c_ptr) :: t
  t = fricreg_f77_element_type(int(itype, c_int64_t), int(ns, c_int64_t))
  stat = int(FRICREG_EINVAL)
  if (.not. c_associated(t)) return
  idim = int(fricreg_element_dim(t))
  npar = int(fricreg_element_nparams(t))
  nstate = int(fricreg_element_nstate(t))
  stat = int(FRICREG_OK)
end subroutine frelsz

!> FRELIN(ITYPE, NS, PARAMS, STATE, STAT): STATE(NSTATE) of an element at rest (every slider
!> at 0), PARAMS(NPAR) checked.
subroutine frelin(itype, ns, params, state, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: itype, ns
  double precision, intent(in) :: params(*)
  double precision, intent(inout) :: state(*)
  integer, intent(out) :: stat
  type(c_ptr) :: t
  t = fricreg_f77_element_type(int(itype, c_int64_t), int(ns, c_int64_t))
  stat = int(FRICREG_EINVAL)
  if (c_associated(t)) stat = int(fricreg_element_init(t, params, state))
end subroutine frelin

!> FRELEV(ITYPE, NS, PARAMS, STATEI, U, F, DFDU, DFDP, STATEO, STAT): the force F(IDIM), the
!> consistent tangent DFDU(IDIM, IDIM), the parameter derivatives DFDP(IDIM, NPAR) and the new
!> state STATEO(NSTATE) at U(IDIM) from STATEI(NSTATE). Allocates nothing: C writes DFDU in
!> its row order, turned here in place, and DFDP into a scratch on the stack (RECURSIVE keeps
!> it there, off static memory, so that threads may call at once) of the largest IDIM NPAR of
!> the table: iwan_3d's 3 (2 FRICREG_ELEMENT_MAX_SLIDERS) = 6144 (iwan_normal's 2 (2 1024 + 3)
!> = 4102, the fixed types' at most 3 5); a type beyond it would be FRICREG_ESIZE, writing
!> nothing (test_f77_element runs iwan_3d at NS = 1024).
recursive subroutine frelev(itype, ns, params, statei, u, f, dfdu, dfdp, stateo, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: itype, ns
  double precision, intent(in) :: params(*), statei(*), u(*)
  double precision, intent(inout) :: f(*), dfdu(*), dfdp(*), stateo(*)
  integer, intent(out) :: stat
  integer, parameter :: max_dfdp = 3 * 2 * 1024
  type(c_ptr) :: t
  integer :: d, np, a, j
  real(c_double) :: tp(max_dfdp), x
  t = fricreg_f77_element_type(int(itype, c_int64_t), int(ns, c_int64_t))
  stat = int(FRICREG_EINVAL)
  if (.not. c_associated(t)) return
  d = int(fricreg_element_dim(t))
  np = int(fricreg_element_nparams(t))
  stat = int(FRICREG_ESIZE)
  if (d * np > max_dfdp) return
  stat = int(fricreg_element_eval(t, params, statei, u, f, dfdu, tp, stateo))
  if (stat /= FRICREG_OK) return
  do a = 1, d
    do j = a + 1, d
      x = dfdu(a + d * (j - 1))
      dfdu(a + d * (j - 1)) = dfdu(j + d * (a - 1))
      dfdu(j + d * (a - 1)) = x
    end do
    do j = 1, np
      dfdp(a + d * (j - 1)) = tp(j + np * (a - 1))
    end do
  end do
end subroutine frelev

!> FRELEN(ITYPE, NS, PARAMS, STATEI, U, DISS, STORED, STAT): the energies of the increment
!> FRELEV makes on the same inputs: DISS what the sliders dissipate in it (FRIC's SFD
!> increment), STORED what the springs hold at its end (FRIC's SED).
subroutine frelen(itype, ns, params, statei, u, diss, stored, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: itype, ns
  double precision, intent(in) :: params(*), statei(*), u(*)
  double precision, intent(inout) :: diss, stored
  integer, intent(out) :: stat
  type(c_ptr) :: t
  t = fricreg_f77_element_type(int(itype, c_int64_t), int(ns, c_int64_t))
  stat = int(FRICREG_EINVAL)
  if (c_associated(t)) stat = int(fricreg_element_energy(t, params, statei, u, diss, stored))
end subroutine frelen

!> FRELMS(ITYPE, NS, PARAMS, STATEI, U, MSG, STAT): STAT and the message MSG (blank-padded,
!> blank on success) of FRELEV's failure on the same inputs. Fortran 77 passes every argument,
!> so this is always fricreg_element_explain's eval case (state and U given), never init's or
!> a NULL's; FRELEV's outputs F, DFDU, DFDP and STATEO are not its arguments.
subroutine frelms(itype, ns, params, statei, u, msg, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: itype, ns
  double precision, intent(in) :: params(*), statei(*), u(*)
  character(len=*), intent(out) :: msg
  integer, intent(out) :: stat
  type(c_ptr) :: t
  character(kind=c_char, len=256) :: buf
  integer :: k
  t = fricreg_f77_element_type(int(itype, c_int64_t), int(ns, c_int64_t))
  msg = ' '
  if (.not. c_associated(t)) then
    stat = int(FRICREG_EINVAL)
    msg = 'FRELEV: no element type of that code with that many sliders'
    return
  end if
  stat = int(fricreg_element_explain(t, params, statei, u, buf, int(len(buf), c_size_t)))
  k = index(buf, c_null_char)
  if (k > 1) msg = buf(1:k - 1)
end subroutine frelms

!> FRELSG(NS, FS, KT, CHI, BETA, RES, K, PHI, STAT): the NS sliders K(NS), PHI(NS) of
!> Segalman's four-parameter model (fricreg_element_segalman).
subroutine frelsg(ns, fs, kt, chi, beta, res, k, phi, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: ns
  double precision, intent(in) :: fs, kt, chi, beta, res
  double precision, intent(inout) :: k(*), phi(*)
  integer, intent(out) :: stat
  stat = int(FRICREG_EINVAL)
  if (ns < 1) return
  stat = int(fricreg_element_segalman(int(ns, c_size_t), fs, kt, chi, beta, res, k, phi))
end subroutine frelsg
