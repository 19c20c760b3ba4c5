% SPDX-License-Identifier: GPL-3.0-or-later
function fricreg_hb_set_element_param(h, elements, index, value)
%FRICREG_HB_SET_ELEMENT_PARAM  Move one parameter of a driver's elements, in place.
%   FRICREG_HB_SET_ELEMENT_PARAM(H, ELEMENTS, INDEX, VALUE) sets parameter INDEX (from 1, in
%   each element's type's layout: jenkins 1 kt, 2 mun; iwan k_1..k_ns then phi_1..phi_ns;
%   jenkins_normal and contact_3d 1 kt, 2 mu, 3 kn, 4 n0, 5 gap; spring 1 k; dahl 1 sigma,
%   2 fc) of the elements ELEMENTS of the driver H (from 1, in the order
%   FRICREG_HARMONIC_BALANCE added them: a scalar, or consecutive indices first:last) to VALUE,
%   in the parameter's units: a parameter study without building the model again. A model
%   change: the last solution, branch and backbone are forgotten (a backbone's points stay
%   readable without their motion). The value is checked as FRICREG_HARMONIC_BALANCE checks it.
%
%   Errors (identifiers):
%      fricreg:handle      H is not a live driver
%      fricreg:size        ELEMENTS empty or not consecutive; VALUE not a scalar
%      fricreg:EINVAL      ELEMENTS beyond the elements; INDEX beyond an element's parameters;
%                          VALUE out of its range (a stiffness <= 0, a slip force, mu or kn
%                          < 0, a gap other than 0): the message names the element
%      fricreg:ENONFINITE  VALUE NaN or infinite
%   On an error no element changes.
%
%   Source: fricreg_hb_set_element_param (include/fricreg_hb.h), through fricreg_mex
%   (matlab/mex_hb.c). Python: HarmonicBalance.set_element_param(first - 1, count, index - 1,
%   value).
%
%   See also FRICREG_HB_ELEMENT_PARAM, FRICREG_HARMONIC_BALANCE.
if nargin < 4
    error('fricreg:nargs', ['fricreg_hb_set_element_param: takes a handle, elements, index, ' ...
                            'value']);
end
if ~isnumeric(elements) || isempty(elements) || any(diff(elements(:)) ~= 1)
    error('fricreg:size', ['fricreg_hb_set_element_param: elements must be an index or ' ...
                           'consecutive indices first:last, not %s'], mat2str(elements));
end
fricreg_mex('hb_set_element_param', h, double(elements(1)), numel(elements), index, value);
end
