% SPDX-License-Identifier: GPL-3.0-or-later
function [domega, dzeta, damp] = fricreg_hb_backbone_sensitivities(h, point, params)
%FRICREG_HB_BACKBONE_SENSITIVITIES  Exact derivatives of a backbone point in model parameters.
%   [DOMEGA, DZETA] = FRICREG_HB_BACKBONE_SENSITIVITIES(H, POINT, PARAMS) differentiates point
%   POINT (from 1) of the driver H's last backbone (FRICREG_HB_BACKBONE,
%   FRICREG_HB_BACKBONE_AT) at its modal amplitude, by the implicit function theorem on the
%   point's converged residual: one solve for all the parameters (docs/nonlinear_modes.md,
%   "Sensitivities"). PARAMS is a cell array, each entry one parameter:
%      {'element', E, INDEX}  parameter INDEX (from 1, in the type's layout: jenkins 1 kt,
%                             2 mun; iwan k_1..k_ns then phi_1..phi_ns; jenkins_normal and
%                             contact_3d 1 kt, 2 mu, 3 kn, 4 n0; spring 1 k; dahl 1 sigma,
%                             2 fc) of the elements E (from 1, in the order added: a scalar,
%                             or consecutive indices first:last sharing one value, the sum of
%                             their derivatives)
%      {'damping', NAME}      NAME 'zeta' (the stuck mode's modal damping ratio, with
%                             'damping', 'modal'), 'a0' or 'a1' (Rayleigh's, 'rayleigh')
%      {'amplitude'}          the modal amplitude: the derivatives along the backbone
%   DOMEGA and DZETA are NP x 1: d omega / dp (rad/s per unit of p) and d zeta / dp.
%   [DOMEGA, DZETA, DAMP] = ... also gives DAMP, NP x NDOF: d|X_1,j| / dp, each dof's
%   first-harmonic amplitude's derivative (displacement units per unit of p).
%
%   The derivatives are those of the harmonic-balance solution at H harmonics, exact to
%   Newton's tolerance; at a stick-slip onset they are one-sided. Below the first slip the
%   backbone is the stuck mode: d omega / dk_t = (J phi)^2 / (2 omega), phi mass-normalized.
%
%   Errors (identifiers):
%      fricreg:handle      H is not a live driver
%      fricreg:type        PARAMS not a cell array, an entry not of those forms
%      fricreg:EINVAL      POINT out of range, no backbone or the model changed since; an
%                          element range or index beyond the elements; a parameter the library
%                          does not support (a slip force of 0, a gap, 'zeta' with the matrix
%                          damping, 'a0' without Rayleigh damping, a stiffness on a model of
%                          more than 256 dofs: the message says which)
%      fricreg:ESINGULAR   at a fold of the backbone, or a repeated stuck mode
%
%   Source: fricreg_hb_nma_point_sensitivities (include/fricreg_hb_nma.h), through fricreg_mex
%   (matlab/mex_hb_estimates.c). Python: HarmonicBalance.backbone_sensitivities(point - 1,
%   params, amplitudes) (Python counts points, elements and indices from 0, the damping by
%   index: 0 zeta, 1 a0, 2 a1).
%
%   Example (the stuck mode's frequency in the Jenkins element's stiffness):
%      M = [1.3 0; 0 0.7]; K = [2.385 -1.1; -1.1 1.9];
%      h = fricreg_harmonic_balance(M, K, [], struct('type', 'jenkins', 'J', [1 -1], ...
%                                   'params', [3.7 0.8]), 5, 'rayleigh', [0.012 0.031]);
%      b = fricreg_hb_backbone_at(h, 1, [1e-3 0.5]);
%      [dw, dz] = fricreg_hb_backbone_sensitivities(h, 2, {{'element', 1, 1}, ...
%                                                         {'damping', 'a1'}});
%      fricreg_hb_free(h);
%
%   See also FRICREG_HB_BACKBONE, FRICREG_HB_SET_ELEMENT_PARAM.
if nargin < 3
    error('fricreg:nargs', 'fricreg_hb_backbone_sensitivities: takes a handle, point, params');
end
if ~iscell(params)
    error('fricreg:type', ['fricreg_hb_backbone_sensitivities: params must be a cell array ' ...
                           'of {''element'', e, index}, {''damping'', name}, {''amplitude''}']);
end
np = numel(params);
kind = zeros(np, 1);
first = zeros(np, 1);
count = zeros(np, 1);
index = zeros(np, 1);
for k = 1:np
    p = params{k};
    if ischar(p)
        p = {p};
    end
    if ~iscell(p) || isempty(p) || ~ischar(p{1})
        bad(k, 'is not a cell {kind, ...}');
    end
    switch p{1}
    case 'element'
        if numel(p) ~= 3 || ~isnumeric(p{2}) || isempty(p{2}) || ~isnumeric(p{3})
            bad(k, 'must be {''element'', e, index}');
        end
        e = p{2}(:)';
        if any(diff(e) ~= 1)
            bad(k, sprintf('elements %s: consecutive indices first:last', mat2str(e)));
        end
        kind(k) = 0;
        first(k) = e(1);
        count(k) = numel(e);
        index(k) = double(p{3});
    case 'damping'
        names = {'zeta', 'a0', 'a1'};
        if numel(p) ~= 2 || ~ischar(p{2}) || ~any(strcmp(p{2}, names))
            bad(k, 'must be {''damping'', name}, name ''zeta'', ''a0'' or ''a1''');
        end
        kind(k) = 1;
        index(k) = find(strcmp(p{2}, names));
    case 'amplitude'
        if numel(p) ~= 1
            bad(k, 'must be {''amplitude''}');
        end
        kind(k) = 2;
    otherwise
        bad(k, sprintf('''%s'' is not element, damping or amplitude', p{1}));
    end
end
[domega, dzeta, damp] = fricreg_mex('hb_nma_sensitivities', h, point, kind, double(first), ...
                                    double(count), index, nargout >= 3);
end

function bad(k, what)
error('fricreg:type', 'fricreg_hb_backbone_sensitivities: params{%d} %s', k, what);
end
