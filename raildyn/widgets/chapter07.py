"""Chapter 7 widgets: the car's roots against speed, its critical speed against conicity, three vehicles,
and the car's bifurcation diagram.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are :mod:`raildyn.vehicles` and :mod:`raildyn.stability`; this
module only turns control values into model calls. The charts are drawn, and
moved in place, by the methods of the results that the chapter's figures call
too: :meth:`raildyn.stability.linear.ModeSweep.plot`,
:meth:`raildyn.stability.linear.CriticalSpeedMap.plot_curves` and
:meth:`raildyn.stability.bifurcation.BifurcationDiagram.plot`.
"""

from __future__ import annotations

from functools import lru_cache

import ipywidgets as widgets
import numpy as np

from raildyn import plots, stability
from raildyn.linear_model import AffineFamily
from raildyn.vehicles import EMPTY_FREIGHT_CAR, LATERAL_LOCOMOTIVE, LOADED_FREIGHT_CAR, LateralCar
from raildyn.widgets._core import Recipe, slider

__all__ = ["bifurcation", "car_roots", "critical_curve", "vehicle_comparison"]

_SPEEDS = np.linspace(5.0, 150.0, 60)  # m/s; enough points for smooth curves, few enough for 100 ms
_CAR = LateralCar()
_K_PSI = _CAR.wheelset.yaw_stiffness / 1e6  # MN·m/rad, the car's primary yaw stiffness per wheelset


@lru_cache(maxsize=64)
def _car_roots(conicity: float, yaw_stiffness: float):
    """Mode sweep and critical speed of the car (yaw stiffness in MN·m/rad), shared by setup and redraw."""
    system = _CAR.replace(conicity=conicity, yaw_stiffness=1e6 * yaw_stiffness).linear_system()
    sweep = stability.mode_sweep(system, _SPEEDS)
    return sweep, stability.critical_speed(system, (_SPEEDS[0], _SPEEDS[-1]), tol=0.05)


def _car_roots_controls():
    return {
        "conicity": slider("conicity λ", _CAR.wheelset.conicity, 0.02, 0.5, 0.01),
        "yaw_stiffness": slider(
            "primary k_ψ (MN·m/rad)", _CAR.wheelset.yaw_stiffness / 1e6, 2.0, 120.0, 1.0, fmt=".0f"
        ),
    }


def _car_roots_setup(live, status):
    sweep, cs = _car_roots(_CAR.wheelset.conicity, _CAR.wheelset.yaw_stiffness / 1e6)  # the defaults
    chart = sweep.plot(live.axes[0], critical=cs)  # drawn once, then moved in place
    live.animate(chart["roots"], *chart["modes"], chart["hunting"], chart["critical"], chart["critical_text"])

    def redraw(v):
        sweep, cs = _car_roots(float(v["conicity"]), float(v["yaw_stiffness"]))
        sweep.plot(critical=cs, artists=chart)
        if cs.found:
            status.value = (
                f"critical speed {cs.speed:.1f} m/s = {cs.speed * 3.6:.0f} km/h, hunting at "
                f"{cs.frequency_hz:.2f} Hz"
            )
        else:
            status.value = (
                f"critical speed: {cs.status} ({_SPEEDS[0] * 3.6:.0f}–{_SPEEDS[-1] * 3.6:.0f} km/h)"
            )

    return redraw


CAR_ROOTS = Recipe(
    _car_roots_controls,
    _car_roots_setup,
    {"nrows": 1, "ncols": 2, "figsize": (10.0, 3.8)},
    static={"conicity": [0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5]},
    title="Roots of the Manchester car against speed, and the damping of every mode",
)


def car_roots():
    """Eigenvalues of the 15-coordinate Manchester car from 18 to 540 km/h, and each mode's damping.

    Left: the roots coloured by speed; right: the damping factor of every mode
    against speed (modes followed by MAC), the one least damped at the top
    speed in colour, and the critical speed marked with its frequency. Controls:
    conicity λ and the primary yaw stiffness of each wheelset k_ψ (MN·m/rad).
    The chart is :meth:`raildyn.stability.linear.ModeSweep.plot`, moved in place.

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``conicity``, ``yaw_stiffness``), redraws and
        returns the PNG frame.
    """
    return CAR_ROOTS.build()


