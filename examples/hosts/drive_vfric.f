C     SPDX-License-Identifier: GPL-3.0-or-later
C     DRIVE_VFRIC.F -- CALLS THE VFRIC TEMPLATE (VFRIC.F) AS
C     ABAQUS/EXPLICIT DOES (DOCS/HOSTS.MD, VFRIC): ONCE AN INCREMENT, NO
C     ITERATIONS, FOR THE POINTS IN CONTACT ONLY, EACH WITH ITS
C     INCREMENTAL SLIP DSLIPFRIC, ITS SLIP DIRECTION DIRCOSSL (T1), THE
C     NORMAL DIRCOSN AND THE NORMAL FORCE FNORMAL, THE STATE IN THE
C     COLUMN OF ITS SURFACE NODE JCONSECID, KINC COUNTING THE
C     INCREMENTS. BUILT TWICE: DRIVE_VFRIC WITH A DOUBLE PRECISION
C     VABA_PARAM.INC, DRIVE_VFRIC_SP WITH A SINGLE PRECISION ONE
C     (ABAQUS/EXPLICIT'S DEFAULT): THE HOST'S ARRAYS ARE THEN REAL*4.
C     THE REFERENCE IS THE JENKINS SLIDER IN CLOSED FORM: AN INCREMENT
C     DU MOVES THE FORCE TO F = MAX(-MUN, MIN(MUN, F + KT DU)), MUN = MU
C     FNORMAL, AND A CYCLE OF U = A SIN T DISSIPATES 4 MUN (A - MUN/KT).
C     CHECKS (TO 1E-12 IN DOUBLE PRECISION; IN SINGLE TO 1E-5, WHERE
C     5E-7 WAS MEASURED; A HOST NEEDS 1E-3):
C     - TWO POINTS (NODES 2 AND 1: THE COLUMNS ARE THE NODES', NOT THE
C       POINTS') SLIDING TO AND FRO ALONG E, 400 INCREMENTS A CYCLE,
C       EACH UNDER ITS OWN NORMAL FORCE: FTANGENTIAL(1) = -F SIGN(DU) AT
C       EVERY INCREMENT, FTANGENTIAL(2) = 0; THE WORK KEPT IN STATEV
C       GROWS BY THE CLOSED FORM OVER THE SECOND CYCLE; THE STORED
C       ENERGY AT A TURN IS MUN**2/(2 KT). IN 2-D (JENKINS_2D), IN 3-D
C       IN THE PLANE Z = 0 (JENKINS_3D), AND A ROTATED 3-D POINT: THE
C       CONTACT PLANE TURNS HALF A REVOLUTION A CYCLE ABOUT AN AXIS IN
C       ITSELF, THE SLIP ALONG ITS TURNING DIRECTION;
C     - REOPEN AND RECLOSE: THE FIRST POINT LEAVES THE CALL FOR AN
C       EIGHTH OF A CYCLE; WHEN IT IS BACK ITS STRETCH IS FORGOTTEN, SO
C       THE CLOSED FORM STARTS AGAIN FROM F = 0, AND THE LOOP TWO CYCLES
C       LATER DISSIPATES THE CLOSED FORM AGAIN;
C     - EACH INCREMENT, CALLED AGAIN FROM THE OLD STATEV AFTER A CALL
C       WITH ANOTHER SLIP, GIVES THE SAME FORCES AND STATEV, BIT FOR
C       BIT;
C     - LONG SLIDING: 1E6 INCREMENTS OF 0.01 ONE WAY (THE POSITION
C       REACHES 1E4, WHERE REAL*4'S SPACING IS 1E-3), THEN A CYCLE OF
C       AMPLITUDE 1 THERE: THE FORCE STAYS THE CLOSED FORM AND THE
C       CYCLE'S WORK IS 4 MUN (A - MUN/KT); THE SAME HISTORY WITH THE
C       POSITIONS U, W KEPT IN REAL*4 (THE STATE OF THIS TEMPLATE UNTIL
C       1.9) MISSES THE FORCE BY MORE THAN 1E-3 MUN;
C     - CONTACT_3D WITH FNORMAL = 0 (OPEN): NO FORCE.
C     EXITS WITH STATUS 1 IF A CHECK FAILS.
      PROGRAM DVFRIC
      IMPLICIT NONE
      INTEGER NFAIL, NBIT, K, N, I, J, L, NT, IC, NC, KO, KR, KINC, NCP
      PARAMETER (NC = 2)
      DOUBLE PRECISION PI, AKT, AMU, AMP, FN(NC), AMUN(NC), EXACT(NC)
      DOUBLE PRECISION PROPS(3), SV(8,NC), SV2(8,NC), E(3), ANRM(3)
      DOUBLE PRECISION FT(2,NC), FT2(2,NC), WK1(NC), WK2(NC), WK4(NC)
      DOUBLE PRECISION WK5(NC), ET(NC), FJ(NC), ERRF(NC), FNP(NC)
      DOUBLE PRECISION DU, UK, UPREV, TH, SG, EPS, TOL, TOLF, TOLE
      DOUBLE PRECISION W0, ERRA, FA, WK
      REAL U4, W4
      INTEGER JCON(NC), JCP(NC), JP(NC)
      LOGICAL OPEN1
      DOUBLE PRECISION HEPS
      EXTERNAL HEPS
      NFAIL = 0
      PI = 4.0D0 * DATAN(1.0D0)
      AKT = 2.385D0
      AMU = 0.3D0
      AMP = 1.0D0
      N = 400
      FN(1) = 2.375D0
      FN(2) = 1.5D0
      JCON(1) = 2
      JCON(2) = 1
      DO 5 J = 1, NC
         AMUN(J) = AMU * FN(J)
         EXACT(J) = 4.0D0 * AMUN(J) * (AMP - AMUN(J) / AKT)
    5 CONTINUE
C     THE HOST'S PRECISION DECIDES WHAT THE CLOSED FORMS ARE HELD TO
C     (REAL*4: THE STRETCH ROUNDED AT EVERY INCREMENT)
      EPS = HEPS()
      TOL = 1.0D-12
      TOLF = 1.0D-14
      TOLE = 1.0D-14
      IF (EPS .GT. 1.0D-10) THEN
         TOL = 1.0D-5
         TOLF = 1.0D-5
         TOLE = 1.0D-5
      END IF
      WRITE (*, '(A, ES10.3)') 'drive_vfric: the host''s epsilon ', EPS
C
C     THE FIRST POINT IS OPEN FROM INCREMENT KO, CLOSED AGAIN AT KR
      KO = 2 * N + 1
      KR = 2 * N + N / 8 + 1
      DO 100 L = 1, 3
         NT = 2
         IC = 2
         IF (L .GE. 2) NT = 3
         IF (L .GE. 2) IC = 6
         PROPS(1) = IC
         PROPS(2) = AKT
         PROPS(3) = AMU
         E(1) = 0.6D0
         E(2) = 0.8D0
         E(3) = 0.0D0
         ANRM(1) = -0.8D0
         ANRM(2) = 0.6D0
         ANRM(3) = 0.0D0
         IF (L .GE. 2) ANRM(1) = 0.0D0
         IF (L .GE. 2) ANRM(2) = 0.0D0
         IF (L .GE. 2) ANRM(3) = 1.0D0
         DO 12 J = 1, NC
            FJ(J) = 0.0D0
            ERRF(J) = 0.0D0
            DO 10 I = 1, 8
               SV(I,J) = 0.0D0
   10       CONTINUE
   12    CONTINUE
         UPREV = 0.0D0
         NBIT = 0
         DO 50 K = 1, 5 * N
            UK = AMP * SIN(2.0D0 * PI * K / N)
            DU = UK - UPREV
            UPREV = UK
            SG = 1.0D0
            IF (DU .LT. 0.0D0) SG = -1.0D0
            IF (L .EQ. 3) THEN
C              THE PLANE TURNS ABOUT Y: N = (SIN, 0, COS), E IN IT
               TH = PI * K / N
               E(1) = COS(TH)
               E(2) = 0.0D0
               E(3) = -SIN(TH)
               ANRM(1) = SIN(TH)
               ANRM(2) = 0.0D0
               ANRM(3) = COS(TH)
            END IF
C           THE POINTS IN THE CALL: BOTH, OR THE SECOND ALONE
            OPEN1 = K .GE. KO .AND. K .LT. KR
            NCP = 0
            DO 14 J = 1, NC
               IF (J .EQ. 1 .AND. OPEN1) GO TO 14
               NCP = NCP + 1
               JP(NCP) = J
               JCP(NCP) = JCON(J)
               FNP(NCP) = FN(J)
   14       CONTINUE
            DO 22 J = 1, NC
               DO 20 I = 1, 8
                  SV2(I,J) = SV(I,J)
   20          CONTINUE
   22       CONTINUE
C           ANOTHER SLIP FIRST, THEN THE INCREMENT FROM THE OLD STATEV
            CALL CALLV(NT, NCP, PROPS, SV2, JCP, K, 0.5D0 * DU, E, ANRM,
     &                 FNP, FT2)
            DO 26 J = 1, NC
               DO 24 I = 1, 8
                  SV2(I,J) = SV(I,J)
   24          CONTINUE
   26       CONTINUE
            CALL CALLV(NT, NCP, PROPS, SV2, JCP, K, DU, E, ANRM, FNP,
     &                 FT2)
            CALL CALLV(NT, NCP, PROPS, SV, JCP, K, DU, E, ANRM, FNP, FT)
            DO 28 J = 1, NC
               DO 27 I = 1, 8
                  IF (SV(I,J) .NE. SV2(I,J)) NBIT = NBIT + 1
   27          CONTINUE
   28       CONTINUE
            DO 30 I = 1, NCP
               J = JP(I)
               IF (FT(1,I) .NE. FT2(1,I) .OR. FT(2,I) .NE. FT2(2,I))
     &            NBIT = NBIT + 1
               IF (J .EQ. 1 .AND. K .EQ. KR) FJ(J) = 0.0D0
               FJ(J) = MAX(-AMUN(J), MIN(AMUN(J), FJ(J) + AKT * DU))
               ERRF(J) = MAX(ERRF(J), ABS(FT(1,I) + FJ(J) * SG),
     &                       ABS(FT(2,I)))
   30       CONTINUE
            DO 32 J = 1, NC
               WK = SV(NT + 1,JCON(J)) + SV(NT + 2,JCON(J))
               IF (K .EQ. N) WK1(J) = WK
               IF (K .EQ. 2 * N) WK2(J) = WK
               IF (K .EQ. 4 * N) WK4(J) = WK
               IF (K .EQ. 5 * N) WK5(J) = WK
               IF (K .EQ. N + N / 4) ET(J) = SV(NT + 3,JCON(J))
   32       CONTINUE
   50    CONTINUE
         CALL CHK(NBIT .EQ. 0, 'VFRIC called again: bit for bit',
     &            NFAIL)
         DO 60 J = 1, NC
            WRITE (*, '(A, I0, A, I0, A, 3ES16.8, A, ES9.2)')
     &         'VFRIC case ', L, ' point ', J,
     &         ': work per cycle, after reclosure, closed form ',
     &         WK2(J) - WK1(J), WK5(J) - WK4(J), EXACT(J),
     &         '; force error/mun ', ERRF(J) / AMUN(J)
            CALL CHK(ABS(WK2(J) - WK1(J) - EXACT(J)) .LE.
     &         TOL * EXACT(J),
     &         'VFRIC work per cycle 4 mun (A - mun/kt)', NFAIL)
            CALL CHK(ABS(WK5(J) - WK4(J) - EXACT(J)) .LE.
     &         TOL * EXACT(J), 'VFRIC work per cycle after reclosure',
     &         NFAIL)
            CALL CHK(ABS(ET(J) - AMUN(J)**2 / (2 * AKT)) .LE.
     &         TOLE * AMUN(J)**2 / (2 * AKT),
     &         'VFRIC stored mun**2/(2 kt) at the turn', NFAIL)
            CALL CHK(ERRF(J) .LE. TOLF * AMUN(J),
     &         'VFRIC fTangential = closed form at every increment',
     &         NFAIL)
   60    CONTINUE
  100 CONTINUE
C
C     LONG SLIDING, ONE POINT (NODE 1) IN 2-D: 1E6 INCREMENTS OF 0.01,
C     THEN A CYCLE OF AMPLITUDE AMP ABOUT WHERE IT GOT. BESIDE IT, THE
C     SAME JENKINS SLIDER WITH ITS POSITIONS U4, W4 KEPT IN REAL*4.
      PROPS(1) = 2
      PROPS(2) = AKT
      PROPS(3) = AMU
      E(1) = 0.6D0
      E(2) = 0.8D0
      ANRM(1) = -0.8D0
      ANRM(2) = 0.6D0
      DO 110 I = 1, 8
         SV(I,1) = 0.0D0
         SV(I,2) = 0.0D0
  110 CONTINUE
      JCP(1) = 1
      FNP(1) = FN(1)
      FJ(1) = 0.0D0
      ERRF(1) = 0.0D0
      U4 = 0.0
      W4 = 0.0
      ERRA = 0.0D0
      KINC = 0
      DO 150 K = 1, 1000000 + N
         IF (K .LE. 1000000) THEN
            DU = 1.0D-2
         ELSE
            UK = AMP * SIN(2.0D0 * PI * (K - 1000000) / N)
            IF (K .EQ. 1000001) UPREV = 0.0D0
            DU = UK - UPREV
            UPREV = UK
         END IF
         IF (K .EQ. 1000001) W0 = SV(3,1) + SV(4,1)
         SG = 1.0D0
         IF (DU .LT. 0.0D0) SG = -1.0D0
         KINC = KINC + 1
         CALL CALLV(2, 1, PROPS, SV, JCP, KINC, DU, E, ANRM, FNP, FT)
         FJ(1) = MAX(-AMUN(1), MIN(AMUN(1), FJ(1) + AKT * DU))
         ERRF(1) = MAX(ERRF(1), ABS(FT(1,1) + FJ(1) * SG))
C        THE OLD STATE: U AND W ROUNDED TO REAL*4 AFTER EVERY INCREMENT
         FA = AKT * (DBLE(U4) + DU - DBLE(W4))
         IF (ABS(FA) .GT. AMUN(1)) THEN
            W4 = REAL(DBLE(U4) + DU - SIGN(AMUN(1), FA) / AKT)
            FA = SIGN(AMUN(1), FA)
         END IF
         U4 = REAL(DBLE(U4) + DU)
         IF (K .GT. 1000000) ERRA = MAX(ERRA, ABS(FA - FJ(1)))
  150 CONTINUE
      WRITE (*, '(A, 2ES16.8, A, 2ES9.2)') 'VFRIC long sliding: work '
     &   // 'of the last cycle, closed form ', SV(3,1) + SV(4,1) - W0,
     &   EXACT(1),
     &   '; force error/mun, with REAL*4 positions ', ERRF(1) / AMUN(1),
     &   ERRA / AMUN(1)
      CALL CHK(ERRF(1) .LE. TOLF * AMUN(1),
     &         'VFRIC long sliding: the force stays the closed form',
     &         NFAIL)
      CALL CHK(ABS(SV(3,1) + SV(4,1) - W0 - EXACT(1)) .LE.
     &         TOL * EXACT(1),
     &         'VFRIC long sliding: the last cycle''s work', NFAIL)
      CALL CHK(ERRA .GT. 1.0D-3 * AMUN(1),
     &         'VFRIC long sliding: REAL*4 positions would lose it',
     &         NFAIL)
C
C     CONTACT_3D (CODE 3) IN 2-D, NO NORMAL FORCE: OPEN, NO FORCE
      PROPS(1) = 3
      FNP(1) = 0.0D0
      FNP(2) = 0.0D0
      JCP(1) = 2
      JCP(2) = 1
      DO 212 J = 1, NC
         DO 210 I = 1, 8
            SV(I,J) = 0.125D0
  210    CONTINUE
  212 CONTINUE
      CALL CALLV(2, NC, PROPS, SV, JCP, 1, 0.01D0, E, ANRM, FNP, FT)
      CALL CHK(FT(1,1) .EQ. 0.0D0 .AND. FT(1,2) .EQ. 0.0D0,
     &         'VFRIC contact_3d open', NFAIL)
C
      WRITE (*, '(A, I0, A)') 'drive_vfric: ', NFAIL, ' failed'
      IF (NFAIL .NE. 0) CALL EXIT(1)
      END

C     HEPS -- THE EPSILON OF THE HOST'S REALS (VABA_PARAM.INC'S TYPING)
      DOUBLE PRECISION FUNCTION HEPS()
      INCLUDE 'vaba_param.inc'
      A = 1
      HEPS = DBLE(EPSILON(A))
      END

C     CALLV -- VFRIC'S DOCUMENTED CALL, INCREMENT KINC OF STEP 1, FOR
C     THE NCP POINTS OF NODES JCONP ON A SURFACE OF 2 NODES IN NDIR = NT
C     DIMENSIONS, EACH SLIDING BY DU ALONG E (DSLIPFRIC = DU E IN GLOBAL
C     AXES, DIRCOSSL = SIGN(DU) E), WITH THE NORMAL ANRM AND THE NORMAL
C     FORCES FNP; FT(1:NT-1, K) = FTANGENTIAL (FT(2, K) = 0 IN 2-D). THE
C     HOST'S ARRAYS ARE IN VABA_PARAM.INC'S PRECISION: SV, IN DOUBLE
C     PRECISION, IS COPIED TO AND FROM THEM (EXACT BOTH WAYS, AS SV ONLY
C     EVER HOLDS WHAT STATEV HELD).
      SUBROUTINE CALLV(NT, NCP, PROPS, SV, JCONP, KINC, DU, E, ANRM,
     &                 FNP, FT)
      INCLUDE 'vaba_param.inc'
      INTEGER NT, NCP, JCONP(NCP), KINC
      DOUBLE PRECISION PROPS(3), SV(8,2), DU, E(3), ANRM(3), FNP(NCP)
      DOUBLE PRECISION FT(2,NCP)
      DIMENSION STATEV(8,2), PRP(3), DSL(6), DCS(6), DCN(6), FSTICK(2)
      DIMENSION FTP(6), AREA(2), SHAPE(1,2), CSEC(6), FTL(4), FNRM(2)
      DIMENSION CMAIN(3,1), TSEC(2), PSEC(2,1), TMAIN(1), PMAIN(1,1)
      INTEGER JSEC(2), JMAIN(1), JCMAIN(1,2), I, K
      CHARACTER*80 SINT, SSEC, SMAIN
      S = 1
      IF (DU .LT. 0.0D0) S = -1
      DO 5 I = 1, 3
         PRP(I) = PROPS(I)
    5 CONTINUE
      DO 8 K = 1, 2
         DO 6 I = 1, 8
            STATEV(I,K) = SV(I,K)
    6    CONTINUE
    8 CONTINUE
      DO 20 K = 1, NCP
         DO 10 I = 1, NT
            DSL(I + NT * (K - 1)) = DU * E(I)
            DCS(I + NT * (K - 1)) = S * E(I)
            DCN(I + NT * (K - 1)) = ANRM(I)
            FTP(I + NT * (K - 1)) = 0
            CSEC(I + NT * (K - 1)) = 0
   10    CONTINUE
         FSTICK(K) = 1000
         SHAPE(1,K) = 1
         TSEC(K) = 20
         PSEC(K,1) = 0
         JCMAIN(1,K) = 1
         FNRM(K) = FNP(K)
   20 CONTINUE
      DO 22 K = 1, 2
         AREA(K) = 1
         JSEC(K) = 100 + K
   22 CONTINUE
      CMAIN(1,1) = 0
      CMAIN(2,1) = 0
      CMAIN(3,1) = 0
      TMAIN(1) = 20
      PMAIN(1,1) = 0
      JMAIN(1) = 200
      WORK = 0
      TSTEP = 1.0E-6 * KINC
      TGLB = TSTEP
      DTCUR = 1.0E-6
      SINT = 'FRICREG'
      SSEC = 'SECONDARY'
      SMAIN = 'MAIN'
C     NDIR = NT, NFRICDIR = NT - 1, NSTATEVAR = 8 (>= NDIR + 5)
      CALL VFRIC(FTL, STATEV, 1, KINC, NCP, 1, 2, 1, NT - 1, NT, 8, 3,
     &   1, 1, 1, JSEC, JMAIN, JCONP, JCMAIN, TSTEP, TGLB, DTCUR, SINT,
     &   SSEC, SMAIN, 1, DSL, FSTICK, FTP, FNRM, WORK, SHAPE, CSEC,
     &   CMAIN, DCS, DCN, PRP, AREA, TSEC, PSEC, TMAIN, PMAIN)
      DO 30 K = 1, 2
         DO 28 I = 1, 8
            SV(I,K) = STATEV(I,K)
   28    CONTINUE
   30 CONTINUE
      DO 40 K = 1, NCP
         FT(2,K) = 0.0D0
         DO 35 I = 1, NT - 1
            FT(I,K) = FTL(I + (NT - 1) * (K - 1))
   35    CONTINUE
   40 CONTINUE
      END
