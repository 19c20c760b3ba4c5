C     SPDX-License-Identifier: GPL-3.0-or-later
C     DRIVE_FRIC.F -- CALLS THE FRIC TEMPLATE (FRIC.F) AS ABAQUS/
C     STANDARD DOES (DOCS/HOSTS.MD, FRIC): EACH INCREMENT IS SOLVED BY
C     ITERATIONS, EVERY ONE CALLING FRIC WITH STATEV AS IT WAS AT THE
C     START OF THE INCREMENT, A TRIAL DGAM AND THE LM THE LAST ITERATION
C     SET; ONLY THE LAST ITERATION'S STATEV IS KEPT. THE REFERENCE IS
C     THE JENKINS SLIDER IN CLOSED FORM: AN INCREMENT DU MOVES THE
C     FORCE TO F = MAX(-MUN, MIN(MUN, F + KT DU)), MUN = MU P, AND A
C     CYCLE OF U = A SIN T DISSIPATES 4 MUN (A - MUN/KT). CHECKS:
C     - THE LOOP (CODES 1 AND 7, NFDIR = 1), 400 INCREMENTS A CYCLE: TAU
C       AT EVERY INCREMENT, SFD SUMMED OVER THE SECOND CYCLE, SED AT A
C       TURN = MUN**2/(2 KT); THE ITERATIONS' LAST CALL GIVES THE SAME
C       NUMBERS, BIT FOR BIT, AS ONE CALL FROM THE START OF THE
C       INCREMENT;
C     - REOPEN AND RECLOSE: THE POINT OPENS (NO CALLS) FOR AN EIGHTH OF
C       A CYCLE, THEN CLOSES WITH LM = 2 PASSED IN: THAT INCREMENT IS
C       FRICTIONLESS (LM = 2 OUT, TAU = 0) AND STATEV IS RESET, SO THAT
C       THE SLIDER STARTS AGAIN FROM REST WHERE THE POINT CLOSED: TAU
C       FOLLOWS THE CLOSED FORM FROM F = 0 THERE, AND THE LOOP TWO
C       CYCLES LATER DISSIPATES 4 MUN (A - MUN/KT) AGAIN;
C     - A ROTATED 3-D POINT (CODES 2 AND 3, NFDIR = 2): THE SURFACE AXES
C       TURN HALF A REVOLUTION A CYCLE (DROT EACH INCREMENT, DGAM GIVEN
C       IN THE TURNED AXES) WHILE THE POINT SLIDES TO AND FRO ALONG A
C       FIXED DIRECTION OF THE SURFACE: TAU TURNED BACK IS THE 1-D
C       LOOP'S FORCE, AND SFD PER CYCLE ITS CLOSED FORM; WITHOUT DROT
C       APPLIED THE SAME RUN MISSES THE CLOSED FORM BY MORE THAN 1E-3
C       (THE CHECK CAN FAIL);
C     - LONG SLIDING: 1E6 INCREMENTS ONE WAY, TAU STAYS MUN (THE STATE
C       IS THE ELASTIC STRETCH, NOT A POSITION THAT GROWS);
C     - NFDIR = 2 (CODES 2 AND 3), IN STICK AND IN SLIP: DDTDDG AGAINST
C       CENTRAL DIFFERENCES IN DGAM, DDTDDP IN PRESS, TO 1E-7;
C     - CONTACT_3D WITH PRESS < 0 (OPEN): TAU = 0, THE STRETCH RESET;
C     - A CODE OF NO JENKINS OR CONTACT LAW, AND KT = 0: PNEWDT < 1,
C       STATEV KEPT, THE REASON PRINTED.
C     THE CLOSED FORMS ARE MET TO 1E-12 (A HOST NEEDS 1E-3).
C     EXITS WITH STATUS 1 IF A CHECK FAILS.
      PROGRAM DFRIC
      IMPLICIT NONE
      INTEGER NFAIL, IC, K, N, I, J, L, LM, LM2, NBIT, NLM, KR, KO, M
      DOUBLE PRECISION PI, AKT, AMU, P, AMP, AMUN, EXACT, DISS, DISS2
      DOUBLE PRECISION ETURN, PROPS(3), SV(2), SV0(2), SV2(2), DG(2)
      DOUBLE PRECISION DG2(2), TAU(2), DTG(2,2), DTP(2), DSL(2), SED
      DOUBLE PRECISION SFD, DTG2(2,2), DTP2(2), DSL2(2), SED2, SFD2
      DOUBLE PRECISION TP(2), TM(2), H, ERR, UK, UPREV, PNEW, FJ, ERRF
      DOUBLE PRECISION EYE(2,2), ROT(2,2), DA, C, S, PX, PY, DU, TH
      DOUBLE PRECISION DNOROT
      NFAIL = 0
      PI = 4.0D0 * DATAN(1.0D0)
      AKT = 2.385D0
      AMU = 0.3D0
      P = 2.375D0
      AMUN = AMU * P
      AMP = 1.0D0
      N = 400
      EXACT = 4.0D0 * AMUN * (AMP - AMUN / AKT)
      EYE(1,1) = 1.0D0
      EYE(2,1) = 0.0D0
      EYE(1,2) = 0.0D0
      EYE(2,2) = 1.0D0
