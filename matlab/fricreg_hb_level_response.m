% SPDX-License-Identifier: GPL-3.0-or-later
function r = fricreg_hb_level_response(h, omega, level0, level1, guess)
%FRICREG_HB_LEVEL_RESPONSE  A branch of the periodic response in the excitation level.
%   R = FRICREG_HB_LEVEL_RESPONSE(H, OMEGA, LEVEL0, LEVEL1) follows the periodic response of the
%   driver H (FRICREG_HARMONIC_BALANCE) at the fixed excitation frequency OMEGA (rad/s, > 0)
%   from the excitation level LEVEL0 to LEVEL1 (>= 0, different, either order), the force being
%   LEVEL times FRICREG_HB_SET's 'excitation' (pc, ps): the S-curve of the amplitude against the
%   level, by pseudo-arclength continuation through its folds; with stability on each point's
%   Floquet stability and the bifurcations between them. Later solves use the excitation as set
%   (level 1).
%   R = FRICREG_HB_LEVEL_RESPONSE(H, OMEGA, LEVEL0, LEVEL1, GUESS) starts from GUESS, the
%   elements' coordinates at LEVEL0, ROWS x (2H + 1), as FRICREG_HB_SOLVE's.
%
%   R is FRICREG_HB_FREQUENCY_RESPONSE's struct: level (NPOINTS x 1) holds each point's level
%   (nondimensional), omega is OMEGA at every point; rms, x, stable, mu_max, multipliers as
%   there; bifurcations' 'TP' are folds in the level, their level field where. The last point
%   is at LEVEL1, or short of it where the branch is a closed loop. FRICREG_HB_PEAK does not
%   apply to such a branch.
%
%   Errors (identifiers): as FRICREG_HB_SOLVE at LEVEL0, and
%      fricreg:EINVAL       OMEGA <= 0; LEVEL0 or LEVEL1 < 0; LEVEL0 == LEVEL1
%      fricreg:ENONFINITE   OMEGA, LEVEL0 or LEVEL1 not finite
%      fricreg:EINTEGRATOR  the step fell below ds_min
%      fricreg:EWORK        max_points were stored before LEVEL1, or the branch doubled back
%   A failed continuation's points are not returned.
%
%   Source: fricreg_hb_continue_level, fricreg_hb_point, fricreg_hb_point_level,
%   fricreg_hb_point_displacement, fricreg_hb_point_stability, fricreg_hb_point_exponents
%   (include/fricreg_hb_forced.h; Krack & Gross 2019, Ch. 5), through fricreg_mex
%   (matlab/mex_hb_results.c). Python: HarmonicBalance.level_response(omega, level0, level1,
%   guess).
%
%   Example (one mass, a spring and a Jenkins element: stuck, then slipping as the level rises):
%      h = fricreg_harmonic_balance(1, 1, 0.02, struct('type', 'jenkins', 'J', 1, ...
%                                   'params', [20 1]), 7, 'excitation', 1);
%      r = fricreg_hb_level_response(h, 2.5, 0.1, 3);   % r.level from 0.1 to 3
%      fricreg_hb_free(h);
%
%   See also FRICREG_HB_FREQUENCY_RESPONSE, FRICREG_HB_SOLVE, FRICREG_HARMONIC_BALANCE.
if nargin < 4
    error('fricreg:nargs', ['fricreg_hb_level_response: takes a handle, omega, level0, ' ...
                            'level1 and optionally a guess']);
end
if nargin < 5
    guess = [];
end
[w, level, rms, x, stable, mu_max, bif, mult] = fricreg_mex('hb_continue_level', h, omega, ...
                                                            level0, level1, guess);
r = struct('omega', w, 'level', level, 'rms', rms, 'x', x, 'stable', stable, ...
           'mu_max', mu_max, 'multipliers', mult);
r.bifurcations = bif;
end
