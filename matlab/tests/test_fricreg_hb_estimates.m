% SPDX-License-Identifier: GPL-3.0-or-later
function failures = test_fricreg_hb_estimates()
%TEST_FRICREG_HB_ESTIMATES  The harmonic-balance surfaces beyond a branch in the frequency:
%   Floquet multipliers against the stuck model's closed form (a linear system x' = A x, its
%   multipliers exp(2 pi eig(A) / Omega)); a branch in the excitation level against the
%   linearity of the stuck response and against point solves of the driver scaled by the
%   level; the truncation estimate against its definition, 2 |rms(2H + 1) - rms(H)| from a
%   second driver at 2H + 1 harmonics (0 where the element sticks); the element parameters
%   read back and a solve after a change against a driver built with the new value; the
%   backbone's sensitivities against the stuck mode's closed form d omega / dk_t =
%   (J phi)^2 / (2 omega) and against central differences of backbones through
%   fricreg_hb_set_element_param; the modal participation against the stuck mode's own (1 in
%   its mode, 0 in the other) and against its definition from the point's coefficients.
cases = {'multipliers_closed_form', @multipliers_closed_form
         'level_response_linear', @level_response_linear
         'level_response_sliding', @level_response_sliding
         'truncation_error_definition', @truncation_error_definition
         'element_param_roundtrip', @element_param_roundtrip
         'sensitivities_stuck_mode', @sensitivities_stuck_mode
         'sensitivities_differences', @sensitivities_differences
         'modal_participation', @modal_participation};
failures = fricreg_test_run('hb_estimates', cases);
end

function [M, K, C, J, kt, mun] = two_masses()
% test_fricreg_hb's model: two masses, a Jenkins element between them.
M = [1.3 0; 0 0.7];
K = [2.385 -1.1; -1.1 1.9];
C = 0.031 * K + 0.012 * M + [0 0.004; 0.004 0];
J = [1 -1];
kt = 3.7;
mun = 0.8;
end