C
C     THE LOOP, THEN OPEN FROM INCREMENT KO, CLOSED AGAIN AT KR
      KO = 2 * N + 1
      KR = 2 * N + N / 8 + 1
      DO 100 L = 1, 2
         IC = 1
         IF (L .EQ. 2) IC = 7
         PROPS(1) = IC
         PROPS(2) = AKT
         PROPS(3) = AMU
         SV(1) = 0.0D0
         UPREV = 0.0D0
         FJ = 0.0D0
         DISS = 0.0D0
         DISS2 = 0.0D0
         ETURN = -1.0D0
         ERRF = 0.0D0
         NBIT = 0
         NLM = 0
         DO 20 K = 1, 5 * N
            UK = AMP * SIN(2.0D0 * PI * K / N)
            DG(1) = UK - UPREV
            UPREV = UK
C           OPEN: ABAQUS DOES NOT CALL FRIC, THE MOTION IS NOBODY'S
            IF (K .GE. KO .AND. K .LT. KR) GO TO 20
C           LM AT THE START OF AN INCREMENT: 2 IF THE POINT WAS OPEN AT
C           THE END OF THE LAST ONE, ELSE 0 (SLIPPING: WE NEVER SET 1)
            LM = 0
            IF (K .EQ. KR) LM = 2
            CALL INCR(1, PROPS, SV, LM, DG, EYE, P, TAU, DTG, DTP, DSL,
     &                SED, SFD, PNEW, NBIT)
            IF (K .EQ. KR) THEN
               FJ = 0.0D0
               IF (LM .NE. 2 .OR. TAU(1) .NE. 0.0D0 .OR. SV(1) .NE.
     &             0.0D0 .OR. SFD .NE. 0.0D0) NLM = NLM + 1
            ELSE
               FJ = MAX(-AMUN, MIN(AMUN, FJ + AKT * DG(1)))
               IF (LM .NE. 0) NLM = NLM + 1
            END IF
            IF (PNEW .NE. 1.0D0) NLM = NLM + 1
            ERRF = MAX(ERRF, ABS(TAU(1) - FJ))
            IF (K .GT. N .AND. K .LE. 2 * N) DISS = DISS + SFD
            IF (K .GT. 4 * N) DISS2 = DISS2 + SFD
            IF (K .EQ. N + N / 4) ETURN = SED
   20    CONTINUE
         WRITE (*, '(A, I0, A, 3ES25.17)') 'FRIC code ', IC,
     &      ': SFD per cycle, after reclosure, closed form ', DISS,
     &      DISS2, EXACT
         CALL CHK(NBIT .EQ. 0, 'FRIC iterations: last = one call',
     &            NFAIL)
         CALL CHK(NLM .EQ. 0, 'FRIC LM: 2 on reclosure, reset, else 0',
     &            NFAIL)
         CALL CHK(ERRF .LE. 1.0D-12 * AMUN,
     &            'FRIC TAU = closed form at every increment', NFAIL)
         CALL CHK(ABS(DISS - EXACT) .LE. 1.0D-12 * EXACT,
     &            'FRIC SFD per cycle 4 mun (A - mun/kt)', NFAIL)
         CALL CHK(ABS(DISS2 - EXACT) .LE. 1.0D-12 * EXACT,
     &            'FRIC SFD per cycle after reclosure', NFAIL)
         CALL CHK(ABS(ETURN - AMUN**2 / (2 * AKT)) .LE. 1.0D-14,
     &            'FRIC SED mun**2/(2 kt) at the turn', NFAIL)
  100 CONTINUE