_CONICITIES = np.linspace(0.03, 0.5, 10)


# (λ, k_ψ, k_sψ) in (–, N·m/rad, N·m/rad): the corners of the widget's controls and conicities
_CURVE_ORIGIN, _CURVE_FAR = (0.03, 2.0e6, 0.0), (0.5, 120.0e6, 2.0e6)


@lru_cache(maxsize=1)
def _curve_families() -> tuple[AffineFamily, AffineFamily]:
    """The car and its bogie as affine families in (λ, k_ψ, k_sψ): a slider move assembles nothing."""

    def car(lam, k, ks):
        return _CAR.replace(conicity=lam, yaw_stiffness=k, secondary_yaw_stiffness=ks)

    return (
        AffineFamily(car, _CURVE_ORIGIN, _CURVE_FAR),
        AffineFamily(lambda *p: car(*p).bogie, _CURVE_ORIGIN, _CURVE_FAR),
    )


def _critical_curves(yaw_stiffness: float, secondary_yaw_stiffness: float):
    """Critical-speed maps of the car and of its bogie against conicity (stiffnesses in MN·m/rad).

    :func:`raildyn.stability.critical_speeds` (scan 16, tol 0.1 m/s over 1–200 m/s) on the families'
    stacks of matrices: every conicity of each vehicle in one batched search.
    """
    points = np.column_stack(
        [
            _CONICITIES,
            np.full(_CONICITIES.size, 1e6 * yaw_stiffness),
            np.full(_CONICITIES.size, 1e6 * secondary_yaw_stiffness),
        ]
    )

    def curve(family):
        stack = stability.StateMatrices(**family.stacks(points))
        found = stability.critical_speeds(stack, (1.0, 200.0), tol=0.1, scan=16)
        return stability.CriticalSpeedMap(
            _CONICITIES, np.array([yaw_stiffness]), found.speeds[None], "conicity λ", "primary k_ψ (MN·m/rad)"
        )

    return tuple(curve(family) for family in _curve_families())


def _critical_curve_setup(live, status):
    (ax,) = live.axes[0]
    car, bogie = _critical_curves(_CAR.wheelset.yaw_stiffness / 1e6, _CAR.bogie.secondary_yaw_stiffness / 1e6)
    car_lines = car.plot_curves(ax, marker="o", color=plots.COLORS[0], label="car")
    bogie_lines = bogie.plot_curves(
        ax, marker="s", ls="--", color=plots.COLORS[1], label="bogie under a still body"
    )
    ax.set_xlim(0, 0.52)
    ax.set_ylim(0, 600)
    ax.legend(loc="upper right")
    live.animate(*car_lines["lines"], *bogie_lines["lines"])

    def redraw(v):
        car, bogie = _critical_curves(float(v["yaw_stiffness"]), float(v["secondary_yaw_stiffness"]))
        car.plot_curves(artists=car_lines)
        bogie.plot_curves(artists=bogie_lines)
        i = int(np.argmin(np.abs(_CONICITIES - 0.15)))
        car_v, bogie_v = 3.6 * car.speeds[0, i], 3.6 * bogie.speeds[0, i]
        status.value = f"at λ ≈ {_CONICITIES[i]:.2f}: car {car_v:.0f} km/h, bogie {bogie_v:.0f} km/h"

    return redraw


CRITICAL_CURVE = Recipe(
    lambda: {
        "yaw_stiffness": slider(
            "primary k_ψ (MN·m/rad)", _CAR.wheelset.yaw_stiffness / 1e6, 2.0, 120.0, 1.0, fmt=".0f"
        ),
        "secondary_yaw_stiffness": slider(
            "secondary k_sψ (MN·m/rad)", _CAR.bogie.secondary_yaw_stiffness / 1e6, 0.0, 2.0, 0.02
        ),
    },
    _critical_curve_setup,
    {"nrows": 1, "ncols": 1, "figsize": (7.0, 3.6)},
    static={"yaw_stiffness": [2.0, 5.0, 10.0, 20.0, 40.0, _K_PSI, 90.0, 120.0]},
    title="Critical speed of the car and of its bogie against conicity",
)


