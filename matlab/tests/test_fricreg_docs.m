% SPDX-License-Identifier: GPL-3.0-or-later
function failures = test_fricreg_docs()
%TEST_FRICREG_DOCS  The examples of docs/matlab.md run as printed: each ```matlab block, in a
%   workspace of its own, checks its own numbers with assert.
here = fileparts(mfilename('fullpath'));
text = fileread(fullfile(here, '..', '..', 'docs', 'matlab.md'));
lines = strsplit(text, sprintf('\n'));
blocks = {};
block = {};
inside = false;
for k = 1:numel(lines)
    line = lines{k};
    if ~inside && strcmp(line, '```matlab')
        inside = true;
        block = {};
    elseif inside && strcmp(line, '```')
        inside = false;
        blocks{end + 1} = strjoin(block, sprintf('\n')); %#ok<AGROW>
    elseif inside
        block{end + 1} = line; %#ok<AGROW>
    end
end
if numel(blocks) < 4
    error('test:docs', 'docs/matlab.md has %d matlab blocks', numel(blocks));
end
cases = cell(numel(blocks), 2);
for k = 1:numel(blocks)
    cases{k, 1} = sprintf('block_%d', k);
    cases{k, 2} = @() run_block(blocks{k});
end
failures = fricreg_test_run('docs', cases);
end

function run_block(code)
eval(code);
end
