"""Fuzz registry: the bridges beyond the simple span, the design codes and the design trains (chapter 10)."""

from __future__ import annotations

from fuzzing import call, fuzz, on

from raildyn.bridge.continuous import ContinuousBeam

CONTINUOUS = ContinuousBeam((20.0, 25.0), 1.0e10, 1.0e4, modes=4)


ENTRIES = [
    fuzz(
        "raildyn.bridge.continuous.ContinuousBeam",
        lambda: call((20.0, 25.0), 1.0e10, 1.0e4, 0.02, 4),
        accepts={"damping_ratio": "zero"},
    ),
    fuzz(
        "raildyn.bridge.continuous.ContinuousBeam.mode_shapes",
        lambda: on(CONTINUOUS, [0.0, 5.0, 50.0], derivative=1),
        accepts={"x": "zero negative", "derivative": "zero"},  # off the beam: 0; derivative 0: φ
    ),
]
