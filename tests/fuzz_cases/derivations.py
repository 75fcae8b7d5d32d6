"""Fuzz registry: the symbolic derivations' shape and chapter 1's derivations (raildyn.derivations)."""

from __future__ import annotations

import numpy as np
import sympy
from fuzzing import call, fuzz, on

from raildyn import derivations
from raildyn.vibration import SDOF

OSC = SDOF(1000.0, 2000.0, 4e5)
SDOF_DERIVED = derivations.sdof()
MATRICES = ([[1000.0]], [[2000.0]], [[4e5]], [[4e5]], [[2000.0]])
M, K = sympy.symbols("m k", positive=True)
(X,) = derivations.coordinates("x")
XD = X.diff(derivations.time)
STEP = derivations.Step("kinetic energy", sympy.Eq(sympy.Symbol("T"), M * XD**2 / 2))

ENTRIES = [
    fuzz("raildyn.derivations.coordinates", lambda: call("y psi"), accepts={"names": "unknown"}),  # any name
    fuzz(
        "raildyn.derivations.Step",
        lambda: call("kinetic energy", sympy.Eq(sympy.Symbol("T"), M)),
        accepts={"caption": "unknown"},
    ),
    fuzz(
        "raildyn.derivations.lagrange",
        lambda: call(M * XD**2 / 2, K * X**2 / 2, 0, [X], forces=None, inputs=()),
        # a number is a constant energy: it drops out of the equations, as it should
        accepts={"kinetic": "type", "potential": "type", "dissipation": "zero negative huge fraction type"},
    ),
    fuzz("raildyn.derivations.generalized_forces", lambda: call([(M, X)], [X])),
    fuzz(
        "raildyn.derivations.Derivation",
        lambda: call(
            "oscillator",
            (X,),
            sympy.Matrix([[M]]),
            sympy.zeros(1, 1),
            sympy.Matrix([[K]]),
            sympy.zeros(1, 0),
            sympy.zeros(1, 0),
            inputs=(),
            parameters=((M, "mass"), (K, "stiffness")),
            speed=None,
            steps=(STEP,),
        ),  # fmt: skip
        accepts={"title": "unknown"},
    ),
    fuzz("raildyn.derivations.Derivation.equations", lambda: on(SDOF_DERIVED)),
    fuzz("raildyn.derivations.Derivation.values", lambda: on(SDOF_DERIVED, OSC)),
    fuzz("raildyn.derivations.Derivation.numeric", lambda: on(SDOF_DERIVED, OSC, None)),
    fuzz(
        "raildyn.derivations.Derivation.difference",
        lambda: on(SDOF_DERIVED, MATRICES, OSC, None),
        accepts={"matrices": "zero negative huge"},  # any numbers compare (a difference comes out)
    ),
    fuzz("raildyn.derivations.sdof", lambda: call()),
    fuzz("raildyn.derivations.chain", lambda: call(3, grounded=True), limit=20.0),
]
_ = np  # numpy arrays are what the fuzzer makes of lists
