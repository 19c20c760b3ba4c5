% SPDX-License-Identifier: GPL-3.0-or-later
function s = fricreg_hb_solve(h, omega, guess)
%FRICREG_HB_SOLVE  The periodic response at one excitation frequency, by harmonic balance.
%   S = FRICREG_HB_SOLVE(H, OMEGA) solves the driver H (FRICREG_HARMONIC_BALANCE) at the
%   excitation frequency OMEGA > 0 (rad/s), starting from the solution reached continuously
%   from the linear regime along the excitation level.
%   S = FRICREG_HB_SOLVE(H, OMEGA, GUESS) starts Newton's method from GUESS, ROWS x (2H + 1)
%   (a solution's q nearby).
%
%   S is a struct:
%      omega   OMEGA, rad/s
%      q       ROWS x (2H + 1): the elements' coordinates q = J x, a row per row of the
%              elements' J, each its Fourier coefficients (x0, a_1, b_1, ..., a_H, b_H)
%      x       NDOF x (2H + 1): the displacements' coefficients, a row per dof
%      stable  true if every Floquet multiplier has |mu| <= 1 + 1e-6; [] with stability off
%              (FRICREG_HB_SET(H, 'stability', true))
%      mu_max  the largest |Floquet multiplier|; NaN with stability off
%      multipliers  1 x (2 NDOF) complex: the Floquet multipliers mu = exp(2 pi lambda /
%              OMEGA) of the exponents lambda the stability's method computed, by decreasing
%              modulus; [] with stability off
%
%   Errors (identifiers):
%      fricreg:handle       H is not a live driver
%      fricreg:size         GUESS not ROWS x (2H + 1)
%      fricreg:type         OMEGA or GUESS not real double
%      fricreg:EINVAL       OMEGA <= 0; the driver's elements fewer than it was made for
%      fricreg:ENONFINITE   OMEGA or GUESS not finite
%      fricreg:ESINGULAR    K or a dynamic stiffness K - (h Omega)^2 M + i h Omega C singular
%      fricreg:EWORK        Newton did not converge
%      fricreg:EINTEGRATOR  the AFT's root solver, or the stability's eigensolver, failed
%   The messages are the library's (fricreg_hb_errmsg).
%
%   Source: fricreg_hb_solve, fricreg_hb_displacement, fricreg_hb_point_stability,
%   fricreg_hb_point_exponents (include/fricreg_hb.h), through fricreg_mex
%   (matlab/mex_hb_results.c). Python: HarmonicBalance.solve(omega, guess).
%
%   See also FRICREG_HARMONIC_BALANCE, FRICREG_HB_FREQUENCY_RESPONSE.
if nargin < 2
    error('fricreg:nargs', 'fricreg_hb_solve: takes a handle, omega and optionally a guess');
end
if nargin < 3
    guess = [];
end
[q, x, stable, mu_max, multipliers] = fricreg_mex('hb_solve', h, omega, guess);
s = struct('omega', omega, 'q', q, 'x', x, 'stable', stable, 'mu_max', mu_max, ...
           'multipliers', multipliers);
end
