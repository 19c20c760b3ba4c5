% SPDX-License-Identifier: GPL-3.0-or-later
function failures = test_fricreg_fit()
%TEST_FRICREG_FIT  fricreg_backbone against the modal Iwan model's closed forms and its
%   sensitivities against central differences; fricreg_fit_backbone recovering known
%   parameters from noise-free levels to 1e-6 (the setup of tests/fit/test_fit.c: a joint near
%   170 Hz, F_S 30, K_T 3e5, chi 0.3, beta 0.5, zeta0 0.002, K0 8.4e5; 8 accelerations at a
%   sensor of shape 0.37 from 3 % to 150 % of phi_max), and the library's failures with
%   their identifiers.
cases = {'backbone_closed_forms', @backbone_closed_forms
         'backbone_sensitivities', @backbone_sensitivities
         'backbone_params_by_name', @backbone_params_by_name
         'noise_free_recovery', @noise_free_recovery
         'recovery_from_levels_start', @recovery_from_levels_start
         'fixed_parameter', @fixed_parameter
         'help_example', @help_example
         'fit_failures', @fit_failures};
failures = fricreg_test_run('fit', cases);
end

function p = truth()
p = [30 3e5 0.3 0.5 0.002 8.4e5];
end

function pm = phi_max(p)
c = p(4) + (p(3) + 1) / (p(3) + 2);
pm = p(1) * (1 + p(4)) / (p(2) * c);
end

function [w2, zeta] = reference(p, a)
% omega^2 and zeta at the modal amplitude a, by the R, S form of tests/fit/test_fit.c.
chi = p(3);
beta = p(4);
fs = p(1);
c = beta + (chi + 1) / (chi + 2);
pm = phi_max(p);
R = fs * (chi + 1) / (pm^(chi + 2) * c);
S = fs / pm * beta / c;
if a < pm
    F = R * a^(chi + 2) / (chi + 2) + a * (R * (pm^(chi + 1) - a^(chi + 1)) / (chi + 1) + S);
    D = 4 * R * a^(chi + 3) / ((chi + 2) * (chi + 3));
else
    F = fs;
    D = 4 * R * (a * pm^(chi + 2) / (chi + 2) - pm^(chi + 3) / (chi + 3)) + 4 * S * pm * (a - pm);
end
w2 = p(6) + F / a;
zeta = p(5) + D / (2 * pi * w2 * a^2);
end

function A = levels(p)
% the levels' accelerations at the sensor: 3 % to 150 % of phi_max, geometric
A = 0.37 * phi_max(p) * 0.03 * 50.^((0:7) / 7) * (2 * pi * 165)^2;
end

function backbone_closed_forms()
p = [2.385 41.7 -0.37 0.81 0.0031 17.3];
A = 0.37 * phi_max(p) * 0.01 * 400.^((0:8) / 8); % 1 % to 4 phi_max
[f, z, a] = fricreg_backbone(p, A, 'sensor', 0.37);
fricreg_test_check(a, A / 0.37, 1e-15, 'modal amplitude');
for i = 1:numel(A)
    [w2, zeta] = reference(p, a(i));
    fricreg_test_check(f(i), sqrt(w2) / (2 * pi), 1e-12, 'frequency');
    fricreg_test_check(z(i), zeta, 1e-12, 'damping');
end
% an acceleration level: |s| omega^2 a = A
Ak = 0.7 * phi_max(p) * 0.37 * (2 * pi * 0.5)^2;
[~, zk, ak] = fricreg_backbone(p, Ak, 'kind', 'acceleration', 'sensor', 0.37);
[w2, zeta] = reference(p, ak);
fricreg_test_check(0.37 * w2 * ak, Ak, 1e-13, 'acceleration');
fricreg_test_check(zk, zeta, 1e-12, 'damping at an acceleration');
end

