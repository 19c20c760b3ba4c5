C     SPDX-License-Identifier: GPL-3.0-or-later
C     DRIVE_FRIC.F -- CALLS THE FRIC TEMPLATE (FRIC.F) AS ABAQUS/STANDARD
C     DOES: STATEV AT THE START OF EACH INCREMENT, DGAM THE INCREMENT OF
C     A HISTORY U(T), THE CONTACT PRESSURE PRESS, AND AFTER A CUT-BACK
C     THE SAME INCREMENT AGAIN FROM THE OLD STATEV. CHECKS:
C     - A JENKINS SLIDER (CODES 1 AND 7, NFDIR = 1) UNDER U = A SIN T AT
C       A CONSTANT PRESSURE P, 400 INCREMENTS A CYCLE: THE SUM OF SFD
C       OVER THE SECOND CYCLE IS 4 MUN (A - MUN/KT), MUN = MU P, TO
C       1E-12 (THE CLOSED FORM OF DOCS/HOSTS.MD; THE INCREMENTS HIT THE
C       TURNS, WHERE SED = MUN**2/(2 KT) TO 1E-14);
C     - EVERY INCREMENT, CALLED AGAIN FROM THE OLD STATEV AFTER A CALL
C       WITH A TWICE LARGER INCREMENT (A CUT-BACK), GIVES THE SAME LM,
C       TAU, TANGENTS, DSLIP, SED, SFD AND STATEV, BIT FOR BIT;
C     - NFDIR = 2 (CODES 2 AND 3), IN STICK AND IN SLIP: DDTDDG AGAINST
C       CENTRAL DIFFERENCES IN DGAM, DDTDDP IN PRESS, TO 1E-7;
C     - CONTACT_3D WITH PRESS < 0 (OPEN): TAU = 0, THE SLIDER AT U;
C     - A CODE OF NO JENKINS OR CONTACT LAW, AND KT = 0: PNEWDT < 1,
C       STATEV KEPT, THE REASON PRINTED.
C     EXITS WITH STATUS 1 IF A CHECK FAILS.
      PROGRAM DFRIC
      IMPLICIT NONE
      INTEGER NFAIL, IC, K, N, I, J, LM, LM2, NOK, L
      DOUBLE PRECISION PI, AKT, AMU, P, AMP, AMUN, EXACT, DISS, ETURN
      DOUBLE PRECISION PROPS(3), SV(4), SV0(4), SV2(4), DG(2), DG2(2)
      DOUBLE PRECISION TAU(2), DTG(2,2), DTP(2), DSL(2), SED, SFD
      DOUBLE PRECISION TAU2(2), DTG2(2,2), DTP2(2), DSL2(2), SED2, SFD2
      DOUBLE PRECISION TP(2), TM(2), H, ERR, UK, UPREV, PNEW
      NFAIL = 0
      PI = 4.0D0 * DATAN(1.0D0)
      AKT = 2.385D0
      AMU = 0.3D0
      P = 2.375D0
      AMUN = AMU * P
      AMP = 1.0D0
      N = 400
      EXACT = 4.0D0 * AMUN * (AMP - AMUN / AKT)
C
C     THE CYCLE, FOR EACH LAW OF ONE DIRECTION
      DO 100 L = 1, 2
         IC = 1
         IF (L .EQ. 2) IC = 7
         PROPS(1) = IC
         PROPS(2) = AKT
         PROPS(3) = AMU
         SV(1) = 0.0D0
         SV(2) = 0.0D0
         UPREV = 0.0D0
         DISS = 0.0D0
         ETURN = -1.0D0
         NOK = 0
         DO 20 K = 1, 2 * N
            UK = AMP * SIN(2.0D0 * PI * K / N)
            DG(1) = UK - UPREV
            UPREV = UK
            SV0(1) = SV(1)
            SV0(2) = SV(2)
C           THE FIRST ATTEMPT: TWICE THE INCREMENT, CUT BACK BY THE HOST
            DG2(1) = 2.0D0 * DG(1)
            SV2(1) = SV0(1)
            SV2(2) = SV0(2)
            CALL CALLF(1, PROPS, SV2, DG2, P, LM2, TAU2, DTG2, DTP2,
     &                 DSL2, SED2, SFD2, PNEW)
