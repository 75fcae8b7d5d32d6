"""Fuzz registry: chapter 9, train dynamics (consists, couplers, resistance, forces, runs, lateral)."""

from __future__ import annotations

import functools

import numpy as np
from fuzzing import call, fuzz, on

from raildyn import train

HOPPER = train.VEHICLES["loaded hopper"]
LOCO = train.VEHICLES["SD40-2"]


def consist():
    """One locomotive and one hopper: one coupler, so a list of two curvatures has the wrong size."""
    return train.make_consist("SD40-2 + loaded hopper")


def model():
    """The smallest braking run: one locomotive, two hoppers, emergency air brake at t = 0."""
    return train.braking_model(2, 1)


def climbing():
    """Full notch on a 2 % climb: the balancing speed lies between 0.5 and 50 m/s."""
    return train.TrainModel(
        train.make_consist("SD40-2 + 2 loaded hopper"), route=train.Route((0.0,), (0.02,)), notch=8
    )


def graded():
    """A model on a route with a grade and a curve, so that positions are read."""
    route = train.Route((0.0, 100.0), (0.0, 0.01), curvature=(0.0, 0.002))
    return train.TrainModel(consist(), route=route, air_brake=train.AirBrake())


@functools.cache
def run():
    return train.simulate(model(), 1.0, 10.0, samples=11)


@functools.cache
def quasi_static():
    return climbing().quasi_static(10.0)


STATE = np.r_[0.0, 0.001, -0.002, 10.0, 10.1, 9.9]
X = np.array([0.0, -18.0, -34.0])
V = np.array([10.0, 10.1, 9.9])
T3 = np.array([0.0, 0.5, 1.0])
Y3 = np.tile(STATE[:, None], (1, 3))
EXT = np.array([-0.03, 0.0, 0.03])

#: Result dataclasses hold whatever a model computes: zero, negative and huge values are valid.
RESULT = {"*": "zero negative huge mm big"}

