% SPDX-License-Identifier: GPL-3.0-or-later
function fricreg_test_check(got, want, tol, what, scale)
%FRICREG_TEST_CHECK  Check got against want elementwise, of the same size:
%   |got - want| <= tol |want| element by element, or <= tol SCALE given a scale (for arrays
%   whose elements cross zero). tol 0: the same numbers (-0 and 0 alike). what names the
%   check in the error.
if ~isequal(size(got), size(want))
    error('test:check', '%s: size %s, expected %s', what, mat2str(size(got)), mat2str(size(want)));
end
if nargin < 5
    scale = abs(want(:));
end
bad = find(~(abs(got(:) - want(:)) <= tol * scale), 1);
if ~isempty(bad)
    error('test:check', '%s: element %d is %.17g, expected %.17g (tolerance %g)', what, bad, ...
          got(bad), want(bad), tol);
end
end
