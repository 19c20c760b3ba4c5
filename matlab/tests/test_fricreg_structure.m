% SPDX-License-Identifier: GPL-3.0-or-later
function failures = test_fricreg_structure()
%TEST_FRICREG_STRUCTURE  Structures stepped in time (fricreg_structure*.m) against closed forms:
%   average-acceleration Newmark's own discrete solution of a linear oscillator, free
%   (u_n = u0 cos(n phi), tan(phi/2) = omega dt/2), under a constant ground acceleration and a
%   constant load, and stuck on a Jenkins element; the Coulomb oscillator's decay to rest and
%   its dissipation; the energy balance; the trajectory of fricreg-sim structure (the C library's
%   numbers by its command line) to the bit; a run continued equal to one run bit for bit; the
%   accuracy warnings as fricreg:accuracy, once per kind until a reset; the error estimate's
%   fields; and every error path.
cases = {'free_vibration', @free_vibration
         'ground_and_load', @ground_and_load
         'stuck_jenkins_element', @stuck_jenkins_element
         'coulomb_oscillator', @coulomb_oscillator
         'sliding_element_energy', @sliding_element_energy
         'continued_run', @continued_run
         'against_the_cli', @against_the_cli
         'sparse_and_schemes', @sparse_and_schemes
         'accuracy_warnings', @accuracy_warnings
         'error_estimate', @error_estimate
         'errors', @errors
         'run_errors', @run_errors};
failures = fricreg_test_run('structure', cases);
end

