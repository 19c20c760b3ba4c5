C     SPDX-License-Identifier: GPL-3.0-or-later
C     DRIVE_USERFRIC.F -- CALLS THE USERFRIC TEMPLATE (USERFRIC.F) AS A
C     CONTA17X ELEMENT DOES (DOCS/HOSTS.MD, USERFRIC): EACH SUBSTEP IS
C     SOLVED BY EQUILIBRIUM ITERATIONS, EVERY ONE CALLING USERFRIC WITH
C     USVR(:, INTPT) AS IT WAS AT THE START OF THE SUBSTEP (HERE POINT 2
C     OF 2), A TRIAL SLIP DSLIP, THE CONTACT PRESSURE PRES, KUPDHIS = 1
C     AND THE STATUS KSTAT THE LAST ITERATION LEFT; ONLY THE LAST
C     ITERATION'S USVR IS KEPT. THE REFERENCE IS THE JENKINS SLIDER IN
C     CLOSED FORM: AN INCREMENT DU MOVES THE FORCE TO F = MAX(-MUN,
C     MIN(MUN, F + KT DU)), MUN = MU P, STICKING (KSTAT 3) WHERE THE
C     BOUND DOES NOT CUT, SLIDING (KSTAT 2) WHERE IT DOES; A CYCLE OF
C     U = A SIN T DISSIPATES 4 MUN (A - MUN/KT). CHECKS, TO 1E-12:
C     - THE LOOP (CODES 1 AND 7, NCOMP = 1), 400 SUBSTEPS A CYCLE: TAU
C       AND KSTAT AT EVERY SUBSTEP, FDISS SUMMED OVER THE SECOND CYCLE,
C       ELENER SUMMING TO 0 OVER IT, THE ENERGY HELD AT A TURN
C       MUN**2/(2 KT); THE ITERATIONS' LAST CALL GIVES THE SAME NUMBERS,
C       BIT FOR BIT, AS ONE CALL FROM THE START OF THE SUBSTEP; POINT
C       1'S COLUMN IS NEVER WRITTEN;
C     - REOPEN AND RECLOSE: THE PRESSURE IS 0 FOR AN EIGHTH OF A CYCLE
C       (KSTAT 1, OPEN NEAR): TAU = 0, KSTAT LEFT AT 1, THE STRETCH
C       RESET; CLOSED AGAIN, TAU FOLLOWS THE CLOSED FORM FROM F = 0,
C       AND THE LOOP TWO CYCLES LATER DISSIPATES THE CLOSED FORM AGAIN;
C     - A ROTATED 3-D POINT (CODES 2 AND 3, NCOMP = 2): THE SAME LOOP
C       ALONG (0.6, 0.8) OF THE ELEMENT'S TANGENTIAL AXES: TAU IS THE
C       1-D FORCE ALONG IT, FDISS PER CYCLE THE CLOSED FORM;
C     - LONG SLIDING: 1E6 SUBSTEPS ONE WAY, TAU STAYS MUN;
C     - NCOMP = 2, IN SLIP: DT AGAINST CENTRAL DIFFERENCES IN DSLIP,
C       DTDP IN PRES, TO 1E-7;
C     - KUPDHIS = 0: USVR UNTOUCHED.
C     EXITS WITH STATUS 1 IF A CHECK FAILS.
      PROGRAM DUFRIC
      IMPLICIT NONE
      INTEGER NFAIL, NBIT, NKS, K, N, I, J, L, IC, KS, KS2, KO, KR, KX
      INTEGER M
      DOUBLE PRECISION PI, AKT, AMU, P, PK, AMP, AMUN, EXACT, DISS
      DOUBLE PRECISION DISS2, ESUM, ETURN, UK, UPREV, H, ERR, FJ, ERRF
      DOUBLE PRECISION UP(3), US(3,2), US0(3,2), US2(3,2), DS(2), DS2(2)
      DOUBLE PRECISION TAU(2), DT(2,2), DTP(2), FD, EL, DU, PX, PY
      DOUBLE PRECISION DT2(2,2), DTP2(2), FD2, EL2, TP(2), TM(2)
      NFAIL = 0
      PI = 4.0D0 * DATAN(1.0D0)
      AKT = 2.385D0
      AMU = 0.3D0
      P = 2.375D0
      AMUN = AMU * P
      AMP = 1.0D0
      N = 400
      EXACT = 4.0D0 * AMUN * (AMP - AMUN / AKT)
      PX = 0.6D0
      PY = 0.8D0
