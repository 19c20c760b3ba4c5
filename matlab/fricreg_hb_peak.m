% SPDX-License-Identifier: GPL-3.0-or-later
function [omega, rms] = fricreg_hb_peak(h, dof)
%FRICREG_HB_PEAK  The largest RMS of one dof along the last frequency response.
%   [OMEGA, RMS] = FRICREG_HB_PEAK(H, DOF) locates the largest RMS of dof DOF (from 1) along
%   the last FRICREG_HB_FREQUENCY_RESPONSE branch of the driver H between its points (Brent's
%   method on the branch, each trial solved on it): its frequency OMEGA (rad/s) and RMS
%   (displacement units).
%
%   Errors (identifiers):
%      fricreg:handle   H is not a live driver
%      fricreg:EINVAL   DOF out of 1..NDOF; no frequency response computed
%      fricreg:EWORK    a corrector did not converge
%
%   Source: fricreg_hb_peak (include/fricreg_hb.h; R. P. Brent 1973, Ch. 5), through
%   fricreg_mex (matlab/mex_hb_results.c). Python: HarmonicBalance.peak(dof - 1).
%
%   See also FRICREG_HB_FREQUENCY_RESPONSE.
if nargin ~= 2
    error('fricreg:nargs', 'fricreg_hb_peak: takes a handle and a dof');
end
[omega, rms] = fricreg_mex('hb_peak', h, dof);
end
