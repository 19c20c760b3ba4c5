% SPDX-License-Identifier: GPL-3.0-or-later
function fricreg_structure_reset(h, u0, v0)
%FRICREG_STRUCTURE_RESET  Restart a structure at t = 0.
%   FRICREG_STRUCTURE_RESET(H, U0, V0) puts the structure H (of FRICREG_STRUCTURE) back at
%   t = 0 with displacements U0 (m) and velocities V0 (m/s), vectors of NDOF ([] or omitted:
%   zeros); clears the energy balance, the dissipation, the counters, the peaks and the
%   warnings raised (they may be raised again), and puts the elements' sliders back at 0.
%
%   Errors: fricreg:handle (H unknown or freed), fricreg:size (U0 or V0 not of NDOF),
%   fricreg:ENONFINITE (a NaN or infinite entry).
%
%   Source: fricreg_structure_set_initial (include/fricreg_structure.h), through fricreg_mex
%   (matlab/mex_structure.c). Python: fricreg.Structure.reset(u0, v0).
%
%   See also FRICREG_STRUCTURE, FRICREG_STRUCTURE_RUN.
if nargin < 1
    error('fricreg:nargs', 'fricreg_structure_reset: takes h [, u0, v0]');
end
if nargin < 2
    u0 = [];
end
if nargin < 3
    v0 = [];
end
fricreg_mex('st_set_initial', h, u0, v0);
end