C
C     L = 1, 2: THE LOOP IN 1-D, OPEN FROM KO, CLOSED AGAIN AT KR;
C     L = 3, 4: THE LOOP ALONG (PX, PY) IN 2-D
      KO = 2 * N + 1
      KR = 2 * N + N / 8 + 1
      DO 100 L = 1, 4
         IC = 1
         IF (L .EQ. 2) IC = 7
         IF (L .EQ. 3) IC = 2
         IF (L .EQ. 4) IC = 3
         M = 1
         IF (L .GE. 3) M = 2
         UP(1) = IC
         UP(2) = AKT
         UP(3) = AMU
         DO 12 J = 1, 2
            DO 10 I = 1, 3
               US(I,J) = 0.0D0
   10       CONTINUE
   12    CONTINUE
         US(1,1) = 7.0D0
         UPREV = 0.0D0
         FJ = 0.0D0
         DISS = 0.0D0
         DISS2 = 0.0D0
         ESUM = 0.0D0
         ETURN = -1.0D0
         ERRF = 0.0D0
         NBIT = 0
         NKS = 0
         KS = 3
         KX = 2 * N
         IF (M .EQ. 1) KX = 5 * N
         DO 40 K = 1, KX
            UK = AMP * SIN(2.0D0 * PI * K / N)
            DU = UK - UPREV
            UPREV = UK
            DS(1) = DU
            IF (M .EQ. 2) DS(1) = DU * PX
            IF (M .EQ. 2) DS(2) = DU * PY
            PK = P
            IF (M .EQ. 1 .AND. K .GE. KO .AND. K .LT. KR) PK = 0.0D0
