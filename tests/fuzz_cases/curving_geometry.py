"""Fuzz registry: chapter 8, curve geometry (raildyn.track.cant, .curve) and wheel climb (curving.climb).

The cant functions and Nadal's and Weinstock's limits take single numbers here, and are
vectorised: a list of two numbers is valid for each of their arguments (declared ``list``). The
curve's methods take an array of distances, any finite value of which is valid (before
s = 0 and beyond the end the track is straight), so zero, negative and reshaped
distances are declared valid.
"""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn.curving import climb
from raildyn.track import Curve

S = np.linspace(0.0, 400.0, 9)  # m, across every segment of the default curve
DISTANCES = {"s": "zero negative shape"}
V = "list mm big"  # a vectorised argument (a radius a thousand times longer is a gentler curve)

# A result dataclass holds what the model computed: signs and shapes are the model's (its docstring).
RESULT = {"*": "zero negative list fraction shape mm big"}


def _climb():
    return climb.wheel_climb([45e3, -20e3], [60e3, 50e3], 1.2, 0.3, 0.2)


def _climb_fields():
    r = _climb()
    return call(
        r.wheel_quotient, r.flanging_wheel, r.flange_quotient, r.axle_sum, r.nadal_limit,
        r.weinstock_limit, r.flange_angle, r.friction, r.other_friction,
    )  # fmt: skip


ENTRIES = [
    # ------------------------------------------------------------------ cant and speed
    fuzz(
        "raildyn.track.cant.equilibrium_cant",
        lambda: call(30.0, 600.0),
        accepts={"speed": "zero list", "radius": V},
    ),
    fuzz(
        "raildyn.track.cant.cant_deficiency",
        lambda: call(30.0, 600.0, 0.1),
        accepts={"speed": "zero list", "radius": V, "cant": "zero list"},
    ),
    fuzz(
        "raildyn.track.cant.unbalanced_acceleration",
        lambda: call(30.0, 600.0, 0.1, exact=True),
        accepts={"speed": "zero list", "radius": V, "cant": "zero list"},
    ),
    fuzz(
        "raildyn.track.cant.balance_speed",
        lambda: call(600.0, 0.1),
        accepts={"radius": V, "cant": "zero list"},
    ),
    fuzz(
        "raildyn.track.cant.speed_for_deficiency",
        lambda: call(600.0, 0.1, 0.15),
        # no cant with a deficiency, no deficiency (the balance speed), or a cant excess equal to the cant
        accepts={"radius": V, "cant": "zero list", "deficiency": "zero negative list big mm"},
    ),
    # ------------------------------------------------------------------ the curve
    fuzz(
        "raildyn.track.curve.Curve",
        lambda: call(600.0, 0.1, 60.0, 200.0, 50.0),
        accepts={
            "radius": "big mm",
            "cant": "zero",
            "transition_length": "zero big mm",
            "arc_length": "zero big mm",
            "straight": "zero big mm",
        },
    ),
    fuzz("raildyn.track.curve.Curve.replace", lambda: on(Curve(), radius=800.0)),
    fuzz("raildyn.track.curve.Curve.ends", lambda: on(Curve())),
    fuzz(
        "raildyn.track.curve.ramp",
        lambda: call(S, 50.0, 370.0, 60.0),
        # any distances and ends of either sign; a curve without transitions (L = 0) steps
        accepts={**DISTANCES, "start": "zero negative", "end": "big mm", "transition": "zero tiny"},
    ),
    fuzz("raildyn.track.curve.Curve.curvature", lambda: on(Curve(), S), accepts=DISTANCES),
    fuzz("raildyn.track.curve.Curve.cant_at", lambda: on(Curve(), S), accepts=DISTANCES),
    fuzz(
        "raildyn.track.curve.Curve.unbalanced_acceleration",
        lambda: on(Curve(), S, 30.0),
        accepts=DISTANCES | {"speed": "zero"},
    ),
    fuzz("raildyn.track.curve.Curve.cant_gradient", lambda: on(Curve(), S), accepts=DISTANCES),
    fuzz(
        "raildyn.track.curve.Curve.twist",
        lambda: on(Curve(), S, 2.5),
        accepts={**DISTANCES, "base": "mm big tiny"},  # a twist over any base length
    ),
    fuzz("raildyn.track.curve.Curve.heading", lambda: on(Curve(), S), accepts=DISTANCES),
    fuzz("raildyn.track.curve.Curve.x", lambda: on(Curve(), S), accepts=DISTANCES),
    fuzz("raildyn.track.curve.Curve.y", lambda: on(Curve(), S), accepts=DISTANCES),
    fuzz("raildyn.track.curve.Curve.plot", lambda: on(Curve(), view="curvature")),
    # ------------------------------------------------------------------ wheel climb
    fuzz(
        "raildyn.curving.climb.nadal_limit",
        lambda: call(1.2, 0.3),
        accepts={"flange_angle": V + " tiny", "friction": "zero list"},  # a flange angle → 0: the limit
    ),
    fuzz(
        "raildyn.curving.climb.weinstock_limit",
        lambda: call(1.2, 0.3, 0.2),
        # other_friction None: the flange's friction
        accepts={"flange_angle": V + " tiny", "friction": "zero list", "other_friction": "zero list none"},
    ),
    fuzz(
        "raildyn.curving.climb.wheel_climb",
        lambda: call([45e3, -20e3], [60e3, 50e3], 1.2, 0.3, 0.2),
        # lateral forces of either sign, or none; two axles (a shape (2, 2)) are refused only by the
        # vertical loads that no longer match
        accepts={
            "flange_angle": "tiny",
            "lateral": "zero negative",
            "friction": "zero",
            "other_friction": "zero none",
        },
    ),
    fuzz("raildyn.curving.climb.WheelClimb", _climb_fields, accepts=RESULT),
    fuzz("raildyn.curving.climb.WheelClimb.plot", lambda: on(_climb())),
    fuzz(
        "raildyn.curving.climb.plot_nadal_limit",
        lambda: call(friction=(0.1, 0.3, 0.5), flange_angle=np.radians(np.linspace(55.0, 80.0, 11))),
        accepts={"friction": "zero", "flange_angle": "none"},  # None: 50° to 80°
    ),
]
