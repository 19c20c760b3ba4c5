! SPDX-License-Identifier: GPL-3.0-or-later
! test_laws2d.f90 — the idiomatic layer of the 1.2 laws (disk_eval, stribeck_eval,
! stribeck_disk_eval, fricreg_disk_law_string/_id), the F77 entry points FRDISK, FRSTRB,
! FRSTRD and ctx%set_keep_tangent:
!  - on 41 random contacts (a fixed seed; v within +-2.385 eps, so both inside and outside the
!    band, and every 7th contact at rest), every law's forces equal the C function's of one
!    contact (fricreg_disk_eval, fricreg_stribeck_eval, fricreg_stribeck_disk_eval), bit for
!    bit: the C batch functions loop over those, and a (2, m) array is C's interleaved layout;
!  - the force balance at v = 0: f = f_eq inside the bound, mun f_eq/|f_eq| outside (2-D (2),
!    and the Stribeck laws with fs in place of mun);
!  - every wrong shape is FRICREG_ESIZE with f untouched;
!  - set_keep_tangent(.false.): the same forces to the bit, tangent refused (FRICREG_EINVAL)
!    until it is turned back on and eval runs again, then the same tangent as before.
program test_laws2d
  use fricreg
  use ftest
  implicit none
  integer, parameter :: m = 41
  real(c_double), parameter :: eps = 0.0375_c_double
  real(c_double) :: v(2, m), g(2, m), mun(m), f(2, m), fc(2, m), fx(2, m)
  real(c_double) :: v1(m), g1(m), fs(m), fk(m), vs(m), delta(m), f1(m), fc1(m), fx1(m)
  integer :: i

  call random_inputs()
  call check_names()
  call check_disk()
  call check_stribeck()
  call check_balance_at_rest()
  call check_shapes()
  call check_keep_tangent()
  call finish('laws2d')

