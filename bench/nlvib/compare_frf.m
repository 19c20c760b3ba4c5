% SPDX-License-Identifier: GPL-3.0-or-later
% compare_frf.m -- NLvib's frequency response (chain_jenkins.m's CSV, REF) against fricreg's
% (fricreg-sim hb --output frf, FR, a finer branch): at each of NLvib's points inside fricreg's
% range, each dof's RMS against fricreg's interpolated linearly in Omega (both branches are
% single-valued in Omega here: checked), the largest relative difference per dof; and each
% dof's peak, NLvib's from the parabola through its largest point and neighbours, against
% fricreg's located peak PEAKS (a row omega,rms per dof from the JSON summary).
%
% octave --no-gui --quiet --eval "ref = 'nlvib.csv'; fr = 'fricreg.csv'; peaks = [...]; compare_frf"
R = csvread(ref);
F = csvread(fr, 1, 0);
F = F(:, 1:4);
F = F(all(isfinite(F), 2), :);  % drop the bifurcation rows' empty columns
if any(diff(R(:, 1)) <= 0) || any(diff(F(:, 1)) <= 0)
  error('a branch is not single-valued in Omega: interpolation does not apply');
end
in = R(:, 1) >= F(1, 1) & R(:, 1) <= F(end, 1);
for k = 1:3
  f = interp1(F(:, 1), F(:, k + 1), R(in, 1));
  rel = abs(R(in, k + 1) ./ f - 1);
  [worst, i] = max(rel);
  w = R(in, 1);
  [~, j] = max(R(:, k + 1));
  x = R(j - 1:j + 1, 1); y = R(j - 1:j + 1, k + 1);
  p = polyfit(x, y, 2);
  wpk = -p(2) / (2 * p(1)); rpk = polyval(p, wpk);
  printf(['dof %d: RMS against fricreg at %d points: largest difference %.2e (Omega %.4f), ' ...
          'median %.2e; peak NLvib %.5f at %.5f, fricreg %.5f at %.5f (%.2e, %.2e)\n'], ...
         k, nnz(in), worst, w(i), median(rel), rpk, wpk, peaks(k, 2), peaks(k, 1), ...
         rpk / peaks(k, 2) - 1, wpk / peaks(k, 1) - 1);
end
