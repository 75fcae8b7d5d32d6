"""Fuzz registry: the bridge of chapter 10."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn.bridge import (
    AxleSequence,
    MovingForceResponse,
    SimplySupportedBeam,
    crossing,
    moving_force_response,
    moving_mass,
    sprung_mass,
)
from raildyn.vehicles import VerticalCar

BEAM = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=5)


def response() -> MovingForceResponse:
    return moving_force_response(BEAM, [20.0, 40.0], 1.0e5, samples=50)


ENTRIES = [
    fuzz(
        "raildyn.bridge.SimplySupportedBeam",
        lambda: call(20.0, 1.0e10, 1.0e4, 0.02, 5),
        accepts={"flexural_rigidity": "big mm", "damping_ratio": "zero"},
    ),  # fmt: skip
    fuzz(
        "raildyn.bridge.SimplySupportedBeam.static_midspan_deflection",
        lambda: on(BEAM, 1.0e5),
        accepts={"force": "zero negative big mm"},
    ),  # fmt: skip
    fuzz(
        "raildyn.bridge.SimplySupportedBeam.mode_shapes",
        lambda: on(BEAM, [0.0, 5.0, 25.0], derivative=1),
        accepts={"x": "zero negative list", "derivative": "zero"},  # off the span: 0; derivative 0: φ
    ),
    fuzz(
        "raildyn.bridge.AxleSequence",
        lambda: call([0.0, 2.5, 17.5, 20.0], [1.7e5] * 4, "coach"),
        accepts={"positions": "zero", "name": "empty"},  # one axle, or all at 0: a single point load
    ),
    fuzz(
        "raildyn.bridge.moving_force_response",
        lambda: call(BEAM, [20.0, 40.0], 1.0e5, position=5.0, samples=50),
        accepts={"force": "zero negative big mm", "position": "zero none", "speeds": "list"},  # None: midspan
    ),
    fuzz(
        "raildyn.bridge.MovingForceResponse",
        lambda: call(
            np.array([20.0]), np.linspace(0, 1, 5)[None], np.ones((1, 5)), 10.0, 1e-3, np.ones((1, 5))
        ),
        accepts={
            "acceleration": "zero negative none",  # None: not computed
            "deflection": "zero negative",
            "time": "zero negative",
            "position": "zero big mm",
            "static": "zero negative big mm",
        },  # fmt: skip
    ),
    fuzz(
        "raildyn.bridge.fryba_deflection",
        lambda: call(BEAM, 30.0, 1.0e5, [0.0, 0.2, 0.5], position=5.0),
        accepts={
            "speed": "tiny",
            "force": "zero negative big mm",
            "position": "zero none",
            "time": "zero list",
        },  # None: midspan
    ),
]

# -- raildyn.bridge.loads and raildyn.bridge.coupled ---------------------------------------------------------

SHORT = SimplySupportedBeam(10.0, 1.0e9, 1.0e4, modes=2)  # a short, light span: a crossing of ~10 ms
PAIR = AxleSequence([0.0, 3.0], [1.0e5, 1.0e5])

ENTRIES += [
    fuzz(
        "raildyn.bridge.MovingLoad",
        lambda: call([0.0, 3.0], [1.0e5, 1.0e5], [100.0, 100.0], None, "pair"),
        accepts={"positions": "zero", "unsprung_masses": "zero", "system": "none", "name": "empty"},
    ),
    fuzz("raildyn.bridge.moving_load", lambda: call(PAIR)),
    fuzz("raildyn.bridge.moving_mass", lambda: call(1000.0), accepts={"mass": "mm"}),
    fuzz(
        "raildyn.bridge.sprung_mass",
        lambda: call(5000.0, 1.0e6, 1.0e3, 500.0),
        accepts={"stiffness": "big tiny mm", "damping": "zero big mm", "unsprung_mass": "zero mm"},
    ),
    fuzz("raildyn.bridge.vehicle", lambda: call(VerticalCar(), 1813.0), accepts={"wheelset_mass": "zero"}),
    fuzz(
        "raildyn.bridge.train",
        lambda: call([moving_mass(1000.0), sprung_mass(5000.0, 1.0e6)], [5.0]),
        accepts={"gaps": "zero list"},
    ),
    fuzz(
        "raildyn.bridge.crossing",
        lambda: call(SHORT, PAIR, 40.0, at=3.0, time_step=1e-3, free_time=0.05),
        accepts={
            "at": "zero none",  # None: the middle of the first span
            "time_step": "none",
            "free_time": "zero none mm",
            "irregularity": "none",
        },
    ),
    fuzz(
        "raildyn.bridge.BridgeCrossing",
        lambda: call(
            30.0,
            5.0,
            np.linspace(0.0, 1.0, 4),
            np.ones(4),
            np.ones(4),
            np.ones(4),
            np.ones(4),
            np.ones((4, 2)),
            np.ones((4, 2, 3)),
            np.ones((4, 3, 1)),
            ("body z",),
        ),  # fmt: skip
        accepts={
            "speed": "tiny",
            **{name: "zero negative" for name in ("deflection", "static_deflection", "moment")},
            **{name: "zero negative" for name in ("deck_acceleration", "contact_forces", "modal", "vehicle")},
            "at": "zero negative big mm",  # a point of the beam; the crossing checks it lies on the beam
            "time": "zero negative",
        },
    ),
    fuzz("raildyn.bridge.BridgeCrossing.plot", lambda: on(crossing(SHORT, PAIR, 40.0, time_step=1e-3))),
    fuzz(
        "raildyn.bridge.BridgeCrossing.vehicle_acceleration",
        lambda: on(crossing(SHORT, sprung_mass(5000.0, 1.0e6), 40.0, time_step=1e-3), "body z"),
    ),
]
