% SPDX-License-Identifier: GPL-3.0-or-later
function ratios = octave_speed(build, rounds)
%OCTAVE_SPEED  The Octave gateway's speed against C on the same work (docs/matlab.md, "Speed"):
%   bench/python_speed.py's method with Octave in Python's place. Each task is run alternately
%   by the C baseline (fricreg-bench-python-baseline, its own CPU clock) and from Octave
%   (cputime around the call of the .m function), in ROUNDS rounds of a few repetitions each
%   side; a round's ratio is of its sides' fastest, and the median over the rounds is printed
%   (the load of this shared machine drifts within seconds: a round's two sides see the same
%   load). The times printed are the medians of the rounds' fastest.
%
%     hb       NLvib's 3-dof chain with two Jenkins elements (bench/nlvib/chain_jenkins.m),
%              H = 7, swept from 0.5 to 2 rad/s with stability: fricreg_harmonic_balance +
%              fricreg_hb_frequency_response (+ fricreg_hb_free) against fricreg_hb_create ..
%              fricreg_hb_continue and the points read (target <= 1.1);
%     nlvib    the same sweep through fricreg_nlvib_frf on NLvib's system struct, its X in
%              NLvib's layout (target <= 1.1);
%     element  10^4 jenkins points with their tangents: one fricreg_element_eval on arrays
%              against 10^4 fricreg_element_eval calls in C (target <= 1.5).
%
%   Usage, from the top of the repository, BUILD a tree configured with -DFRICREG_OCTAVE=ON
%   -DFRICREG_BENCH=ON:
%      OPENBLAS_NUM_THREADS=1 octave-cli --eval "addpath bench; octave_speed('BUILD')"
%   One BLAS thread on both sides, as python_speed.py's: OpenBLAS's idle threads spin and
%   inflate both CPU clocks by amounts that differ run to run; the variable must be set before
%   Octave starts (it loads OpenBLAS then), so the function refuses to run without it.
if nargin < 2
    rounds = 7;
end
if ~strcmp(getenv('OPENBLAS_NUM_THREADS'), '1')
    error('octave_speed:env', ['start Octave with OPENBLAS_NUM_THREADS=1 (one BLAS thread on ' ...
                               'both sides)']);
end
addpath(fullfile(build, 'matlab'));
baseline = fullfile(build, 'bench', 'fricreg-bench-python-baseline');
tasks = {'hb', 'nlvib', 'element'};
targets = [1.1 1.1 1.5];
c_task = {'hb', 'hb', 'element'};
reps = [3 3 50];
work = {@hb_sweep, @nlvib_sweep, []};
printf('task        C (s)          Octave (s)          ratio   target\n');
ratios = zeros(1, numel(tasks));
for t = 1:numel(tasks)
    c = zeros(rounds, 1);
    o = zeros(rounds, 1);
    for r = 1:rounds % alternate, so that the machine's load falls on both
        c(r) = min(c_seconds(baseline, c_task{t}, reps(t)));
        if isempty(work{t})
            o(r) = min(element_seconds(reps(t)));
        else
            o(r) = min(octave_seconds(work{t}, reps(t)));
        end
    end
    ratios(t) = median(o ./ c); % a round's pair: the machine's drift cancels
    flag = '';
    if ratios(t) > targets(t)
        flag = '(above)';
    end
    printf('%-10s  %12.6f   %17.6f   %5.2f   <= %.2f %s\n', tasks{t}, median(c), median(o), ...
           ratios(t), targets(t), flag);
end
end

function s = c_seconds(baseline, task, reps)
% The baseline's own CPU seconds per repetition ("TASK SECONDS" lines).
[status, out] = system(sprintf('"%s" %s %d', baseline, task, reps));
if status ~= 0
    error('octave_speed:baseline', '%s %s failed: %s', baseline, task, out);
end
s = sscanf(strrep(out, task, ''), '%f');
end

function s = octave_seconds(work, reps)
s = zeros(reps, 1);
for k = 1:reps
    t0 = cputime();
    work();
    s(k) = cputime() - t0;
end
end

function sys = chain()
% NLvib's ChainOfOscillators with ki = [1 1 1 1], di = 0.02 ki, Fex1 = [0; 1; 0] and its two
% elasticDryFriction elements (python_baseline.c's model).
K = [2 -1 0; -1 2 -1; 0 -1 2];
sys = struct('M', eye(3), 'K', K, 'D', 0.02 * K, 'Fex1', [0; 1; 0]);
sys.nonlinear_elements = {struct('type', 'elasticDryFriction', 'stiffness', 20, ...
    'friction_limit_force', 1, 'force_direction', [1; 0; 0]), ...
    struct('type', 'elasticDryFriction', 'stiffness', 20, ...
    'friction_limit_force', 1, 'force_direction', [-1; 1; 0])};
end

function hb_sweep()
K = [2 -1 0; -1 2 -1; 0 -1 2];
jenkins = struct('type', 'jenkins', 'J', [1 0 0; -1 1 0], 'params', [20 1]);
h = fricreg_harmonic_balance(eye(3), K, 0.02 * K, jenkins, 7, 'excitation', [0; 1; 0], ...
                             'stability', true);
r = fricreg_hb_frequency_response(h, 0.5, 2); %#ok<NASGU>
fricreg_hb_free(h);
end

function nlvib_sweep()
[X, info] = fricreg_nlvib_frf(chain(), 7, 0.5, 2, 'stability', true); %#ok<ASGLU>
end

function s = element_seconds(reps)
% python_baseline.c's points (u from -1 to 1, the states 0.1 u^2, kt = 2, mun = 0.5), the call
% timed where it is written: a handle's call around it would cost as much as the gateway's
% own overhead (about 5 us a call level, against 30 us of work).
u = linspace(-1, 1, 10000)';
w = 0.1 * u .* u;
s = zeros(reps, 1);
for k = 1:reps
    t0 = cputime();
    [f, dfdu] = fricreg_element_eval('jenkins', [2 0.5], u, w); %#ok<ASGLU>
    s(k) = cputime() - t0;
end
end
