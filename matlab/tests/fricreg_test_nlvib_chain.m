% SPDX-License-Identifier: GPL-3.0-or-later
function sys = fricreg_test_nlvib_chain(all_elements)
%FRICREG_TEST_NLVIB_CHAIN  NLvib's example 07 (M. Krack and J. Gross,
%   https://github.com/maltekrack/NLvib: EXAMPLES/07_multiDOFoscillator_multipleNonlinearities)
%   as the struct its
%   ChainOfOscillators(mi, di, ki, nonlinear_elements, Fex1) holds: unit masses, springs ki =
%   [1 1 1 1] ground-1-2-3-ground, dampers di = 0.02 ki, Fex1 = [0; 1; 0]; its two
%   elasticDryFriction elements (knl = 20, muN = 1, between dof 1 and the ground and between
%   dofs 1 and 2) and, given all_elements true, its cubic springs and unilateral spring too.
mi = [1 1 1];
ki = [1 1 1 1];
di = 0.02 * ki;
chain = @(k) diag(k(1:end - 1) + k(2:end)) - diag(k(2:end - 1), -1) - diag(k(2:end - 1), 1);
sys = struct('M', diag(mi), 'K', chain(ki), 'D', chain(di), 'Fex1', [0; 1; 0], 'n', 3);
knl = 20;
muN = 1;
e = {struct('type', 'elasticDryFriction', 'stiffness', knl, 'friction_limit_force', muN, ...
            'ishysteretic', true, 'force_direction', [1; 0; 0]), ...
     struct('type', 'elasticDryFriction', 'stiffness', knl, 'friction_limit_force', muN, ...
            'ishysteretic', true, 'force_direction', [-1; 1; 0])};
if nargin > 0 && all_elements
    e{3} = struct('type', 'cubicSpring', 'stiffness', 1., 'force_direction', [0; 1; 0]);
    e{4} = struct('type', 'cubicSpring', 'stiffness', 1., 'force_direction', [0; -1; 1]);
    e{5} = struct('type', 'unilateralSpring', 'stiffness', 1., 'gap', .25, ...
                  'force_direction', [0; 0; 1]);
end
sys.nonlinear_elements = e;
end
