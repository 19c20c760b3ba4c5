% SPDX-License-Identifier: GPL-3.0-or-later
function b = fricreg_hb_backbone_at(h, mode, amplitudes, varargin)
%FRICREG_HB_BACKBONE_AT  A nonlinear mode's backbone at the caller's modal amplitudes.
%   B = FRICREG_HB_BACKBONE_AT(H, MODE, AMPLITUDES) is FRICREG_HB_BACKBONE's backbone of mode
%   MODE (from 1) of the driver H, a point at each of AMPLITUDES (a vector, > 0 and strictly
%   increasing, at most max_points of them): the amplitudes of a test's levels, which a
%   geometric grid does not hold. FRICREG_HB_BACKBONE_AT(..., 'damping', D) as
%   FRICREG_HB_BACKBONE's. B has FRICREG_HB_BACKBONE's fields, NPOINTS = numel(AMPLITUDES).
%
%   Errors (identifiers): as FRICREG_HB_BACKBONE's, and fricreg:EINVAL if AMPLITUDES are not
%   > 0 and increasing, fricreg:ENONFINITE if one is NaN or infinite, fricreg:size if
%   AMPLITUDES is not a vector.
%
%   Source: fricreg_hb_nma_at (include/fricreg_hb.h), through fricreg_mex
%   (matlab/mex_hb_results.c). Python: HarmonicBalance.backbone_at(mode - 1, amplitudes,
%   damping).
%
%   See also FRICREG_HB_BACKBONE.
if nargin < 3
    error('fricreg:nargs', 'fricreg_hb_backbone_at: takes a handle, mode, amplitudes');
end
damping = 'matrix';
for k = 1:2:numel(varargin)
    if ~strcmp(varargin{k}, 'damping') || k == numel(varargin)
        error('fricreg:option', 'fricreg_hb_backbone_at: the one option is damping, a value');
    end
    damping = varargin{k + 1};
end
[a, w, z, x, e, sp] = fricreg_mex('hb_nma', h, mode, damping, amplitudes);
b = struct('amplitude', a, 'omega', w, 'zeta', z, 'x', x, 'harmonic_energy', e);
b.special_points = sp;
end
