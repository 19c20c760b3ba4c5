! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_joints_f77.f90 — module-free entry points for Fortran 77 callers: joints, the Jenkins
! and Iwan elements with trial/commit and normal load (fricreg_jenkins.h, fricreg_iwan.h), and
! the AFT of the 1-D elements for harmonic balance (fricreg_aft.h); docs/joints.md, docs/aft.md.
! Conventions of fricreg_f77.f90: external subroutines, every argument by reference, INTEGER*8
! handle H (0: none), INTEGER STAT last (the C status, FRICREG_OK = 0), DOUBLE PRECISION reals,
! nothing changed on failure; counts are checked by the C library against the object
! (FRICREG_ESIZE) before an array is read.
!
! Layouts. An element's vectors are DIM numbers, so U, F and W of N elements are (DIM, N)
! arrays, column I element I (C's interleaved layout); the tangents DFDU are (DIM, DIM, N),
! symmetric blocks (C's row-major block is the same numbers), DFDG (DIM, N). An Iwan element's
! NS sliders are a column: K, PHI and W are (NS, N). The AFT's coefficients U and F are
! vectors of NC = 2H + 1 numbers (U0, A1, B1, ..., AH, BH), and its Jacobian is column-major
! JAC(I, J) = dF(I)/dU(J), (NC, NC), transposed here from C's row order. F77 has no optional
! argument: every output array is written (pass a scratch array for one not wanted).
!
!   call                                             C function
!   FRJKCR(IDIM, N, H, STAT)                         fricreg_jenkins_create
!   FRJKFR(H, STAT)                                  _free, then H = 0
!   FRJKPA(H, N, KT, MUN, STAT)                      _set_params
!   FRJKNL(H, N, MU, N0, KN, STAT)                   _set_normal
!   FRJKTR(H, N, U, F, DFDU, STAT)                   _trial
!   FRJKTN(H, N, U, G, F, NF, DFDU, DFDG, STAT)      _trial_normal
!   FRJKCM(H, STAT), FRJKRS(H, STAT)                 _commit, _reset
!   FRJKSL(H, N, W, STAT)                            _get_slider
!   FRJKER(H, CODE, MSG, STAT)                       _errcode, _errmsg
!   FRIWCR(IDIM, N, NS, H, STAT)                     fricreg_iwan_create
!   FRIWFR(H, STAT)                                  _free, then H = 0
!   FRIWPA(H, N, NS, K, PHI, STAT)                   _set_params
!   FRIWSG(H, N, FS, KT, CHI, BETA, RES, STAT)       _set_segalman
!   FRIWNL(H, N, N0, KN, STAT)                       _set_normal
!   FRIWTR(H, N, U, F, DFDU, STAT)                   _trial
!   FRIWTN(H, N, U, G, F, NF, DFDU, DFDG, STAT)      _trial_normal
!   FRIWCM(H, STAT), FRIWRS(H, STAT)                 _commit, _reset
!   FRIWSL(H, N, NS, W, STAT)                        _get_slider
!   FRIWER(H, CODE, MSG, STAT)                       _errcode, _errmsg
!   FRAFCR(NH, NSAMP, H, STAT)                       fricreg_aft_create
!   FRAFFR(H, STAT)                                  _free, then H = 0
!   FRAFJE(H, KT, MUN, NC, U, F, JAC, STAT)          _jenkins_exact
!   FRAFJS(H, KT, MUN, NC, U, F, JAC, STAT)          _jenkins_sampled
!   FRAFJN(H, KT, MU, N0, KN, NC, U, G, F, NF, JAC, STAT)  _jenkins_normal_sampled
!   FRAFNE(H, KT, MU, N0, KN, NC, U, G, F, NF, JAC, STAT)  _jenkins_normal_exact
!   FRAFIE(H, NS, K, PHI, NC, U, F, JAC, STAT)       _iwan_exact
!   FRAFIS(H, NS, K, PHI, NC, U, F, JAC, STAT)       _iwan_sampled
!   FRAFER(H, CODE, MSG, STAT)                       _errcode, _errmsg
! The creators refuse a negative count before C sees it (it would wrap into size_t), with
! FRICREG_EINVAL and no object to record it.
!
! Generated, not here: the entry points that are one C call (FRJKPA, FRJKNL, FRJKTR, FRJKTN,
! FRJKCM, FRJKRS, FRJKSL, FRIWPA, FRIWSG, FRIWNL, FRIWTR, FRIWTN, FRIWCM, FRIWRS, FRIWSL) are a
! line each, with their doc comments, in the table fricreg_joints_f77.txt, which
! fortran/gen_f77.cmake turns into fricreg_joints_f77_generated.f90 at build time; those below
! have logic of their own.

! ---- Jenkins elements (fricreg_jenkins.h) ----------------------------------------------------

!> FRJKCR(IDIM, N, H, STAT): N >= 1 Jenkins elements of dimension IDIM = 1 or 2 into H, every
!> slider at 0, kt = 1 and mun = 1 until FRJKPA.
subroutine frjkcr(idim, n, h, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: idim, n
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  type(c_ptr) :: p
  if (n < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  p = c_null_ptr
  stat = fricreg_f77_created(fricreg_jenkins_create(int(idim, c_int), int(n, c_size_t), p), p, h)
end subroutine frjkcr

!> FRJKFR(H, STAT): release the elements H and set H = 0; H = 0 does nothing.
subroutine frjkfr(h, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  stat = fricreg_f77_release(h, fricreg_jenkins_free)
end subroutine frjkfr

!> FRJKER(H, CODE, MSG, STAT): code and message of the elements' last failure.
subroutine frjker(h, code, msg, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: code
  character(len=*), intent(out) :: msg
  integer, intent(out) :: stat
  integer(c_int) :: last
  stat = fricreg_f77_last_error(h, fricreg_jenkins_errcode, fricreg_jenkins_errmsg, last, msg)
  code = last
end subroutine frjker

! ---- Iwan elements (fricreg_iwan.h) ----------------------------------------------------------

!> FRIWCR(IDIM, N, NS, H, STAT): N >= 1 Iwan elements of NS >= 1 sliders each, dimension IDIM
!> = 1 or 2, into H (each slider k = PHI = 1/NS until FRIWPA or FRIWSG).
subroutine friwcr(idim, n, ns, h, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: idim, n, ns
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  type(c_ptr) :: p
  if (n < 0 .or. ns < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  p = c_null_ptr
  stat = fricreg_f77_created(fricreg_iwan_create(int(idim, c_int), int(n, c_size_t), &
                                                 int(ns, c_size_t), p), p, h)
end subroutine friwcr

!> FRIWFR(H, STAT): release the elements H and set H = 0; H = 0 does nothing.
subroutine friwfr(h, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  stat = fricreg_f77_release(h, fricreg_iwan_free)
end subroutine friwfr

!> FRIWER(H, CODE, MSG, STAT): code and message of the elements' last failure.
subroutine friwer(h, code, msg, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: code
  character(len=*), intent(out) :: msg
  integer, intent(out) :: stat
  integer(c_int) :: last
  stat = fricreg_f77_last_error(h, fricreg_iwan_errcode, fricreg_iwan_errmsg, last, msg)
  code = last
end subroutine friwer

! ---- The AFT of the 1-D elements (fricreg_aft.h) ---------------------------------------------

!> FRAFCR(NH, NSAMP, H, STAT): an AFT workspace for harmonics 0..NH and NSAMP samples a period
!> (0: the exact path only; else a power of two >= 2 NH + 2) into H.
subroutine frafcr(nh, nsamp, h, stat)
  use fricreg_c
  implicit none
  integer, intent(in) :: nh, nsamp
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  type(c_ptr) :: p
  if (nsamp < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  p = c_null_ptr
  stat = fricreg_f77_created(fricreg_aft_create(int(nh, c_int), int(nsamp, c_size_t), p), p, h)
end subroutine frafcr

!> FRAFFR(H, STAT): release the workspace H and set H = 0; H = 0 does nothing.
subroutine fraffr(h, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  stat = fricreg_f77_release(h, fricreg_aft_free)
end subroutine fraffr

!> FRAFJE(H, KT, MUN, NC, U, F, JAC, STAT): exact AFT of one Jenkins element (KT > 0,
!> MUN >= 0): from U(NC), NC = 2H + 1, the force's coefficients F(NC) and JAC(NC, NC),
!> JAC(I, J) = dF(I)/dU(J).
subroutine frafje(h, kt, mun, nc, u, f, jac, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  double precision, intent(in) :: kt, mun, u(*)
  integer, intent(in) :: nc
  double precision, intent(inout) :: f(*), jac(*)
  integer, intent(out) :: stat
  stat = int(fricreg_aft_jenkins_exact(fricreg_handle_to_ptr(h), kt, mun, int(nc, c_size_t), u, &
                                       f, jac))
  if (stat == FRICREG_OK) call fricreg_transpose(jac, int(nc, c_size_t))
end subroutine frafje

!> FRAFJS(H, KT, MUN, NC, U, F, JAC, STAT): the sampled AFT of one Jenkins element, as FRAFJE
!> (FRICREG_EINVAL for a workspace of no samples).
subroutine frafjs(h, kt, mun, nc, u, f, jac, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  double precision, intent(in) :: kt, mun, u(*)
  integer, intent(in) :: nc
  double precision, intent(inout) :: f(*), jac(*)
  integer, intent(out) :: stat
  stat = int(fricreg_aft_jenkins_sampled(fricreg_handle_to_ptr(h), kt, mun, int(nc, c_size_t), &
                                         u, f, jac))
  if (stat == FRICREG_OK) call fricreg_transpose(jac, int(nc, c_size_t))
end subroutine frafjs

!> FRAFJN(H, KT, MU, N0, KN, NC, U, G, F, NF, JAC, STAT): the sampled AFT of one Jenkins
!> element under normal load with lift-off (bound MU max(0, N0 + KN G)): from U(NC) and the
!> normal displacement's G(NC), the tangential force's F(NC), the normal force's NF(NC) and
!> JAC(2 NC, 2 NC), column-major, rows (F, NF) and columns (U, G): JAC(I, J) = dF(I)/dU(J),
!> JAC(I, NC + J) = dF(I)/dG(J), JAC(NC + I, NC + J) = dNF(I)/dG(J).
subroutine frafjn(h, kt, mu, n0, kn, nc, u, g, f, nf, jac, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  double precision, intent(in) :: kt, mu, n0, kn, u(*), g(*)
  integer, intent(in) :: nc
  double precision, intent(inout) :: f(*), nf(*), jac(*)
  integer, intent(out) :: stat
  stat = int(fricreg_aft_jenkins_normal_sampled(fricreg_handle_to_ptr(h), kt, mu, n0, kn, &
                                                int(nc, c_size_t), u, g, f, nf, jac))
  if (stat == FRICREG_OK) call fricreg_transpose(jac, 2 * int(nc, c_size_t))
end subroutine frafjn

!> FRAFNE(H, KT, MU, N0, KN, NC, U, G, F, NF, JAC, STAT): the exact AFT of one Jenkins
!> element under normal load with lift-off, as FRAFJN (same arguments and layouts) without
!> sampling error (the workspace may have NSAMP = 0).
subroutine frafne(h, kt, mu, n0, kn, nc, u, g, f, nf, jac, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  double precision, intent(in) :: kt, mu, n0, kn, u(*), g(*)
  integer, intent(in) :: nc
  double precision, intent(inout) :: f(*), nf(*), jac(*)
  integer, intent(out) :: stat
  stat = int(fricreg_aft_jenkins_normal_exact(fricreg_handle_to_ptr(h), kt, mu, n0, kn, &
                                              int(nc, c_size_t), u, g, f, nf, jac))
  if (stat == FRICREG_OK) call fricreg_transpose(jac, 2 * int(nc, c_size_t))
end subroutine frafne

!> FRAFIE(H, NS, K, PHI, NC, U, F, JAC, STAT): exact AFT of one Iwan element of NS sliders
!> K(NS) > 0, PHI(NS) >= 0, as FRAFJE.
subroutine frafie(h, ns, k, phi, nc, u, f, jac, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: ns, nc
  double precision, intent(in) :: k(*), phi(*), u(*)
  double precision, intent(inout) :: f(*), jac(*)
  integer, intent(out) :: stat
  stat = int(fricreg_aft_iwan_exact(fricreg_handle_to_ptr(h), int(ns, c_size_t), k, phi, &
                                    int(nc, c_size_t), u, f, jac))
  if (stat == FRICREG_OK) call fricreg_transpose(jac, int(nc, c_size_t))
end subroutine frafie

!> FRAFIS(H, NS, K, PHI, NC, U, F, JAC, STAT): the sampled AFT of one Iwan element, as FRAFIE.
subroutine frafis(h, ns, k, phi, nc, u, f, jac, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: ns, nc
  double precision, intent(in) :: k(*), phi(*), u(*)
  double precision, intent(inout) :: f(*), jac(*)
  integer, intent(out) :: stat
  stat = int(fricreg_aft_iwan_sampled(fricreg_handle_to_ptr(h), int(ns, c_size_t), k, phi, &
                                      int(nc, c_size_t), u, f, jac))
  if (stat == FRICREG_OK) call fricreg_transpose(jac, int(nc, c_size_t))
end subroutine frafis

!> FRAFER(H, CODE, MSG, STAT): code and message of the workspace's last failure.
subroutine frafer(h, code, msg, stat)
  use fricreg_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: code
  character(len=*), intent(out) :: msg
  integer, intent(out) :: stat
  integer(c_int) :: last
  stat = fricreg_f77_last_error(h, fricreg_aft_errcode, fricreg_aft_errmsg, last, msg)
  code = last
end subroutine frafer