function mu = linear_multipliers(M, K0, C, w)
% The multipliers of x'' = -M \ (K0 x + C x') over one period 2 pi / w, by decreasing modulus.
n = size(M, 1);
A = [zeros(n), eye(n); -M \ K0, -M \ C];
mu = exp(2 * pi / w * eig(A)).';
[~, order] = sort(-abs(mu));
mu = mu(order);
end

function same_multipliers(got, want, what)
% got by decreasing modulus, and the same set as want (a conjugate pair's order within equal
% moduli is rounding's: matched by the nearest, not by position).
if ~isequal(size(got), size(want)) || any(diff(abs(got)) > 1e-12)
    error('test:hb', '%s: %s not by decreasing modulus', what, mat2str(got, 6));
end
for j = 1:numel(want)
    fricreg_test_check(min(abs(got - want(j))), 0, 1e-10, sprintf('%s, multiplier %d', what, j), 1);
end
end

function multipliers_closed_form()
[M, K, C, J, kt, mun] = two_masses();
jk = struct('type', 'jenkins', 'J', J, 'params', [kt mun]);
h = fricreg_harmonic_balance(M, K, C, jk, 5, 'excitation', [1.2e-4; 0], 'stability', true);
cleanup = onCleanup(@() fricreg_hb_free(h));
K0 = K + kt * (J' * J);
s = fricreg_hb_solve(h, 1.37);
mu = linear_multipliers(M, K0, C, 1.37);
same_multipliers(s.multipliers, mu, 'solve');
fricreg_test_check(abs(s.multipliers(1)), s.mu_max, 1e-14, 'mu_max');
% a stuck branch: each point's multipliers at its frequency
r = fricreg_hb_frequency_response(h, 0.5, 2.5);
n = numel(r.omega);
if ~isequal(size(r.multipliers), [n 4]) || ~iscomplex(r.multipliers)
    error('test:hb', 'branch multipliers: size %s', mat2str(size(r.multipliers)));
end
for k = [1 round(n / 2) n]
    same_multipliers(r.multipliers(k, :), linear_multipliers(M, K0, C, r.omega(k)), ...
                     sprintf('point %d', k));
end
fricreg_test_check(abs(r.multipliers(:, 1)), r.mu_max, 1e-14, 'branch mu_max');
% stability off: none
fricreg_hb_set(h, 'stability', false);
s = fricreg_hb_solve(h, 1.37);
r = fricreg_hb_frequency_response(h, 1, 1.5);
if ~isempty(s.multipliers) || ~isempty(r.multipliers)
    error('test:hb', 'multipliers with stability off');
end
end

function level_response_linear()
% Stuck at every level up to 3e4 x 1.2e-4 (|q| <= 0.09 < mun/kt = 0.22): x scales with it.
[M, K, C, J, kt, mun] = two_masses();
pc = [1.2e-4; 0];
ps = [0; -3.1e-5];
h = fricreg_harmonic_balance(M, K, C, struct('type', 'jenkins', 'J', J, 'params', [kt mun]), ...
                             5, 'excitation', {pc, ps}, 'stability', true);
cleanup = onCleanup(@() fricreg_hb_free(h));
w = 1.37;
r = fricreg_hb_level_response(h, w, 0.1, 300);
n = numel(r.level);
X = (K + kt * (J' * J) - w^2 * M + 1i * w * C) \ (pc - 1i * ps);
if n < 2 || any(r.omega ~= w) || ~isequal(size(r.x), [n 2 11]) || ~isempty(r.bifurcations)
    error('test:hb', 'level branch: %d points, shapes', n);
end
fricreg_test_check(r.level([1 end]), [0.1; 300], 1e-14, 'level ends');
fricreg_test_check(r.rms, r.level * abs(X)' / sqrt(2), 1e-10, 'rms = level |X| / sqrt 2');
fricreg_test_check(squeeze(r.x(n, :, 2:3)), 300 * [real(X), -imag(X)], 1e-10, 'x at 300', ...
                   300 * max(abs(X)));
same_multipliers(r.multipliers(n, :), linear_multipliers(M, K + kt * (J' * J), C, w), ...
                 'level branch');
% the lower-level command gives the same numbers
[omega, level] = fricreg_mex('hb_continue_level', h, w, 0.1, 300);
fricreg_test_check(level, r.level, 0, 'gateway');
fricreg_test_check(omega, r.omega, 0, 'gateway omega');
end

function level_response_sliding()
% One mass, a spring and a Jenkins element: it slips from a level on; each point is the
% solution of the driver forced at that level.
jk = struct('type', 'jenkins', 'J', 1, 'params', [20 1]);
h = fricreg_harmonic_balance(1, 1, 0.05, jk, 7, 'excitation', 1, 'newton', [1e-12 50]);
cleanup = onCleanup(@() fricreg_hb_free(h));
w = 2.5;
r = fricreg_hb_level_response(h, w, 0.2, 3);
n = numel(r.level);
if ~(n > 3 && all(diff(r.level) > 0) && r.level(end) == 3 && isempty(r.stable))
    error('test:hb', 'level branch from 0.2 to 3: %d points', n);
end
% stuck at 0.2: the linear response with k + kt
fricreg_test_check(r.rms(1), 0.2 / abs(21 - w^2 + 0.05i * w) / sqrt(2), 1e-10, 'stuck start');
for k = [round(n / 2) n]
    g = fricreg_harmonic_balance(1, 1, 0.05, jk, 7, 'excitation', r.level(k), ...
                                 'newton', [1e-12 50]);
    cg = onCleanup(@() fricreg_hb_free(g));
    s = fricreg_hb_solve(g, w);
    fricreg_test_check(squeeze(r.x(k, 1, :))', s.x, 1e-8, sprintf('point %d', k), max(abs(s.x)));
    clear cg;
end
end

function truncation_error_definition()
jk = struct('type', 'jenkins', 'J', 1, 'params', [20 1]);
H = 3;
h = fricreg_harmonic_balance(1, 1, 0.05, jk, H, 'excitation', 1.5, 'newton', [1e-12 50]);
c1 = onCleanup(@() fricreg_hb_free(h));
g = fricreg_harmonic_balance(1, 1, 0.05, jk, 2 * H + 1, 'excitation', 1.5, ...
                             'newton', [1e-12 50]);
c2 = onCleanup(@() fricreg_hb_free(g));
w = 2.5; % sliding: |x| ~ 0.3 against the slip at 0.05
s = fricreg_hb_solve(h, w);
t = fricreg_hb_solve(g, w);
rms = @(x) sqrt(x(1)^2 + sum(x(2:end).^2) / 2);
[rms_error, amplitude_error] = fricreg_hb_truncation_error(h);
fricreg_test_check(rms_error, 2 * abs(rms(t.x) - rms(s.x)), 1e-4, 'rms_error');
fricreg_test_check(amplitude_error, 2 * abs(norm(t.x(2:3)) - norm(s.x(2:3))), 1e-4, ...
                   'amplitude_error');
if ~(rms_error > 1e-6 * rms(s.x))
    error('test:hb', 'sliding: the estimate %g is not above rounding', rms_error);
end
% a branch's points: the last one is the solution's
r = fricreg_hb_frequency_response(h, 0.3, w);
n = numel(r.omega);
fricreg_test_check(fricreg_hb_truncation_error(h, n), fricreg_hb_truncation_error(h), 1e-12, ...
                   'last point');
% stuck (|x| ~ 0.024 against the slip at 0.05): the linear response, one harmonic, no error
fricreg_hb_set(h, 'excitation', 0.5);
s = fricreg_hb_solve(h, 0.3);
fricreg_test_check(fricreg_hb_truncation_error(h), 0, 1e-12, 'stuck', rms(s.x));
end

function element_param_roundtrip()
[M, K, C, J, kt, mun] = two_masses();
blocks = [struct('type', 'jenkins', 'J', [J; 1 0], 'params', [kt mun; 2.1 0.3]), ...
          struct('type', 'spring', 'J', [0 1], 'params', 0.77)];
h = fricreg_harmonic_balance(M, K, C, blocks, 5, 'excitation', [0.3; 0]);
cleanup = onCleanup(@() fricreg_hb_free(h));
got = [fricreg_hb_element_param(h, 1, 1), fricreg_hb_element_param(h, 1, 2), ...
       fricreg_hb_element_param(h, 2, 1), fricreg_hb_element_param(h, 2, 2), ...
       fricreg_hb_element_param(h, 3, 1)];
fricreg_test_check(got, [kt mun 2.1 0.3 0.77], 0, 'read back');
fricreg_hb_set_element_param(h, 1:2, 2, 0.45); % both Jenkins elements' slip force
fricreg_hb_set_element_param(h, 3, 1, 1.3);
s = fricreg_hb_solve(h, 1.1);
blocks(1).params(:, 2) = 0.45;
blocks(2).params = 1.3;
g = fricreg_harmonic_balance(M, K, C, blocks, 5, 'excitation', [0.3; 0]);
cg = onCleanup(@() fricreg_hb_free(g));
t = fricreg_hb_solve(g, 1.1);
fricreg_test_check(s.x, t.x, 0, 'set = built with the value');
fricreg_test_check(fricreg_hb_element_param(h, 2, 2), 0.45, 0, 'moved');
end

function [phi, wk] = stuck_mode(M, K0, mode)
[V, D] = eig(K0, M);
[w2, order] = sort(diag(D));
phi = V(:, order(mode));
phi = phi / sqrt(phi' * M * phi);
wk = sqrt(w2(mode));
end

function sensitivities_stuck_mode()
[M, K, C, J, kt, mun] = two_masses();
h = fricreg_harmonic_balance(M, K, C, struct('type', 'jenkins', 'J', J, 'params', [kt mun]), 5);
cleanup = onCleanup(@() fricreg_hb_free(h));
for mode = 1:2
    [phi, wk] = stuck_mode(M, K + kt * (J' * J), mode);
    fricreg_hb_backbone_at(h, mode, 1e-3, 'damping', 'modal');
    [dw, dz] = fricreg_hb_backbone_sensitivities(h, 1, {{'element', 1, 1}, ...
                                                        {'element', 1, 2}, {'damping', 'zeta'}});
    fricreg_test_check(dw, [(J * phi)^2 / (2 * wk); 0; 0], 1e-8, ...
                       sprintf('mode %d: d omega / d(kt, mun, zeta_k)', mode), wk);
    fricreg_test_check(dz(2:3), [0; 1], 1e-10, sprintf('mode %d: d zeta / d(mun, zeta_k)', ...
                                                       mode), 1);
end
end

function sensitivities_differences()
% A sliding point of mode 1 (Rayleigh damping): the derivatives in kt, mun, a1 and along the
% backbone against central differences, the backbone marched again at the same amplitude.
[M, K, ~, J, kt, mun] = two_masses();
rayleigh = [0.012 0.031];
h = fricreg_harmonic_balance(M, K, [], struct('type', 'jenkins', 'J', J, 'params', [kt mun]), ...
                             5, 'rayleigh', rayleigh, 'newton', [1e-12 50]);
cleanup = onCleanup(@() fricreg_hb_free(h));
a = 30; % |J phi| a = 0.31 against the slip at mun/kt = 0.22: sliding
b = fricreg_hb_backbone_at(h, 1, [1 a]);
[dw, dz, damp] = fricreg_hb_backbone_sensitivities(h, 2, {{'element', 1, 1}, ...
                                                          {'element', 1, 2}, ...
                                                          {'damping', 'a1'}, {'amplitude'}});
if ~isequal(size(damp), [4 2])
    error('test:hb', 'damp: size %s', mat2str(size(damp)));
end
x1 = @(b) [norm(squeeze(b.x(end, 1, 2:3))), norm(squeeze(b.x(end, 2, 2:3)))];
values = [kt mun];
for p = 1:2
    d = 1e-5 * values(p);
    fricreg_hb_set_element_param(h, 1, p, values(p) + d);
    up = fricreg_hb_backbone_at(h, 1, [1 a]);
    fricreg_hb_set_element_param(h, 1, p, values(p) - d);
    down = fricreg_hb_backbone_at(h, 1, [1 a]);
    fricreg_hb_set_element_param(h, 1, p, values(p));
    what = sprintf('parameter %d', p);
    fricreg_test_check(dw(p), (up.omega(end) - down.omega(end)) / (2 * d), 1e-5, [what ' omega']);
    fricreg_test_check(dz(p), (up.zeta(end) - down.zeta(end)) / (2 * d), 1e-5, [what ' zeta']);
    fricreg_test_check(damp(p, :), (x1(up) - x1(down)) / (2 * d), 1e-5, [what ' |X_1|'], ...
                       max(abs(damp(p, :))));
end
% Rayleigh's a1 through a driver built with it moved
d = 1e-5 * rayleigh(2);
w = zeros(1, 2);
z = zeros(1, 2);
for s = [1 -1]
    g = fricreg_harmonic_balance(M, K, [], struct('type', 'jenkins', 'J', J, ...
                                 'params', [kt mun]), 5, 'rayleigh', rayleigh + [0 s * d], ...
                                 'newton', [1e-12 50]);
    c = fricreg_hb_backbone_at(g, 1, [1 a]);
    fricreg_hb_free(g);
    w((3 - s) / 2) = c.omega(end);
    z((3 - s) / 2) = c.zeta(end);
end
fricreg_test_check(dw(3), (w(1) - w(2)) / (2 * d), 1e-5, 'a1 omega');
fricreg_test_check(dz(3), (z(1) - z(2)) / (2 * d), 1e-5, 'a1 zeta');
% along the backbone
da = 1e-5 * a;
c = fricreg_hb_backbone_at(h, 1, [1 a - da a + da]);
fricreg_test_check(dw(4), (c.omega(3) - c.omega(2)) / (2 * da), 1e-5, 'amplitude omega');
fricreg_test_check(dz(4), (c.zeta(3) - c.zeta(2)) / (2 * da), 1e-5, 'amplitude zeta');
% two outputs, one parameter: the same numbers
fricreg_hb_backbone_at(h, 1, [1 a]);
[dw2, dz2] = fricreg_hb_backbone_sensitivities(h, 2, {{'element', 1, 1}});
fricreg_test_check([dw2 dz2], [dw(1) dz(1)], 1e-14, 'two outputs');
end

function modal_participation()
[M, K, C, J, kt, mun] = two_masses();
h = fricreg_harmonic_balance(M, K, C, struct('type', 'jenkins', 'J', J, 'params', [kt mun]), 5);
cleanup = onCleanup(@() fricreg_hb_free(h));
b = fricreg_hb_backbone_at(h, 2, [1e-3 1], 'damping', 'modal');
fricreg_test_check(fricreg_hb_modal_participation(h, 1, 1), [0 1], 1e-12, 'stuck mode 2', 1);
fricreg_test_check(fricreg_hb_modal_participation(h, 1, 3), [0 0], 0, 'stuck: no 3rd harmonic');
% sliding: the definition from the point's coefficients and the stuck modes
[V, D] = eig(K + kt * (J' * J), M);
[~, order] = sort(diag(D));
phi = V(:, order) ./ sqrt(diag(V(:, order)' * M * V(:, order)))';
for harmonic = [1 3]
    x = squeeze(b.x(2, :, :));
    ab = x(:, 2 * harmonic:2 * harmonic + 1);
    p = sum((phi' * M * ab).^2, 2)';
    got = fricreg_hb_modal_participation(h, 2, harmonic);
    fricreg_test_check(got, p / sum(p), 1e-10, sprintf('harmonic %d', harmonic), 1);
    if ~(abs(sum(got) - 1) < 1e-14 && got(1) > 0)
        error('test:hb', 'harmonic %d: %s', harmonic, mat2str(got));
    end
end
end
