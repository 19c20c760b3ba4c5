% SPDX-License-Identifier: GPL-3.0-or-later
function failures = test_fricreg_hb_errors()
%TEST_FRICREG_HB_ERRORS  Every error path of the harmonic-balance commands and .m files raises
%   its identifier and never crashes: stale, foreign and malformed handles on every hb_*
%   command; wrong shapes and types; NaN and infinite inputs; values out of range (the
%   library's fricreg:EINVAL with its message); unknown options; an NLvib element type with no
%   fricreg element; a failed construction leaves no driver behind, and clearing the MEX file
%   frees the drivers.
cases = {'handles', @handles
         'argument_counts', @argument_counts
         'shapes', @shapes
         'types', @types
         'non_finite', @non_finite
         'out_of_range', @out_of_range
         'options', @options
         'nlvib', @nlvib
         'failed_construction_frees', @failed_construction_frees
         'clear_frees_drivers', @clear_frees_drivers
         'level_and_multipliers', @level_and_multipliers
         'truncation_error', @truncation_error
         'element_params', @element_params
         'sensitivities', @sensitivities};
failures = fricreg_test_run('hb_errors', cases);
end

function h = oscillator()
% One mass, a spring, a Jenkins element: solvable.
h = fricreg_harmonic_balance(1, 1, 0.02, struct('type', 'jenkins', 'J', 1, 'params', [20 1]), ...
                             3, 'excitation', 0.5);
end

function calls = every_command(h)
% Each hb_* command with arguments valid for oscillator()'s driver, the handle h.
calls = {@() fricreg_mex('hb_set_matrix', h, 'mass', 1)
         @() fricreg_mex('hb_set_rayleigh', h, 0, 0)
         @() fricreg_mex('hb_set_jenkins', h, 1, 20, 1)
         @() fricreg_mex('hb_add_elements', h, 'jenkins', 1, [20 1])
         @() fricreg_mex('hb_set_excitation', h, 1, 0)
         @() fricreg_mex('hb_set_newton', h, 1e-10, 50)
         @() fricreg_mex('hb_set_continuation', h, 0.02, 1e-6, 0.1, 100)
         @() fricreg_mex('hb_set_stability', h, true, 'auto')
         @() fricreg_mex('hb_set_max_iterations', h, 0)
         @() fricreg_mex('hb_info', h)
         @() fricreg_mex('hb_solve', h, 1.5)
         @() fricreg_mex('hb_continue', h, 1, 2)
         @() fricreg_mex('hb_nma', h, 1, 'matrix', 0.01, 1, 5, false)
         @() fricreg_mex('hb_nma', h, 1, 'matrix', [0.1 0.2])
         @() fricreg_mex('hb_peak', h, 1)
         @() fricreg_mex('hb_continue_level', h, 1.5, 0.5, 1)
         @() fricreg_mex('hb_truncation_error', h, 0)
         @() fricreg_mex('hb_nma_sensitivities', h, 1, 0, 1, 1, 1, false)
         @() fricreg_mex('hb_set_element_param', h, 1, 1, 1, 20)
         @() fricreg_mex('hb_get_element_param', h, 1, 1)
         @() fricreg_hb_level_response(h, 1.5, 0.5, 1)
         @() fricreg_hb_truncation_error(h)
         @() fricreg_hb_backbone_sensitivities(h, 1, {{'amplitude'}})
         @() fricreg_hb_set_element_param(h, 1, 1, 20)
         @() fricreg_hb_element_param(h, 1, 1)
         @() fricreg_mex('hb_modal_participation', h, 1, 1)
         @() fricreg_hb_modal_participation(h, 1, 1)
         @() fricreg_hb_solve(h, 1.5)
         @() fricreg_hb_frequency_response(h, 1, 2)
         @() fricreg_hb_backbone(h, 1, 0.01, 1)
         @() fricreg_hb_backbone_at(h, 1, 0.1)
         @() fricreg_hb_peak(h, 1)
         @() fricreg_hb_set(h, 'newton', [1e-10 50])};
end

function handles()
r = @fricreg_test_raises;
h = oscillator();
fricreg_hb_free(h);
fit = fricreg_mex('fit_create');
cleanup = onCleanup(@() fricreg_mex('free', fit));
for bad = {h, fit, 0, -1, NaN, 1.5, [1 2], 'h', int32(1), {1}, []}
    calls = every_command(bad{1});
    for k = 1:numel(calls)
        r('fricreg:handle', calls{k});
    end
end
r('fricreg:handle', @() fricreg_hb_free(h)); % twice
% and a driver's handle on the fit's commands
g = oscillator();
cg = onCleanup(@() fricreg_hb_free(g));
r('fricreg:handle', @() fricreg_mex('fit_run', g), 'not of this command''s kind');
end

function argument_counts()
r = @fricreg_test_raises;
h = oscillator();
cleanup = onCleanup(@() fricreg_hb_free(h));
r('fricreg:nargs', @() fricreg_mex('hb_create', 1, 1));
r('fricreg:nargs', @() fricreg_mex('hb_solve', h));
r('fricreg:nargs', @() fricreg_mex('hb_solve', h, 1, [], 1));
r('fricreg:nargs', @() fricreg_mex('hb_continue', h, 1));
r('fricreg:nargs', @() fricreg_mex('hb_nma', h, 1, 'matrix', 0.1, 1));
r('fricreg:nargs', @() fricreg_mex('hb_set_matrix', h, 'mass'));
r('fricreg:nargs', @() fricreg_harmonic_balance(1, 1, 0, struct('type', 'jenkins', 'J', 1, ...
                                                                  'params', [1 1])));
r('fricreg:nargs', @() fricreg_hb_solve(h));
r('fricreg:nargs', @() fricreg_hb_frequency_response(h, 1));
r('fricreg:nargs', @() fricreg_hb_backbone(h, 1, 0.1));
r('fricreg:nargs', @() fricreg_hb_peak(h));
r('fricreg:nargs', @() fricreg_hb_free());
r('fricreg:nargs', @() fricreg_nlvib_frf(struct(), 3, 1));
r('fricreg:nargs', @() two_outputs('hb_create', 1, 1, 3));
end

function two_outputs(varargin)
[a, b] = fricreg_mex(varargin{:}); %#ok<ASGLU>
end

function shapes()
r = @fricreg_test_raises;
jk = struct('type', 'jenkins', 'J', [1 -1], 'params', [20 1]);
r('fricreg:size', @() fricreg_harmonic_balance(eye(2), [1 0 0; 0 1 0], [], jk, 3), 'stiffness');
r('fricreg:size', @() fricreg_harmonic_balance(eye(2), eye(2), zeros(3), jk, 3), 'damping');
r('fricreg:size', @() fricreg_harmonic_balance(eye(2), eye(2), [], ...
                   struct('type', 'jenkins', 'J', [1 -1 0], 'params', [20 1]), 3), 'J');
r('fricreg:size', @() fricreg_harmonic_balance(eye(2), eye(2), [], ...
                   struct('type', 'jenkins_normal', 'J', [1 0; 0 1; 1 1], ...
                          'params', [20 0.3 10 5 0]), 3), 'jenkins_normal');
r('fricreg:size', @() fricreg_harmonic_balance(eye(2), eye(2), [], ...
                   struct('type', 'jenkins', 'J', [1 -1], 'params', [20 1 3]), 3), 'nparams');
r('fricreg:size', @() fricreg_harmonic_balance(eye(2), eye(2), [], ...
                   struct('type', 'jenkins', 'J', [1 -1; 1 0], 'params', [20 1; 20 1; 2 2]), 3));
r('fricreg:size', @() fricreg_harmonic_balance(eye(2), eye(2), [], jk, 3, 'rayleigh', 1));
h = fricreg_harmonic_balance(eye(2), 2 * eye(2), 0.1 * eye(2), jk, 3);
cleanup = onCleanup(@() fricreg_hb_free(h));
r('fricreg:size', @() fricreg_hb_set(h, 'excitation', [1 2 3]), 'pc');
r('fricreg:size', @() fricreg_hb_set(h, 'excitation', {[1 0], [1 2 3]}), 'ps');
r('fricreg:size', @() fricreg_hb_set(h, 'excitation', {1}));
r('fricreg:size', @() fricreg_hb_set(h, 'newton', 1e-10));
r('fricreg:size', @() fricreg_hb_set(h, 'continuation', [0.02 1e-6 0.1]));
r('fricreg:size', @() fricreg_hb_solve(h, [1 2]), 'omega');
r('fricreg:size', @() fricreg_hb_solve(h, 1.5, zeros(2, 7)), 'guess must be rows x (2H + 1) = 1x7');
r('fricreg:size', @() fricreg_hb_solve(h, 1.5, zeros(1, 5)));
r('fricreg:size', @() fricreg_hb_frequency_response(h, 1, 2, zeros(7, 1)));
r('fricreg:size', @() fricreg_hb_backbone_at(h, 1, [0.1 0.2; 0.3 0.4]), 'amplitudes');
r('fricreg:size', @() fricreg_mex('hb_set_jenkins', h, [1 -1], [20 20], 1), 'kt');
r('fricreg:size', @() fricreg_mex('hb_set_jenkins', h, [1 -1 0], 20, 1), 'J');
r('fricreg:size', @() fricreg_mex('hb_set_matrix', h, 'mass', ones(2, 2, 2)));
end

function types()
r = @fricreg_test_raises;
jk = struct('type', 'jenkins', 'J', 1, 'params', [20 1]);
r('fricreg:type', @() fricreg_harmonic_balance(1, 1, [], {1}, 3));
r('fricreg:type', @() fricreg_harmonic_balance(1, 1, [], 'jenkins', 3));
r('fricreg:type', @() fricreg_harmonic_balance(1, 1, [], struct('type', 'jenkins', 'J', 1), 3), ...
  'params');
r('fricreg:type', @() fricreg_harmonic_balance(1i, 1, [], jk, 3), 'mass');
r('fricreg:type', @() fricreg_harmonic_balance(single(1), 1, [], jk, 3));
r('fricreg:type', @() fricreg_harmonic_balance(1, {1}, [], jk, 3));
r('fricreg:type', @() fricreg_harmonic_balance(1, 1, [], struct('type', 3, 'J', 1, ...
                                                                 'params', [1 1]), 3));
h = fricreg_harmonic_balance(1, 1, 0.02, jk, 3);
cleanup = onCleanup(@() fricreg_hb_free(h));
for bad = {single(1.5), int32(2), true, 1.5 + 1i, sparse(1.5), 'a', {1.5}}
    r('fricreg:type', @() fricreg_hb_solve(h, bad{1}));
    r('fricreg:type', @() fricreg_hb_frequency_response(h, 1, bad{1}));
end
r('fricreg:type', @() fricreg_hb_solve(h, 1.5, single(zeros(1, 7))));
r('fricreg:type', @() fricreg_mex('hb_add_elements', h, 'jenkins', single(1), [1 1]));
r('fricreg:type', @() fricreg_mex('hb_set_excitation', h, {1}, 0));
r('fricreg:type', @() fricreg_hb_backbone(h, 1, 0.1, 1, 5, 'damping', 3));
r('fricreg:type', @() fricreg_hb_set(h, 'stability', true, 'method', 2));
end

function non_finite()
r = @fricreg_test_raises;
jk = struct('type', 'jenkins', 'J', 1, 'params', [20 1]);
r('fricreg:ENONFINITE', @() fricreg_harmonic_balance(NaN, 1, [], jk, 3));
r('fricreg:ENONFINITE', @() fricreg_harmonic_balance(1, Inf, [], jk, 3));
r('fricreg:ENONFINITE', @() fricreg_harmonic_balance(1, 1, sparse(NaN), jk, 3));
r('fricreg:ENONFINITE', @() fricreg_harmonic_balance(1, 1, [], ...
                        struct('type', 'jenkins', 'J', NaN, 'params', [20 1]), 3));
r('fricreg:ENONFINITE', @() fricreg_harmonic_balance(1, 1, [], ...
                        struct('type', 'jenkins', 'J', 1, 'params', [Inf 1]), 3));
r('fricreg:ENONFINITE', @() fricreg_harmonic_balance(1, 1, [], jk, 3, 'rayleigh', [NaN 0]));
h = oscillator();
cleanup = onCleanup(@() fricreg_hb_free(h));
r('fricreg:ENONFINITE', @() fricreg_hb_set(h, 'excitation', NaN));
r('fricreg:ENONFINITE', @() fricreg_hb_set(h, 'excitation', {1, Inf}));
r('fricreg:ENONFINITE', @() fricreg_hb_set(h, 'newton', [NaN 50]));
r('fricreg:ENONFINITE', @() fricreg_hb_set(h, 'continuation', [Inf 1e-6 0.1 100]));
r('fricreg:ENONFINITE', @() fricreg_hb_solve(h, NaN));
r('fricreg:ENONFINITE', @() fricreg_hb_solve(h, Inf));
r('fricreg:ENONFINITE', @() fricreg_hb_solve(h, 1.5, [0 NaN 0 0 0 0 0]));
r('fricreg:ENONFINITE', @() fricreg_hb_frequency_response(h, 1, Inf));
r('fricreg:ENONFINITE', @() fricreg_hb_backbone(h, 1, 0.01, Inf));
r('fricreg:ENONFINITE', @() fricreg_hb_backbone_at(h, 1, [0.1 NaN]));
end

function out_of_range()
r = @fricreg_test_raises;
jk = struct('type', 'jenkins', 'J', 1, 'params', [20 1]);
r('fricreg:EINVAL', @() fricreg_harmonic_balance(1, 1, [], jk, 41), 'harmonics 1..40');
r('fricreg:EINVAL', @() fricreg_harmonic_balance(1, 1, [], jk, 0));
r('fricreg:EINVAL', @() fricreg_harmonic_balance(1, 1, [], jk, 2.5), 'whole number');
r('fricreg:EINVAL', @() fricreg_harmonic_balance(1, 1, [], ...
                     struct('type', 'jenkins', 'J', 1, 'params', [-20 1]), 3));
r('fricreg:EINVAL', @() fricreg_harmonic_balance(1, 1, [], ...
                     struct('type', 'slider', 'J', 1, 'params', [20 1]), 3), 'jenkins');
r('fricreg:EINVAL', @() fricreg_harmonic_balance(1, 1, [], ...
                     struct('type', 'jenkins', 'J', 0, 'params', [20 1]), 3));
r('fricreg:EINVAL', @() fricreg_harmonic_balance(1, 1, [], jk, 3, 'rayleigh', [-1 0]));
r('fricreg:EINVAL', @() fricreg_harmonic_balance(1, 1, 0.1, jk, 3, 'rayleigh', [0 0.1]), ...
  'one damping');
r('fricreg:EINVAL', @() fricreg_harmonic_balance(-1, 1, [], jk, 3), 'M(1, 1) = -1');
r('fricreg:EINVAL', @() fricreg_harmonic_balance(sparse([1 0; 0 -2]), eye(2), [], ...
                     struct('type', 'jenkins', 'J', [1 -1], 'params', [20 1]), 3), 'M(2, 2)');
r('fricreg:ENOTSYM', @() fricreg_harmonic_balance(eye(2), [2 -1; 0 2], [], ...
                      struct('type', 'jenkins', 'J', [1 -1], 'params', [20 1]), 3));
h = oscillator();
cleanup = onCleanup(@() fricreg_hb_free(h));
r('fricreg:EINVAL', @() fricreg_hb_solve(h, 0));
r('fricreg:EINVAL', @() fricreg_hb_solve(h, -1.5));
r('fricreg:EINVAL', @() fricreg_hb_frequency_response(h, 1.5, 1.5));
r('fricreg:EINVAL', @() fricreg_hb_set(h, 'newton', [2 50]));
r('fricreg:EINVAL', @() fricreg_hb_set(h, 'newton', [1e-10 0]));
r('fricreg:EINVAL', @() fricreg_hb_set(h, 'continuation', [0.5 1e-6 0.1 100]));
r('fricreg:EINVAL', @() fricreg_hb_set(h, 'stability', true, 'method', 'euler'), 'hill');
r('fricreg:EINVAL', @() fricreg_hb_set(h, 'solver', 'sparse'), 'capacitance');
r('fricreg:EINVAL', @() fricreg_hb_set(h, 'receptance', 'klu'), 'modes');
r('fricreg:EINVAL', @() fricreg_hb_set(h, 'stability', 2));
r('fricreg:EINVAL', @() fricreg_hb_backbone(h, 0, 0.01, 1), 'mode');
r('fricreg:EINVAL', @() fricreg_hb_backbone(h, 2, 0.01, 1), 'mode');
r('fricreg:EINVAL', @() fricreg_hb_backbone(h, 1, 1, 0.01));
r('fricreg:EINVAL', @() fricreg_hb_backbone(h, 1, 0.01, 1, 1));
r('fricreg:EINVAL', @() fricreg_hb_backbone(h, 1, 0.01, 1, 5, 'damping', 'viscous'), 'modal');
r('fricreg:EINVAL', @() fricreg_hb_backbone_at(h, 1, [0.2 0.1]));
r('fricreg:EINVAL', @() fricreg_hb_peak(h, 1)); % no branch yet
r('fricreg:EINVAL', @() fricreg_hb_peak(h, 2), 'dof');
r('fricreg:EINVAL', @() fricreg_mex('hb_set_matrix', h, 'inertia', 1), 'stiffness');
r('fricreg:EINVAL', @() fricreg_hb_set(h, 'max_iterations', -1));
% a bound on the Newton steps stops a call with fricreg:EWORK (MATLAB's stand-in for Ctrl-C)
fricreg_hb_set(h, 'max_iterations', 3);
r('fricreg:EWORK', @() fricreg_hb_frequency_response(h, 1, 2), 'Newton');
fricreg_hb_set(h, 'max_iterations', 0);
fricreg_hb_frequency_response(h, 1, 2);
% a driver made for two elements holding one: the solves refuse it
g = fricreg_mex('hb_create', 1, 2, 3);
cg = onCleanup(@() fricreg_mex('free', g));
fricreg_mex('hb_set_matrix', g, 'stiffness', 1);
fricreg_mex('hb_add_elements', g, 'jenkins', 1, [20 1]);
r('fricreg:EINVAL', @() fricreg_hb_solve(g, 1.5));
r('fricreg:ESIZE', @() fricreg_mex('hb_add_elements', g, 'jenkins', [1; 1], [20 1]));
end

function options()
r = @fricreg_test_raises;
jk = struct('type', 'jenkins', 'J', 1, 'params', [20 1]);
r('fricreg:option', @() fricreg_harmonic_balance(1, 1, [], jk, 3, 'damping'));
r('fricreg:option', @() fricreg_harmonic_balance(1, 1, [], jk, 3, 'damping', 1), 'damping');
r('fricreg:option', @() fricreg_harmonic_balance(1, 1, [], jk, 3, 3, 1));
h = oscillator();
cleanup = onCleanup(@() fricreg_hb_free(h));
r('fricreg:option', @() fricreg_hb_set(h, 'tolerance', 1e-9), 'tolerance');
r('fricreg:option', @() fricreg_hb_set(h, 'newton'));
r('fricreg:option', @() fricreg_hb_backbone(h, 1, 0.01, 1, 5, 'folds', true));
r('fricreg:option', @() fricreg_hb_backbone_at(h, 1, 0.1, 'through_folds', true));
r('fricreg:option', @() fricreg_nlvib_frf(fricreg_test_nlvib_chain(), 3, 0.5, 2, 'N', 1024));
end

function nlvib()
r = @fricreg_test_raises;
e = r('fricreg:nlvib', @() fricreg_nlvib_frf(fricreg_test_nlvib_chain(true), 7, 0.5, 2));
if isempty(strfind(e.message, 'cubicSpring (element 3)')) || ...
   isempty(strfind(e.message, 'cubicSpring (element 4)')) || ...
   ~isempty(strfind(e.message, 'unilateralSpring (element 5)')) % it has one: jenkins_normal
    error('test:nlvib', 'the message does not name every type: %s', e.message);
end
sys = fricreg_test_nlvib_chain();
sys.nonlinear_elements{2}.islocal = false;
r('fricreg:nlvib', @() fricreg_nlvib_frf(sys, 7, 0.5, 2), 'global');
sys = fricreg_test_nlvib_chain();
sys.nonlinear_elements{1} = rmfield(sys.nonlinear_elements{1}, 'stiffness');
r('fricreg:nlvib', @() fricreg_nlvib_frf(sys, 7, 0.5, 2), 'stiffness');
sys = fricreg_test_nlvib_chain(true);
sys.nonlinear_elements = sys.nonlinear_elements([1 2 5]);
sys.nonlinear_elements{3} = rmfield(sys.nonlinear_elements{3}, 'gap');
r('fricreg:nlvib', @() fricreg_nlvib_frf(sys, 7, 0.5, 2), 'unilateralSpring) has no field gap');
sys = fricreg_test_nlvib_chain();
sys.nonlinear_elements{1}.force_direction = [1; 0];
r('fricreg:nlvib', @() fricreg_nlvib_frf(sys, 7, 0.5, 2), 'force_direction');
sys = fricreg_test_nlvib_chain();
sys.nonlinear_elements = [sys.nonlinear_elements{:}];   % a struct array works as a cell
sys.nonlinear_elements(2).type = 'tanhDryFriction';
r('fricreg:nlvib', @() fricreg_nlvib_frf(sys, 7, 0.5, 2), 'tanhDryFriction (element 2)');
sys = fricreg_test_nlvib_chain();
r('fricreg:size', @() fricreg_nlvib_frf(sys, 7, 0.5, 2, 'x0', zeros(44, 1)), 'x0');
sys.Fex1 = [0; 1];
r('fricreg:size', @() fricreg_nlvib_frf(sys, 7, 0.5, 2), 'Fex1');
sys = fricreg_test_nlvib_chain();
sys.nonlinear_elements{1}.friction_limit_force = NaN;
r('fricreg:ENONFINITE', @() fricreg_nlvib_frf(sys, 7, 0.5, 2));
end

function failed_construction_frees()
% A driver made and then refused (a setter failed) is freed before the error.
before = fricreg_mex('handles');
fricreg_test_raises('fricreg:ENOTSYM', @() fricreg_harmonic_balance(eye(2), [2 -1; 0 2], [], ...
                    struct('type', 'jenkins', 'J', [1 -1], 'params', [20 1]), 3));
fricreg_test_raises('fricreg:ENONFINITE', @() fricreg_harmonic_balance(1, 1, [], ...
                    struct('type', 'jenkins', 'J', 1, 'params', [20 1]), 3, 'excitation', NaN));
fricreg_test_raises('fricreg:nlvib', @() fricreg_nlvib_frf(fricreg_test_nlvib_chain(true), ...
                                                           7, 0.5, 2));
sys = fricreg_test_nlvib_chain();
fricreg_test_raises('fricreg:EINVAL', @() fricreg_nlvib_frf(sys, 7, 0.5, 0.5));
if fricreg_mex('handles') ~= before
    error('test:free', '%d drivers left', fricreg_mex('handles') - before);
end
end

function clear_frees_drivers()
old = [oscillator(), oscillator()];
clear fricreg_mex
if fricreg_mex('handles') ~= 0
    error('test:clear', 'drivers survived the clear');
end
fricreg_test_raises('fricreg:handle', @() fricreg_hb_solve(old(1), 1.5));
fricreg_test_raises('fricreg:handle', @() fricreg_hb_free(old(2)));
end

function level_and_multipliers()
r = @fricreg_test_raises;
h = oscillator();
cleanup = onCleanup(@() fricreg_hb_free(h));
r('fricreg:nargs', @() fricreg_hb_level_response(h, 1.5, 0.5));
r('fricreg:nargs', @() fricreg_mex('hb_continue_level', h, 1.5, 0.5));
r('fricreg:nargs', @() fricreg_mex('hb_continue_level', h, 1.5, 0.5, 1, [], 1));
r('fricreg:EINVAL', @() fricreg_hb_level_response(h, 1.5, 1, 1));
r('fricreg:EINVAL', @() fricreg_hb_level_response(h, 1.5, -0.5, 1));
r('fricreg:EINVAL', @() fricreg_hb_level_response(h, 0, 0.5, 1));
r('fricreg:ENONFINITE', @() fricreg_hb_level_response(h, 1.5, 0.5, Inf));
r('fricreg:ENONFINITE', @() fricreg_hb_level_response(h, NaN, 0.5, 1));
r('fricreg:size', @() fricreg_hb_level_response(h, 1.5, 0.5, 1, zeros(2, 7)), 'guess');
r('fricreg:size', @() fricreg_hb_level_response(h, 1.5, [0.5 1], 2), 'level0');
r('fricreg:type', @() fricreg_hb_level_response(h, 1.5, 0.5, int8(1)), 'level1');
fricreg_hb_set(h, 'max_iterations', 2);
r('fricreg:EWORK', @() fricreg_hb_level_response(h, 1.5, 0.5, 1));
fricreg_hb_set(h, 'max_iterations', 0);
r('fricreg:nargs', @() six_outputs('hb_solve', h, 1.5));
end

function six_outputs(varargin)
[a, b, c, d, e, f] = fricreg_mex(varargin{:}); %#ok<ASGLU>
end

function truncation_error()
r = @fricreg_test_raises;
h = oscillator();
cleanup = onCleanup(@() fricreg_hb_free(h));
r('fricreg:nargs', @() fricreg_hb_truncation_error());
r('fricreg:nargs', @() fricreg_mex('hb_truncation_error', h));
r('fricreg:EINVAL', @() fricreg_hb_truncation_error(h), 'solution'); % none yet
fricreg_hb_frequency_response(h, 1, 1.2);
r('fricreg:EINVAL', @() fricreg_hb_truncation_error(h, 1e6));
r('fricreg:EINVAL', @() fricreg_hb_truncation_error(h, 0), 'from 1');
r('fricreg:EINVAL', @() fricreg_hb_truncation_error(h, 1.5), 'whole number');
r('fricreg:EINVAL', @() fricreg_hb_truncation_error(h, -1));
r('fricreg:size', @() fricreg_hb_truncation_error(h, [1 2]));
fricreg_hb_set_element_param(h, 1, 1, 21); % a model change: the branch is gone
r('fricreg:EINVAL', @() fricreg_hb_truncation_error(h, 1));
g = fricreg_harmonic_balance(1, 1, 0.02, struct('type', 'jenkins', 'J', 1, 'params', [20 1]), ...
                             20, 'excitation', 0.5);
cg = onCleanup(@() fricreg_hb_free(g));
fricreg_hb_solve(g, 1.5);
r('fricreg:EINVAL', @() fricreg_hb_truncation_error(g), 'H');
end

function element_params()
r = @fricreg_test_raises;
h = oscillator();
cleanup = onCleanup(@() fricreg_hb_free(h));
r('fricreg:nargs', @() fricreg_hb_set_element_param(h, 1, 1));
r('fricreg:nargs', @() fricreg_hb_element_param(h, 1));
r('fricreg:nargs', @() fricreg_mex('hb_set_element_param', h, 1, 1, 1));
r('fricreg:nargs', @() fricreg_mex('hb_get_element_param', h, 1));
r('fricreg:EINVAL', @() fricreg_hb_set_element_param(h, 2, 1, 20));
r('fricreg:EINVAL', @() fricreg_hb_set_element_param(h, 1:2, 1, 20));
r('fricreg:EINVAL', @() fricreg_hb_set_element_param(h, 1, 3, 20));
r('fricreg:EINVAL', @() fricreg_hb_set_element_param(h, 1, 1, -20));
r('fricreg:EINVAL', @() fricreg_hb_set_element_param(h, 1, 0, 20), 'index');
r('fricreg:EINVAL', @() fricreg_hb_set_element_param(h, 0, 1, 20), 'first');
r('fricreg:EINVAL', @() fricreg_mex('hb_set_element_param', h, 1, 0, 1, 20)); % count 0
r('fricreg:ENONFINITE', @() fricreg_hb_set_element_param(h, 1, 1, NaN));
r('fricreg:size', @() fricreg_hb_set_element_param(h, [1 3], 1, 20), 'consecutive');
r('fricreg:size', @() fricreg_hb_set_element_param(h, [], 1, 20));
r('fricreg:size', @() fricreg_hb_set_element_param(h, 1, 1, [20 21]), 'value');
r('fricreg:type', @() fricreg_hb_set_element_param(h, 1, 1, '20'));
r('fricreg:EINVAL', @() fricreg_hb_element_param(h, 2, 1));
r('fricreg:EINVAL', @() fricreg_hb_element_param(h, 1, 3));
r('fricreg:EINVAL', @() fricreg_hb_element_param(h, 0, 1), 'element');
r('fricreg:EINVAL', @() fricreg_hb_element_param(h, 1, 1.5), 'index');
if fricreg_hb_element_param(h, 1, 1) ~= 20
    error('test:hb', 'a refused value changed the element');
end
end

function sensitivities()
r = @fricreg_test_raises;
h = oscillator();
cleanup = onCleanup(@() fricreg_hb_free(h));
r('fricreg:EINVAL', @() fricreg_hb_backbone_sensitivities(h, 1, {{'amplitude'}}), 'point');
fricreg_hb_backbone_at(h, 1, [0.01 0.2]);
r('fricreg:nargs', @() fricreg_hb_backbone_sensitivities(h, 1));
r('fricreg:nargs', @() fricreg_mex('hb_nma_sensitivities', h, 1, 0, 1, 1, 1));
r('fricreg:type', @() fricreg_hb_backbone_sensitivities(h, 1, {'element', 1, 1}));
r('fricreg:type', @() fricreg_hb_backbone_sensitivities(h, 1, [1 2]), 'cell');
r('fricreg:type', @() fricreg_hb_backbone_sensitivities(h, 1, {{'stiffness', 1}}), 'stiffness');
r('fricreg:type', @() fricreg_hb_backbone_sensitivities(h, 1, {{'element', 1}}));
r('fricreg:type', @() fricreg_hb_backbone_sensitivities(h, 1, {{'element', [1 3], 1}}), ...
  'consecutive');
r('fricreg:type', @() fricreg_hb_backbone_sensitivities(h, 1, {{'damping', 'xi'}}), 'zeta');
r('fricreg:type', @() fricreg_hb_backbone_sensitivities(h, 1, {{'amplitude', 1}}));
r('fricreg:type', @() fricreg_hb_backbone_sensitivities(h, 1, {{}}));
r('fricreg:EINVAL', @() fricreg_hb_backbone_sensitivities(h, 3, {{'amplitude'}}));
r('fricreg:EINVAL', @() fricreg_hb_backbone_sensitivities(h, 0, {{'amplitude'}}), 'point');
r('fricreg:EINVAL', @() fricreg_hb_backbone_sensitivities(h, 1, {{'element', 2, 1}}));
r('fricreg:EINVAL', @() fricreg_hb_backbone_sensitivities(h, 1, {{'element', 1, 3}}));
r('fricreg:EINVAL', @() fricreg_hb_backbone_sensitivities(h, 1, {{'element', 1, 0}}), 'index');
r('fricreg:EINVAL', @() fricreg_hb_backbone_sensitivities(h, 1, {{'element', 1, 1.5}}));
r('fricreg:EINVAL', @() fricreg_hb_backbone_sensitivities(h, 1, {{'damping', 'zeta'}}));
r('fricreg:EINVAL', @() fricreg_hb_backbone_sensitivities(h, 1, {{'damping', 'a0'}}));
r('fricreg:EINVAL', @() fricreg_mex('hb_nma_sensitivities', h, 1, 7, 1, 1, 1, false));
r('fricreg:EINVAL', @() fricreg_mex('hb_nma_sensitivities', h, 1, -1, 1, 1, 1, false), 'kind');
r('fricreg:EINVAL', @() fricreg_mex('hb_nma_sensitivities', h, 1, 0, 1, 1, 1, 2), 'amplitudes');
r('fricreg:size', @() fricreg_mex('hb_nma_sensitivities', h, 1, [0 0], 1, [1 1], [1 1], 0), ...
  'first');
r('fricreg:type', @() fricreg_mex('hb_nma_sensitivities', h, 1, 0, {1}, 1, 1, 0));
r('fricreg:EINVAL', @() fricreg_mex('hb_nma_sensitivities', h, 1, 0, NaN, 1, 1, 0), 'whole');
% none asked: empty results; then the backbone forgotten by a model change
[dw, dz, da] = fricreg_hb_backbone_sensitivities(h, 1, {});
if ~isempty(dw) || ~isempty(dz) || ~isempty(da)
    error('test:hb', 'no parameters: empty results');
end
r('fricreg:nargs', @() fricreg_hb_modal_participation(h, 1));
r('fricreg:nargs', @() fricreg_mex('hb_modal_participation', h, 1));
r('fricreg:EINVAL', @() fricreg_hb_modal_participation(h, 3, 1), 'point');
r('fricreg:EINVAL', @() fricreg_hb_modal_participation(h, 0, 1), 'point');
r('fricreg:EINVAL', @() fricreg_hb_modal_participation(h, 1, 4)); % H = 3
r('fricreg:EINVAL', @() fricreg_hb_modal_participation(h, 1, -1), 'harmonic');
r('fricreg:size', @() fricreg_hb_modal_participation(h, 1, [1 2]), 'harmonic');
fricreg_hb_set_element_param(h, 1, 2, 1.1);
r('fricreg:EINVAL', @() fricreg_hb_backbone_sensitivities(h, 1, {{'amplitude'}}));
r('fricreg:EINVAL', @() fricreg_hb_modal_participation(h, 1, 1));
end