function backbone_sensitivities()
p = truth();
A = 0.37 * phi_max(p) * 0.02 * 75.^((0:7)' / 7); % a column: columns out
[f, z, ~, df, dz] = fricreg_backbone(p, A, 'sensor', 0.37);
if ~isequal(size(f), [8 1]) || ~isequal(size(df), [8 6]) || ~isequal(size(dz), [8 6])
    error('test:fit', 'shapes');
end
for j = 1:6
    h = 1e-5 * abs(p(j));
    q = p;
    q(j) = p(j) + h;
    [fp, zp] = fricreg_backbone(q, A, 'sensor', 0.37);
    q(j) = p(j) - h;
    [fm, zm] = fricreg_backbone(q, A, 'sensor', 0.37);
    fricreg_test_check((fp - fm) / (2 * h), df(:, j), 1e-6, sprintf('dfreq/dp(%d)', j), ...
                       max(abs(df(:, j))));
    fricreg_test_check((zp - zm) / (2 * h), dz(:, j), 1e-6, sprintf('dzeta/dp(%d)', j), ...
                       max(abs(dz(:, j))));
end
end

function backbone_params_by_name()
p = truth();
s = struct('fs', p(1), 'kt', p(2), 'chi', p(3), 'beta', p(4), 'zeta0', p(5), 'k0', p(6));
[f1, z1] = fricreg_backbone(p, levels(p), 'kind', 'acceleration', 'sensor', 0.37);
[f2, z2] = fricreg_backbone(s, levels(p), 'Kind', 'acceleration', 'SENSOR', 0.37);
if ~isequal(f1, f2) || ~isequal(z1, z2) || ~isequal(size(f1), [1 8])
    error('test:fit', 'by name and by position differ');
end
end

function noise_free_recovery()
p = truth();
A = levels(p);
[f, z] = fricreg_backbone(p, A, 'kind', 'acceleration', 'sensor', 0.37);
off = [10 0.1 10 10 0.1 10];
x0 = struct('fs', 10 * p(1), 'kt', 0.1 * p(2), 'chi', 10 * (p(3) + 1) - 1, 'beta', 10 * p(4), ...
            'zeta0', 0.1 * p(5), 'k0', 10 * p(6));
fit = fricreg_fit_backbone(A, f, z, 'sensor', 0.37, 'sd_freq_hz', 5e-4 * f, ...
                           'sd_zeta', 0.01 * z, 'x0', x0);
fricreg_test_check(fit.x, p, 1e-6, 'recovered');
if any(off == 0) || ~all(fit.lower < p & p < fit.upper)
    error('test:fit', 'the truth is outside the intervals');
end
if ~(fit.cost < 1e-12) || ~fit.success || ~all(fit.free)
    error('test:fit', 'cost %g', fit.cost);
end
fricreg_test_check(fit.quantile, 1.959963984540054, 1e-12, 'quantile');
fricreg_test_check(fit.params.kt, p(2), 1e-6, 'params.kt');
sizes = {size(fit.cov), size(fit.sv), size(fit.vectors), size(fit.residuals_freq)};
if ~isequal(sizes, {[6 6], [6 1], [6 6], [8 1]})
    error('test:fit', 'shapes');
end
if ~isequal(fit.cov, fit.cov') || any(diag(fit.cov) <= 0)
    error('test:fit', 'the covariance is not symmetric positive');
end
if any(diff(fit.sv) > 0) || fit.nfev < 1 || fit.njev < 1
    error('test:fit', 'singular values out of order, or no evaluations');
end
end

function recovery_from_levels_start()
p = truth();
A = levels(p);
[f, z] = fricreg_backbone(p, A, 'kind', 'acceleration', 'sensor', 0.37);
fit = fricreg_fit_backbone(A, f, z, 'sensor', 0.37, 'sd_freq_hz', 5e-4 * f, 'sd_zeta', 0.01 * z);
fricreg_test_check(fit.x, p, 1e-6, 'recovered from the levels');
end

function fixed_parameter()
p = truth();
A = levels(p);
[f, z] = fricreg_backbone(p, A, 'kind', 'acceleration', 'sensor', 0.37);
fit = fricreg_fit_backbone(A, f, z, 'sensor', 0.37, 'fixed', struct('beta', 0.5));
if fit.x(4) ~= 0.5 || fit.free(4) || numel(fit.sv) ~= 5 || ~isequal(size(fit.vectors), [5 6])
    error('test:fit', 'beta not held');
end
if any(fit.cov(4, :)) || any(fit.cov(:, 4)) || any(fit.vectors(:, 4))
    error('test:fit', 'a fixed parameter with a covariance');
end
fricreg_test_check(fit.x, p, 1e-6, 'recovered with beta fixed');
end

function help_example()
% the example of fricreg_fit_backbone's help text
truth_ = [30 3e5 0.3 0.5 0.002 8.4e5];
A = 0.37 * 1.4085e-4 * 0.03 * 50.^((0:7) / 7) * (2 * pi * 165)^2;
[f, z] = fricreg_backbone(truth_, A, 'kind', 'acceleration', 'sensor', 0.37);
fit = fricreg_fit_backbone(A, f, z, 'sensor', 0.37);
fricreg_test_check(fit.params.fs, 30, 1e-6, 'the help example');
end

function fit_failures()
p = truth();
A = levels(p);
[f, z] = fricreg_backbone(p, A, 'kind', 'acceleration', 'sensor', 0.37);
sd = {'sd_freq_hz', 5e-4 * f, 'sd_zeta', 0.01 * z};
% one start 10x off does not converge within 500 iterations (tests/fit/test_fit.c)
x0 = struct('fs', 10 * p(1), 'kt', 0.1 * p(2), 'chi', 10 * (p(3) + 1) - 1, 'beta', 10 * p(4), ...
            'zeta0', 0.1 * p(5), 'k0', 10 * p(6));
fricreg_test_raises('fricreg:EWORK', @() fricreg_fit_backbone(A, f, z, 'sensor', 0.37, sd{:}, ...
                                                               'x0', x0, 'starts', 1));
% levels of a joint without the delta, fitted with beta free: at its bound
q = p;
q(4) = 0;
[fq, zq] = fricreg_backbone(q, A, 'kind', 'acceleration', 'sensor', 0.37);
fricreg_test_raises('fricreg:EINVAL', @() fricreg_fit_backbone(A, fq, zq, 'sensor', 0.37, ...
                    'sd_freq_hz', 5e-4 * fq, 'sd_zeta', 0.01 * zq, 'starts', 8), ...
                    'beta ended at its lower bound');
% eight levels at one amplitude: two numbers for three free parameters
same = A(5) * ones(1, 8);
[fs, zs] = fricreg_backbone(p, same, 'kind', 'acceleration', 'sensor', 0.37);
fricreg_test_raises('fricreg:ESINGULAR', @() fricreg_fit_backbone(same, fs, zs, ...
                    'sensor', 0.37, 'fixed', struct('chi', p(3), 'beta', p(4), 'zeta0', p(5))), ...
                    'do not determine');
% fewer levels than free parameters; bad values; deviations of another length
fricreg_test_raises('fricreg:EINVAL', @() fricreg_fit_backbone(A(1:2), f(1:2), z(1:2)));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_fit_backbone(-A, f, z));
fricreg_test_raises('fricreg:ENONFINITE', @() fricreg_fit_backbone(A, [NaN f(2:end)], z));
fricreg_test_raises('fricreg:ESIZE', @() fricreg_fit_backbone(A, f, z, 'sd_freq_hz', f(1:3), ...
                                                               'sd_zeta', z(1:3)));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_fit_backbone(A, f, z, 'starts', 0));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_fit_backbone(A, f, z, 'kind', 'jerk'));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_fit_backbone(A, f, z, 'sensor', 0));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_fit_backbone(A, f, z, 'fixed', struct('kt', -1)));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_fit_backbone(A, f, z, ...
                                                                'bounds', struct('fs', [5 1])));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_backbone([30 3e5 -2 0.5 0.002 8.4e5], 1e-5));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_backbone(p, [1e-5 0]));