def critical_curve():
    """Critical speed against conicity for the Manchester car and for its bogie alone.

    Controls: primary yaw stiffness k_ψ of each wheelset (MN·m/rad) and the
    secondary yaw stiffness k_sψ of each bogie (MN·m/rad). Speeds above 720 km/h
    (no crossing below 200 m/s) are left blank. The curves are
    :meth:`raildyn.stability.linear.CriticalSpeedMap.plot_curves`, moved in place.

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``yaw_stiffness``, ``secondary_yaw_stiffness``),
        redraws and returns the PNG frame.
    """
    return CRITICAL_CURVE.build()


# The three vehicle types of chapter 7, by the name the dropdown shows.
VEHICLES = {
    "passenger car": _CAR,
    "freight car, empty": EMPTY_FREIGHT_CAR,
    "freight car, loaded": LOADED_FREIGHT_CAR,
    "locomotive": LATERAL_LOCOMOTIVE,
}
_COMPARE_CONICITIES = np.linspace(0.02, 0.4, 12)
_COMPARE_RANGE = (1.0, 200.0)  # m/s
# The hunting mode's shape, grouped by body so that the four models (15, 17, 17 and 19 coordinates) share
# one set of bars: each bar is the largest |entry| among the coordinates whose label starts and ends so.
_GROUPS = (
    ("body y", "body", " y"),
    ("body ψ", "body", " ψ"),
    ("body φ", "body", " φ"),
    ("frames y", "frame", " y"),
    ("frames ψ", "frame", " ψ"),
    ("bolsters ψ", "bolster", " ψ"),
    ("wheelsets y", "wheelset", " y"),
    ("wheelsets ψ", "wheelset", " ψ"),
)


@lru_cache(maxsize=256)
def _vehicle_critical(vehicle: str, conicity: float):
    """Linear critical speed of one of ``VEHICLES`` at a conicity (shared by curves, marker and tests)."""
    model = VEHICLES[vehicle].replace(conicity=conicity)
    return stability.critical_speed(model, _COMPARE_RANGE, tol=0.05)


def _mode_groups(crit) -> np.ndarray:
    """The hunting mode's largest |entry| in each of ``_GROUPS`` (0 for groups the model lacks)."""
    shape = np.abs(np.nan_to_num(crit.mode_shape))
    return np.array(
        [
            max(
                (
                    a
                    for a, c in zip(shape, crit.coordinates, strict=True)
                    if c.startswith(p) and c.endswith(q)
                ),
                default=0.0,
            )
            for _, p, q in _GROUPS
        ]
    )


def _vehicle_controls():
    return {
        "vehicle": widgets.Dropdown(
            options=list(VEHICLES), value="freight car, empty", description="vehicle"
        ),
        "conicity": slider("conicity λ", 0.05, 0.02, 0.4, 0.01),
    }


