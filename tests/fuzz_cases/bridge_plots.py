"""Fuzz registry: chapter 10's curves, drawn by one function for its figures and its widgets."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn.bridge import SimplySupportedBeam, moving_force_response


def _response():
    return moving_force_response(
        SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=3), [20.0, 40.0], 1.0e5, samples=50
    )


ENTRIES = [
    fuzz(
        "raildyn.bridge.plot_amplification",
        lambda: call([20.0, 40.0], np.array([1.05, 1.2])),
        # an amplification of zero (no deflection) is still a curve
        accepts={"amplification": "zero big mm", "alpha_speed": "big mm tiny", "speeds": "tiny"},
    ),
    fuzz(
        "raildyn.bridge.MovingForceResponse.plot",
        lambda: on(_response(), alpha_speed=78.6),
        # any speed scale > 0 draws the same curve, rescaled (2f₁L may pass 200 m/s: no speed of a
        # train); None draws it against km/h
        accepts={"alpha_speed": "big mm tiny kmh none"},
    ),
]
