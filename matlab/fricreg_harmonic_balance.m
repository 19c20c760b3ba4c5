% SPDX-License-Identifier: GPL-3.0-or-later
function h = fricreg_harmonic_balance(M, K, C, elements, harmonics, varargin)
%FRICREG_HARMONIC_BALANCE  A harmonic-balance driver: a linear structure with friction elements.
%   H = FRICREG_HARMONIC_BALANCE(M, K, C, ELEMENTS, HARMONICS) makes the driver of the model
%
%       M x'' + C x' + K x + J' f(J x) = pc cos(Omega t) + ps sin(Omega t)
%
%   for HARMONICS harmonics and returns its handle H, which FRICREG_HB_SOLVE,
%   FRICREG_HB_FREQUENCY_RESPONSE, FRICREG_HB_LEVEL_RESPONSE, FRICREG_HB_BACKBONE,
%   FRICREG_HB_BACKBONE_AT, FRICREG_HB_PEAK, FRICREG_HB_TRUNCATION_ERROR,
%   FRICREG_HB_BACKBONE_SENSITIVITIES, FRICREG_HB_MODAL_PARTICIPATION, FRICREG_HB_SET,
%   FRICREG_HB_SET_ELEMENT_PARAM and FRICREG_HB_ELEMENT_PARAM take. Free it with FRICREG_HB_FREE (or it is freed when fricreg_mex
%   is cleared or the session ends).
%   FRICREG_HARMONIC_BALANCE(..., NAME, VALUE, ...) also sets:
%      'rayleigh'    [a0 a1]: C = a0 M + a1 K (a0 in 1/s, a1 in s), in place of C (give C = []).
%      'excitation'  pc or {pc, ps}: the force's cosine and sine amplitudes, vectors of NDOF (N);
%                    without it the force is zero (a backbone needs none).
%      'newton', 'continuation', 'stability', 'method': as FRICREG_HB_SET.
%
%   M, K      NDOF x NDOF, symmetric (mass units, e.g. kg; N/m), full or sparse (a sparse one
%             makes the model sparse: KLU); K nonsingular.
%   C         NDOF x NDOF damping (N s/m), symmetric, or [] (none, or 'rayleigh'). A model
%             without damping has no finite response at its linear resonances.
%   ELEMENTS  a struct array (or a cell array of structs), one entry per block of elements of
%             one type, with the fields
%                type    an element type of fricreg_element_eval ('jenkins', 'iwan',
%                        'jenkins_normal', 'contact_3d', 'jenkins_2d', 'spring', 'dahl', ...)
%                J       (ME DIM) x NDOF: element i's DIM rows, its relative displacements
%                        q = J x (tangential components, then the normal one), in order
%                params  ME x NPARAMS (a row an element) or a vector of NPARAMS shared, in the
%                        type's layout (jenkins: [kt mun]; iwan: [k_1..k_ns phi_1..phi_ns]; ...).
%             Any number of elements: memory is the limit. The unknowns q are the rows of all the blocks' J,
%             in order: ROWS x (2 HARMONICS + 1).
%   HARMONICS H, 1..40.
%
%   Fourier coefficients, here and in every result: a row's (x0, a_1, b_1, ..., a_H, b_H) of
%   x(t) = x0 + sum_h a_h cos(h Omega t) + b_h sin(h Omega t).
%
%   Errors (identifiers):
%      fricreg:nargs       fewer than five arguments
%      fricreg:type        ELEMENTS not a struct array, a field missing; an array not real double
%      fricreg:size        M, K or C not NDOF x NDOF; J not (ME DIM) x NDOF; params of a length
%                          the type does not take
%      fricreg:option      an unknown option, or one without its value
%      fricreg:EINVAL      NDOF, the elements' count or HARMONICS out of range; a parameter out
%                          of its range (the message names the element); an unknown type; a
%                          negative mass on M's diagonal; both C and 'rayleigh'
%      fricreg:ENOTSYM     M, K or C not symmetric (the message names the entry)
%      fricreg:ENONFINITE  a NaN or infinite entry
%   The driver made is freed before any error is raised.
%
%   Source: fricreg_hb_create, fricreg_hb_set_matrix, fricreg_hb_set_rayleigh,
%   fricreg_hb_add_elements, fricreg_hb_set_excitation (include/fricreg_hb.h; M. Krack, J.
%   Gross, "Harmonic Balance for Nonlinear Vibration Problems", Springer 2019), through
%   fricreg_mex (matlab/mex_hb.c). Python: fricreg.HarmonicBalance(M, K, C, elements=...,
%   harmonics=..., rayleigh=..., excitation=...).
%
%   Example (one mass on a spring and a Jenkins element, forced at its cosine):
%      h = fricreg_harmonic_balance(1, 1, 0.02, struct('type', 'jenkins', 'J', 1, ...
%                                   'params', [20 1]), 7, 'excitation', 0.5);
%      s = fricreg_hb_solve(h, 2.5);   % s.x: 1 x 15 coefficients
%      fricreg_hb_free(h);
%
%   See also FRICREG_HB_SET, FRICREG_HB_SOLVE, FRICREG_HB_FREQUENCY_RESPONSE,
%   FRICREG_HB_BACKBONE, FRICREG_HB_FREE, FRICREG_NLVIB_FRF.
if nargin < 5
    error('fricreg:nargs', 'fricreg_harmonic_balance: takes M, K, C, elements, harmonics');
