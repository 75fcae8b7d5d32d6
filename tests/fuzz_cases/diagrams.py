"""Fuzz registry: the schematics of raildyn.diagrams (one valid call each; lengths come from the models)."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn.bridge import SimplySupportedBeam
from raildyn.diagrams import BogiePlan, beam_load, wheelset_plan
from raildyn.train import DraftGear, make_consist
from raildyn.vehicles import Bogie, LateralCar, ThreePieceTruck, VerticalCar
from raildyn.vibration import SDOF
from raildyn.wheelset import Wheelset

CONSIST = make_consist("1 SD40-2 + 3 loaded hopper")
# y and ψ are signed coordinates: zero and negative are positions like any other
SIGNED = "zero negative"


def _plan():
    return wheelset_plan(Wheelset(), 0.002, 0.001, exaggerate=10.0)


def _beam():
    return beam_load(SimplySupportedBeam(), 5.0)


ENTRIES = [
    fuzz("raildyn.diagrams.oscillator_model", lambda: call(SDOF(1000.0, 2000.0, 4e5))),
    fuzz("raildyn.diagrams.rigid_body_freedoms", lambda: call(False)),
    fuzz(
        "raildyn.diagrams.wheelset_section",
        lambda: call(Wheelset(), 0.004, exaggerate=5.0),
        accepts={"y": SIGNED},
    ),
    fuzz(
        "raildyn.diagrams.wheelset_plan",
        lambda: call(Wheelset(), 0.003, 0.002, exaggerate=20.0),
        accepts={"y": SIGNED, "psi": SIGNED},
    ),
    fuzz(
        "raildyn.diagrams.WheelsetPlan",
        lambda: call(Wheelset(), 0.003, 0.002, exaggerate=20.0),
        accepts={"y": SIGNED, "psi": SIGNED},
    ),
    fuzz(
        "raildyn.diagrams.WheelsetPlan.update",
        lambda: on(_plan(), 0.001, -0.002),
        accepts={"y": SIGNED, "psi": SIGNED},
    ),
    fuzz("raildyn.diagrams.bogie_plan", lambda: call(Bogie())),
    fuzz("raildyn.diagrams.BogiePlan", lambda: call(Bogie(), exaggerate=20.0)),
    fuzz(
        "raildyn.diagrams.BogiePlan.update",
        lambda: on(BogiePlan(Bogie(), exaggerate=10.0), [0.001, 0.0005], [[0.002, 0.001], [-0.001, 0.0]]),
        accepts={"frame": SIGNED, "wheelsets": SIGNED},
    ),
    fuzz("raildyn.diagrams.car_side", lambda: call(VerticalCar())),
    fuzz(
        "raildyn.diagrams.car_plan",
        lambda: call(LateralCar(), 0.002, exaggerate=10.0),
        accepts={"psi": SIGNED},
    ),
    fuzz("raildyn.diagrams.truck_schematic", lambda: call(ThreePieceTruck())),
    # gear None is the default DraftGear()
    fuzz(
        "raildyn.diagrams.coupler_chain",
        lambda: call(CONSIST, DraftGear(), vehicles=3),
        accepts={"gear": "none"},
    ),
    # a load on a support (x = 0) is a position like any other
    fuzz(
        "raildyn.diagrams.beam_load",
        lambda: call(SimplySupportedBeam(), 6.0, sprung=True),
        accepts={"position": "zero"},
    ),
    fuzz("raildyn.diagrams.BeamLoad", lambda: call(SimplySupportedBeam(), 6.0), accepts={"position": "zero"}),
    # a deflection is signed (a beam may rise as it swings back) and may be zero (at rest)
    fuzz(
        "raildyn.diagrams.BeamLoad.update",
        lambda: on(_beam(), 12.0, deflection=0.01 * np.sin(np.pi * _beam().points / 20.0)),
        accepts={"position": "zero", "deflection": SIGNED + " none"},  # None: the static shape
    ),
]
