% SPDX-License-Identifier: GPL-3.0-or-later
function [f, nf, jac] = fricreg_aft_jenkins_2d_normal(kt, mu, n0, kn, u, g, varargin)
%FRICREG_AFT_JENKINS_2D_NORMAL  The sampled AFT of one 3-D contact element.
%   [F, NF] = FRICREG_AFT_JENKINS_2D_NORMAL(KT, MU, N0, KN, U, G, 'samples', N) returns the
%   Fourier coefficients of the tangential forces F (rows fx, fy) and of the normal force NF
%   of a 2-D Jenkins element (an isotropic Coulomb disk |f| <= mu N) under
%   N = max(0, N0 + KN g) with lift-off, over its periodic response under the tangential
%   displacements of coefficients U (rows ux, uy) and the normal one G, from the return
%   mapping at N samples a period and an FFT. There is no exact path: 'samples' is required.
%   [F, NF, JAC] = ... also returns the Jacobian.
%
%   KT, MU, N0, KN  as FRICREG_AFT_JENKINS_NORMAL.
%   U    2 x n, n = 2H + 1: rows ux, uy (m).      G  a vector of n (m), positive pressing.
%   F    2 x n (N).   NF  of G's shape (N).
%   JAC  3n x 3n, rows (fx, fy, NF), columns (ux, uy, G).
%   Its error is first order in 1/N where the slip turns (the sampled return mapping drags the
%   slider along chords); with uy = 0 and KN = 0, fx and NF equal FRICREG_AFT_JENKINS_NORMAL's
%   sampled ones.
%
%   Errors: as FRICREG_AFT_JENKINS_NORMAL; fricreg:size where U is not 2 x n or G not a vector
%   of n; fricreg:EINVAL without 'samples' (N = 0).
%
%   Source: fricreg_aft_jenkins_2d_normal_sampled (include/fricreg_aft.h), through fricreg_mex
%   (matlab/mex_aft.c). Python: fricreg.AFT(H, N).jenkins_2d_normal(kt, mu, n0, kn, u, g).
%
%   See also FRICREG_AFT_JENKINS_NORMAL, FRICREG_AFT_ELEMENT.
if nargin < 6
    error('fricreg:nargs', 'fricreg_aft_jenkins_2d_normal: takes kt, mu, n0, kn, u, g');
end
N = 0;
if ~isempty(varargin) % parsed only where given: a call a few us shorter
    N = samples_option('fricreg_aft_jenkins_2d_normal', varargin);
end
if ~isscalar(kt) || ~isscalar(mu) || ~isscalar(n0) || ~isscalar(kn)
    error('fricreg:size', 'fricreg_aft_jenkins_2d_normal: kt, mu, n0 and kn must be scalars');
end
if ~isnumeric(u) || ~isnumeric(g) || ~ismatrix(u) || size(u, 1) ~= 2 || ~isvector(g) || ...
   numel(g) ~= size(u, 2)
    error('fricreg:size', ['fricreg_aft_jenkins_2d_normal: u must be 2 x n (rows ux, uy) and ' ...
                           'g a vector of n, not %s and %s'], mat2str(size(u)), mat2str(size(g)));
end
if nargout > 2
    [F, jac] = fricreg_mex('aft', 'jenkins_2d_normal', N, [kt mu n0 kn], [u; g(:)']);
else
    F = fricreg_mex('aft', 'jenkins_2d_normal', N, [kt mu n0 kn], [u; g(:)']);
end
f = F(1:2, :);
nf = reshape(F(3, :), size(g));
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
