% SPDX-License-Identifier: GPL-3.0-or-later
function failures = test_fricreg_errors()
%TEST_FRICREG_ERRORS  Every error path of the gateway and the .m files raises its identifier
%   (fricreg:nargs, :type, :size, :command, :handle, and fricreg:<STATUS> for the library's
%   refusals) and never crashes: wrong argument counts, inputs that are not real full doubles,
%   wrong sizes, unknown commands, stale and foreign handles, handles kept across a clear of
%   the MEX file, and the library's failures.
cases = {'argument_counts', @argument_counts
         'types', @types
         'sizes', @sizes
         'commands', @commands
         'handles', @handles
         'clear_frees_everything', @clear_frees_everything
         'law_failures', @law_failures
         'element_failures', @element_failures};
failures = fricreg_test_run('errors', cases);
end

function argument_counts()
r = @fricreg_test_raises;
r('fricreg:nargs', @() fricreg_mex());
r('fricreg:nargs', @() fricreg_law_eval('quinn', 1, 1));
r('fricreg:nargs', @() fricreg_law_eval('quinn', 1, 1, 1, 1, 1));
r('fricreg:nargs', @() fricreg_element_eval('jenkins', [1 1]));
r('fricreg:nargs', @() fricreg_element_eval('jenkins', [1 1], 0, 0, 0));
r('fricreg:nargs', @() fricreg_version(1));
r('fricreg:nargs', @() fricreg_mex('fit_create', 1));
r('fricreg:nargs', @() fricreg_mex('free'));
% more outputs than a command gives
r('fricreg:nargs', @() two_outputs('law_eval', 'quinn', 1, 1, 1, 1));
r('fricreg:nargs', @() two_outputs('fit_create'));
r('fricreg:nargs', @() five_outputs('element_eval', 'jenkins', [1 1], 0));
end

function two_outputs(varargin)
[a, b] = fricreg_mex(varargin{:}); %#ok<ASGLU>
end

function five_outputs(varargin)
[a, b, c, d, e] = fricreg_mex(varargin{:}); %#ok<ASGLU>
end

function types()
r = @fricreg_test_raises;
for bad = {single(1), int32(1), true, 1 + 2i, sparse(1), 'a', {1}, struct('a', 1)}
    r('fricreg:type', @() fricreg_law_eval('quinn', bad{1}, 1, 1, 0.1));
    r('fricreg:type', @() fricreg_law_eval('quinn', 1, bad{1}, 1, 0.1));
    r('fricreg:type', @() fricreg_law_eval('quinn', 1, 1, bad{1}, 0.1));
    r('fricreg:type', @() fricreg_law_eval('quinn', 1, 1, 1, bad{1}));
    r('fricreg:type', @() fricreg_element_eval('jenkins', bad{1}, 0));
    r('fricreg:type', @() fricreg_element_eval('jenkins', [1 1], bad{1}));
    r('fricreg:type', @() fricreg_element_eval('jenkins', [1 1], 0, bad{1}));
end
r('fricreg:type', @() fricreg_element_eval(1, [1 1], 0));
r('fricreg:type', @() fricreg_element_eval(['ab'; 'cd'], [1 1], 0));
r('fricreg:type', @() fricreg_law_eval({'quinn'}, 1, 1, 1, 0.1));
h = fricreg_mex('fit_create');
cleanup = onCleanup(@() fricreg_mex('free', h));
r('fricreg:type', @() fricreg_mex('fit_set_levels', h, 2, 1, 1, 1)); % a kind is a name
r('fricreg:type', @() fricreg_mex('fit_set_free', h, 1, NaN, 0, Inf)); % a parameter too
end

function sizes()
r = @fricreg_test_raises;
r('fricreg:size', @() fricreg_law_eval('quinn', [1 2 3], 1, [1 2], 0.1));
r('fricreg:size', @() fricreg_law_eval('quinn', [1 2 3], [1; 2; 3], 1, 0.1));
r('fricreg:size', @() fricreg_law_eval('quinn', 1, 1, 1, [0.1 0.2]));
r('fricreg:size', @() fricreg_law_eval('quinn', 1, 1, 1, []));
r('fricreg:size', @() fricreg_law_eval(repmat('q', 1, 40), 1, 1, 1, 0.1));
r('fricreg:size', @() fricreg_element_eval('jenkins', [1 1], [0 0]));          % u: n x 1
r('fricreg:size', @() fricreg_element_eval('jenkins_2d', [1 1], [0; 0]));      % u: n x 2
r('fricreg:size', @() fricreg_element_eval('jenkins', [1 1 1], 0));            % 2 parameters
r('fricreg:size', @() fricreg_element_eval('iwan', [1 1 1], 0));               % 2 ns
r('fricreg:size', @() fricreg_element_eval('jenkins', ones(3, 2), [0; 0]));    % 2 rows, not 3
r('fricreg:size', @() fricreg_element_eval('jenkins', [1 1], [0; 0], [0 0]));  % state 2 x 1
r('fricreg:size', @() fricreg_element_eval('jenkins', [1 1], zeros(2, 1, 2)));
end

