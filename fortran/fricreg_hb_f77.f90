! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_hb_f77.f90 — module-free entry points for Fortran 77 callers: harmonic balance of a
! linear structure with 1-D Jenkins elements (fricreg_hb.h; docs/harmonic_balance.md), the
! frequency-domain side of a legacy joint code. Built with the drivers, like
! fricreg_structure_f77.f90, whose conventions it shares: external subroutines, every argument
! by reference, INTEGER*8 handle H (0: none), INTEGER STAT last (the C status, FRICREG_OK = 0),
! DOUBLE PRECISION reals, nothing changed on failure; counts checked by C against the driver.
!
! Layouts. M, K, C are (NDOF, NDOF) symmetric (Fortran's order is C's); J is Fortran's
! J(M, NDOF), transposed here into C's row order in a scratch copy. The elements' coordinates
! Q(NC, M), NC = 2 NH + 1, column I element I's coefficients (Q0, A1, B1, ..., ANH, BNH); the
! displacements X(NC, NDOF); the same numbers as C's. Continuation points count from 1.
!
!   call                                              C function (fricreg_hb_*)
!   FRHBCR(NDOF, M, NH, H, STAT)                      _create
!   FRHBFR(H, STAT)                                   _free, then H = 0
!   FRHBMF(H, NDOF, A, STAT), FRHBKF, FRHBCF          _set_mass, _set_stiffness, _set_damping
!   FRHBMX(H, WHICH, NROWS, NCOLS, FORMAT, PTR, IND, VALUES, STAT)
!                                                     _set_matrix (M, K, C; dense or compressed)
!   FRHBCA(H, A0, A1, STAT)                           _set_rayleigh
!   FRHBJF(H, M, NDOF, J, KT, MUN, STAT)              _set_elements (given J transposed)
!   FRHBIW(H, M, NDOF, J, NS, K, PHI, STAT)           _set_iwan (J transposed, K(NS, M))
!   FRHBLO(H, M, NDOF, JT, JN, KT, MU, N0, KN, STAT)  _set_normal_elements (JT, JN transposed)
!   FRHBIL(H, M, NDOF, JT, JN, NS, K, MU, N0, KN, STAT)  _set_iwan_normal (K, MU (NS, M))
!   FRHBL2(H, M, NDOF, JE, JN, KT, MU, N0, KN, STAT)  _set_jenkins_2d_normal (JE(2M, NDOF))
!   FRHBAE(H, ITYPE, NS, ME, NDOF, J, PARAMS, STAT)  _add_elements (J(ME IDIM, NDOF) transposed,
!                                                     PARAMS(NPAR, ME))
!   FRHBXE(H, STAT)                                   _clear_elements
!   FRHBEC(H, ME, STAT)                               _element_count
!   FRHBPF(H, NDOF, PC, PS, STAT)                     _set_excitation
!   FRHBNT(H, TOL, MAXIT, STAT)                       _set_newton
!   FRHBCT(H, DS, DSMIN, DSMAX, MAXPT, STAT)          _set_continuation
!   FRHBSV(H, OMEGA, NQ, IGUESS, Q, STAT)             _solve (IGUESS = 1: Q holds the guess)
!   FRHBXD(H, NDOF, NC, X, STAT)                      _displacement
!   FRHBGO(H, W0, W1, NQ, IGUESS, Q0, STAT)           _continue (IGUESS = 1: Q0 the guess)
!   FRHBNP(H, NP, STAT)                               _points
!   FRHBPT(H, K, OMEGA, NDOF, RMS, STAT)              _point (K from 1)
!   FRHBPK(H, IDOF, OMEGA, RMS, STAT)                 _peak (IDOF from 1)
!   FRHBST(H, ION, STAT)                              _set_stability (ION 0 or 1)
!   FRHBSM(H, METHOD, STAT)                           _set_stability_method
!   FRHBGM(H, METHOD, STAT)                           _get_stability_method
!   FRHBSB(H, K, ISTAB, MUMAX, STAT)                  _point_stability (K from 1; 0: solution)
!   FRHBEX(H, K, NEXP, EXPS, STAT)                    _point_exponents (K from 1; 0: solution)
!   FRHBBN(H, NB, STAT)                               _bifurcations
!   FRHBBF(H, I, ITYPE, OMEGA, K, NDOF, RMS, STAT)    _bifurcation (I, K from 1)
!   FRHBNM(H, MODE, IDAMP, A0, A1, NP, STAT)          _nma (MODE from 1)
!   FRHBNN(H, NP, STAT)                               _nma_points
!   FRHBNQ(H, I, A, OMEGA, ZETA, NDOF, NC, X, STAT)   _nma_point (I from 1)
!   FRHBNC(H, MODE, IDAMP, A0, A1, NP, STAT)          _nma_continue (MODE from 1)
!   FRHBNE(H, I, NH, FRAC, STAT)                      _nma_harmonic_energy (I from 1)
!   FRHBNR(H, I, IHARM, NM, FRAC, STAT)               _nma_modal_participation (I from 1)
!   FRHBNS(H, NS, STAT)                               _nma_special_points
!   FRHBNK(H, I, ITYPE, A, OMEGA, ZETA, K, MODE, STAT) _nma_special_point (I, MODE from 1)
!   FRHBGL(H, OMEGA, L0, L1, NQ, IGUESS, Q0, STAT)    _continue_level (IGUESS = 1: Q0 the guess)
!   FRHBPL(H, K, LEVEL, STAT)                         _point_level (K from 1)
!   FRHBPX(H, K, NDOF, NC, X, STAT)                   _point_displacement (K from 1; 0: solution)
!   FRHBBL(H, I, LEVEL, STAT)                         _bifurcation_level (I from 1)
!   FRHBMS(H, MONITR, STAT), FRHBMU(H, STAT)          _set_monitor (MONITR below; FRHBMU removes it)
!   FRHBMI(H, MAXIT, STAT)                            _set_max_iterations (INTEGER*8 MAXIT)
!   FRHBER(H, CODE, MSG, STAT)                        _errcode, _errmsg
! Refused here, before C sees them, with FRICREG_EINVAL: FRHBCR's NDOF or M below 1, a
! negative MAXPT, IGUESS other than 0 or 1, and a K or IDOF below 1 (counts that would wrap
! into size_t or C's 0-based index; FRHBSB's, FRHBEX's and FRHBPX's K below 0, FRHBEX's NEXP below 0), FRHBIW's and FRHBIL's NS below 1,
! FRHBNM's MODE below 1 or negative NP, FRHBAE's code or NS of no type or ME below 0,
! FRHBNQ's and FRHBNK's I below 1.
!
! A monitor is the caller's INTEGER FUNCTION MONITR(ITERS, PARAM, RESID), INTEGER*8 ITERS (the
! Newton steps of this call so far), DOUBLE PRECISION PARAM (the continued parameter), RESID
! (the residual over Newton's bound); a nonzero value stops the call (STAT FRICREG_EWORK). C
! calls the bind(C) relay below, which calls MONITR, whose address C keeps as user: nothing is
! allocated, as for the warning handlers (fricreg_warnings_f77.f90 says why the address may
! pass through a void*).
!
! Generated, not here: the entry points that are one C call (FRHBMF, FRHBKF, FRHBCF, FRHBMX,
! FRHBCA, FRHBPF, FRHBNT, FRHBXD, FRHBST, FRHBSM, FRHBXE) are a line each, with their doc
! comments, in the table fricreg_hb_f77.txt, which fortran/gen_f77.cmake turns into
! fricreg_hb_f77_generated.f90 at build time; those below have logic of their own.

!> FRHBCR(NDOF, M, NH, H, STAT): a driver for NDOF >= 1 degrees of freedom, M >= 1 Jenkins
!> elements and NH harmonics (1 <= NH <= FRICREG_HB_MAX_HARMONICS) into H.
subroutine frhbcr(ndof, m, nh, h, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer, intent(in) :: ndof, m, nh
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  type(c_ptr) :: p
  if (ndof < 1 .or. m < 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  p = c_null_ptr
  stat = fricreg_f77_created(fricreg_hb_create(int(ndof, c_size_t), int(m, c_size_t), &
                                               int(nh, c_int), p), p, h)
end subroutine frhbcr

!> FRHBFR(H, STAT): release the driver H and set H = 0; H = 0 does nothing.
subroutine frhbfr(h, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  stat = fricreg_f77_release(h, fricreg_hb_free)
end subroutine frhbfr

!> FRHBJF(H, M, NDOF, J, KT, MUN, STAT): the elements, Fortran's J(M, NDOF) (row I element
!> I's relative displacement), stiffnesses KT(M) > 0 and slip forces MUN(M) >= 0.
subroutine frhbjf(h, m, ndof, j, kt, mun, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m, ndof
  double precision, intent(in) :: j(max(m, 0), *), kt(*), mun(*)
  integer, intent(out) :: stat
  double precision, allocatable :: jt(:, :)
  integer :: mm, nn, alloc
  ! Sizes that cannot be the driver's copy nothing: C answers FRICREG_ESIZE.
  mm = max(m, 0)
  nn = max(ndof, 0)
  allocate (jt(nn, mm), stat=alloc)
  if (alloc /= 0) then
    stat = int(FRICREG_ENOMEM)
    return
  end if
  if (mm > 0 .and. nn > 0) jt = transpose(j(1:mm, 1:nn))
  stat = int(fricreg_hb_set_elements(fricreg_handle_to_ptr(h), int(m, c_size_t), &
                                     int(ndof, c_size_t), jt, kt, mun))
end subroutine frhbjf

!> FRHBIW(H, M, NDOF, J, NS, K, PHI, STAT): Iwan elements instead, J(M, NDOF) as FRHBJF,
!> element I's NS sliders the stiffnesses K(1:NS, I) > 0 and slip forces PHI(1:NS, I) >= 0
!> (C's row-major K[M NS], the same numbers). FRHBJF is the case NS = 1.
subroutine frhbiw(h, m, ndof, j, ns, k, phi, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m, ndof, ns
  double precision, intent(in) :: j(max(m, 0), *), k(*), phi(*)
  integer, intent(out) :: stat
  double precision, allocatable :: jt(:, :)
  integer :: mm, nn, alloc
  ! Sizes that cannot be the driver's copy nothing: C answers FRICREG_ESIZE.
  mm = max(m, 0)
  nn = max(ndof, 0)
  if (ns < 1) then ! would wrap into size_t
    stat = int(FRICREG_EINVAL)
    return
  end if
  allocate (jt(nn, mm), stat=alloc)
  if (alloc /= 0) then
    stat = int(FRICREG_ENOMEM)
    return
  end if
  if (mm > 0 .and. nn > 0) jt = transpose(j(1:mm, 1:nn))
  stat = int(fricreg_hb_set_iwan(fricreg_handle_to_ptr(h), int(m, c_size_t), &
                                 int(ndof, c_size_t), jt, int(ns, c_size_t), k, phi))
end subroutine frhbiw

!> FRHBLO(H, M, NDOF, JT, JN, KT, MU, N0, KN, STAT): Jenkins elements under a normal load with
!> lift-off instead, JT(M, NDOF) and JN(M, NDOF) the tangential and normal rows as FRHBJF's J,
!> KT(M) > 0, MU(M) >= 0, N0(M) the preloads, KN(M) >= 0: the normal force MAX(0, N0 + KN G),
!> the slip bound MU N. Q then has 2 M columns (NQ = 2 M NC): column 2I - 1 element I's U,
!> column 2I its G. Each element setter replaces the others.
subroutine frhblo(h, m, ndof, jt, jn, kt, mu, n0, kn, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m, ndof
  double precision, intent(in) :: jt(max(m, 0), *), jn(max(m, 0), *), kt(*), mu(*), n0(*), kn(*)
  integer, intent(out) :: stat
  double precision, allocatable :: ct(:, :), cn(:, :)
  integer :: mm, nn
  ! Sizes that cannot be the driver's copy nothing: C answers FRICREG_ESIZE.
  mm = max(m, 0)
  nn = max(ndof, 0)
  stat = int(fricreg_f77_transposed_rows(jt(1:mm, 1:nn), jn(1:mm, 1:nn), ct, cn))
  if (stat /= FRICREG_OK) return
  stat = int(fricreg_hb_set_normal_elements(fricreg_handle_to_ptr(h), int(m, c_size_t), &
                                            int(ndof, c_size_t), ct, cn, kt, mu, n0, kn))
end subroutine frhblo

!> FRHBL2(H, M, NDOF, JE, JN, KT, MU, N0, KN, STAT): 3-D contact elements instead (C's
!> fricreg_hb_set_jenkins_2d_normal): element I's tangential rows 2I - 1 (x) and 2I (y) of
!> JE(2 M, NDOF), its normal row I of JN(M, NDOF), KT, MU, N0, KN as FRHBLO's. Q then has 3 M
!> columns (NQ = 3 M NC): 3I - 2 element I's UX, 3I - 1 its UY, 3I its G. Since 1.7.
subroutine frhbl2(h, m, ndof, je, jn, kt, mu, n0, kn, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m, ndof
  double precision, intent(in) :: je(2 * min(max(m, 0), 2**25), *), jn(max(m, 0), *), kt(*), &
                                  mu(*), n0(*), kn(*)
  integer, intent(out) :: stat
  double precision, allocatable :: ct(:, :), cn(:, :)
  integer :: mm, nn
  if (m > 2**25) then ! 2 M would wrap a default INTEGER (C answers FRICREG_ESIZE for any M
    stat = int(FRICREG_ESIZE) ! other than the driver's)
    return
  end if
  ! Sizes that cannot be the driver's copy nothing: C answers FRICREG_ESIZE.
  mm = max(m, 0)
  nn = max(ndof, 0)
  stat = int(fricreg_f77_transposed_rows(je(1:2 * mm, 1:nn), jn(1:mm, 1:nn), ct, cn))
  if (stat /= FRICREG_OK) return
  stat = int(fricreg_hb_set_jenkins_2d_normal(fricreg_handle_to_ptr(h), int(m, c_size_t), &
                                              int(ndof, c_size_t), ct, cn, kt, mu, n0, kn))
end subroutine frhbl2

!> FRHBIL(H, M, NDOF, JT, JN, NS, K, MU, N0, KN, STAT): Iwan elements under a normal load with
!> lift-off instead, JT, JN, N0, KN as FRHBLO's, element I's NS sliders the stiffnesses
!> K(1:NS, I) > 0 bounded by MU(1:NS, I) N (MU >= 0; C's row-major K[M NS], the same numbers).
!> Q has 2 M columns as FRHBLO's, which is the case NS = 1.
subroutine frhbil(h, m, ndof, jt, jn, ns, k, mu, n0, kn, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m, ndof, ns
  double precision, intent(in) :: jt(max(m, 0), *), jn(max(m, 0), *), k(*), mu(*), n0(*), kn(*)
  integer, intent(out) :: stat
  double precision, allocatable :: ct(:, :), cn(:, :)
  integer :: mm, nn
  ! Sizes that cannot be the driver's copy nothing: C answers FRICREG_ESIZE.
  mm = max(m, 0)
  nn = max(ndof, 0)
  if (ns < 1) then ! would wrap into size_t
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_f77_transposed_rows(jt(1:mm, 1:nn), jn(1:mm, 1:nn), ct, cn))
  if (stat /= FRICREG_OK) return
  stat = int(fricreg_hb_set_iwan_normal(fricreg_handle_to_ptr(h), int(m, c_size_t), &
                                        int(ndof, c_size_t), ct, cn, int(ns, c_size_t), k, mu, &
                                        n0, kn))
end subroutine frhbil

!> FRHBAE(H, ITYPE, NS, ME, NDOF, J, PARAMS, STAT): ME elements of the type of code ITYPE with
!> NS sliders (FRELEV's codes; HB takes jenkins, iwan, jenkins_normal, iwan_normal and
!> contact_3d; NS 1 but for the Iwan types) beside those the driver holds, of any of those
!> types (C's fricreg_hb_add_elements): element I's IDIM rows (FRELSZ; tangential, then the
!> normal one) (I - 1) IDIM + 1 .. I IDIM of J(ME IDIM, NDOF), its parameters PARAMS(1:NPAR, I)
!> in the type's layout (gap 0). Q's columns are the elements' rows in the order added.
!> FRICREG_EINVAL for a code or NS of no type, or ME below 0 (nothing changed); C's codes.
!> Since 1.8.
subroutine frhbae(h, itype, ns, me, ndof, j, params, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: itype, ns, me, ndof
  double precision, intent(in) :: j(*), params(*)
  integer, intent(out) :: stat
  real(c_double), allocatable :: jt(:, :)
  type(c_ptr) :: t
  stat = int(fricreg_f77_element_rows(int(itype, c_int64_t), int(ns, c_int64_t), &
                                      int(me, c_int64_t), int(ndof, c_int64_t), j, t, jt))
  if (stat /= FRICREG_OK) return
  stat = int(fricreg_hb_add_elements(fricreg_handle_to_ptr(h), t, int(me, c_size_t), &
                                     int(ndof, c_size_t), jt, params))
end subroutine frhbae

!> FRHBEC(H, ME, STAT): ME, the number of elements the driver holds, of all types (C's
!> fricreg_hb_element_count). Since 1.8.
subroutine frhbec(h, me, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(inout) :: me
  integer, intent(out) :: stat
  me = int(fricreg_hb_element_count(fricreg_handle_to_ptr(h)))
  stat = int(FRICREG_OK)
end subroutine frhbec

!> FRHBCT(H, DS, DSMIN, DSMAX, MAXPT, STAT): the continuation's step control and its most
!> points MAXPT >= 1.
subroutine frhbct(h, ds, dsmin, dsmax, maxpt, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  double precision, intent(in) :: ds, dsmin, dsmax
  integer, intent(in) :: maxpt
  integer, intent(out) :: stat
  if (maxpt < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_hb_set_continuation(fricreg_handle_to_ptr(h), ds, dsmin, dsmax, &
                                         int(maxpt, c_size_t)))
end subroutine frhbct

!> FRHBSV(H, OMEGA, NQ, IGUESS, Q, STAT): solve at OMEGA into Q(NC, M), NQ = NC M; with
!> IGUESS = 1 from the guess Q holds on entry, with 0 from the linear response.
subroutine frhbsv(h, omega, nq, iguess, q, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  double precision, intent(in) :: omega
  integer, intent(in) :: nq, iguess
  double precision, intent(inout) :: q(*)
  integer, intent(out) :: stat
  double precision, allocatable :: q0(:)
  integer :: alloc
  if (iguess /= 0 .and. iguess /= 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  if (iguess == 1) then ! the guess copied: Fortran forbids passing Q as both arguments
    allocate (q0(max(nq, 0)), stat=alloc)
    if (alloc /= 0) then
      stat = int(FRICREG_ENOMEM)
      return
    end if
    if (nq > 0) q0 = q(1:nq)
    stat = int(fricreg_hb_solve(fricreg_handle_to_ptr(h), omega, int(nq, c_size_t), q0, q))
  else
    stat = int(fricreg_hb_solve(fricreg_handle_to_ptr(h), omega, int(nq, c_size_t), q=q))
  end if
end subroutine frhbsv

!> FRHBGO(H, W0, W1, NQ, IGUESS, Q0, STAT): follow the response from W0 to W1 by
!> continuation; with IGUESS = 1 from the guess Q0(NC, M) at W0, with 0 from the linear
!> response (Q0 not read).
subroutine frhbgo(h, w0, w1, nq, iguess, q0, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  double precision, intent(in) :: w0, w1, q0(*)
  integer, intent(in) :: nq, iguess
  integer, intent(out) :: stat
  if (iguess /= 0 .and. iguess /= 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  if (iguess == 1) then
    stat = int(fricreg_hb_continue(fricreg_handle_to_ptr(h), w0, w1, int(nq, c_size_t), q0))
  else
    stat = int(fricreg_hb_continue(fricreg_handle_to_ptr(h), w0, w1, int(nq, c_size_t)))
  end if
end subroutine frhbgo

!> FRHBGL(H, OMEGA, L0, L1, NQ, IGUESS, Q0, STAT): follow the response at the frequency OMEGA
!> from the excitation level L0 to L1 (the excitation times the level) by continuation; with
!> IGUESS = 1 from the guess Q0(NC, M) at L0, with 0 from the stuck response (Q0 not read).
subroutine frhbgl(h, omega, l0, l1, nq, iguess, q0, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  double precision, intent(in) :: omega, l0, l1, q0(*)
  integer, intent(in) :: nq, iguess
  integer, intent(out) :: stat
  if (iguess /= 0 .and. iguess /= 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  if (iguess == 1) then
    stat = int(fricreg_hb_continue_level(fricreg_handle_to_ptr(h), omega, l0, l1, &
                                         int(nq, c_size_t), q0))
  else
    stat = int(fricreg_hb_continue_level(fricreg_handle_to_ptr(h), omega, l0, l1, &
                                         int(nq, c_size_t)))
  end if
end subroutine frhbgl

!> FRHBNP(H, NP, STAT): the number of points NP of the last continuation (0 if none).
subroutine frhbnp(h, np, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: np, stat
  np = int(fricreg_hb_points(fricreg_handle_to_ptr(h)))
  stat = int(FRICREG_OK)
end subroutine frhbnp

!> FRHBPT(H, K, OMEGA, NDOF, RMS, STAT): point K (1 <= K <= NP) of the last continuation, its
!> frequency OMEGA and the RMS of each dof, RMS(NDOF).
subroutine frhbpt(h, k, omega, ndof, rms, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: k, ndof
  double precision, intent(inout) :: omega, rms(*)
  integer, intent(out) :: stat
  if (k < 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_hb_point(fricreg_handle_to_ptr(h), int(k - 1, c_size_t), omega, &
                              int(ndof, c_size_t), rms))
end subroutine frhbpt

!> FRHBPL(H, K, LEVEL, STAT): the excitation level LEVEL of point K (1 <= K <= NP): a level
!> branch's parameter, 1 on a frequency branch.
subroutine frhbpl(h, k, level, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: k
  double precision, intent(inout) :: level
  integer, intent(out) :: stat
  if (k < 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_hb_point_level(fricreg_handle_to_ptr(h), int(k - 1, c_size_t), level))
end subroutine frhbpl

!> FRHBPX(H, K, NDOF, NC, X, STAT): the displacements' coefficients X(NC, NDOF) of point K
!> (1 <= K <= NP), recomputed from its unknowns, or with K = 0 of the last solution (as FRHBXD).
subroutine frhbpx(h, k, ndof, nc, x, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: k, ndof, nc
  double precision, intent(inout) :: x(*)
  integer, intent(out) :: stat
  integer(c_size_t) :: idx
  if (k < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  idx = -1_c_size_t ! FRICREG_HB_SOLUTION, (size_t)-1
  if (k > 0) idx = int(k - 1, c_size_t)
  stat = int(fricreg_hb_point_displacement(fricreg_handle_to_ptr(h), idx, int(ndof, c_size_t), &
                                           int(nc, c_size_t), x))
end subroutine frhbpx

!> FRHBPK(H, IDOF, OMEGA, RMS, STAT): the largest RMS of dof IDOF (1 <= IDOF <= NDOF) along
!> the last continuation's branch, located between its points, and its frequency OMEGA.
subroutine frhbpk(h, idof, omega, rms, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: idof
  double precision, intent(inout) :: omega, rms
  integer, intent(out) :: stat
  if (idof < 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_hb_peak(fricreg_handle_to_ptr(h), int(idof - 1, c_size_t), omega, rms))
end subroutine frhbpk

!> FRHBSB(H, K, ISTAB, MUMAX, STAT): the stability of point K (1 <= K <= NP), or with K = 0 of
!> the last solution: ISTAB 1 stable, 0 not, and the largest |Floquet multiplier| MUMAX.
subroutine frhbsb(h, k, istab, mumax, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: k
  integer, intent(inout) :: istab
  double precision, intent(inout) :: mumax
  integer, intent(out) :: stat
  integer(c_int) :: flag
  integer(c_size_t) :: idx
  if (k < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  idx = -1_c_size_t
  if (k > 0) idx = int(k - 1, c_size_t)
  flag = 0
  stat = int(fricreg_hb_point_stability(fricreg_handle_to_ptr(h), idx, flag, mumax))
  if (stat == FRICREG_OK) istab = int(flag)
end subroutine frhbsb

!> FRHBEX(H, K, NEXP, EXPS, STAT): the Floquet exponents EXPS(2, NEXP), (Re, Im) in rad/s, of
!> point K (from 1; 0 the last solution); NEXP must be 2 NDOF.
subroutine frhbex(h, k, nexp, exps, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: k, nexp
  double precision, intent(inout) :: exps(*)
  integer, intent(out) :: stat
  integer(c_size_t) :: idx
  if (k < 0 .or. nexp < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  idx = -1_c_size_t ! FRICREG_HB_SOLUTION, (size_t)-1
  if (k > 0) idx = int(k - 1, c_size_t)
  stat = int(fricreg_hb_point_exponents(fricreg_handle_to_ptr(h), idx, int(nexp, c_size_t), exps))
end subroutine frhbex

!> FRHBBN(H, NB, STAT): the number of bifurcations the last continuation located.
subroutine frhbbn(h, nb, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: nb, stat
  nb = int(fricreg_hb_bifurcations(fricreg_handle_to_ptr(h)))
  stat = int(FRICREG_OK)
end subroutine frhbbn

!> FRHBBF(H, I, ITYPE, OMEGA, K, NDOF, RMS, STAT): bifurcation I (1 <= I <= NB): its type ITYPE
!> (FRICREG_HB_TP, _BP, _PD, _NS), frequency OMEGA, the point K (from 1) it follows, RMS(NDOF).
subroutine frhbbf(h, i, itype, omega, k, ndof, rms, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: i, ndof
  integer, intent(inout) :: itype, k
  double precision, intent(inout) :: omega, rms(*)
  integer, intent(out) :: stat
  integer(c_int) :: t
  integer(c_size_t) :: kp
  if (i < 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  t = 0
  kp = 0
  stat = int(fricreg_hb_bifurcation(fricreg_handle_to_ptr(h), int(i - 1, c_size_t), t, omega, &
                                    kp, int(ndof, c_size_t), rms))
  if (stat == FRICREG_OK) then
    itype = int(t)
    k = int(kp) + 1
  end if
end subroutine frhbbf

!> FRHBBL(H, I, LEVEL, STAT): the excitation level LEVEL of bifurcation I (1 <= I <= NB), 1 on
!> a frequency branch.
subroutine frhbbl(h, i, level, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: i
  double precision, intent(inout) :: level
  integer, intent(out) :: stat
  if (i < 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_hb_bifurcation_level(fricreg_handle_to_ptr(h), int(i - 1, c_size_t), &
                                          level))
end subroutine frhbbl

!> FRHBNM(H, MODE, IDAMP, A0, A1, NP, STAT): the backbone of mode MODE (1 <= MODE <= NDOF, by
!> increasing linearized frequency) at NP modal amplitudes from A0 to A1; IDAMP one of
!> FRICREG_HB_NMA_DAMPING_MATRIX or _MODAL (fricreg_hb_nma).
subroutine frhbnm(h, mode, idamp, a0, a1, np, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: mode, idamp, np
  double precision, intent(in) :: a0, a1
  integer, intent(out) :: stat
  if (mode < 1 .or. np < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_hb_nma(fricreg_handle_to_ptr(h), int(mode - 1, c_size_t), int(idamp, c_int), &
                            a0, a1, int(np, c_size_t)))
end subroutine frhbnm

!> FRHBNN(H, NP, STAT): the number of points NP of the last backbone.
subroutine frhbnn(h, np, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: np, stat
  np = int(fricreg_hb_nma_points(fricreg_handle_to_ptr(h)))
  stat = int(FRICREG_OK)
end subroutine frhbnn

!> FRHBNQ(H, I, A, OMEGA, ZETA, NDOF, NC, X, STAT): point I (from 1) of the last backbone: its
!> modal amplitude A, natural frequency OMEGA, damping ratio ZETA and the displacements'
!> coefficients X(NC, NDOF), NC = 2 NH + 1 (fricreg_hb_nma_point).
subroutine frhbnq(h, i, a, omega, zeta, ndof, nc, x, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: i, ndof, nc
  double precision, intent(inout) :: a, omega, zeta
  double precision, intent(inout) :: x(*)
  integer, intent(out) :: stat
  if (i < 1 .or. ndof < 0 .or. nc < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_hb_nma_point(fricreg_handle_to_ptr(h), int(i - 1, c_size_t), a, omega, zeta, &
                                  int(ndof, c_size_t), int(nc, c_size_t), x))
end subroutine frhbnq

!> FRHBNC(H, MODE, IDAMP, A0, A1, NP, STAT): the backbone of mode MODE (from 1) from A0 to A1
!> by pseudo-arclength continuation, through its folds in the amplitude, NP points stored at
!> equal arclength; IDAMP as FRHBNM's (fricreg_hb_nma_continue).
subroutine frhbnc(h, mode, idamp, a0, a1, np, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: mode, idamp, np
  double precision, intent(in) :: a0, a1
  integer, intent(out) :: stat
  if (mode < 1 .or. np < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_hb_nma_continue(fricreg_handle_to_ptr(h), int(mode - 1, c_size_t), &
                                     int(idamp, c_int), a0, a1, int(np, c_size_t)))
end subroutine frhbnc

!> FRHBGM(H, METHOD, STAT): the method that computes the next solution's stability,
!> FRICREG_HB_STABILITY_HILL, _MONODROMY or _CONDENSED (fricreg_hb_get_stability_method).
!> Since 1.8.
subroutine frhbgm(h, method, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(inout) :: method
  integer, intent(out) :: stat
  integer(c_int) :: m
  m = 0
  stat = int(fricreg_hb_get_stability_method(fricreg_handle_to_ptr(h), m))
  if (stat == FRICREG_OK) method = int(m)
end subroutine frhbgm

!> The C monitor of FRHBMS: calls the caller's MONITR, whose address user holds, with copies
!> of the arguments. Not for callers: FRHBMS installs it.
function fricreg_f77_hb_monitor_relay(user, iterations, parameter, residual) &
    bind(C, name='fricreg_f77_hb_monitor_relay') result(stop_solve)
  use fricreg_c
  use, intrinsic :: iso_c_binding, only: c_null_funptr, c_f_procpointer
  implicit none
  type(c_ptr), value :: user
  integer(c_int64_t), value :: iterations
  real(c_double), value :: parameter, residual
  integer(c_int) :: stop_solve
  interface
    integer function monitr(iters, param, resid)
      import :: c_int64_t
      integer(c_int64_t) :: iters
      double precision :: param, resid
    end function monitr
  end interface
  procedure(monitr), pointer :: caller
  integer(c_int64_t) :: iters
  double precision :: param, resid
  call c_f_procpointer(transfer(user, c_null_funptr), caller)
  iters = iterations ! copies: an F77 function may write to its arguments
  param = parameter
  resid = residual
  stop_solve = 0
  if (caller(iters, param, resid) /= 0) stop_solve = 1
end function fricreg_f77_hb_monitor_relay

!> FRHBMS(H, MONITR, STAT): install the caller's EXTERNAL MONITR (the file's comment), called
!> before every Newton step of every solve; a second call replaces it.
subroutine frhbms(h, monitr, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  interface
    integer function monitr(iters, param, resid)
      import :: c_int64_t
      integer(c_int64_t) :: iters
      double precision :: param, resid
    end function monitr
  end interface
  integer, intent(out) :: stat
  procedure(fricreg_hb_monitor), bind(C, name='fricreg_f77_hb_monitor_relay') :: relay
  stat = int(fricreg_hb_set_monitor(fricreg_handle_to_ptr(h), c_funloc(relay), &
                                    transfer(c_funloc(monitr), c_null_ptr)))
end subroutine frhbms

!> FRHBMU(H, STAT): remove the monitor (an F77 code cannot pass a null EXTERNAL).
subroutine frhbmu(h, stat)
  use fricreg_c
  use fricreg_sim_c
  use, intrinsic :: iso_c_binding, only: c_null_funptr
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: stat
  stat = int(fricreg_hb_set_monitor(fricreg_handle_to_ptr(h), c_null_funptr, c_null_ptr))
end subroutine frhbmu

!> FRHBMI(H, MAXIT, STAT): bound the Newton steps of one solving call at INTEGER*8 MAXIT (0: no
!> bound, the default); a call that needs more returns FRICREG_EWORK. FRICREG_EINVAL if
!> MAXIT < 0.
subroutine frhbmi(h, maxit, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h, maxit
  integer, intent(out) :: stat
  stat = int(fricreg_hb_set_max_iterations(fricreg_handle_to_ptr(h), maxit))
end subroutine frhbmi

!> FRHBER(H, CODE, MSG, STAT): code and message of the driver's last failure.
subroutine frhber(h, code, msg, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: code
  character(len=*), intent(out) :: msg
  integer, intent(out) :: stat
  integer(c_int) :: last
  stat = fricreg_f77_last_error(h, fricreg_hb_errcode, fricreg_hb_errmsg, last, msg)
  code = last
end subroutine frhber

!> FRHBNE(H, I, NH, FRAC, STAT): the share FRAC(J + 1) of harmonic J = 0..H in the kinetic
!> energy of point I (from 1) of the last backbone, NH = H + 1 (FRAC(1) = 0), adding up to 1
!> (fricreg_hb_nma_harmonic_energy).
subroutine frhbne(h, i, nh, frac, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: i, nh
  double precision, intent(inout) :: frac(*)
  integer, intent(out) :: stat
  if (i < 1 .or. nh < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_hb_nma_harmonic_energy(fricreg_handle_to_ptr(h), int(i - 1, c_size_t), &
                                            int(nh, c_size_t), frac))
end subroutine frhbne

!> FRHBNR(H, I, IHARM, NM, FRAC, STAT): the share FRAC(R) of the stuck structure's mode R
!> (from 1, NM = NDOF of them) in harmonic IHARM (0..H; 0 the mean) of point I (from 1) of the
!> last backbone, adding up to 1; dense models, sparse ones up to 256 dofs
!> (fricreg_hb_nma_modal_participation).
subroutine frhbnr(h, i, iharm, nm, frac, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: i, iharm, nm
  double precision, intent(inout) :: frac(*)
  integer, intent(out) :: stat
  if (i < 1 .or. nm < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_hb_nma_modal_participation(fricreg_handle_to_ptr(h), int(i - 1, c_size_t), &
                                                int(iharm, c_int), int(nm, c_size_t), frac))
end subroutine frhbnr

!> FRHBNS(H, NS, STAT): the number NS of special points of the last backbone, its folds and
!> crossings in one list (fricreg_hb_nma_special_points). Since 1.8.
subroutine frhbns(h, ns, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: ns, stat
  ns = int(fricreg_hb_nma_special_points(fricreg_handle_to_ptr(h)))
  stat = int(FRICREG_OK)
end subroutine frhbns

!> FRHBNK(H, I, ITYPE, A, OMEGA, ZETA, K, MODE, STAT): special point I (from 1) of the last
!> backbone, in the branch's order: ITYPE FRICREG_HB_NMA_FOLD (the amplitude turns; K = 1, MODE
!> the backbone's) or FRICREG_HB_NMA_CROSSING (harmonic K OMEGA crosses the frequency of the
!> linear mode MODE, from 1), the modal amplitude A, the backbone's OMEGA and damping ratio ZETA
!> there (fricreg_hb_nma_special_point). Since 1.8.
subroutine frhbnk(h, i, itype, a, omega, zeta, k, mode, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: i
  integer, intent(inout) :: itype, k, mode
  double precision, intent(inout) :: a, omega, zeta
  integer, intent(out) :: stat
  integer(c_int) :: tc, kc
  integer(c_size_t) :: rc
  if (i < 1) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_hb_nma_special_point(fricreg_handle_to_ptr(h), int(i - 1, c_size_t), tc, a, &
                                          omega, zeta, kc, rc))
  if (stat == FRICREG_OK) then
    itype = int(tc)
    k = int(kc)
    mode = int(rc) + 1
  end if
end subroutine frhbnk
