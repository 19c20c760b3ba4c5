% SPDX-License-Identifier: GPL-3.0-or-later
function [f, dfdu, state_out, dfdp] = fricreg_element_eval(name, params, u, state, varargin)
%FRICREG_ELEMENT_EVAL  Friction elements' forces, tangents and new state at many points.
%   [F, DFDU, STATE_OUT, DFDP] = FRICREG_ELEMENT_EVAL(NAME, PARAMS, U, STATE) evaluates the
%   element type NAME at every point (a row of U) from its old state STATE: the return
%   mapping of include/fricreg_element.h, all points in one call of the C library.
%   FRICREG_ELEMENT_EVAL(NAME, PARAMS, U) starts every point from rest (STATE all zeros).
%
%   NAME    the type, a char row vector: 'jenkins', 'jenkins_2d', 'jenkins_3d',
%           'jenkins_normal', 'contact_3d', 'iwan', 'iwan_2d', 'iwan_3d', 'iwan_normal',
%           'spring', 'dahl' (fricreg_mex('element_types') lists them).
%   PARAMS  the parameters in the order of the header's table, in the caller's units: a
%           vector of NPARAMS shared by every point, or NPOINTS x NPARAMS (a row each).
%           jenkins*: [kt mun]; jenkins_normal, contact_3d: [kt mu kn n0 gap];
%           iwan, iwan_2d, iwan_3d: [k_1..k_ns phi_1..phi_ns]; iwan_normal:
%           [k_1..k_ns mu_1..mu_ns kn n0 gap]; spring: k; dahl: [sigma fc]. An Iwan type's
%           slider count ns follows from the length.
%   U       NPOINTS x DIM, the relative displacement at the end of the increment, one point a
%           row (DIM = 1, 2 or 3 by type; a normal type's last column is the normal
%           displacement g, positive pressing).
%   STATE   NPOINTS x NSTATE, the state at the start of the increment (from an earlier
%           call's STATE_OUT); [] or omitted: at rest.
%
%   F          NPOINTS x DIM, the element's force (a normal type's normal force N last); the
%              body whose relative displacement is U feels -F.
%   DFDU       NPOINTS x DIM x DIM, the consistent tangent: DFDU(i, a, c) = dF_a/dU_c at
%              point i. Computed only when asked for.
%   STATE_OUT  NPOINTS x NSTATE, the state at the end of the increment.
%   DFDP       NPOINTS x DIM x NPARAMS, DFDP(i, a, j) = dF_a/dPARAMS_j. Only when asked for.
%
%   Jenkins (one slider): F = kt (u - w) while kt |u - w| <= mun (stick), else F = mun
%   sign(u - w) and w' = u - F/kt (slip); Iwan types sum ns such sliders (J. C. Simo, T. J.
%   R. Hughes, "Computational Inelasticity", 1998, Ch. 1 and 3). Each point's numbers equal
%   one call of fricreg_element_eval on it bit for bit.
%
%   Errors (identifiers):
%      fricreg:nargs       not three or four arguments, more than four outputs
%      fricreg:type        an array not a real, full double; NAME not a char row vector
%      fricreg:size        U not NPOINTS x DIM; PARAMS of a length the type does not take;
%                          STATE not NPOINTS x NSTATE
%      fricreg:EINVAL      NAME names no type; a parameter out of its range (kt > 0, mun >= 0,
%                          ...): the message names the point and the parameter
%      fricreg:ENONFINITE  a parameter, state or displacement NaN or infinite (point named)
%
%   Source: fricreg_element_eval_batch (include/fricreg_element.h), through the gateway
%   fricreg_mex (matlab/fricreg_mex.c). MATLAB's column-major tables are copied into the
%   library's row-major ones and back where they have more than one column. Python:
%   fricreg.Element(name, params).eval(u, state).
%
%   Example (a Jenkins element, kt = 1e5 N/m, mun = 20 N, loaded past its slip):
%      u = [1e-4; 3e-4; 1e-4];
%      [f, dfdu, w] = fricreg_element_eval('jenkins', [1e5 20], u)
%      % f = [10; 20; 10], w = [0; 1e-4; 0]: each point from rest, the second slipping
%
%   See also FRICREG_LAW_EVAL, FRICREG_VERSION.
% Named arguments and one call per output count, not varargin/varargout: the cells cost
% 2 us a call, 7% of 10^4 Jenkins points' work (bench/octave_speed.m).
if nargin ~= 4
    if nargin ~= 3
        error('fricreg:nargs', ['fricreg_element_eval: takes name, params, u and optionally ' ...
                                'state, not %d arguments'], nargin);
    end
    state = [];
end
if nargout <= 1
    f = fricreg_mex('element_eval', name, params, u, state);
elseif nargout == 2
    [f, dfdu] = fricreg_mex('element_eval', name, params, u, state);
elseif nargout == 3
    [f, dfdu, state_out] = fricreg_mex('element_eval', name, params, u, state);
else
    [f, dfdu, state_out, dfdp] = fricreg_mex('element_eval', name, params, u, state);
end
end
