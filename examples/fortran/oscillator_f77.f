C     SPDX-License-Identifier: GPL-3.0-or-later
C     OSCILLATOR_F77.F -- FRICREG FROM FIXED-FORM FORTRAN 77, THROUGH
C     THE MODULE-FREE ENTRY POINTS (NO MODULE, NO INTERFACE BLOCK).
C
C     THE UNFORCED OSCILLATOR OF QUINN (2004), EQ. (5):
C        X'' + X = F,  MU*N = 1,  X(0) = 2.75,  X'(0) = 0,
C     WITH LAW (4), EPS = 2 DT, INTEGRATED BY THE CALLER'S OWN CLASSICAL
C     RK4 LOOP, DT = 0.01, TO T = 20. THE EXACT COULOMB MOTION STICKS AT
C     X = -0.75 FROM T = PI; THE PAPER REPORTS -0.750090 FOR LAW (4).
C     THEN THE LIBRARY'S OWN DRIVER (FRICREG_SIM, RK4) AT THE SAME
C     SETTINGS, AS ./BUILD/FRICREG-SIM OSCILLATOR --T-END 20 PRINTS IT.
C     EXITS WITH STATUS 1 IF THE TWO REST POSITIONS DIFFER BY > 1E-6.
C     IT FIRST ASKS FRCHK WHETHER IT WAS COMPILED FOR THE LIBRARY IT
C     LINKS: WITH -FDEFAULT-INTEGER-8 IT MUST LINK FRICREG_FORTRAN_ILP64.
C
C     BUILD (SEE FORTRAN/README.MD):
C        gfortran -std=legacy oscillator_f77.f -Ibuild/fortran/generated
C                 build/fortran/libfricreg_fortran.a -Lbuild -lfricreg
C     OR, FOR AN 8-BYTE DEFAULT INTEGER:
C        gfortran -std=legacy -fdefault-integer-8 oscillator_f77.f
C                 -Ibuild/fortran/generated
C                 build/fortran/libfricreg_fortran_ilp64.a -Lbuild -lfricreg
      PROGRAM OSCF77
      IMPLICIT NONE
      INCLUDE 'fricreg.fi'
      INTEGER*8 IH, IS
      INTEGER IST, K, NSTEP, NDOF, M, ICODE
      DOUBLE PRECISION Y(2), DT, EPS, XC(1), VC(1), DIFF
      CHARACTER*256 MSG
      DT = 0.01D0
      EPS = 2.0D0 * DT
      NSTEP = 2000
      IH = 0
      IS = 0
C
C     THE KINDS THIS PROGRAM WAS COMPILED WITH, AGAINST THE LIBRARY'S.
      CALL FRCHK(KIND(0), KIND(0.0), KIND(0.0D0), MSG, IST)
      IF (IST .NE. FRICREG_OK) THEN
         WRITE (*, '(A)') MSG
         STOP 1
      END IF
C
C     A CONTEXT OF ONE CONTACT: LAW (4), MU*N = 1 AND W = 1 (DEFAULTS).
      CALL FRCTXC(1, IH, IST)
      IF (IST .NE. FRICREG_OK) GO TO 900
      CALL FRLAW(IH, FRICREG_LAW_QUINN, EPS, IST)
      IF (IST .NE. FRICREG_OK) GO TO 900
      Y(1) = 2.75D0
      Y(2) = 0.0D0
      DO 10 K = 1, NSTEP
         CALL RK4STP(IH, Y, DT, IST)
         IF (IST .NE. FRICREG_OK) GO TO 900
   10 CONTINUE
      WRITE (*, '(A, 1PE24.16, A)')
     &   'own RK4 loop:   rest position x(20) =', Y(1),
     &   '  (paper: -0.750090)'
      CALL FRCTXF(IH, IST)
