% SPDX-License-Identifier: GPL-3.0-or-later
function [f, jac] = fricreg_aft_element(name, params, coefficients, varargin)
%FRICREG_AFT_ELEMENT  The AFT of an element type of FRICREG_ELEMENT_EVAL, by its name.
%   F = FRICREG_AFT_ELEMENT(NAME, PARAMS, C) returns the Fourier coefficients of the force of
%   an element of the type NAME with the parameters PARAMS (the type's layout, as
%   FRICREG_ELEMENT_EVAL takes them) over its periodic response under the displacement of
%   coefficients C, one row per component of the element's u.
%   [F, JAC] = ... also returns the Jacobian. FRICREG_AFT_ELEMENT(..., 'samples', N): the
%   sampled path (contact_3d has no other: 'samples' is required).
%
%   NAME    'jenkins' (PARAMS [kt mun]), 'iwan' ([k_1..k_ns phi_1..phi_ns]), 'jenkins_normal'
%           ([kt mu kn n0 gap], C 2 x n: rows u, g) or 'contact_3d' ([kt mu kn n0 gap], C 3 x n:
%           rows ux, uy, g). The elements' normal law N = max(0, n0 + kn (g - gap)) is the
%           AFT's N = max(0, N0 + kn g) with N0 = n0 - kn gap.
%   C       DIM x n, n = 2H + 1 (a vector of n for jenkins and iwan) (m).
%   F       of C's shape: the forces' coefficients, the normal force N last (N).
%   JAC     (DIM n) x (DIM n), JAC((a - 1) n + i, (c - 1) n + j) = dF(a, i)/dC(c, j).
%
%   Errors: as FRICREG_AFT_JENKINS; fricreg:EINVAL for a type without an AFT (the message lists
%   those with one); fricreg:size for PARAMS or C of another shape.
%
%   Source: fricreg_aft_jenkins_*, fricreg_aft_iwan_*, fricreg_aft_jenkins_normal_* and
%   fricreg_aft_jenkins_2d_normal_sampled (include/fricreg_aft.h), through fricreg_mex
%   (matlab/mex_aft.c). Python: fricreg.AFT(H, N).element(fricreg.Element(name, params), c).
%
%   See also FRICREG_AFT_JENKINS, FRICREG_AFT_IWAN, FRICREG_AFT_JENKINS_NORMAL,
%   FRICREG_AFT_JENKINS_2D_NORMAL, FRICREG_ELEMENT_EVAL.
if nargin < 3
    error('fricreg:nargs', 'fricreg_aft_element: takes name, params, coefficients');
end
if ~ischar(name)
    error('fricreg:type', 'fricreg_aft_element: name must be a string');
end
if ~isnumeric(params) || ~isvector(params)
    error('fricreg:size', 'fricreg_aft_element: params must be a vector');
end
options = varargin;
switch name
    case {'jenkins', 'iwan'}
        kind = name;
        p = params;
    case {'jenkins_normal', 'contact_3d'}
        if numel(params) ~= 5
            error('fricreg:size', ['fricreg_aft_element: %s''s params must be [kt mu kn n0 ' ...
                                   'gap], not %s'], name, mat2str(size(params)));
        end
        n0 = params(4);
        if params(5) ~= 0
            n0 = n0 - params(3) * params(5);
        end
        p = [params(1) params(2) n0 params(3)];
        kind = 'jenkins_normal';
        if strcmp(name, 'contact_3d')
            kind = 'jenkins_2d_normal';
        end
    otherwise
        error('fricreg:EINVAL', ['fricreg_aft_element: ''%s'' has no AFT (one of jenkins, ' ...
                                 'iwan, jenkins_normal, contact_3d) (FRICREG_EINVAL)'], name);
end
N = 0;
if mod(numel(options), 2) ~= 0
    error('fricreg:option', 'fricreg_aft_element: options come in name/value pairs');
end
for k = 1:2:numel(options)
    if ~ischar(options{k}) || ~strcmp(options{k}, 'samples')
        error('fricreg:option', ['fricreg_aft_element: unknown option (the one option is ' ...
                                 '''samples'')']);
    end
    N = options{k + 1};
end
if nargout > 1
    [f, jac] = fricreg_mex('aft', kind, N, p, coefficients);
else
    f = fricreg_mex('aft', kind, N, p, coefficients);
end
end