ENTRIES = [
    # --- vehicles and consists
    fuzz(
        "raildyn.train.Vehicle",
        lambda: call("test car", 50e3, 15.0, 4, 9.0, 10.0, "freight", 1e5, 1e6, 1e5, 2e4),
        accepts={
            p: "zero" for p in ("max_tractive_effort", "rail_power", "max_dynamic_brake", "brake_force")
        },
    ),
    # description is free text for display (any string).
    fuzz("raildyn.train.Consist", lambda: call((LOCO, HOPPER), "test"), accepts={"description": "unknown"}),
    fuzz(
        "raildyn.train.Consist.with_vehicle",
        lambda: on(train.make_consist("SD40-2 + 2 loaded hopper"), 1, mass=60e3),
        accepts={"index": "zero negative"},  # negative counts from the rear
    ),
    fuzz("raildyn.train.make_consist", lambda: call("SD40-2 + 2 loaded hopper")),
    # --- resistance and routes
    fuzz(
        "raildyn.train.davis_resistance",
        lambda: call(20.0, 1e5, 4, 9.0),
        accepts={
            "speed": "zero negative list",  # its sign is ignored
            "mass": "list",
            "axles": "list",
            "frontal_area": "list",
        },
    ),
    fuzz(
        "raildyn.train.grade_force",
        lambda: call(1e5, 0.01),
        accepts={"mass": "list big tiny mm", "grade": "zero negative list"},
    ),
    fuzz(
        "raildyn.train.curve_resistance",
        lambda: call(1e5, 0.005),
        accepts={"mass": "list big tiny mm", "curvature": "zero negative list"},
    ),
    fuzz(
        "raildyn.train.Route",
        lambda: call((0.0, 100.0), (0.0, 0.01)),
        accepts={"grade": "zero negative"},
    ),
    fuzz("raildyn.train.Route.level", lambda: call()),
    fuzz(
        "raildyn.train.Route.grade_at",
        lambda: on(graded().route, 50.0),
        accepts={"position": "zero negative list big mm"},
    ),
    fuzz(
        "raildyn.train.Route.curvature_at",
        lambda: on(graded().route, 50.0),
        accepts={"position": "zero negative list big mm"},
    ),
    fuzz(
        "raildyn.train.Route.vertical_curvature_at",
        lambda: on(graded().route, 50.0),
        accepts={"position": "zero negative list big mm"},
    ),
    # --- couplers
    fuzz(
        "raildyn.train.DraftGear",
        lambda: call(),
        accepts={
            "loading_stiffness": "big mm",
            "unloading_stiffness": "tiny",
            "travel": "tiny",
            "smoothing": "tiny",
            "transition_rate": "big tiny mm",
            "slack": "zero",
            "solid_stiffness": "zero big mm",
        },
    ),
    fuzz(
        "raildyn.train.DraftGear.deflection",
        lambda: on(train.DraftGear(), EXT),
        accepts={"extension": "zero negative shape"},
    ),
    fuzz(
        "raildyn.train.DraftGear.force",
        lambda: on(train.DraftGear(), EXT, np.array([0.1, -0.1, 0.2])),
        accepts={"extension": "zero negative shape", "rate": "zero negative shape"},
    ),
    fuzz(
        "raildyn.train.DraftGear.loop_energy",
        lambda: on(train.DraftGear(), 0.05),
        accepts={"amplitude": "zero"},
    ),
    fuzz(
        "raildyn.train.DraftGear.static_loop",
        lambda: on(train.DraftGear(), 0.05, points=5),
        accepts={"amplitude": "tiny"},
    ),
    fuzz(
        "raildyn.train.DraftGearLoop",
        lambda: call(np.array([0.0, 0.05, 0.0]), np.array([0.0, 1e6, 0.0]), 100.0),
        accepts=RESULT,
    ),
    fuzz("raildyn.train.DraftGearLoop.plot", lambda: on(train.DraftGear().static_loop(0.05, points=5))),
    # --- forces
    fuzz(
        "raildyn.train.tractive_effort",
        lambda: call(10.0, 8, 5e5, 2e6),
        accepts={
            "speed": "zero negative list",  # its sign is ignored
            "notch": "zero",  # idle
            "max_tractive_effort": "zero big mm",
            "rail_power": "zero big mm",
        },
    ),
    fuzz(
        "raildyn.train.dynamic_brake_force",
        lambda: call(10.0, 1.0, 3e5),
        accepts={"speed": "zero negative list", "level": "zero", "max_force": "zero big mm"},
    ),
    fuzz(
        "raildyn.train.AirBrake",
        lambda: call(),
        accepts={"build_up_time": "big tiny mm", "level": "tiny", "start": "zero big"},
    ),
    fuzz(
        "raildyn.train.AirBrake.arrival",
        lambda: on(train.AirBrake(), 100.0),
        accepts={"distance": "zero list big mm"},
    ),
    fuzz(
        "raildyn.train.AirBrake.fraction",
        lambda: on(train.AirBrake(), 1.0, 100.0),
        accepts={
            "t": "zero negative list big mm",
            "distance": "zero list big mm",
        },  # before the signal arrives: 0
    ),
    # --- the longitudinal model
    fuzz(
        "raildyn.train.TrainModel",
        lambda: call(consist(), air_brake=train.AirBrake()),
        accepts={
            "creep_speed": "tiny",
            "notch": "zero",
            "dynamic_brake": "zero",
            "air_brake": "none",  # no air-brake application
            "front_start": "zero negative big",
        },
    ),
    fuzz(
        "raildyn.train.TrainModel.initial_state",
        lambda: on(model(), 10.0, extension=0.001),
        accepts={"speed": "zero negative", "extension": "zero negative mm"},  # backwards; bunched
    ),
    fuzz("raildyn.train.TrainModel.positions", lambda: on(model(), STATE), accepts={"y": "zero negative"}),
    fuzz(
        "raildyn.train.TrainModel.coupler_extension",
        lambda: on(model(), X, V),
        accepts={"x": "zero negative", "v": "zero negative"},
    ),
    fuzz(
        "raildyn.train.TrainModel.coupler_forces",
        lambda: on(model(), X, V),
        accepts={"x": "zero negative", "v": "zero negative"},
    ),
    fuzz(
        "raildyn.train.TrainModel.external_forces",
        lambda: on(graded(), 1.0, X[:2], V[:2]),
        accepts={"t": "zero negative big mm", "x": "zero negative", "v": "zero negative"},
    ),
    fuzz(
        "raildyn.train.TrainModel.rhs",
        lambda: on(model(), 1.0, STATE),
        accepts={"t": "zero negative big mm", "y": "zero negative"},
    ),
    fuzz(
        "raildyn.train.TrainModel.rhs_numpy",
        lambda: on(model(), 1.0, STATE),
        accepts={"t": "zero negative big mm", "y": "zero negative"},
    ),
    fuzz(
        "raildyn.train.TrainModel.run_from_states",
        lambda: on(model(), T3, Y3, evaluations=5),
        accepts={"y": "zero negative", "evaluations": "zero"},
    ),
    fuzz("raildyn.train.TrainModel.quasi_static", lambda: on(climbing(), 10.0), accepts={"speed": "zero"}),
    fuzz("raildyn.train.TrainModel.balancing_speed", lambda: on(climbing()), accepts={"low": "zero"}),
    fuzz(
        "raildyn.train.simulate",
        lambda: call(model(), 1.0, 10.0, samples=11),
        accepts={
            "duration": "tiny mm",
            "rtol": "mm",
            "initial_speed": "zero negative",  # standing; running backwards
            "initial_extension": "zero negative",  # centred; bunched
        },
    ),
    fuzz("raildyn.train.braking_model", lambda: call(2, 1), accepts={"locomotives": "zero", "slack": "zero"}),
    # --- results
    fuzz(
        "raildyn.train.TrainRun",
        lambda: call(
            *(getattr(run(), f) for f in ("t", "position", "speed", "coupler_force", "coupler_offsets")), 26
        ),
        accepts=RESULT,
    ),
    fuzz(
        "raildyn.train.TrainRun.stop_time",
        lambda: on(run()),
        accepts={"threshold": "big tiny mm", "vehicle": "zero negative"},
    ),
    fuzz("raildyn.train.TrainRun.plot_envelope", lambda: on(run())),
    fuzz("raildyn.train.TrainRun.plot_wave", lambda: on(run())),
    fuzz("raildyn.train.CouplerPeak", lambda: call(-1e5, 1, 20.0, 0.5), accepts=RESULT),
    fuzz(
        "raildyn.train.QuasiStatic",
        lambda: call(
            *(
                getattr(quasi_static(), f)
                for f in ("coupler_force", "acceleration", "external_force", "position", "coupler_offsets")
            )
        ),
        accepts=RESULT,
    ),
    fuzz("raildyn.train.QuasiStatic.plot", lambda: on(quasi_static())),
    # --- lateral effects
    fuzz(
        "raildyn.train.coupler_angles",
        lambda: call(consist(), 1 / 200),
        accepts={"curvature": "zero negative"},  # straight; a curve to the right
    ),
    fuzz(
        "raildyn.train.coupler_effects",
        lambda: call(consist(), np.array([2e5]), curvature=1 / 200, vertical_curvature=1 / 2000),
        accepts={
            "forces": "zero negative",
            "curvature": "zero negative",
            "vertical_curvature": "zero negative",  # level; a crest
        },
    ),
    fuzz(
        "raildyn.train.CouplerEffects",
        lambda: call(
            *(
                getattr(train.coupler_effects(consist(), [2e5], curvature=1 / 200), f)
                for f in ("lateral_force", "l_over_v", "vertical_force", "unloading", "mode")
            )
        ),
        accepts=RESULT,
    ),
    fuzz(
        "raildyn.train.limiting_coupler_force",
        lambda: call(consist(), 1 / 150, 0.5, vehicle=1),
        accepts={
            "l_over_v": "big tiny mm",
            "curvature": "negative tiny",
            "vehicle": "zero negative",
        },  # its sign is ignored; from the rear
    ),
]
