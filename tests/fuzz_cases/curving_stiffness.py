"""Fuzz registry: self-steering (chapter 8): bending and shear stiffness, the closed-form steady curving of a
bogie described by them, and the trade-off between stability and curving (and its widget)."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn.curving.stiffness import BendingShear, StabilityCurving, stability_and_curving
from raildyn.vehicles import Bogie


def tradeoff() -> StabilityCurving:
    # A bogie under a still body: cheaper than the car, and the same code.
    return stability_and_curving(Bogie(), [5e6, 20e6, 60e6], 25.0, 800.0, 0.05, scan=8)


ENTRIES = [
    fuzz("raildyn.curving.stiffness.bending_shear_stiffness", lambda: call(Bogie())),
    # stiffnesses ≥ 0: a bogie with no primary yaw or lateral spring has none
    fuzz(
        "raildyn.curving.stiffness.BendingShear",
        lambda: call(31.4e6, 3.2e6),
        accepts={"bending": "big mm", "shear": "big mm", "*": "zero"},
    ),
    fuzz(
        "raildyn.curving.stiffness.self_steering_curving",
        lambda: call(Bogie(), 600.0),
        accepts={"radius": "big mm"},
    ),
    fuzz(
        "raildyn.curving.stiffness.SelfSteeringCurving",
        lambda: call(600.0, BendingShear(31.4e6, 3.2e6), np.array([4e-3, 3e-3]), np.array([1e-3, -1e-3])),
        # a result: offsets and angles of attack of either sign
        accepts={"radius": "big tiny mm", "offset": "zero negative", "angle_of_attack": "zero negative"},
    ),
    fuzz(
        "raildyn.curving.stiffness.stability_and_curving",
        lambda: call(Bogie(), [5e6, 20e6], 25.0, 800.0, 0.05, scan=8),
        # k_ψ = 0 is a bogie with no primary yaw spring; on straight track the cant may be zero
        accepts={"speed": "tiny", "radius": "big mm", "tol": "big tiny mm", "cant": "zero"},
        limit=10.0,
    ),
    fuzz(
        "raildyn.curving.stiffness.StabilityCurving",
        lambda: call(
            np.array([1e6, 2e6]),
            np.array([30.0, 40.0]),
            ("crossing", "crossing"),
            np.array([1e-3, 2e-3]),
            25.0,
            800.0,
            0.05,
            (1.0, 150.0),
        ),
        accepts={
            "speed": "tiny",
            "radius": "big tiny mm",
            "angle_of_attack": "zero negative",
            "cant": "zero big mm",
        },
    ),
    fuzz("raildyn.curving.stiffness.StabilityCurving.plot", lambda: on(tradeoff()), accepts={"ax": "none"}),
    # a widget factory takes no arguments: only the unknown keyword applies (tests/test_widgets_ch08.py
    # makes the valid call)
    fuzz("raildyn.widgets.chapter08.stiffness_tradeoff", lambda: call()),
]
