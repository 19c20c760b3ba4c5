% SPDX-License-Identifier: GPL-3.0-or-later
function f = fricreg_law_eval(varargin)
%FRICREG_LAW_EVAL  The friction force of one friction law at many contacts.
%   F = FRICREG_LAW_EVAL(LAW, V, F_EQ, MUN, EPS) evaluates the law LAW at every element of
%   the arrays V, F_EQ and MUN, in one call of the C library.
%
%   LAW   the law's name, a char row vector: 'coulomb' (1), 'force-balance' (2),
%         'karnopp', 'velocity-limited' (3), 'tanh' or 'quinn' (4); or its code 1..6
%         (in that order; fricreg_mex('law_names') lists them).
%   V     relative contact velocities (velocity units), a real double array of any size.
%   F_EQ  equilibrium forces (force units): the force that keeps each contact at rest. []
%         for the laws that do not read it (coulomb, velocity-limited, tanh).
%   MUN   friction bounds mu*N >= 0 (force units).
%   EPS   the regularization, a scalar >= realmin (velocity units); checked though
%         coulomb and force-balance ignore it.
%
%   V, F_EQ and MUN are arrays of one size, or scalars (expanded to it). F has that size,
%   |F| <= MUN elementwise.
%
%   The laws (D. D. Quinn, "A New Regularization of Coulomb Friction", J. Vib. Acoust. 126
%   (2004) 391-397, eqs. (1)-(4) and Sec. 2), sat(y) = max(-1, min(1, y)):
%      coulomb           F = -MUN sign(V)
%      force-balance     V == 0: F = MUN sat(F_EQ/MUN); else coulomb
%      karnopp           |V| < EPS: F = MUN sat(F_EQ/MUN); else coulomb
%      velocity-limited  |V| < EPS: F = -(MUN/EPS) V; else coulomb
%      tanh              F = -MUN tanh(V/EPS)
%      quinn             xi = (EPS/2) sat(F_EQ/MUN); |V - xi| < EPS/2: F = -(2 MUN/EPS)(V - xi);
%                        else F = -MUN sign(V - xi). Continuous in V and F_EQ, and equal to
%                        the force balance at V = 0.
%
%   Errors (identifiers):
%      fricreg:nargs       not five arguments, or more than one output
%      fricreg:type        an array not a real, full double (complex, sparse, single,
%                          integer, logical ...); LAW neither a name nor a number
%      fricreg:size        V, F_EQ and MUN of different sizes (and not scalars); EPS not a
%                          scalar
%      fricreg:EINVAL      LAW names no law; a bound MUN < 0; EPS < realmin
%      fricreg:ENULL       F_EQ is [] for a law that reads it
%      fricreg:ENONFINITE  an input is NaN or infinite (the message names which)
%
%   Source: fricreg_law_eval_batch (include/fricreg.h), through the gateway fricreg_mex
%   (matlab/fricreg_mex.c); the arrays are passed to it as they lie (no copy). Python:
%   fricreg.law_eval.
%
%   Example:
%      f = fricreg_law_eval('quinn', [0 0.0213 -0.015], 1.137, 2.385, 0.0731)
%      % f = [1.137 -0.252890560875513 2.115796169630643]
%
%   See also FRICREG_ELEMENT_EVAL, FRICREG_VERSION.
f = fricreg_mex('law_eval', varargin{:});
end
