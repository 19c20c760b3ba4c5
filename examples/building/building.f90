! SPDX-License-Identifier: GPL-3.0-or-later
! building.f90 — the ten-storey building (docs/structural.md) from Fortran, through
! type(fricreg_structure) of module fricreg: Newmark average acceleration, dt = 0.01 s,
! eps = 0.01 m/s, 15 s (10 s of ground motion, 5 s free), law (4). Prints what building.c
! prints: the peak roof displacement, each damper's energy and their total, Newton's
! iterations per step (mean, max) and failures, and the energy balance.
!
! The structure is built in code (M, K, J and the slip loads: storey mass 1e5 kg, stiffness
! 1e8 N/m, a damper on each storey drift slipping at 5 % of the weight above), in Fortran's
! order: J(i, k) = d zdot_i / d u'_k. The ground acceleration record and the Rayleigh
! coefficients are read from the files make_building writes, as a structural code reads its
! accelerogram: computed here, they would not be the C program's doubles, since gfortran -O2
! vectorizes a loop of sin with glibc's vector sin (libmvec, a few ulp) and evaluates constant
! expressions with its own correctly rounded one, where C calls libm's scalar sin; 6644 of the
! 10001 samples then differ in their last bits. Read, they are the same doubles, they reach the
! same C calls in the same order, and the numbers equal the CLI's summary bit for bit (test
! example_building_fortran).
!
!   usage: building_fortran DIR [DT [EPS]]   (DIR as written by make_building; defaults
!          0.01 s and 0.01 m/s)
program building
  use fricreg
  implicit none
  integer, parameter :: n = 10, nrec = 10001
  real(c_double), parameter :: mass = 1e5_c_double, stiffness = 1e8_c_double, &
                               g = 9.81_c_double, dt_rec = 1e-3_c_double, t_end = 15.0_c_double
  type(fricreg_structure) :: st
  real(c_double) :: M(n, n), K(n, n), J(n, n), mun(n), ag(nrec), a0, a1, dt, eps
  character(len=:), allocatable :: dir
  integer :: i, length

  call get_command_argument(1, length=length)
  if (length == 0) error stop 'usage: building_fortran DIR [DT [EPS]] (DIR: make_building DIR)'
  allocate (character(len=length) :: dir)
  call get_command_argument(1, dir)
  dt = argument(2, 0.01_c_double)
  eps = argument(3, 0.01_c_double)
  M = 0.0_c_double
  K = 0.0_c_double
  J = 0.0_c_double
  do i = 1, n
    M(i, i) = mass
    K(i, i) = merge(2.0_c_double * stiffness, stiffness, i < n) ! the top floor has one spring
    J(i, i) = 1.0_c_double                                       ! damper i: u_i - u_(i-1)
    if (i > 1) then
      K(i, i - 1) = -stiffness
      K(i - 1, i) = -stiffness
      J(i, i - 1) = -1.0_c_double
    end if
    mun(i) = 0.05_c_double * g * mass * real(n - i + 1, c_double)
  end do
  call read_record(dir // '/ground.txt', ag)
  call read_rayleigh(dir // '/rayleigh.txt', a0, a1)

  call check(st%create(n, n), 'create')
  call check(st%set_mass(M), 'set_mass')
  call check(st%set_stiffness(K), 'set_stiffness')
  call check(st%set_rayleigh(a0, a1), 'set_rayleigh')
  call check(st%set_contacts(J), 'set_contacts')
  call check(st%set_bounds(mun), 'set_bounds')
  call check(st%set_influence([(1.0_c_double, i = 1, n)]), 'set_influence')
  call check(st%set_ground_accel(ag, dt_rec), 'set_ground_accel')
  call check(st%set_law(FRICREG_LAW_QUINN, eps), 'set_law') ! Newmark is the default scheme
  call run()
  call report()
  call st%destroy()
  deallocate (dir) ! the end of a program frees nothing: a leak checker would report it

contains

  !> Command-line argument k as a number, or default if it is absent.
  real(c_double) function argument(k, default)
    integer, intent(in) :: k
    real(c_double), intent(in) :: default
    character(len=64) :: text
    integer :: length, ios
    argument = default
    call get_command_argument(k, text, length)
    if (length == 0) return
    read (text, *, iostat=ios) argument
    if (ios /= 0 .or. .not. argument > 0.0_c_double) error stop 'usage: building_fortran DIR [DT [EPS]]'
  end function argument

  !> The ground acceleration record: lines "t a_g" after '#' comment lines, nrec of them, at
  !> t = 0, dt_rec, ... (as make_building writes it).
  subroutine read_record(path, ag)
    character(len=*), intent(in) :: path
    real(c_double), intent(out) :: ag(:)
    character(len=256) :: line
    real(c_double) :: t
    integer :: unit, ios, k
    open (newunit=unit, file=path, status='old', action='read', iostat=ios)
    if (ios /= 0) error stop 'building_fortran: cannot open ground.txt (run make_building DIR)'
    k = 0
    do while (k < size(ag))
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) error stop 'building_fortran: ground.txt is short'
      if (line(1:1) == '#') cycle
      k = k + 1
      read (line, *) t, ag(k)
    end do
    close (unit)
  end subroutine read_record

  !> a0, a1 of 5 % Rayleigh damping in modes 1 and 2 (1/s, s), one line "a0,a1".
  subroutine read_rayleigh(path, a0, a1)
    character(len=*), intent(in) :: path
    real(c_double), intent(out) :: a0, a1
    integer :: unit, ios
    open (newunit=unit, file=path, status='old', action='read', iostat=ios)
    if (ios == 0) read (unit, *, iostat=ios) a0, a1
    if (ios /= 0) error stop 'building_fortran: cannot read rayleigh.txt (run make_building DIR)'
    close (unit)
  end subroutine read_rayleigh

  subroutine check(status, what)
    integer(c_int), intent(in) :: status
    character(len=*), intent(in) :: what
    if (status == FRICREG_OK) return
    write (*, '(a, a, a, a)') 'building: ', what, ': ', st%errmsg()
    error stop 1
  end subroutine check

  !> Steps to t_end. Step k ends at k dt exactly: each is one step of t_k - t, since
  !> k dt - (k - 1) dt may exceed dt by a rounding (run would add a tiny step).
  subroutine run()
    real(c_double) :: t, t1
    integer :: k, nsteps
    nsteps = ceiling(t_end / dt * (1.0_c_double - 1e-12_c_double))
    do k = 1, nsteps
      t1 = merge(t_end, real(k, c_double) * dt, k == nsteps)
      call check(st%get_value(FRICREG_SVALUE_TIME, t), 'get_value')
      call check(st%run(t1 - t, t1), 'run')
    end do
  end subroutine run

  !> The peak roof displacement is the structure's own max |u| over the run, turning points
  !> between the step ends included (a maximum of the step ends alone falls short).
  subroutine report()
    real(c_double) :: D(n), peak(n), total, input, residual
    integer(c_int64_t) :: steps, iterations, most, failures
    character(len=*), parameter :: real_line = '(a, 1x, es26.17e3)', int_line = '(a, 1x, i0)'
    call check(st%get_peak_displacement(peak), 'get_peak_displacement')
    call check(st%get_dissipation(D), 'get_dissipation')
    call check(st%get_value(FRICREG_SVALUE_FRICTION, total), 'get_value')
    call check(st%get_value(FRICREG_SVALUE_INPUT, input), 'get_value')
    call check(st%get_value(FRICREG_SVALUE_RESIDUAL, residual), 'get_value')
    call check(st%get_stat(FRICREG_SSTAT_STEPS, steps), 'get_stat')
    call check(st%get_stat(FRICREG_SSTAT_NEWTON_ITERATIONS, iterations), 'get_stat')
    call check(st%get_stat(FRICREG_SSTAT_NEWTON_MAX, most), 'get_stat')
    call check(st%get_stat(FRICREG_SSTAT_NEWTON_FAILURES, failures), 'get_stat')
    write (*, real_line) 'peak_roof_displacement_m', peak(n)
    do i = 1, n
      write (*, '(a, 1x, i0, 1x, es26.17e3)') 'damper_energy_J', i, D(i)
    end do
    write (*, real_line) 'damper_energy_total_J', total
    write (*, real_line) 'newton_iterations_mean', real(iterations, c_double) / real(steps, c_double)
    write (*, int_line) 'newton_iterations_max', most
    write (*, int_line) 'newton_failures', failures
    write (*, real_line) 'energy_input_J', input
    write (*, real_line) 'energy_residual_J', residual
    write (*, real_line) 'energy_residual_over_input', residual / input
  end subroutine report

end program building
