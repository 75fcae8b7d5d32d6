"""Fuzz registry: the three-piece freight truck and the freight car in the lateral plane (chapters 6
and 7), and the nonlinear suspension elements of :class:`raildyn.wheelset.NonlinearLateral`."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn import vehicles as veh
from raildyn.linear_model import Assembler
from raildyn.suspension import coulomb_friction
from raildyn.wheelset import WheelRailContact


def wedge(d, v):
    """A spring of 1 MN/m beside friction wedges of 5 kN (smooth law, v_ε = 5 mm/s)."""
    return 1.0e6 * np.asarray(d) + coulomb_friction(v, 5.0e3, velocity_scale=5.0e-3)


def truck_assembler():
    labels = ["frame y", "frame ψ", "bolster ψ"] + [f"wheelset{k} {q}" for k in (1, 2) for q in "yψ"]
    return Assembler(labels, n_inputs=4)


# Friction forces and the stiffnesses that sit beside friction may be zero (no wedge, no warp spring), and
# have no plausible upper bound; the side frames' mass and the inertias a thousand times larger are still
# within the plausible ranges (PLAUSIBLE_RANGES "mass", "inertia"); the reference conditions of the
# equivalent linearisation (frequency, amplitude, angle) are any positive numbers.
TRUCK_ZEROS = {
    **{
        name: "zero mm big"
        for name in (
            "warp_stiffness",
            "nest_shear_stiffness",
            "lateral_friction",
            "warp_friction",
            "centre_plate_friction",
        )
    },
    **{name: "mm" for name in ("side_frame_mass", "side_frame_yaw_inertia", "bolster_yaw_inertia")},
    **{name: "mm big tiny" for name in ("reference_frequency", "reference_amplitude", "reference_angle")},
}

ENTRIES = [
    fuzz(
        "raildyn.wheelset.SuspensionElement",
        lambda: call({"frame y": 1.0, "wheelset1 y": -1.0}, wedge, 1.0e6, 2.0e4),
        # a law's force has either sign (it pulls a deflection of either sign back)
        accepts={"stiffness": "zero big mm", "damping": "zero big mm", "force": "returns-negative"},
    ),
    fuzz("raildyn.vehicles.ThreePieceTruck", lambda: call(), accepts=TRUCK_ZEROS),
    fuzz(
        "raildyn.vehicles.ThreePieceTruck.assemble",
        lambda: on(veh.ThreePieceTruck(), truck_assembler(), "", {}, None, 0),
        accepts={"first_input": "zero"},
    ),
    fuzz("raildyn.vehicles.ThreePieceTruck.linear_system", lambda: on(veh.ThreePieceTruck())),
    fuzz(
        "raildyn.vehicles.ThreePieceTruck.nonlinear",
        lambda: on(veh.ThreePieceTruck(), WheelRailContact(friction=0.25)),
        accepts={"contact": "none"},  # the default contact
    ),
    fuzz("raildyn.vehicles.ThreePieceTruck.replace", lambda: on(veh.ThreePieceTruck(), warp_stiffness=1.0e6)),
    fuzz(
        "raildyn.vehicles.LateralFreightCar",
        lambda: call(),
        accepts={
            "body_roll_inertia": "mm",
            "roll_stiffness": "big mm",
            "body_height": "zero",
            "roll_damping": "zero big mm",
        },
    ),
    fuzz("raildyn.vehicles.LateralFreightCar.linear_system", lambda: on(veh.LateralFreightCar())),
    fuzz(
        "raildyn.vehicles.LateralFreightCar.nonlinear",
        lambda: on(veh.LateralFreightCar(), WheelRailContact(friction=0.25)),
        accepts={"contact": "none"},  # the default contact
    ),
    fuzz(
        "raildyn.vehicles.LateralFreightCar.replace",
        lambda: on(veh.LateralFreightCar(), body_mass=100_000.0),
    ),
    fuzz("raildyn.vehicles.freight_car", lambda: call(loaded=False)),
]
