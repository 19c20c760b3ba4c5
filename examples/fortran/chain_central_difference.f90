! SPDX-License-Identifier: GPL-3.0-or-later
! chain_central_difference.f90 — the paper's n-dof chain (Quinn 2004, Sec. 3.2, Fig. 8)
! integrated with the explicit central-difference scheme of explicit structural codes, with
! friction from fricreg: one context of n contacts, one call per step for all blocks.
!
! The chain: n blocks of mass 1/n, springs of stiffness n, block 1 driven by G = a sin(omega t),
! block n tied to a wall, every block mun = 1, friction entering as f_i/n. Per unit mass,
!     u_i'' = a_free_i + f_i,   a_free = -n^2 K u + n G e_1,
! K the tridiagonal (-1, 2, -1) stiffness with a free end at block 1 and a wall at block n. So
! the contacts are the blocks (zdot = u'), W = I and mun_i = 1: the context's defaults, and
! f_eq = -a_free comes from the context.
!
! Central difference (leapfrog), the scheme of explicit finite-element codes:
!     a^k = a_free(u^k, t_k) + f^k,  v^(k+1/2) = v^(k-1/2) + dt a^k,  u^(k+1) = u^k + dt v^(k+1/2)
! started with v^(1/2) = v^0 + (dt/2) a^0. The friction at t_k needs a velocity at t_k, which the
! scheme does not have; we predict it as v^k ~ v^(k-1/2) + (dt/2) a^(k-1) (second order; the
! half-step velocity v^(k-1/2) alone, as many codes use for damping, lags by dt/2: see
! fortran/README.md for both).
!
! Step and eps: dt = T/1257, the largest step <= 0.01 (the paper's) that puts a whole number
! of steps in a forcing period T = 2 pi/omega, so each cycle's D is a sum over whole steps; eps =
! 10 omega dt, the paper's rule for the chain. Stability: the stiffest spring mode has
! omega_max < 2n, and dt omega_max < 2n dt = 0.64 < 2; in the stick zone law (4) is a damper
! of rate 2 mun/eps per unit mass, and dt 2/eps = 0.4 < 1, the bound of the predicted velocity
! (2 with the half-step velocity), so the stick decays without overshoot.
!
! D per cycle = -(1/n) sum_i int u_i' f_i dt, summed step by step as the work of the friction
! forces, (u^(k+1) - u^k) . (f^k + f^(k+1))/2 (the energy balance of explicit codes).
! The paper: D -> 0.0105 (Fig. 9). Exits with status 1 if the 4th cycle is off by more than 1%.
!
! Usage: chain_central_difference [STEPS_PER_CYCLE [predicted|half-step]]
!        (defaults 1257 and predicted: the velocity the friction sees)
program chain_central_difference
  use fricreg
  implicit none
  integer, parameter :: n = 32, cycles = 4
  real(c_double), parameter :: a = 0.25_c_double, omega = 0.5_c_double
  real(c_double), parameter :: D_paper = 0.0105_c_double
  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  type(fricreg_context) :: ctx
  real(c_double) :: u(n), v(n), acc(n), a_free(n), f(n), f_old(n), zdot(n)
  real(c_double) :: D(cycles), dt, eps, period, t, n2, G, work, cpu_start, cpu_end
  integer :: steps_per_cycle, k, cycle, i
  real(c_double) :: predict ! 1: v^(k+1/2) + (dt/2) a^k; 0: the half-step v^(k+1/2)
  character(len=32) :: arg, velocity

  steps_per_cycle = 1257
  if (command_argument_count() >= 1) then
    call get_command_argument(1, arg)
    read (arg, *) steps_per_cycle
  end if
  velocity = 'predicted'
  if (command_argument_count() >= 2) call get_command_argument(2, velocity)
  if (velocity /= 'predicted' .and. velocity /= 'half-step') then
    write (*, '(a)') 'usage: chain_central_difference [STEPS_PER_CYCLE [predicted|half-step]]'
    stop 2
  end if
  predict = merge(1.0_c_double, 0.0_c_double, velocity == 'predicted')
  period = 2.0_c_double * pi / omega
  dt = period / steps_per_cycle
  eps = 10.0_c_double * omega * dt
  n2 = real(n, c_double)**2

  call check(ctx%create(n))
  call check(ctx%set_law(FRICREG_LAW_QUINN, eps)) ! W = I and mun = 1: the defaults

  call cpu_time(cpu_start)
  u = 0.0_c_double
  v = 0.0_c_double
  t = 0.0_c_double
  call forces(t, v)                  ! a^0, f^0 at rest
  v = v + 0.5_c_double * dt * acc    ! v^(1/2)
  do cycle = 1, cycles
    D(cycle) = 0.0_c_double
    do k = 1, steps_per_cycle
      u = u + dt * v                 ! u^(k+1), v holds v^(k+1/2)
      t = real((cycle - 1) * steps_per_cycle + k, c_double) * dt
      f_old = f
      call forces(t, v + predict * 0.5_c_double * dt * acc) ! v^(k+1); acc is still a^k
      work = 0.0_c_double
      do i = 1, n
        work = work + dt * v(i) * 0.5_c_double * (f_old(i) + f(i))
      end do
      D(cycle) = D(cycle) - work / n
      v = v + dt * acc               ! v^(k+3/2)
    end do
  end do
  call cpu_time(cpu_end)

  write (*, '(a, i0, a, f4.2, a, f3.1, a)') 'chain: n = ', n, ', a = ', a, ', omega = ', &
    omega, ', law (4), central difference'
  write (*, '(a, f9.7, a, f9.7, a, i0, a, a, a)') 'dt = ', dt, ', eps = ', eps, ' (', &
    steps_per_cycle, ' steps per cycle), friction velocity ', trim(velocity)
  do cycle = 1, cycles
    write (*, '(a, i0, a, f10.7)') 'D, cycle ', cycle, ' = ', D(cycle)
  end do
  write (*, '(a, f10.7, a, f6.4, a, sp, f6.2, a)') 'D, 4th cycle = ', D(cycles), &
    ' (paper: ', D_paper, ', difference ', 100.0_c_double * (D(cycles) / D_paper - 1.0_c_double), &
    '%)'
  write (*, '(a, f8.5, a, i0, a)') 'cpu seconds = ', cpu_end - cpu_start, ' (', &
    cycles * steps_per_cycle, ' steps, one fricreg call each)'
  call ctx%destroy()
  if (abs(D(cycles) / D_paper - 1.0_c_double) > 0.01_c_double) then
    write (*, '(a)') 'FAIL: the 4th cycle is more than 1% from the paper''s D = 0.0105'
    stop 1
  end if

contains

  !> a_free, f and the accelerations acc = a_free + f at time tt, with contact velocities vel.
  subroutine forces(tt, vel)
    real(c_double), intent(in) :: tt, vel(n)
    G = a * sin(omega * tt)
    a_free(1) = -n2 * (u(1) - u(2)) + n * G
    do i = 2, n - 1
      a_free(i) = -n2 * (-u(i - 1) + 2.0_c_double * u(i) - u(i + 1))
    end do
    a_free(n) = -n2 * (-u(n - 1) + 2.0_c_double * u(n))
    zdot = vel
    call check(ctx%eval(zdot, a_free, f))
    acc = a_free + f
  end subroutine forces

  subroutine check(status)
    integer(c_int), intent(in) :: status
    if (status /= FRICREG_OK) then
      write (*, '(a, a)') 'fricreg: ', ctx%errmsg()
      stop 1
    end if
  end subroutine check

end program chain_central_difference
