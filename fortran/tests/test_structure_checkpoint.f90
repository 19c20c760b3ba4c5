! SPDX-License-Identifier: GPL-3.0-or-later
! test_structure_checkpoint.f90 — type(fricreg_structure)'s save and restore
! (fricreg_structure_save, _restore): the block of test_structure_jenkins.f90 (2.385 kg,
! 217.3 N/m, a constant load of -0.731 m/s^2 times its mass) with a contact of 0.3 N and a slipping
! Jenkins element, run by Newmark with dt = 0.01 s to 1 s in one run, and to 0.5 s (50 steps:
! a step time of the one run), saved, restored into a new structure set up the same way and run
! on to 1 s: u, v, a, the forces, the dissipation, the element's state and the counters agree
! bit for bit. A structure of another stiffness refuses the checkpoint (FRICREG_EINVAL, its
! state unchanged), and so does a truncated one.
program test_structure_checkpoint
  use fricreg
  use ftest
  use, intrinsic :: iso_c_binding, only: c_int8_t
  implicit none
  type(fricreg_structure) :: full, first, again, other
  integer(c_int8_t), allocatable :: blob(:)
  real(c_double) :: a(3, 2), fe(2), we(2), De(2), before(3), after(3)
  integer(c_int64_t) :: steps(2)
  integer :: k

  call make(full, 217.3_c_double)
  call check_status(full%run(0.01_c_double, 1.0_c_double), FRICREG_OK, 'run to 1 s')

  call make(first, 217.3_c_double)
  call check_status(first%run(0.01_c_double, 0.5_c_double), FRICREG_OK, 'run to 0.5 s')
  call check_status(first%save(blob), FRICREG_OK, 'save')
  call check(size(blob) > 64, 'the checkpoint has its header and state')
  call first%destroy()

  call make(again, 217.3_c_double)
  call check_status(again%restore(blob), FRICREG_OK, 'restore')
  call check_status(again%run(0.01_c_double, 1.0_c_double), FRICREG_OK, 'run on to 1 s')

  do k = 1, 3 ! u, v, a of both, one at a time
    call state_entry(full, k, a(k, 1))
    call state_entry(again, k, a(k, 2))
    call check_bits(a(k, 2), a(k, 1), 'state entry after restore')
  end do
  call check_status(full%get_dissipation(fe(1:1)), FRICREG_OK, 'get_dissipation')
  call check_status(again%get_dissipation(fe(2:2)), FRICREG_OK, 'get_dissipation')
  call check_bits(fe(2), fe(1), 'contact dissipation')
  call check(fe(1) > 1e-4_c_double, 'the contact slipped')
  call check_status(full%get_jenkins_state(fe(1:1), we(1:1), De(1:1)), FRICREG_OK, 'jenkins')
  call check_status(again%get_jenkins_state(fe(2:2), we(2:2), De(2:2)), FRICREG_OK, 'jenkins')
  call check_bits(fe(2), fe(1), 'element force')
  call check_bits(we(2), we(1), 'element slider')
  call check_bits(De(2), De(1), 'element dissipation')
  call check(De(1) > 0.0_c_double, 'the element slipped')
  call check_status(full%get_stat(FRICREG_SSTAT_NEWTON_ITERATIONS, steps(1)), FRICREG_OK, 'stat')
  call check_status(again%get_stat(FRICREG_SSTAT_NEWTON_ITERATIONS, steps(2)), FRICREG_OK, 'stat')
  call check(steps(1) == steps(2), 'Newton iterations')

  call make(other, 217.4_c_double)
  call check_status(other%run(0.01_c_double, 0.2_c_double), FRICREG_OK, 'other run')
  call check_status(other%get_state(u=before(1:1)), FRICREG_OK, 'other state')
  call check_status(other%restore(blob), FRICREG_EINVAL, 'restore into another model')
  call check(index(other%errmsg(), 'not the checkpoint') > 0, 'message: ' // other%errmsg())
  call check_status(other%get_state(u=after(1:1)), FRICREG_OK, 'other state after')
  call check_bits(after(1), before(1), 'unchanged by the refusal')
  call check_status(again%restore(blob(1:size(blob) - 1)), FRICREG_EINVAL, 'truncated')
  call finish('test_structure_checkpoint')

contains

  subroutine make(st, k)
    type(fricreg_structure), intent(inout) :: st
    real(c_double), intent(in) :: k
    real(c_double), parameter :: J(1, 1) = reshape([1.0_c_double], [1, 1])
    call check_status(st%create(1, 1), FRICREG_OK, 'create')
    call check_status(st%set_mass(reshape([2.385_c_double], [1, 1])), FRICREG_OK, 'set_mass')
    call check_status(st%set_stiffness(reshape([k], [1, 1])), FRICREG_OK, 'set_stiffness')
    call check_status(st%set_contacts(J), FRICREG_OK, 'set_contacts')
    call check_status(st%set_bounds([0.3_c_double]), FRICREG_OK, 'set_bounds')
    call check_status(st%set_law(FRICREG_LAW_QUINN, 1e-3_c_double), FRICREG_OK, 'set_law')
    call check_status(st%set_load([-0.731_c_double * 2.385_c_double]), FRICREG_OK, 'set_load')
    call check_status(st%set_jenkins(J, [200.0_c_double], [0.05_c_double]), FRICREG_OK, &
                      'set_jenkins')
  end subroutine make

  !> Entry k of (u, v, a) of the one-dof structure.
  subroutine state_entry(st, k, x)
    type(fricreg_structure), intent(inout) :: st
    integer, intent(in) :: k
    real(c_double), intent(out) :: x
    real(c_double) :: u(1), v(1), acc(1)
    call check_status(st%get_state(u, v, acc), FRICREG_OK, 'get_state')
    x = merge(u(1), merge(v(1), acc(1), k == 2), k == 1)
  end subroutine state_entry
end program test_structure_checkpoint
