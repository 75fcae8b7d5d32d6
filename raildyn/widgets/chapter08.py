"""Chapter 8 widgets: the car's wheelsets in a curve, Nadal's limit against the car's Y/Q, a
bogie's entry into a curve against speed, and the car's stability–curving trade-off.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are :mod:`raildyn.curving` and :mod:`raildyn.vehicles`; this module only
turns control values into model calls and moves artists. The plan view is
:meth:`raildyn.curving.steady.SteadyCurving.plot` of the quasi-static equilibrium and the
curve entry :meth:`raildyn.curving.entry.CurveEntry.plot`, both moved in place; the trade-off
:meth:`raildyn.curving.stiffness.StabilityCurving.plot`.
"""

from __future__ import annotations

from functools import lru_cache

import ipywidgets as widgets
import numpy as np

from raildyn import plots
from raildyn.curving import climb, curve_entry, quasi_static_curving
from raildyn.curving.stiffness import stability_and_curving
from raildyn.errors import SolverError
from raildyn.track import Curve, balance_speed, cant_deficiency
from raildyn.vehicles import Bogie, LateralCar
from raildyn.widgets._core import Recipe, slider

__all__ = ["curve_entry_speed", "curving_plan", "nadal_chart", "stiffness_tradeoff"]

_CAR = LateralCar().nonlinear()  # the Manchester benchmark car with saturating creep and flanges
_EXAGGERATION = 50.0  # on the offsets and angles of attack in the plan view, as SteadyCurving.plot's default
_FLANGING = plots.COLORS[1]  # an axle on its flange
_ROLLING = plots.COLORS[0]  # an axle on its treads


class _CarEquilibria:
    """The car's quasi-static equilibria for one widget: each (R, V, D, flange angle) solved once, from
    the last one solved (a slider moves a little, so Newton meets the new point in a step or two).

    Calling it gives the equilibrium (m, m/s, m, deg) or the SolverError that says why there is none.
    """

    def __init__(self):
        self.solved: dict = {}
        self.last = None

    def __call__(self, radius: float, speed: float, cant: float, flange_angle_deg: float = 70.0):
        key = (radius, speed, cant, flange_angle_deg)
        if key not in self.solved:
            try:
                state = quasi_static_curving(
                    _CAR, speed, radius, cant, flange_angle=np.radians(flange_angle_deg), start=self.last
                )
                self.last = state
            except SolverError as err:
                state = err
            self.solved[key] = state
        return self.solved[key]


# ---------------------------------------------------------------------------
# The car in plan


def _plan_controls():
    return {
        "radius": slider("radius R (m)", 600.0, 150.0, 3000.0, 10.0, fmt=".0f"),
        "speed_kmh": slider("speed V (km/h)", 71.0, 10.0, 160.0, 1.0, fmt=".0f"),
        "cant_mm": slider("cant h_t (mm)", 100.0, 0.0, 150.0, 5.0, fmt=".0f"),
    }