C
C     A ROTATED 3-D POINT: THE AXES TURN BY DA AN INCREMENT; THE POINT
C     MOVES ALONG THE SURFACE'S FIXED DIRECTION (PX, PY), WHOSE
C     COMPONENTS IN THE AXES OF INCREMENT K ARE R(K DA) (PX, PY), R(A)
C     THE ROTATION BY A: THE CONVENTION E <- DROT E OF FRIC.F.
      PX = 0.6D0
      PY = 0.8D0
      DA = PI / N
      ROT(1,1) = COS(DA)
      ROT(2,1) = SIN(DA)
      ROT(1,2) = -SIN(DA)
      ROT(2,2) = COS(DA)
      DO 200 L = 1, 3
         IC = 2
         IF (L .EQ. 2) IC = 3
         PROPS(1) = IC
         PROPS(2) = AKT
         PROPS(3) = AMU
         SV(1) = 0.0D0
         SV(2) = 0.0D0
         UPREV = 0.0D0
         FJ = 0.0D0
         DISS = 0.0D0
         ERRF = 0.0D0
         NBIT = 0
         DO 150 K = 1, 2 * N
            UK = AMP * SIN(2.0D0 * PI * K / N)
            DU = UK - UPREV
            UPREV = UK
            TH = K * DA
            C = COS(TH)
            S = SIN(TH)
            DG(1) = DU * (C * PX - S * PY)
            DG(2) = DU * (S * PX + C * PY)
            LM = 0
C           L = 3: THE SAME RUN AS L = 1 WITH DROT NOT APPLIED
            IF (L .LE. 2) CALL INCR(2, PROPS, SV, LM, DG, ROT, P, TAU,
     &         DTG, DTP, DSL, SED, SFD, PNEW, NBIT)
            IF (L .EQ. 3) CALL INCR(2, PROPS, SV, LM, DG, EYE, P, TAU,
     &         DTG, DTP, DSL, SED, SFD, PNEW, NBIT)
            FJ = MAX(-AMUN, MIN(AMUN, FJ + AKT * DU))
            ERRF = MAX(ERRF, ABS(C * TAU(1) + S * TAU(2) - FJ * PX),
     &                 ABS(-S * TAU(1) + C * TAU(2) - FJ * PY))
            IF (K .GT. N) DISS = DISS + SFD
  150    CONTINUE
         IF (L .EQ. 3) THEN
            DNOROT = DISS
            WRITE (*, '(A, 2ES25.17)') 'FRIC without DROT: SFD per '
     &         // 'cycle, closed form ', DISS, EXACT
            CALL CHK(ABS(DISS - EXACT) .GT. 1.0D-3 * EXACT,
     &               'FRIC rotated point: DROT ignored is seen', NFAIL)
            GO TO 200
         END IF
         WRITE (*, '(A, I0, A, 2ES25.17)') 'FRIC code ', IC,
     &      ': turning axes, SFD per cycle, closed form ', DISS, EXACT
         CALL CHK(NBIT .EQ. 0, 'FRIC 3-D iterations: last = one call',
     &            NFAIL)
         CALL CHK(ERRF .LE. 1.0D-12 * AMUN,
     &            'FRIC turning axes: TAU turned back = 1-D loop',
     &            NFAIL)
         CALL CHK(ABS(DISS - EXACT) .LE. 1.0D-12 * EXACT,
     &            'FRIC turning axes: SFD per cycle', NFAIL)
  200 CONTINUE