function u = newmark_free(u0, omega, dt, n)
% Average-acceleration Newmark is the trapezoidal rule on (u, u'): a rotation by phi a step.
phi = 2 * atan(omega * dt / 2);
u = u0 * cos(phi * (0:n)');
end

function free_vibration()
m = 2.385; k = 1.37e3; u0 = 1.7e-3; dt = 2e-3;
h = fricreg_structure(m, k, 'u0', u0);
r = fricreg_structure_run(h, 'newmark', dt, 1);
fricreg_structure_free(h);
assert(isequal(size(r.times), [501 1]) && r.times(end) == 1 && r.t == 1)
fricreg_test_check(r.times, (0:500)' * dt, 1e-15, 'times', 1);
fricreg_test_check(r.displacements, newmark_free(u0, sqrt(k / m), dt, 500), 1e-12, 'u', u0);
assert(isequal(size(r.forces), [501 0]) && isempty(r.dissipation))   % no contacts
fricreg_test_check(r.peak_displacement, u0, 1e-6, 'peak');   % turning points inside steps
assert(abs(r.energy.residual) < 1e-12 * r.energy.initial)
fricreg_test_check(r.energy.initial, k * u0^2 / 2, 1e-15, 'initial energy');
assert(r.stats.steps == 500 && isempty(r.warnings) && isempty(r.peak_displacement_error))
end

function ground_and_load()
% From rest under a constant ground acceleration a_g: u_n = -(m a_g/k)(1 - cos(n phi)); under
% a constant load p: (p/k)(1 - cos(n phi)); Rayleigh damping 0 changes nothing.
m = 2.385; k = 1.37e3; ag = 2.9; dt = 1e-3; n = 400;
h = fricreg_structure(m, k, 'ground_accel', {0, 1, [ag ag]}, 'rayleigh', [0 0]);
r = fricreg_structure_run(h, 'newmark', dt, n * dt);
fricreg_structure_free(h);
us = -m * ag / k;
fricreg_test_check(r.displacements, us * (1 - newmark_free(1, sqrt(k / m), dt, n)), 1e-10, ...
                   'ground', abs(us));
assert(r.energy.input > 0 && abs(r.energy.residual) < 1e-12 * r.energy.input)
p = 0.731;
h = fricreg_structure(m, k, 'load', p, 'load_history', {0, 1, [1 1]});
r = fricreg_structure_run(h, 'newmark', dt, n * dt);
fricreg_structure_free(h);
fricreg_test_check(r.displacements, p / k * (1 - newmark_free(1, sqrt(k / m), dt, n)), 1e-10, ...
                   'load', p / k);
end

function stuck_jenkins_element()
% A Jenkins element that never slips (kt u below mun throughout) adds its spring: the
% oscillator of stiffness k + kt, its sliders at 0 from the start.
m = 2.385; k = 1.37e3; kt = 2.2e3; u0 = 1.1e-3; dt = 1e-3;
e = struct('type', 'jenkins', 'J', 1, 'params', [kt 10]);   % kt u0 = 2.4 N < 10 N
h = fricreg_structure(m, k, 'elements', e, 'u0', u0);
r = fricreg_structure_run(h, 'newmark', dt, 0.5);
fricreg_structure_free(h);
fricreg_test_check(r.displacements, newmark_free(u0, sqrt((k + kt) / m), dt, 500), 1e-10, ...
                   'u', u0);
assert(r.element_dissipation == 0 && r.energy.elements == 0)
fricreg_test_check(r.element_forces{1}, kt * r.displacements(end), 1e-10, 'element force', kt * u0);
end

function coulomb_oscillator()
% Coulomb damping: each half cycle the extreme falls by 2 r, r = mun/k, until it is within r:
% 2.385 mm -> -1.765 -> 1.145 -> -0.525 -> rest at -0.095 mm, having dissipated
% k (u0^2 - uf^2)/2 (law (4), eps small: to O(eps, dt)).
m = 2.385; k = 1e3; u0 = 2.385e-3; mun = 0.31;
h = fricreg_structure(m, k, 'J', 1, 'mun', mun, 'eps', 1e-6, 'u0', u0);
r = fricreg_structure_run(h, 'newmark', 1e-4, 1.5, 'output_every', 100);
fricreg_structure_free(h);
uf = -9.5e-5;
assert(numel(r.times) == 151 && size(r.forces, 2) == 1)
fricreg_test_check(r.displacements(end), uf, 1e-6, 'rest', u0);
fricreg_test_check(r.dissipation, k * (u0^2 - uf^2) / 2, 1e-6, 'dissipation');
fricreg_test_check(r.energy.friction, r.dissipation, 1e-15, 'friction energy');
assert(abs(r.forces(end)) <= mun && abs(r.energy.residual) < 1e-12 * r.energy.initial)
end

function sliding_element_energy()
% A Jenkins element that slips: its dissipation (fricreg_structure_get_elements) is the
% balance's, and the average-acceleration balance closes to Newton's tolerance.
m = 2.385; k = 1.37e3; kt = 5e3; mun = 0.7; u0 = 2e-3;
e = struct('type', 'jenkins', 'J', [1; 1], 'params', [kt mun; 2 * kt mun / 2]);
h = fricreg_structure(m, k, 'elements', e, 'u0', u0);
r = fricreg_structure_run(h, 'newmark', 2e-4, 1);
fricreg_structure_free(h);
assert(isequal(size(r.element_dissipation), [1 2]) && all(r.element_dissipation > 0))
fricreg_test_check(sum(r.element_dissipation), r.energy.elements, 1e-14, 'element energy');
assert(abs(r.energy.residual) < 1e-9 * r.energy.initial)
assert(isequal(size(r.element_forces{1}), [2 1]) && all(abs(r.element_forces{1}) <= [mun; mun / 2]))
end

function continued_run()
% Two runs to T1 and T2 take the steps of one run to T2 (the library continues its grid).
m = [1.3 0; 0 0.7]; k = [2.385 -1.1; -1.1 1.9] * 1e3; J = [1 -1];
args = {'J', J, 'mun', 0.4, 'u0', [2e-3 -1e-3], 'rayleigh', [0.1 1e-4]};
h = fricreg_structure(m, k, args{:});
one = fricreg_structure_run(h, 'newmark', 1e-3, 0.6);
fricreg_structure_free(h);
h = fricreg_structure(m, k, args{:});
a = fricreg_structure_run(h, 'newmark', 1e-3, 0.25);
b = fricreg_structure_run(h, 'newmark', 1e-3, 0.6);
fricreg_structure_reset(h, [2e-3 -1e-3]);            % again from the start: the same run
c = fricreg_structure_run(h, 'newmark', 1e-3, 0.6);
fricreg_structure_free(h);
assert(a.times(end) == b.times(1))
assert(isequal([a.displacements; b.displacements(2:end, :)], one.displacements))
assert(isequal(b.dissipation, one.dissipation) && isequal(b.peak_displacement, one.peak_displacement))
assert(isequal(c.displacements, one.displacements) && isequal(c.forces, one.forces))
h = fricreg_structure(m, k, args{:});                % the output dofs: the columns chosen
d = fricreg_structure_run(h, 'newmark', 1e-3, 0.6, 'output_dofs', [2 1 2]);
fricreg_structure_free(h);
assert(isequal(d.output_dofs, [2 1 2]) && isequal(one.output_dofs, [1 2]))
assert(isequal(d.displacements, one.displacements(:, [2 1 2])) && ...
       isequal(d.velocities, one.velocities(:, [2 1 2])))
end

function against_the_cli()
% The same model through fricreg-sim structure --output trajectory (the build's, beside the
% gateway's folder; skipped where there is none): its rows are the run's to the bit.
cli = fullfile(fileparts(which('fricreg_mex')), '..', 'fricreg-sim');
if ~exist(cli, 'file')
    fprintf('     (no fricreg-sim beside the gateway: skipped)\n');
    return;
end
dir = tempname(); mkdir(dir);
cleanup = onCleanup(@() remove(dir));
mm = @(name, text) write(fullfile(dir, name), ['%%MatrixMarket matrix coordinate real general', ...
                                               sprintf('\n'), text]);
mm('M.mtx', sprintf('2 2 2\n1 1 1.3\n2 2 0.7\n'));
mm('K.mtx', sprintf('2 2 4\n1 1 2385\n1 2 -1100\n2 1 -1100\n2 2 1900\n'));
mm('J.mtx', sprintf('1 2 2\n1 1 1\n1 2 -1\n'));
mm('Je.mtx', sprintf('1 2 1\n1 2 1\n'));
write(fullfile(dir, 'mun.txt'), sprintf('0.4\n'));
write(fullfile(dir, 'P.txt'), sprintf('2000 0.3\n'));
t = (0:200) * 0.01; ag = 3 * sin(4 * pi * t);
write(fullfile(dir, 'ag.txt'), sprintf('%.17g %.17g\n', [t; ag]));
f = @(name) fullfile(dir, name);
command = sprintf(['"%s" structure --mass %s --stiffness %s --contacts %s --mun %s --elements ' ...
                   'jenkins:%s:%s --rayleigh 0.1,1e-4 --ground-accel %s --dt 1e-3 --t-end 0.5 ' ...
                   '--output trajectory --error-estimate off --output-every 50 > %s 2> %s'], ...
                  cli, f('M.mtx'), f('K.mtx'), f('J.mtx'), f('mun.txt'), f('Je.mtx'), f('P.txt'), ...
                  f('ag.txt'), f('out.csv'), f('err.txt'));
assert(system(command) == 0)
rows = dlmread(f('out.csv'), ',', 1, 0);            % t, u1, u2, v1, v2, f1
h = fricreg_structure(diag([1.3 0.7]), [2385 -1100; -1100 1900], 'J', [1 -1], 'mun', 0.4, ...
                      'elements', struct('type', 'jenkins', 'J', [0 1], 'params', [2000 0.3]), ...
                      'rayleigh', [0.1 1e-4], 'ground_accel', {0, 0.01, ag});
state = warning('off', 'fricreg:accuracy');         % the CLI's eps_speed warning, here too
r = fricreg_structure_run(h, 'newmark', 1e-3, 0.5, 'output_every', 50);
warning(state);
fricreg_structure_free(h);
assert(numel(r.times) == 11 && any(r.forces ~= 0))
fricreg_test_check([r.times r.displacements r.velocities r.forces], rows, 0, 'trajectory');
assert(any(strcmp({r.warnings.name}, 'eps_speed')))
end

function remove(dir)
% The folder and its files (rmdir(dir, 's') asks first in Octave).
delete(fullfile(dir, '*'));
rmdir(dir);
end

function write(name, text)
fid = fopen(name, 'w');
fputs(fid, text);
fclose(fid);
end

function sparse_and_schemes()
% A sparse M and K give the dense model's run; HHT and central differences run and keep the
% linear oscillator's period to their order.
m = [1.3 0; 0 0.7]; k = [2.385 -1.1; -1.1 1.9] * 1e3;
h = fricreg_structure(m, k, 'u0', [1e-3 0]);
d = fricreg_structure_run(h, 'newmark', 1e-3, 0.3);
fricreg_structure_free(h);
h = fricreg_structure(sparse(m), sparse(k), 'u0', [1e-3 0]);
s = fricreg_structure_run(h, 'newmark', 1e-3, 0.3);
fricreg_structure_free(h);
fricreg_test_check(s.displacements, d.displacements, 1e-13, 'sparse', 1e-3);
for scheme = {'hht', 'central'}
    h = fricreg_structure(m, k, 'u0', [1e-3 0]);
    r = fricreg_structure_run(h, scheme{1}, 1e-3, 0.3, 'alpha', -0.1);
    fricreg_structure_free(h);
    fricreg_test_check(r.displacements, d.displacements, 2e-2, scheme{1}, 1e-3);
end
end

function accuracy_warnings()
% dt above a tenth of the period: dt_coarse, raised as fricreg:accuracy once until a reset,
% and kept in r.warnings every run.
m = 2.385; k = 1e3;
h = fricreg_structure(m, k, 'u0', 1e-3);
state = warning('on', 'fricreg:accuracy');
lastwarn('');
r = fricreg_structure_run(h, 'newmark', 0.05, 1);
[msg, id] = lastwarn();
assert(strcmp(id, 'fricreg:accuracy') && ~isempty(strfind(msg, 'dt_coarse: dt = 0.05 s')))
assert(numel(r.warnings) == 1 && strcmp(r.warnings(1).name, 'dt_coarse'))
lastwarn('');
r = fricreg_structure_run(h, 'newmark', 0.05, 2);
assert(isempty(lastwarn()) && strcmp(r.warnings(1).name, 'dt_coarse'))   % not raised again
fricreg_structure_reset(h, 1e-3);
r = fricreg_structure_run(h, 'newmark', 0.05, 1);
[~, id] = lastwarn();
assert(strcmp(id, 'fricreg:accuracy'))
warning('off', 'fricreg:accuracy');                 % silenced: the field keeps them
fricreg_structure_reset(h);
lastwarn('');
r = fricreg_structure_run(h, 'newmark', 0.05, 1);
assert(isempty(lastwarn()) && numel(r.warnings) == 1)
warning(state);
fricreg_structure_free(h);
end

function error_estimate()
m = 2.385; k = 1e3;
h = fricreg_structure(m, k, 'J', 1, 'mun', 0.31, 'eps', 1e-4, 'u0', 2.385e-3, ...
                      'error_estimate', 'on', 'elements', ...
                      struct('type', 'jenkins', 'J', 1, 'params', [2e3 0.2]));
state = warning('off', 'fricreg:accuracy');
r = fricreg_structure_run(h, 'newmark', 1e-3, 0.5);
warning(state);
fricreg_structure_free(h);
for f = {'peak_displacement_error', 'dissipation_error', 'element_dissipation_error'}
    e = r.(f{1});
    assert(isstruct(e) && all(e.error >= 0) && iscellstr(e.kind) && ...
           all(ismember(e.kind, {'asymptotic', 'bound', 'assumed'})))
end
assert(numel(r.peak_displacement_error.error) == 1 && numel(r.dissipation_error.kind) == 1)
end

function errors()
m = 2.385; k = 1e3;
fricreg_test_raises('fricreg:nargs', @() fricreg_structure(m));
fricreg_test_raises('fricreg:type', @() fricreg_structure(single(m), k));
fricreg_test_raises('fricreg:type', @() fricreg_structure(m, k + 1i));
fricreg_test_raises('fricreg:type', @() fricreg_structure(m, k, 'elements', 3));
fricreg_test_raises('fricreg:type', @() fricreg_structure(m, k, 'elements', struct('type', 'jenkins')));
fricreg_test_raises('fricreg:type', @() fricreg_structure(m, k, 'ground_accel', [0 1 2]));
fricreg_test_raises('fricreg:size', @() fricreg_structure(eye(2), k));
fricreg_test_raises('fricreg:size', @() fricreg_structure(m, k, 'J', [1 1], 'mun', 1));
fricreg_test_raises('fricreg:size', @() fricreg_structure(m, k, 'J', 1, 'mun', [1 1]));
fricreg_test_raises('fricreg:size', @() fricreg_structure(m, k, 'u0', [1 2]));
fricreg_test_raises('fricreg:size', @() fricreg_structure(m, k, 'influence', [1 1]));
fricreg_test_raises('fricreg:size', @() fricreg_structure(m, k, 'load', [1 1]));
fricreg_test_raises('fricreg:size', @() fricreg_structure(m, k, 'rayleigh', 1));
fricreg_test_raises('fricreg:size', @() fricreg_structure(m, k, 'newton', 1e-9));
fricreg_test_raises('fricreg:size', @() fricreg_structure(m, k, 'ground_accel', {0, 0.1, 1}));
fricreg_test_raises('fricreg:size', @() fricreg_structure(m, k, 'elements', ...
                    struct('type', 'jenkins', 'J', [1 1], 'params', [1 1])));
fricreg_test_raises('fricreg:size', @() fricreg_structure(m, k, 'elements', ...
                    struct('type', 'jenkins', 'J', 1, 'params', [1 1 1])), 'nparams');
fricreg_test_raises('fricreg:option', @() fricreg_structure(m, k, 'mass', 1));
fricreg_test_raises('fricreg:option', @() fricreg_structure(m, k, 'J'));
fricreg_test_raises('fricreg:option', @() fricreg_structure(m, k, 'J', 1), 'together');
fricreg_test_raises('fricreg:option', @() fricreg_structure(m, k, 'eps', 1e-3));
fricreg_test_raises('fricreg:option', @() fricreg_structure(m, k, 'damping', 1, 'rayleigh', [0 0]));
fricreg_test_raises('fricreg:option', @() fricreg_structure(m, k, 'load_history', {0, 1, [1 1]}));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure(m, k, 'J', 1, 'mun', -1));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure(m, k, 'J', 0, 'mun', 1));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure(m, k, 'J', 1, 'mun', 1, 'eps', 0));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure(m, k, 'J', 1, 'mun', 1, 'law', 'x'));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure(m, k, 'J', 1, 'mun', 1, 'law', 99));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure(m, k, 'rayleigh', [-1 0]));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure(m, k, 'newton', [2 10]));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure(m, k, 'error_estimate', 'yes'));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure(m, k, 'ground_accel', {0, -1, [1 1]}));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure(m, k, 'elements', ...
                    struct('type', 'jenkins', 'J', 1, 'params', [-1 1])));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure(m, k, 'elements', ...
                    struct('type', 'nope', 'J', 1, 'params', [1 1])));
