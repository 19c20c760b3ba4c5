! SPDX-License-Identifier: GPL-3.0-or-later
! fricreg_structure_f77.f90 — module-free entry points for Fortran 77 callers: the linear
! structure with friction contacts (fricreg_structure.h), M u'' + C u' + K u = p(t) - M r a_g(t)
! + J^T f, stepped by Newmark, HHT-alpha or central difference. Built only with the drivers
! (FRICREG_DRIVERS), like fricreg_sim_f77.f90, whose conventions it shares with
! fricreg_f77.f90: external subroutines, every argument by reference, INTEGER*8 handle H (0:
! none), INTEGER STAT last (the C status, FRICREG_OK = 0; nothing stops the program), DOUBLE
! PRECISION reals, nothing changed on failure. NDOF and M are checked by the C library against
! the structure (FRICREG_ESIZE) before any array is read, but for the dense rows that are
! transposed here first (FRSTJF's J, FRSTJK's, FRSTJ2's, FRSTIW's, FRSTLO's and FRSTIL's JE and JN): those
! are read as (M, NDOF), (ME, NDOF) or (2 ME, NDOF) as given, so they must have those dimensions.
!
! Matrices. The model is sparse inside; a legacy code hands over the compressed sparse columns
! (CSC) it holds, one-based, as they are: INTEGER*8 COLPTR(NCOL + 1), the column pointers
! (COLPTR(1) = 1, never decreasing), INTEGER*8 ROWIND(NNZ), the row indices, DOUBLE PRECISION
! VALUES(NNZ), NNZ = COLPTR(NCOL + 1) - 1 entries read from each of the last two. FLAGS are the
! FRICREG_SPARSE_* constants, added: FRICREG_SPARSE_ONE_BASED for Fortran's indices (0 for
! zero-based arrays), plus FRICREG_SPARSE_LOWER (or _UPPER) when only one triangle of a
! symmetric M, K or C is stored. Compressed arrays have no leading dimension or storage order,
! so no row-/column-major question arises, and CSR needs no entry point for M, K and C: the
! CSR arrays of a symmetric matrix are its CSC arrays (swap _UPPER and _LOWER). The dense
! setters take M, K, C as (NDOF, NDOF) arrays, symmetric, so Fortran's order is C's; J as
! Fortran's J(M, NDOF), which FRSTJF transposes into C's row order in a scratch copy.
!
!   call                                         C function (fricreg_structure_*)
!   FRSTCR(NDOF, M, H, STAT)                     _create
!   FRSTFR(H, STAT)                              _free, then H = 0 (H = 0 does nothing)
!   FRSTMC(H, NDOF, FLAGS, COLPTR, ROWIND, VALUES, STAT)   _set_mass_csc
!   FRSTKC(H, NDOF, FLAGS, COLPTR, ROWIND, VALUES, STAT)   _set_stiffness_csc
!   FRSTCC(H, NDOF, FLAGS, COLPTR, ROWIND, VALUES, STAT)   _set_damping_csc
!   FRSTJC(H, M, NDOF, FLAGS, COLPTR, ROWIND, VALUES, STAT) _set_contacts_csc (J's columns)
!   FRSTJR(H, M, NDOF, FLAGS, ROWPTR, COLIND, VALUES, STAT) _set_contacts_csr (J's rows)
!   FRSTMF(H, NDOF, A, STAT), FRSTKF, FRSTCF     _set_mass, _set_stiffness, _set_damping
!   FRSTJF(H, M, NDOF, J, STAT)                  _set_contacts (given J transposed)
!   FRSTMX(H, WHICH, NROWS, NCOLS, FORMAT, PTR, IND, VALUES, STAT)
!                                                _set_matrix (a dense J as JT(NDOF, M))
!   FRSTCA(H, A0, A1, STAT)                      _set_rayleigh: C = A0 M + A1 K
!   FRSTBD(H, M, MUN, STAT)                      _set_bounds
!   FRSTLW(H, LAW, EPS, STAT)                    _set_law
!   FRSTIV(H, NDOF, R, STAT)                     _set_influence
!   FRSTAG(H, T0, DTREC, N, AG, STAT)            _set_ground_accel
!   FRSTLD(H, NDOF, P, T0, DTREC, N, G, STAT)    _set_load
!   FRSTU0(H, NDOF, U0, V0, STAT)                _set_initial
!   FRSTNM(H, BETA, GAMMA, STAT)                 _set_newmark
!   FRSTHH(H, ALPHA, STAT)                       _set_hht
!   FRSTCD(H, STAT)                              _set_central_difference
!   FRSTNT(H, TOL, MAXIT, STAT)                  _set_newton
!   FRSTSP(H, DT, STAT)                          _step
!   FRSTTE(H, DT, TEND, STAT)                    _run
!   FRSTGS(H, NDOF, U, V, A, STAT)               _get_state
!   FRSTGF(H, M, F, STAT), FRSTGD(H, M, D, STAT) _get_forces, _get_dissipation
!   FRSTGV(H, WHICH, VALUE, STAT)                _get_value (FRICREG_SVALUE_*)
!   FRSTGT(H, WHICH, VALUE, STAT)                _get_stat (FRICREG_SSTAT_*, INTEGER*8 VALUE)
!   FRSTJK(H, ME, NDOF, JE, KT, MUN, STAT)       _set_jenkins (given JE transposed)
!   FRSTIW(H, ME, NDOF, JE, NS, K, PHI, STAT)    _set_iwan (JE transposed, K(NS, ME))
!   FRSTLO(H, ME, NDOF, JE, JN, KT, MU, N0, KN, STAT)   _set_jenkins_normal (JE, JN transposed)
!   FRSTIL(H, ME, NDOF, JE, JN, NS, K, MU, N0, KN, STAT)   _set_iwan_normal (K, MU (NS, ME))
!   FRSTJ2(H, ME, NDOF, JE, KT, MUN, STAT)       _set_jenkins_2d (JE(2 ME, NDOF) transposed)
!   FRSTL2(H, ME, NDOF, JE, JN, KT, MU, N0, KN, STAT)   _set_jenkins_2d_normal (3-D contact)
!   FRSTJS(H, ME, F, W, D, STAT)                 _get_jenkins_state
!   FRSTS2(H, ME, F, W, D, STAT)                 _get_jenkins_2d_state (F(2, ME), W(2, ME))
!   FRSTIS(H, ME, NS, F, W, D, STAT)             _get_iwan_state (W(NS, ME))
!   FRSTNF(H, ME, N, STAT)                       _get_normal_forces
!   FRSTEE(H, ON, STAT)                          _set_error_estimate (ON 1, 2 or 0)
!   FRSTPK(H, NDOF, PEAK, STAT)                  _get_peak_displacement
!   FRSTPE(H, NDOF, ERR, STAT)                   _get_peak_displacement_error
!   FRSTDE(H, M, ERR, STAT)                      _get_dissipation_error
!   FRSTJE(H, ME, ERR, STAT)                     _get_jenkins_dissipation_error
!   FRSTEK(H, QUANT, N, KINDS, STAT)             _get_error_kind
!   FRSTAR(H, RTOL, STAT)                        _set_answer_rtol
!   FRSTEC(H, WHICH, STAT)                       _set_error_companions (0 finer, 1 coarser, 2 auto)
!   FRSTCS(H, SOLVER, STAT)                      _set_contact_solver
!   FRSTCG(H, SOLVER, STAT)                      _get_contact_solver
!   FRSTAE(H, ITYPE, NS, ME, NDOF, J, PARAMS, STAT)   _add_elements (J(ME IDIM, NDOF)
!                                                transposed, PARAMS(NPAR, ME); ITYPE as FRELEV's)
!   FRSTXE(H, STAT)                              _clear_elements
!   FRSTNE(H, ME, STAT)                          _element_count
!   FRSTGE(H, ME, F, STATE, D, STAT)             _get_elements
!   FRSTOD(H, INTEG, DT, RTOL, ATOL, TEND, STAT) _run_ode (ATOL = -1: tolerances from eps)
!   FRSTOT(H, N, ATOL, STAT)                     _set_ode_abs_tolerances (N = 0 removes them)
!   FRSTOG(H, N, ATOL, STAT)                     _get_ode_abs_tolerances
!   FRSTER(H, CODE, MSG, STAT)                   _errcode, _errmsg
!   FRCSTP(H, M, ZS, ZP, AP, W, WEFF, C, TOL, MAXIT, FLAGS, F, ITERS, CONV, STAT)
!                                                fricreg_ctx_solve_step, on a context H of
!                                                FRCTXC (the user's own Newmark)
!   FRCSTR(H, M, ZS, ZP, AP, SFLAGS, WP, WI, WV, EP, EI, EV, C, TOL, MAXIT, FLAGS, F, ITERS,
!          CONV, STAT)                           fricreg_ctx_solve_step_csr (FRCSTC: _csc)
!   FRCSTM(H, M, ZS, ZP, AP, FORMAT, WP, WI, WV, EP, EI, EV, C, TOL, MAXIT, FLAGS, F, ITERS,
!          CONV, STAT)                           fricreg_ctx_solve_step_matrix (any storage)
! The getters (FRSTG*, FRSTJS, FRSTS2, FRSTIS, FRSTNF, FRSTPK, FRSTPE, FRSTDE, FRSTJE,
! FRSTEK, FRSTOG, FRSTCG, FRSTNE, FRSTGE) read a const structure: C records no failure of theirs, so FRSTER still shows the
! failure before (their STAT is the answer). So do the few refusals made here, before C is
! called, of counts that would wrap into size_t: FRSTCR's NDOF or M below 1 (there is no
! structure yet to record it), FRSTAG's and FRSTLD's N below 0, FRSTIW's, FRSTIL's and
! FRSTIS's NS below 0, FRSTJ2's ME above 2**25 (C's limit 2 ME <= 2**26; FRICREG_EINVAL).
!
! Generated, not here: the entry points that are one C call (FRSTMC, FRSTKC, FRSTCC, FRSTJC,
! FRSTJR, FRSTMX, FRSTMF, FRSTKF, FRSTCF, FRSTCA, FRSTBD, FRSTLW, FRSTIV, FRSTU0, FRSTNM, FRSTHH,
! FRSTCD, FRSTNT, FRSTSP, FRSTTE, FRSTGS, FRSTGF, FRSTGD, FRSTGV, FRSTEE, FRSTPK, FRSTPE,
! FRSTDE, FRSTJE, FRSTAR, FRSTEC, FRSTCS, FRSTXE, FRSTGE, FRSTOD, FRSTOG, FRSTGT, FRSTJS,
! FRSTS2, FRSTNF) are a line each, with their doc comments, in the table
! fricreg_structure_f77.txt, which fortran/gen_f77.cmake turns into
! fricreg_structure_f77_generated.f90 at build time. Those below have logic of their own: a
! handle made or released, a refused count, J transposed into a scratch copy, the message, C's
! ints copied into the caller's INTEGER (FRSTEK, FRSTCG, FRSTNE), an element type from its code
! (FRSTAE).

!> FRSTCR(NDOF, M, H, STAT): create a structure of NDOF >= 1 degrees of freedom and M >= 1
!> contacts into H, with C's defaults (M = I, C = K = 0, J unset, law (4), eps = 1e-3,
!> average-acceleration Newmark).
subroutine frstcr(ndof, m, h, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer, intent(in) :: ndof, m
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  type(c_ptr) :: p
  if (ndof < 1 .or. m < 1) then ! a negative count must not reach size_t as a huge one
    stat = int(FRICREG_EINVAL)
    return
  end if
  p = c_null_ptr
  stat = fricreg_f77_created(fricreg_structure_create(int(ndof, c_size_t), int(m, c_size_t), &
                                                      p), p, h)
end subroutine frstcr

!> FRSTFR(H, STAT): release the structure H and set H = 0; H = 0 does nothing.
subroutine frstfr(h, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(inout) :: h
  integer, intent(out) :: stat
  stat = fricreg_f77_release(h, fricreg_structure_free)
end subroutine frstfr

!> FRSTJF(H, M, NDOF, J, STAT): dense contact matrix J(M, NDOF) in Fortran's order,
!> J(I, K) = d zdot_I / d u'_K. J is not symmetric and C reads it row-major, so it is
!> transposed into a scratch copy of M*NDOF values here (FRICREG_ENOMEM if that fails).
subroutine frstjf(h, m, ndof, j, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m, ndof
  double precision, intent(in) :: j(max(m, 0), *)
  integer, intent(out) :: stat
  double precision, allocatable :: jt(:, :)
  integer :: mm, nn, alloc
  ! Sizes that cannot be the structure's copy nothing: C answers FRICREG_ESIZE or ENULL.
  mm = max(m, 0)
  nn = max(ndof, 0)
  allocate (jt(nn, mm), stat=alloc)
  if (alloc /= 0) then
    stat = int(FRICREG_ENOMEM)
    return
  end if
  if (mm > 0 .and. nn > 0) jt = transpose(j(1:mm, 1:nn))
  stat = int(fricreg_structure_set_contacts(fricreg_handle_to_ptr(h), int(m, c_size_t), &
                                            int(ndof, c_size_t), jt))
end subroutine frstjf

!> FRSTAG(H, T0, DTREC, N, AG, STAT): ground acceleration record AG(N), N >= 2, AG(K) at
!> T0 + (K - 1) DTREC, linear between samples and zero outside; N = 0 removes it (AG not read).
subroutine frstag(h, t0, dtrec, n, ag, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  double precision, intent(in) :: t0, dtrec, ag(*)
  integer, intent(in) :: n
  integer, intent(out) :: stat
  if (n < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_structure_set_ground_accel(fricreg_handle_to_ptr(h), t0, dtrec, &
                                                int(n, c_size_t), ag))
end subroutine frstag

!> FRSTLD(H, NDOF, P, T0, DTREC, N, G, STAT): external load P(NDOF) g(t), g the record G(N)
!> at T0 + (K - 1) DTREC as in FRSTAG, or g = 1 at all times with N = 0 (G not read).
subroutine frstld(h, ndof, p, t0, dtrec, n, g, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: ndof, n
  double precision, intent(in) :: p(*), t0, dtrec, g(*)
  integer, intent(out) :: stat
  if (n < 0) then
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_structure_set_load(fricreg_handle_to_ptr(h), int(ndof, c_size_t), p, t0, &
                                        dtrec, int(n, c_size_t), g))
end subroutine frstld

!> FRSTOT(H, N, ATOL, STAT): absolute tolerances ATOL(N) per component of FRSTOD's state
!> (U(NDOF), V(NDOF), the input work, the viscous and each contact's dissipation: N = 2 NDOF +
!> 2 + M), each finite and > 0, used by every later adaptive FRSTOD in place of its ATOL; N = 0
!> removes them (ATOL is then not read). C's fricreg_structure_set_ode_abs_tolerances.
subroutine frstot(h, n, atol, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: n
  double precision, intent(in) :: atol(*)
  integer, intent(out) :: stat
  if (n < 0) then
    stat = FRICREG_ESIZE
    return
  end if
  stat = int(fricreg_structure_set_ode_abs_tolerances(fricreg_handle_to_ptr(h), &
                                                      int(n, c_size_t), atol))
end subroutine frstot

!> FRSTER(H, CODE, MSG, STAT): status CODE and message MSG of the structure's last failed call
!> (FRICREG_OK and blanks if none; 'NULL structure' for H = 0); MSG blank-padded or truncated.
subroutine frster(h, code, msg, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(out) :: code
  character(len=*), intent(out) :: msg
  integer, intent(out) :: stat
  integer(c_int) :: last
  stat = fricreg_f77_last_error(h, fricreg_structure_errcode, fricreg_structure_errmsg, last, &
                                msg)
  code = last
end subroutine frster

!> FRSTJK(H, ME, NDOF, JE, KT, MUN, STAT): ME Jenkins elements (C's
!> fricreg_structure_set_jenkins) on the rows of JE(ME, NDOF) in Fortran's order: element I
!> sees Q_I = sum over K of JE(I, K) U(K) and its force FE_I = KT(I) (Q_I - W_I),
!> |FE_I| <= MUN(I), acting on the structure as -JE^T FE. KT(ME) > 0, MUN(ME) >= 0; ME = 0
!> removes them. Every contact's bound must be 0 beside them. JE is transposed into a scratch
!> copy of ME*NDOF values (FRICREG_ENOMEM if that fails). Replaces the elements in force.
subroutine frstjk(h, me, ndof, je, kt, mun, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: me, ndof
  double precision, intent(in) :: je(max(me, 0), *), kt(*), mun(*)
  integer, intent(out) :: stat
  double precision, allocatable :: jt(:, :)
  integer :: mm, nn, alloc
  ! Sizes that cannot be the structure's copy nothing: C answers FRICREG_ESIZE or EINVAL.
  mm = max(me, 0)
  nn = max(ndof, 0)
  allocate (jt(nn, mm), stat=alloc)
  if (alloc /= 0) then
    stat = int(FRICREG_ENOMEM)
    return
  end if
  if (mm > 0 .and. nn > 0) jt = transpose(je(1:mm, 1:nn))
  stat = int(fricreg_structure_set_jenkins(fricreg_handle_to_ptr(h), int(me, c_size_t), &
                                           int(ndof, c_size_t), jt, kt, mun))
end subroutine frstjk

!> FRSTIW(H, ME, NDOF, JE, NS, K, PHI, STAT): ME Iwan elements instead (C's
!> fricreg_structure_set_iwan), JE(ME, NDOF) as FRSTJK's, element I's NS sliders the
!> stiffnesses K(1:NS, I) > 0 and slip forces PHI(1:NS, I) >= 0 (C's row-major K[ME NS], the
!> same numbers); its force the sum of its sliders'. FRSTJK is the case NS = 1; NS below 0 is
!> FRICREG_EINVAL here.
subroutine frstiw(h, me, ndof, je, ns, k, phi, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: me, ndof, ns
  double precision, intent(in) :: je(max(me, 0), *), k(*), phi(*)
  integer, intent(out) :: stat
  double precision, allocatable :: jt(:, :)
  integer :: mm, nn, alloc
  mm = max(me, 0)
  nn = max(ndof, 0)
  if (ns < 0) then ! would wrap into size_t
    stat = int(FRICREG_EINVAL)
    return
  end if
  allocate (jt(nn, mm), stat=alloc)
  if (alloc /= 0) then
    stat = int(FRICREG_ENOMEM)
    return
  end if
  if (mm > 0 .and. nn > 0) jt = transpose(je(1:mm, 1:nn))
  stat = int(fricreg_structure_set_iwan(fricreg_handle_to_ptr(h), int(me, c_size_t), &
                                        int(ndof, c_size_t), jt, int(ns, c_size_t), k, phi))
end subroutine frstiw

!> FRSTLO(H, ME, NDOF, JE, JN, KT, MU, N0, KN, STAT): ME Jenkins elements with a normal load
!> and lift-off instead (C's fricreg_structure_set_jenkins_normal): tangential rows JE(ME, NDOF)
!> and normal rows JN(ME, NDOF), both as FRSTJK's JE; G_I = (JN U)_I positive closing, the
!> normal force N_I = MAX(0, N0(I) + KN(I) G_I), the bound MU(I) N_I; both forces act on the
!> structure (-JE^T FE - JN^T N). KT(ME) > 0, MU(ME) >= 0, N0(ME) finite, KN(ME) > 0.
subroutine frstlo(h, me, ndof, je, jn, kt, mu, n0, kn, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: me, ndof
  double precision, intent(in) :: je(max(me, 0), *), jn(max(me, 0), *), kt(*), mu(*), n0(*), &
                                  kn(*)
  integer, intent(out) :: stat
  double precision, allocatable :: ct(:, :), cn(:, :)
  integer :: mm, nn
  mm = max(me, 0)
  nn = max(ndof, 0)
  stat = int(fricreg_f77_transposed_rows(je(1:mm, 1:nn), jn(1:mm, 1:nn), ct, cn))
  if (stat /= FRICREG_OK) return
  stat = int(fricreg_structure_set_jenkins_normal(fricreg_handle_to_ptr(h), int(me, c_size_t), &
                                                  int(ndof, c_size_t), ct, cn, kt, mu, n0, kn))
end subroutine frstlo

!> FRSTIL(H, ME, NDOF, JE, JN, NS, K, MU, N0, KN, STAT): ME Iwan elements with a normal load and
!> lift-off instead (C's fricreg_structure_set_iwan_normal): JE(ME, NDOF), JN(ME, NDOF) as
!> FRSTLO's, element I's NS sliders the stiffnesses K(1:NS, I) > 0 bounded by MU(1:NS, I) N_I
!> (MU >= 0; C's row-major K[ME NS], the same numbers), N_I = MAX(0, N0(I) + KN(I) G_I) with
!> KN(ME) > 0. FRSTLO is the case NS = 1; NS below 0 is FRICREG_EINVAL here.
subroutine frstil(h, me, ndof, je, jn, ns, k, mu, n0, kn, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: me, ndof, ns
  double precision, intent(in) :: je(max(me, 0), *), jn(max(me, 0), *), k(*), mu(*), n0(*), &
                                  kn(*)
  integer, intent(out) :: stat
  double precision, allocatable :: ct(:, :), cn(:, :)
  integer :: mm, nn
  mm = max(me, 0)
  nn = max(ndof, 0)
  if (ns < 0) then ! would wrap into size_t
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_f77_transposed_rows(je(1:mm, 1:nn), jn(1:mm, 1:nn), ct, cn))
  if (stat /= FRICREG_OK) return
  stat = int(fricreg_structure_set_iwan_normal(fricreg_handle_to_ptr(h), int(me, c_size_t), &
                                               int(ndof, c_size_t), ct, cn, int(ns, c_size_t), &
                                               k, mu, n0, kn))
end subroutine frstil

!> FRSTJ2(H, ME, NDOF, JE, KT, MUN, STAT): ME 2-D Jenkins elements instead (C's
!> fricreg_structure_set_jenkins_2d): element I on rows 2I - 1 (x) and 2I (y) of JE(2 ME, NDOF)
!> in Fortran's order, Q_I = (JE U) on those two rows, its force FE_I = KT(I) (Q_I - W_I) with
!> |FE_I| <= MUN(I) (an isotropic slider, radial return), acting on the structure as -JE^T FE.
!> KT(ME) > 0, MUN(ME) >= 0; ME = 0 removes them; ME above 2**25 is FRICREG_EINVAL here. JE is
!> transposed into a scratch copy of 2 ME NDOF values (FRICREG_ENOMEM if that fails). Motion on
!> one axis is FRSTJK's element on that row. Replaces the elements in force.
subroutine frstj2(h, me, ndof, je, kt, mun, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: me, ndof
  double precision, intent(in) :: je(2 * min(max(me, 0), 2**25), *), kt(*), mun(*)
  integer, intent(out) :: stat
  double precision, allocatable :: jt(:, :)
  integer :: mr, nn, alloc
  if (me > 2**25) then ! 2 ME would pass C's limit (and may wrap a default INTEGER)
    stat = int(FRICREG_EINVAL)
    return
  end if
  mr = 2 * max(me, 0)
  nn = max(ndof, 0)
  allocate (jt(nn, mr), stat=alloc)
  if (alloc /= 0) then
    stat = int(FRICREG_ENOMEM)
    return
  end if
  if (mr > 0 .and. nn > 0) jt = transpose(je(1:mr, 1:nn))
  stat = int(fricreg_structure_set_jenkins_2d(fricreg_handle_to_ptr(h), int(me, c_size_t), &
                                              int(ndof, c_size_t), jt, kt, mun))
end subroutine frstj2

!> FRSTL2(H, ME, NDOF, JE, JN, KT, MU, N0, KN, STAT): ME 3-D contact elements instead, 2-D
!> Jenkins elements with a normal load and lift-off (C's fricreg_structure_set_jenkins_2d_normal):
!> element I's tangential rows 2I - 1 (x) and 2I (y) of JE(2 ME, NDOF) as FRSTJ2's, its normal
!> row I of JN(ME, NDOF) as FRSTLO's; N_I = MAX(0, N0(I) + KN(I) G_I), G_I = (JN U)_I positive
!> closing, |FE_I| <= MU(I) N_I (radial return; separated: FE_I = 0 and the slider follows).
!> KT(ME) > 0, MU(ME) >= 0, N0(ME) finite, KN(ME) > 0; ME above 2**25 is FRICREG_EINVAL here.
!> FRSTS2 reads FE, W, D and FRSTNF the normal forces. Since 1.7.
subroutine frstl2(h, me, ndof, je, jn, kt, mu, n0, kn, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: me, ndof
  double precision, intent(in) :: je(2 * min(max(me, 0), 2**25), *), jn(max(me, 0), *), kt(*), &
                                  mu(*), n0(*), kn(*)
  integer, intent(out) :: stat
  double precision, allocatable :: ct(:, :), cn(:, :)
  integer :: mm, nn
  if (me > 2**25) then ! 2 ME would pass C's limit (and may wrap a default INTEGER)
    stat = int(FRICREG_EINVAL)
    return
  end if
  mm = max(me, 0)
  nn = max(ndof, 0)
  stat = int(fricreg_f77_transposed_rows(je(1:2 * mm, 1:nn), jn(1:mm, 1:nn), ct, cn))
  if (stat /= FRICREG_OK) return
  stat = int(fricreg_structure_set_jenkins_2d_normal(fricreg_handle_to_ptr(h), &
                                                     int(me, c_size_t), int(ndof, c_size_t), &
                                                     ct, cn, kt, mu, n0, kn))
end subroutine frstl2

!> FRSTIS(H, ME, NS, F, W, D, STAT): the elements' forces F(ME), committed sliders W(NS, ME)
!> (element I's slider S at W(S, I)) and dissipation D(ME) (C's
!> fricreg_structure_get_iwan_state; Jenkins elements with NS = 1). FRICREG_ESIZE if ME or NS
!> is not the elements'.
subroutine frstis(h, me, ns, f, w, d, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: me, ns
  double precision, intent(inout) :: f(*), w(*), d(*)
  integer, intent(out) :: stat
  if (ns < 0) then ! would wrap into size_t
    stat = int(FRICREG_EINVAL)
    return
  end if
  stat = int(fricreg_structure_get_iwan_state(fricreg_handle_to_ptr(h), &
                                              int(max(me, 0), c_size_t), int(ns, c_size_t), f, &
                                              w, d))
end subroutine frstis

!> FRSTEK(H, QUANT, N, KINDS, STAT): the kind KINDS(N) of each error estimate of QUANT
!> (FRICREG_EST_PEAK_DISPLACEMENT: N = NDOF; FRICREG_EST_DISSIPATION: N = M;
!> FRICREG_EST_ELEMENT_DISSIPATION: N = the joint elements set), each
!> FRICREG_EST_KIND_ASYMPTOTIC, _BOUND or _ASSUMED, parallel to FRSTPE's, FRSTDE's and FRSTJE's
!> ERR (C's fricreg_structure_get_error_kind; C's ints copied into the caller's INTEGER, of any
!> size). FRICREG_EINVAL for an unknown QUANT or without an estimate; FRICREG_ESIZE if N is not
!> QUANT's length; KINDS written only on success. Since 1.8.
subroutine frstek(h, quant, n, kinds, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: quant, n
  integer, intent(inout) :: kinds(*)
  integer, intent(out) :: stat
  integer(c_int), allocatable :: tmp(:)
  integer :: astat
  allocate (tmp(max(n, 1)), stat=astat)
  if (astat /= 0) then
    stat = int(FRICREG_ENOMEM)
    return
  end if
  ! an ILP64 caller's QUANT beyond an int is clamped (refused by C); a negative N reaches C as
  ! 0, a size it refuses, not as a huge one
  stat = int(fricreg_structure_get_error_kind(fricreg_handle_to_ptr(h), &
             int(min(max(quant, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), &
             int(max(n, 0), c_size_t), tmp))
  if (stat == FRICREG_OK .and. n > 0) kinds(1:n) = int(tmp(1:n))
end subroutine frstek

!> FRSTCG(H, SOLVER, STAT): the near-stick block's solver of the next step,
!> FRICREG_CONTACT_SOLVER_DENSE or _SPARSE (fricreg_structure_get_contact_solver). Since 1.8.
subroutine frstcg(h, solver, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(inout) :: solver
  integer, intent(out) :: stat
  integer(c_int) :: k
  k = 0
  stat = int(fricreg_structure_get_contact_solver(fricreg_handle_to_ptr(h), k))
  if (stat == FRICREG_OK) solver = int(k)
end subroutine frstcg

!> FRSTAE(H, ITYPE, NS, ME, NDOF, J, PARAMS, STAT): ME elements of the type of code ITYPE with
!> NS sliders (FRELEV's codes: 1 jenkins ... 10 spring; NS 1 but for the Iwan types) beside
!> those the structure holds, of any types (C's fricreg_structure_add_elements): element I's
!> IDIM components (FRELSZ; tangential, then the normal one) on rows (I - 1) IDIM + 1 ..
!> I IDIM of J(ME IDIM, NDOF), its parameters PARAMS(1:NPAR, I) in the type's layout. Every
!> element, the held ones too, starts again at rest. FRICREG_EINVAL for a code or NS of no
!> type, or ME below 0 (nothing changed); C's codes. Since 1.8.
subroutine frstae(h, itype, ns, me, ndof, j, params, stat)
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
  stat = int(fricreg_structure_add_elements(fricreg_handle_to_ptr(h), t, int(me, c_size_t), &
                                            int(ndof, c_size_t), jt, params))
end subroutine frstae

!> FRSTNE(H, ME, STAT): ME, the number of elements the structure holds, of all types (C's
!> fricreg_structure_element_count). Since 1.8.
subroutine frstne(h, me, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(inout) :: me
  integer, intent(out) :: stat
  me = int(fricreg_structure_element_count(fricreg_handle_to_ptr(h)))
  stat = int(FRICREG_OK)
end subroutine frstne

!> FRCSTP(H, M, ZS, ZP, AP, W, WEFF, C, TOL, MAXIT, FLAGS, F, ITERS, CONV, STAT): the forces of
!> one implicit step of the caller's own integrator on a context H (FRCTXC), C's
!> fricreg_ctx_solve_step (fricreg_structure.h, docs/structural.md "Your own Newmark with
!> fricreg"): F(M) in: the guess, out: the step's forces solving F = law(ZP + C WEFF F,
!> AP - (W - WEFF) F); ZS(M) the velocities at the step's start; W(M, M) = J M^-1 J^T and
!> WEFF(M, M) = J K_eff^-1 J^T, symmetric (Fortran's order is C's); C = gamma dt; TOL > 0 in
!> force units; MAXIT >= 1; FLAGS 0 or FRICREG_STEP_PLAIN. ITERS the Newton iterations, CONV 1
!> if converged, else 0 (STAT FRICREG_OK all the same). F, ITERS and CONV written only on
!> success.
subroutine frcstp(h, m, zs, zp, ap, w, weff, c, tol, maxit, flags, f, iters, conv, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h
  integer, intent(in) :: m, maxit, flags
  double precision, intent(in) :: zs(*), zp(*), ap(*), w(*), weff(*), c, tol
  double precision, intent(inout) :: f(*)
  integer, intent(inout) :: iters, conv
  integer, intent(out) :: stat
  integer(c_int) :: info(2)
  ! C takes ints: an ILP64 caller's count beyond their range is clamped, so that C refuses it.
  stat = int(fricreg_ctx_solve_step(fricreg_handle_to_ptr(h), int(max(m, 0), c_size_t), zs, zp, &
             ap, w, weff, c, tol, &
             int(min(max(maxit, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), &
             int(min(max(flags, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), f, info))
  if (stat /= FRICREG_OK) return
  iters = int(info(1))
  conv = int(info(2))
end subroutine frcstp

!> FRCSTR(H, M, ZS, ZP, AP, SFLAGS, WP, WI, WV, EP, EI, EV, C, TOL, MAXIT, FLAGS, F, ITERS, CONV,
!> STAT): FRCSTP with W and WEFF in compressed sparse rows (fricreg_ctx_solve_step_csr): INTEGER*8
!> WP(M + 1), WI(NNZ), WV(NNZ) for W and EP(M + 1), EI(NNZ_EFF), EV(NNZ_EFF) for WEFF; SFLAGS
!> the FRICREG_SPARSE_* constants for both (FRICREG_SPARSE_ONE_BASED for Fortran's indices).
!> The same forces as FRCSTP on the same matrices, O(NNZ) a call. The rest as FRCSTP.
subroutine frcstr(h, m, zs, zp, ap, sflags, wp, wi, wv, ep, ei, ev, c, tol, maxit, flags, f, &
                  iters, conv, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h, wp(*), wi(*), ep(*), ei(*)
  integer, intent(in) :: m, sflags, maxit, flags
  double precision, intent(in) :: zs(*), zp(*), ap(*), wv(*), ev(*), c, tol
  double precision, intent(inout) :: f(*)
  integer, intent(inout) :: iters, conv
  integer, intent(out) :: stat
  integer(c_int) :: info(2)
  stat = int(fricreg_ctx_solve_step_csr(fricreg_handle_to_ptr(h), int(max(m, 0), c_size_t), zs, &
             zp, ap, int(min(max(sflags, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), &
             wp, wi, wv, ep, ei, ev, c, tol, &
             int(min(max(maxit, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), &
             int(min(max(flags, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), f, info))
  if (stat /= FRICREG_OK) return
  iters = int(info(1))
  conv = int(info(2))
end subroutine frcstr

!> FRCSTC(H, M, ZS, ZP, AP, SFLAGS, WP, WI, WV, EP, EI, EV, C, TOL, MAXIT, FLAGS, F, ITERS, CONV,
!> STAT): FRCSTR in compressed sparse columns, what Fortran codes hold: one-based INTEGER*8
!> column pointers WP, EP and row indices WI, EI with SFLAGS = FRICREG_SPARSE_ONE_BASED
!> (fricreg_ctx_solve_step_csc; W and WEFF being symmetric, the same arrays as by rows).
subroutine frcstc(h, m, zs, zp, ap, sflags, wp, wi, wv, ep, ei, ev, c, tol, maxit, flags, f, &
                  iters, conv, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h, wp(*), wi(*), ep(*), ei(*)
  integer, intent(in) :: m, sflags, maxit, flags
  double precision, intent(in) :: zs(*), zp(*), ap(*), wv(*), ev(*), c, tol
  double precision, intent(inout) :: f(*)
  integer, intent(inout) :: iters, conv
  integer, intent(out) :: stat
  integer(c_int) :: info(2)
  stat = int(fricreg_ctx_solve_step_csc(fricreg_handle_to_ptr(h), int(max(m, 0), c_size_t), zs, &
             zp, ap, int(min(max(sflags, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), &
             wp, wi, wv, ep, ei, ev, c, tol, &
             int(min(max(maxit, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), &
             int(min(max(flags, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), f, info))
  if (stat /= FRICREG_OK) return
  iters = int(info(1))
  conv = int(info(2))
end subroutine frcstc

!> FRCSTM(H, M, ZS, ZP, AP, FORMAT, WP, WI, WV, EP, EI, EV, C, TOL, MAXIT, FLAGS, F, ITERS, CONV,
!> STAT): FRCSTP with W and WEFF in the storage FORMAT names (fricreg_ctx_solve_step_matrix):
!> FRICREG_MATRIX_DENSE, WV(M, M) and EV(M, M) as FRCSTP's W and WEFF, WP, WI, EP, EI not read
!> (any INTEGER*8 array); or FRICREG_MATRIX_CSR or FRICREG_MATRIX_CSC plus the
!> FRICREG_SPARSE_* constants (FRICREG_SPARSE_ONE_BASED for Fortran's indices), the arrays as
!> FRCSTR's or FRCSTC's. The same forces as those on the same matrices; FRICREG_EINVAL for a
!> format both CSR and CSC, or dense with a sparse flag. The rest as FRCSTP.
subroutine frcstm(h, m, zs, zp, ap, format, wp, wi, wv, ep, ei, ev, c, tol, maxit, flags, f, &
                  iters, conv, stat)
  use fricreg_c
  use fricreg_sim_c
  implicit none
  integer(c_int64_t), intent(in) :: h, wp(*), wi(*), ep(*), ei(*)
  integer, intent(in) :: m, format, maxit, flags
  double precision, intent(in) :: zs(*), zp(*), ap(*), wv(*), ev(*), c, tol
  double precision, intent(inout) :: f(*)
  integer, intent(inout) :: iters, conv
  integer, intent(out) :: stat
  integer(c_int) :: info(2)
  stat = int(fricreg_ctx_solve_step_matrix(fricreg_handle_to_ptr(h), int(max(m, 0), c_size_t), &
             zs, zp, ap, int(min(max(format, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), &
             wp, wi, wv, ep, ei, ev, c, tol, &
             int(min(max(maxit, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), &
             int(min(max(flags, -int(huge(0_c_int))), int(huge(0_c_int))), c_int), f, info))
  if (stat /= FRICREG_OK) return
  iters = int(info(1))
  conv = int(info(2))
end subroutine frcstm
