% SPDX-License-Identifier: GPL-3.0-or-later
function [f, jac] = fricreg_aft_iwan(k, phi, u, varargin)
%FRICREG_AFT_IWAN  The AFT of one 1-D Iwan element: the sum of its sliders' Jenkins AFTs.
%   F = FRICREG_AFT_IWAN(K, PHI, U) returns the Fourier coefficients of the force of an Iwan
%   element of ns Jenkins sliders in parallel (slider s: stiffness K(s), slip force PHI(s))
%   over its periodic hysteresis under the displacement of coefficients U, exactly (the
%   velocity reversals, which U alone decides, found once for every slider).
%   [F, JAC] = FRICREG_AFT_IWAN(...) also returns the Jacobian.
%   FRICREG_AFT_IWAN(..., 'samples', N): the sampled path (one FFT for the sum).
%
%   K, PHI  vectors of ns >= 1: stiffnesses > 0 (N/m), slip forces >= 0 (N).
%   U, N, F, JAC  as FRICREG_AFT_JENKINS: U a vector of n = 2H + 1 coefficients (m), F of U's
%           shape (N), JAC n x n (N/m).
%
%   Errors: as FRICREG_AFT_JENKINS; fricreg:size also where K and PHI differ in length;
%   fricreg:EINVAL for no slider, some k <= 0 or phi < 0.
%
%   Source: fricreg_aft_iwan_exact, fricreg_aft_iwan_sampled (include/fricreg_aft.h), through
%   fricreg_mex (matlab/mex_aft.c). Python: fricreg.AFT(H, N).iwan(k, phi, u, exact=...).
%
%   See also FRICREG_AFT_JENKINS, FRICREG_AFT_ELEMENT.
if nargin < 3
    error('fricreg:nargs', 'fricreg_aft_iwan: takes k, phi, u');
end
N = 0;
if ~isempty(varargin) % parsed only where given: a call a few us shorter
    N = samples_option('fricreg_aft_iwan', varargin);
end
if ~isnumeric(k) || ~isnumeric(phi) || numel(k) ~= numel(phi) || ~isvector(k) || ~isvector(phi)
    error('fricreg:size', 'fricreg_aft_iwan: k and phi must be vectors of one length (ns)');
end
if nargout > 1
    [f, jac] = fricreg_mex('aft', 'iwan', N, [k(:); phi(:)], u);
else
    f = fricreg_mex('aft', 'iwan', N, [k(:); phi(:)], u);
end
end

function N = samples_option(fn, args)
% The option 'samples' (0 without it).
N = 0;
if mod(numel(args), 2) ~= 0
    error('fricreg:option', '%s: options come in name/value pairs', fn);
end
for j = 1:2:numel(args)
    if ~ischar(args{j}) || ~strcmp(args{j}, 'samples')
        error('fricreg:option', '%s: unknown option (the one option is ''samples'')', fn);
    end
    N = args{j + 1};
end
end
