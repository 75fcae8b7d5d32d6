"""Fuzz registry: a wheel rolling on a discrete track, its inputs and its impact forces (chapters 3, 10)."""

from __future__ import annotations

import functools

import numpy as np
from fuzzing import call, fuzz, on

from raildyn.bridge.defects import DippedJoint, Roughness, WheelFlat
from raildyn.bridge.impact import wheel_on_track
from raildyn.bridge.sleepers import DiscreteTrack
from raildyn.bridge.wheels import VehicleWheels, Wheel
from raildyn.vehicles import VerticalCar

SMALL = DiscreteTrack(bays=8, quiet_bays=2)  # runs between x = 1.65 and 2.75 m
JOINT = DippedJoint(2.2, (0.004, 0.004), 0.3)


@functools.cache  # one run serves every bad value of the three entries built from it (it is not changed)
def _run():
    return wheel_on_track(Wheel(), 10.0, JOINT, track=SMALL, start=1.9, distance=0.5, record_every=4)


def _block_fields():
    block = Wheel(sprung_mass=4000.0, primary_stiffness=1.2e6).block()
    names = ("mass", "damping", "stiffness", "contact_dofs", "static_loads", "offsets", "hertz_constants")
    return [getattr(block, name) for name in names]


def _psd(w):
    return 1e-13 * (w / 10.0) ** -2.0


ENTRIES = [
    fuzz(
        "raildyn.bridge.defects.DippedJoint",
        lambda: call(2.2, (0.004, 0.004), 0.3),
        accepts={"position": "zero negative big mm tiny", "angles": "list"},
    ),
    fuzz(
        "raildyn.bridge.defects.DippedJoint.profile",
        lambda: on(JOINT, np.linspace(1.0, 3.0, 5)),
        accepts={"x": "zero negative shape big mm tiny list huge"},
    ),
    fuzz(
        "raildyn.bridge.defects.WheelFlat",
        lambda: call(0.001, 0.46, 1.0),
        accepts={"first": "zero negative big mm tiny", "depth": "tiny"},
    ),
    fuzz(
        "raildyn.bridge.defects.WheelFlat.profile",
        lambda: on(WheelFlat(0.001), np.linspace(0.0, 3.0, 5)),
        accepts={"x": "zero negative shape big mm tiny list huge"},
    ),
    fuzz(
        "raildyn.bridge.defects.Roughness",
        lambda: call(np.linspace(0.0, 1.0, 5), np.full(5, 1e-6)),
        accepts={"x": "big tiny mm list", "r": "zero negative tiny mm list"},
    ),
    fuzz(
        "raildyn.bridge.defects.Roughness.profile",
        lambda: on(Roughness(np.linspace(0.0, 1.0, 5), np.full(5, 1e-6)), np.linspace(-1.0, 2.0, 4)),
        accepts={"x": "zero negative shape big mm tiny list huge"},
    ),
    fuzz(
        "raildyn.bridge.wheels.Wheel",
        lambda: call(900.0, 60e3, 4000.0, 1.2e6, 4e3, 0.46, 0.3),
        accepts={
            "unsprung_mass": "big mm",
            "static_load": "big mm",
            "sprung_mass": "zero tiny mm",
            "primary_stiffness": "big mm tiny",
            "primary_damping": "zero big mm tiny",
            "rail_head_radius": "big mm",
        },
    ),
    fuzz("raildyn.bridge.wheels.Wheel.block", lambda: on(Wheel())),
    fuzz(
        "raildyn.bridge.wheels.VehicleWheels",
        lambda: call(VerticalCar(), 1813.0, 0.46, 0.3),
        accepts={"wheelset_mass": "big mm", "rail_head_radius": "big mm"},
    ),
    fuzz("raildyn.bridge.wheels.VehicleWheels.block", lambda: on(VehicleWheels(VerticalCar()))),
    fuzz(
        "raildyn.bridge.wheels.WheelBlock",
        lambda: call(*_block_fields()),
        accepts={
            "*": "big tiny mm",
            "contact_dofs": "zero",  # one wheel: its coordinate 0 is as good as 1
            "offsets": "zero",  # one wheel: its offset is 0
            "damping": "zero negative big tiny mm huge",
            "stiffness": "zero negative big tiny mm huge",
        },
    ),
    fuzz(
        "raildyn.bridge.wheels.Wheel.receptance",
        lambda: on(Wheel(), [10.0, 100.0]),
        accepts={"frequencies": "big mm tiny list"},
    ),
    fuzz(
        "raildyn.bridge.impact.wheel_on_track",
        lambda: call(Wheel(), 10.0, JOINT, track=SMALL, distance=0.2, record_every=4),
        accepts={
            "irregularity": "none",
            "track": "none",
            "start": "none",
            "distance": "none tiny",
            "standing": "zero",
        },
    ),
    fuzz(
        "raildyn.bridge.impact.WheelOnTrack",
        lambda: call(*[getattr(_run(), f) for f in _run().__dataclass_fields__]),
        accepts={"*": "zero negative big mm tiny"},
    ),
    fuzz("raildyn.bridge.impact.WheelOnTrack.peaks", lambda: on(_run(), 2.2), accepts={"wheel": "zero"}),
    fuzz(
        "raildyn.bridge.impact.WheelOnTrack.plot",
        lambda: on(_run(), position=2.2),
        accepts={"position": "none", "wheel": "zero"},
    ),
    fuzz(
        "raildyn.bridge.impact.contact_force_spectrum",
        lambda: call(Wheel(), 20.0, _psd, [50.0, 200.0], track=SMALL),
        accepts={"speed": "tiny", "track": "none", "position": "none", "frequencies": "big mm tiny list"},
    ),
    fuzz(
        "raildyn.bridge.impact.jenkins_p2",
        lambda: call(Wheel(), 20.0, 0.01, 300.0, 60e6, 1e5),
        accepts={
            "speed": "tiny",
            "total_angle": "tiny",
            "track_damping": "zero tiny mm big",
            "track_mass": "big mm tiny",
            "track_stiffness": "big mm tiny",
        },
    ),
    fuzz(
        "raildyn.bridge.impact.lumped_track",
        lambda: call(SMALL, 2.2, (5.0, 60.0)),
        accepts={"position": "none tiny zero", "band": "list"},
    ),
    fuzz(
        "raildyn.bridge.impact.contact_compliance",
        lambda: call(Wheel(), [50.0, 200.0], track=SMALL),
        accepts={"track": "none", "position": "none", "frequencies": "big mm tiny list"},
    ),
]