fricreg_test_raises('fricreg:ENOTSYM', @() fricreg_structure([1 0.5; 0 1], eye(2)));
fricreg_test_raises('fricreg:ENONFINITE', @() fricreg_structure(m, NaN));
fricreg_test_raises('fricreg:ENONFINITE', @() fricreg_structure(m, k, 'u0', Inf));
assert(fricreg_mex('handles') == 0)                 % the failed constructions freed theirs
end

function run_errors()
m = 2.385; k = 1e3;
h = fricreg_structure(m, k, 'u0', 1e-3);
fricreg_test_raises('fricreg:nargs', @() fricreg_structure_run(h, 'newmark', 1e-3));
fricreg_test_raises('fricreg:type', @() fricreg_structure_run(h, 3, 1e-3, 1));
fricreg_test_raises('fricreg:type', @() fricreg_structure_run(h, 'newmark', single(1e-3), 1));
fricreg_test_raises('fricreg:option', @() fricreg_structure_run(h, 'newmark', 1e-3, 1, 'every', 2));
fricreg_test_raises('fricreg:option', @() fricreg_structure_run(h, 'newmark', 1e-3, 1, 'alpha'));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure_run(h, 'euler', 1e-3, 1), 'euler');
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure_run(h, 'newmark', -1e-3, 1));
fricreg_test_raises('fricreg:ENONFINITE', @() fricreg_structure_run(h, 'newmark', NaN, 1));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure_run(h, 'newmark', 1e-3, 0), 'after t = 0');
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure_run(h, 'hht', 1e-3, 1, 'alpha', -0.5));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure_run(h, 'newmark', 1e-3, 1, ...
                                                                'output_every', 0));
