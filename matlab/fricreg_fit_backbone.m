% SPDX-License-Identifier: GPL-3.0-or-later
function fit = fricreg_fit_backbone(amplitude, freq_hz, zeta, varargin)
%FRICREG_FIT_BACKBONE  Fit the modal Iwan model to a mode's measured frequency and damping.
%   FIT = FRICREG_FIT_BACKBONE(AMPLITUDE, FREQ_HZ, ZETA) fits the modal Iwan model (Segalman's
%   four-parameter Iwan joint beside a linear modal stiffness K0 and damping ratio zeta0) to
%   the levels of a stepped-sine test: at each level its response amplitude, its natural
%   frequency and its damping ratio. GSL's trust-region least squares with the exact
%   Jacobian runs from several starts; the best converged one is the fit.
%   FIT = FRICREG_FIT_BACKBONE(..., NAME, VALUE, ...) sets options.
%
%   AMPLITUDE  vector of n levels' response amplitudes at the sensor, > 0: m, m/s or m/s^2
%              by 'kind' (any consistent unit).
%   FREQ_HZ    vector of n measured natural frequencies, Hz, > 0.
%   ZETA       vector of n measured damping ratios, > 0.
%
%   Options (names case-insensitive):
%   'kind'        'acceleration' (default), 'velocity' or 'displacement': AMPLITUDE is
%                 |s| omega^k a for k = 2, 1, 0 (a the modal amplitude).
%   'sensor'      the mass-normalized mode shape's value s at the sensor (default 1: the
%                 amplitudes are modal).
%   'sd_freq_hz', 'sd_zeta'  vectors of n standard deviations (both or neither): residuals
%                 weighted by them, the covariance not rescaled, normal intervals. Without:
%                 relative residuals, the covariance scaled by the residual variance,
%                 Student's t intervals.
%   'x0'          struct of starts by name (fields among fs, kt, chi, beta, zeta0, k0); a
%                 parameter without one starts from the levels' estimate.
%   'bounds'      struct of [lower upper] by name; default [0 Inf] ([-1 Inf] for chi).
%   'fixed'       struct of values by name: those parameters are not fitted
%                 (struct('beta', 0): the model without the delta at phi_max).
%   'starts'      how many starts, 1..1000 (default 32).
%
%   FIT is a struct (Python: fricreg.FitResult), parameters always in the order
%   fs, kt, chi, beta, zeta0, k0:
%      x               1 x 6, the parameters (the fixed ones as fixed): fs (macroslip force,
%                      modal force), kt (the joint's stiffness, 1/s^2), chi (> -1), beta
%                      (>= 0), zeta0, k0 (1/s^2)
%      params          the same, a struct by name
%      free            1 x 6 logical, the parameters fitted
%      cov             6 x 6 covariance (a fixed parameter's row and column 0)
%      lower, upper    1 x 6, the 95 % intervals (asymmetric for a log-scaled parameter)
%      sv              p x 1, the singular values of the Jacobian in the transformed free
%                      parameters, largest first (p free parameters)
%      vectors         p x 6, row k the parameter combination sv(k) determines
%      residuals_freq, residuals_zeta   n x 1, the weighted residuals (model - measured)/sd
%      cost            r'*r (chi-square with deviations given)
%      residual_variance, quantile, condition
%      nfev, njev, nit, starts_converged, best_start
%      success         true (a failed fit raises an error instead); message
%
%   Errors (identifiers):
%      fricreg:nargs       fewer than three arguments
%      fricreg:option      an unknown option, a value without a name, an unknown parameter
%                          name in x0, bounds or fixed, one of sd_freq_hz and sd_zeta alone
%      fricreg:type, fricreg:size   an input not a real double vector; lengths that differ
%      fricreg:EINVAL      a value out of range; fewer levels than free parameters; the best
%                          fit at a bound (the message names the parameter); a level beyond
%                          the backbone's reach
%      fricreg:ESIZE       deviations of another length than the levels
%      fricreg:ENONFINITE  an input NaN or infinite
%      fricreg:ESINGULAR   the levels do not determine the parameters (the message names the
%                          combination): fix one, or add levels
%      fricreg:EWORK       no start converged
%
%   Source: fricreg_fit_* (include/fricreg_fit.h, docs/identification.md), a fit object held
%   in the gateway fricreg_mex (matlab/fricreg_mex.c) and freed on return. D. J. Segalman, J.
%   Appl. Mech. 72 (2005) 752-760; R. M. Lacayo, M. S. Allen, MSSP 118 (2019) 133-157.
%   Python: fricreg.fit_backbone.
%
%   Example (levels made by FRICREG_BACKBONE from known parameters, recovered):
%      truth = [30 3e5 0.3 0.5 0.002 8.4e5];
%      A = logspace(0, 2, 8);
%      [f, z] = fricreg_backbone(truth, A, 'kind', 'acceleration', 'sensor', 0.37);
%      fit = fricreg_fit_backbone(A, f, z, 'sensor', 0.37);
%      fit.params.fs    % 30
%
%   See also FRICREG_BACKBONE.
if nargin < 3
    error('fricreg:nargs', ...
          'fricreg_fit_backbone: takes AMPLITUDE, FREQ_HZ, ZETA and options, not %d arguments', ...
          nargin);
end
names = {'fs', 'kt', 'chi', 'beta', 'zeta0', 'k0'};
opts = struct('kind', 'acceleration', 'sensor', 1, 'sd_freq_hz', [], 'sd_zeta', [], ...
              'x0', struct(), 'bounds', struct(), 'fixed', struct(), 'starts', 32);
opts = parse_options(opts, varargin, 'fricreg_fit_backbone');
x0 = by_name(opts.x0, 'x0', names);
bounds = by_name(opts.bounds, 'bounds', names);
fixed = by_name(opts.fixed, 'fixed', names);
if isempty(opts.sd_freq_hz) ~= isempty(opts.sd_zeta)
    error('fricreg:option', 'fricreg_fit_backbone: give both sd_freq_hz and sd_zeta, or neither');
end

h = fricreg_mex('fit_create');
cleanup = onCleanup(@() fricreg_mex('free', h)); % freed on return and on error
fricreg_mex('fit_set_sensor', h, opts.sensor);
fricreg_mex('fit_set_levels', h, opts.kind, amplitude, freq_hz, zeta);
if ~isempty(opts.sd_freq_hz)
    fricreg_mex('fit_set_deviations', h, opts.sd_freq_hz, opts.sd_zeta);
end
free = true(1, 6);
for j = 1:6
    name = names{j};
    if isfield(fixed, name)
        fricreg_mex('fit_set_fixed', h, name, fixed.(name));
        free(j) = false;
        continue
    end
    range = [0 Inf];
    if strcmp(name, 'chi')
        range = [-1 Inf];
    end
    if isfield(bounds, name)
        range = bounds.(name);
        if ~isnumeric(range) || numel(range) ~= 2
            error('fricreg:option', 'fricreg_fit_backbone: bounds.%s must be [lower upper]', name);
        end
    end
    start = NaN;
    if isfield(x0, name)
        start = x0.(name);
    end
    fricreg_mex('fit_set_free', h, name, start, range(1), range(2));
end
fricreg_mex('fit_set_starts', h, opts.starts);
fricreg_mex('fit_run', h);

x = fricreg_mex('fit_params', h);
[cov, lower, upper] = fricreg_mex('fit_covariance', h);
[sv, vectors] = fricreg_mex('fit_identifiability', h);
[rf, rz] = fricreg_mex('fit_residuals', h);
p = fricreg_mex('fit_value', h, 'nfree');
converged = fricreg_mex('fit_value', h, 'starts_converged');
fit = struct();
fit.x = x;
fit.params = cell2struct(num2cell(x), names, 2);
fit.free = free;
fit.cov = cov;
fit.lower = lower;
fit.upper = upper;
fit.sv = sv(1:p);
fit.vectors = vectors(1:p, :);
fit.residuals_freq = rf;
fit.residuals_zeta = rz;
fit.cost = fricreg_mex('fit_value', h, 'cost');
fit.residual_variance = fricreg_mex('fit_value', h, 'residual_variance');
fit.quantile = fricreg_mex('fit_quantile', h);
fit.condition = fricreg_mex('fit_value', h, 'condition');
fit.nfev = fricreg_mex('fit_value', h, 'nfev');
fit.njev = fricreg_mex('fit_value', h, 'njev');
fit.nit = fricreg_mex('fit_value', h, 'iterations');
fit.starts_converged = converged;
fit.best_start = fricreg_mex('fit_value', h, 'best_start');
fit.success = true;
fit.message = sprintf('converged from %d of the starts', converged);
end

function opts = parse_options(opts, args, caller)
% Name/value pairs into the defaults' struct; names case-insensitive.
if mod(numel(args), 2) ~= 0
    error('fricreg:option', '%s: options come as name, value pairs', caller);
end
for k = 1:2:numel(args)
    name = args{k};
    if ~ischar(name) || ~isfield(opts, lower(name))
        error('fricreg:option', '%s: option %d is not one of %s', caller, (k + 1) / 2, ...
              strjoin(fieldnames(opts)', ', '));
    end
    opts.(lower(name)) = args{k + 1};
end
end

function s = by_name(s, what, names)
% A scalar struct whose fields are parameter names (an empty [] for none).
if isempty(s) && ~isstruct(s)
    s = struct();
end
if ~isstruct(s) || numel(s) ~= 1
    error('fricreg:option', 'fricreg_fit_backbone: %s must be a struct by parameter name', what);
end
unknown = setdiff(fieldnames(s), names);
if ~isempty(unknown)
    error('fricreg:option', 'fricreg_fit_backbone: %s: unknown parameter %s (one of %s)', ...
          what, unknown{1}, strjoin(names, ', '));
end
end
