"""Fuzz registry: the batched critical-speed search (:mod:`raildyn.stability.search`) and the affine model
family of :mod:`raildyn.linear_model` that feeds it."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn.linear_model import AffineFamily
from raildyn.stability import StateMatrices
from raildyn.wheelset import Wheelset


def _wheelset(lam, k):
    return Wheelset(conicity=lam, yaw_stiffness=k, lateral_stiffness=1.0e6)


def family() -> AffineFamily:
    return AffineFamily(_wheelset, (0.05, 1.0e6), (0.4, 5.0e6))


def _matrices():
    system = _wheelset(0.1, 2.0e6).linear_system()
    return system.M, system.K, system.C0, system.C1


def stack() -> StateMatrices:
    return StateMatrices(**family().stacks([(0.1, 2.0e6), (0.2, 3.0e6)]))


ENTRIES = [
    fuzz(
        "raildyn.stability.StateMatrices",
        lambda: call(*_matrices()),
        # K, C₀ and C₁ hold creep, damper and gravity terms of either sign; an extra axis makes a stack
        # of one system, as documented
        accepts={
            "M": "shape",
            "K": "zero negative shape",
            "C0": "zero negative shape",
            "C1": "zero negative shape",
        },
    ),
    fuzz("raildyn.stability.StateMatrices.of", lambda: call(_wheelset(0.1, 2.0e6))),
    fuzz(
        "raildyn.stability.StateMatrices.state_matrices",
        lambda: on(stack(), [20.0, 30.0], which=[0, 1]),
        accepts={"which": "zero", "speeds": "tiny"},  # system 0 for both; any speed > 0
    ),
    fuzz(
        "raildyn.stability.StateMatrices.largest_real_part",
        lambda: on(stack(), [20.0, 30.0], which=[0, 1]),
        accepts={"which": "zero", "speeds": "tiny"},
    ),
    fuzz(
        "raildyn.stability.CriticalSpeeds",
        lambda: call(np.array([40.0, 50.0]), ("crossing", "crossing")),
        accepts={"speeds": "big tiny mm"},
    ),
    fuzz(
        "raildyn.stability.critical_speeds",
        lambda: call(stack(), (1.0, 150.0), tol=0.05, scan=16),
        accepts={"tol": "big tiny mm"},  # any tolerance > 0: a large one is a coarse answer
        infinite=("speeds",),  # inf: stable over the range, the documented answer
    ),
    fuzz(
        "raildyn.linear_model.AffineFamily",
        lambda: call(_wheelset, (0.05, 1.0e6), (0.4, 5.0e6)),
        # a cylinder without a yaw spring (λ = 0, k_ψ = 0) is a wheelset too
        accepts={"origin": "zero", "far": "zero"},
    ),
    fuzz("raildyn.linear_model.AffineFamily.constant", lambda: on(family(), "M")),
    fuzz(
        "raildyn.linear_model.AffineFamily.stacks",
        lambda: on(family(), [(0.1, 2.0e6), (0.2, 3.0e6)]),
        # an affine family is exact anywhere on its plane: K holds creep and spring terms of either sign
        accepts={"points": "zero negative mm"},
    ),
]
