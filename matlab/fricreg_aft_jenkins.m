% SPDX-License-Identifier: GPL-3.0-or-later
function [f, jac] = fricreg_aft_jenkins(kt, mun, u, varargin)
%FRICREG_AFT_JENKINS  The AFT of one 1-D Jenkins element: its force's Fourier coefficients.
%   F = FRICREG_AFT_JENKINS(KT, MUN, U) returns the Fourier coefficients of the force of a
%   Jenkins element (a spring KT in series with a slider of bound MUN) over its stabilized,
%   periodic hysteresis under the relative displacement of coefficients U, exactly: the
%   velocity reversals and stick-slip switches as roots of trigonometric polynomials, the
%   pieces integrated in closed form (no sampling error).
%   [F, JAC] = FRICREG_AFT_JENKINS(...) also returns the Jacobian, computed only when asked for.
%   FRICREG_AFT_JENKINS(..., 'samples', N) takes the sampled path instead: the return mapping
%   at N samples a period and an FFT (error O(N^-2) from the kinks).
%
%   KT   tangential stiffness > 0 (N/m).
%   MUN  slip bound mu N >= 0 (N); 0 gives F = 0 and JAC = 0.
%   U    a vector (row or column) of n = 2H + 1 coefficients (u0, a_1, b_1, ..., a_H, b_H) of
%        u(theta) = u0 + sum_h a_h cos(h theta) + b_h sin(h theta) (m), 1 <= H <= 40.
%   N    a power of two, 2H + 2 <= N <= 2^24; 0 (the default): the exact path.
%   F    the force's coefficients in the same layout and shape as U (N): the spring force
%        kt (u - w), so u = A cos(theta) gives fa_1 > 0, fb_1 < 0.
%   JAC  n x n, JAC(i, j) = dF(i)/dU(j) (N/m).
%   The element is rate-independent: nothing depends on the frequency. Where it slips its
%   periodic response is unique; where it sticks throughout, the slider is centred,
%   w = (max u + min u)/2. For u = A cos(theta), kt A > mun, r = mun/kt:
%   fa_1 = (kt A/pi)(beta - sin(2 beta)/2), cos(beta) = 1 - 2r/A, fb_1 = -(4 mun/pi)(1 - r/A)
%   (Caughey 1960), and the energy dissipated per period, pi sum_h h (b_h fa_h - a_h fb_h), is
%   4 mun (A - r).
%
%   Errors (identifiers):
%      fricreg:nargs       fewer than three arguments, more than two outputs
%      fricreg:type        an argument not a real double
%      fricreg:size        KT or MUN not a scalar; U not a vector of an odd length
%      fricreg:option      an unknown option, or one without its value
%      fricreg:EINVAL      kt <= 0, mun < 0; H out of 1..40, N not 0 or a power of two in
%                          2H + 2..2^24
%      fricreg:ENONFINITE  a NaN or infinite input, or kt sum |u| beyond the double range
%      fricreg:EINTEGRATOR GSL's polynomial root solver did not converge (not seen so far)
%
%   Source: fricreg_aft_jenkins_exact, fricreg_aft_jenkins_sampled (include/fricreg_aft.h;
%   AFT after M. Krack, J. Gross, "Harmonic Balance for Nonlinear Vibration Problems",
%   Springer 2019, Sec. 3.3), through fricreg_mex (matlab/mex_aft.c), each call with a
%   workspace of its own. Python: fricreg.AFT(H, N).jenkins(kt, mun, u, exact=..., jacobian=...).
%
%   Example (the describing function of a Jenkins element):
%      A = 2e-3; f = fricreg_aft_jenkins(1e5, 50, [0 A 0 0 0]);   % H = 2
%      beta = acos(1 - 2 * 50 / (1e5 * A));
%      f(2) - (1e5 * A / pi) * (beta - sin(2 * beta) / 2)           % 0, to rounding
%
%   See also FRICREG_AFT_IWAN, FRICREG_AFT_JENKINS_NORMAL, FRICREG_AFT_JENKINS_2D_NORMAL,
%   FRICREG_AFT_ELEMENT, FRICREG_ELEMENT_EVAL.
if nargin < 3
    error('fricreg:nargs', 'fricreg_aft_jenkins: takes kt, mun, u');
end
N = 0;
if ~isempty(varargin) % parsed only where given: a call a few us shorter
    N = samples_option('fricreg_aft_jenkins', varargin);
end
if ~isscalar(kt) || ~isscalar(mun)
    error('fricreg:size', 'fricreg_aft_jenkins: kt and mun must be scalars');
end
if nargout > 1
    [f, jac] = fricreg_mex('aft', 'jenkins', N, [kt mun], u);
else
    f = fricreg_mex('aft', 'jenkins', N, [kt mun], u);
end
end

function N = samples_option(fn, args)
% The option 'samples' (0 without it).
N = 0;
if mod(numel(args), 2) ~= 0
    error('fricreg:option', '%s: options come in name/value pairs', fn);
end
for k = 1:2:numel(args)
    if ~ischar(args{k}) || ~strcmp(args{k}, 'samples')
        error('fricreg:option', '%s: unknown option (the one option is ''samples'')', fn);
    end
    N = args{k + 1};
end
end
