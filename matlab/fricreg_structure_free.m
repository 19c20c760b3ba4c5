% SPDX-License-Identifier: GPL-3.0-or-later
function fricreg_structure_free(h)
%FRICREG_STRUCTURE_FREE  Free a structure of FRICREG_STRUCTURE.
%   FRICREG_STRUCTURE_FREE(H) frees the structure H; H is unknown afterwards (fricreg:handle).
%   Structures are also freed when fricreg_mex is cleared or the session ends.
%
%   Source: fricreg_structure_free, through fricreg_mex('free', H).
%
%   See also FRICREG_STRUCTURE.
if nargin ~= 1
    error('fricreg:nargs', 'fricreg_structure_free: takes h');
end
fricreg_mex('free', h);
end
