% SPDX-License-Identifier: GPL-3.0-or-later
% chain_jenkins.m -- NLvib's frequency response of the 3-dof chain with two Jenkins elements,
% the reference of bench/nlvib_chain.sh (run there; needs NLvib, M. Krack and J. Gross,
% https://github.com/maltekrack/NLvib, which is not part of fricreg).
%
% The system of NLvib's example 07 without its cubic and unilateral springs: unit masses and
% springs, ground-1-2-3, dampers 0.02 times the springs, force cos(Omega t) on dof 2; Jenkins
% elements (NLvib's elasticDryFriction, hysteretic, N = 2^10 samples a period) kt = 20, mu N =
% 1 between dof 1 and the ground and between dofs 1 and 2. Continued from Omega = 0.5 to 2 at
% H harmonics with example 07's step ds = 0.005 and NLvib's other defaults, from the stuck
% linear response, as the example does.
% Writes OUT, a CSV row Omega,rms_1,rms_2,rms_3 per point.
%
% octave --no-gui --quiet --eval "nlvib = 'PATH'; H = 7; out = 'nlvib.csv'; chain_jenkins"
addpath(fullfile(nlvib, 'SRC'));
addpath(fullfile(nlvib, 'SRC', 'MechanicalSystems'));
mi = [1 1 1];
ki = [1 1 1 1];
di = 0.02 * ki;
Fex1 = [0; 1; 0];
knl = 20; muN = 1;
W1 = [1; 0; 0];
W2 = [-1; 1; 0];
nonlinear_elements{1} = struct('type', 'elasticDryFriction', 'stiffness', knl, ...
    'friction_limit_force', muN, 'ishysteretic', true, 'force_direction', W1);
nonlinear_elements{2} = struct('type', 'elasticDryFriction', 'stiffness', knl, ...
    'friction_limit_force', muN, 'ishysteretic', true, 'force_direction', W2);
sys = ChainOfOscillators(mi, di, ki, nonlinear_elements, Fex1);
n = sys.n;
N = 2^10; Om_s = 0.5; Om_e = 2;
Q1 = (-Om_s^2 * sys.M + 1i * Om_s * sys.D + sys.K + knl * (W1 * W1' + W2 * W2')) \ Fex1;
x0 = zeros((2 * H + 1) * n, 1);
x0(n + (1:2 * n)) = [real(Q1); -imag(Q1)];
ds = 0.005;  % example 07's step, NLvib's other defaults
% NLvib's default solver options, spelled for Octave (its optimset(@fsolve) is MATLAB's)
Solopt = optimset(optimset('fsolve'), 'Display', 'off', 'Jacobian', 'on', 'MaxIter', 50);
tic;
[X, Solinfo] = solve_and_continue(x0, @(X) HB_residual(X, sys, H, N, 'FRF'), ...
    Om_s, Om_e, ds, struct(), {}, Solopt);
seconds = toc;
Om = X(end, :);
rms = zeros(n, numel(Om));
for k = 1:n
    c = X(k, :);  % the mean, then cosine and sine of each harmonic, n rows apart
    s = c.^2;
    for h = 1:H
        s = s + 0.5 * (X(n * (2 * h - 1) + k, :).^2 + X(n * 2 * h + k, :).^2);
    end
    rms(k, :) = sqrt(s);
end
fid = fopen(out, 'w');
fprintf(fid, '%.17g,%.17g,%.17g,%.17g\n', [Om; rms]);
fclose(fid);
iters = sum(Solinfo.NIT);
printf('NLvib H = %d: %d points, %d Newton iterations, %.2f s\n', H, numel(Om), iters, seconds);