C           THE INCREMENT, TWICE FROM THE OLD STATEV
            SV2(1) = SV0(1)
            SV2(2) = SV0(2)
            CALL CALLF(1, PROPS, SV2, DG, P, LM2, TAU2, DTG2, DTP2,
     &                 DSL2, SED2, SFD2, PNEW)
            CALL CALLF(1, PROPS, SV, DG, P, LM, TAU, DTG, DTP, DSL, SED,
     &                 SFD, PNEW)
            IF (LM .NE. LM2 .OR. LM .NE. 0 .OR. TAU(1) .NE. TAU2(1)
     &          .OR. DTG(1,1) .NE. DTG2(1,1) .OR. DTP(1) .NE. DTP2(1)
     &          .OR. DSL(1) .NE. DSL2(1) .OR. SED .NE. SED2 .OR.
     &          SFD .NE. SFD2 .OR. SV(1) .NE. SV2(1) .OR.
     &          SV(2) .NE. SV2(2) .OR. PNEW .NE. 1.0D0) NOK = NOK + 1
            IF (K .GT. N) DISS = DISS + SFD
            IF (K .EQ. N + N / 4) ETURN = SED
   20    CONTINUE
         WRITE (*, '(A, I0, A, 2ES25.17)') 'FRIC code ', IC,
     &      ': SFD per cycle, closed form ', DISS, EXACT
         CALL CHK(NOK .EQ. 0, 'FRIC cut-back bit for bit', NFAIL)
         CALL CHK(ABS(DISS - EXACT) .LE. 1.0D-12 * EXACT,
     &            'FRIC SFD per cycle 4 mun (A - mun/kt)', NFAIL)
         CALL CHK(ABS(ETURN - AMUN**2 / (2 * AKT)) .LE. 1.0D-14,
     &            'FRIC SED mun**2/(2 kt) at the turn', NFAIL)
  100 CONTINUE
C
C     TWO DIRECTIONS: THE TANGENTS IN STICK (J = 1) AND IN SLIP (J = 2)
      H = 1.0D-6
      DO 200 L = 1, 2
         IC = 2
         IF (L .EQ. 2) IC = 3
         PROPS(1) = IC
         PROPS(2) = 50.0D0
         PROPS(3) = 0.3D0
         P = 2.0D0
         DO 190 J = 1, 2
            SV0(1) = 0.01D0
            SV0(2) = -0.02D0
            SV0(3) = 0.012D0
            SV0(4) = -0.019D0
            DG(1) = 0.001D0
            DG(2) = 0.002D0
            IF (J .EQ. 2) DG(1) = 0.05D0
            IF (J .EQ. 2) DG(2) = 0.04D0
            DO 110 I = 1, 4
               SV(I) = SV0(I)
  110       CONTINUE
            CALL CALLF(2, PROPS, SV, DG, P, LM, TAU, DTG, DTP, DSL, SED,
     &                 SFD, PNEW)
            CALL CHK(PNEW .EQ. 1.0D0, 'FRIC 2-D call', NFAIL)
            IF (J .EQ. 1) CALL CHK(DTG(1,1) .EQ. 50.0D0 .AND.
     &         DTG(1,2) .EQ. 0.0D0 .AND. SFD .EQ. 0.0D0,
     &         'FRIC 2-D stick: kt I, no dissipation', NFAIL)
            IF (J .EQ. 2) CALL CHK(ABS(SQRT(TAU(1)**2 + TAU(2)**2)
     &         - 0.6D0) .LE. 1.0D-15, 'FRIC 2-D slides at mu p', NFAIL)
            ERR = 0.0D0
            DO 130 K = 1, 2
               DO 120 I = 1, 4
                  SV2(I) = SV0(I)
  120          CONTINUE
               DG2(1) = DG(1)
               DG2(2) = DG(2)
               DG2(K) = DG(K) + H
               CALL CALLF(2, PROPS, SV2, DG2, P, LM2, TP, DTG2, DTP2,
     &                    DSL2, SED2, SFD2, PNEW)
               DO 125 I = 1, 4
                  SV2(I) = SV0(I)
  125          CONTINUE
               DG2(K) = DG(K) - H
               CALL CALLF(2, PROPS, SV2, DG2, P, LM2, TM, DTG2, DTP2,
     &                    DSL2, SED2, SFD2, PNEW)
               DO 128 I = 1, 2
                  ERR = MAX(ERR, ABS((TP(I) - TM(I)) / (2 * H)
     &                               - DTG(I,K)))
  128          CONTINUE
  130       CONTINUE
            CALL CHK(ERR .LE. 1.0D-7, 'FRIC DDTDDG central', NFAIL)
            DO 140 I = 1, 4
               SV2(I) = SV0(I)
  140       CONTINUE
            CALL CALLF(2, PROPS, SV2, DG, P + H, LM2, TP, DTG2, DTP2,
     &                 DSL2, SED2, SFD2, PNEW)
            DO 145 I = 1, 4
               SV2(I) = SV0(I)
  145       CONTINUE
            CALL CALLF(2, PROPS, SV2, DG, P - H, LM2, TM, DTG2, DTP2,
     &                 DSL2, SED2, SFD2, PNEW)
            ERR = MAX(ABS((TP(1) - TM(1)) / (2 * H) - DTP(1)),
     &                ABS((TP(2) - TM(2)) / (2 * H) - DTP(2)))
            CALL CHK(ERR .LE. 1.0D-7, 'FRIC DDTDDP central', NFAIL)
            IF (J .EQ. 2) WRITE (*, '(A, I0, A, 2ES25.17)')
     &         'FRIC code ', IC, ': DDTDDP in slip ', DTP
  190    CONTINUE
  200 CONTINUE
