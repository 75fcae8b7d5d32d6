"""Chapter 8 widget: the running safety of the Manchester car through a curve, every criterion
against its limit, as speed, radius, cant and a side wind move.

The factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The model is
:func:`raildyn.curving.safety.safety_assessment` on the car's new S1002 wheels on UIC 60 rails
inclined at 1:40 (:func:`raildyn.wheelset.profile_contact`: the pair's own flange angle for Nadal);
the chart is :meth:`raildyn.curving.safety.SafetyAssessment.plot`, drawn once and moved in place.
Kept apart from :mod:`raildyn.widgets.chapter08`, whose four widgets fill that module.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from raildyn.contact.profiles import s1002_wheel, uic60_rail
from raildyn.curving import safety_assessment
from raildyn.errors import SolverError
from raildyn.track import cant_deficiency
from raildyn.vehicles import LateralCar
from raildyn.wheelset import profile_contact
from raildyn.widgets._core import Recipe, slider

__all__ = ["safety_chart"]

_CAR = LateralCar()  # the Manchester benchmark car (Iwnicki 1998)
_WIND_HEIGHT = 2.0  # m above the rails: about the middle of a coach's side


@lru_cache(maxsize=1)
def _contact():
    """New S1002 wheels on UIC 60 rails at 1:40, tabulated once (about a second)."""
    return profile_contact(s1002_wheel(), uic60_rail(1 / 40))


class _Assessments:
    """The car's assessments for one widget: each (R, V, D, F_w) once, each started from the last
    equilibrium (a slider moves a little, so Newton meets the new point in a step or two). Calling it
    gives the assessment or the SolverError that says why there is none."""

    def __init__(self):
        self.solved: dict = {}
        self.last = None

    def __call__(self, radius: float, speed: float, cant: float, wind: float):
        key = (radius, speed, cant, wind)
        if key not in self.solved:
            try:
                result = safety_assessment(
                    _CAR, speed, radius, cant, contact=_contact(), wind_force=wind,
                    wind_height=_WIND_HEIGHT, start=self.last,
                )  # fmt: skip
                self.last = result.equilibrium
            except SolverError as err:
                result = err
            self.solved[key] = result
        return self.solved[key]


def _controls():
    return {
        "speed_kmh": slider("speed V (km/h)", 100.0, 10.0, 200.0, 5.0, fmt=".0f"),
        "radius": slider("radius R (m)", 600.0, 150.0, 3000.0, 10.0, fmt=".0f"),
        "cant_mm": slider("cant h_t (mm)", 100.0, 0.0, 150.0, 5.0, fmt=".0f"),
        "wind_kn": slider("side wind force F_w (kN)", 0.0, 0.0, 200.0, 10.0, fmt=".0f"),
    }


def _setup(live, status):
    (ax,) = live.axes[0]
    assess = _Assessments()
    first = assess(600.0, 100.0 / 3.6, 0.1, 0.0)
    chart = first.plot(ax)  # drawn once, then moved in place
    ax.set_title("The Manchester car on S1002/UIC 60 1:40: each criterion's value over its limit")
    live.animate(*chart["bars"], *chart["labels"])

    def redraw(v):
        R, V = float(v["radius"]), float(v["speed_kmh"]) / 3.6
        D, F = 1e-3 * float(v["cant_mm"]), 1e3 * float(v["wind_kn"])
        head = (
            f"R = {R:.0f} m, V = {3.6 * V:.0f} km/h, h_t = {1e3 * D:.0f} mm "
            f"(cant deficiency {1e3 * cant_deficiency(V, R, D):.0f} mm), wind {1e-3 * F:.0f} kN"
        )
        result = assess(R, V, D, F)
        if isinstance(result, SolverError):
            for artist in (*chart["bars"], *chart["labels"]):
                artist.set_visible(False)
            status.value = f"{head} · no equilibrium: {result}"
            return
        for artist in (*chart["bars"], *chart["labels"]):
            artist.set_visible(True)
        result.plot(artists=chart)
        worst = max(result.utilisation, key=result.utilisation.get)
        verdict = "every criterion within its limit" if result.safe else f"{worst} beyond its limit"
        status.value = (
            f"{head} · {verdict} · leading axle Y/Q {np.max(result.wheel_quotient[0]):.2f} "
            f"(Nadal {result.nadal_limit:.2f} at ϑ_f = {np.degrees(result.flange_angle):.1f}°) · "
            f"ΣY {1e-3 * result.track_shift_force.max():.1f} kN (Prud'homme "
            f"{1e-3 * result.prudhomme_limit:.1f} kN) · twist ΔQ/Q₀ {result.twist_unloading:.2f} · "
            f"overturning ΔQ/Q₀ {result.overturning_unloading:.2f}, wheels lift at "
            f"{1e3 * result.overturning_deficiency:.0f} mm of cant deficiency"
        )

    return redraw


SAFETY_CHART = Recipe(
    _controls,
    _setup,
    {"nrows": 1, "ncols": 1, "figsize": (8.0, 3.4)},
    static={"speed_kmh": [40.0, 60.0, 80.0, 100.0, 120.0, 140.0, 160.0, 180.0]},
    title="The Manchester car's running-safety criteria against their limits in a curve",
)


def safety_chart():
    """The Manchester car's running safety in a curve: each criterion's value over its limit.

    The car on new S1002 wheels and UIC 60 rails at 1:40
    (:func:`raildyn.curving.safety.safety_assessment`): the largest wheel Y/Q against Nadal's
    limit at the pair's flange angle, the largest axle Σ|Y/Q| against Weinstock's, the largest ΣY
    against Prud'homme's, the unloading ΔQ/Q₀ on the limit twists against 0.6, and the unloading of
    the inner rail under the cant deficiency, the body's roll and the wind against 1 (the wheels
    lift). A bar beyond 1 is drawn in red. The status line gives the numbers and the cant
    deficiency at which the wheels lift. Controls: speed V (km/h), radius R (m), cant h_t (mm),
    side wind force F_w (kN, at 2 m above the rails).

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``speed_kmh``, ``radius``, ``cant_mm``, ``wind_kn``),
        redraws and returns the PNG frame.
    """
    return SAFETY_CHART.build()


# The benchmark's moves (benchmarks/bench_ch08_curving.py): one control at a time, back to its start.
BENCH_MOVES = [
    ("ch08 safety_chart V", SAFETY_CHART, "speed_kmh", [60.0, 80.0, 120.0, 140.0, 160.0, 100.0]),
    ("ch08 safety_chart R", SAFETY_CHART, "radius", [300.0, 450.0, 800.0, 1500.0, 3000.0, 600.0]),
    ("ch08 safety_chart F_w", SAFETY_CHART, "wind_kn", [20.0, 50.0, 80.0, 120.0, 160.0, 0.0]),
]
