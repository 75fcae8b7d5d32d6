"""Fuzz registry: the three-piece freight truck and the freight car in the lateral plane (chapters 6
and 7), and the nonlinear suspension elements of :class:`raildyn.wheelset.NonlinearLateral`."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz

from raildyn.suspension import coulomb_friction


def wedge(d, v):
    """A spring of 1 MN/m beside friction wedges of 5 kN (smooth law, v_ε = 5 mm/s)."""
    return 1.0e6 * np.asarray(d) + coulomb_friction(v, 5.0e3, velocity_scale=5.0e-3)


ENTRIES = [
    fuzz(
        "raildyn.wheelset.SuspensionElement",
        lambda: call({"frame y": 1.0, "wheelset1 y": -1.0}, wedge, 1.0e6, 2.0e4),
        # a law's force has either sign (it pulls a deflection of either sign back)
        accepts={"stiffness": "zero", "damping": "zero", "force": "returns-negative"},
    ),
]
