% SPDX-License-Identifier: GPL-3.0-or-later
function fricreg_hb_set(h, varargin)
%FRICREG_HB_SET  Settings of a harmonic-balance driver: excitation, Newton, continuation, stability.
%   FRICREG_HB_SET(H, NAME, VALUE, ...) with the names
%      'excitation'    pc or {pc, ps}: the force pc cos(Omega t) + ps sin(Omega t), vectors of
%                      NDOF (N; ps zero when omitted).
%      'newton'        [tol max_iter]: converged when the largest residual is at most tol
%                      (0 < tol < 1) times the displacement scale, at most max_iter (1..1000)
%                      iterations a solve. Defaults [1e-10 50].
%      'solver'        how Newton's matrix is solved: 'auto' (default: by its capacitance from
%                      512 unknowns where few rows of the elements' Jacobian are off its
%                      diagonal, else dense, from 1024 first by refinement on the last LU),
%                      'dense' (LAPACK's LU of each, 1.9's) or 'capacitance'; the results
%                      agree to rounding.
%      'receptance'    how D_h = K - (h Omega)^2 M + i h Omega C is solved at each frequency:
%                      'auto' (default: through the modes of (K, M) from 200 dofs where the
%                      damping is Rayleigh's), 'lu' (LAPACK's LU of each D_h, 1.9's) or
%                      'modes'; the results agree to rounding.
%      'continuation'  [ds ds_min ds_max max_points]: the step in the scaled arclength
%                      (ds_min <= ds <= ds_max <= 1) and the most points stored (>= 2).
%                      Defaults [0.02 1e-6 0.1 2000].
%      'stability'     true or false: the Floquet stability of every later solution (stable,
%                      mu_max in the results, and period-doubling and Neimark-Sacker
%                      bifurcations along a branch). Default false.
%      'method'        how: 'auto' (default), 'hill', 'monodromy', 'condensed'.
%      'max_iterations'  the Newton steps one solve, branch or backbone may take in all (0, the
%                      default: no bound); a call that would take more raises fricreg:EWORK.
%                      The way to bound a call's time: Ctrl-C does not stop it (docs/matlab.md).
%   H is a handle of FRICREG_HARMONIC_BALANCE.
%
%   Errors (identifiers):
%      fricreg:handle      H is not a live driver
%      fricreg:option      an unknown name, or one without its value
%      fricreg:size        a vector of the wrong length
%      fricreg:EINVAL      a value out of its range (the message names it); an unknown method
%                          solver or receptance
%      fricreg:ENONFINITE  a NaN or infinite value
%
%   Source: fricreg_hb_set_excitation, fricreg_hb_set_newton, fricreg_hb_set_newton_solver,
%   fricreg_hb_set_receptance, fricreg_hb_set_continuation,
%   fricreg_hb_set_stability_method, fricreg_hb_set_stability, fricreg_hb_set_max_iterations
%   (include/fricreg_hb.h), through fricreg_mex (matlab/mex_hb.c). Python:
%   HarmonicBalance.set_excitation, .set_newton, .set_continuation, .set_stability (Python's
%   Ctrl-C stops a call through the library's monitor instead of max_iterations).
%
%   See also FRICREG_HARMONIC_BALANCE.
if nargin < 1
    error('fricreg:nargs', 'fricreg_hb_set: takes a handle, then name/value pairs');
end
if mod(numel(varargin), 2) ~= 0
    error('fricreg:option', 'fricreg_hb_set: options come in name/value pairs');
end
[~, ~, ~, ~, stability] = fricreg_mex('hb_info', h);
method = [];
for k = 1:2:numel(varargin)
    name = varargin{k};
    value = varargin{k + 1};
    if ~ischar(name)
        error('fricreg:option', 'fricreg_hb_set: an option name must be a string');
    end
    switch name
    case 'excitation'
        if iscell(value)
            if numel(value) ~= 2
                error('fricreg:size', 'fricreg_hb_set: excitation must be pc or {pc, ps}');
            end
            pc = value{1};
            ps = value{2};
        else
            pc = value;
            ps = zeros(size(value));
        end
        fricreg_mex('hb_set_excitation', h, pc, ps);
    case 'newton'
        v = vector(value, 2, name, '[tol max_iter]');
        fricreg_mex('hb_set_newton', h, v(1), v(2));
    case 'solver'
        fricreg_mex('hb_set_newton_solver', h, value);
    case 'receptance'
        fricreg_mex('hb_set_receptance', h, value);
    case 'continuation'
        v = vector(value, 4, name, '[ds ds_min ds_max max_points]');
        fricreg_mex('hb_set_continuation', h, v(1), v(2), v(3), v(4));
    case 'stability'
        stability = value;
        if isempty(method)
            method = 'auto';
        end
    case 'method'
        method = value;
    case 'max_iterations'
        fricreg_mex('hb_set_max_iterations', h, value);
    otherwise
        error('fricreg:option', ['fricreg_hb_set: unknown option ''%s'' (excitation, newton, ' ...
                                 'solver, receptance, continuation, stability, method, ' ...
                                 'max_iterations)'], name);
    end
end
if ~isempty(method)
    fricreg_mex('hb_set_stability', h, stability, method);
end
end

function v = vector(value, n, name, what)
if ~isnumeric(value) || numel(value) ~= n
    error('fricreg:size', 'fricreg_hb_set: %s must be %s', name, what);
end
v = double(value);
end