C
C     LONG SLIDING: 1E6 INCREMENTS OF 0.01 ONE WAY (U GROWS TO 1E4)
      PROPS(1) = 1
      PROPS(2) = AKT
      PROPS(3) = AMU
      SV(1) = 0.0D0
      DG(1) = 1.0D-2
      ERRF = 0.0D0
      DO 250 K = 1, 1000000
         LM = 0
         CALL CALLF(1, PROPS, SV, DG, P, LM, EYE, TAU, DTG, DTP, DSL,
     &              SED, SFD, PNEW)
  250 CONTINUE
      WRITE (*, '(A, 2ES25.17)') 'FRIC after 1e6 increments: TAU, mun ',
     &   TAU(1), AMUN
      CALL CHK(ABS(TAU(1) - AMUN) .LE. 1.0D-12 * AMUN .AND.
     &         ABS(SFD - AMUN * DG(1)) .LE. 1.0D-12 * AMUN * DG(1),
     &         'FRIC long sliding: TAU = mun, SFD = mun DGAM', NFAIL)
C
C     TWO DIRECTIONS: THE TANGENTS IN STICK (J = 1) AND IN SLIP (J = 2)
      H = 1.0D-6
      DO 300 L = 1, 2
         IC = 2
         IF (L .EQ. 2) IC = 3
         PROPS(1) = IC
         PROPS(2) = 50.0D0
         PROPS(3) = 0.3D0
         P = 2.0D0
         DO 290 J = 1, 2
C           THE STRETCH (0.002, 0.001): A FORCE OF (0.1, 0.05), STICKING
            SV0(1) = 0.002D0
            SV0(2) = 0.001D0
            DG(1) = 0.001D0
            DG(2) = 0.002D0
            IF (J .EQ. 2) DG(1) = 0.05D0
            IF (J .EQ. 2) DG(2) = 0.04D0
            SV(1) = SV0(1)
            SV(2) = SV0(2)
            LM = 0
            CALL CALLF(2, PROPS, SV, DG, P, LM, EYE, TAU, DTG, DTP, DSL,
     &                 SED, SFD, PNEW)
            CALL CHK(PNEW .EQ. 1.0D0, 'FRIC 2-D call', NFAIL)
            IF (J .EQ. 1) CALL CHK(DTG(1,1) .EQ. 50.0D0 .AND.
     &         DTG(1,2) .EQ. 0.0D0 .AND. SFD .EQ. 0.0D0,
     &         'FRIC 2-D stick: kt I, no dissipation', NFAIL)
            IF (J .EQ. 2) CALL CHK(ABS(SQRT(TAU(1)**2 + TAU(2)**2)
     &         - 0.6D0) .LE. 1.0D-15, 'FRIC 2-D slides at mu p', NFAIL)
            ERR = 0.0D0
            DO 230 K = 1, 2
               DO 225 M = -1, 1, 2
                  SV2(1) = SV0(1)
                  SV2(2) = SV0(2)
                  DG2(1) = DG(1)
                  DG2(2) = DG(2)
                  DG2(K) = DG(K) + M * H
                  LM2 = 0
                  IF (M .EQ. 1) CALL CALLF(2, PROPS, SV2, DG2, P, LM2,
     &               EYE, TP, DTG2, DTP2, DSL2, SED2, SFD2, PNEW)
                  IF (M .EQ. -1) CALL CALLF(2, PROPS, SV2, DG2, P, LM2,
     &               EYE, TM, DTG2, DTP2, DSL2, SED2, SFD2, PNEW)
  225          CONTINUE
               DO 228 I = 1, 2
                  ERR = MAX(ERR, ABS((TP(I) - TM(I)) / (2 * H)
     &                               - DTG(I,K)))
  228          CONTINUE
  230       CONTINUE
            CALL CHK(ERR .LE. 1.0D-7, 'FRIC DDTDDG central', NFAIL)
            DO 240 M = -1, 1, 2
               SV2(1) = SV0(1)
               SV2(2) = SV0(2)
               LM2 = 0
               IF (M .EQ. 1) CALL CALLF(2, PROPS, SV2, DG, P + H, LM2,
     &            EYE, TP, DTG2, DTP2, DSL2, SED2, SFD2, PNEW)
               IF (M .EQ. -1) CALL CALLF(2, PROPS, SV2, DG, P - H, LM2,
     &            EYE, TM, DTG2, DTP2, DSL2, SED2, SFD2, PNEW)
  240       CONTINUE
            ERR = MAX(ABS((TP(1) - TM(1)) / (2 * H) - DTP(1)),
     &                ABS((TP(2) - TM(2)) / (2 * H) - DTP(2)))
            CALL CHK(ERR .LE. 1.0D-7, 'FRIC DDTDDP central', NFAIL)
            IF (J .EQ. 2) WRITE (*, '(A, I0, A, 2ES25.17)')
     &         'FRIC code ', IC, ': DDTDDP in slip ', DTP
  290    CONTINUE
  300 CONTINUE
