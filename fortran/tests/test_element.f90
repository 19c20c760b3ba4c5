! SPDX-License-Identifier: GPL-3.0-or-later
! test_element.f90 — the element types of host codes (fricreg_element.h) from Fortran: the type
! fricreg_element of module fricreg, a host's own state arrays, the Fortran order of the
! tangents, and the errors.
!
! Values. An Iwan element under monotone loading from rest follows the backbone
! F(u) = sum_s min(k_s u, phi_s) (fricreg_iwan.h), and unloading from u_r follows Masing's rule
! F(u_r) - F(u) = 2 F((u_r - u)/2), exactly for any sliders; here the sliders are Segalman's
! (fricreg_element_segalman, F_S = 2, K_T = 10, chi = -0.5, beta = 0, 6 sliders). The
! contact_3d tangent in slip: dfdu(1, 3) = df_x/dg = mu kn n_x /= 0 while dfdu(3, 1) = dN/du_x
! = 0, which C gives at [2] and [6] of its row-major block. Its energies in that slip from
! rest: the slider's f . dw and the springs' f**2 / (2 k) (fricreg_element_energy).
program test_element
  use fricreg
  use ftest
  implicit none
  type(fricreg_element) :: iw, ct, none
  integer, parameter :: ns = 6
  real(c_double) :: p(2 * ns), w(ns), w2(ns), u(3), f(3), dfdu(3, 3), dfdp(3, 5), c_tu(9)
  real(c_double) :: pc(5), wc(2), wc2(2), ur, fr, fu, back, one(1), f1(1), big(2)
  integer :: i

  call check_status(iw%lookup('iwan', ns), FRICREG_OK, 'lookup iwan')
  call check(iw%name() == 'iwan' .and. iw%dim() == 1 .and. iw%nparams() == 2 * ns .and. &
             iw%nstate() == ns, 'iwan sizes')
  call check_status(fricreg_element_segalman(int(ns, c_size_t), 2.0_c_double, 10.0_c_double, &
                                             -0.5_c_double, 0.0_c_double, 1e-3_c_double, &
                                             p(1:ns), p(ns + 1:)), FRICREG_OK, 'segalman')
  call check_status(iw%init(p, w), FRICREG_OK, 'init')
  ! monotone loading to u_r = 0.3 in 30 steps: the backbone at every step
  do i = 1, 30
    one(1) = 0.01_c_double * i
    call check_status(iw%eval(p, w, one, f1, w2), FRICREG_OK, 'eval loading')
    call check_close(f1(1), backbone(one(1)), 1e-14_c_double, 'backbone')
    w = w2
  end do
  ur = 0.3_c_double
  fr = backbone(ur)
  ! unloading to -0.3: Masing's rule
  do i = 1, 60
    one(1) = ur - 0.01_c_double * i
    call check_status(iw%eval(p, w, one, f1, w2), FRICREG_OK, 'eval unloading')
    fu = f1(1)
    back = fr - 2.0_c_double * backbone((ur - one(1)) / 2.0_c_double)
    call check_close(fu, back, 1e-14_c_double, 'Masing')
    w = w2
  end do

  ! contact_3d: Fortran's order of the tangents
  call check_status(ct%lookup('contact_3d'), FRICREG_OK, 'lookup contact_3d')
  pc = [10.0_c_double, 0.5_c_double, 4.0_c_double, 2.0_c_double, 0.0_c_double]
  wc = 0.0_c_double
  u = [0.8_c_double, 0.3_c_double, 0.25_c_double]
  call check_status(ct%eval(pc, wc, u, f, wc2, dfdu, dfdp), FRICREG_OK, 'eval contact_3d')
  call check_status(fricreg_element_eval(fricreg_element_lookup('contact_3d' // c_null_char), &
                                         pc, wc, u, f, c_tu, state_out=wc2), FRICREG_OK, 'C eval')
  call check(dfdu(1, 3) /= 0.0_c_double .and. dfdu(3, 1) == 0.0_c_double, 'dfdu(1, 3) = df/dg')
  call check_bits(dfdu(1, 3), c_tu(3), 'dfdu(1, 3) is C''s [2]')
  call check_bits(dfdu(3, 3), c_tu(9), 'dfdu(3, 3) is C''s [8]')
  call check_close(dfdp(3, 4), 1.0_c_double, 0.0_c_double, 'dN/dn0 = 1')
  call check_close(dfdp(1, 2), 3.0_c_double * 0.8_c_double / hypot(0.8_c_double, 0.3_c_double), &
                   1e-15_c_double, 'df_x/dmu = N n_x')
  call check_close(hypot(f(1), f(2)), 0.5_c_double * 3.0_c_double, 1e-15_c_double, 'slip mu N')
  ! its energies: the slider slips by |u_t| - mu N / kt at the force mu N = 1.5 (N = n0 + kn g
  ! = 3), and the springs hold (mu N)**2 / (2 kt) + N**2 / (2 kn)
  call check_status(ct%energy(pc, wc, u, ur, fr), FRICREG_OK, 'energy contact_3d')
  call check_close(ur, 1.5_c_double * (hypot(0.8_c_double, 0.3_c_double) - 0.15_c_double), &
                   1e-15_c_double, 'dissipated mu N slip')
  call check_close(fr, 1.5_c_double**2 / 20 + 3.0_c_double**2 / 8, 1e-15_c_double, 'stored')
  call check_status(ct%energy(pc, wc, u(1:2), ur, fr), FRICREG_ESIZE, 'energy u size')

  ! errors: nothing written, a message
  call check_status(none%lookup('coulomb'), FRICREG_EINVAL, 'lookup unknown')
  call check(index(none%errmsg(), 'coulomb') > 0, 'lookup message')
  call check_status(none%eval(pc, wc, u, f, wc2), FRICREG_ENULL, 'eval without a type')
  call check_status(ct%lookup('contact_3d', 2), FRICREG_EINVAL, 'contact_3d has no sliders')
  call check_status(ct%eval(pc(1:4), wc, u, f, wc2), FRICREG_ESIZE, 'params size')
  call check_status(ct%eval(pc, wc, u(1:2), f, wc2), FRICREG_ESIZE, 'u size')
  call check_status(ct%eval(pc, wc, u, f, wc2, dfdu(1:2, :)), FRICREG_ESIZE, 'dfdu shape')
  pc(1) = 0.0_c_double
  f = -7.0_c_double
  wc2 = -7.0_c_double
  call check_status(ct%eval(pc, wc, u, f, wc2, dfdu), FRICREG_EINVAL, 'kt = 0')
  call check(all(f == -7.0_c_double) .and. all(wc2 == -7.0_c_double), 'nothing written')
  call check(index(ct%errmsg(), 'eval: contact_3d: kt = 0') == 1, 'message: ' // ct%errmsg())
  big = [1.0_c_double, 1.0_c_double]
  call check_status(ct%init(big, wc), FRICREG_ESIZE, 'init params size')
  call finish('test_element')

contains

  !> The Iwan element's backbone sum_s min(k_s u, phi_s) at u >= 0.
  real(c_double) function backbone(x)
    real(c_double), intent(in) :: x
    integer :: s
    backbone = 0.0_c_double
    do s = 1, ns
      backbone = backbone + min(p(s) * x, p(ns + s))
    end do
  end function backbone

end program test_element