def _plan_setup(live, status):
    (ax,) = live.axes[0]
    equilibrium = _CarEquilibria()
    state = equilibrium(600.0, 71.0 / 3.6, 0.1)
    chart = state.plot(ax, exaggeration=_EXAGGERATION)  # drawn once, then moved in place
    del chart["title"]  # the widget's own title below stays
    ax.set_title(
        f"Manchester car in quasi-static equilibrium, offsets and yaw × {_EXAGGERATION:g}; "
        "inner rail at the top, running to the right",
        fontsize="medium",
    )
    ax.set_xlim(-14.0, 14.0)
    ax.plot([], [], color=_FLANGING, lw=3, label="on its flange")
    ax.plot([], [], color=_ROLLING, lw=3, label="on its treads")
    ax.legend(loc="lower right", fontsize=8)
    # The numbers are in the wheelsets' labels and the status line: each more text costs ~4 ms a frame.
    live.animate(*chart["axles"], *chart["labels"])

    def redraw(v):
        R, V, D = float(v["radius"]), float(v["speed_kmh"]) / 3.6, 1e-3 * float(v["cant_mm"])
        deficiency = 1e3 * cant_deficiency(V, R, D)
        head = (
            f"R = {R:.0f} m, V = {3.6 * V:.0f} km/h, h_t = {1e3 * D:.0f} mm: "
            f"cant deficiency {deficiency:.0f} mm"
        )
        state = equilibrium(R, V, D)
        if isinstance(state, SolverError):
            for artist in (*chart["axles"], *chart["labels"][1:]):
                artist.set_visible(False)
            chart["labels"][0].set_text("no equilibrium")  # moved back by the next plot
            chart["labels"][0].set_x(0.0)
            status.value = f"{head} · no equilibrium: {state}"
            return
        state.plot(artists=chart, exaggeration=_EXAGGERATION)
        for axle, label, flanging in zip(chart["axles"], chart["labels"], state.flange_contact, strict=True):
            axle.set_visible(True)
            label.set_visible(True)
            axle.set_color(_FLANGING if flanging else _ROLLING)
        quotient = state.derailment_quotient[0, 1]
        forces = zip(state.longitudinal_creep_force, state.lateral_creep_force, strict=True)
        wheelsets = "; ".join(
            f"{k + 1}: α {1e3 * a:+.2f} mrad, y {1e3 * y:+.1f} mm, {'flange' if f else 'treads'}, "
            f"creep Tx {1e-3 * tx:+.1f} kN, Ty {1e-3 * ty:+.1f} kN"
            for k, (a, y, f, (tx, ty)) in enumerate(
                zip(state.angle_of_attack, state.offset, state.flange_contact, forces, strict=True)
            )
        )
        status.value = (
            f"{head} (a_q = {state.unbalanced_acceleration:.2f} m/s²) · leading outer wheel "
            f"Y/Q = {quotient:.3f} · wheelsets front to back (Tx: the outer wheel's longitudinal creep "
            f"force, Ty: both wheels' lateral, outwards): {wheelsets}"
        )

    return redraw


CURVING_PLAN = Recipe(
    _plan_controls,
    _plan_setup,
    {"nrows": 1, "ncols": 1, "figsize": (10.0, 3.6)},
    static={"radius": [150.0, 200.0, 300.0, 400.0, 600.0, 800.0, 1200.0, 2000.0, 3000.0]},
    title="The Manchester car's four wheelsets in plan in a curve, in quasi-static equilibrium",
)


def curving_plan():
    """The Manchester car's wheelsets in plan in a curve: offsets, angles of attack, flange contact.

    The car with saturating creep and flanges (``LateralCar().nonlinear()``) in its quasi-static
    equilibrium (:func:`raildyn.curving.quasi_static.quasi_static_curving`), drawn on the straightened
    track with its offsets and angles of attack exaggerated 50 times; an axle on its
    flange is drawn in red. The status line gives the cant deficiency, the leading outer
    wheel's Y/Q and each wheelset's angle of attack, offset and contact; where the car has
    no equilibrium (it overturns, or no search finds one) it says why. Controls: radius R
    (m), speed V (km/h) and cant h_t (mm).

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``radius``, ``speed_kmh``, ``cant_mm``), redraws and
        returns the PNG frame.
    """
    return CURVING_PLAN.build()


# ---------------------------------------------------------------------------
# Nadal's limit and the car's Y/Q

_NADAL_CANT = 0.1  # m: the cant of the curve the car runs in
_FLANGE_ANGLES = np.linspace(50.0, 80.0, 121)  # deg
_REFERENCE_FRICTIONS = (0.0, 0.2, 0.4, 0.6)


def _nadal_controls():
    return {
        "flange_angle": slider("flange angle ϑ_f (deg)", 70.0, 50.0, 80.0, 0.5, fmt=".1f"),
        "friction": slider("flange friction μ", 0.36, 0.0, 0.8, 0.01),
        "radius": slider("radius R (m)", 300.0, 150.0, 3000.0, 10.0, fmt=".0f"),
        "speed_kmh": slider("speed V (km/h)", 71.0, 10.0, 140.0, 1.0, fmt=".0f"),
    }


