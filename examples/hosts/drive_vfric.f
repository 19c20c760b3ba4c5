C     SPDX-License-Identifier: GPL-3.0-or-later
C     DRIVE_VFRIC.F -- CALLS THE VFRIC TEMPLATE (VFRIC.F) AS
C     ABAQUS/EXPLICIT DOES: A BLOCK OF CONTACT POINTS, EACH WITH ITS
C     INCREMENTAL SLIP DSLIPFRIC, ITS SLIP DIRECTION DIRCOSSL (T1), THE
C     NORMAL DIRCOSN AND THE NORMAL FORCE FNORMAL, THE STATE IN THE
C     COLUMN OF ITS SURFACE NODE JCONSECID. CHECKS:
C     - TWO POINTS (NODES 2 AND 1: THE COLUMNS ARE THE NODES', NOT THE
C       POINTS') SLIDING TO AND FRO ALONG E = (0.6, 0.8) IN 2-D, U =
C       A SIN T, 400 INCREMENTS A CYCLE, EACH UNDER ITS OWN NORMAL FORCE:
C       THE FRICTIONAL WORK KEPT IN STATEV GROWS BY 4 MUN (A - MUN/KT)
C       OVER THE SECOND CYCLE, TO 1E-12, MUN = MU FNORMAL; THE STORED
C       ENERGY AT A TURN IS MUN**2/(2 KT); WHILE SLIDING FTANGENTIAL(1)
C       = -MUN (IT OPPOSES THE SLIP); NEVER |FTANGENTIAL| > MUN;
C     - EACH INCREMENT, CALLED AGAIN FROM THE OLD STATEV AFTER A CALL
C       WITH ANOTHER SLIP, GIVES THE SAME FORCES AND STATEV, BIT FOR BIT;
C     - THE SAME CYCLE IN 3-D (JENKINS_3D, NFRICDIR = 2) IN THE PLANE
C       Z = 0: THE SAME WORK, AND FTANGENTIAL(2) = 0;
C     - CONTACT_3D WITH FNORMAL = 0 (OPEN): NO FORCE.
C     EXITS WITH STATUS 1 IF A CHECK FAILS.
      PROGRAM DVFRIC
      IMPLICIT NONE
      INTEGER NFAIL, NOK, K, N, I, J, NT, NC, IC
      PARAMETER (NC = 2)
      DOUBLE PRECISION PI, AKT, AMU, AMP, FN(NC), AMUN(NC), EXACT
      DOUBLE PRECISION PROPS(3), SV(8,NC), SV0(8,NC), SV2(8,NC)
      DOUBLE PRECISION E(3), ANRM(3), FT(2,NC), FT2(2,NC), W1(NC)
      DOUBLE PRECISION W2(NC), ET(NC), DU, UK, UPREV, FMAX(NC), FSL(NC)
      INTEGER JCON(NC)
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
    5 CONTINUE
C
C     2-D (JENKINS_2D, CODE 2) AND 3-D (JENKINS_3D, CODE 6)
      DO 100 NT = 2, 3
         IC = 2
         IF (NT .EQ. 3) IC = 6
         PROPS(1) = IC
         PROPS(2) = AKT
         PROPS(3) = AMU
         E(1) = 0.6D0
         E(2) = 0.8D0
         E(3) = 0.0D0
         ANRM(1) = -0.8D0
         ANRM(2) = 0.6D0
         ANRM(3) = 0.0D0
         IF (NT .EQ. 3) ANRM(1) = 0.0D0
         IF (NT .EQ. 3) ANRM(2) = 0.0D0
         IF (NT .EQ. 3) ANRM(3) = 1.0D0
         DO 12 J = 1, NC
            FMAX(J) = 0.0D0
            FSL(J) = 0.0D0
            DO 10 I = 1, 8
               SV(I,J) = 0.0D0
   10       CONTINUE
   12    CONTINUE
         UPREV = 0.0D0
         NOK = 0
         DO 50 K = 1, 2 * N
            UK = AMP * SIN(2.0D0 * PI * K / N)
            DU = UK - UPREV
            UPREV = UK
            DO 22 J = 1, NC
               DO 20 I = 1, 8
                  SV0(I,J) = SV(I,J)
                  SV2(I,J) = SV(I,J)
   20          CONTINUE
   22       CONTINUE
C           ANOTHER SLIP FIRST, THEN THE INCREMENT FROM THE OLD STATEV
            CALL CALLV(NT, NC, PROPS, SV2, JCON, 0.5D0 * DU, E, ANRM,
     &                 FN, FT2)
            DO 26 J = 1, NC
               DO 24 I = 1, 8
                  SV2(I,J) = SV0(I,J)
   24          CONTINUE
   26       CONTINUE
            CALL CALLV(NT, NC, PROPS, SV2, JCON, DU, E, ANRM, FN, FT2)
            CALL CALLV(NT, NC, PROPS, SV, JCON, DU, E, ANRM, FN, FT)
            DO 30 J = 1, NC
               DO 28 I = 1, 8
                  IF (SV(I,J) .NE. SV2(I,J)) NOK = NOK + 1
   28          CONTINUE
               DO 29 I = 1, NT - 1
                  IF (FT(I,J) .NE. FT2(I,J)) NOK = NOK + 1
   29          CONTINUE
               FMAX(J) = MAX(FMAX(J), ABS(FT(1,J)) / AMUN(J) - 1)
               IF (NT .EQ. 3) FMAX(J) = MAX(FMAX(J), ABS(FT(2,J)))
C              SLIDING: THE SLIDER MOVED BY DU ALONG E
               IF (SV(1,JCON(J)) .NE. SV0(1,JCON(J))) FSL(J) =
     &            MAX(FSL(J), ABS(FT(1,J) + AMUN(J)))
               IF (K .EQ. N) W1(J) = SV(2 * NT + 1,JCON(J))
               IF (K .EQ. N + N / 4) ET(J) = SV(2 * NT + 2,JCON(J))
   30       CONTINUE
   50    CONTINUE
         CALL CHK(NOK .EQ. 0, 'VFRIC cut-back bit for bit', NFAIL)
         DO 60 J = 1, NC
            W2(J) = SV(2 * NT + 1,JCON(J)) - W1(J)
            EXACT = 4.0D0 * AMUN(J) * (AMP - AMUN(J) / AKT)
            WRITE (*, '(A, I0, A, I0, A, 2ES25.17)') 'VFRIC code ', IC,
     &         ' point ', J, ': work per cycle, closed form ', W2(J),
     &         EXACT
            CALL CHK(ABS(W2(J) - EXACT) .LE. 1.0D-12 * EXACT,
     &               'VFRIC work per cycle 4 mun (A - mun/kt)', NFAIL)
            CALL CHK(ABS(ET(J) - AMUN(J)**2 / (2 * AKT)) .LE. 1.0D-14,
     &               'VFRIC stored mun**2/(2 kt) at the turn', NFAIL)
            CALL CHK(FSL(J) .LE. 1.0D-14 * AMUN(J),
     &               'VFRIC sliding: fTangential(1) = -mun', NFAIL)
            CALL CHK(FMAX(J) .LE. 1.0D-14,
     &               'VFRIC |fTangential(1)| <= mun, (2) = 0', NFAIL)
   60    CONTINUE
  100 CONTINUE
C
C     CONTACT_3D (CODE 3) IN 2-D, NO NORMAL FORCE: OPEN, NO FORCE
      PROPS(1) = 3
      FN(1) = 0.0D0
      FN(2) = 0.0D0
      DO 112 J = 1, NC
         DO 110 I = 1, 8
            SV(I,J) = 0.1D0
  110    CONTINUE
  112 CONTINUE
      CALL CALLV(2, NC, PROPS, SV, JCON, 0.01D0, E, ANRM, FN, FT)
      CALL CHK(FT(1,1) .EQ. 0.0D0 .AND. FT(1,2) .EQ. 0.0D0,
     &         'VFRIC contact_3d open', NFAIL)
C
      WRITE (*, '(A, I0, A)') 'drive_vfric: ', NFAIL, ' failed'
      IF (NFAIL .NE. 0) CALL EXIT(1)
      END

C     CALLV -- VFRIC'S DOCUMENTED CALL FOR NC POINTS OF A SURFACE OF NC
C     NODES IN NDIR = NT DIMENSIONS, EACH POINT SLIDING BY DU ALONG E
C     (DSLIPFRIC = DU E IN GLOBAL AXES, DIRCOSSL = SIGN(DU) E), WITH THE
C     NORMAL ANRM AND THE NORMAL FORCES FN; FT(1:NT-1, K) = FTANGENTIAL
C     (FT(2, K) = 0 IN 2-D).
      SUBROUTINE CALLV(NT, NC, PROPS, STATEV, JCON, DU, E, ANRM, FN, FT)
      IMPLICIT NONE
      INTEGER NT, NC, JCON(NC)
      DOUBLE PRECISION PROPS(3), STATEV(8,NC), DU, E(3), ANRM(3)
      DOUBLE PRECISION FN(NC), FT(2,NC)
C     THE (NDIR, NCONTACT) ARRAYS PACKED BY HAND: DSL(I + NT (K - 1))
      DOUBLE PRECISION DSL(6), DCS(6), DCN(6), FSTICK(2)
      DOUBLE PRECISION FTP(6), AREA(2), SHAPE(1,2), CSEC(6), FTL(4)
      DOUBLE PRECISION CMAIN(3,1), TSEC(2), PSEC(2,1), TMAIN(1)
      DOUBLE PRECISION PMAIN(1,1), WORK, S
      INTEGER JSEC(2), JMAIN(1), JCMAIN(1,2), I, K
      CHARACTER*80 SINT, SSEC, SMAIN
      S = 1.0D0
      IF (DU .LT. 0.0D0) S = -1.0D0
      DO 20 K = 1, NC
         DO 10 I = 1, NT
            DSL(I + NT * (K - 1)) = DU * E(I)
            DCS(I + NT * (K - 1)) = S * E(I)
            DCN(I + NT * (K - 1)) = ANRM(I)
            FTP(I + NT * (K - 1)) = 0.0D0
            CSEC(I + NT * (K - 1)) = 0.0D0
   10    CONTINUE
         FSTICK(K) = 1.0D3
         AREA(K) = 1.0D0
         SHAPE(1,K) = 1.0D0
         TSEC(K) = 20.0D0
         PSEC(K,1) = 0.0D0
         JSEC(K) = 100 + K
         JCMAIN(1,K) = 1
   20 CONTINUE
      CMAIN(1,1) = 0.0D0
      CMAIN(2,1) = 0.0D0
      CMAIN(3,1) = 0.0D0
      TMAIN(1) = 20.0D0
      PMAIN(1,1) = 0.0D0
      JMAIN(1) = 200
      WORK = 0.0D0
      SINT = 'FRICREG'
      SSEC = 'SECONDARY'
      SMAIN = 'MAIN'
C     NDIR = NT, NFRICDIR = NT - 1, NSTATEVAR = 8 (>= 2 NDIR + 2)
      CALL VFRIC(FTL, STATEV, 1, 1, NC, 1, NC, 1, NT - 1, NT, 8, 3, 1,
     &   1, 1, JSEC, JMAIN, JCON, JCMAIN, 1.0D-6, 1.0D-3, 1.0D-6, SINT,
     &   SSEC, SMAIN, 1, DSL, FSTICK, FTP, FN, WORK, SHAPE, CSEC,
     &   CMAIN, DCS, DCN, PROPS, AREA, TSEC, PSEC, TMAIN, PMAIN)
      DO 40 K = 1, NC
         FT(2,K) = 0.0D0
         DO 30 I = 1, NT - 1
            FT(I,K) = FTL(I + (NT - 1) * (K - 1))
   30    CONTINUE
   40 CONTINUE
      END
