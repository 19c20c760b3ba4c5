% SPDX-License-Identifier: GPL-3.0-or-later
function b = fricreg_hb_backbone(h, mode, a0, a1, npoints, varargin)
%FRICREG_HB_BACKBONE  A nonlinear mode's backbone: natural frequency and damping against amplitude.
%   B = FRICREG_HB_BACKBONE(H, MODE, A0, A1, NPOINTS) follows the backbone of mode MODE (1 the
%   lowest natural frequency of the structure with its elements stuck) of the driver H
%   (FRICREG_HARMONIC_BALANCE) from the modal amplitude A0 to A1 (0 < A0 < A1), NPOINTS points
%   (default 50, at equal arclength), by the extended periodic motion concept: the
%   free motion with the dissipation made up by a negative mass-proportional damping xi M,
%   zeta = xi / (2 omega); the excitation is not used.
%   FRICREG_HB_BACKBONE(..., 'damping', D) with D 'matrix' (default: C as set) or 'modal'
%   (the mode's own modal damping); 'through_folds' true (the default, as Python's and the
%   CLI's) continues by pseudo-arclength through the folds in the amplitude (internal
%   resonances); false is the natural march in the amplitude, the points geometric in it,
%   which stops at a fold.
%
%   The amplitude a is modal, phi' M X_1 with phi the stuck mode mass-normalized: displacement
%   units times the square root of mass units.
%
%   B is a struct, NPOINTS points:
%      amplitude        NPOINTS x 1, modal amplitude a
%      omega            NPOINTS x 1, natural frequency omega(a), rad/s
%      zeta             NPOINTS x 1, damping ratio zeta(a)
%      x                NPOINTS x NDOF x (2H + 1), the periodic motion's coefficients
%      harmonic_energy  NPOINTS x (H + 1), each harmonic's share of the kinetic energy
%      special_points   1 x NS struct array: kind ('fold', 'crossing'), amplitude, omega,
%                       zeta, harmonic, mode (from 1)
%   Below the first slip the backbone is the stuck linear mode: omega its natural frequency,
%   zeta its damping ratio.
%
%   Errors (identifiers):
%      fricreg:handle       H is not a live driver
%      fricreg:option       an unknown option
%      fricreg:EINVAL       MODE out of 1..NDOF; not 0 < A0 < A1; NPOINTS out of 2..max_points;
%                           an unknown damping; the stuck mode's omega^2 <= 0
%      fricreg:ENONFINITE   A0 or A1 not finite
%      fricreg:ENOTPSD      M not positive definite
%      fricreg:ESINGULAR    a dynamic stiffness or Newton's matrix singular
%      fricreg:EWORK        Newton did not converge (or, 'through_folds' false, the march
%                           met a fold)
%      fricreg:EINTEGRATOR  the continuation's step fell below ds_min
%
%   Source: fricreg_hb_nma, fricreg_hb_nma_continue, fricreg_hb_nma_point,
%   fricreg_hb_nma_harmonic_energy, fricreg_hb_nma_special_point (include/fricreg_hb.h;
%   M. Krack, Computers & Structures 154, 2015, 59-71), through fricreg_mex
%   (matlab/mex_hb_results.c). Python: HarmonicBalance.backbone(mode - 1, a0, a1, npoints,
%   damping, through_folds) (Python counts modes from 0).
%
%   See also FRICREG_HB_BACKBONE_AT, FRICREG_HARMONIC_BALANCE.
if nargin < 4
    error('fricreg:nargs', 'fricreg_hb_backbone: takes a handle, mode, a0, a1 [, npoints]');
end
if nargin < 5 || isempty(npoints)
    npoints = 50;
end
damping = 'matrix';
folds = true;
if mod(numel(varargin), 2) ~= 0
    error('fricreg:option', 'fricreg_hb_backbone: options come in name/value pairs');
end
for k = 1:2:numel(varargin)
    switch varargin{k}
    case 'damping'
        damping = varargin{k + 1};
    case 'through_folds'
        folds = varargin{k + 1};
    otherwise
        error('fricreg:option', ['fricreg_hb_backbone: unknown option ''%s'' (damping, ' ...
                                 'through_folds)'], num2str(varargin{k}));
    end
end
[a, w, z, x, e, sp] = fricreg_mex('hb_nma', h, mode, damping, a0, a1, npoints, folds);
b = struct('amplitude', a, 'omega', w, 'zeta', z, 'x', x, 'harmonic_energy', e);
b.special_points = sp;
end