C
C     CONTACT_3D OPEN: NO STRESS, THE SLIDER FOLLOWS U
      DO 210 I = 1, 4
         SV(I) = SV0(I)
  210 CONTINUE
      CALL CALLF(2, PROPS, SV, DG, -1.0D0, LM, TAU, DTG, DTP, DSL, SED,
     &           SFD, PNEW)
      CALL CHK(TAU(1) .EQ. 0.0D0 .AND. TAU(2) .EQ. 0.0D0 .AND.
     &         SV(1) .EQ. SV(3) .AND. SV(2) .EQ. SV(4),
     &         'FRIC contact_3d open', NFAIL)
C
C     A CODE THAT IS NO LAW OF FRHLAW: A CUT-BACK, STATEV UNTOUCHED
      PROPS(1) = 5
      DO 220 I = 1, 4
         SV(I) = SV0(I)
  220 CONTINUE
      CALL CALLF(2, PROPS, SV, DG, 2.0D0, LM, TAU, DTG, DTP, DSL, SED,
     &           SFD, PNEW)
      CALL CHK(PNEW .LT. 1.0D0 .AND. SV(1) .EQ. SV0(1) .AND.
     &         SV(4) .EQ. SV0(4), 'FRIC code 5: cut-back', NFAIL)
C     A PARAMETER FRICREG REFUSES (KT = 0): FRELMS'S MESSAGE, A CUT-BACK
      PROPS(1) = 2
      PROPS(2) = 0.0D0
      CALL CALLF(2, PROPS, SV, DG, 2.0D0, LM, TAU, DTG, DTP, DSL, SED,
     &           SFD, PNEW)
      CALL CHK(PNEW .LT. 1.0D0 .AND. SV(1) .EQ. SV0(1) .AND.
     &         SV(4) .EQ. SV0(4), 'FRIC kt = 0: cut-back', NFAIL)
C
      WRITE (*, '(A, I0, A)') 'drive_fric: ', NFAIL, ' failed'
      IF (NFAIL .NE. 0) CALL EXIT(1)
      END

C     CALLF -- FRIC'S DOCUMENTED CALL, WITH THE ARGUMENTS THE TEMPLATE
C     DOES NOT READ SET TO PLAUSIBLE VALUES; PNEW IS PNEWDT, SET TO 1
C     BEFORE THE CALL AS ABAQUS DOES.
      SUBROUTINE CALLF(NFDIR, PROPS, STATEV, DGAM, PRESS, LM, TAU,
     &                 DDTDDG, DDTDDP, DSLIP, SED, SFD, PNEW)
      IMPLICIT NONE
      INTEGER NFDIR, LM
      DOUBLE PRECISION PROPS(3), STATEV(*), DGAM(NFDIR), PRESS
      DOUBLE PRECISION TAU(NFDIR), DDTDDG(NFDIR,NFDIR), DDTDDP(NFDIR)
      DOUBLE PRECISION DSLIP(NFDIR), SED, SFD, PNEW
      DOUBLE PRECISION DDTDDT(2,2), TAULM(2), DPRESS, DDPDDH, SLIP(2)
      DOUBLE PRECISION TIME(2), DTIME, COORDS(3), RCOORD(3), DROT(2,2)
      DOUBLE PRECISION TEMP(2), PREDEF(2,1), CHRLNGTH
      CHARACTER*80 CINAME, SLNAME, MSNAME
      INTEGER I
      DO 10 I = 1, 2
         TAULM(I) = 0.0D0
         SLIP(I) = 0.0D0
         TEMP(I) = 20.0D0
         TIME(I) = 0.0D0
   10 CONTINUE
      DPRESS = 0.0D0
      DDPDDH = 0.0D0
      DTIME = 1.0D-2
      CHRLNGTH = 1.0D0
      CINAME = 'FRICREG'
      SLNAME = 'SECONDARY'
      MSNAME = 'MAIN'
      LM = 1
      PNEW = 1.0D0
      CALL FRIC(LM, TAU, DDTDDG, DDTDDP, DSLIP, SED, SFD, DDTDDT, PNEW,
     &   STATEV, DGAM, TAULM, PRESS, DPRESS, DDPDDH, SLIP, 1, 1, TIME,
     &   DTIME, 1, CINAME, SLNAME, MSNAME, 1, 1, 1, COORDS, RCOORD,
     &   DROT, TEMP, PREDEF, NFDIR, 3, 1, 4, CHRLNGTH, PROPS, 3)
      END
