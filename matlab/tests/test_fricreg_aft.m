% SPDX-License-Identifier: GPL-3.0-or-later
function failures = test_fricreg_aft()
%TEST_FRICREG_AFT  The AFT of an element (fricreg_aft_*.m): the Jenkins element's describing
%   function and its loop's dissipation in closed form; the Jacobian against central
%   differences; the sampled path against a march of fricreg_element_eval over the same samples
%   and a DFT (the C library's return mapping by another path) and against the exact path to
%   O(N^-2); the Iwan element as the sum of its sliders, the normal and 3-D elements reducing to
%   the 1-D ones; fricreg_aft_element against the functions bit for bit; and every error path.
cases = {'describing_function', @describing_function
         'dissipation_and_time_shift', @dissipation_and_time_shift
         'jacobian', @jacobian
         'sampled_against_element_march', @sampled_against_element_march
         'iwan_is_sum_of_sliders', @iwan_is_sum_of_sliders
         'normal_reduces_to_jenkins', @normal_reduces_to_jenkins
         'element_by_name', @element_by_name
         'shapes_and_kept_workspace', @shapes_and_kept_workspace
         'errors', @errors};
failures = fricreg_test_run('aft', cases);
end

function describing_function()
% u = A cos(theta), r = mun/kt: slipping (A > r), fa_1 = (kt A/pi)(beta - sin(2 beta)/2) with
% cos(beta) = 1 - 2r/A, fb_1 = -(4 mun/pi)(1 - r/A) (Caughey 1960); even harmonics 0. Sticking
% (A <= r), the centred slider: f = kt u.
kt = 2.385e5; mun = 41.3; r = mun / kt;
for A = [1.37 2.9 11.3 240] * r
    u = zeros(1, 15); u(2) = A;                        % H = 7
    f = fricreg_aft_jenkins(kt, mun, u);
    if A <= r
        fa = kt * A; fb = 0;
    else
        beta = acos(1 - 2 * r / A);
        fa = (kt * A / pi) * (beta - sin(2 * beta) / 2);
        fb = -(4 * mun / pi) * (1 - r / A);
    end
    fricreg_test_check(f(2:3), [fa fb], 1e-12, sprintf('f_1 at A = %g r', A / r), kt * A);
    fricreg_test_check(f([1 4 5 8 9 12 13]), zeros(1, 7), 1e-12, 'even harmonics', kt * A);
end
u = [0 0.7 * r 0];                                    % sticking: kt u exactly
fricreg_test_check(fricreg_aft_jenkins(kt, mun, u), kt * u, 1e-15, 'stick', kt * r);
end

function dissipation_and_time_shift()
% u = A cos(theta - phi): the loop dissipates 4 mun (A - r) a period,
% pi sum_h h (b_h fa_h - a_h fb_h), and the response is the shifted one (the force's first
% harmonic rotated by phi).
kt = 1.1e4; mun = 2.385; r = mun / kt; A = 6.1 * r; phi = 0.731; H = 9;
u = zeros(1, 2 * H + 1); u(2:3) = A * [cos(phi) sin(phi)];
f = fricreg_aft_jenkins(kt, mun, u);
h = 1:H; a = u(2:2:end); b = u(3:2:end); fa = f(2:2:end); fb = f(3:2:end);
D = pi * sum(h .* (b .* fa - a .* fb));
fricreg_test_check(D, 4 * mun * (A - r), 1e-12, 'dissipation');
f0 = fricreg_aft_jenkins(kt, mun, [0 A zeros(1, 2 * H - 1)]);
R = [cos(phi) -sin(phi); sin(phi) cos(phi)];        % (a, b) of a shift by phi
fricreg_test_check(f(2:3)', R * f0(2:3)', 1e-12, 'shifted first harmonic', kt * A);
end

function jacobian()
% The exact Jacobian against central differences of the exact coefficients.
kt = 3.7e3; mun = 1.9; H = 4;
u = [1e-4 8.2e-4 -3.1e-4 1.3e-4 0.9e-4 -0.4e-4 0.2e-4 0.1e-4 -0.05e-4];
[f, jac] = fricreg_aft_jenkins(kt, mun, u);
assert(isequal(size(jac), [2 * H + 1, 2 * H + 1]))
d = 1e-9; J = zeros(size(jac));
for j = 1:numel(u)
    e = zeros(size(u)); e(j) = d;
    J(:, j) = (fricreg_aft_jenkins(kt, mun, u + e) - fricreg_aft_jenkins(kt, mun, u - e))' / (2 * d);
end
fricreg_test_check(jac, J, 1e-5, 'jacobian', kt);
[f2, jac2] = fricreg_aft_iwan([kt 2 * kt], [mun 3 * mun], u);   % the Iwan's: its sliders' sum
[~, jb] = fricreg_aft_jenkins(2 * kt, 3 * mun, u);
fricreg_test_check(jac2, jac + jb, 1e-12, 'iwan jacobian', 3 * kt);
assert(isequal(size(f2), size(f)))
end

function sampled_against_element_march()
% The sampled AFT is the return mapping at N samples from the stabilized state: a march of
% fricreg_element_eval over two periods from rest reaches it within the first (the slider's
% wiping out at the maximum), and the second period's DFT gives the same coefficients.
kt = 5.3e4; mun = 12.7; H = 3; N = 256;
u = [2e-5 9.1e-4 -2.2e-4 1.7e-4 0.8e-4 -0.6e-4 0.3e-4];
theta = 2 * pi * (0:N - 1)' / N;
ut = u(1) * ones(N, 1);
for h = 1:H
    ut = ut + u(2 * h) * cos(h * theta) + u(2 * h + 1) * sin(h * theta);
end
state = 0; f = zeros(N, 1);
for pass = 1:2
    for k = 1:N
        [f(k), ~, state] = fricreg_element_eval('jenkins', [kt mun], ut(k), state);
    end
end
c = zeros(1, 2 * H + 1); c(1) = mean(f);
for h = 1:H
    c(2 * h) = 2 / N * sum(f .* cos(h * theta));
    c(2 * h + 1) = 2 / N * sum(f .* sin(h * theta));
end
fs = fricreg_aft_jenkins(kt, mun, u, 'samples', N);
fricreg_test_check(fs, c, 1e-11, 'sampled against the march', mun);
fe = fricreg_aft_jenkins(kt, mun, u);                  % exact: the sampled within O(N^-2)
fricreg_test_check(fs, fe, 20 / N^2, 'sampled against exact', mun);
f2 = fricreg_aft_jenkins(kt, mun, u, 'samples', 4 * N);
assert(max(abs(f2 - fe)) < max(abs(fs - fe)) / 4)   % second order: 16x in theory
end

function iwan_is_sum_of_sliders()
kt = [1.2e4 3.4e4 7.7e4]; phi = [0.8 2.1 5.3];
u = [0 3.3e-4 1.1e-4 -0.7e-4 0 0.2e-4 0];
f = fricreg_aft_iwan(kt, phi, u');
assert(isequal(size(f), [7 1]))                      % a column in, a column out
s = zeros(7, 1);
for k = 1:3
    s = s + fricreg_aft_jenkins(kt(k), phi(k), u');
end
fricreg_test_check(f, s, 1e-13, 'iwan exact', sum(phi));
fs = fricreg_aft_iwan(kt, phi, u, 'samples', 128);
s = 0;
for k = 1:3
    s = s + fricreg_aft_jenkins(kt(k), phi(k), u, 'samples', 128);
end
fricreg_test_check(fs, s, 1e-13, 'iwan sampled', sum(phi));
end

function normal_reduces_to_jenkins()
% kn = 0, N0 >= 0: the Jenkins element at mun = mu N0, N = N0 throughout; the 3-D contact
% with uy = 0 and kn = 0: fx and N those of the 1-D element, sampled (to the bit where it slips).
kt = 2.2e4; mu = 0.31; n0 = 57.3; H = 3; n = 2 * H + 1;
u = [0 1.9e-3 -0.4e-3 0.3e-3 0 0 0.1e-3]; g = zeros(1, n);
[f, nf, jac] = fricreg_aft_jenkins_normal(kt, mu, n0, 0, u, g);
fricreg_test_check(f, fricreg_aft_jenkins(kt, mu * n0, u), 1e-12, 'normal exact', mu * n0);
fricreg_test_check(nf, [n0 zeros(1, n - 1)], 1e-15, 'normal force', n0);
assert(isequal(size(jac), [2 * n 2 * n]) && all(all(jac(n + 1:end, :) == 0)))
[fs, nfs] = fricreg_aft_jenkins_normal(kt, mu, n0, 0, u, g, 'samples', 256);
fricreg_test_check(fs, fricreg_aft_jenkins(kt, mu * n0, u, 'samples', 256), 0, 'normal sampled');
[f3, nf3, jac3] = fricreg_aft_jenkins_2d_normal(kt, mu, n0, 0, [u; zeros(1, n)], g, ...
                                                'samples', 256);
fricreg_test_check(f3(1, :), fs, 0, '3-D fx');
fricreg_test_check(f3(2, :), zeros(1, n), 0, '3-D fy');
fricreg_test_check(nf3, nfs, 0, '3-D N');
assert(isequal(size(jac3), [3 * n 3 * n]))
end

function element_by_name()
kt = 2.2e4; mu = 0.31; kn = 3e4; n0 = 57.3; gap = 2e-4; n = 7;
u = [0 1.9e-3 -0.4e-3 0.3e-3 0 0 0.1e-3]; g = [1e-4 2e-4 0 0 1e-4 0 0];
[f, jac] = fricreg_aft_element('jenkins', [kt 4.1], u);
[f1, jac1] = fricreg_aft_jenkins(kt, 4.1, u);
assert(isequal(f, f1) && isequal(jac, jac1))
f = fricreg_aft_element('iwan', [kt 2 * kt 1 3], u, 'samples', 64);
assert(isequal(f, fricreg_aft_iwan([kt 2 * kt], [1 3], u, 'samples', 64)))
[f, jac] = fricreg_aft_element('jenkins_normal', [kt mu kn n0 gap], [u; g]);
[f1, nf1, jac1] = fricreg_aft_jenkins_normal(kt, mu, n0 - kn * gap, kn, u, g);
assert(isequal(f, [f1; nf1]) && isequal(jac, jac1))
uy = 0.5 * circshift(u, 1);
[f, jac] = fricreg_aft_element('contact_3d', [kt mu kn n0 gap], [u; uy; g], 'samples', 128);
[f1, nf1, jac1] = fricreg_aft_jenkins_2d_normal(kt, mu, n0 - kn * gap, kn, [u; uy], g, ...
                                                'samples', 128);
assert(isequal(f, [f1; nf1]) && isequal(jac, jac1) && isequal(size(f), [3 n]))
end

function shapes_and_kept_workspace()
% A row in, a row out; a column, a column. The workspace the gateway keeps between calls is no
% handle, and clearing the gateway frees it (the calls after it make a new one).
u = [0 1e-3 0];
assert(isequal(size(fricreg_aft_jenkins(1e4, 2, u)), [1 3]))
assert(isequal(size(fricreg_aft_jenkins(1e4, 2, u')), [3 1]))
f = fricreg_aft_jenkins(1e4, 2, [0 1e-3 0 0 0]);
assert(fricreg_mex('handles') == 0)
clear fricreg_mex
assert(isequal(fricreg_aft_jenkins(1e4, 2, [0 1e-3 0 0 0]), f))
end

function errors()
u = [0 1e-3 0];
fricreg_test_raises('fricreg:nargs', @() fricreg_aft_jenkins(1, 2));
fricreg_test_raises('fricreg:nargs', @() fricreg_mex('aft', 'jenkins', 0, [1 2]));
fricreg_test_raises('fricreg:type', @() fricreg_aft_jenkins(1, 2, single(u)));
fricreg_test_raises('fricreg:type', @() fricreg_aft_jenkins(1, 2, u + 1i));
fricreg_test_raises('fricreg:type', @() fricreg_aft_jenkins(1, 2, {0, 1, 0}));
fricreg_test_raises('fricreg:type', @() fricreg_aft_element(3, [1 2], u));
fricreg_test_raises('fricreg:size', @() fricreg_aft_jenkins(1, 2, [0 1 0 0]), '2H + 1');
fricreg_test_raises('fricreg:size', @() fricreg_aft_jenkins(1, 2, zeros(3, 3)));
fricreg_test_raises('fricreg:size', @() fricreg_aft_jenkins([1 1], 2, u));
fricreg_test_raises('fricreg:size', @() fricreg_aft_iwan([1 2], 3, u));
fricreg_test_raises('fricreg:size', @() fricreg_aft_jenkins_normal(1, 0.3, 1, 0, u, [0 0]));
fricreg_test_raises('fricreg:size', @() fricreg_aft_jenkins_2d_normal(1, 0.3, 1, 0, u, u, ...
                                                                      'samples', 8));
fricreg_test_raises('fricreg:size', @() fricreg_aft_element('jenkins', [1 2 3], u), '[kt mun]');
fricreg_test_raises('fricreg:size', @() fricreg_aft_element('jenkins_normal', [1 2 3], [u; u]));
fricreg_test_raises('fricreg:size', @() fricreg_aft_element('jenkins_normal', [1 .3 0 1 0], u));
fricreg_test_raises('fricreg:size', @() fricreg_mex('aft', 'iwan', 0, [1 2 3], u));
fricreg_test_raises('fricreg:option', @() fricreg_aft_jenkins(1, 2, u, 'sample', 8));
fricreg_test_raises('fricreg:option', @() fricreg_aft_jenkins(1, 2, u, 'samples'));
fricreg_test_raises('fricreg:option', @() fricreg_aft_element('jenkins', [1 2], u, 'exact', 1));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_aft_jenkins(0, 2, u), 'kt');
fricreg_test_raises('fricreg:EINVAL', @() fricreg_aft_jenkins(1, -2, u), 'mun');
fricreg_test_raises('fricreg:EINVAL', @() fricreg_aft_iwan([1 2], [1 -3], u), 'phi');
fricreg_test_raises('fricreg:EINVAL', @() fricreg_aft_jenkins_normal(1, 0.3, 1, -1, u, u));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_aft_jenkins(1, 2, zeros(1, 83)), 'H = 41');
fricreg_test_raises('fricreg:EINVAL', @() fricreg_aft_jenkins(1, 2, u, 'samples', 12), 'power');
fricreg_test_raises('fricreg:EINVAL', @() fricreg_aft_jenkins(1, 2, u, 'samples', 2));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_aft_jenkins_2d_normal(1, 0.3, 1, 0, ...
                                          [u; u], u), 'no samples');
fricreg_test_raises('fricreg:EINVAL', @() fricreg_aft_element('dahl', [1 2 3], u), 'no AFT');
fricreg_test_raises('fricreg:EINVAL', @() fricreg_mex('aft', 'coulomb', 0, [1 2], u));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_mex('aft', 'jenkins', -1, [1 2], u));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_mex('aft', 'jenkins', 1.5, [1 2], u));
fricreg_test_raises('fricreg:ENONFINITE', @() fricreg_aft_jenkins(1, 2, [0 NaN 0]));
fricreg_test_raises('fricreg:ENONFINITE', @() fricreg_aft_jenkins(Inf, 2, u));
fricreg_test_raises('fricreg:ENONFINITE', @() fricreg_aft_jenkins_normal(1, 0.3, 1, 0, u, ...
                                              [0 Inf 0], 'samples', 8));
% the kept workspace survives an error: the next call's numbers are the same
f = fricreg_aft_jenkins(1e4, 2, u);
fricreg_test_raises('fricreg:EINVAL', @() fricreg_aft_jenkins(-1e4, 2, u));
assert(isequal(fricreg_aft_jenkins(1e4, 2, u), f))
end
