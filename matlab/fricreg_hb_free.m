% SPDX-License-Identifier: GPL-3.0-or-later
function fricreg_hb_free(h)
%FRICREG_HB_FREE  Free a harmonic-balance driver.
%   FRICREG_HB_FREE(H) frees the driver of FRICREG_HARMONIC_BALANCE's handle H; H is unknown
%   afterwards (fricreg:handle). Every driver is also freed when fricreg_mex is cleared
%   (clear fricreg_mex, clear all) or the session ends.
%
%   Errors: fricreg:handle if H is not a live handle (freed already, or never made).
%   Source: fricreg_hb_free (include/fricreg_hb.h), through fricreg_mex (matlab/mex_handles.c).
%   Python: the HarmonicBalance object's garbage collection.
%
%   See also FRICREG_HARMONIC_BALANCE.
if nargin ~= 1
    error('fricreg:nargs', 'fricreg_hb_free: takes one handle');
end
fricreg_mex('free', h);
end
