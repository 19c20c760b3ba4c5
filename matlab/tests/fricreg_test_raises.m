% SPDX-License-Identifier: GPL-3.0-or-later
function err = fricreg_test_raises(id, fn, text)
%FRICREG_TEST_RAISES  Check that fn() raises an error with the identifier id (and, given
%   text, a message containing it); returns the error.
err = [];
try
    fn();
catch err
end
if isempty(err)
    error('test:raises', 'expected %s, but nothing was raised', id);
end
if ~strcmp(err.identifier, id)
    error('test:raises', 'expected %s, got %s: %s', id, err.identifier, err.message);
end
if nargin >= 3 && isempty(strfind(err.message, text))
    error('test:raises', 'expected "%s" in the message of %s: %s', text, id, err.message);
end
end
