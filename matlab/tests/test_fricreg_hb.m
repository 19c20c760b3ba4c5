% SPDX-License-Identifier: GPL-3.0-or-later
function failures = test_fricreg_hb()
%TEST_FRICREG_HB  Harmonic balance through the gateway (fricreg_harmonic_balance and
%   fricreg_hb_*) against closed forms: a model whose Jenkins element sticks responds as the
%   linear structure with the element's spring, X_1 = (K + kt J'J - Omega^2 M + i Omega C) \
%   (pc - i ps), every other harmonic zero (one solve and a branch); a backbone below the first
%   slip is the stuck linear mode (omega_k, zeta_k = phi' C phi / (2 omega_k) with modal
%   damping: Krack 2015, Sec. 3), its motion a phi cos(omega t). NLvib's 3-dof chain through
%   fricreg_nlvib_frf equals the same model built through the gateway's lower-level commands
%   (fricreg_mex 'hb_*', with fricreg_hb_set_jenkins rather than fricreg_hb_add_elements) bit
%   for bit, its layout NLvib's (SRC/HB_residual.m: [X0; Xc1; Xs1; ...; Om], n rows a block); its
%   unilateral spring against the linear closed forms where it never or always touches; and,
%   where the environment's FRICREG_NLVIB names an NLvib checkout, NLvib's own HB_residual at
%   the adapter's X.
cases = {'stuck_solve_is_linear', @stuck_solve_is_linear
         'stuck_branch_is_linear', @stuck_branch_is_linear
         'sparse_equals_dense', @sparse_equals_dense
         'newton_solvers_agree', @newton_solvers_agree
         'receptances_agree', @receptances_agree
         'elements_as_cell', @elements_as_cell
         'backbone_linear_limit', @backbone_linear_limit
         'backbone_at_amplitudes', @backbone_at_amplitudes
         'chain_stability_and_peak', @chain_stability_and_peak
         'nlvib_chain_bit_for_bit', @nlvib_chain_bit_for_bit
         'nlvib_guess_and_object', @nlvib_guess_and_object
         'nlvib_layout', @nlvib_layout
         'nlvib_unilateral_spring', @nlvib_unilateral_spring
         'nlvib_unilateral_stability', @nlvib_unilateral_stability
         'nlvib_residual', @nlvib_residual};
failures = fricreg_test_run('hb', cases);
end

function [M, K, C, J, kt, mun] = two_masses()
% Two masses, a Jenkins element between them; C is not proportional to K + kt J'J.
M = [1.3 0; 0 0.7];
K = [2.385 -1.1; -1.1 1.9];
C = 0.031 * K + 0.012 * M + [0 0.004; 0.004 0];
J = [1 -1];
kt = 3.7;
mun = 0.8;
end

