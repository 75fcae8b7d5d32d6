"""Curving (book chapter 8): steady-state curving, the nonlinear equilibrium and entry, wheel climb.

The curve itself (cant, cant deficiency, balance speed, curves with transitions) lives in
:mod:`raildyn.track` (:mod:`raildyn.track.cant`, :mod:`raildyn.track.curve`), below the models
that run on it.

* :mod:`raildyn.curving.steady` — the linear steady state of any lateral model in a curve
  (:func:`~raildyn.curving.steady.steady_curving`);
* :mod:`raildyn.curving.quasi_static` — the nonlinear equilibrium in a curve, flanges included
  (:func:`~raildyn.curving.quasi_static.quasi_static_curving`, over a map:
  :func:`~raildyn.curving.quasi_static.curving_map`);
* :mod:`raildyn.curving.entry` — a nonlinear run from straight track into a curve
  (:func:`~raildyn.curving.entry.curve_entry`);
* :mod:`raildyn.curving.stiffness` — self-steering in bending and shear stiffness, and the
  trade-off between stability and curving
  (:func:`~raildyn.curving.stiffness.stability_and_curving`);
* :mod:`raildyn.curving.climb` — wheel climb: Nadal's limit and Weinstock's axle sum;
* :mod:`raildyn.curving.safety` — running safety of a car through a curve: wheel climb, Prud'homme's
  track shift, unloading on twisted track and overturning
  (:func:`~raildyn.curving.safety.safety_assessment`).
"""

from raildyn.curving import geometry  # noqa: F401  (the old path of raildyn.track.cant and .curve; goes after one issue)
from raildyn.curving.entry import CurveEntry, curve_entry
from raildyn.curving.quasi_static import CurvingMap, QuasiStaticCurving, curving_map, quasi_static_curving
from raildyn.curving.safety import (
    SafetyAssessment,
    limit_twist,
    prudhomme_limit,
    safety_assessment,
    twist_unloading,
)
from raildyn.curving.steady import SteadyCurving, steady_curving
from raildyn.curving.stiffness import (
    BendingShear,
    SelfSteeringCurving,
    StabilityCurving,
    bending_shear_stiffness,
    self_steering_curving,
    stability_and_curving,
)
from raildyn.track.curve import Curve  # re-exported from its old home; goes after one issue

__all__ = [
    "BendingShear",
    "Curve",
    "CurveEntry",
    "CurvingMap",
    "QuasiStaticCurving",
    "SafetyAssessment",
    "SelfSteeringCurving",
    "StabilityCurving",
    "SteadyCurving",
    "curve_entry",
    "bending_shear_stiffness",
    "curving_map",
    "limit_twist",
    "prudhomme_limit",
    "quasi_static_curving",
    "safety_assessment",
    "self_steering_curving",
    "stability_and_curving",
    "steady_curving",
    "twist_unloading",
]
