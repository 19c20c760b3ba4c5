% SPDX-License-Identifier: GPL-3.0-or-later
function failures = test_fricreg_element()
%TEST_FRICREG_ELEMENT  fricreg_element_eval against the Jenkins element's closed form (stick
%   f = kt (u - w), slip |f| = mun; J. C. Simo, T. J. R. Hughes, "Computational Inelasticity",
%   1998, Ch. 1) and its hysteresis loop, and every type's batched call against a loop of
%   single-point calls through the same gateway, bit for bit (fricreg_element_eval_batch).
cases = {'jenkins_from_rest', @jenkins_from_rest
         'jenkins_loop', @jenkins_loop
         'jenkins_2d_layout', @jenkins_2d_layout
         'types_and_shapes', @types_and_shapes
         'batch_equals_single_points', @batch_equals_single_points
         'params_per_point', @params_per_point};
failures = fricreg_test_run('element', cases);
end

function jenkins_from_rest()
kt = 1e5;
mun = 20;
u = [-5e-4; -2e-4; -1e-4; 0; 1e-4; 2e-4; 2.5e-4];
[f, dfdu, w, dfdp] = fricreg_element_eval('jenkins', [kt mun], u);
stick = kt * abs(u) <= mun;
fricreg_test_check(f, stick .* (kt * u) + ~stick .* (mun * sign(u)), 0, 'f');
fricreg_test_check(dfdu, kt * stick, 0, 'dfdu');
fricreg_test_check(w, ~stick .* (u - mun * sign(u) / kt), 1e-15, 'w');
fricreg_test_check(dfdp, cat(3, stick .* u, ~stick .* sign(u)), 0, 'dfdp');
end

function jenkins_loop()
% One element driven 0 -> A -> -A -> A in steps landing on the turning points: the force
% follows the loop's closed form, min(kt u, mun) up, max(mun - kt (A - u), -mun) down and
% min(-mun + kt (u + A), mun) up again (Masing), to rounding.
kt = 1e5;
mun = 20;
A = 6e-4; % > mun/kt: slips
up = linspace(0, A, 13);
down = linspace(A, -A, 25);
again = linspace(-A, A, 25);
path = [up, down(2:end), again(2:end)];
state = 0;
f = zeros(size(path));
for k = 1:numel(path)
    [f(k), ~, state] = fricreg_element_eval('jenkins', [kt mun], path(k), state);
end
want = [min(kt * up, mun), max(mun - kt * (A - down(2:end)), -mun), ...
        min(-mun + kt * (again(2:end) + A), mun)];
fricreg_test_check(f, want, 1e-12, 'loop', mun);
% the dissipation of the closed loop, 4 mun (A - mun/kt): the loop's area by the trapezoids
% of the second and third legs (exact: f is piecewise linear with kinks on the grid)
n = numel(up);
legs = n:numel(path);
area = trapz(path(legs), f(legs)); % the work done on the element
fricreg_test_check(area, 4 * mun * (A - mun / kt), 1e-12, 'dissipation');
end