function commands()
r = @fricreg_test_raises;
r('fricreg:command', @() fricreg_mex('nothing'), 'nothing');
r('fricreg:command', @() fricreg_mex(3));
r('fricreg:command', @() fricreg_mex({'law_eval'}));
r('fricreg:command', @() fricreg_mex(repmat('x', 1, 100)));
end

function handles()
r = @fricreg_test_raises;
h = fricreg_mex('fit_create');
if fricreg_mex('handles') ~= 1 || h ~= round(h) || h < 1
    error('test:handles', 'a new handle: %g', h);
end
fricreg_mex('free', h);
if fricreg_mex('handles') ~= 0
    error('test:handles', 'not freed');
end
r('fricreg:handle', @() fricreg_mex('fit_run', h), 'not a live handle');   % stale
r('fricreg:handle', @() fricreg_mex('free', h));                           % freed twice
g = fricreg_mex('fit_create');
if g == h
    error('test:handles', 'a handle reused');
end
r('fricreg:handle', @() fricreg_mex('fit_run', h));
r('fricreg:handle', @() fricreg_mex('fit_run', g + 1));                    % never made
r('fricreg:handle', @() fricreg_mex('fit_run', 0));
r('fricreg:handle', @() fricreg_mex('fit_run', -g));
r('fricreg:handle', @() fricreg_mex('fit_run', g + 0.5));
r('fricreg:handle', @() fricreg_mex('fit_run', NaN));
r('fricreg:handle', @() fricreg_mex('fit_run', [g g]));
r('fricreg:handle', @() fricreg_mex('fit_run', int32(g)));
r('fricreg:handle', @() fricreg_mex('fit_run', 'g'));
r('fricreg:handle', @() fricreg_mex('fit_run', complex(g, 0)));
r('fricreg:handle', @() fricreg_mex('fit_run', []));
fricreg_mex('free_all');
r('fricreg:handle', @() fricreg_mex('fit_run', g));
if fricreg_mex('handles') ~= 0
    error('test:handles', 'free_all left objects');
end
end

function clear_frees_everything()
% Clearing the MEX file runs its mexAtExit function: every object freed; the handles kept in
% variables are unknown to the reloaded gateway, not its new objects.
old = [fricreg_mex('fit_create'), fricreg_mex('fit_create')];
clear fricreg_mex
if fricreg_mex('handles') ~= 0
    error('test:clear', 'objects survived the clear');
end
new = fricreg_mex('fit_create');
cleanup = onCleanup(@() fricreg_mex('free', new));
if any(old == new)
    error('test:clear', 'a handle from before the clear names a new object');
end
fricreg_test_raises('fricreg:handle', @() fricreg_mex('fit_run', old(1)));
fricreg_test_raises('fricreg:handle', @() fricreg_mex('free', old(2)));
end

function law_failures()
r = @fricreg_test_raises;
r('fricreg:EINVAL', @() fricreg_law_eval('stribeck', 1, 1, 1, 0.1), 'quinn');
r('fricreg:EINVAL', @() fricreg_law_eval(9, 1, 1, 1, 0.1), 'FRICREG_EINVAL');
r('fricreg:EINVAL', @() fricreg_law_eval(1.5, 1, 1, 1, 0.1));
r('fricreg:EINVAL', @() fricreg_law_eval('quinn', 1, 1, [1 -2], 0.1), 'mun(2) = -2');
r('fricreg:EINVAL', @() fricreg_law_eval('quinn', 1, 1, 1, 0), 'eps');
r('fricreg:EINVAL', @() fricreg_law_eval('coulomb', 1, [], 1, -1));
r('fricreg:ENONFINITE', @() fricreg_law_eval('quinn', [0 NaN], 1, 1, 0.1), 'v(2)');
r('fricreg:ENONFINITE', @() fricreg_law_eval('quinn', 0, [1 Inf 1], 1, 0.1), 'f_eq(2)');
r('fricreg:ENONFINITE', @() fricreg_law_eval('quinn', 0, 1, 1, Inf));
r('fricreg:ENULL', @() fricreg_law_eval('quinn', 1, [], 1, 0.1), 'needs f_eq');
end

function element_failures()
r = @fricreg_test_raises;
r('fricreg:EINVAL', @() fricreg_element_eval('slider', [1 1], 0), 'jenkins');
e = r('fricreg:EINVAL', @() fricreg_element_eval('jenkins', [1e5 -1], [0; 1]));
if isempty(strfind(e.message, 'point 1')) || isempty(strfind(e.message, 'mun'))
    error('test:element', 'the message names neither the point nor the parameter: %s', e.message);
end
r('fricreg:EINVAL', @() fricreg_element_eval('jenkins', [1e5 20; 0 20], [0; 1]), 'point 2');
r('fricreg:ENONFINITE', @() fricreg_element_eval('jenkins', [1e5 20], [0; 1; NaN]), 'point 3');
r('fricreg:ENONFINITE', @() fricreg_element_eval('jenkins_2d', [1e5 20], [0 0; 0 0], ...
                                                 [0 0; Inf 0]), 'point 2');
r('fricreg:EINVAL', @() fricreg_element_eval('contact_3d', [1e5 0.3 2e5 50 1], zeros(1, 3)));
end
