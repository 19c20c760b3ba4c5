% SPDX-License-Identifier: GPL-3.0-or-later
function value = fricreg_hb_element_param(h, element, index)
%FRICREG_HB_ELEMENT_PARAM  One parameter of one of a driver's elements.
%   VALUE = FRICREG_HB_ELEMENT_PARAM(H, ELEMENT, INDEX) is parameter INDEX (from 1, the layout
%   of FRICREG_HB_SET_ELEMENT_PARAM: jenkins 1 kt, 2 mun, ...) of element ELEMENT (from 1, in
%   the order added) of the driver H, in the parameter's units (a gap reads 0).
%
%   Errors (identifiers):
%      fricreg:handle  H is not a live driver
%      fricreg:EINVAL  ELEMENT not an element held, INDEX beyond its parameters (or not whole
%                      numbers >= 1)
%
%   Source: fricreg_hb_get_element_param (include/fricreg_hb.h), through fricreg_mex
%   (matlab/mex_hb.c). Python: HarmonicBalance.element_param(element - 1, index - 1).
%
%   See also FRICREG_HB_SET_ELEMENT_PARAM.
if nargin < 3
    error('fricreg:nargs', 'fricreg_hb_element_param: takes a handle, element, index');
end
value = fricreg_mex('hb_get_element_param', h, element, index);
end
