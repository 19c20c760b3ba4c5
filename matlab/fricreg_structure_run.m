% SPDX-License-Identifier: GPL-3.0-or-later
function r = fricreg_structure_run(h, integrator, dt, t_end, varargin)
%FRICREG_STRUCTURE_RUN  Step a structure to t_end: its time series and the run's summary.
%   R = FRICREG_STRUCTURE_RUN(H, INTEGRATOR, DT, T_END) steps the structure H (of
%   FRICREG_STRUCTURE) from its current time to T_END with steps DT (the last one shortened to
%   land on T_END) and returns the result as a struct. A run continues the structure's state:
%   two runs to T1 and T2 take the steps of one run to T2.
%   FRICREG_STRUCTURE_RUN(..., 'output_every', K) keeps a row every K-th step of the run (and
%   the first and the last); 'output_dofs', D the dofs (from 1) whose u and u' the time series
%   holds (default all); 'alpha', A sets HHT's alpha in [-1/3, 0] (default -0.05).
%
%   INTEGRATOR  'newmark' (average acceleration, the friction implicit: Newton on the exact
%               tangent), 'hht' (HHT-alpha) or 'central' (explicit central differences, refused
%               beyond its stability bound: fricreg:ESTEP).
%   DT, T_END   s; DT > 0, T_END after the structure's time.
%   R           a struct with the fields
%      times                 NSAMPLES x 1 (s): the run's start, every K-th step, its end
%      displacements, velocities   NSAMPLES x NOUT (m, m/s): u and u' at the output dofs
%      output_dofs           1 x NOUT: the dofs of their columns, from 1
%      forces                NSAMPLES x M: the contacts' friction forces (N)
%      t                     the time reached (s)
%      peak_displacement     1 x NDOF: max |u| since the last reset, turning points inside
%                            steps included (m)
%      dissipation           1 x M: each contact's dissipated energy since the reset (J)
%      element_dissipation   1 x NELEMENTS: each joint element's (J), in the order given
%      element_forces        a cell, one ME x DIM array per element set: the forces now (N)
%      energy                struct: initial, input, kinetic, strain, viscous, friction,
%                            elements, residual (J; residual = initial + input - the rest)
%      stats                 struct: steps, newton_iterations, newton_max, newton_failures,
%                            line_search_cuts (since the reset)
%      peak_displacement_error, dissipation_error, element_dissipation_error
%                            with 'error_estimate' on: struct with error (1 x n, >= 0, Inf
%                            where a companion failed) and kind (1 x n cell: 'asymptotic',
%                            'bound' or 'assumed'); [] without an estimate
%      warnings              1 x NW struct array of name, message: the library's accuracy
%                            warnings on the model and the run since the last reset
%   Each warning is also raised, once per kind until FRICREG_STRUCTURE_RESET, as
%   warning('fricreg:accuracy', 'name: message') (warning('off', 'fricreg:accuracy') silences
%   them; the field keeps them).
%
%   Errors (identifiers):
%      fricreg:nargs, fricreg:type, fricreg:size, fricreg:option   as FRICREG_STRUCTURE
%      fricreg:handle      H unknown or freed, or not a structure's
%      fricreg:EINVAL      DT <= 0, T_END not after the current time, an unknown integrator,
%                          alpha out of range, an output dof not in 1..NDOF
%      fricreg:ESTEP       a central-difference step beyond its stability bound
%      fricreg:EDIVERGED, fricreg:ESINGULAR, fricreg:ENOTPSD, fricreg:ENOMEM   the run failed;
%                          the message says after which time. The structure stays at its last
%                          successful step.
%   Ctrl-C does not stop a run (no interrupt query in Octave's MEX API).
%
%   Source: fricreg_structure_run with an observer recording the rows, and the getters
%   (include/fricreg_structure_run.h, fricreg_structure_results.h; warnings:
%   fricreg_structure_warning_count, _get_warning), through fricreg_mex
%   (matlab/mex_structure_run.c). Python: fricreg.Structure.run(integrator, dt=, t_end=).
%
%   See also FRICREG_STRUCTURE, FRICREG_STRUCTURE_RESET, FRICREG_STRUCTURE_FREE.
if nargin < 4
    error('fricreg:nargs', 'fricreg_structure_run: takes h, integrator, dt, t_end');
end
every = 1;
alpha = -0.05;
dofs = [];
if mod(numel(varargin), 2) ~= 0
    error('fricreg:option', 'fricreg_structure_run: options come in name/value pairs');
end
for k = 1:2:numel(varargin)
    if ~ischar(varargin{k})
        error('fricreg:option', 'fricreg_structure_run: an option name must be a string');
    end
    switch varargin{k}
        case 'output_every'
            every = varargin{k + 1};
        case 'alpha'
            alpha = varargin{k + 1};
        case 'output_dofs'
            dofs = varargin{k + 1};
        otherwise
            error('fricreg:option', ['fricreg_structure_run: unknown option %s (one of ' ...
                                     'output_every, output_dofs, alpha)'], varargin{k});
    end
end
r = fricreg_mex('st_run', h, integrator, dt, t_end, every, alpha, dofs);
end
