"""Fuzz registry: chapters 6 and 7, the six-axle locomotive in the lateral plane (three-axle truck,
locomotive, the rigid truck's kinematic wavelength)."""

from __future__ import annotations

from fuzzing import call, fuzz, on

from raildyn import vehicles as veh
from raildyn.linear_model import Assembler
from raildyn.wheelset import WheelRailContact


def truck_assembler():
    labels = ["frame y", "frame ψ"] + [f"wheelset{k} {q}" for k in (1, 2, 3) for q in "yψ"]
    return Assembler(labels, n_inputs=6)


ENTRIES = [
    fuzz(
        "raildyn.vehicles.ThreeAxleTruck",
        lambda: call(),
        accepts={
            "frame_yaw_inertia": "mm",
            "motor_mass": "zero",
            "motor_axle_share": "zero",
            "middle_lateral_stiffness": "zero big mm",
            "middle_lateral_damping": "zero big mm",
            "middle_lateral_play": "zero big mm",
            "secondary_lateral_stiffness": "zero big mm",
            "secondary_lateral_damping": "zero big mm",
            "secondary_yaw_stiffness": "zero big mm",
            "secondary_yaw_damping": "zero big",
        },
    ),
    fuzz(
        "raildyn.vehicles.ThreeAxleTruck.assemble",
        lambda: on(veh.ThreeAxleTruck(), truck_assembler(), "", {}, None, 0),
        accepts={"first_input": "zero"},
    ),
    fuzz("raildyn.vehicles.ThreeAxleTruck.linear_system", lambda: on(veh.ThreeAxleTruck())),
    fuzz("raildyn.vehicles.ThreeAxleTruck.replace", lambda: on(veh.ThreeAxleTruck(), frame_mass=2500.0)),
    fuzz("raildyn.vehicles.ThreeAxleTruck.without_play", lambda: on(veh.ThreeAxleTruck())),
    fuzz("raildyn.vehicles.ThreeAxleTruck.play_element", lambda: on(veh.ThreeAxleTruck(), "1")),
    fuzz(
        "raildyn.vehicles.ThreeAxleTruck.nonlinear",
        lambda: on(veh.ThreeAxleTruck(), WheelRailContact(friction=0.25)),
        accepts={"contact": "none"},  # the default contact
    ),
    fuzz(
        "raildyn.vehicles.LateralLocomotive.nonlinear",
        lambda: on(veh.LateralLocomotive(), WheelRailContact(friction=0.25)),
        accepts={"contact": "none"},  # the default contact
    ),
    fuzz(
        "raildyn.vehicles.LateralLocomotive",
        lambda: call(),
        accepts={
            "body_roll_inertia": "mm",
            "roll_stiffness": "big mm",
            "body_height": "zero",
            "roll_damping": "zero big mm",
        },
    ),
    fuzz("raildyn.vehicles.LateralLocomotive.linear_system", lambda: on(veh.LateralLocomotive())),
    fuzz(
        "raildyn.vehicles.LateralLocomotive.replace",
        lambda: on(veh.LateralLocomotive(), body_mass=120_000.0),
    ),
    fuzz("raildyn.vehicles.LateralLocomotive.without_play", lambda: on(veh.LateralLocomotive())),
    fuzz(
        "raildyn.vehicles.rigid_truck_wavelength",
        lambda: call(0.508, 0.75, 0.05, 2.07),
        accepts={"conicity": "tiny"},
    ),
]
