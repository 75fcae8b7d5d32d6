"""Fuzz registry: chapter 6, the rocking freight car whose wheels lift (RockingFreightCar, its runs over
jointed rail and its statics)."""

from __future__ import annotations

import functools

import numpy as np
from fuzzing import call, fuzz, on

from raildyn import vehicles as veh

CAR = veh.RockingFreightCar()
T = np.linspace(0.0, 0.5, 11)  # s, uniform


@functools.cache
def sweep():
    return veh.rocking_sweep(CAR, [7.0, 8.0], cycles=4)


def loads(value=1.0e5):
    return np.full((T.size, 2, 2), value)


# Stiffnesses and dampers of the joints have no plausible bound, only a sign: any positive value (big,
# tiny, a value in mm) is a car, and the dampers may be zero. The masses and lengths have their ranges.
JOINTS = {
    name: "big tiny mm"
    for name in (
        "centre_plate_stiffness",
        "side_bearer_stiffness",
        "plate_lateral_stiffness",
        "nest_lateral_stiffness",
        "track_stiffness",
    )
} | {"contact_damping": "zero big tiny mm", "track_damping": "zero big tiny mm"}

ENTRIES = [
    fuzz(
        "raildyn.vehicles.RockingFreightCar",
        lambda: call(),
        accepts=JOINTS
        | {
            "side_bearer_gap": "zero tiny mm",
            "velocity_scale": "tiny",
            "bolster_roll_inertia": "mm tiny big",
            "wheelset_roll_inertia": "mm tiny big",
            "bolster_mass": "mm big",
            "wheelset_mass": "mm big",
        },
    ),
    fuzz("raildyn.vehicles.RockingFreightCar.replace", lambda: on(CAR, side_bearer_gap=0.005)),
    fuzz("raildyn.vehicles.RockingFreightCar.element_names", lambda: on(CAR)),
    fuzz(
        "raildyn.vehicles.RockingFreightCar.forces",
        lambda: on(CAR, np.full(18, 1e-3), np.zeros(18)),
        accepts={"q": "zero negative tiny mm", "v": "zero negative tiny mm big", "*": "none"},
    ),
    fuzz("raildyn.vehicles.RockingFreightCar.linearized", lambda: on(CAR), accepts={"engaged": "bool"}),
    fuzz("raildyn.vehicles.RockingFreightCar.natural_frequencies", lambda: on(CAR)),
    fuzz("raildyn.vehicles.RockingFreightCar.roll_frequency", lambda: on(CAR)),
    fuzz("raildyn.vehicles.RockingFreightCar.roll_resonance_speed", lambda: on(CAR, 11.9)),
    fuzz(
        "raildyn.vehicles.RockingFreightCar.static_roll",
        lambda: on(CAR, 1.0e5),
        accepts={"roll_moment": "zero negative tiny mm", "lateral_acceleration": "zero negative tiny mm"},
        limit=20.0,
    ),
    fuzz("raildyn.vehicles.RockingFreightCar.wheel_lift_acceleration", lambda: on(CAR), limit=60.0),
    fuzz("raildyn.vehicles.RockingFreightCar.plate_lift_moment", lambda: on(CAR), limit=60.0),
    fuzz(
        "raildyn.vehicles.rocking_run",
        lambda: call(CAR, 8.0, cycles=4),
        accepts={"depth": "zero tiny mm", "dt": "none tiny", "output_step": "big"},
        limit=30.0,
    ),
    fuzz(
        "raildyn.vehicles.rocking_sweep",
        lambda: call(CAR, [7.0, 8.0], cycles=4),
        accepts={"depth": "zero tiny mm", "dt": "none tiny", "output_step": "big", "progress": "bool"},
        limit=30.0,
    ),
    fuzz(
        "raildyn.vehicles.RockingRun",
        lambda: call(
            8.0,
            11.9,
            T,
            np.full((T.size, 4, 2), 1e5),
            loads(),
            loads(0.0),
            np.zeros(T.size),
            1.6e5,
            0.4,
            0.0,
            0.1,
            0.0,
            0.01,
        ),  # fmt: skip
        accepts={"*": "zero", "roll": "zero negative", "rail_length": "big tiny mm"},
    ),
    fuzz("raildyn.vehicles.RockingRun.plot", lambda: on(sweep().runs[0]), accepts={"truck": "zero"}),
    fuzz(
        "raildyn.vehicles.RockingSweep",
        lambda: call(
            sweep().speeds, *(np.full(2, 0.5) for _ in range(4)), np.full(2, 0.01), 8.0, sweep().runs
        ),
        accepts={"*": "zero", "resonance_speed": "tiny"},
    ),
    fuzz("raildyn.vehicles.RockingSweep.plot", lambda: on(sweep()), accepts={"resonance": "bool"}),
    fuzz(
        "raildyn.vehicles.StaticRoll",
        lambda: call(
            1e5,
            0.0,
            np.zeros(18),
            np.full((4, 2), 1e5),
            np.full((4, 2), 1e5),
            np.full((2, 2), 1e5),
            np.zeros((2, 2)),
        ),  # fmt: skip
        accepts={"*": "zero negative tiny mm big"},
    ),
    fuzz("raildyn.widgets.chapter06.unloading_sweep", lambda: call(), limit=60.0),
]