def _nadal_setup(live, status):
    (ax,) = live.axes[0]
    equilibrium = _CarEquilibria()
    references = climb.plot_nadal_limit(
        ax, friction=_REFERENCE_FRICTIONS, flange_angle=np.radians(_FLANGE_ANGLES)
    )
    for line in references.values():
        line.set_alpha(0.35)
        line.set_linewidth(1.0)
    (limit,) = ax.plot(_FLANGE_ANGLES, _FLANGE_ANGLES * 0.0, color="k", lw=2.2, label="chosen μ")
    (at_angle,) = ax.plot([70.0], [1.0], "o", mfc="white", mec="k", ms=8)
    (level,) = ax.plot(_FLANGE_ANGLES[[0, -1]], [0.0, 0.0], ":", color=_FLANGING)
    (car,) = ax.plot([70.0], [0.0], "D", color=_FLANGING, ms=8, label="car: leading outer wheel Y/Q")
    verdict = ax.text(0.02, 0.96, "", transform=ax.transAxes, va="top", fontsize=9)
    ax.set_xlim(_FLANGE_ANGLES[0], _FLANGE_ANGLES[-1])
    ax.set_ylim(0.0, 2.6)
    ax.set_title(
        f"Nadal's limit and the Manchester car's Y/Q (quasi-static, {1e3 * _NADAL_CANT:.0f} mm cant)",
        fontsize="medium",
    )
    ax.legend(loc="upper right", fontsize=8, ncol=2)
    live.animate(limit, at_angle, level, car, verdict)

    def redraw(v):
        delta, mu = float(v["flange_angle"]), float(v["friction"])
        R, V = float(v["radius"]), float(v["speed_kmh"]) / 3.6
        limit.set_ydata(climb.nadal_limit(np.radians(_FLANGE_ANGLES), mu))
        nadal = climb.nadal_limit(np.radians(delta), mu)
        at_angle.set_data([delta], [nadal])
        deficiency = 1e3 * cant_deficiency(V, R, _NADAL_CANT)
        head = (
            f"R = {R:.0f} m, V = {3.6 * V:.0f} km/h, {1e3 * _NADAL_CANT:.0f} mm cant "
            f"(deficiency {deficiency:.0f} mm)"
        )
        state = equilibrium(R, V, _NADAL_CANT, delta)
        if isinstance(state, SolverError):
            car.set_data([], [])
            level.set_data([], [])
            verdict.set_text(f"R = {R:.0f} m, V = {3.6 * V:.0f} km/h: no equilibrium")
            status.value = f"{head} · no equilibrium: {state}"
            return
        quotient = float(state.derailment_quotient[0, 1])
        car.set_data([delta], [quotient])
        level.set_data(_FLANGE_ANGLES[[0, -1]], [quotient, quotient])
        axle = climb.wheel_climb(state.wheel_lateral[0], state.wheel_vertical[0], np.radians(delta), mu)
        if quotient > nadal:
            word, short = "above Nadal's limit: the flange may climb", "may climb"
        else:
            word, short = "below Nadal's limit: no climb", "no climb"
        # the curve and the speed head the verdict: a few km/h move Y/Q by less than a pixel, and the
        # figure should still say which case it shows
        verdict.set_text(
            f"R = {R:.0f} m, V = {3.6 * V:.0f} km/h: Y/Q {quotient:.2f} {'>' if quotient > nadal else '<'} "
            f"{nadal:.2f}: {short}"
        )
        status.value = (
            f"{head} · leading outer wheel Y/Q = {quotient:.3f}, Nadal's limit at ϑ_f = {delta:.1f}°, "
            f"μ = {mu:.2f}: {nadal:.3f} — {word} · axle sum Σ|Y/Q| = {axle.axle_sum:.3f} against "
            f"Weinstock's {axle.weinstock_limit:.3f}"
        )

    return redraw


NADAL_CHART = Recipe(
    _nadal_controls,
    _nadal_setup,
    {"nrows": 1, "ncols": 1, "figsize": (8.0, 4.0)},
    static={"flange_angle": [60.0, 65.0, 70.0, 75.0], "friction": [0.1, 0.2, 0.3, 0.36, 0.4, 0.5, 0.6]},
    title="Nadal's limit against flange angle for a chosen friction, with the car's leading outer wheel Y/Q",
)


