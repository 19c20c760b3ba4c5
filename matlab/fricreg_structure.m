% SPDX-License-Identifier: GPL-3.0-or-later
function [h, eps] = fricreg_structure(M, K, varargin)
%FRICREG_STRUCTURE  A linear structure with friction contacts and joint elements, to step in time.
%   H = FRICREG_STRUCTURE(M, K, NAME, VALUE, ...) makes the structure
%
%       M u'' + C u' + K u = p g(t) - M r a_g(t) + J' f - Je' fe,      zdot = J u'
%
%   and returns its handle H, which FRICREG_STRUCTURE_RUN steps, FRICREG_STRUCTURE_RESET
%   restarts and FRICREG_STRUCTURE_FREE frees (or it is freed when fricreg_mex is cleared or
%   the session ends). f are the contacts' friction forces from a law of Quinn's paper (law (4)
%   by default), fe the joint elements' (FRICREG_ELEMENT_EVAL's types). [H, EPS] = ... also
%   returns the law's eps in force (m/s).
%
%   M, K   NDOF x NDOF (kg, N/m), symmetric, full or sparse; M positive definite.
%   Options (name/value pairs):
%      'damping'       NDOF x NDOF damping matrix C (N s/m), symmetric; not with 'rayleigh'.
%      'rayleigh'      [a0 a1]: C = a0 M + a1 K (a0 in 1/s, a1 in s, >= 0).
%      'J', 'mun'      the friction contacts: J M x NDOF (contact i slides at (J u')_i, no zero
%                      row), mun a vector of M bounds mu N_i >= 0 (N). Together; without them
%                      the structure has no contacts.
%      'law', 'eps'    the contacts' law (a name of fricreg_mex('law_names') or its code;
%                      default 'quinn', law (4)) and its regularization eps > 0 (m/s); default
%                      1 % of the ground record's peak velocity, or 1e-3 without a record.
%      'influence'     r, a vector of NDOF (default 1 at every dof).
%      'ground_accel'  {t0, dt_rec, samples}: a_g (m/s^2), n >= 2 samples at t0 + k dt_rec (s),
%                      linear between them and 0 outside.
%      'load'          p, a vector of NDOF (N), of the load p g(t).
%      'load_history'  {t0, dt_rec, samples}: g (dimensionless), as 'ground_accel'; default
%                      g = 1 (a constant load).
%      'elements'      a struct array (or cell array of structs), one block of one element type
%                      each, with the fields type, J ((ME DIM) x NDOF) and params (ME x NPARAMS or
%                      a vector shared), as FRICREG_HARMONIC_BALANCE's elements.
%      'u0', 'v0'      initial displacements (m) and velocities (m/s), vectors of NDOF.
%      'newton'        [tol max_iter]: Newton's relative tolerance (0 < tol < 1, default 1e-10)
%                      and iterations per step (1..1000, default 50).
%      'error_estimate'  'off' (default), 'on' (two companion runs at (eps/2, dt/2) and
%                      (eps/4, dt/4), or coarser ones screening first) or 'one' (1.6's one).
%
%   Errors (identifiers):
%      fricreg:nargs       fewer than two arguments
%      fricreg:type        an array not real double; elements not structs or a field missing
%      fricreg:size        a matrix or vector of the wrong shape
%      fricreg:option      an unknown option, or one without its value; J without mun, law or
%                          eps without J, both 'damping' and 'rayleigh'
%      fricreg:EINVAL      a negative bound, a zero row of J, a parameter out of its range (the
%                          message names the element), eps <= 0, an unknown law or element type
%      fricreg:ENOTSYM     M, K or C not symmetric;   fricreg:ENOTPSD  M not positive definite
%      fricreg:ENONFINITE  a NaN or infinite entry
%   The structure made is freed before any error is raised.
%
%   Source: fricreg_structure_create and its setters (include/fricreg_structure.h,
%   fricreg_structure_elements.h), through fricreg_mex (matlab/mex_structure.c). Python:
%   fricreg.Structure(M, K, damping=..., rayleigh=..., J=..., mun=..., law=..., eps=...,
%   ground_accel=..., load=..., elements=..., error_estimate=...).
%
%   Example (a mass on a spring, released from 1 mm: free vibration):
%      h = fricreg_structure(2.385, 1e3, 'u0', 1e-3);
%      r = fricreg_structure_run(h, 'newmark', 1e-3, 1);   % r.displacements ~ 1e-3 cos(w t)
%      fricreg_structure_free(h);
%
%   See also FRICREG_STRUCTURE_RUN, FRICREG_STRUCTURE_RESET, FRICREG_STRUCTURE_FREE.
if nargin < 2
    error('fricreg:nargs', 'fricreg_structure: takes M, K and options');
end
names = {'damping', 'rayleigh', 'J', 'mun', 'law', 'eps', 'influence', 'ground_accel', ...
         'load', 'load_history', 'elements', 'u0', 'v0', 'newton', 'error_estimate'};
o = struct();
if mod(numel(varargin), 2) ~= 0
    error('fricreg:option', 'fricreg_structure: options come in name/value pairs');
end
for k = 1:2:numel(varargin)
    if ~ischar(varargin{k}) || ~any(strcmp(varargin{k}, names))
        error('fricreg:option', 'fricreg_structure: unknown option (one of %s)', ...
              strjoin(names, ', '));
    end
    o.(varargin{k}) = varargin{k + 1};
end
if isfield(o, 'J') ~= isfield(o, 'mun')
    error('fricreg:option', ['fricreg_structure: J and mun come together (neither: no ' ...
                             'friction contacts)']);
end
if ~isfield(o, 'J') && (isfield(o, 'law') || isfield(o, 'eps'))
    error('fricreg:option', 'fricreg_structure: law, eps: the contacts'' law; without J there is none');
end
if isfield(o, 'damping') && isfield(o, 'rayleigh')
    error('fricreg:option', 'fricreg_structure: give damping or rayleigh, not both');
end
if isfield(o, 'load_history') && ~isfield(o, 'load')
    error('fricreg:option', 'fricreg_structure: load_history is the time function of load: give both');
end
elements = {};
if isfield(o, 'elements')
    elements = o.elements;
    if isstruct(elements)
        elements = num2cell(elements);
    elseif ~iscell(elements) || ~all(cellfun(@isstruct, elements))
        error('fricreg:type', 'fricreg_structure: elements must be a struct array with fields type, J, params');
    end
    for i = 1:numel(elements)
        for field = {'type', 'J', 'params'}
            if ~isfield(elements{i}, field{1})
                error('fricreg:type', 'fricreg_structure: elements(%d) has no field %s', i, field{1});
            end
        end
    end
end
m = 0;
if isfield(o, 'J')
    m = size(o.J, 1);
end
h = fricreg_mex('st_create', size(M, 1), m);
try
    fricreg_mex('st_set_matrix', h, 'mass', M);
    fricreg_mex('st_set_matrix', h, 'stiffness', K);
    if isfield(o, 'damping')
        fricreg_mex('st_set_matrix', h, 'damping', o.damping);
    end
    if isfield(o, 'rayleigh')
        if ~isnumeric(o.rayleigh) || numel(o.rayleigh) ~= 2
            error('fricreg:size', 'fricreg_structure: rayleigh must be [a0 a1]');
        end
        fricreg_mex('st_set_rayleigh', h, o.rayleigh(1), o.rayleigh(2));
    end
    if m > 0
        fricreg_mex('st_set_matrix', h, 'contacts', o.J);
        fricreg_mex('st_set_bounds', h, o.mun);
    elseif isfield(o, 'mun')
        fricreg_mex('st_set_bounds', h, o.mun); % J with no row: mun must be empty too
    end
    if isfield(o, 'influence')
        fricreg_mex('st_set_influence', h, o.influence);
    end
    if isfield(o, 'ground_accel')
        [t0, dt_rec, samples] = record(o.ground_accel, 'ground_accel');
        fricreg_mex('st_set_ground_accel', h, t0, dt_rec, samples);
    end
    if isfield(o, 'load')
        t0 = 0; dt_rec = 0; samples = [];
        if isfield(o, 'load_history')
            [t0, dt_rec, samples] = record(o.load_history, 'load_history');
        end
        fricreg_mex('st_set_load', h, o.load, t0, dt_rec, samples);
    end
    for i = 1:numel(elements)
        fricreg_mex('st_add_elements', h, elements{i}.type, elements{i}.J, elements{i}.params);
    end
    eps = [];
    if m > 0
        law = 'quinn';
        if isfield(o, 'law')
            law = o.law;
        end
        e = [];
        if isfield(o, 'eps')
            e = o.eps;
            if isempty(e)
                error('fricreg:size', 'fricreg_structure: eps must be a scalar');
            end
        end
        eps = fricreg_mex('st_set_law', h, law, e);
    end
    if isfield(o, 'u0') || isfield(o, 'v0')
        u0 = []; v0 = [];
        if isfield(o, 'u0'), u0 = o.u0; end
        if isfield(o, 'v0'), v0 = o.v0; end
        fricreg_mex('st_set_initial', h, u0, v0);
    end
    if isfield(o, 'newton')
        if ~isnumeric(o.newton) || numel(o.newton) ~= 2
            error('fricreg:size', 'fricreg_structure: newton must be [tol max_iter]');
        end
        fricreg_mex('st_set_newton', h, o.newton(1), o.newton(2));
    end
    if isfield(o, 'error_estimate')
        fricreg_mex('st_set_error_estimate', h, o.error_estimate);
    end
catch err
    fricreg_mex('free', h);
    rethrow(err);
end
end

function [t0, dt_rec, samples] = record(r, name)
% {t0, dt_rec, samples} of a record.
if ~iscell(r) || numel(r) ~= 3
    error('fricreg:type', 'fricreg_structure: %s must be {t0, dt_rec, samples}', name);
end
[t0, dt_rec, samples] = r{:};
if ~isnumeric(samples) || numel(samples) < 2
    error('fricreg:size', 'fricreg_structure: %s: a record needs at least 2 samples', name);
end
end