contains

  subroutine random_inputs()
    integer :: n
    integer, allocatable :: seed(:)
    real(c_double) :: u(2, m), w(m)
    call random_seed(size=n)
    allocate (seed(n))
    seed = [(2385 + 7919 * i, i = 1, n)]
    call random_seed(put=seed)
    call random_number(u)
    v = (2 * u - 1) * 2.385_c_double * eps
    call random_number(u)
    call random_number(mun)
    mun = 0.1_c_double + 2.4_c_double * mun
    g(1, :) = (2 * u(1, :) - 1) * 2.7_c_double * mun
    g(2, :) = (2 * u(2, :) - 1) * 2.7_c_double * mun
    v(:, 1:m:7) = 0
    call random_number(v1)
    v1 = (2 * v1 - 1) * 2.385_c_double * eps
    v1(1:m:7) = 0
    call random_number(g1)
    call random_number(fs)
    fs = 1 + 2 * fs
    g1 = (2 * g1 - 1) * 1.6_c_double * fs
    call random_number(w)
    fk = w * fs
    fk(1:m:5) = fs(1:m:5) ! fs = fk: constant Coulomb friction
    call random_number(vs)
    vs = 0.05_c_double + 0.45_c_double * vs
    call random_number(delta)
    delta = 0.5_c_double + 2 * delta
  end subroutine random_inputs

  subroutine check_names()
    integer(c_int) :: law
    do law = 1, FRICREG_DISK_QUINN_NESTED
      call check(len(fricreg_disk_law_string(law)) > 0, 'a name for every 2-D law')
      call check(fricreg_disk_law_id(fricreg_disk_law_string(law)) == law, 'name -> id')
      call check(fricreg_disk_law_id(fricreg_disk_law_string(law) // '   ') == law, &
                 'trailing blanks ignored')
    end do
    call check(fricreg_disk_law_string(FRICREG_DISK_QUINN) == 'quinn', "'quinn'")
    call check(fricreg_disk_law_string(0_c_int) == '', 'law 0 has no name')
    call check(fricreg_disk_law_string(FRICREG_DISK_QUINN_NESTED + 1_c_int) == '', &
               'no law after the last')
    call check(fricreg_disk_law_id('Quinn') == 0, 'names are case-sensitive')
  end subroutine check_names

  subroutine check_disk()
    external :: frdisk
    integer(c_int) :: law, status
    integer :: ist
    real(c_double) :: zeros(2, m)
    zeros = 0
    do law = 1, FRICREG_DISK_QUINN_NESTED
      do i = 1, m
        call check_status(fricreg_disk_eval(law, v(:, i), g(:, i), mun(i), eps, fc(:, i)), &
                          FRICREG_OK, 'C disk_eval')
        fx(:, i) = -9
        call check_status(disk_eval(law, eps, v(:, i), g(:, i), mun(i), fx(:, i)), FRICREG_OK, &
                          'disk_eval, one contact')
      end do
      call check_same(fx, fc, 'disk_eval, one contact, = C')
      f = -9
      call check_status(disk_eval(law, eps, v, g, mun, f), FRICREG_OK, 'disk_eval, batch')
      call check_same(f, fc, 'disk_eval, batch, = C')
      f = -9
      call frdisk(int(law), eps, m, v, g, mun, f, ist)
      call check(ist == FRICREG_OK, 'FRDISK')
      call check_same(f, fc, 'FRDISK = C')
    end do
    ! Coulomb does not read f_eq: omitted here, zeros to FRDISK; the others need it.
    f = -9
    status = disk_eval(FRICREG_DISK_COULOMB, eps, v, mun=mun, f=f)
    call check_status(status, FRICREG_OK, 'disk_eval Coulomb without f_eq')
    call check_status(disk_eval(FRICREG_DISK_COULOMB, eps, v(:, 2), mun=mun(2), f=fx(:, 2)), &
                      FRICREG_OK, 'disk_eval Coulomb, one contact, without f_eq')
    do i = 1, m
      status = fricreg_disk_eval(FRICREG_DISK_COULOMB, v(:, i), mun=mun(i), eps=eps, f=fc(:, i))
    end do
    call check_same(f, fc, 'Coulomb without f_eq = C')
    call check_bits(fx(1, 2), fc(1, 2), 'Coulomb one contact without f_eq = C')
    call frdisk(int(FRICREG_DISK_COULOMB), eps, m, v, zeros, mun, f, ist)
    call check_same(f, fc, 'FRDISK Coulomb with zeros for FEQ')
    fx = -9
    call check_status(disk_eval(FRICREG_DISK_QUINN, eps, v, mun=mun, f=fx), FRICREG_ENULL, &
                      'disk_eval (4) without f_eq')
    call check(all(fx == -9), 'f untouched')
    call frdisk(int(FRICREG_DISK_QUINN), eps, -1, v, g, mun, fx, ist)
    call check(ist == FRICREG_EINVAL .and. all(fx == -9), 'FRDISK M = -1')
    call check_status(disk_eval(99_c_int, eps, v, g, mun, fx), FRICREG_EINVAL, 'law 99')
  end subroutine check_disk

  subroutine check_stribeck()
    external :: frstrb, frstrd
    integer :: ist
    real(c_double) :: s
    do i = 1, m
      call check_status(fricreg_stribeck_eval(v1(i), g1(i), fs(i), fk(i), vs(i), delta(i), &
                                              eps, fc1(i)), FRICREG_OK, 'C stribeck_eval')
      s = -9
      call check_status(stribeck_eval(eps, v1(i), g1(i), fs(i), fk(i), vs(i), delta(i), s), &
                        FRICREG_OK, 'stribeck_eval, one contact')
      call check_bits(s, fc1(i), 'stribeck_eval, one contact, = C')
      call check_status(fricreg_stribeck_disk_eval(v(:, i), g(:, i), fs(i), fk(i), vs(i), &
                                                   delta(i), eps, fc(:, i)), FRICREG_OK, &
                        'C stribeck_disk_eval')
      fx(:, i) = -9
      call check_status(stribeck_disk_eval(eps, v(:, i), g(:, i), fs(i), fk(i), vs(i), &
                                           delta(i), fx(:, i)), FRICREG_OK, &
                        'stribeck_disk_eval, one contact')
    end do
    call check_same(fx, fc, 'stribeck_disk_eval, one contact, = C')
    f1 = -9
    call check_status(stribeck_eval(eps, v1, g1, fs, fk, vs, delta, f1), FRICREG_OK, &
                      'stribeck_eval, batch')
    call check_same1(f1, fc1, 'stribeck_eval, batch, = C')
    f1 = -9
    call frstrb(eps, m, v1, g1, fs, fk, vs, delta, f1, ist)
    call check(ist == FRICREG_OK, 'FRSTRB')
    call check_same1(f1, fc1, 'FRSTRB = C')
    f = -9
    call check_status(stribeck_disk_eval(eps, v, g, fs, fk, vs, delta, f), FRICREG_OK, &
                      'stribeck_disk_eval, batch')
    call check_same(f, fc, 'stribeck_disk_eval, batch, = C')
    f = -9
    call frstrd(eps, m, v, g, fs, fk, vs, delta, f, ist)
    call check(ist == FRICREG_OK, 'FRSTRD')
    call check_same(f, fc, 'FRSTRD = C')
    ! C's refusals pass through: kinetic above static at contact 3.
    fx1 = fk
    fx1(3) = 1.5_c_double * fs(3)
    f1 = -9
    call check_status(stribeck_eval(eps, v1, g1, fs, fx1, vs, delta, f1), FRICREG_EINVAL, &
                      'stribeck_eval, fk > fs')
    call frstrb(eps, m, v1, g1, fs, fx1, vs, delta, f1, ist)
    call check(ist == FRICREG_EINVAL .and. all(f1 == -9), 'FRSTRB fk > fs, f untouched')
    call frstrd(eps, -1, v, g, fs, fk, vs, delta, f, ist)
    call check(ist == FRICREG_EINVAL, 'FRSTRD M = -1')
  end subroutine check_stribeck

  !> At v = 0 the 2-D laws but Coulomb, and the Stribeck laws, are the force balance (2):
  !> f = f_eq while |f_eq| <= bound, else bound f_eq/|f_eq| (a high-entropy f_eq direction).
  subroutine check_balance_at_rest()
    real(c_double), parameter :: zero(2) = 0, dir(2) = [0.6_c_double, -0.8_c_double]
    real(c_double) :: inside(2), outside(2), bound, fr(2), s
    integer(c_int) :: law
    bound = 1.385_c_double
    inside = 0.7_c_double * bound * dir
    outside = 2.385_c_double * bound * dir
    do law = FRICREG_DISK_FORCE_BALANCE, FRICREG_DISK_QUINN_NESTED
      call check_status(disk_eval(law, eps, zero, inside, bound, fr), FRICREG_OK, 'rest, in')
      call check_close(fr(1), inside(1), 4 * epsilon(bound), 'rest, inside: f = f_eq, x')
      call check_close(fr(2), inside(2), 4 * epsilon(bound), 'rest, inside: f = f_eq, y')
      call check_status(disk_eval(law, eps, zero, outside, bound, fr), FRICREG_OK, 'rest, out')
      call check_close(fr(1), bound * dir(1), 4 * epsilon(bound), 'rest, outside: x')
      call check_close(fr(2), bound * dir(2), 4 * epsilon(bound), 'rest, outside: y')
    end do
    call check_status(stribeck_disk_eval(eps, zero, outside, bound, 0.6_c_double, &
                                         0.2_c_double, 2.0_c_double, fr), FRICREG_OK, &
                      'stribeck disk at rest')
    call check_close(fr(1), bound * dir(1), 4 * epsilon(bound), 'stribeck disk, rest: fs, x')
    call check_close(fr(2), bound * dir(2), 4 * epsilon(bound), 'stribeck disk, rest: fs, y')
    call check_status(stribeck_disk_eval(eps, zero, inside, bound, 0.6_c_double, &
                                         0.2_c_double, 2.0_c_double, fr), FRICREG_OK, &
                      'stribeck disk at rest, inside')
    call check_close(fr(2), inside(2), 4 * epsilon(bound), 'stribeck disk, rest: f = f_eq')
    call check_status(stribeck_eval(eps, 0.0_c_double, -2.385_c_double, bound, &
                                    0.6_c_double, 0.2_c_double, 2.0_c_double, s), FRICREG_OK, &
                      'stribeck at rest')
    call check_bits(s, -bound, 'stribeck, rest, outside: f = -fs')
    call check_status(stribeck_eval(eps, 0.0_c_double, 0.9_c_double, bound, 0.6_c_double, &
                                    0.2_c_double, 2.0_c_double, s), FRICREG_OK, 'stribeck')
    call check_bits(s, 0.9_c_double, 'stribeck, rest, inside: f = f_eq')
  end subroutine check_balance_at_rest

  !> Every wrong shape: FRICREG_ESIZE before C is called, f untouched.
  subroutine check_shapes()
    real(c_double) :: v3(3), f3(3), f2(2), a3(3, m), b(2, m + 1), c(2, m - 1), s(m + 1)
    real(c_double) :: t(m - 1), ff(2, m), ff1(m)
    v3 = 0.1_c_double
    a3 = 0.1_c_double
    b = 0.1_c_double
    c = 0.1_c_double
    s = 1
    t = 1
    f3 = -9
    f2 = -9
    ff = -9
    ff1 = -9
    call esize(disk_eval(FRICREG_DISK_QUINN, eps, v3, g(:, 1), 1.0_c_double, f2), 'disk: v(3)')
    call esize(disk_eval(FRICREG_DISK_QUINN, eps, v(:, 1), v3, 1.0_c_double, f2), &
               'disk: f_eq(3)')
    call esize(disk_eval(FRICREG_DISK_QUINN, eps, v(:, 1), g(:, 1), 1.0_c_double, f3), &
               'disk: f(3)')
    call esize(disk_eval(FRICREG_DISK_COULOMB, eps, v3, mun=1.0_c_double, f=f2), &
               'disk: v(3), no f_eq')
    call esize(disk_eval(FRICREG_DISK_QUINN, eps, a3, g, mun, ff), 'disk: v(3, m)')
    call esize(disk_eval(FRICREG_DISK_QUINN, eps, b, g, mun, ff), 'disk: v(2, m + 1)')
    call esize(disk_eval(FRICREG_DISK_QUINN, eps, v, c, mun, ff), 'disk: f_eq(2, m - 1)')
    call esize(disk_eval(FRICREG_DISK_QUINN, eps, v, g, s, ff), 'disk: mun(m + 1)')
    call esize(disk_eval(FRICREG_DISK_QUINN, eps, v, g, mun, b), 'disk: f(2, m + 1)')
    call esize(disk_eval(FRICREG_DISK_COULOMB, eps, v, mun=mun, f=c), 'disk: f(2, m - 1)')
    call esize(stribeck_eval(eps, s, g1, fs, fk, vs, delta, ff1), 'stribeck: v(m + 1)')
    call esize(stribeck_eval(eps, v1, t, fs, fk, vs, delta, ff1), 'stribeck: f_eq(m - 1)')
    call esize(stribeck_eval(eps, v1, g1, s, fk, vs, delta, ff1), 'stribeck: fs(m + 1)')
    call esize(stribeck_eval(eps, v1, g1, fs, t, vs, delta, ff1), 'stribeck: fk(m - 1)')
    call esize(stribeck_eval(eps, v1, g1, fs, fk, s, delta, ff1), 'stribeck: vs(m + 1)')
    call esize(stribeck_eval(eps, v1, g1, fs, fk, vs, t, ff1), 'stribeck: delta(m - 1)')
    call esize(stribeck_eval(eps, v1, g1, fs, fk, vs, delta, s), 'stribeck: f(m + 1)')
    call esize(stribeck_disk_eval(eps, v3, g(:, 1), 2.0_c_double, 1.0_c_double, &
                                  0.1_c_double, 1.0_c_double, f2), 'stribeck disk: v(3)')
    call esize(stribeck_disk_eval(eps, v(:, 1), v3, 2.0_c_double, 1.0_c_double, &
                                  0.1_c_double, 1.0_c_double, f2), 'stribeck disk: f_eq(3)')
    call esize(stribeck_disk_eval(eps, v(:, 1), g(:, 1), 2.0_c_double, 1.0_c_double, &
                                  0.1_c_double, 1.0_c_double, f3), 'stribeck disk: f(3)')
    call esize(stribeck_disk_eval(eps, a3, g, fs, fk, vs, delta, ff), 'stribeck disk: v(3, m)')
    call esize(stribeck_disk_eval(eps, v, c, fs, fk, vs, delta, ff), &
               'stribeck disk: f_eq(2, m - 1)')
    call esize(stribeck_disk_eval(eps, v, g, fs, t, vs, delta, ff), 'stribeck disk: fk(m - 1)')
    call esize(stribeck_disk_eval(eps, v, g, fs, fk, s, delta, ff), 'stribeck disk: vs(m + 1)')
    call esize(stribeck_disk_eval(eps, v, g, fs, fk, vs, t, ff), 'stribeck disk: delta(m - 1)')
    call esize(stribeck_disk_eval(eps, v, g, fs, fk, vs, delta, b), 'stribeck disk: f(2, m + 1)')
    call check(all(f3 == -9) .and. all(f2 == -9) .and. all(ff == -9) .and. all(ff1 == -9) &
               .and. all(b == 0.1_c_double) .and. all(c == 0.1_c_double) .and. all(s == 1), &
               'outputs untouched on FRICREG_ESIZE')
  end subroutine check_shapes

  subroutine check_keep_tangent()
    type(fricreg_context) :: ctx, empty
    real(c_double) :: W(3, 3), zdot(3), a(3), fa(3), fb(3), qa(3), qb(3), t1(3, 3), t2(3, 3)
    W = reshape([2.0_c_double, -0.5_c_double, 0.25_c_double, -0.5_c_double, 1.5_c_double, &
                 -0.3_c_double, 0.25_c_double, -0.3_c_double, 1.2_c_double], [3, 3])
    zdot = [0.0_c_double, 0.011_c_double, -0.3_c_double]
    a = [0.7385_c_double, -0.2_c_double, 0.35_c_double]
    call check_status(ctx%create(3), FRICREG_OK, 'create')
    call check_status(ctx%set_law(FRICREG_LAW_QUINN, 0.02_c_double), FRICREG_OK, 'set_law')
    call check_status(ctx%set_coupling_dense(W), FRICREG_OK, 'set_coupling_dense')
    call check_status(ctx%eval(zdot, a, fa, qa), FRICREG_OK, 'eval, keeping')
    call check_status(ctx%tangent(t1), FRICREG_OK, 'tangent, keeping')
    call check_status(ctx%set_keep_tangent(.false.), FRICREG_OK, 'set_keep_tangent(.false.)')
    call check_status(ctx%eval(zdot, a, fb, qb), FRICREG_OK, 'eval, not keeping')
    do i = 1, 3
      call check_bits(fb(i), fa(i), 'f the same without the tangent')
      call check_bits(qb(i), qa(i), 'f_eq the same without the tangent')
    end do
    t2 = -9
    call check_status(ctx%tangent(t2), FRICREG_EINVAL, 'tangent refused while off')
    call check(all(t2 == -9), 'tangent untouched')
    call check_status(ctx%set_keep_tangent(.true.), FRICREG_OK, 'set_keep_tangent(.true.)')
    call check_status(ctx%tangent(t2), FRICREG_EINVAL, 'tangent refused before the next eval')
    call check_status(ctx%eval(zdot, a, fb), FRICREG_OK, 'eval, keeping again')
    call check_status(ctx%tangent(t2), FRICREG_OK, 'tangent, keeping again')
    call check_same3(t2, t1)
    call ctx%destroy()
    call check_status(empty%set_keep_tangent(.true.), FRICREG_ENULL, 'not created')
    call check(empty%errmsg() == 'set_keep_tangent: the context is not created (call create)', &
               'its message')
  end subroutine check_keep_tangent

  subroutine check_same3(a, b)
    real(c_double), intent(in) :: a(3, 3), b(3, 3)
    call check(all(transfer(a, 0_c_int64_t, 9) == transfer(b, 0_c_int64_t, 9)), &
               'the same tangent as before, bit for bit')
  end subroutine check_same3

  subroutine esize(status, what)
    integer(c_int), intent(in) :: status
    character(len=*), intent(in) :: what
    call check_status(status, FRICREG_ESIZE, what)
  end subroutine esize

  subroutine check_same(a, b, what)
    real(c_double), intent(in) :: a(2, m), b(2, m)
    character(len=*), intent(in) :: what
    call check(all(transfer(a, 0_c_int64_t, 2 * m) == transfer(b, 0_c_int64_t, 2 * m)), &
               what // ', bit for bit')
  end subroutine check_same

  subroutine check_same1(a, b, what)
    real(c_double), intent(in) :: a(m), b(m)
    character(len=*), intent(in) :: what
    call check(all(transfer(a, 0_c_int64_t, m) == transfer(b, 0_c_int64_t, m)), &
               what // ', bit for bit')
  end subroutine check_same1
end program test_laws2d
