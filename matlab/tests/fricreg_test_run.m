% SPDX-License-Identifier: GPL-3.0-or-later
function failures = fricreg_test_run(suite, cases)
%FRICREG_TEST_RUN  Run a suite's cases: each a {name, function handle} pair that raises on a
%   failure. Prints a line per case and returns the number that failed; the gateway must hold
%   no object when the suite ends (every handle freed).
failures = 0;
started = tic;
for k = 1:size(cases, 1)
    name = cases{k, 1};
    t = tic;
    try
        cases{k, 2}();
        fprintf('PASS %s.%s (%.2f s)\n', suite, name, toc(t));
    catch err
        failures = failures + 1;
        fprintf('FAIL %s.%s: %s [%s]\n', suite, name, err.message, err.identifier);
        for s = 1:numel(err.stack)
            fprintf('     at %s line %d\n', err.stack(s).name, err.stack(s).line);
        end
    end
end
live = fricreg_mex('handles');
if live ~= 0
    failures = failures + 1;
    fprintf('FAIL %s: %d objects left in the gateway\n', suite, live);
end
fprintf('%s: %d passed, %d failed (%.2f s)\n', suite, size(cases, 1) - failures, failures, ...
        toc(started));
end
