% SPDX-License-Identifier: GPL-3.0-or-later
function [text, number] = fricreg_version(varargin)
%FRICREG_VERSION  The version of the fricreg library the MEX gateway runs on.
%   TEXT = FRICREG_VERSION() is the version 'MAJOR.MINOR.PATCH', a char row vector.
%   [TEXT, NUMBER] = FRICREG_VERSION() also gives it as the double
%   MAJOR*10000 + MINOR*100 + PATCH (10900 for 1.9.0).
%
%   These are the library's that the gateway is linked to at run time (Python:
%   fricreg.__version__).
%
%   Errors: fricreg:nargs if called with an argument.
%
%   Source: fricreg_version and fricreg_version_number (include/fricreg.h), through the
%   gateway fricreg_mex (matlab/fricreg_mex.c).
%
%   Example:
%      [text, number] = fricreg_version()
%
%   See also FRICREG_LAW_EVAL, FRICREG_ELEMENT_EVAL, FRICREG_FIT_BACKBONE, FRICREG_BACKBONE.
[text, number] = fricreg_mex('version', varargin{:});
end
