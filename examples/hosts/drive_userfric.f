C     SPDX-License-Identifier: GPL-3.0-or-later
C     DRIVE_USERFRIC.F -- CALLS THE USERFRIC TEMPLATE (USERFRIC.F) AS A
C     CONTA17X ELEMENT DOES: THE SUBSTEP'S SLIP INCREMENT DSLIP, THE
C     CONTACT PRESSURE PRES, THE POINT'S STATE USVR(:, INTPT) AT THE
C     START OF THE SUBSTEP (HERE POINT 2 OF 2), KUPDHIS = 1. CHECKS:
C     - A JENKINS SLIDER (CODES 1 AND 7, NCOMP = 1) UNDER U = A SIN T
C       AT A CONSTANT PRESSURE P, 400 SUBSTEPS A CYCLE: FDISS SUMS TO
C       4 MUN (A - MUN/KT) OVER THE SECOND CYCLE, MUN = MU P, TO 1E-12;
C       ELENER SUMS TO 0 OVER IT (THE SAME ENERGY AT BOTH ENDS), AND THE
C       ENERGY HELD AT A TURN IS MUN**2/(2 KT); KSTAT IS 2 WHILE THE
C       SLIDER MOVES, 1 OTHERWISE;
C     - EACH SUBSTEP, CALLED AGAIN FROM THE OLD USVR AFTER A CALL WITH A
C       TWICE LARGER SLIP (A BISECTION), GIVES THE SAME TAU, DT, DTDP,
C       FDISS, ELENER, KSTAT AND USVR, BIT FOR BIT; POINT 1'S COLUMN IS
C       NEVER WRITTEN;
C     - NCOMP = 2 (CODES 2 AND 3), IN SLIP: DT AGAINST CENTRAL
C       DIFFERENCES IN DSLIP, DTDP IN PRES, TO 1E-7;
C     - KUPDHIS = 0: USVR UNTOUCHED.
C     EXITS WITH STATUS 1 IF A CHECK FAILS.
      PROGRAM DUFRIC
      IMPLICIT NONE
      INTEGER NFAIL, NOK, K, N, I, J, L, IC, KS, KS2, NKS
      DOUBLE PRECISION PI, AKT, AMU, P, AMP, AMUN, EXACT, DISS, ESUM
      DOUBLE PRECISION ETURN, UK, UPREV, H, ERR
      DOUBLE PRECISION UP(3), US(5,2), US0(5,2), US2(5,2), DS(2), DS2(2)
      DOUBLE PRECISION TAU(2), DT(2,2), DTP(2), FD, EL
      DOUBLE PRECISION TAU2(2), DT2(2,2), DTP2(2), FD2, EL2
      DOUBLE PRECISION TP(2), TM(2)
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
      DO 100 L = 1, 2
         IC = 1
         IF (L .EQ. 2) IC = 7
         UP(1) = IC
         UP(2) = AKT
         UP(3) = AMU
         DO 12 J = 1, 2
            DO 10 I = 1, 5
               US(I,J) = 0.0D0
   10       CONTINUE
   12    CONTINUE
         US(1,1) = 7.0D0
         UPREV = 0.0D0
         DISS = 0.0D0
         ESUM = 0.0D0
         ETURN = -1.0D0
         NOK = 0
         NKS = 0
         DO 40 K = 1, 2 * N
            UK = AMP * SIN(2.0D0 * PI * K / N)
            DS(1) = UK - UPREV
            UPREV = UK
            DO 22 J = 1, 2
               DO 20 I = 1, 5
                  US0(I,J) = US(I,J)
                  US2(I,J) = US(I,J)
   20          CONTINUE
   22       CONTINUE
            DS2(1) = 2.0D0 * DS(1)
            CALL CALLU(1, UP, US2, DS2, P, 1, TAU2, DT2, DTP2, FD2, EL2,
     &                 KS2)
            DO 26 J = 1, 2
               DO 24 I = 1, 5
                  US2(I,J) = US0(I,J)
   24          CONTINUE
   26       CONTINUE
            CALL CALLU(1, UP, US2, DS, P, 1, TAU2, DT2, DTP2, FD2, EL2,
     &                 KS2)
            CALL CALLU(1, UP, US, DS, P, 1, TAU, DT, DTP, FD, EL, KS)
            IF (TAU(1) .NE. TAU2(1) .OR. DT(1,1) .NE. DT2(1,1) .OR.
     &          DTP(1) .NE. DTP2(1) .OR. FD .NE. FD2 .OR. EL .NE. EL2
     &          .OR. KS .NE. KS2 .OR. US(1,1) .NE. 7.0D0) NOK = NOK + 1
            DO 30 I = 1, 5
               IF (US(I,2) .NE. US2(I,2)) NOK = NOK + 1
   30       CONTINUE
            IF ((US(1,2) .NE. US0(1,2) .AND. KS .NE. 2) .OR.
     &          (US(1,2) .EQ. US0(1,2) .AND. KS .NE. 1)) NKS = NKS + 1
            IF (K .GT. N) DISS = DISS + FD
            IF (K .GT. N) ESUM = ESUM + EL
            IF (K .EQ. N + N / 4) ETURN = US(3,2)
   40    CONTINUE
         WRITE (*, '(A, I0, A, 2ES25.17)') 'USERFRIC code ', IC,
     &      ': FDISS per cycle, closed form ', DISS, EXACT
         CALL CHK(NOK .EQ. 0, 'USERFRIC bisection bit for bit', NFAIL)
         CALL CHK(NKS .EQ. 0, 'USERFRIC KSTAT 1 stick, 2 slide', NFAIL)
         CALL CHK(ABS(DISS - EXACT) .LE. 1.0D-12 * EXACT,
     &            'USERFRIC FDISS per cycle 4 mun (A - mun/kt)', NFAIL)
         CALL CHK(ABS(ESUM) .LE. 1.0D-14,
     &            'USERFRIC ELENER sums to 0 over a cycle', NFAIL)
         CALL CHK(ABS(ETURN - AMUN**2 / (2 * AKT)) .LE. 1.0D-14,
     &            'USERFRIC energy mun**2/(2 kt) at the turn', NFAIL)
  100 CONTINUE
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
         US0(1,2) = 0.01D0
         US0(2,2) = -0.02D0
         US0(3,2) = 0.012D0
         US0(4,2) = -0.019D0
         US0(5,2) = 1.0D-3
         DS(1) = 0.05D0
         DS(2) = 0.04D0
         DO 110 I = 1, 5
            US(I,2) = US0(I,2)
  110    CONTINUE
         CALL CALLU(2, UP, US, DS, P, 1, TAU, DT, DTP, FD, EL, KS)
         CALL CHK(KS .EQ. 2 .AND. ABS(SQRT(TAU(1)**2 + TAU(2)**2)
     &            - 0.6D0) .LE. 1.0D-15, 'USERFRIC 2-D slides', NFAIL)
         ERR = 0.0D0
         DO 130 K = 1, 2
            DO 120 J = -1, 1, 2
               DO 115 I = 1, 5
                  US2(I,2) = US0(I,2)
  115          CONTINUE
               DS2(1) = DS(1)
               DS2(2) = DS(2)
               DS2(K) = DS(K) + J * H
               IF (J .EQ. 1) CALL CALLU(2, UP, US2, DS2, P, 1, TP, DT2,
     &                                  DTP2, FD2, EL2, KS2)
               IF (J .EQ. -1) CALL CALLU(2, UP, US2, DS2, P, 1, TM, DT2,
     &                                   DTP2, FD2, EL2, KS2)
  120       CONTINUE
            DO 125 I = 1, 2
               ERR = MAX(ERR, ABS((TP(I) - TM(I)) / (2 * H) - DT(I,K)))
  125       CONTINUE
  130    CONTINUE
         CALL CHK(ERR .LE. 1.0D-7, 'USERFRIC DT central', NFAIL)
         DO 140 I = 1, 5
            US2(I,2) = US0(I,2)
  140    CONTINUE
         CALL CALLU(2, UP, US2, DS, P + H, 1, TP, DT2, DTP2, FD2, EL2,
     &              KS2)
         DO 145 I = 1, 5
            US2(I,2) = US0(I,2)
  145    CONTINUE
         CALL CALLU(2, UP, US2, DS, P - H, 1, TM, DT2, DTP2, FD2, EL2,
     &              KS2)
         ERR = MAX(ABS((TP(1) - TM(1)) / (2 * H) - DTP(1)),
     &             ABS((TP(2) - TM(2)) / (2 * H) - DTP(2)))
         CALL CHK(ERR .LE. 1.0D-7, 'USERFRIC DTDP central', NFAIL)
  200 CONTINUE