def nadal_chart():
    """Nadal's limit against the flange angle, and the Manchester car's leading outer wheel's Y/Q on it.

    The limit Y/Q = (tan ϑ_f − μ)/(1 + μ tan ϑ_f) (:func:`raildyn.curving.climb.nadal_limit`)
    for the chosen friction, over faint curves for μ = 0 (tan ϑ_f), 0.2, 0.4 and 0.6; the
    car's quotient comes from its quasi-static equilibrium
    (:func:`raildyn.curving.quasi_static.quasi_static_curving`, with the chosen flange angle) in a curve
    with 100 mm of cant, at the chosen radius and speed. The status line gives the verdict
    and the leading axle's sum against Weinstock's limit. Controls: flange angle ϑ_f (deg),
    flange friction μ, radius R (m) and speed V (km/h).

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``flange_angle``, ``friction``, ``radius``,
        ``speed_kmh``), redraws and returns the PNG frame.
    """
    return NADAL_CHART.build()


# ---------------------------------------------------------------------------
# Curve entry against speed

# A 600 m curve with 100 mm of cant, entered by a 50 m clothoid (a ramp of 2 mm/m) straight from
# the start, and a 30 m arc: the bogie settles on it within a few metres.
ENTRY_CURVE = Curve(radius=600.0, cant=0.1, transition_length=50.0, arc_length=30.0, straight=0.0)
ENTRY_SPEEDS = (60.0, 80.0, 100.0, 120.0)  # km/h: each run takes about a second, so a few, made once
_BOGIE = Bogie().nonlinear()  # a bogie's run costs about half the car's
_QUANTITIES = {"flange force": "flange_force", "offset": "offset", "angle of attack": "angle_of_attack"}
_SCALES = {"flange_force": (1e-3, "kN"), "offset": (1e3, "mm"), "angle_of_attack": (1e3, "mrad")}


@lru_cache(maxsize=1)
def _entry_runs() -> dict:
    """Speed (km/h) → (CurveEntry, QuasiStaticCurving) of the bogie in ENTRY_CURVE, computed once."""
    runs = {}
    for kmh in ENTRY_SPEEDS:
        V = kmh / 3.6
        runs[kmh] = (
            curve_entry(_BOGIE, V, ENTRY_CURVE),
            quasi_static_curving(_BOGIE, V, ENTRY_CURVE.radius, ENTRY_CURVE.cant),
        )
    return runs


def _limits(runs: dict, quantity: str) -> tuple[float, float]:
    """y-limits that hold every precomputed run's ``quantity``, in the plotted unit."""
    scale = _SCALES[quantity][0]
    values = np.concatenate([scale * getattr(run, quantity).ravel() for run, _ in runs.values()])
    low, high = min(values.min(), 0.0), max(values.max(), 0.0)
    margin = 0.08 * (high - low)
    return low - margin, high + margin


def _entry_controls():
    return {
        "speed_kmh": widgets.SelectionSlider(
            options=list(ENTRY_SPEEDS),
            value=80.0,
            description="speed V (km/h)",
            style={"description_width": "initial"},
            layout=widgets.Layout(width="360px"),
        ),
        "quantity": widgets.Dropdown(
            options=list(_QUANTITIES.items()), value="flange_force", description="show"
        ),
    }


def _entry_setup(live, status):
    (ax,) = live.axes[0]
    runs = _entry_runs()
    run, state = runs[80.0]
    chart = run.plot(ax, quantity="flange_force")  # one line per wheelset, moved in place
    ends = run.distance[[0, -1]]
    dashed = [
        ax.plot(
            ends, [0.0, 0.0], "--", color=line.get_color(), lw=1.2, label="quasi-static" if k == 0 else None
        )[0]
        for k, line in enumerate(chart["lines"])
    ]
    ax.set_xlim(*ends)
    ax.set_title(
        f"Bogie entering a {ENTRY_CURVE.radius:.0f} m curve ({1e3 * ENTRY_CURVE.cant:.0f} mm cant) by a "
        f"{ENTRY_CURVE.transition_length:.0f} m transition (dotted: its ends)",
        fontsize="medium",
    )
    ax.legend(loc="lower right", fontsize=8)
    live.animate(*chart["lines"], *dashed)
    shown = {"quantity": None}

    def redraw(v):
        kmh, quantity = float(v["speed_kmh"]), str(v["quantity"])
        run, state = runs[kmh]
        scale, unit = _SCALES[quantity]
        if quantity != shown["quantity"]:  # a new axis: its label and limits, drawn into the background
            ax.set_ylabel(f"{quantity.replace('_', ' ')} ({unit})")
            ax.set_ylim(*_limits(runs, quantity))
            live.invalidate()
            shown["quantity"] = quantity
        run.plot(artists=chart, quantity=quantity)
        settled = scale * getattr(state, quantity)
        for line, value in zip(dashed, settled, strict=True):
            line.set_ydata([value, value])
        values = scale * getattr(run, quantity)[0]
        peak = int(np.argmax(np.abs(values)))
        deficiency = 1e3 * cant_deficiency(kmh / 3.6, ENTRY_CURVE.radius, ENTRY_CURVE.cant)
        status.value = (
            f"V = {kmh:.0f} km/h (cant deficiency {deficiency:.0f} mm) · leading wheelset's "
            f"{quantity.replace('_', ' ')}: largest {values[peak]:.2f} {unit} "
            f"at s = {run.distance[peak]:.1f} m, "
            f"at the end {values[-1]:.2f} {unit}, quasi-static {settled[0]:.2f} {unit}"
        )

    return redraw


