% SPDX-License-Identifier: GPL-3.0-or-later
function [rms_error, amplitude_error] = fricreg_hb_truncation_error(h, point)
%FRICREG_HB_TRUNCATION_ERROR  How far a harmonic-balance solution is from the converged series.
%   [RMS_ERROR, AMPLITUDE_ERROR] = FRICREG_HB_TRUNCATION_ERROR(H, POINT) estimates the error
%   of point POINT (from 1) of the driver H's last branch (FRICREG_HB_FREQUENCY_RESPONSE's or
%   FRICREG_HB_LEVEL_RESPONSE's) that truncating the series at H harmonics makes: the point is
%   solved again with H' = 2H + 1 harmonics from its own coefficients, and
%
%      RMS_ERROR(k)       = 2 |rms_k(H') - rms_k(H)|
%      AMPLITUDE_ERROR(k) = 2 ||X_1,k(H')| - |X_1,k(H)||
%
%   for each dof k (1 x NDOF each, displacement units, >= 0), rms_k as the branch's rms (all
%   harmonics) and X_1,k dof k's fundamental. The factor 2 makes it a bound on the error
%   against the converged series where H' harmonics at least halve that error (friction's
%   kinked forces converge as about H^-3 to H^-4); where every element sticks it is 0 to
%   rounding. FRICREG_HB_TRUNCATION_ERROR(H) or (H, []) estimates the last solution's
%   (FRICREG_HB_SOLVE's, or a branch's last point). Needs H <= 19. The driver's results are
%   not changed.
%
%   Errors (identifiers):
%      fricreg:handle      H is not a live driver
%      fricreg:EINVAL      POINT out of range; no solution yet, or the model changed since;
%                          H > 19
%      fricreg:ESINGULAR, fricreg:EWORK, fricreg:EINTEGRATOR, fricreg:ENONFINITE
%                          the solve at 2H + 1 failed (the message says why)
%
%   Source: fricreg_hb_truncation_error (include/fricreg_hb_forced.h), through fricreg_mex
%   (matlab/mex_hb_estimates.c). Python has no wrapper of it yet.
%
%   See also FRICREG_HB_FREQUENCY_RESPONSE, FRICREG_HB_SOLVE.
if nargin < 1
    error('fricreg:nargs', 'fricreg_hb_truncation_error: takes a handle and optionally a point');
end
if nargin < 2 || isempty(point)
    point = 0; % the gateway's 0: the last solution
elseif isnumeric(point) && isscalar(point) && point == 0
    error('fricreg:EINVAL', ['fricreg_hb_truncation_error: point = 0; points count from 1 ' ...
                             '(omit it for the last solution) (FRICREG_EINVAL)']);
end
[rms_error, amplitude_error] = fricreg_mex('hb_truncation_error', h, point);
end