def _vehicle_setup(live, status):
    curves_ax, shape_ax = live.axes[0]
    curves = {}
    for k, name in enumerate(VEHICLES):
        speeds = [3.6 * _vehicle_critical(name, float(lam)).speed for lam in _COMPARE_CONICITIES]
        (curves[name],) = curves_ax.plot(
            _COMPARE_CONICITIES, speeds, marker="o", ms=3, color=plots.COLORS[k], alpha=0.45, label=name
        )
    curves_ax.set_xlim(0, 0.42)
    curves_ax.set_ylim(0, 3.6 * _COMPARE_RANGE[1])
    curves_ax.set_xlabel("conicity λ")
    curves_ax.set_ylabel("linear critical speed (km/h)")
    curves_ax.legend(loc="upper right", fontsize="small")
    (highlight,) = curves_ax.plot([], [], lw=3.0, color="k", alpha=0.6)
    (marker,) = curves_ax.plot([], [], "D", ms=9, color="k")
    x = np.arange(len(_GROUPS))
    bars = shape_ax.bar(x, np.zeros(len(_GROUPS)), color=plots.COLORS[0])
    shape_ax.set_xticks(x, [g for g, _, _ in _GROUPS], rotation=45, ha="right")
    shape_ax.set_ylim(0, 1.05)
    shape_ax.set_ylabel("|mode shape| (largest entry 1)")
    shape_ax.set_title("hunting mode at the critical speed", fontsize="medium")
    live.animate(highlight, marker, *bars)

    def redraw(v):
        name, lam = str(v["vehicle"]), float(v["conicity"])
        highlight.set_data(curves[name].get_xdata(), curves[name].get_ydata())
        highlight.set_color(curves[name].get_color())
        crit = _vehicle_critical(name, lam)
        if crit.found:
            marker.set_data([lam], [3.6 * crit.speed])
            heights = _mode_groups(crit)
            dominant = ", ".join(_GROUPS[i][0] for i in np.argsort(-heights)[:2])
            status.value = (
                f"{name}, λ = {lam:.2f}: critical speed {crit.speed:.1f} m/s = {3.6 * crit.speed:.0f} km/h, "
                f"hunting at {crit.frequency_hz:.2f} Hz, mostly {dominant}"
            )
        else:
            marker.set_data([], [])
            heights = np.zeros(len(_GROUPS))
            status.value = f"{name}, λ = {lam:.2f}: critical speed: {crit.status} (up to 720 km/h)"
        for bar, h in zip(bars, heights, strict=True):
            bar.set_height(h)
            bar.set_color(curves[name].get_color())

    return redraw


VEHICLE_COMPARISON = Recipe(
    _vehicle_controls,
    _vehicle_setup,
    {"nrows": 1, "ncols": 2, "figsize": (10.0, 3.8)},
    static={"vehicle": list(VEHICLES), "conicity": [0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4]},
    title="Critical speed against conicity of a passenger car, a freight car empty and loaded, and a "
    "locomotive, and the hunting mode of the chosen one",
)


def vehicle_comparison():
    """Critical speed against conicity of the three vehicle types, and the chosen one's hunting mode.

    Left: the linear critical speed against conicity of the Manchester passenger car,
    the 100-ton hopper on three-piece trucks empty and loaded, and the six-axle
    locomotive (``VEHICLES``), the chosen vehicle's curve drawn over the others
    and its critical speed at the chosen conicity marked. Right: the shape of the mode
    that loses stability there, grouped as body, truck frames, bolsters and wheelsets
    (the largest |entry| of each group, the largest entry of the shape 1). Controls:
    the vehicle and the conicity λ.

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``vehicle``, ``conicity``), redraws and
        returns the PNG frame.
    """
    return VEHICLE_COMPARISON.build()


# ---------------------------------------------------------------------------
# The bifurcation diagram, live

_BIFURCATION_SPEEDS = np.linspace(20.0, 140.0, 13)  # m/s (72 to 504 km/h): every fold on the grid below
_BIFURCATION_RUN = {"duration": 4.0, "refine": 3, "progress": False}  # 4 s: eight cycles of 2 Hz hunting
_BIFURCATION_GRID = {
    "conicity": [0.05, 0.1, 0.15, 0.2, 0.3],
    "yaw_stiffness": [0.5 * _K_PSI, _K_PSI, 2.0 * _K_PSI],  # MN·m/rad: half, the car's, twice
}


def _bifurcation_car(conicity: float, yaw_stiffness: float) -> LateralCar:
    return _CAR.replace(conicity=conicity, yaw_stiffness=1e6 * yaw_stiffness)


@lru_cache(maxsize=1)
def _bifurcation_family() -> dict:
    """The diagrams of the kernel-free grid, run as one batch of the compiled engine (a few seconds):
    the kernel-free copy's preparation (the live widget draws one diagram at a time)."""
    keys = [(lam, k) for lam in _BIFURCATION_GRID["conicity"] for k in _BIFURCATION_GRID["yaw_stiffness"]]
    models = [_bifurcation_car(*key).nonlinear() for key in keys]
    diagrams = stability.bifurcation_diagrams(models, _BIFURCATION_SPEEDS, **_BIFURCATION_RUN)
    return dict(zip(keys, diagrams, strict=True))


