"""Fuzz registry: chapter 8, running safety (raildyn.curving.safety, raildyn.widgets.chapter08_safety).

Prud'homme's limit and the limit twist are vectorised (a list of axle loads or bases is valid);
the twist's unloading takes single numbers. The assessment runs the Manchester car's quasi-static
equilibrium, so it is built once and its start reused.
"""

from __future__ import annotations

from functools import lru_cache

from fuzzing import call, fuzz, on

from raildyn.curving import safety_assessment
from raildyn.vehicles import LateralCar

V, R, D = 100 / 3.6, 600.0, 0.1

# A result dataclass holds what the model computed: signs and shapes are the model's (its docstring).
RESULT = {"*": "zero negative list fraction shape mm big"}


@lru_cache(maxsize=1)
def _assessment():
    return safety_assessment(LateralCar(), V, R, D)


def _fields():
    r = _assessment()
    return call(
        r.speed, r.radius, r.cant, r.cant_deficiency, r.wheel_quotient, r.nadal_limit, r.axle_sum,
        r.weinstock_limit, r.flange_angle, r.friction, r.track_shift_force, r.prudhomme_limit,
        r.bogie_twist, r.car_twist, r.twist_unloading, r.twist_limit, r.flexibility, r.wind_force,
        r.wind_height, r.overturning_unloading, r.overturning_limit, r.overturning_deficiency,
        r.equilibrium,
    )  # fmt: skip


ENTRIES = [
    fuzz(
        "raildyn.curving.prudhomme_limit",
        lambda: call(120e3, 0.85),
        accepts={"axle_load": "list", "factor": "fraction"},  # α of 0.85 × a fraction is above 0.5
    ),
    fuzz("raildyn.curving.limit_twist", lambda: call(2.56), accepts={"base": "list mm big tiny"}),
    fuzz(
        "raildyn.curving.twist_unloading",
        lambda: call(110e3, 0.75, 1.3, 9.0, 2.44e6, 1.8e6, 7e-3, 3e-3),
        accepts={
            # any twist up to 50 ‰, None: the limit twist of the base
            "bogie_twist": "zero tiny fraction none",
            "car_twist": "zero tiny fraction none",
            "half_gauge": "fraction",
            "axle_load": "fraction",
            "primary_roll_stiffness": "fraction",
            "secondary_roll_stiffness": "fraction",
            "semi_bogie_spacing": "fraction",  # 4.5 m: still beyond the semi-wheelbase
        },
    ),
    fuzz(
        "raildyn.curving.safety_assessment",
        lambda: call(LateralCar(), V, R, D, start=_assessment().equilibrium),
        accepts={
            "radius": "big mm",  # a gentler curve
            "cant": "zero",
            "start": "none",
            "contact": "none",
            "factor": "fraction",
            "wind_force": "zero tiny mm big",  # a wind that alone lifts the wheels is an answer too
            "wind_height": "fraction",
            "primary_roll_stiffness": "fraction",
            "speed": "tiny",
            "cg_height": "fraction",
        },
        limit=20.0,
    ),
    fuzz("raildyn.curving.SafetyAssessment", _fields, accepts=RESULT),
    fuzz("raildyn.curving.SafetyAssessment.plot", lambda: on(_assessment())),
    # the widget takes no arguments: only the unknown keyword applies (tests/test_safety.py and
    # tests/test_widget_contract.py make the valid call)
    fuzz("raildyn.widgets.chapter08_safety.safety_chart", lambda: call()),
]