fricreg_test_raises('fricreg:ESTEP', @() fricreg_structure_run(h, 'central', 0.2, 1));
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure_run(h, 'newmark', 1e-3, 1, ...
                                                                'output_dofs', 2), 'not a dof');
fricreg_test_raises('fricreg:EINVAL', @() fricreg_structure_run(h, 'newmark', 1e-3, 1, ...
                                                                'output_dofs', 0.5));
fricreg_test_raises('fricreg:type', @() fricreg_structure_run(h, 'newmark', 1e-3, 1, ...
                                                              'output_dofs', int32(1)));
fricreg_test_raises('fricreg:size', @() fricreg_structure_reset(h, [1 2]));
fricreg_test_raises('fricreg:nargs', @() fricreg_structure_free());
r = fricreg_structure_run(h, 'newmark', 1e-3, 0.1);  % still usable after the errors
assert(r.t == 0.1)
fricreg_structure_free(h);
fricreg_test_raises('fricreg:handle', @() fricreg_structure_run(h, 'newmark', 1e-3, 1));
fricreg_test_raises('fricreg:handle', @() fricreg_structure_free(h));
hb = fricreg_harmonic_balance(1, 1, 0.02, struct('type', 'jenkins', 'J', 1, 'params', [20 1]), 3);
fricreg_test_raises('fricreg:handle', @() fricreg_structure_run(hb, 'newmark', 1e-3, 1));
fricreg_test_raises('fricreg:handle', @() fricreg_mex('st_set_bounds', hb, 1));
fricreg_hb_free(hb);
h = fricreg_structure(m, k);
clear fricreg_mex                                    % frees the structure; the handle is stale
fricreg_test_raises('fricreg:handle', @() fricreg_structure_run(h, 'newmark', 1e-3, 1));
end