end
if iscell(elements)
    if ~all(cellfun(@isstruct, elements))
        error('fricreg:type', 'fricreg_harmonic_balance: elements must be structs');
    end
elseif isstruct(elements)
    elements = num2cell(elements);
else
    error('fricreg:type', ['fricreg_harmonic_balance: elements must be a struct array with ' ...
                           'fields type, J, params, not %s'], class(elements));
end
m = 0;
for i = 1:numel(elements)
    e = elements{i};
    for field = {'type', 'J', 'params'}
        if ~isfield(e, field{1})
            error('fricreg:type', 'fricreg_harmonic_balance: elements(%d) has no field %s', ...
                  i, field{1});
        end
    end
    dim = fricreg_mex('element_info', e.type);
    if ~isnumeric(e.J) || ndims(e.J) ~= 2 || mod(size(e.J, 1), dim) ~= 0
        error('fricreg:size', ['fricreg_harmonic_balance: elements(%d).J must be ' ...
                               '(me %d) x ndof (%s: %d rows an element), not %s'], ...
              i, dim, e.type, dim, mat2str(size(e.J)));
    end
    m = m + size(e.J, 1) / dim;
end
[options, rest] = split_options(varargin, {'rayleigh', 'excitation'});
if isfield(options, 'rayleigh') && ~isempty(C)
    error('fricreg:EINVAL', ['fricreg_harmonic_balance: C, rayleigh: give one damping, the ' ...
                             'matrix C or Rayleigh''s [a0 a1] (FRICREG_EINVAL)']);
end
if isnumeric(M) && ismatrix(M) && size(M, 1) == size(M, 2)
    bad = find(diag(M) < 0, 1);
    if ~isempty(bad) % the C driver takes any symmetric M: a negative mass is the binding's check
        error('fricreg:EINVAL', ['fricreg_harmonic_balance: M(%d, %d) = %g; a mass is >= 0 ' ...
                                 '(FRICREG_EINVAL)'], bad, bad, full(M(bad, bad)));
    end
end
h = fricreg_mex('hb_create', size(M, 1), m, harmonics);
try
    fricreg_mex('hb_set_matrix', h, 'mass', M);
    fricreg_mex('hb_set_matrix', h, 'stiffness', K);
    if ~isempty(C)
        fricreg_mex('hb_set_matrix', h, 'damping', C);
    end
    if isfield(options, 'rayleigh')
        r = options.rayleigh;
        if ~isnumeric(r) || numel(r) ~= 2
            error('fricreg:size', 'fricreg_harmonic_balance: rayleigh must be [a0 a1]');
        end
        fricreg_mex('hb_set_rayleigh', h, r(1), r(2));
    end
    for i = 1:numel(elements)
        fricreg_mex('hb_add_elements', h, elements{i}.type, elements{i}.J, elements{i}.params);
    end
    if isfield(options, 'excitation')
        rest = [{'excitation', options.excitation}, rest];
    end
    if ~isempty(rest)
        fricreg_hb_set(h, rest{:});
    end
catch err
    fricreg_mex('free', h);
    rethrow(err);
end
end

function [options, rest] = split_options(args, names)
% The name/value pairs of names into a struct, the others (FRICREG_HB_SET's) left in rest.
options = struct();
rest = {};
if mod(numel(args), 2) ~= 0
    error('fricreg:option', 'fricreg_harmonic_balance: options come in name/value pairs');
end
for k = 1:2:numel(args)
    if ~ischar(args{k})
        error('fricreg:option', 'fricreg_harmonic_balance: an option name must be a string');
    end
    if any(strcmp(args{k}, names))
        options.(args{k}) = args{k + 1};
    else
        rest = [rest, args(k:k + 1)]; %#ok<AGROW>
    end
end
end