C
C     CONTACT_3D OPEN: NO STRESS, THE STRETCH GONE
      SV(1) = SV0(1)
      SV(2) = SV0(2)
      LM = 0
      CALL CALLF(2, PROPS, SV, DG, -1.0D0, LM, EYE, TAU, DTG, DTP, DSL,
     &           SED, SFD, PNEW)
      CALL CHK(TAU(1) .EQ. 0.0D0 .AND. TAU(2) .EQ. 0.0D0 .AND.
     &         SV(1) .EQ. 0.0D0 .AND. SV(2) .EQ. 0.0D0,
     &         'FRIC contact_3d open', NFAIL)
C
C     A CODE THAT IS NO LAW OF FRHLAW: A CUT-BACK, STATEV UNTOUCHED
      PROPS(1) = 5
      SV(1) = SV0(1)
      SV(2) = SV0(2)
      LM = 0
      CALL CALLF(2, PROPS, SV, DG, 2.0D0, LM, EYE, TAU, DTG, DTP, DSL,
     &           SED, SFD, PNEW)
      CALL CHK(PNEW .LT. 1.0D0 .AND. SV(1) .EQ. SV0(1) .AND.
     &         SV(2) .EQ. SV0(2), 'FRIC code 5: cut-back', NFAIL)
C     A PARAMETER FRICREG REFUSES (KT = 0): FRELMS'S MESSAGE, A CUT-BACK
      PROPS(1) = 2
      PROPS(2) = 0.0D0
      CALL CALLF(2, PROPS, SV, DG, 2.0D0, LM, EYE, TAU, DTG, DTP, DSL,
     &           SED, SFD, PNEW)
      CALL CHK(PNEW .LT. 1.0D0 .AND. SV(1) .EQ. SV0(1) .AND.
     &         SV(2) .EQ. SV0(2), 'FRIC kt = 0: cut-back', NFAIL)
C
      WRITE (*, '(A, I0, A)') 'drive_fric: ', NFAIL, ' failed'
      IF (NFAIL .NE. 0) CALL EXIT(1)
      END

