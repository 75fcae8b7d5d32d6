"""Curving (book chapter 8): curve geometry, steady-state curving, wheel climb.

* :mod:`raildyn.curving.geometry` — cant, cant deficiency, balance speed, curves with transitions;
* :mod:`raildyn.curving.steady` — the linear steady state of any lateral model in a curve
  (:func:`~raildyn.curving.steady.steady_curving`);
* :mod:`raildyn.curving.quasi_static` — the nonlinear equilibrium in a curve, flanges included
  (:func:`~raildyn.curving.quasi_static.quasi_static_curving`, over a map:
  :func:`~raildyn.curving.quasi_static.curving_map`);
* :mod:`raildyn.curving.entry` — a nonlinear run from straight track into a curve
  (:func:`~raildyn.curving.entry.curve_entry`);
* :mod:`raildyn.curving.climb` — wheel climb: Nadal's limit and Weinstock's axle sum.
"""

from raildyn.curving.entry import CurveEntry, curve_entry
from raildyn.curving.quasi_static import CurvingMap, QuasiStaticCurving, curving_map, quasi_static_curving
from raildyn.curving.steady import SteadyCurving, steady_curving

__all__ = [
    "CurveEntry",
    "CurvingMap",
    "QuasiStaticCurving",
    "SteadyCurving",
    "curve_entry",
    "curving_map",
    "quasi_static_curving",
    "steady_curving",
]
