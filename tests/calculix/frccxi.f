! SPDX-License-Identifier: GPL-3.0-or-later
! frccxi.f: the Iwan hook of fricreg's CalculiX tier (fricreg's own
! code, not ccx's). ccx-iwan.patch calls FRCCXI from ccx's four
! penalty-friction routines in place of FRELEV's jenkins_3d; build.sh
! compiles it into the private patched-iwan ccx only (README.md here).
!
! FRCCXI(XK, B, NSTAT, SOLD, T, F, DFDU, DFDB, SNEW, SE, VE, IST):
! fricreg's iwan_3d (FRELEV code 9) with NS sliders at ccx's contact
! point, NS = 5, slider s (1..NS) of stiffness and bound
!     k_s = XK / NS,   phi_s = c_s B,   c_s = 2 s / (NS (NS + 1))
! (sum k_s = XK, ccx's stick slope times the slave area; sum c_s = 1:
! macroslip at ccx's Coulomb bound B = mu |F_n|, set at every call),
! so slider s starts to slip at a stretch of 2 s / (NS + 1) times
! B / XK: 1/3 .. 5/3 of it, the microslip between.
!   XK, B    in: ccx's xk and dfshear (1d300 for its elastic
!            predictor, ielas = 1: every slider sticks)
!   NSTAT    in: ccx's nstate_, at least 9 + 3 NS = 24 (*DEPVAR)
!   SOLD     in: the point's state at the start of the increment,
!            xstateini(1:NSTAT): slider s at SOLD(10+3(s-1):12+3(s-1))
!   T        in: ccx's relative tangential displacement t (3 global
!            components in the contact plane)
!   F        out: the tangential force, sum_s f_s
!   DFDU     out: dF/dt (3, 3), the consistent tangent
!   DFDB     out: dF/dB = sum_s c_s dF/dphi_s (the sliding sliders'
!            directions times c_s; 0 in stick)
!   SNEW     out: xstate(1:NSTAT): the sliders in 10 .. 9 + 3 NS and,
!            in ccx's slots 1..3 (its slip vector t_p, k (t - t_p) its
!            force), t - F / XK: the Iwan's equivalent slip
!   SE, VE   out: sum_s k_s |t - w_s'|**2 (ccx's elastic energy form)
!            and sum_s phi_s |w_s' - w_s| (dissipated in the increment)
!   IST      out: FRICREG_OK, or FRELEV's status (message printed)
      SUBROUTINE FRCCXI(XK, B, NSTAT, SOLD, T, F, DFDU, DFDB, SNEW,
     &                  SE, VE, IST)
      IMPLICIT NONE
      INCLUDE 'fricreg.fi'
      INTEGER NS
      PARAMETER (NS = 5)
      INTEGER NSTAT, IST, I, S
      DOUBLE PRECISION XK, B, SOLD(NSTAT), T(3), F(3), DFDU(3, 3)
      DOUBLE PRECISION DFDB(3), SNEW(NSTAT), SE, VE
      DOUBLE PRECISION P(2 * NS), W(3 * NS), WN(3 * NS), DP(3, 2 * NS)
      DOUBLE PRECISION C, D
      CHARACTER*200 MSG
      IF (NSTAT .LT. 9 + 3 * NS) THEN
         WRITE(*, *) '*ERROR in FRCCXI: fricreg''s Iwan hook keeps ',
     &        3 * NS, ' sliders'' numbers past ccx''s 9: *DEPVAR ',
     &        9 + 3 * NS, ' in the deck (has ', NSTAT, ')'
         IST = FRICREG_EINVAL
         RETURN
      END IF
      DO S = 1, NS
         P(S) = XK / NS
         P(NS + S) = B * (2.0D0 * S / (NS * (NS + 1)))
      END DO
      DO I = 1, 3 * NS
         W(I) = SOLD(9 + I)
      END DO
      CALL FRELEV(FRICREG_ELEMENT_IWAN_3D, NS, P, W, T, F, DFDU, DP,
     &            WN, IST)
      IF (IST .NE. FRICREG_OK) THEN
         CALL FRELMS(FRICREG_ELEMENT_IWAN_3D, NS, P, W, T, MSG, IST)
         WRITE(*, *) '*ERROR in FRCCXI: fricreg: ', TRIM(MSG)
         RETURN
      END IF
      SE = 0.0D0
      VE = 0.0D0
      DO I = 1, 3
         DFDB(I) = 0.0D0
      END DO
      DO S = 1, NS
         C = 2.0D0 * S / (NS * (NS + 1))
         DO I = 1, 3
            DFDB(I) = DFDB(I) + C * DP(I, NS + S)
         END DO
         D = 0.0D0
         DO I = 3 * S - 2, 3 * S
            SE = SE + P(S) * (T(I - 3 * S + 3) - WN(I))**2
            D = D + (WN(I) - W(I))**2
         END DO
         VE = VE + P(NS + S) * SQRT(D)
      END DO
      DO I = 1, 3
         SNEW(I) = T(I) - F(I) / XK
      END DO
      DO I = 1, 3 * NS
         SNEW(9 + I) = WN(I)
      END DO
      END