function jenkins_2d_layout()
% Point 1 sticks, point 2 slips; w differs per component, so a transposed table would show.
kt = 1e5;
mun = 20;
w = [1e-5 -2e-5; 3e-5 -4e-5];
u = [5e-5 3e-5; 4e-4 -3e-4];
[f, dfdu, w_out, dfdp] = fricreg_element_eval('jenkins_2d', [kt mun], u, w);
fricreg_test_check(f(1, :), kt * (u(1, :) - w(1, :)), 1e-15, 'stick f');
fricreg_test_check(w_out(1, :), w(1, :), 0, 'stick w');
fricreg_test_check(reshape(dfdu(1, :, :), 2, 2), kt * eye(2), 0, 'stick dfdu');
d = u(2, :) - w(2, :);
nrm = d / norm(d);
fricreg_test_check(f(2, :), mun * nrm, 1e-15, 'slip f');
fricreg_test_check(w_out(2, :), u(2, :) - mun * nrm / kt, 1e-15, 'slip w');
fricreg_test_check(reshape(dfdu(2, :, :), 2, 2), (mun / norm(d)) * (eye(2) - nrm' * nrm), ...
                   1e-14, 'slip dfdu');
fricreg_test_check(reshape(dfdp(2, :, :), 2, 2), [0 nrm(1); 0 nrm(2)], 1e-15, 'slip dfdp');
d1 = u(1, :) - w(1, :);
fricreg_test_check(reshape(dfdp(1, :, :), 2, 2), [d1' [0; 0]], 0, 'stick dfdp');
end

function types_and_shapes()
types = fricreg_mex('element_types');
want = {'jenkins', 'jenkins_2d', 'contact_3d', 'iwan', 'iwan_normal', 'jenkins_3d', ...
        'jenkins_normal', 'iwan_2d', 'iwan_3d', 'spring', 'dahl'};
if ~isequal(types, want)
    error('test:element', 'element_types: %s', strjoin(types, ', '));
end
% iwan with 3 sliders: dim 1, 6 parameters, 3 state variables; 5 points
[f, dfdu, s, dfdp] = fricreg_element_eval('iwan', [3e4 3e4 4e4 5 10 20], (1:5)' * 1e-4);
sizes = {size(f), size(dfdu), size(s), size(dfdp)};
if ~isequal(sizes, {[5 1], [5 1], [5 3], [5 1 6]})
    error('test:element', 'iwan shapes');
end
[f, dfdu, s, dfdp] = fricreg_element_eval('contact_3d', [1e5 0.3 2e5 50 0], zeros(4, 3));
sizes = {size(f), size(dfdu), size(s), size(dfdp)};
if ~isequal(sizes, {[4 3], [4 3 3], [4 2], [4 3 5]})
    error('test:element', 'contact_3d shapes');
end
[f, ~, s] = fricreg_element_eval('spring', 1e4, [1; 2]);
if ~isequal(f, [1e4; 2e4]) || ~isequal(size(s), [2 0])
    error('test:element', 'spring');
end
f = fricreg_element_eval('jenkins', [1e5 20], zeros(0, 1));
if ~isequal(size(f), [0 1])
    error('test:element', 'no points');
end
end

function [params, u, state] = inputs(name, n)
% Deterministic pseudo-random points of each type: sticking, slipping, open and closed.
r = @(k) mod(sin((1:n)' * 12.9898 + k * 78.233) * 43758.5453, 1) * 2 - 1; % in (-1, 1)
switch name
case 'jenkins'
    params = [1e5 20];
    u = 4e-4 * r(1);
    state = 2e-4 * r(2);
case 'jenkins_2d'
    params = [1e5 20];
    u = 4e-4 * [r(1) r(2)];
    state = 2e-4 * [r(3) r(4)];
case 'contact_3d'
    params = [1e5 0.3 2e5 50 0];
    u = [4e-4 * r(1), 4e-4 * r(2), 5e-4 * r(3)];
    state = 2e-4 * [r(4) r(5)];
case 'iwan'
    params = [3e4 3e4 4e4 5 10 20];
    u = 8e-4 * r(1);
    state = 4e-4 * [r(2) r(3) r(4)];
case 'iwan_normal'
    params = [5e4 5e4 0.2 0.4 2e5 30 0];
    u = [4e-4 * r(1), 3e-4 * r(2)];
    state = 2e-4 * [r(3) r(4)];
case 'spring'
    params = 1e4;
    u = r(1);
    state = zeros(n, 0);
case 'dahl'
    params = [1e5 20];
    u = 4e-4 * r(1);
    state = 2e-4 * [r(2) r(3)];
end
end

function batch_equals_single_points()
names = {'jenkins', 'jenkins_2d', 'contact_3d', 'iwan', 'iwan_normal', 'spring', 'dahl'};
n = 40;
for k = 1:numel(names)
    [params, u, state] = inputs(names{k}, n);
    [f, dfdu, s, dfdp] = fricreg_element_eval(names{k}, params, u, state);
    for i = 1:n
        [f1, dfdu1, s1, dfdp1] = fricreg_element_eval(names{k}, params, u(i, :), state(i, :));
        if ~same_bits(f(i, :), f1) || ~same_bits(dfdu(i, :, :), dfdu1) || ...
           ~same_bits(s(i, :), s1) || ~same_bits(dfdp(i, :, :), dfdp1)
            error('test:element', '%s: point %d differs from its single call', names{k}, i);
        end
    end
    % fewer outputs: the same force and state
    [f2, ~, s2] = fricreg_element_eval(names{k}, params, u, state);
    if ~same_bits(f2, f) || ~same_bits(s2, s)
        error('test:element', '%s: fewer outputs, other numbers', names{k});
    end
end
end

function params_per_point()
n = 25;
[params, u, state] = inputs('iwan_normal', n);
scale = 1 + 0.2 * mod((1:n)' * 0.6180339887498949, 1);
rows = params .* scale; % a row each (implicit expansion: n x 7)
[f, dfdu, s, dfdp] = fricreg_element_eval('iwan_normal', rows, u, state);
for i = 1:n
    [f1, dfdu1, s1, dfdp1] = fricreg_element_eval('iwan_normal', rows(i, :), u(i, :), state(i, :));
    if ~same_bits(f(i, :), f1) || ~same_bits(dfdu(i, :, :), dfdu1) || ...
       ~same_bits(s(i, :), s1) || ~same_bits(dfdp(i, :, :), dfdp1)
        error('test:element', 'point %d differs from its single call', i);
    end
end
% a one-parameter type's column of parameters is a parameter a point
f = fricreg_element_eval('spring', [1; 2; 3], [1; 1; 1]);
if ~isequal(f, [1; 2; 3])
    error('test:element', 'spring per point');
end
end

function same = same_bits(a, b)
a = a(:);
b = b(:);
same = isequal(size(a), size(b)) && isequal(typecast(a, 'uint64'), typecast(b, 'uint64'));
end
