% SPDX-License-Identifier: GPL-3.0-or-later
function [f, nf, jac] = fricreg_aft_jenkins_normal(kt, mu, n0, kn, u, g, varargin)
%FRICREG_AFT_JENKINS_NORMAL  The AFT of a 1-D Jenkins element under a normal load with lift-off.
%   [F, NF] = FRICREG_AFT_JENKINS_NORMAL(KT, MU, N0, KN, U, G) returns the Fourier
%   coefficients of the tangential force F and of the normal force NF of a Jenkins element
%   whose slip bound is mu N, N = max(0, N0 + KN g), over its periodic response under the
%   tangential displacement of coefficients U and the normal one of coefficients G, exactly
%   (open, stick and slip pieces between the roots of trigonometric polynomials).
%   [F, NF, JAC] = ... also returns the Jacobian.
%   FRICREG_AFT_JENKINS_NORMAL(..., 'samples', N): the sampled path.
%
%   KT   tangential stiffness > 0 (N/m).     MU  friction coefficient >= 0.
%   N0   preload (N): the normal force at g = 0 (negative: open at g = 0).
%   KN   normal stiffness >= 0 (N/m).
%   U, G vectors of n = 2H + 1 coefficients (m), as FRICREG_AFT_JENKINS's U; G positive
%        pressing.
%   F, NF  coefficients of U's shape (N).
%   JAC  2n x 2n, rows (F, NF), columns (U, G): JAC(i, n + j) = dF(i)/dG(j),
%        JAC(n + i, n + j) = dNF(i)/dG(j); dNF/dU = 0.
%   With KN = 0 and N0 >= 0 it is FRICREG_AFT_JENKINS at mun = MU N0.
%
%   Errors: as FRICREG_AFT_JENKINS; fricreg:size where U and G differ in length; fricreg:EINVAL
%   for kt <= 0, mu < 0 or kn < 0.
%
%   Source: fricreg_aft_jenkins_normal_exact, fricreg_aft_jenkins_normal_sampled
%   (include/fricreg_aft.h), through fricreg_mex (matlab/mex_aft.c). Python:
%   fricreg.AFT(H, N).jenkins_normal(kt, mu, n0, kn, u, g, exact=...).
%
%   See also FRICREG_AFT_JENKINS, FRICREG_AFT_JENKINS_2D_NORMAL, FRICREG_AFT_ELEMENT.
if nargin < 6
    error('fricreg:nargs', 'fricreg_aft_jenkins_normal: takes kt, mu, n0, kn, u, g');
end
N = 0;
if ~isempty(varargin) % parsed only where given: a call a few us shorter
    N = samples_option('fricreg_aft_jenkins_normal', varargin);
end
if ~isscalar(kt) || ~isscalar(mu) || ~isscalar(n0) || ~isscalar(kn)
    error('fricreg:size', 'fricreg_aft_jenkins_normal: kt, mu, n0 and kn must be scalars');
end
if ~isnumeric(u) || ~isnumeric(g) || ~isvector(u) || ~isvector(g) || numel(u) ~= numel(g)
    error('fricreg:size', ['fricreg_aft_jenkins_normal: u and g must be vectors of n = 2H + 1 ' ...
                           'coefficients each, not %s and %s'], mat2str(size(u)), mat2str(size(g)));
end
if nargout > 2
    [F, jac] = fricreg_mex('aft', 'jenkins_normal', N, [kt mu n0 kn], [u(:)'; g(:)']);
else
    F = fricreg_mex('aft', 'jenkins_normal', N, [kt mu n0 kn], [u(:)'; g(:)']);
end
f = reshape(F(1, :), size(u));
nf = reshape(F(2, :), size(u));
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
