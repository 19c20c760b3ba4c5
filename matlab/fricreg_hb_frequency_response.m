% SPDX-License-Identifier: GPL-3.0-or-later
function r = fricreg_hb_frequency_response(h, omega0, omega1, guess)
%FRICREG_HB_FREQUENCY_RESPONSE  A branch of the periodic response from one frequency to another.
%   R = FRICREG_HB_FREQUENCY_RESPONSE(H, OMEGA0, OMEGA1) follows the periodic response of the
%   driver H (FRICREG_HARMONIC_BALANCE) from OMEGA0 to OMEGA1 (rad/s, > 0, either order) by
%   pseudo-arclength continuation, through turning points; with stability on
%   (FRICREG_HB_SET(H, 'stability', true)) each point's Floquet stability and the
%   bifurcations between them. The step control is FRICREG_HB_SET's 'continuation'.
%   R = FRICREG_HB_FREQUENCY_RESPONSE(H, OMEGA0, OMEGA1, GUESS) starts from GUESS, the
%   elements' coordinates at OMEGA0, ROWS x (2H + 1), as FRICREG_HB_SOLVE's.
%
%   R is a struct, its points in the branch's order (NPOINTS of them):
%      omega         NPOINTS x 1, each point's excitation frequency, rad/s
%      level         NPOINTS x 1, the excitation level (1 along a frequency branch)
%      rms           NPOINTS x NDOF, each dof's RMS over a period,
%                    sqrt(x0^2 + sum_h (a_h^2 + b_h^2)/2), displacement units
%      x             NPOINTS x NDOF x (2H + 1), the displacements' Fourier coefficients
%                    (x0, a_1, b_1, ..., a_H, b_H) of each point
%      stable        NPOINTS x 1 logical, each point's stability; [] with stability off
%      mu_max        NPOINTS x 1, each point's largest |Floquet multiplier|; [] when off
%      multipliers   NPOINTS x (2 NDOF) complex, each point's Floquet multipliers by
%                    decreasing modulus (FRICREG_HB_SOLVE's); [] when off
%      bifurcations  1 x NB struct array: kind ('TP' turning point, 'BP' branch point, 'PD'
%                    period doubling, 'NS' Neimark-Sacker: the last two with stability on),
%                    omega (rad/s), level, point (it lies between points point and point + 1),
%                    rms (1 x NDOF)
%   The last point is at OMEGA1, or short of it where the branch is a closed loop.
%
%   Errors (identifiers): as FRICREG_HB_SOLVE at OMEGA0, and
%      fricreg:EINVAL       OMEGA0 == OMEGA1
%      fricreg:EINTEGRATOR  the step fell below ds_min
%      fricreg:EWORK        max_points were stored before OMEGA1, or the branch doubled back
%   A failed continuation's points are not returned.
%
%   Source: fricreg_hb_continue, fricreg_hb_point, fricreg_hb_point_displacement,
%   fricreg_hb_point_stability, fricreg_hb_point_exponents, fricreg_hb_bifurcation
%   (include/fricreg_hb.h; Krack & Gross 2019, Ch. 5), through fricreg_mex
%   (matlab/mex_hb_results.c). Python:
%   HarmonicBalance.frequency_response(omega0, omega1, guess).
%
%   See also FRICREG_HB_SOLVE, FRICREG_HB_PEAK, FRICREG_HB_LEVEL_RESPONSE,
%   FRICREG_HB_TRUNCATION_ERROR, FRICREG_NLVIB_FRF.
if nargin < 3
    error('fricreg:nargs', ['fricreg_hb_frequency_response: takes a handle, omega0, omega1 ' ...
                            'and optionally a guess']);
end
if nargin < 4
    guess = [];
end
[omega, level, rms, x, stable, mu_max, bif, mult] = fricreg_mex('hb_continue', h, omega0, ...
                                                                omega1, guess);
r = struct('omega', omega, 'level', level, 'rms', rms, 'x', x, 'stable', stable, ...
           'mu_max', mu_max, 'multipliers', mult);
r.bifurcations = bif;
end