fricreg_test_raises('fricreg:ENONFINITE', @() fricreg_backbone(p, [1e-5 Inf]));
% the gateway's and the .m files' own checks
fricreg_test_raises('fricreg:size', @() fricreg_fit_backbone(A, f(1:7), z));
fricreg_test_raises('fricreg:size', @() fricreg_backbone(p(1:5), 1e-5));
fricreg_test_raises('fricreg:size', @() fricreg_fit_backbone(reshape([A A], 2, 8), f, z));
fricreg_test_raises('fricreg:type', @() fricreg_fit_backbone(single(A), f, z));
fricreg_test_raises('fricreg:type', @() fricreg_backbone(p, 1e-5 + 1e-6i));
fricreg_test_raises('fricreg:option', @() fricreg_fit_backbone(A, f, z, 'sd_freq_hz', f));
fricreg_test_raises('fricreg:option', @() fricreg_fit_backbone(A, f, z, 'nonsense', 1));
fricreg_test_raises('fricreg:option', @() fricreg_fit_backbone(A, f, z, 'starts'));
fricreg_test_raises('fricreg:option', @() fricreg_fit_backbone(A, f, z, 'x0', struct('mu', 1)));
fricreg_test_raises('fricreg:option', @() fricreg_backbone(struct('fs', 1), 1e-5));
fricreg_test_raises('fricreg:nargs', @() fricreg_fit_backbone(A, f));
fricreg_test_raises('fricreg:nargs', @() fricreg_backbone(p));
% a fit's results before a successful run: the library's EINVAL
h = fricreg_mex('fit_create');
cleanup = onCleanup(@() fricreg_mex('free', h));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_mex('fit_params', h), 'FRICREG_EINVAL');
fricreg_test_raises('fricreg:EINVAL', @() fricreg_mex('fit_run', h));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_mex('fit_value', h, 'cost'));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_mex('fit_value', h, 'nothing'));
end