C     INCR -- ONE INCREMENT AS ABAQUS/STANDARD SOLVES IT: THREE
C     ITERATIONS WITH THE TRIAL MOTIONS 1.5 DG, 0.75 DG AND DG (THE LAST
C     CONVERGES), EACH FROM STATEV AS IT WAS AT THE START AND WITH THE
C     LM THE ITERATION BEFORE SET; THE LAST ITERATION'S STATEV IS KEPT.
C     NBIT COUNTS A DIFFERENCE, IN ANY OUTPUT, BETWEEN THAT LAST CALL
C     AND ONE CALL FROM THE START (NOTHING A TRIAL CALL DID MAY REMAIN).
      SUBROUTINE INCR(NFDIR, PROPS, SV, LM, DG, DROT, P, TAU, DTG, DTP,
     &                DSL, SED, SFD, PNEW, NBIT)
      IMPLICIT NONE
      INTEGER NFDIR, LM, NBIT
      DOUBLE PRECISION PROPS(3), SV(2), DG(2), DROT(2,2), P, TAU(2)
      DOUBLE PRECISION DTG(2,2), DTP(2), DSL(2), SED, SFD, PNEW
      DOUBLE PRECISION SV0(2), SVD(2), DGT(2), FAC(3)
      DOUBLE PRECISION TAUD(2), DTGD(2,2), DTPD(2), DSLD(2), SEDD, SFDD
      DOUBLE PRECISION TT(2), TTG(2,2), TTP(2), TSL(2), PNEWD
      INTEGER LM0, LMD, IT, I, J
      DATA FAC /1.5D0, 0.75D0, 1.0D0/
      LM0 = LM
      DO 30 IT = 1, 3
         DO 10 I = 1, NFDIR
            SV0(I) = SV(I)
            DGT(I) = FAC(IT) * DG(I)
   10    CONTINUE
         CALL CALLF(NFDIR, PROPS, SV0, DGT, P, LM, DROT, TT, TTG, TTP,
     &              TSL, SED, SFD, PNEW)
         IF (IT .EQ. 3) THEN
            DO 20 I = 1, NFDIR
               TAU(I) = TT(I)
               DTP(I) = TTP(I)
               DSL(I) = TSL(I)
               DO 15 J = 1, NFDIR
                  DTG(I,J) = TTG(I,J)
   15          CONTINUE
   20       CONTINUE
         END IF
   30 CONTINUE
      DO 40 I = 1, NFDIR
         SVD(I) = SV(I)
   40 CONTINUE
      LMD = LM0
      CALL CALLF(NFDIR, PROPS, SVD, DG, P, LMD, DROT, TAUD, DTGD, DTPD,
     &           DSLD, SEDD, SFDD, PNEWD)
      IF (LMD .NE. LM .OR. SEDD .NE. SED .OR. SFDD .NE. SFD .OR.
     &    PNEWD .NE. PNEW) NBIT = NBIT + 1
      DO 60 I = 1, NFDIR
         IF (TAUD(I) .NE. TAU(I) .OR. DTPD(I) .NE. DTP(I) .OR.
     &       DSLD(I) .NE. DSL(I) .OR. SVD(I) .NE. SV0(I))
     &      NBIT = NBIT + 1
         DO 50 J = 1, NFDIR
            IF (DTGD(I,J) .NE. DTG(I,J)) NBIT = NBIT + 1
   50    CONTINUE
   60 CONTINUE
C     CONVERGED: THE HOST KEEPS THE LAST ITERATION'S STATEV
      DO 70 I = 1, NFDIR
         SV(I) = SV0(I)
   70 CONTINUE
      END

C     CALLF -- FRIC'S DOCUMENTED CALL, WITH THE ARGUMENTS THE TEMPLATE
C     DOES NOT READ SET TO PLAUSIBLE VALUES; LM IN AND OUT, DROT THE
C     INCREMENT'S ROTATION OF THE SURFACE AXES; PNEW IS PNEWDT, SET TO 1
C     BEFORE THE CALL AS ABAQUS DOES.
      SUBROUTINE CALLF(NFDIR, PROPS, STATEV, DGAM, PRESS, LM, DROT,
     &                 TAU, DDTDDG, DDTDDP, DSLIP, SED, SFD, PNEW)
      IMPLICIT NONE
      INTEGER NFDIR, LM
      DOUBLE PRECISION PROPS(3), STATEV(*), DGAM(NFDIR), PRESS
      DOUBLE PRECISION DROT(2,2), TAU(NFDIR), DDTDDG(NFDIR,NFDIR)
      DOUBLE PRECISION DDTDDP(NFDIR), DSLIP(NFDIR), SED, SFD, PNEW
      DOUBLE PRECISION DDTDDT(2,2), TAULM(2), DPRESS, DDPDDH, SLIP(2)
      DOUBLE PRECISION TIME(2), DTIME, COORDS(3), RCOORD(3)
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
      PNEW = 1.0D0
      CALL FRIC(LM, TAU, DDTDDG, DDTDDP, DSLIP, SED, SFD, DDTDDT, PNEW,
     &   STATEV, DGAM, TAULM, PRESS, DPRESS, DDPDDH, SLIP, 1, 1, TIME,
     &   DTIME, 1, CINAME, SLNAME, MSNAME, 1, 1, 1, COORDS, RCOORD,
     &   DROT, TEMP, PREDEF, NFDIR, 3, 1, 2, CHRLNGTH, PROPS, 3)
      END
