% SPDX-License-Identifier: GPL-3.0-or-later
function fraction = fricreg_hb_modal_participation(h, point, harmonic)
%FRICREG_HB_MODAL_PARTICIPATION  Which stuck linear mode a harmonic of a backbone point moves.
%   FRACTION = FRICREG_HB_MODAL_PARTICIPATION(H, POINT, HARMONIC) is each linear mode's share
%   of harmonic HARMONIC (0 the mean, 1 the fundamental, .. H) of point POINT (from 1) of the
%   driver H's last backbone (FRICREG_HB_BACKBONE, FRICREG_HB_BACKBONE_AT): 1 x NDOF,
%   nondimensional, FRACTION(r) the share of mode r of the structure with its elements stuck
%   (the lowest first), with a_h, b_h the harmonic's cosine and sine coefficients and phi_r
%   the modes mass-normalized,
%
%      p_r = (phi_r' M a_h)^2 + (phi_r' M b_h)^2,   FRACTION(r) = p_r / sum_s p_s,
%
%   which sums to 1; every fraction is 0 where the harmonic is exactly zero. Near an internal
%   resonance a higher harmonic moves mostly another mode (the backbone's special points
%   'crossing' say where one can start).
%
%   Errors (identifiers):
%      fricreg:handle  H is not a live driver
%      fricreg:EINVAL  POINT or HARMONIC out of range; no backbone, or the model changed since;
%                      a sparse model of more than 256 dofs
%
%   Source: fricreg_hb_nma_modal_participation (include/fricreg_hb_nma.h), through fricreg_mex
%   (matlab/mex_hb_estimates.c). Python: HarmonicBalance.modal_participation(point - 1,
%   harmonic) (its modes from 0).
%
%   See also FRICREG_HB_BACKBONE, FRICREG_HB_BACKBONE_SENSITIVITIES.
if nargin < 3
    error('fricreg:nargs', 'fricreg_hb_modal_participation: takes a handle, point, harmonic');
end
fraction = fricreg_mex('hb_modal_participation', h, point, harmonic);
end
