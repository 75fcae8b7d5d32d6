"""Fuzz registry: chapter 6, vehicle models (lateral Bogie/LateralCar, VerticalCar, VerticalLocomotive,
VerticalFreightCar) and their response to the track (FRFs, spectra, time histories, rock and roll)."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn import track
from raildyn import vehicles as veh
from raildyn.linear_model import Assembler
from raildyn.vehicles import vertical

OMEGA = np.linspace(1.0, 60.0, 12)  # rad/s
T = np.linspace(0.0, 0.5, 26)  # s, uniform
Z = 0.01 * np.sin(2 * np.pi * np.arange(16) / 16)  # one period of a track profile, m


def spatial_psd(Omega):
    """A small one-sided spatial track spectrum, m²/(rad/m)."""
    return 1e-7 / (0.01 + np.asarray(Omega) ** 2)


def sine_track(x, rails):
    """A sinusoidal track profile, m (negative heights are valid)."""
    return 0.005 * np.sin(2 * np.pi * x / 20.0)


def sine_slope(x, rails):
    """Its slope dz/dx."""
    return 0.005 * 2 * np.pi / 20.0 * np.cos(2 * np.pi * x / 20.0)


def bogie_assembler():
    labels = ["frame y", "frame ψ", "wheelset1 y", "wheelset1 ψ", "wheelset2 y", "wheelset2 ψ"]
    return Assembler(labels, n_inputs=4)


def spectrum():
    return veh.response_spectrum(veh.VerticalCar(), spatial_psd, 30.0, OMEGA, component="vertical")


def rocking():
    return veh.rock_and_roll(veh.VerticalFreightCar(), [25.0, 30.0], cycles=4)


# Result dataclasses hold what a model computes: their own domains (a frequency ≥ 0, a PSD ≥ 0, a
# response of either sign) are stated in their docstrings and declared here field by field.

# A body on two trucks (the vertical car's and the locomotive's): a truck's pitch inertia a thousand
# times larger is still an inertia; springs and dampers have no plausible bound.
BODY_ON_TRUCKS = {
    "truck_pitch_inertia": "mm",
    "primary_stiffness": "big tiny mm",
    "secondary_stiffness": "big tiny mm",
    "primary_damping": "zero big mm",
    "secondary_damping": "zero big mm",
}

ENTRIES = [
    # ------------------------------------------------------------------ lateral models
    fuzz(
        "raildyn.vehicles.Bogie",
        lambda: call(),
        accepts={
            "frame_yaw_inertia": "mm",
            "secondary_lateral_stiffness": "zero big mm",
            "secondary_lateral_damping": "zero big mm",
            "secondary_yaw_stiffness": "zero big mm",
            "secondary_yaw_damping": "zero big",
        },
    ),
    fuzz(
        "raildyn.vehicles.Bogie.assemble",
        lambda: on(veh.Bogie(), bogie_assembler(), "", {}, None, 0),
        accepts={"first_input": "zero"},
    ),
    fuzz("raildyn.vehicles.Bogie.linear_system", lambda: on(veh.Bogie())),
    fuzz("raildyn.vehicles.Bogie.replace", lambda: on(veh.Bogie(), frame_mass=2000.0)),
    fuzz(
        "raildyn.vehicles.LateralCar",
        lambda: call(),
        accepts={
            "body_roll_inertia": "mm",
            "roll_stiffness": "big mm",
            "body_height": "zero",
            "roll_damping": "zero big mm",
        },
    ),
    fuzz("raildyn.vehicles.LateralCar.linear_system", lambda: on(veh.LateralCar())),
    fuzz("raildyn.vehicles.LateralCar.replace", lambda: on(veh.LateralCar(), body_mass=30000.0)),
    fuzz("raildyn.vehicles.cooperrider_car", lambda: call()),
    # ------------------------------------------------------------------ vertical models
    fuzz(
        "raildyn.vehicles.VerticalCar",
        lambda: call(),
        accepts={
            "bogie_pitch_inertia": "mm",
            "primary_stiffness": "big tiny mm",
            "secondary_stiffness": "big tiny mm",
            "primary_damping": "zero big mm",
            "secondary_damping": "zero big mm",
        },
    ),
    fuzz("raildyn.vehicles.VerticalCar.linear_system", lambda: on(veh.VerticalCar())),
    fuzz("raildyn.vehicles.VerticalCar.body_frequencies", lambda: on(veh.VerticalCar())),
    fuzz(
        "raildyn.vehicles.BodyFrequencies",
        lambda: call(1.0, 2.0, 0.5),
        accepts={
            "bounce_hz": "zero big mm",
            "pitch_hz": "zero big mm",
            "roll_hz": "zero none big mm",
        },  # None: no roll coordinate
    ),
    fuzz(
        "raildyn.vehicles.vertical.body_on_two_trucks",
        lambda: call(
            vertical.LABELS,
            32000.0,
            1.97e6,
            2615.0,
            1476.0,
            9.5,
            (1.28, -1.28),
            2.44e6,
            8.0e3,
            8.6e5,
            4.0e4,
            np.array([0.0, 2.56, 19.0, 21.56]),
        ),  # fmt: skip
        accepts=BODY_ON_TRUCKS,
    ),
    fuzz(
        "raildyn.vehicles.VerticalLocomotive",
        lambda: call(),
        accepts=BODY_ON_TRUCKS,
    ),
    fuzz("raildyn.vehicles.VerticalLocomotive.linear_system", lambda: on(veh.VerticalLocomotive())),
    # ------------------------------------------------------------------ freight car
    fuzz(
        "raildyn.vehicles.VerticalFreightCar",
        lambda: call(),
        accepts={
            "body_roll_inertia": "mm",
            "nest_stiffness": "big mm",
            "cg_height": "zero",
            "wedge_friction": "zero big mm",
            "equivalent_damping": "zero big",
        },
    ),
    fuzz("raildyn.vehicles.VerticalFreightCar.linear_system", lambda: on(veh.VerticalFreightCar())),
    fuzz("raildyn.vehicles.VerticalFreightCar.natural_frequencies", lambda: on(veh.VerticalFreightCar())),
    fuzz("raildyn.vehicles.VerticalFreightCar.nests", lambda: on(veh.VerticalFreightCar())),
    fuzz("raildyn.vehicles.VerticalFreightCar.roll_input_factor", lambda: on(veh.VerticalFreightCar(), 11.9)),
    fuzz(
        "raildyn.vehicles.VerticalFreightCar.roll_resonance_speed", lambda: on(veh.VerticalFreightCar(), 11.9)
    ),
    fuzz("raildyn.vehicles.gdu_ore_car", lambda: call()),
    fuzz(
        "raildyn.vehicles.rock_and_roll",
        lambda: call(veh.VerticalFreightCar(), [25.0, 30.0], cycles=4),
        accepts={"depth": "zero"},
    ),
    fuzz(
        "raildyn.vehicles.RockAndRoll",
        lambda: call(np.array([25.0, 30.0]), np.array([0.01, 0.02]), 20.0, T, np.zeros((2, T.size))),
        accepts={"resonance_speed": "tiny", "roll_amplitude": "zero", "roll": "zero negative"},
    ),
    fuzz("raildyn.vehicles.RockAndRoll.plot", lambda: on(rocking())),
    fuzz(
        "raildyn.vehicles.wedge_energy_per_cycle",
        lambda: call(6000.0, 0.01, 2.0, velocity_scale=0.002),
        accepts={
            "amplitude": "big tiny mm",
            "frequency": "big tiny mm",
            "friction_force": "zero big mm",
            "velocity_scale": "none",
        },  # None: the ideal Coulomb law
    ),
    fuzz(
        "raildyn.vehicles.wedge_friction_force",
        lambda: call(16000.0, 0.65, 0.1),
        accepts={"spring_force": "zero big mm", "friction_coefficient": "zero"},
    ),
    fuzz(
        "raildyn.vehicles.WedgeFriction",
        lambda: call(4900.0, 3800.0),
        accepts={"bolster_down": "zero big mm", "bolster_up": "zero big mm"},
    ),
    # ------------------------------------------------------------------ response to the track
    fuzz(
        "raildyn.vehicles.track_frf",
        lambda: call(veh.VerticalCar(), OMEGA, 30.0),
        accepts={"omega": "zero", "derivative": "zero"},
    ),
    # A spectrum must say what it describes: a plain callable with component= (component None: the
    # refusal of an unstated component, "unknown" and "type": of a name that is no component) ...
    fuzz(
        "raildyn.vehicles.response_spectrum",
        lambda: call(veh.VerticalCar(), spatial_psd, 30.0, OMEGA, component="vertical"),
        accepts={"derivative": "zero"},
    ),
    # ... or a TrackSpectrum, which names its own (component "abc": refused by name, not taken for it).
    fuzz(
        "raildyn.vehicles.rms_over_speeds",
        lambda: call(veh.VerticalCar(), track.track_psd("german", "vertical", "low"), [20.0, 30.0], OMEGA),
        accepts={"derivative": "zero"},
    ),
    fuzz(
        "raildyn.vehicles.ResponseSpectrum",
        lambda: call(OMEGA, np.full(OMEGA.size, 1e-3), 0.05, 30.0),
        accepts={"psd": "zero", "rms": "zero big mm"},
    ),
    fuzz("raildyn.vehicles.ResponseSpectrum.plot", lambda: on(spectrum())),
    fuzz(
        "raildyn.vehicles.time_response",
        lambda: call(veh.VerticalCar(), sine_track, 30.0, T, profile_rate=sine_slope),
        accepts={
            "derivative": "zero",
            "profile": "returns-negative",
            "profile_rate": "returns-negative",
        },
    ),
    fuzz(
        "raildyn.vehicles.TimeResponse",
        lambda: call(T, np.zeros(T.size), np.zeros((T.size, 4))),
        accepts={"y": "zero negative", "inputs": "zero negative"},
    ),
    fuzz(
        "raildyn.vehicles.periodic_profile",
        lambda: call(Z, 0.5),
        accepts={"dx": "big tiny mm", "height": "zero negative"},
    ),
    fuzz(
        "raildyn.vehicles.PeriodicProfile",
        lambda: call(Z, 0.5),
        accepts={"dx": "big tiny mm", "heights": "zero negative"},
    ),
    fuzz(
        "raildyn.vehicles.PeriodicProfile.height",
        lambda: on(veh.periodic_profile(Z, 0.5), np.array([0.0, 1.0, 2.5])),
        accepts={"x": "zero negative shape"},
    ),
    fuzz(
        "raildyn.vehicles.PeriodicProfile.slope",
        lambda: on(veh.periodic_profile(Z, 0.5), np.array([0.0, 1.0, 2.5])),
        accepts={"x": "zero negative shape"},
    ),
]
