% SPDX-License-Identifier: GPL-3.0-or-later
function failures = test_fricreg_law()
%TEST_FRICREG_LAW  fricreg_law_eval against the laws' closed forms (Quinn 2004, eqs. (1)-(4);
%   the reference values of tests/law/test_law.c, mun = 2.385, eps = 0.0731), one call against
%   single-point calls bit for bit, shapes and scalar expansion.
cases = {'coulomb_closed_form', @coulomb_closed_form
         'quinn_reference_values', @quinn_reference_values
         'every_law_closed_form', @every_law_closed_form
         'codes_and_names', @codes_and_names
         'shapes_and_expansion', @shapes_and_expansion
         'array_equals_single_points', @array_equals_single_points
         'version', @version};
failures = fricreg_test_run('law', cases);
end

function coulomb_closed_form()
% (1): f = -mun sgn(v), sgn(0) = 0; f_eq and eps do not enter (test_law.c).
mun = 2.385;
v = [0 0.412 -0.0031 1e-300 -1e-300];
f = fricreg_law_eval('coulomb', v, 1.137, mun, 0.0731);
fricreg_test_check(f, [0 -mun mun -mun mun], 0, 'coulomb');
fricreg_test_check(fricreg_law_eval('coulomb', v, [], mun, 17.3), f, 0, 'coulomb without f_eq');
end

function quinn_reference_values()
% (4) with f_eq = 1.137 < mun: xi = (eps/2)(1.137/2.385); inside the zone |v - xi| < eps/2
% f = -(2 mun/eps)(v - xi), values in exact rationals from tests/law/test_law.c.
mun = 2.385;
eps = 0.0731;
inside = fricreg_law_eval('quinn', [0 0.0213 -0.0150 0.0539 -0.0191], 1.137, mun, eps);
fricreg_test_check(inside, [1.137 -0.25289056087551298 2.1157961696306429 ...
                            -2.3801409028727769 2.3833337893296855], 1e-13, 'quinn inside');
outside = fricreg_law_eval('quinn', [0.0540 -0.0192 0.0600 0.412 -0.3], 1.137, mun, eps);
fricreg_test_check(outside, [-mun mun -mun -mun mun], 0, 'quinn outside');
neg = fricreg_law_eval('quinn', [0 -0.0021 0.0072 -0.0658], -1.913, mun, eps);
fricreg_test_check(neg, [-1.913 -1.7759685362517099 -2.3828221614227085 2.3806525307797539], ...
                   1e-13, 'quinn, f_eq < 0');
% |f_eq| = mun: xi = eps/2, both zone edges exact
edges = fricreg_law_eval('quinn', [0 eps 0.5 * eps], mun, mun, eps);
fricreg_test_check(edges, [mun -mun 0], 0, 'quinn zone edges');
end

function every_law_closed_form()
% Each law on a grid of (v, f_eq, mun) against its formula of include/fricreg.h.
[v, feq, mun] = ndgrid(linspace(-0.2, 0.2, 41), linspace(-4, 4, 17), [0 0.5 2.385]);
eps = 0.0731;
sat = @(y) max(-1, min(1, y));
ratio = feq ./ mun;
ratio(mun == 0) = 0; % sat(f_eq/0): the law's f = mun sat(...) = 0 there
coulomb = -mun .* sign(v);
want = struct();
want.coulomb = coulomb;
want.force_balance = coulomb;
want.force_balance(v == 0) = mun(v == 0) .* sat(ratio(v == 0));
want.karnopp = coulomb;
in = abs(v) < eps;
want.karnopp(in) = mun(in) .* sat(ratio(in));
want.velocity_limited = coulomb;
want.velocity_limited(in) = -(mun(in) / eps) .* v(in);
want.tanh = -mun .* tanh(v / eps);
xi = (eps / 2) * sat(ratio);
want.quinn = -mun .* sign(v - xi);
zone = abs(v - xi) < eps / 2;
want.quinn(zone) = -(2 * mun(zone) / eps) .* (v(zone) - xi(zone));
laws = {'coulomb', 'force-balance', 'karnopp', 'velocity-limited', 'tanh', 'quinn'};
for k = 1:numel(laws)
    f = fricreg_law_eval(laws{k}, v, feq, mun, eps);
    fricreg_test_check(f, want.(strrep(laws{k}, '-', '_')), 1e-14, laws{k}, 2.385);
    if any(abs(f(:)) > mun(:))
        error('test:law', '%s: |f| > mun', laws{k});
    end
end
end

function codes_and_names()
names = fricreg_mex('law_names');
if ~isequal(names, {'coulomb', 'force-balance', 'karnopp', 'velocity-limited', 'tanh', 'quinn'})
    error('test:law', 'law_names: %s', strjoin(names, ', '));
end
v = linspace(-0.1, 0.1, 9);
for code = 1:6
    by_code = fricreg_law_eval(code, v, 0.7, 2.385, 0.0731);
    by_name = fricreg_law_eval(names{code}, v, 0.7, 2.385, 0.0731);
    if ~same_bits(by_code, by_name)
        error('test:law', 'law %d and %s differ', code, names{code});
    end
end
end

function shapes_and_expansion()
v = reshape(linspace(-0.1, 0.1, 24), 2, 3, 4);
f = fricreg_law_eval('quinn', v, 1.137, 2.385, 0.0731);
if ~isequal(size(f), [2 3 4])
    error('test:law', 'shape %s', mat2str(size(f)));
end
full = fricreg_law_eval('quinn', v, 1.137 * ones(2, 3, 4), 2.385 * ones(2, 3, 4), 0.0731);
if ~same_bits(f, full)
    error('test:law', 'a scalar expanded differs from the array');
end
col = fricreg_law_eval('tanh', (1:5)', [], 1, 2);
if ~isequal(size(col), [5 1])
    error('test:law', 'column shape %s', mat2str(size(col)));
end
empty = fricreg_law_eval('quinn', zeros(0, 3), zeros(0, 3), 1, 0.1);
if ~isequal(size(empty), [0 3])
    error('test:law', 'empty shape %s', mat2str(size(empty)));
end
end

function array_equals_single_points()
% One batched call equals a call per contact, bit for bit (fricreg_law_eval_batch).
v = [-0.3 -0.02 0 1e-9 0.0213 0.06];
feq = [-3 -1.913 0.4 1.137 2.385 9];
mun = [2.385 2.385 1 0.5 2.385 3];
f = fricreg_law_eval('quinn', v, feq, mun, 0.0731);
for i = 1:numel(v)
    one = fricreg_law_eval('quinn', v(i), feq(i), mun(i), 0.0731);
    if ~same_bits(one, f(i))
        error('test:law', 'contact %d: %.17g against %.17g', i, one, f(i));
    end
end
end

function version()
[text, number] = fricreg_version();
parts = sscanf(text, '%d.%d.%d');
if numel(parts) ~= 3 || number ~= parts(1) * 10000 + parts(2) * 100 + parts(3)
    error('test:version', '%s and %d disagree', text, number);
end
end

function same = same_bits(a, b)
same = isequal(size(a), size(b)) && isequal(typecast(a(:), 'uint64'), typecast(b(:), 'uint64'));
end