C
C     KUPDHIS = 0: THE STATE IS LEFT AS IT WAS
      DO 210 I = 1, 5
         US(I,2) = US0(I,2)
  210 CONTINUE
      CALL CALLU(2, UP, US, DS, P, 0, TAU, DT, DTP, FD, EL, KS)
      NOK = 0
      DO 220 I = 1, 5
         IF (US(I,2) .NE. US0(I,2)) NOK = NOK + 1
  220 CONTINUE
      CALL CHK(NOK .EQ. 0 .AND. FD .GT. 0.0D0,
     &         'USERFRIC KUPDHIS = 0 keeps USVR', NFAIL)
C
      WRITE (*, '(A, I0, A)') 'drive_userfric: ', NFAIL, ' failed'
      IF (NFAIL .NE. 0) CALL EXIT(1)
      END

C     CALLU -- USERFRIC'S DOCUMENTED CALL AT POINT 2 OF AN ELEMENT OF TWO
C     POINTS, 5 STATE VARIABLES A POINT (NSVR); KUPD IS KUPDHIS, KS THE
C     CONTACT STATUS (SET TO 2, SLIDING, BEFORE THE CALL).
      SUBROUTINE CALLU(NCOMP, UPROP, USVR, DSLIP, PRES, KUPD, TAU, DT,
     &                 DTDP, FDISS, ELENER, KS)
      IMPLICIT NONE
      INTEGER NCOMP, KUPD, KS
      DOUBLE PRECISION UPROP(3), USVR(5,2), DSLIP(NCOMP), PRES
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
      KS = 2
      CALL USERFRIC(1, 1, 2, 12, KEYOPT, 1, RLCONST, NCOMP, 3, UPROP,
     &   0, 0, 1.0D3, 1.0D2, 1.0D0, KS, 1.0D0, 1.0D-2, 20.0D0, 20.0D0,
     &   273.0D0, DSLIP, SLIP, PRES, TAU, DT, USVR, FDISS, ELENER, KUPD,
     &   AMU, DTDP, 5, 2)
      END
