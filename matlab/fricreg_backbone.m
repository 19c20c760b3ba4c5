% SPDX-License-Identifier: GPL-3.0-or-later
function [freq_hz, zeta, modal, dfreq_dp, dzeta_dp] = fricreg_backbone(params, amplitude, varargin)
%FRICREG_BACKBONE  The modal Iwan model's backbone: frequency and damping against amplitude.
%   [FREQ_HZ, ZETA, MODAL] = FRICREG_BACKBONE(PARAMS, AMPLITUDE) gives the natural frequency
%   and damping ratio of the modal Iwan model at each amplitude, by the quasi-static modal
%   analysis in closed form:
%      k_sec = k0 + F(a)/a,   FREQ_HZ = sqrt(k_sec)/(2 pi),
%      ZETA = zeta0 + D(a)/(2 pi k_sec a^2)
%   F and D the joint's backbone force and Masing dissipation per cycle at the modal
%   amplitude a (include/fricreg_fit.h).
%   [..., DFREQ_DP, DZETA_DP] = FRICREG_BACKBONE(...) also gives the exact derivatives in the
%   parameters, the amplitude held.
%   FRICREG_BACKBONE(..., 'kind', KIND, 'sensor', S) sets what AMPLITUDE is.
%
%   PARAMS     1 x 6 (or 6 x 1) in the order fs, kt, chi, beta, zeta0, k0, or a struct with
%              those six fields: fs the macroslip force (modal force, > 0), kt the joint's
%              stiffness (1/s^2, > 0), chi (> -1), beta (>= 0), zeta0 (>= 0), k0 (1/s^2,
%              >= 0).
%   AMPLITUDE  vector of n amplitudes at the sensor, > 0, of 'kind'.
%   'kind'     'displacement' (default), 'velocity' or 'acceleration': AMPLITUDE is
%              |s| omega^k a for k = 0, 1, 2.
%   'sensor'   the mass-normalized mode shape's value s at the sensor (default 1: modal).
%
%   FREQ_HZ, ZETA, MODAL  of AMPLITUDE's shape: the natural frequencies (Hz), the damping
%              ratios and the modal amplitudes a.
%   DFREQ_DP, DZETA_DP    n x 6, d/dp in the order of PARAMS.
%
%   Errors (identifiers):
%      fricreg:nargs       fewer than two arguments, more than five outputs
%      fricreg:option      an unknown option or parameter name, a struct missing a parameter
%      fricreg:type, fricreg:size   not real double vectors; PARAMS not of 6
%      fricreg:EINVAL      a parameter out of its range, an amplitude <= 0 or beyond the
%                          backbone's reach (an acceleration with k0 = 0), an unknown kind
%      fricreg:ENONFINITE  an input NaN or infinite
%
%   Source: fricreg_fit_eval (include/fricreg_fit.h, docs/identification.md), through the
%   gateway fricreg_mex (matlab/fricreg_mex.c). Python: fricreg.backbone.
%
%   Example (modal amplitudes from 1e-6 to 1e-3):
%      [f, z] = fricreg_backbone([30 3e5 0.3 0.5 0.002 8.4e5], logspace(-6, -3, 5))
%
%   See also FRICREG_FIT_BACKBONE.
if nargin < 2
    error('fricreg:nargs', ...
          'fricreg_backbone: takes PARAMS, AMPLITUDE and options, not %d arguments', nargin);
end
names = {'fs', 'kt', 'chi', 'beta', 'zeta0', 'k0'};
opts = struct('kind', 'displacement', 'sensor', 1);
if mod(numel(varargin), 2) ~= 0
    error('fricreg:option', 'fricreg_backbone: options come as name, value pairs');
end
for k = 1:2:numel(varargin)
    name = varargin{k};
    if ~ischar(name) || ~isfield(opts, lower(name))
        error('fricreg:option', 'fricreg_backbone: option %d is not one of kind, sensor', ...
              (k + 1) / 2);
    end
    opts.(lower(name)) = varargin{k + 1};
end
if isstruct(params)
    if numel(params) ~= 1 || ~isempty(setxor(fieldnames(params), names))
        error('fricreg:option', 'fricreg_backbone: a struct PARAMS has the fields %s', ...
              strjoin(names, ', '));
    end
    p = zeros(1, 6);
    for j = 1:6
        value = params.(names{j});
        if ~isa(value, 'double') || numel(value) ~= 1
            error('fricreg:type', 'fricreg_backbone: params.%s must be a double scalar', names{j});
        end
        p(j) = value;
    end
    params = p;
end
h = fricreg_mex('fit_create');
cleanup = onCleanup(@() fricreg_mex('free', h)); % freed on return and on error
fricreg_mex('fit_set_sensor', h, opts.sensor);
[freq_hz, zeta, modal, dfreq_dp, dzeta_dp] = deal([]);
if nargout >= 4
    [freq_hz, zeta, modal, dfreq_dp, dzeta_dp] = ...
        fricreg_mex('fit_eval', h, params, opts.kind, amplitude);
else
    [freq_hz, zeta, modal] = fricreg_mex('fit_eval', h, params, opts.kind, amplitude);
end
end
