% SPDX-License-Identifier: GPL-3.0-or-later
function [X, info] = fricreg_nlvib_frf(system, H, Om_s, Om_e, varargin)
%FRICREG_NLVIB_FRF  NLvib's frequency response of a system, computed by fricreg.
%   X = FRICREG_NLVIB_FRF(SYSTEM, H, OM_S, OM_E) is the frequency response that NLvib's
%   solve_and_continue(x0, @(X) HB_residual(X, SYSTEM, H, N, 'FRF'), OM_S, OM_E, ds) computes,
%   in NLvib's layout, computed by fricreg's harmonic balance (exact AFT, pseudo-arclength
%   continuation): an NLvib script swaps that one call for this one and keeps its own
%   post-processing (X(end, :) the frequencies, X(k:n:end-1, :) dof k's coefficients).
%
%   SYSTEM  NLvib's system: a MechanicalSystem object (ChainOfOscillators, ...) or a struct
%           with its fields M, K, D (NDOF x NDOF), Fex1 (NDOF x 1, the complex amplitude of
%           the fundamental force: real(Fex1 exp(i Om t))) and nonlinear_elements (a cell or
%           struct array; [] or absent for none). The element types with a fricreg element:
%              elasticDryFriction  fricreg's 'jenkins' (exact, not sampled at N): stiffness,
%                                  friction_limit_force, force_direction (the row of J).
%              unilateralSpring    stiffness max(q - gap, 0): fricreg's 'jenkins_normal' with
%                                  mu = 0 (no friction), kn = stiffness, n0 = -stiffness gap,
%                                  two rows w' of J (its tangential row carries no force);
%                                  with 'stability', Hill's method unless 'method' is given.
%           Any other type (cubicSpring, tanhDryFriction, quadraticDamper,
%           polynomialStiffness, ...) raises fricreg:nlvib naming it.
%   H       the harmonics, 1..40.
%   OM_S, OM_E  the start and end frequencies, rad/s (> 0, either order).
%   FRICREG_NLVIB_FRF(..., NAME, VALUE) also takes:
%      'x0'           NLvib's initial guess at OM_S, NDOF (2H + 1) x 1 in its layout (below);
%                     default: fricreg's own start (the solution reached from the linear
%                     regime along the excitation level).
%      'stability'    true: each point's Floquet stability in INFO.
%      'ds'           the first step in fricreg's scaled arclength (default 0.02; NLvib's ds
%                     is in its own unscaled unknowns: not the same number).
%      'newton', 'continuation', 'method': as FRICREG_HB_SET.
%
%   X       NDOF (2H + 1) + 1 x NPOINTS, a column per point as NLvib's: the coefficients in
%           NLvib's order [X0; Xc1; Xs1; Xc2; Xs2; ...; Xs_H], each block NDOF long (dof k's
%           mean at X(k), its cos(h Om t) and sin(h Om t) amplitudes at X(NDOF (2h - 1) + k)
%           and X(NDOF 2h + k)), then Om in X(end, :). (That is reshape(X(1:end-1, p), NDOF,
%           2H + 1): fricreg's per-dof coefficients (x0, a_1, b_1, ...).)
%   INFO    a struct: rms (NDOF x NPOINTS, each dof's RMS), stable and mu_max (1 x NPOINTS,
%           with 'stability'; [] otherwise), bifurcations (FRICREG_HB_FREQUENCY_RESPONSE's).
%
%   Errors (identifiers):
%      fricreg:nlvib   an element type with no fricreg element, or a global (non-local)
%                      element: the message names its type and index; an element's field
%                      missing
%      fricreg:size    x0 not NDOF (2H + 1) long; Fex1 not NDOF long
%      fricreg:option  an unknown option
%      and FRICREG_HARMONIC_BALANCE's and FRICREG_HB_FREQUENCY_RESPONSE's.
%
%   Source: fricreg_harmonic_balance.m and fricreg_hb_frequency_response.m (fricreg_hb.h's
%   fricreg_hb_continue); NLvib's conventions from its SRC/HB_residual.m (M. Krack, J. Gross,
%   https://github.com/maltekrack/NLvib; Krack & Gross, "Harmonic Balance for Nonlinear
%   Vibration Problems", Springer 2019). Python has no NLvib adapter.
%
%   Example (NLvib's example 07, its chain of three oscillators, with its two Jenkins
%   elements only):
%      sys = struct('M', eye(3), 'K', [2 -1 0; -1 2 -1; 0 -1 2], 'D', 0.02 * [2 -1 0; ...
%                   -1 2 -1; 0 -1 2], 'Fex1', [0; 1; 0]);
%      sys.nonlinear_elements = {struct('type', 'elasticDryFriction', 'stiffness', 20, ...
%          'friction_limit_force', 1, 'force_direction', [1; 0; 0]), ...
%          struct('type', 'elasticDryFriction', 'stiffness', 20, ...
%          'friction_limit_force', 1, 'force_direction', [-1; 1; 0])};
%      X = fricreg_nlvib_frf(sys, 7, 0.5, 2);   % for solve_and_continue(...)
%      Om = X(end, :); Q2 = X(2:3:end-1, :);    % NLvib's own post-processing
%
%   See also FRICREG_HARMONIC_BALANCE, FRICREG_HB_FREQUENCY_RESPONSE.
if nargin < 4
    error('fricreg:nargs', 'fricreg_nlvib_frf: takes system, H, Om_s, Om_e');
end
opts = struct('x0', [], 'stability', false);
rest = {};
if mod(numel(varargin), 2) ~= 0
    error('fricreg:option', 'fricreg_nlvib_frf: options come in name/value pairs');
end
for k = 1:2:numel(varargin)
    switch varargin{k}
    case {'x0', 'stability'}
        opts.(varargin{k}) = varargin{k + 1};
    case 'ds'
        ds = varargin{k + 1};
        rest = [rest, {'continuation', [ds 1e-6 max(0.1, ds) 2000]}]; %#ok<AGROW>
    case {'newton', 'continuation', 'method'}
        rest = [rest, varargin(k:k + 1)]; %#ok<AGROW>
        opts.method_given = true;
    otherwise
        error('fricreg:option', ['fricreg_nlvib_frf: unknown option ''%s'' (x0, stability, ' ...
                                 'ds, newton, continuation, method)'], num2str(varargin{k}));
    end
end
n = size(system.M, 1);
nc = 2 * H + 1;
elements = nlvib_elements(system, n);
unilateral = any(strcmp({elements.type}, 'jenkins_normal'));
if opts.stability && unilateral && ~isfield(opts, 'method_given')
    % a unilateral spring: Hill's method, whose verdict NLvib's shooting confirms on example
    % 03's middle branch, where the exact monodromy (the default's choice) finds a stable stretch
    rest = [rest, {'method', 'hill'}];
end
Fex1 = system.Fex1;
if numel(Fex1) ~= n
    error('fricreg:size', 'fricreg_nlvib_frf: Fex1 must have ndof = %d elements, not %d', n, ...
          numel(Fex1));
end
% NLvib's force real(Fex1 exp(i Om t)) = real(Fex1) cos(Om t) - imag(Fex1) sin(Om t)
h = fricreg_harmonic_balance(system.M, system.K, system.D, elements, H, ...
                             'excitation', {real(Fex1(:)), -imag(Fex1(:))}, ...
                             'stability', logical(opts.stability), rest{:});
cleanup = onCleanup(@() fricreg_hb_free(h));
guess = [];
if ~isempty(opts.x0)
    if numel(opts.x0) ~= n * nc
        error('fricreg:size', ['fricreg_nlvib_frf: x0 must have ndof (2H + 1) = %d elements ' ...
                               '(NLvib''s layout, Om not included), not %d'], n * nc, ...
              numel(opts.x0));
    end
    J = vertcat(elements.J);
    guess = J * reshape(opts.x0, n, nc); % the elements' q = J x, from NLvib's blocks
end
r = fricreg_hb_frequency_response(h, Om_s, Om_e, guess);
% NLvib's [X0; Xc1; Xs1; ...] a column per point: each point's NDOF x (2H + 1) coefficients
% column by column; one permute for the branch, not a loop over its points (bench/octave_speed.m)
X = [reshape(permute(r.x, [2 3 1]), n * nc, numel(r.omega)); r.omega'];
info = struct('rms', r.rms', 'stable', r.stable', 'mu_max', r.mu_max');
info.bifurcations = r.bifurcations;
end

function elements = nlvib_elements(system, n)
% NLvib's nonlinear_elements as fricreg_harmonic_balance's struct array: every type with no
% fricreg element named in one error.
elements = struct('type', {}, 'J', {}, 'params', {});
if ~isfield(system, 'nonlinear_elements') && ~isprop_(system, 'nonlinear_elements')
    return;
end
list = system.nonlinear_elements;
if isstruct(list)
    list = num2cell(list);
end
bad = {};
for i = 1:numel(list)
    e = list{i};
    type = '';
    if isstruct(e) && isfield(e, 'type') && ischar(e.type)
        type = e.type;
    end
    if isfield(e, 'islocal') && ~e.islocal
        bad{end + 1} = sprintf('%s (element %d, global)', type, i); %#ok<AGROW>
    elseif strcmpi(type, 'elasticDryFriction')
        w = direction(e, i, n, {'stiffness', 'friction_limit_force', 'force_direction'});
        elements(end + 1) = struct('type', 'jenkins', 'J', w, ...
                                   'params', [e.stiffness, e.friction_limit_force]); %#ok<AGROW>
    elseif strcmpi(type, 'unilateralSpring')
        w = direction(e, i, n, {'stiffness', 'gap', 'force_direction'});
        % k max(q - gap, 0) = max(0, n0 + kn q), n0 = -k gap: jenkins_normal's normal law,
        % its friction off (mu = 0: no tangential force on its tangential row, q's too)
        k = e.stiffness;
        elements(end + 1) = struct('type', 'jenkins_normal', 'J', [w; w], ...
                                   'params', [k, 0, k, -k * e.gap, 0]); %#ok<AGROW>
    else
        if isempty(type)
            type = '(no type)';
        end
        bad{end + 1} = sprintf('%s (element %d)', type, i); %#ok<AGROW>
    end
end
if ~isempty(bad)
    error('fricreg:nlvib', ['fricreg_nlvib_frf: NLvib element type with no fricreg element: ' ...
                            '%s; supported: elasticDryFriction (fricreg''s jenkins), ' ...
                            'unilateralSpring (jenkins_normal without friction)'], ...
          strjoin(bad, ', '));
end
end

function w = direction(e, i, n, fields)
% Element i's force_direction as a row of J, its fields checked.
for field = fields
    if ~isfield(e, field{1})
        error('fricreg:nlvib', 'fricreg_nlvib_frf: nonlinear_elements{%d} (%s) has no field %s', ...
              i, e.type, field{1});
    end
end
w = e.force_direction;
if ~isnumeric(w) || numel(w) ~= n
    error('fricreg:nlvib', ['fricreg_nlvib_frf: nonlinear_elements{%d}.force_direction must ' ...
                            'have ndof = %d elements'], i, n);
end
w = reshape(double(w), 1, n);
end

function yes = isprop_(object, name)
% Whether an NLvib object (a classdef MechanicalSystem) has the property name.
yes = isobject(object) && any(strcmp(properties(object), name));
end