CURVE_ENTRY_SPEED = Recipe(
    _entry_controls,
    _entry_setup,
    {"nrows": 1, "ncols": 1, "figsize": (9.0, 3.8)},
    static={"speed_kmh": list(ENTRY_SPEEDS), "quantity": list(_QUANTITIES.values())},
    title="A bogie's flange force, offset and angle of attack through a curve's entry, against speed",
)


def curve_entry_speed():
    """A bogie's run from straight track into a 600 m curve, at one of a few speeds.

    The Manchester car's bogie with saturating creep and flanges (``Bogie().nonlinear()``)
    runs through a 50 m clothoid with a linear cant ramp into an arc of 600 m with 100 mm
    of cant (``ENTRY_CURVE``, :func:`raildyn.curving.entry.curve_entry`); each wheelset's
    flange force (or offset, or angle of attack) against the distance of the bogie's
    centre, with its quasi-static value (:func:`raildyn.curving.quasi_static.quasi_static_curving`)
    dashed. The runs at ``ENTRY_SPEEDS`` are made once, when the first widget is
    built (a few seconds), and kept. Controls: speed V (km/h) and the quantity shown.

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``speed_kmh``, one of ``ENTRY_SPEEDS``;
        ``quantity``, "flange_force", "offset" or "angle_of_attack"), redraws and returns
        the PNG frame.
    """
    return CURVE_ENTRY_SPEED.build()


# ---------------------------------------------------------------------------
# The trade-off between stability and curving

_TRADEOFF_STIFFNESSES = np.geomspace(1.0e6, 120.0e6, 20)  # N·m/rad per wheelset; the car's own is 62.8e6
_TRADEOFF_CANT = 0.1  # m: the curve is run at its balance speed, so the angle of attack is self-steering's
_TRADEOFF_RANGE = (1.0, 150.0)  # m/s searched for the critical speed
_TRADEOFF_RADII = (300.0, 2000.0)  # m: the radius slider's range


@lru_cache(maxsize=256)
def _tradeoff(conicity: float, radius: float):
    """The car's trade-off at a conicity in a curve of ``radius`` m (100 mm of cant, at balance speed)."""
    model = LateralCar().replace(conicity=conicity)
    speed = balance_speed(radius, _TRADEOFF_CANT)
    # 8 speeds a scan and 0.25 m/s (0.9 km/h) on each critical speed: finer than the plot shows
    return stability_and_curving(
        model,
        _TRADEOFF_STIFFNESSES,
        speed,
        radius,
        _TRADEOFF_CANT,
        speed_range=_TRADEOFF_RANGE,
        tol=0.25,
        scan=8,
    )


def _tradeoff_controls():
    return {
        "conicity": slider("conicity λ", 0.15, 0.05, 0.4, 0.01),
        "radius": slider("radius R (m)", 600.0, *_TRADEOFF_RADII, 50.0, fmt=".0f"),
    }