@lru_cache(maxsize=64)
def _bifurcation(conicity: float, yaw_stiffness: float):
    """The car's diagram and linear critical speed: from the grid's batch once it has run, else one
    diagram on its own (a third of a second; the same numbers, bit for bit)."""
    car = _bifurcation_car(conicity, yaw_stiffness)
    family = _bifurcation_family() if _bifurcation_family.cache_info().currsize else {}
    diagram = family.get((conicity, yaw_stiffness))
    if diagram is None:
        diagram = stability.bifurcation_diagram(car.nonlinear(), _BIFURCATION_SPEEDS, **_BIFURCATION_RUN)
    return diagram, stability.critical_speed(car, (5.0, 200.0), tol=0.05)


def _bifurcation_controls():
    return {
        "conicity": slider("conicity λ", _CAR.wheelset.conicity, 0.05, 0.3, 0.01),
        "yaw_stiffness": slider("primary k_ψ (MN·m/rad)", _K_PSI, 0.5 * _K_PSI, 2.0 * _K_PSI, 1.0, fmt=".0f"),
    }


def _bifurcation_setup(live, status):
    diagram, linear = _bifurcation(_CAR.wheelset.conicity, _K_PSI)
    ax = live.axes[0, 0]
    chart = diagram.plot(ax, linear_critical_speed=linear.speed)
    ax.set_ylim(0.0, 25.0)  # mm: the largest cycle of the grid is 21 mm
    live.animate(
        *(
            chart[key]
            for key in ("cycles", "decaying", "linear", "linear_text", "nonlinear", "nonlinear_text")
        )
    )

    def redraw(v):
        diagram, linear = _bifurcation(float(v["conicity"]), float(v["yaw_stiffness"]))
        diagram.plot(linear_critical_speed=linear.speed if linear.found else None, artists=chart)
        vnl = diagram.nonlinear_critical_speed
        if not np.isfinite(vnl):
            text = f"no limit cycle up to {3.6 * _BIFURCATION_SPEEDS[-1]:.0f} km/h"
        else:
            text = f"limit cycles from {3.6 * vnl:.0f} km/h"
            if linear.found and vnl < linear.speed:
                text += (
                    f", below the linear critical speed {3.6 * linear.speed:.0f} km/h: between the two a "
                    "large disturbance starts hunting that persists (subcritical)"
                )
        status.value = text

    return redraw


BIFURCATION = Recipe(
    _bifurcation_controls,
    _bifurcation_setup,
    {"figsize": (8.0, 3.6)},
    static=_BIFURCATION_GRID,
    title="Bifurcation diagram of the Manchester car: limit-cycle amplitude against speed",
    prepare=_bifurcation_family,
)


def bifurcation():
    """The Manchester car's bifurcation diagram, redrawn as the conicity or the primary yaw stiffness moves.

    The amplitude of the leading wheelset's limit cycle along a ramp-down of speed from 504 to 72
    km/h (:func:`raildyn.stability.bifurcation.bifurcation_diagram` on the compiled engine: 13
    speeds of 4 s and three bisections, a third of a second), with the nonlinear and the linear
    critical speeds marked. Controls: conicity λ and the primary yaw stiffness of each wheelset
    k_ψ (MN·m/rad). The kernel-free copy shows the 15 diagrams of a grid of both, run as one batch.

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``conicity``, ``yaw_stiffness``), redraws and
        returns the PNG frame.
    """
    return BIFURCATION.build()


BENCH_MOVES = [
    ("ch07 car_roots λ", CAR_ROOTS, "conicity", [0.05, 0.1, 0.2, 0.3, 0.4, 0.15]),
    ("ch07 car_roots k_ψ", CAR_ROOTS, "yaw_stiffness", [5.0, 10.0, 20.0, 40.0, 80.0, 63.0]),
    ("ch07 critical_curve k_ψ", CRITICAL_CURVE, "yaw_stiffness", [5.0, 10.0, 20.0, 40.0, 80.0, 63.0]),
    ("ch07 vehicle_comparison λ", VEHICLE_COMPARISON, "conicity", [0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.25]),
    ("ch07 vehicle_comparison vehicle", VEHICLE_COMPARISON, "vehicle", [*VEHICLES, "freight car, empty"]),
]