function X = stuck(M, K, C, J, kt, w, pc, ps)
X = (K + kt * (J' * J) - w^2 * M + 1i * w * C) \ (pc - 1i * ps);
end

function stuck_solve_is_linear()
% |q| ~ 1e-4 against the slip at mun/kt = 0.22: the element sticks all period.
[M, K, C, J, kt, mun] = two_masses();
pc = [1.2e-4; 0];
ps = [0; -3.1e-5];
h = fricreg_harmonic_balance(M, K, C, struct('type', 'jenkins', 'J', J, 'params', [kt mun]), ...
                             5, 'excitation', {pc, ps});
cleanup = onCleanup(@() fricreg_hb_free(h));
w = 1.37;
s = fricreg_hb_solve(h, w);
X = stuck(M, K, C, J, kt, w, pc, ps);
fricreg_test_check(s.x(:, 2:3), [real(X), -imag(X)], 1e-12, 'x_1', max(abs(X)));
fricreg_test_check(s.x(:, [1 4:end]), zeros(2, 9), 1e-16, 'other harmonics', max(abs(X)));
fricreg_test_check(s.q, J * s.x, 1e-12, 'q = J x', max(abs(X)));
if ~isequal(size(s.q), [1 11]) || ~isempty(s.stable) || ~isnan(s.mu_max) || s.omega ~= w
    error('test:hb', 'solve: shapes or stability off');
end
% from the solution as a guess: the same solution, bit for bit
s2 = fricreg_hb_solve(h, w, s.q);
fricreg_test_check(s2.x, s.x, 1e-13, 'from the guess', max(abs(X)));
end

function stuck_branch_is_linear()
% Each point of a branch of the stuck model: rms_k = |X_1,k| / sqrt(2), to Newton's 1e-10.
[M, K, C, J, kt, mun] = two_masses();
pc = [1.2e-4; 0];
ps = [0; -3.1e-5];
h = fricreg_harmonic_balance(M, K, C, struct('type', 'jenkins', 'J', J, 'params', [kt mun]), ...
                             3, 'excitation', {pc, ps}, 'stability', true);
cleanup = onCleanup(@() fricreg_hb_free(h));
r = fricreg_hb_frequency_response(h, 0.5, 2.5);
n = numel(r.omega);
if n < 10 || r.omega(1) ~= 0.5 || r.omega(end) ~= 2.5 || ~isequal(size(r.x), [n 2 7]) || ...
   ~isequal(size(r.rms), [n 2]) || ~islogical(r.stable) || ~all(r.stable) || ...
   ~isempty(r.bifurcations) || ~all(r.level == 1)
    error('test:hb', 'branch: %d points, shapes or stability', n);
end
for p = 1:n
    X = stuck(M, K, C, J, kt, r.omega(p), pc, ps);
    fricreg_test_check(r.rms(p, :), abs(X') / sqrt(2), 1e-9, sprintf('rms at point %d', p));
    fricreg_test_check(squeeze(r.x(p, :, 2:3)), [real(X), -imag(X)], 1e-9, ...
                       sprintf('x_1 at point %d', p), max(abs(X)));
end
% a stable linear response: every multiplier inside the unit circle
if any(r.mu_max >= 1)
    error('test:hb', 'mu_max %g', max(r.mu_max));
end
end

function sparse_equals_dense()
% The same model with sparse M, K, C (KLU) and dense (fricreg's LU), sliding: to 1e-10.
[M, K, C, J, kt, mun] = two_masses();
el = struct('type', 'jenkins', 'J', J, 'params', [kt mun]);
dense = fricreg_harmonic_balance(M, K, C, el, 5, 'excitation', [0.9; 0]);
cd = onCleanup(@() fricreg_hb_free(dense));
sp = fricreg_harmonic_balance(sparse(M), sparse(K), sparse(C), el, 5, 'excitation', [0.9; 0]);
cs = onCleanup(@() fricreg_hb_free(sp));
a = fricreg_hb_solve(dense, 3.3); % near the second mode, where J phi is large: slipping
b = fricreg_hb_solve(sp, 3.3);
fricreg_test_check(b.x, a.x, 1e-10, 'sparse x', max(abs(a.x(:))));
if max(max(abs(a.x(:, 6:7)))) < 1e-4 % a_3, b_3: Jenkins gives odd harmonics
    error('test:hb', 'the element does not slip: no third harmonic');
end
end

function newton_solvers_agree()
% Newton's matrix by its capacitance and by the dense LU, sliding: to 1e-10 (the C library's
% tests/hb/test_hb_capacitance.c checks every element type).
[M, K, C, J, kt, mun] = two_masses();
h = fricreg_harmonic_balance(M, K, C, struct('type', 'jenkins', 'J', J, 'params', [kt mun]), ...
                             5, 'excitation', [0.9; 0]);
cleanup = onCleanup(@() fricreg_hb_free(h));
fricreg_hb_set(h, 'solver', 'dense');
a = fricreg_hb_solve(h, 3.3);
fricreg_hb_set(h, 'solver', 'capacitance');
b = fricreg_hb_solve(h, 3.3);
fricreg_test_check(b.x, a.x, 1e-10, 'capacitance x', max(abs(a.x(:))));
end

function receptances_agree()
% D_h solved through the modes of (K, M) and by the LU, Rayleigh damping, sliding: to 1e-10
% (the C library's tests/hb/test_hb_receptance.c checks every harmonic's receptance).
[M, K, ~, J, kt, mun] = two_masses();
h = fricreg_harmonic_balance(M, K, [], struct('type', 'jenkins', 'J', J, 'params', [kt mun]), ...
                             5, 'excitation', [0.9; 0], 'rayleigh', [0.01 0.002]);
cleanup = onCleanup(@() fricreg_hb_free(h));
fricreg_hb_set(h, 'receptance', 'lu');
a = fricreg_hb_solve(h, 3.3);
fricreg_hb_set(h, 'receptance', 'modes');
b = fricreg_hb_solve(h, 3.3);
fricreg_test_check(b.x, a.x, 1e-10, 'modes x', max(abs(a.x(:))));
end

function elements_as_cell()
% A cell of blocks of two types (fields in other orders): a Jenkins element that sticks and a
% linear spring (a marched type), both on dof 2 - dof 1: the linear response with kt + k.
[M, K, C, J, kt, mun] = two_masses();
blocks = {struct('type', 'jenkins', 'J', J, 'params', [kt mun]), ...
          struct('params', 0.45, 'J', 2 * J, 'type', 'spring')};
h = fricreg_harmonic_balance(M, K, C, blocks, 3, 'excitation', {[0; 2e-4], [1e-4; 0]});
cleanup = onCleanup(@() fricreg_hb_free(h));
s = fricreg_hb_solve(h, 2.1);
X = (K + (kt + 4 * 0.45) * (J' * J) - 2.1^2 * M + 2.1i * C) \ ([0; 2e-4] - 1i * [1e-4; 0]);
fricreg_test_check(s.x(:, 2:3), [real(X), -imag(X)], 1e-10, 'x_1', max(abs(X)));
if ~isequal(size(s.q), [2 7])
    error('test:hb', 'q: a row per block''s row');
end
end

function [phi, w] = stuck_mode(M, K0, k)
[V, L] = eig(K0, M);
[l, i] = sort(diag(L));
phi = V(:, i(k));
phi = phi / sqrt(phi' * M * phi);
w = sqrt(l(k));
end

function backbone_linear_limit()
[M, K, C, J, kt, mun] = two_masses();
h = fricreg_harmonic_balance(M, K, C, struct('type', 'jenkins', 'J', J, 'params', [kt mun]), 5);
cleanup = onCleanup(@() fricreg_hb_free(h));
top = [200 5]; % J phi is -0.0103 for mode 1, -1.48 for mode 2: the slip at |J phi| a = mun/kt
for mode = 1:2
    [phi, wk] = stuck_mode(M, K + kt * (J' * J), mode);
    b = fricreg_hb_backbone(h, mode, 1e-3, top(mode), 12, 'damping', 'modal', ...
                            'through_folds', false);
    if ~isequal(size(b.amplitude), [12 1]) || ~isequal(size(b.x), [12 2 11]) || ...
       ~isequal(size(b.harmonic_energy), [12 6]) || ~isstruct(b.special_points)
        error('test:hb', 'backbone shapes');
    end
    fricreg_test_check(b.amplitude, logspace(-3, log10(top(mode)), 12)', 1e-13, 'amplitudes');
    fricreg_test_check(b.omega(1), wk, 1e-13, 'omega_k');
    fricreg_test_check(b.zeta(1), phi' * C * phi / (2 * wk), 1e-12, 'zeta_k');
    x1 = squeeze(b.x(1, :, 2))';
    fricreg_test_check(abs(phi' * M * x1), b.amplitude(1), 1e-12, 'phi'' M X_1 = a');
    fricreg_test_check(x1, b.amplitude(1) * phi * sign(phi' * M * x1), 1e-10, 'X_1 = a phi', ...
                       b.amplitude(1));
    fricreg_test_check(b.harmonic_energy(1, :), [0 1 0 0 0 0], 0, 'energy', 1e-12);
    % the element slips at the top: softer and more damped than the stuck mode
    if ~(b.omega(end) < wk * (1 - 1e-4) && b.zeta(end) > b.zeta(1) * (1 + 1e-3))
        error('test:hb', 'mode %d: no slip at a = %g (omega %g of %g)', mode, top(mode), ...
              b.omega(end), wk);
    end
    % through the folds (the default): the same ends, its first point the stuck mode's
    c = fricreg_hb_backbone(h, mode, 1e-3, top(mode), 12, 'damping', 'modal');
    fricreg_test_check(c.amplitude([1 end]), b.amplitude([1 end]), 1e-12, 'ends');
    fricreg_test_check(c.omega(1), wk, 1e-13, 'omega_k, through folds');
    fricreg_test_check(c.omega(end), b.omega(end), 1e-8, 'omega at a1, through folds');
end
end

function backbone_at_amplitudes()
[M, K, C, J, kt, mun] = two_masses();
h = fricreg_harmonic_balance(M, K, [], struct('type', 'jenkins', 'J', J, 'params', [kt mun]), ...
                             5, 'rayleigh', [0.012 0.031]);
cleanup = onCleanup(@() fricreg_hb_free(h));
a = [0.0123 0.05 0.7 1.9 3.3];
b = fricreg_hb_backbone_at(h, 1, a, 'damping', 'modal');
fricreg_test_check(b.amplitude, a', 1e-14, 'amplitudes');
% below the slip (a < 21) the stuck mode, its modal damping from Rayleigh's C = a0 M + a1 K
[phi, wk] = stuck_mode(M, K + kt * (J' * J), 1);
fricreg_test_check(b.omega, wk * ones(5, 1), 1e-13, 'omega_k');
fricreg_test_check(b.zeta, phi' * (0.012 * M + 0.031 * K) * phi / (2 * wk) * ones(5, 1), ...
                   1e-12, 'zeta_k');
end

function h = chain_low_level(stability)
% NLvib's chain through the gateway's commands, one C call each: the Jenkins elements by
% fricreg_hb_set_jenkins (fricreg_nlvib_frf adds them by fricreg_hb_add_elements).
sys = fricreg_test_nlvib_chain();
h = fricreg_mex('hb_create', 3, 2, 7);
fricreg_mex('hb_set_matrix', h, 'mass', sys.M);
fricreg_mex('hb_set_matrix', h, 'stiffness', sys.K);
fricreg_mex('hb_set_matrix', h, 'damping', sys.D);
fricreg_mex('hb_set_jenkins', h, [1 0 0; -1 1 0], [20 20], [1 1]);
fricreg_mex('hb_set_excitation', h, real(sys.Fex1), -imag(sys.Fex1));
fricreg_mex('hb_set_stability', h, stability, 'auto');
end

function chain_stability_and_peak()
h = chain_low_level(true);
cleanup = onCleanup(@() fricreg_mex('free', h));
[omega, ~, rms, ~, stable, mu_max, bif] = fricreg_mex('hb_continue', h, 0.5, 2);
n = numel(omega);
if ~isequal(size(stable), [n 1]) || ~islogical(stable) || ~isequal(size(mu_max), [n 1])
    error('test:hb', 'stability shapes');
end
if any(stable ~= (mu_max <= 1 + 1e-6))
    error('test:hb', 'stable disagrees with mu_max');
end
for k = 1:numel(bif)
    if ~any(strcmp(bif(k).kind, {'TP', 'BP', 'PD', 'NS'})) || bif(k).point < 1 || ...
       bif(k).point >= n || ~isequal(size(bif(k).rms), [1 3])
        error('test:hb', 'bifurcation %d', k);
    end
end
for dof = 1:3
    [w, peak] = fricreg_hb_peak(h, dof);
    [top, at] = max(rms(:, dof));
    if ~(peak >= top && peak <= top * (1 + 1e-2) && abs(w - omega(at)) <= 0.05)
        error('test:hb', 'dof %d: peak %.9g at %.9g, points %.9g at %.9g', dof, peak, w, top, ...
              omega(at));
    end
end
end

function same = same_bits(a, b)
same = isequal(size(a), size(b)) && isequal(typecast(a(:), 'uint64'), typecast(b(:), 'uint64'));
end

function X = nlvib_layout_of(omega, x)
% NLvib's X (SRC/HB_residual.m: X(1:n) the means, X(n (2h - 1) + k) and X(n 2h + k) dof k's
% cos and sin amplitudes of harmonic h, Om last) from fricreg's x(point, dof, coefficient),
% element by element.
[npoints, n, nc] = size(x);
X = zeros(n * nc + 1, npoints);
for p = 1:npoints
    for k = 1:n
        X(k, p) = x(p, k, 1);
        for hh = 1:(nc - 1) / 2
            X(n * (2 * hh - 1) + k, p) = x(p, k, 2 * hh);
            X(n * 2 * hh + k, p) = x(p, k, 2 * hh + 1);
        end
    end
    X(end, p) = omega(p);
end
end

function nlvib_chain_bit_for_bit()
sys = fricreg_test_nlvib_chain();
[X, info] = fricreg_nlvib_frf(sys, 7, 0.5, 2, 'stability', true);
h = chain_low_level(true);
cleanup = onCleanup(@() fricreg_mex('free', h));
[omega, ~, rms, x, stable, mu_max, bif] = fricreg_mex('hb_continue', h, 0.5, 2);
if ~same_bits(X, nlvib_layout_of(omega, x)) || ~same_bits(info.rms, rms') || ...
   ~isequal(info.stable, stable') || ~same_bits(info.mu_max, mu_max') || ...
   ~isequal(info.bifurcations, bif)
    error('test:hb', 'the adapter''s branch differs from the lower-level one');
end
if size(X, 2) < 20 || X(end, 1) ~= 0.5 || X(end, end) ~= 2
    error('test:hb', '%d points from %g to %g', size(X, 2), X(end, 1), X(end, end));
end
% the elements slip near the resonances: harmonic 3 (X(n 5 + 1 : n 7, :)) is there, the
% branch is not the linear one
if max(max(abs(X(3 * 5 + 1:3 * 7, :)))) < 1e-3
    error('test:hb', 'no third harmonic along the branch');
end
end

function nlvib_guess_and_object()
% NLvib's own initial guess x0 (example 07: the stuck linear response at Om_s, in its layout),
% on an object with MechanicalSystem's properties: the branch of the lower-level continuation
% from q0 = J x0, bit for bit.
sys = fricreg_test_nlvib_chain();
obj = fricreg_test_system(sys);
n = 3;
H = 7;
Om_s = 0.5;
W = [1 0 0; -1 1 0]';
Q1 = (-Om_s^2 * sys.M + 1i * Om_s * sys.D + sys.K + 20 * (W * W')) \ sys.Fex1;
x0 = zeros((2 * H + 1) * n, 1);
x0(n + (1:2 * n)) = [real(Q1); -imag(Q1)];
X = fricreg_nlvib_frf(obj, H, Om_s, 2, 'x0', x0);
h = chain_low_level(false);
cleanup = onCleanup(@() fricreg_mex('free', h));
q0 = W' * reshape(x0, n, 2 * H + 1);
[omega, ~, ~, x] = fricreg_mex('hb_continue', h, Om_s, 2, q0);
if ~same_bits(X, nlvib_layout_of(omega, x))
    error('test:hb', 'from x0: the adapter''s branch differs from the lower-level one');
end
end

function nlvib_layout()
% NLvib's post-processing of X (its example 07, bench/nlvib/chain_jenkins.m) gives the RMS
% fricreg computed.
sys = fricreg_test_nlvib_chain();
[X, info] = fricreg_nlvib_frf(sys, 5, 2, 0.6);
n = 3;
Om = X(end, :);
if Om(1) ~= 2 || Om(end) ~= 0.6 || size(X, 1) ~= n * 11 + 1 || ~isempty(info.stable)
    error('test:hb', 'layout: %d rows, from %g to %g', size(X, 1), Om(1), Om(end));
end
for k = 1:n
    Qk = X(k:n:end - 1, :); % NLvib's example: Q1 = X(1:n:end-1, :), ...
    rms = sqrt(Qk(1, :).^2 + sum(Qk(2:end, :).^2) / 2);
    fricreg_test_check(rms, info.rms(k, :), 1e-14, sprintf('rms of dof %d', k));
end
end

function sys = example_03(gap)
% NLvib's example 03 (EXAMPLES/03_twoDOFoscillator_unilateralSpring): masses [1 1], springs
% ki = [0 1 1], dampers 0.03 ki, Fex1 = [0; 0.1], a unilateral spring of stiffness 100 on dof 1.
K = [1 -1; -1 2];
sys = struct('M', eye(2), 'K', K, 'D', 0.03 * K, 'Fex1', [0; 0.1]);
sys.nonlinear_elements = struct('type', 'unilateralSpring', 'stiffness', 1e2, 'gap', gap, ...
                                'force_direction', [1; 0]);
end

function nlvib_unilateral_spring()
% Never touching (gap 50): the linear response without the spring. Always pressed (gap -50:
% the force k (q - gap) > 0 all period): the linear response with it, and the mean
% (K + k w w') x0 = k gap w from the preload -k gap.
w = [1; 0];
k = 1e2;
for gap = [50 -50]
    sys = example_03(gap);
    [X, info] = fricreg_nlvib_frf(sys, 5, 0.8, 0.5);
    K0 = sys.K + (gap < 0) * k * (w * w');
    x0 = K0 \ ((gap < 0) * k * gap * w);
    for p = 1:size(X, 2)
        Om = X(end, p);
        Q1 = (K0 - Om^2 * sys.M + 1i * Om * sys.D) \ sys.Fex1;
        fricreg_test_check(X(1:2, p), x0, 1e-12, sprintf('gap %g: X0', gap), max(abs(x0)) + 1);
        fricreg_test_check(X(3:6, p), [real(Q1); -imag(Q1)], 1e-9, sprintf('gap %g: X1', gap), ...
                           max(abs(Q1)));
        fricreg_test_check(X(7:end - 1, p), zeros(size(X, 1) - 7, 1), 1e-9, ...
                           sprintf('gap %g: higher harmonics', gap), max(abs(Q1)));
    end
end
% touching part of the period (gap 1, example 03's): the lower-level build, bit for bit
sys = example_03(1);
X = fricreg_nlvib_frf(sys, 9, 0.8, 0.5);
h = fricreg_mex('hb_create', 2, 1, 9);
cleanup = onCleanup(@() fricreg_mex('free', h));
fricreg_mex('hb_set_matrix', h, 'mass', sys.M);
fricreg_mex('hb_set_matrix', h, 'stiffness', sys.K);
fricreg_mex('hb_set_matrix', h, 'damping', sys.D);
fricreg_mex('hb_add_elements', h, 'jenkins_normal', [1 0; 1 0], [1e2 0 1e2 -1e2 0]);
fricreg_mex('hb_set_excitation', h, [0; 0.1], [0; 0]);
[omega, ~, ~, x] = fricreg_mex('hb_continue', h, 0.8, 0.5);
if ~same_bits(X, nlvib_layout_of(omega, x)) || max(abs(X(1, :))) < 1e-3
    error('test:hb', 'example 03: the adapter differs from the lower-level build, or no contact');
end
end

function nlvib_unilateral_stability()
% Example 03's branch from 0.8 down to 0.5 rad/s folds twice (a hardening overhang): every
% point strictly between the two turning points is unstable (a saddle's multiplier past +1),
% as NLvib's own shooting finds there; the lower branch before the first fold is stable.
[X, info] = fricreg_nlvib_frf(example_03(1), 21, 0.8, 0.5, 'stability', true);
b = info.bifurcations;
tp = [b(strcmp({b.kind}, 'TP')).point];
if numel(tp) ~= 2 || ~all(info.stable(1:tp(1) - 1)) || any(info.stable(tp(1) + 1:tp(2)))
    error('test:hb', 'example 03: turning points after %s, stability %s', mat2str(tp), ...
          mat2str(find(diff(info.stable))));
end
if abs(X(end, tp(1)) - 0.6534) > 2e-3 || abs(X(end, tp(2)) - 0.7556) > 2e-3
    error('test:hb', 'example 03: folds at %g and %g', X(end, tp(1)), X(end, tp(2)));
end
end

function nlvib_residual()
% NLvib's own residual (SRC/HB_residual.m, its AFT at 2^12 samples a period) at the adapter's
% X, on NLvib's own ChainOfOscillators, with a complex Fex1: small as the samples' error where
% the conventions (layout, signs, Fex1's phase) agree, O(1) where one does not. Only where
% FRICREG_NLVIB names an NLvib checkout (it is not part of fricreg).
root = getenv('FRICREG_NLVIB');
if isempty(root)
    fprintf('     (skipped: FRICREG_NLVIB is not set)\n');
    return;
end
addpath(fullfile(root, 'SRC'), fullfile(root, 'SRC', 'MechanicalSystems'));
c = fricreg_test_nlvib_chain();
sys = ChainOfOscillators([1 1 1], 0.02 * [1 1 1 1], [1 1 1 1], c.nonlinear_elements, ...
                         [0; 0.6 - 0.8i; 0.3i]);
X = fricreg_nlvib_frf(sys, 7, 0.5, 2);
e3 = example_03(1);
osc = ChainOfOscillators([1 1], 0.03 * [0 1 1], [0 1 1], e3.nonlinear_elements, e3.Fex1);
X3 = fricreg_nlvib_frf(osc, 21, 0.8, 0.5);
worst = [0 0];
for p = 1:size(X, 2)
    worst(1) = max(worst(1), max(abs(HB_residual(X(:, p), sys, 7, 2^12, 'FRF'))));
end
for p = 1:size(X3, 2)
    worst(2) = max(worst(2), max(abs(HB_residual(X3(:, p), osc, 21, 2^12, 'FRF'))));
end
fprintf('     NLvib''s residual at fricreg''s X: %.3g (chain), %.3g (example 03)\n', worst);
if any(worst > 1e-4)
    error('test:hb', 'NLvib''s residual %g, %g', worst);
end
end