C           ANSYS'S STATUS OF THE POINT: OPEN NEAR WHILE IT HAS NO
C           PRESSURE, ELSE WHAT THE ROUTINE SET
            IF (PK .LE. 0.0D0) KS = 1
            CALL INCRU(M, UP, US, DS, PK, KS, TAU, DT, DTP, FD, EL,
     &                 NBIT)
            IF (US(1,1) .NE. 7.0D0) NBIT = NBIT + 1
            IF (PK .LE. 0.0D0) THEN
               FJ = 0.0D0
               IF (KS .NE. 1 .OR. TAU(1) .NE. 0.0D0 .OR.
     &             US(1,2) .NE. 0.0D0) NKS = NKS + 1
            ELSE
               IF ((ABS(FJ + AKT * DU) .GT. AMUN .AND. KS .NE. 2) .OR.
     &             (ABS(FJ + AKT * DU) .LT. AMUN .AND. KS .NE. 3))
     &            NKS = NKS + 1
               FJ = MAX(-AMUN, MIN(AMUN, FJ + AKT * DU))
            END IF
            IF (M .EQ. 1) ERRF = MAX(ERRF, ABS(TAU(1) - FJ))
            IF (M .EQ. 2) ERRF = MAX(ERRF, ABS(TAU(1) - FJ * PX),
     &                               ABS(TAU(2) - FJ * PY))
            IF (K .GT. N .AND. K .LE. 2 * N) DISS = DISS + FD
            IF (K .GT. N .AND. K .LE. 2 * N) ESUM = ESUM + EL
            IF (K .GT. 4 * N) DISS2 = DISS2 + FD
            IF (K .EQ. N + N / 4) ETURN = US(M + 1,2)
   40    CONTINUE
         WRITE (*, '(A, I0, A, 3ES25.17)') 'USERFRIC code ', IC,
     &      ': FDISS per cycle (after reclosure), closed form ', DISS,
     &      DISS2, EXACT
         CALL CHK(NBIT .EQ. 0, 'USERFRIC iterations: last = one call,'
     &            // ' point 1 untouched', NFAIL)
         CALL CHK(NKS .EQ. 0, 'USERFRIC KSTAT 3 stick, 2 slide, open '
     &            // 'left 1 with TAU = 0 and the stretch reset', NFAIL)
         CALL CHK(ERRF .LE. 1.0D-12 * AMUN,
     &            'USERFRIC TAU = closed form at every substep', NFAIL)
         CALL CHK(ABS(DISS - EXACT) .LE. 1.0D-12 * EXACT,
     &            'USERFRIC FDISS per cycle 4 mun (A - mun/kt)', NFAIL)
         IF (M .EQ. 1) CALL CHK(ABS(DISS2 - EXACT) .LE. 1.0D-12 * EXACT,
     &            'USERFRIC FDISS per cycle after reclosure', NFAIL)
         CALL CHK(ABS(ESUM) .LE. 1.0D-14,
     &            'USERFRIC ELENER sums to 0 over a cycle', NFAIL)
         CALL CHK(ABS(ETURN - AMUN**2 / (2 * AKT)) .LE. 1.0D-14,
     &            'USERFRIC energy mun**2/(2 kt) at the turn', NFAIL)
  100 CONTINUE
C
C     LONG SLIDING: 1E6 SUBSTEPS OF 0.01 ONE WAY
      UP(1) = 1
      US(1,2) = 0.0D0
      US(2,2) = 0.0D0
      DS(1) = 1.0D-2
      DO 150 K = 1, 1000000
         CALL CALLU(1, UP, US, DS, P, 1, KS, TAU, DT, DTP, FD, EL)
  150 CONTINUE
      WRITE (*, '(A, 2ES25.17)') 'USERFRIC after 1e6 substeps: TAU, '
     &   // 'mun ', TAU(1), AMUN
      CALL CHK(ABS(TAU(1) - AMUN) .LE. 1.0D-12 * AMUN .AND. KS .EQ. 2
     &         .AND. ABS(FD - AMUN * DS(1)) .LE. 1.0D-12 * AMUN * DS(1),
     &         'USERFRIC long sliding: TAU = mun, FDISS = mun DSLIP',
     &         NFAIL)
C
C     TWO DIRECTIONS, SLIDING: THE TANGENTS
      H = 1.0D-6
      DO 200 L = 1, 2
         IC = 2
         IF (L .EQ. 2) IC = 3
         UP(1) = IC
         UP(2) = 50.0D0
         UP(3) = 0.3D0
         P = 2.0D0
C        THE STRETCH (0.002, 0.001): A FORCE OF (0.1, 0.05)
         US0(1,2) = 0.002D0
         US0(2,2) = 0.001D0
         US0(3,2) = 1.0D-3
         DS(1) = 0.05D0
         DS(2) = 0.04D0
         DO 110 I = 1, 3
            US(I,2) = US0(I,2)
  110    CONTINUE
         CALL CALLU(2, UP, US, DS, P, 1, KS, TAU, DT, DTP, FD, EL)
         CALL CHK(KS .EQ. 2 .AND. ABS(SQRT(TAU(1)**2 + TAU(2)**2)
     &            - 0.6D0) .LE. 1.0D-15, 'USERFRIC 2-D slides', NFAIL)
         ERR = 0.0D0
         DO 130 K = 1, 2
            DO 120 J = -1, 1, 2
               DO 115 I = 1, 3
                  US2(I,2) = US0(I,2)
  115          CONTINUE
               DS2(1) = DS(1)
               DS2(2) = DS(2)
               DS2(K) = DS(K) + J * H
               IF (J .EQ. 1) CALL CALLU(2, UP, US2, DS2, P, 1, KS2, TP,
     &                                  DT2, DTP2, FD2, EL2)
               IF (J .EQ. -1) CALL CALLU(2, UP, US2, DS2, P, 1, KS2, TM,
     &                                   DT2, DTP2, FD2, EL2)
  120       CONTINUE
            DO 125 I = 1, 2
               ERR = MAX(ERR, ABS((TP(I) - TM(I)) / (2 * H) - DT(I,K)))
  125       CONTINUE
  130    CONTINUE
         CALL CHK(ERR .LE. 1.0D-7, 'USERFRIC DT central', NFAIL)
         DO 140 J = -1, 1, 2
            DO 135 I = 1, 3
               US2(I,2) = US0(I,2)
  135       CONTINUE
            IF (J .EQ. 1) CALL CALLU(2, UP, US2, DS, P + H, 1, KS2, TP,
     &                               DT2, DTP2, FD2, EL2)
            IF (J .EQ. -1) CALL CALLU(2, UP, US2, DS, P - H, 1, KS2, TM,
     &                                DT2, DTP2, FD2, EL2)
  140    CONTINUE
         ERR = MAX(ABS((TP(1) - TM(1)) / (2 * H) - DTP(1)),
     &             ABS((TP(2) - TM(2)) / (2 * H) - DTP(2)))
         CALL CHK(ERR .LE. 1.0D-7, 'USERFRIC DTDP central', NFAIL)
  200 CONTINUE
C
C     KUPDHIS = 0: THE STATE IS LEFT AS IT WAS
      DO 210 I = 1, 3
         US(I,2) = US0(I,2)
  210 CONTINUE
      CALL CALLU(2, UP, US, DS, P, 0, KS, TAU, DT, DTP, FD, EL)
      NBIT = 0
      DO 220 I = 1, 3
         IF (US(I,2) .NE. US0(I,2)) NBIT = NBIT + 1
  220 CONTINUE
      CALL CHK(NBIT .EQ. 0 .AND. FD .GT. 0.0D0,
     &         'USERFRIC KUPDHIS = 0 keeps USVR', NFAIL)
C
      WRITE (*, '(A, I0, A)') 'drive_userfric: ', NFAIL, ' failed'
      IF (NFAIL .NE. 0) CALL EXIT(1)
      END

C     INCRU -- ONE SUBSTEP AS ANSYS SOLVES IT: THREE EQUILIBRIUM
C     ITERATIONS WITH THE TRIAL SLIPS 1.5 DS, 0.75 DS AND DS (THE LAST
C     CONVERGES), EACH FROM USVR AS IT WAS AT THE START AND WITH THE
C     KSTAT THE ITERATION BEFORE LEFT; THE LAST ITERATION'S USVR IS
C     KEPT. NBIT COUNTS A DIFFERENCE, IN ANY OUTPUT, BETWEEN THAT LAST
C     CALL AND ONE CALL FROM THE START.
      SUBROUTINE INCRU(M, UP, US, DS, P, KS, TAU, DT, DTP, FD, EL, NBIT)
      IMPLICIT NONE
      INTEGER M, KS, NBIT
      DOUBLE PRECISION UP(3), US(3,2), DS(2), P, TAU(2), DT(2,2)
      DOUBLE PRECISION DTP(2), FD, EL
      DOUBLE PRECISION UST(3,2), USD(3,2), DST(2), FAC(3)
      DOUBLE PRECISION TT(2), TTG(2,2), TTP(2), TAUD(2), DTD(2,2)
      DOUBLE PRECISION DTPD(2), FDD, ELD
      INTEGER KS0, KSD, IT, I, J
      DATA FAC /1.5D0, 0.75D0, 1.0D0/
      KS0 = KS
      DO 30 IT = 1, 3
         DO 10 J = 1, 2
            DO 5 I = 1, 3
               UST(I,J) = US(I,J)
    5       CONTINUE
   10    CONTINUE
         DO 12 I = 1, M
            DST(I) = FAC(IT) * DS(I)
   12    CONTINUE
         CALL CALLU(M, UP, UST, DST, P, 1, KS, TT, TTG, TTP, FD, EL)
   30 CONTINUE
      DO 40 I = 1, M
         TAU(I) = TT(I)
         DTP(I) = TTP(I)
         DO 35 J = 1, M
            DT(I,J) = TTG(I,J)
   35    CONTINUE
   40 CONTINUE
      DO 45 J = 1, 2
         DO 44 I = 1, 3
            USD(I,J) = US(I,J)
   44    CONTINUE
   45 CONTINUE
      KSD = KS0
      CALL CALLU(M, UP, USD, DS, P, 1, KSD, TAUD, DTD, DTPD, FDD, ELD)
      IF (KSD .NE. KS .OR. FDD .NE. FD .OR. ELD .NE. EL) NBIT = NBIT + 1
      DO 60 I = 1, M
         IF (TAUD(I) .NE. TAU(I) .OR. DTPD(I) .NE. DTP(I))
     &      NBIT = NBIT + 1
         DO 50 J = 1, M
            IF (DTD(I,J) .NE. DT(I,J)) NBIT = NBIT + 1
   50    CONTINUE
   60 CONTINUE
C     CONVERGED: ANSYS KEEPS THE LAST ITERATION'S USVR
      DO 70 J = 1, 2
         DO 65 I = 1, 3
            IF (USD(I,J) .NE. UST(I,J)) NBIT = NBIT + 1
            US(I,J) = UST(I,J)
   65    CONTINUE
   70 CONTINUE
      END

C     CALLU -- USERFRIC'S DOCUMENTED CALL AT POINT 2 OF AN ELEMENT OF
C     TWO POINTS, 3 STATE VARIABLES A POINT (NSVR); KUPD IS KUPDHIS, KS THE
C     CONTACT STATUS, IN AND OUT.
      SUBROUTINE CALLU(NCOMP, UPROP, USVR, DSLIP, PRES, KUPD, KS, TAU,
     &                 DT, DTDP, FDISS, ELENER)
      IMPLICIT NONE
      INTEGER NCOMP, KUPD, KS
      DOUBLE PRECISION UPROP(3), USVR(3,2), DSLIP(NCOMP), PRES
      DOUBLE PRECISION TAU(NCOMP), DT(NCOMP,NCOMP), DTDP(NCOMP)
      DOUBLE PRECISION FDISS, ELENER
      INTEGER KEYOPT(12)
      DOUBLE PRECISION RLCONST(1), SLIP(2), AMU
      INTEGER I
      DO 10 I = 1, 12
         KEYOPT(I) = 0
   10 CONTINUE
      RLCONST(1) = 0.0D0
      SLIP(1) = 0.0D0
      SLIP(2) = 0.0D0
      CALL USERFRIC(1, 1, 2, 12, KEYOPT, 1, RLCONST, NCOMP, 3, UPROP,
     &   0, 0, 1.0D3, 1.0D2, 1.0D0, KS, 1.0D0, 1.0D-2, 20.0D0, 20.0D0,
     &   273.0D0, DSLIP, SLIP, PRES, TAU, DT, USVR, FDISS, ELENER, KUPD,
     &   AMU, DTDP, 3, 2)
      END