C
C     THE LIBRARY'S DRIVER: OSCILLATOR, LAW (4), EPS = 2 DT, RK4.
      CALL FRSIMC(FRICREG_SYSTEM_OSCILLATOR, IS, IST)
      IF (IST .NE. FRICREG_OK) GO TO 910
      CALL FRSIML(IS, FRICREG_LAW_QUINN, EPS, IST)
      IF (IST .NE. FRICREG_OK) GO TO 910
      CALL FRSIMI(IS, FRICREG_INT_RK4, DT, 0.0D0, 0.0D0, IST)
      IF (IST .NE. FRICREG_OK) GO TO 910
      CALL FRSIMR(IS, 20.0D0, IST)
      IF (IST .NE. FRICREG_OK) GO TO 910
      CALL FRSIMN(IS, NDOF, M, IST)
      CALL FRSIMX(IS, NDOF, XC, VC, IST)
      IF (IST .NE. FRICREG_OK) GO TO 910
      WRITE (*, '(A, 1PE24.16)')
     &   'C driver (RK4): rest position x(20) =', XC(1)
      CALL FRSIMF(IS, IST)
      DIFF = Y(1) - XC(1)
      WRITE (*, '(A, 1PE24.16)')
     &   'difference:                          ', DIFF
      IF (ABS(DIFF) .GT. 1.0D-6) THEN
         WRITE (*, '(A)') 'FAIL: the rest positions differ by > 1e-6'
         STOP 1
      END IF
      STOP
C
  900 CALL FRERRM(IH, ICODE, MSG, IST)
      WRITE (*, '(A, A)') 'fricreg: ', MSG
      STOP 1
  910 CALL FRSIME(IS, ICODE, MSG, IST)
      WRITE (*, '(A, A)') 'fricreg: ', MSG
      STOP 1
      END
C
C     ONE CLASSICAL RK4 STEP OF (X, V)' = (V, -X + F), CONTEXT IH.
      SUBROUTINE RK4STP(IH, Y, H, IST)
      IMPLICIT NONE
      INTEGER*8 IH
      DOUBLE PRECISION Y(2), H
      INTEGER IST
      DOUBLE PRECISION YS(2), K1(2), K2(2), K3(2), K4(2)
      CALL RHS(IH, Y, K1, IST)
      IF (IST .NE. 0) RETURN
      YS(1) = Y(1) + 0.5D0 * H * K1(1)
      YS(2) = Y(2) + 0.5D0 * H * K1(2)
      CALL RHS(IH, YS, K2, IST)
      IF (IST .NE. 0) RETURN
      YS(1) = Y(1) + 0.5D0 * H * K2(1)
      YS(2) = Y(2) + 0.5D0 * H * K2(2)
      CALL RHS(IH, YS, K3, IST)
      IF (IST .NE. 0) RETURN
      YS(1) = Y(1) + H * K3(1)
      YS(2) = Y(2) + H * K3(2)
      CALL RHS(IH, YS, K4, IST)
      IF (IST .NE. 0) RETURN
      Y(1) = Y(1) + H / 6.0D0 * (K1(1) + 2.0D0*K2(1) + 2.0D0*K3(1)
     &       + K4(1))
      Y(2) = Y(2) + H / 6.0D0 * (K1(2) + 2.0D0*K2(2) + 2.0D0*K3(2)
     &       + K4(2))
      END
C
C     THE RIGHT-HAND SIDE: FREE ACCELERATION -X (SO F_EQ = X), FRICTION
C     FROM THE CONTEXT AT THE CONTACT VELOCITY V.
      SUBROUTINE RHS(IH, Y, DYDT, IST)
      IMPLICIT NONE
      INTEGER*8 IH
      DOUBLE PRECISION Y(2), DYDT(2)
      INTEGER IST
      DOUBLE PRECISION AFREE(1), F(1), FEQ(1)
      AFREE(1) = -Y(1)
      CALL FREVAL(IH, 1, Y(2), AFREE, F, FEQ, IST)
      DYDT(1) = Y(2)
      DYDT(2) = AFREE(1) + F(1)
      END
