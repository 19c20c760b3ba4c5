% SPDX-License-Identifier: GPL-3.0-or-later
classdef fricreg_test_system < handle
    %FRICREG_TEST_SYSTEM  An object with the properties of NLvib's MechanicalSystem (SRC/
    %   MechanicalSystems/MechanicalSystem.m: n, K, M, D, nonlinear_elements, Fex1), for
    %   fricreg_nlvib_frf's test on an object rather than a struct.
    properties
        n
        K
        M
        D
        nonlinear_elements
        Fex1
    end
    methods
        function obj = fricreg_test_system(s)
            obj.n = size(s.M, 1);
            obj.K = s.K;
            obj.M = s.M;
            obj.D = s.D;
            obj.nonlinear_elements = s.nonlinear_elements;
            obj.Fex1 = s.Fex1;
        end
    end
end
