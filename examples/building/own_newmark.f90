! SPDX-License-Identifier: GPL-3.0-or-later
! own_newmark.f90 — the ten-storey building (docs/structural.md) through the user's OWN
! Newmark integrator, with fricreg only for the friction: a type(fricreg_context) holds the law,
! eps, the slip loads and W = J M^-1 J^T, and each step's forces come from its solve_step
! (C's fricreg_ctx_solve_step: Newton on the exact tangent with the stick guess, the stop at
! zdot = 0 and the line search). No fricreg_structure. K_eff is factored by LAPACK (dpotrf),
! as a structural code factors its own.
!
! The model is examples/building's (building_model.h: storey mass 1e5 kg, stiffness 1e8 N/m,
! 5 % Rayleigh damping, a damper on each storey drift slipping at 5 % of the weight above),
! built in code as building.f90 builds it; the ground record and the Rayleigh coefficients are
! read from make_building's files. Newmark average acceleration (beta = 1/4, gamma = 1/2),
! dt = 0.01 s, 15 s, law (4).
!
! The step (docs/structural.md, "Your own Newmark with fricreg"), with x the end's acceleration:
!   u_pred = u + dt v + (1/2 - beta) dt^2 a,  v_pred = v + (1 - gamma) dt a,
!   K_eff x = p1 - C v_pred - K u_pred + J^T f1,   K_eff = M + gamma dt C + beta dt^2 K,
! so with y = K_eff^-1 (p1 - C v_pred - K u_pred) and X = K_eff^-1 J^T (once):
!   zdot(f1) = J v_pred + gamma dt (J y + W_eff f1),   a_free(f1) = J y - (W - W_eff) f1,
! W_eff = J X; the context solves for f1, then x = y + X f1, u1 = u_pred + beta dt^2 x,
! v1 = v_pred + gamma dt x.
!
! Prints the peak roof displacement (the step ends and the turning points between them, as
! fricreg_structure takes it), the dampers' total energy (trapezoidal rule on the
! displacement increments, as fricreg_structure's balance), Newton's iterations per step (mean,
! max) and the steps that did not converge.
!
!   usage: own_newmark DIR EPS [plain]   (DIR as written by make_building; plain: Newton
!          without the safeguards, FRICREG_STEP_PLAIN, for comparison)
program own_newmark
  use fricreg
  implicit none
  integer, parameter :: n = 10, nrec = 10001, max_iter = 50
  real(c_double), parameter :: mass = 1e5_c_double, stiffness = 1e8_c_double, &
                               g = 9.81_c_double, dt = 0.01_c_double, t_end = 15.0_c_double, &
                               beta = 0.25_c_double, gamma = 0.5_c_double
  type(fricreg_context) :: ctx
  real(c_double) :: M(n, n), Ks(n, n), Cd(n, n), J(n, n), Keff(n, n), X(n, n), W(n, n), Weff(n, n)
  real(c_double) :: mun(n), ag(nrec), a0, a1, eps, tol
  real(c_double) :: u(n), v(n), a(n), f(n), f1(n), up(n), vp(n), y(n), xa(n), u1(n), v1(n)
  real(c_double) :: zstart(n), zpred(n), apred(n), dz(n), p1(n)
  real(c_double) :: peak_roof, dissipation
  character(len=:), allocatable :: dir
  character(len=16) :: mode
  integer :: i, k, length, nsteps, iters, total, most, failures, flags, info
  logical :: converged
  external :: dpotrf, dpotrs ! LAPACK

  call get_command_argument(1, length=length)
  if (length == 0) error stop 'usage: own_newmark DIR EPS [plain]'
  allocate (character(len=length) :: dir)
  call get_command_argument(1, dir)
  call get_command_argument(2, mode)
  read (mode, *, iostat=info) eps
  if (info /= 0 .or. .not. eps > 0.0_c_double) error stop 'usage: own_newmark DIR EPS [plain]'
  call get_command_argument(3, mode)
  flags = merge(FRICREG_STEP_PLAIN, 0_c_int, mode == 'plain')

  M = 0.0_c_double
  Ks = 0.0_c_double
  J = 0.0_c_double
  do i = 1, n
    M(i, i) = mass
    Ks(i, i) = merge(2.0_c_double * stiffness, stiffness, i < n)
    J(i, i) = 1.0_c_double ! damper i: u_i - u_(i-1)
    if (i > 1) then
      Ks(i, i - 1) = -stiffness
      Ks(i - 1, i) = -stiffness
      J(i, i - 1) = -1.0_c_double
    end if
    mun(i) = 0.05_c_double * g * mass * real(n - i + 1, c_double)
  end do
  call read_record(dir // '/ground.txt', ag)
  call read_rayleigh(dir // '/rayleigh.txt', a0, a1)
  Cd = a0 * M + a1 * Ks

  ! K_eff = L L^T (LAPACK), X = K_eff^-1 J^T, W_eff = J X; W = J M^-1 J^T (M diagonal).
  Keff = M + gamma * dt * Cd + beta * dt * dt * Ks
  call dpotrf('L', n, Keff, n, info)
  if (info /= 0) error stop 'own_newmark: K_eff is not positive definite'
  X = transpose(J)
  call dpotrs('L', n, n, Keff, n, X, n, info)
  Weff = matmul(J, X)
  Weff = 0.5_c_double * (Weff + transpose(Weff)) ! symmetric to the last bit
  do i = 1, n
    W(:, i) = J(:, i) / mass
  end do
  W = matmul(W, transpose(J))

  call check(ctx%create(n), 'create')
  call check(ctx%set_law(FRICREG_LAW_QUINN, eps), 'set_law')
  call check(ctx%set_bounds(mun), 'set_bounds')
  call check(ctx%set_coupling_dense(W), 'set_coupling_dense')
  tol = 1e-10_c_double * 2.0_c_double * maxval(mun) ! force units, |J|^T mun's scale

  u = 0.0_c_double
  v = 0.0_c_double
  f = 0.0_c_double
  a = -ag(1) ! M a = p(0) = -M 1 a_g(0), at rest with no friction force
  nsteps = nint(t_end / dt)
  peak_roof = 0.0_c_double
  dissipation = 0.0_c_double
  total = 0
  most = 0
  failures = 0
  do k = 1, nsteps
    p1 = 0.0_c_double ! the record's sample at t = k dt (its step is 1e-3 s); none after 10 s
    if (10 * k + 1 <= nrec) p1 = -mass * ag(10 * k + 1)
    up = u + dt * v + (0.5_c_double - beta) * dt * dt * a
    vp = v + (1.0_c_double - gamma) * dt * a
    y = p1 - matmul(Cd, vp) - matmul(Ks, up)
    call dpotrs('L', n, 1, Keff, n, y, n, info)
    apred = matmul(J, y)
    zpred = matmul(J, vp) + gamma * dt * apred
    zstart = matmul(J, v)
    f1 = f
    call check(ctx%solve_step(zstart, zpred, apred, W, Weff, gamma * dt, tol, max_iter, f1, &
                              iters, converged, flags), 'solve_step')
    total = total + iters
    most = max(most, iters)
    if (.not. converged) failures = failures + 1
    xa = y + matmul(X, f1)
    u1 = up + beta * dt * dt * xa
    v1 = vp + gamma * dt * xa
    dz = matmul(J, u1 - u)
    dissipation = dissipation - sum(dz * (0.5_c_double * f + 0.5_c_double * f1))
    peak_roof = max(peak_roof, abs(u1(n)), turning_point(u(n), v(n), v1(n)))
    u = u1
    v = v1
    a = xa
    f = f1
  end do

  write (*, '(a, 1x, es26.17e3)') 'peak_roof_displacement_m', peak_roof
  write (*, '(a, 1x, es26.17e3)') 'damper_energy_total_J', dissipation
  write (*, '(a, 1x, es26.17e3)') 'newton_iterations_mean', real(total, c_double) / nsteps
  write (*, '(a, 1x, i0)') 'newton_iterations_max', most
  write (*, '(a, 1x, i0)') 'newton_failures', failures
  write (*, '(a, 1x, i0)') 'steps', nsteps
  call ctx%destroy()
  deallocate (dir) ! a leak checker counts a main program's allocatables at exit

contains

  !> |u| at the turning point inside a step from (u0, v0) to velocity v1, 0 if v keeps its sign.
  !> Average acceleration moves u along its own quadratic, u0 + v0 tau + (v1 - v0) tau^2 / (2 dt),
  !> whose vertex is at tau = v0 dt / (v0 - v1).
  pure real(c_double) function turning_point(u0, v0, v1)
    real(c_double), intent(in) :: u0, v0, v1
    turning_point = 0.0_c_double
    if (v0 * v1 < 0.0_c_double) turning_point = abs(u0 + 0.5_c_double * dt * v0 * v0 / (v0 - v1))
  end function turning_point

  !> The ground acceleration record: lines "t a_g" after '#' comment lines (make_building's).
  subroutine read_record(path, ag)
    character(len=*), intent(in) :: path
    real(c_double), intent(out) :: ag(:)
    character(len=256) :: line
    real(c_double) :: t
    integer :: unit, ios, k
    open (newunit=unit, file=path, status='old', action='read', iostat=ios)
    if (ios /= 0) error stop 'own_newmark: cannot open ground.txt (run make_building DIR)'
    k = 0
    do while (k < size(ag))
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) error stop 'own_newmark: ground.txt is short'
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
    if (ios /= 0) error stop 'own_newmark: cannot read rayleigh.txt (run make_building DIR)'
    close (unit)
  end subroutine read_rayleigh

  subroutine check(status, what)
    integer(c_int), intent(in) :: status
    character(len=*), intent(in) :: what
    if (status == FRICREG_OK) return
    write (*, '(a, a, a, a)') 'own_newmark: ', what, ': ', ctx%errmsg()
    error stop 1
  end subroutine check

end program own_newmark