def _tradeoff_setup(live, status):
    (ax,) = live.axes[0]
    result = _tradeoff(0.15, 600.0)
    chart = result.plot(ax)  # drawn once, then moved in place
    own = LateralCar().wheelset.yaw_stiffness / 1e6
    b = LateralCar().bogie.semi_wheelbase
    ax.axvline(own, color="0.6", lw=1, ls=":")
    ax.text(own, 0.02, " Manchester car", transform=ax.get_xaxis_transform(), fontsize=8, color="0.4")
    ax.set_title(
        "Manchester car: linear critical speed, and angle of attack at the balance speed for 100 mm cant",
        fontsize="medium",
    )
    live.animate(chart["critical"], chart["attack"])
    left, right = chart["axes"]
    left.set_ylim(0.0, 3.6 * _TRADEOFF_RANGE[1])  # km/h: fixed, so that a move only moves the lines
    # mrad: fixed too, up to b/R of the sharpest curve on the slider (the rigid bogie's angle of attack)
    right.set_ylim(-0.5, 1.1e3 * b / _TRADEOFF_RADII[0])
    i = int(np.argmin(np.abs(_TRADEOFF_STIFFNESSES / 1e6 - own)))  # the grid's point nearest the car's

    def redraw(v):
        lam, R = float(v["conicity"]), float(v["radius"])
        r = _tradeoff(lam, R)
        r.plot(artists=chart)
        v_c = r.critical_speed[i]
        text = f"{3.6 * v_c:.0f} km/h" if np.isfinite(v_c) else "stable up to 540 km/h"
        status.value = (
            f"λ = {lam:.2f}, R = {R:.0f} m at {3.6 * r.speed:.0f} km/h · at k_ψ = "
            f"{_TRADEOFF_STIFFNESSES[i] / 1e6:.0f} MN·m/rad: critical speed {text}, leading wheelset's "
            f"angle of attack {1e3 * r.angle_of_attack[i]:.2f} mrad (b/R = {1e3 * b / R:.2f} mrad)"
        )

    return redraw


STIFFNESS_TRADEOFF = Recipe(
    _tradeoff_controls,
    _tradeoff_setup,
    {"nrows": 1, "ncols": 1, "figsize": (8.0, 3.8)},
    static={"conicity": [0.05, 0.08, 0.1, 0.12, 0.15, 0.2, 0.3, 0.4]},
    title="The Manchester car's critical speed and leading angle of attack against primary yaw stiffness",
)


def stiffness_tradeoff():
    """The stability–curving trade-off of the Manchester car against its primary yaw stiffness.

    For 20 primary yaw stiffnesses k_ψ per wheelset (1–120 MN·m/rad), the car's linear
    critical speed (left axis) and its leading wheelset's angle of attack in a curve run at
    its balance speed for 100 mm of cant (right axis), from
    :func:`raildyn.curving.stiffness.stability_and_curving`, drawn by
    :meth:`~raildyn.curving.stiffness.StabilityCurving.plot` and moved in place. The status
    line reads both at the car's own stiffness. Controls: conicity λ and radius R (m).

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``conicity``, ``radius``), redraws and returns the
        PNG frame.
    """
    return STIFFNESS_TRADEOFF.build()


BENCH_MOVES = [
    ("ch08 curving_plan R", CURVING_PLAN, "radius", [300.0, 450.0, 800.0, 1500.0, 3000.0, 600.0]),
    ("ch08 curving_plan V", CURVING_PLAN, "speed_kmh", [40.0, 60.0, 80.0, 100.0, 120.0, 71.0]),
    ("ch08 nadal_chart μ", NADAL_CHART, "friction", [0.1, 0.2, 0.3, 0.5, 0.6, 0.36]),
    ("ch08 nadal_chart R", NADAL_CHART, "radius", [200.0, 400.0, 600.0, 1000.0, 2000.0, 300.0]),
    ("ch08 nadal_chart ϑ_f", NADAL_CHART, "flange_angle", [60.0, 62.5, 65.0, 67.5, 72.5, 75.0]),
    ("ch08 curve_entry_speed V", CURVE_ENTRY_SPEED, "speed_kmh", [*ENTRY_SPEEDS, 80.0]),
    ("ch08 stiffness_tradeoff λ", STIFFNESS_TRADEOFF, "conicity", [0.05, 0.1, 0.2, 0.3, 0.4, 0.15]),
    ("ch08 stiffness_tradeoff R", STIFFNESS_TRADEOFF, "radius", [300.0, 450.0, 800.0, 1500.0, 2000.0, 600.0]),
]
