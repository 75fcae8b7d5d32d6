"""Fuzz registry: the wheelset on a curve (chapter 5) and the curving models of chapter 8: linear steady
state, nonlinear quasi-static equilibrium and the dynamic curve entry."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn.contact.profiles import s1002_wheel, uic60_rail
from raildyn.curving import (
    CurveEntry,
    SteadyCurving,
    curve_entry,
    curving_map,
    quasi_static_curving,
    steady_curving,
)
from raildyn.track import Curve
from raildyn.vehicles import Bogie
from raildyn.wheelset import ContactTable, WheelRailContact, Wheelset


def state() -> SteadyCurving:
    return steady_curving(Bogie(), 30.0, 1200.0, 0.05)


# A short curve the bogie runs in under a second of simulated time at 25 m/s.
SHORT = Curve(radius=1500.0, cant=0.05, transition_length=5.0, arc_length=10.0, straight=0.0)


def curved():
    return Bogie().nonlinear().replace(curve=SHORT, start=0.0)


def entry() -> CurveEntry:
    return curve_entry(Bogie().nonlinear(), 25.0, SHORT)


def nearby():
    return quasi_static_curving(Bogie().nonlinear(), 20.0, 700.0, 0.1)


def grid():
    return curving_map(Bogie().nonlinear(), [15.0, 25.0], [300.0, 600.0], 0.1)


RESULT = {"*": "zero negative mm big", "radius": "", "speed": "", "cant": "zero"}

TABLE = ContactTable(np.array([-2e-3, 0.0, 2e-3]), np.array([0.04, 0.05, 0.06]))  # rad: a tread angle


ENTRIES = [
    fuzz(
        "raildyn.wheelset.track_on_arc",
        lambda: call(np.array([-1.28, 1.28]), 1 / 600.0),
        # behind the origin, on straight track, turning right: every sign is a place on some track
        # arrays broadcast: an extra axis is a grid of places
        accepts={"position": "zero negative list shape", "curvature": "zero negative list"},
    ),
    fuzz(
        "raildyn.wheelset.pure_rolling_offset",
        lambda: call(0.46, 0.75, 0.15, 600.0),
        accepts={"conicity": "tiny", "radius": "big tiny mm"},
    ),
    # a wheelset behind the axes' origin is at a negative position; at the origin it is zero
    fuzz(
        "raildyn.wheelset.curve_loads",
        lambda: call(Wheelset(), 600.0, 1.28),
        accepts={"radius": "big mm", "position": "zero negative"},
    ),
    fuzz(
        "raildyn.curving.steady_curving",
        lambda: call(Bogie(), 25.0, 600.0, 0.1),
        accepts={"speed": "tiny", "radius": "big mm", "cant": "zero"},
    ),
    fuzz(
        "raildyn.curving.SteadyCurving",
        lambda: call(600.0, 20.0, 0.0, 0.1, ("a y", "a ψ"), np.zeros(2), np.zeros(1), *np.ones((4, 1))),
        # a result: its fields hold whatever the solve gives, of either sign
        accepts=RESULT,
    ),
    fuzz("raildyn.curving.SteadyCurving.coordinate", lambda: on(state(), "frame y")),
    fuzz(
        "raildyn.curving.SteadyCurving.plot",
        lambda: on(state()),
        accepts={"exaggeration": "big tiny mm", "ax": "none"},
    ),
    fuzz(
        "raildyn.curving.quasi_static_curving",
        lambda: call(Bogie().nonlinear(), 25.0, 600.0, 0.1, start=nearby()),
        accepts={
            "speed": "tiny",
            "radius": "big mm",
            "cg_height": "tiny",
            "flange_angle": "tiny",
            "cant": "zero",
            "start": "none",
        },  # None: from the linear steady state
        limit=20.0,  # a stalled search tries four methods and a short run before it gives up
    ),
    fuzz(
        "raildyn.curving.QuasiStaticCurving",
        lambda: call(
            600.0,
            20.0,
            0.0,
            0.1,
            ("a y", "a ψ"),
            np.zeros(2),
            np.zeros(1),
            *np.ones((6, 1)),
            np.array([True]),
            np.ones(1),
            np.ones((1, 2)),
            np.ones((1, 2)),
        ),
        accepts=RESULT | {"wheel_vertical": ""},
    ),
    fuzz(
        "raildyn.curving.curve_entry",
        lambda: call(Bogie().nonlinear(), 25.0, SHORT),
        limit=20.0,
        accepts={"max_step": "big mm", "rtol": "mm"},
    ),
    fuzz(
        "raildyn.curving.CurveEntry",
        lambda: call(25.0, SHORT, np.arange(3.0), np.zeros(1), *np.ones((3, 1, 3))),
        accepts={"*": "zero negative", "speed": "", "distance": "zero negative"},
    ),
    fuzz("raildyn.curving.CurveEntry.plot", lambda: on(entry()), accepts={"ax": "none"}),
    fuzz(
        "raildyn.curving.curving_map",
        lambda: call(Bogie().nonlinear(), [15.0, 25.0], [300.0, 600.0], 0.1),
        accepts={"cg_height": "tiny", "flange_angle": "tiny", "cant": "zero"},
        limit=20.0,  # as quasi_static_curving, for each point a stalled search leaves
    ),
    fuzz(
        "raildyn.curving.CurvingMap",
        lambda: call(
            np.array([300.0]),
            np.array([20.0]),
            0.1,
            np.ones((1, 1)),
            *np.ones((4, 1, 1, 1)),
            np.ones((1, 1, 1, 2)),
        ),
        accepts={
            "unbalanced_acceleration": "zero negative",
            "offset": "zero negative",
            "angle_of_attack": "zero negative",
            "flange_force": "zero negative",
            "wear_number": "zero",
            "derailment_quotient": "zero",
            "cant": "zero big mm",
        },  # fmt: skip
    ),
    fuzz(
        "raildyn.curving.CurvingMap.plot",
        lambda: on(grid(), quantity="offset", wheelset=1),
        accepts={"ax": "none", "wheelset": "zero"},
    ),  # fmt: skip
    fuzz(
        "raildyn.wheelset.NonlinearLateral.arc_forces",
        lambda: on(Bogie().nonlinear(), np.full(6, 1e-3), 25.0, 1.0 / 600.0, 0.5),
        # a state of either sign; a tangent track (κ = 0) and any unbalanced acceleration
        accepts={
            "speed": "tiny",
            "q": "zero negative",
            "curvature": "zero negative",
            "unbalanced_acceleration": "zero negative big mm",
        },
    ),
    fuzz(
        "raildyn.wheelset.NonlinearLateral.arc_jacobian",
        lambda: on(Bogie().nonlinear(), np.full(6, 1e-3), 25.0, 1.0 / 600.0, 0.5),
        accepts={
            "speed": "tiny",
            "q": "zero negative",
            "curvature": "zero negative",
            "unbalanced_acceleration": "zero negative big mm",
        },
    ),
    fuzz(
        "raildyn.wheelset.arc_newton",
        lambda: call(Bogie().nonlinear(), np.zeros((6, 2)), 20.0, [1 / 600, 1 / 300], 0.3, tolerance=1e-3),
        # any start, tangent track or an arc either way, any unbalanced acceleration; a looser tolerance or
        # more steps only change when it stops
        accepts={
            "q": "zero negative",
            "speed": "tiny list",  # one speed, or one per column
            "curvature": "zero negative",
            "unbalanced_acceleration": "zero negative big mm list",
            "tolerance": "big mm tiny",  # a tolerance nothing meets leaves every point unconverged
            "steps": "big",
        },
    ),
    fuzz(
        "raildyn.wheelset.NonlinearLateral.relative_to_track",
        lambda: on(curved(), 1.0, np.full(12, 1e-3), 25.0),
        accepts={"t": "zero negative big mm", "state": "zero negative", "speed": "tiny"},
    ),
    fuzz(
        "raildyn.wheelset.profile_contact",
        lambda: call(s1002_wheel(), uic60_rail(1 / 40), friction=0.3, flange_stiffness=1.0e7),
        accepts={"friction": "tiny", "flange_stiffness": "zero big mm"},
    ),
    fuzz(
        "raildyn.wheelset.ContactTable",
        lambda: call(np.array([-2e-3, 0.0, 2e-3]), np.array([-1e-4, 0.0, 1e-4])),
        # the values are any finite numbers of either sign (a difference in m or an angle in rad);
        # the shifts must rise strictly, so a zeroed, negated or overflowing entry is refused
        accepts={"f": "zero negative huge"},
    ),
    fuzz(
        "raildyn.wheelset.ContactTables",
        lambda: call(TABLE, TABLE),
    ),
    fuzz(
        "raildyn.wheelset.wheel_forces",
        lambda: call(Wheelset(), WheelRailContact(), 0.012, 1e-3, 0.01, 0.02, 30.0),
        # displacements and rates of either sign; arrays broadcast (the speeds too, each > 0)
        accepts={
            **{name: "zero negative list mm big" for name in ("y", "psi", "ydot", "psidot")},
            "speed": "list tiny",
        },
    ),
    fuzz(
        "raildyn.wheelset.WheelForces",
        lambda: call(*np.ones((5, 2))),
        accepts={"*": "zero negative", "wear_number": "zero"},
    ),
]
