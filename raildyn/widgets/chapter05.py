"""Chapter 5 widgets: Klingel's kinematic oscillation, the suspended wheelset's roots against speed,
its hunting mode drawn in plan, and the suspended wheelset's steady state on a curve.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are :mod:`raildyn.wheelset`, :mod:`raildyn.stability` and
:mod:`raildyn.curving`; this module only turns control values into model calls and
moves artists.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from raildyn import diagrams, plots, stability, wheelset
from raildyn.curving import steady_curving
from raildyn.track import speed_for_deficiency
from raildyn.widgets._core import Recipe, slider

__all__ = ["curved_wheelset", "hunting_wheelset", "klingel", "wheelset_roots"]

_DISTANCE = np.linspace(0.0, 120.0, 1200)  # m of track: a fixed axis keeps the cached picture valid


def _klingel_controls():
    return {
        "conicity": slider("conicity λ", 0.15, 0.02, 0.5, 0.01),
        "rolling_radius_mm": slider("r₀ (mm)", 460.0, 300.0, 600.0, 5.0, fmt=".0f"),
        "semi_wheelbase": slider("bogie b (m)", 1.28, 0.5, 2.0, 0.02),
    }


def _klingel_setup(live, status):
    (ax,) = live.axes[0]
    a = 0.75  # m, half the distance between the contact points
    # The chart of figure 5.1, KinematicOscillation.plot, drawn once and moved in place.
    chart = wheelset.kinematic_oscillation(0.46, a, 0.15, 1.28).plot(ax, distance=_DISTANCE)
    ax.set_ylim(-6.5, 6.5)
    ax.legend(loc="upper right")
    live.animate(chart["free"], chart["bogie"])

    def redraw(v):
        r0 = v["rolling_radius_mm"] / 1000.0
        k = wheelset.kinematic_oscillation(r0, a, v["conicity"], v["semi_wheelbase"])
        k.plot(artists=chart)
        L, Lb = k.wavelength, k.rigid_bogie_wavelength
        status.value = (
            f"Klingel wavelength 2π√(r₀a/λ) = {L:.2f} m · rigid bogie 2π√(r₀a/λ·(1+b²/a²)) = {Lb:.2f} m "
            f"· at 100 km/h the wheelset sways at {100 / 3.6 / L:.2f} Hz"
        )

    return redraw


KLINGEL = Recipe(
    _klingel_controls,
    _klingel_setup,
    {"nrows": 1, "ncols": 1, "figsize": (8.0, 3.2)},
    static={"conicity": [0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5]},
    title="Kinematic oscillation of a free wheelset and of a rigid bogie",
)


def klingel():
    """The kinematic (Klingel) path of a coned wheelset and of a rigid two-axle bogie.

    Controls: conicity λ, rolling radius r₀ (mm) and the bogie's half wheelbase
    b (m); the contact points are 2a = 1.5 m apart. The status line gives both
    wavelengths and the sway frequency at 100 km/h.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return KLINGEL.build()


_SPEEDS = np.linspace(2.0, 120.0, 240)  # m/s


def _wheelset_roots_controls():
    return {
        "conicity": slider("conicity λ", 0.15, 0.02, 0.5, 0.01),
        "yaw_stiffness": slider("primary k_ψ (MN·m/rad)", 4.0, 0.0, 20.0, 0.25),
        "lateral_stiffness": slider("primary k_y (MN/m)", 1.0, 0.0, 8.0, 0.1),
    }


def _wheelset(values) -> wheelset.Wheelset:
    return wheelset.Wheelset(
        conicity=float(values["conicity"]),
        yaw_stiffness=1e6 * float(values["yaw_stiffness"]),
        lateral_stiffness=1e6 * float(values["lateral_stiffness"]),
    )


def _wheelset_roots_setup(live, status):
    defaults = {name: control.value for name, control in _wheelset_roots_controls().items()}
    # The chart of every lateral model, ModeSweep.plot (as figure 7.1 and the car widget), drawn once
    # with this chapter's windows and then moved in place.
    chart = stability.mode_sweep(_wheelset(defaults), _SPEEDS).plot(
        live.axes[0], real_limits=(-100.0, 10.0), imag_limits=(0.0, 80.0), damping_limits=(-0.3, 1.05)
    )
    live.animate(chart["roots"], *chart["modes"], chart["hunting"], chart["critical"], chart["critical_text"])

    def redraw(v):
        ws = _wheelset(v)
        cs = stability.critical_speed(ws, (_SPEEDS[0], _SPEEDS[-1]), tol=0.05)
        stability.mode_sweep(ws, _SPEEDS).plot(critical=cs, artists=chart)
        if cs.found:
            text = (
                f"critical speed {cs.speed:.1f} m/s = {cs.speed * 3.6:.0f} km/h at {cs.frequency_hz:.2f} Hz"
            )
        else:
            text = "critical speed: " + cs.status
        if v["yaw_stiffness"] + v["lateral_stiffness"] > 0:
            text += f" · Wickens' high-creep limit {wheelset.wickens_critical_speed(ws) * 3.6:.0f} km/h"
        status.value = text

    return redraw


WHEELSET_ROOTS = Recipe(
    _wheelset_roots_controls,
    _wheelset_roots_setup,
    {"nrows": 1, "ncols": 2, "figsize": (10.0, 3.8)},
    static={"yaw_stiffness": [0.0, 0.5, 1.0, 2.0, 4.0, 6.0, 8.0, 12.0, 16.0, 20.0]},
    title="Roots of the suspended wheelset against speed, and their damping",
)


def wheelset_roots():
    """Eigenvalues of a wheelset on a primary suspension to a frame at speed V, from 7 to 430 km/h.

    Left: the roots in the complex plane coloured by speed; right: the damping
    factor of the two oscillatory modes against speed, with the critical speed
    marked. Controls: conicity λ, primary yaw stiffness k_ψ (MN·m/rad) and
    lateral stiffness k_y (MN/m). With both stiffnesses at 0 the free wheelset
    is unstable at every speed.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return WHEELSET_ROOTS.build()


# ---------------------------------------------------------------------------
# The hunting wheelset, drawn in plan

_HUNTING_WHEELSET = wheelset.Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)  # notebook 05's soft one
_HUNTING_EXAGGERATE = 20.0  # hunting is millimetres and milliradians: drawn 20 times larger
_HUNTING_Y = 4.0e-3  # m: the largest lateral displacement drawn over the cycle
_HUNTING_PSI = 0.9 * (np.pi / 6) / _HUNTING_EXAGGERATE  # rad: within what wheelset_plan draws
_PHASES = np.linspace(0.0, 360.0, 121)  # degrees over one cycle of the mode


def _hunting_controls():
    return {
        "speed_kmh": slider("speed V (km/h)", 150.0, 20.0, 300.0, 5.0, fmt=".0f"),
        "phase_deg": slider("phase ωt (°)", 0.0, 0.0, 360.0, 15.0, fmt=".0f"),
    }


@lru_cache(maxsize=4)
def _hunting_motion(speed: float) -> tuple[np.ndarray, np.ndarray, complex]:
    """The least-damped mode of the chapter's soft wheelset at ``speed`` (m/s), over one cycle.

    Returns y (m) and ψ (rad) at the phases ωt of ``_PHASES`` (degrees): the mode's eigenvector
    times e^{s_r t}, growing or decaying as e^{(Re s_r)t} over the cycle, scaled so that the largest
    |y| is 4 mm (or |ψ| stays within what the plan draws); and the eigenvalue s_r (1/s).
    """
    sweep = stability.mode_sweep(_HUNTING_WHEELSET, [speed])
    j = sweep.hunting_mode
    lam = complex(sweep.eigenvalues[0, j])
    shape = sweep.shapes[0, :, j]
    phase = np.radians(_PHASES)
    # x(t) = Re(v e^{s_r t}) at t = φ/ω: one turn of the phase, with the growth e^{(Re s_r)t} of the cycle.
    path = np.exp((lam.real / abs(lam.imag) + 1j) * phase)
    y, psi = np.real(shape[0] * path), np.real(shape[1] * path)
    scale = min(_HUNTING_Y / np.abs(y).max(), _HUNTING_PSI / np.abs(psi).max())
    return scale * y, scale * psi, lam


def _hunting_setup(live, status):
    ax_plan, ax_time = live.axes[0]
    plan = diagrams.wheelset_plan(_HUNTING_WHEELSET, exaggerate=_HUNTING_EXAGGERATE, ax=ax_plan)
    art = plan.artists
    (y_line,) = ax_time.plot(_PHASES, np.zeros_like(_PHASES), color=plots.COLORS[0], label="$y$ (mm)")
    (psi_line,) = ax_time.plot(_PHASES, np.zeros_like(_PHASES), color=plots.COLORS[1], label=r"$\psi$ (mrad)")
    cursor = ax_time.axvline(0.0, color="0.5", lw=0.8, ls=":")
    (dots,) = ax_time.plot([0.0, 0.0], [0.0, 0.0], "o", color="0.2", ms=4)
    note = ax_time.text(0.02, 0.97, "", transform=ax_time.transAxes, va="top", size=8)
    ax_time.set_xlim(0.0, 360.0)
    ax_time.set_xticks(np.arange(0.0, 361.0, 90.0))
    ax_time.set_ylim(-5.0, 5.0)
    ax_time.set_xlabel("phase ωt over one cycle (°)")
    ax_time.set_ylabel("y (mm), ψ (mrad)")
    ax_time.legend(loc="lower right")
    live.animate(
        *art["wheels"],
        art["axle"],
        art["heading"],
        art["reference"],
        art["y"],
        art["psi"],
        art["psi_head"],
        art["texts"]["y"],
        art["texts"]["psi"],
        y_line,
        psi_line,
        cursor,
        dots,
        note,
    )

    def redraw(v):
        speed = float(v["speed_kmh"]) / 3.6
        y, psi, lam = _hunting_motion(speed)
        k = int(np.argmin(np.abs(_PHASES - float(v["phase_deg"]))))
        plan.update(y[k], psi[k])
        y_line.set_ydata(1e3 * y)
        psi_line.set_ydata(1e3 * psi)
        cursor.set_xdata([_PHASES[k]])
        dots.set_data([_PHASES[k]] * 2, [1e3 * y[k], 1e3 * psi[k]])
        frequency = abs(lam.imag) / (2 * np.pi)
        xi = -lam.real / abs(lam)
        per_cycle = np.exp(2 * np.pi * lam.real / abs(lam.imag))
        note.set_text(f"{v['speed_kmh']:.0f} km/h: f = {frequency:.2f} Hz, ξ = {xi:.3f}")
        ws = _HUNTING_WHEELSET
        L = wheelset.kinematic_wavelength(ws.rolling_radius, ws.half_gauge, ws.conicity)
        status.value = (
            f"least-damped mode at {speed:.1f} m/s: f = {frequency:.2f} Hz "
            f"(Klingel V/L = {speed / L:.2f} Hz), "
            f"ξ = {xi:.3f}, amplitude × {per_cycle:.2f} per cycle ("
            + ("grows: above V_c" if lam.real > 0 else "decays: below V_c")
            + ")"
        )

    return redraw


HUNTING_WHEELSET = Recipe(
    _hunting_controls,
    _hunting_setup,
    {"nrows": 1, "ncols": 2, "figsize": (10.0, 3.6)},
    static={"speed_kmh": [150.0, 250.0], "phase_deg": [float(p) for p in range(0, 360, 30)]},
    title="The hunting mode of the suspended wheelset, drawn in plan over one cycle",
)


def hunting_wheelset():
    """The suspended wheelset's least-damped (hunting) mode, drawn in plan and moved over one cycle.

    The chapter's soft wheelset (k_ψ = 2 MN·m/rad, k_y = 1 MN/m, V_c ≈ 197 km/h). At the chosen
    speed the linear model's least-damped mode, the eigenvalue s_r with eigenvector (y, ψ), gives the motion
    Re(v e^{s_r t}); the phase slider moves ωt over one cycle. Left: the wheelset in plan
    (:func:`raildyn.diagrams.rolling.wheelset_plan`, y and ψ drawn 20 times larger), moved in place; right:
    y (mm) and ψ (mrad) over the cycle, scaled so that the largest |y| is 4 mm, growing above the
    critical speed and decaying below it. Controls: speed V (km/h), phase ωt (degrees).

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return HUNTING_WHEELSET.build()


# ---------------------------------------------------------------------------
# The wheelset on a curve

_RADII = np.geomspace(300.0, 5000.0, 20)  # m: from about the free wheelset's flange contact to gentle curves
_RADIUS_TICKS = (300.0, 500.0, 1000.0, 2000.0, 5000.0)
_CURVE_CANT = 0.1  # m: the cant of every curve; the speed follows from the chosen cant deficiency
_CURVE_WHEELSET = wheelset.Wheelset()  # the Manchester wheelset of chapter 5 on its cone


def _curved_wheelset_controls():
    return {
        "radius": slider("radius R (m)", 600.0, 300.0, 3000.0, 50.0, fmt=".0f"),
        "deficiency_mm": slider("cant deficiency I (mm)", 50.0, 0.0, 150.0, 5.0, fmt=".0f"),
        "yaw_stiffness": slider(
            "primary k_ψ (MN·m/rad)", round(_CURVE_WHEELSET.yaw_stiffness / 1e6, 1), 0.0, 80.0, 0.1, fmt=".1f"
        ),
        "lateral_stiffness": slider(
            "primary k_y (MN/m)", round(_CURVE_WHEELSET.lateral_stiffness / 1e6, 1), 0.0, 10.0, 0.1, fmt=".1f"
        ),
    }


def _curve_system(yaw_stiffness: float, lateral_stiffness: float):
    """The suspended wheelset's linear system: k_ψ (N·m/rad), k_y (N/m)."""
    return _CURVE_WHEELSET.replace(
        yaw_stiffness=yaw_stiffness, lateral_stiffness=lateral_stiffness
    ).linear_system()


def _curve_states(system, radii, deficiency: float):
    """SteadyCurving of ``system`` on each radius (m), at the speed of the cant deficiency I (m)."""
    speeds = np.atleast_1d(speed_for_deficiency(radii, _CURVE_CANT, deficiency))
    return [steady_curving(system, V, R, cant=_CURVE_CANT) for V, R in zip(speeds, radii, strict=True)]


@lru_cache(maxsize=1)  # the last curves: a move of the radius alone moves only the markers
def _curve_sweep(deficiency: float, yaw_stiffness: float, lateral_stiffness: float) -> np.ndarray:
    """Offset (mm), angle of attack (mrad), backward longitudinal and outward lateral creep force (kN)
    over _RADII: an array (4, len(_RADII))."""
    return _curve_numbers(_curve_states(_curve_system(yaw_stiffness, lateral_stiffness), _RADII, deficiency))


def _curve_numbers(states) -> np.ndarray:
    return np.array(
        [
            [1e3 * s.offset[0] for s in states],
            [1e3 * s.angle_of_attack[0] for s in states],
            [-1e-3 * s.longitudinal_creep_force[0] for s in states],
            [1e-3 * s.lateral_creep_force[0] for s in states],
        ]
    )


def _curved_wheelset_setup(live, status):
    ax_y, ax_a, ax_f = live.axes[0]
    ws = _CURVE_WHEELSET
    rolling = [
        1e3 * wheelset.pure_rolling_offset(ws.rolling_radius, ws.half_gauge, ws.conicity, R) for R in _RADII
    ]
    ax_y.plot(_RADII, rolling, "--", color="0.5", label="free: $r_0a/(\\lambda R)$")
    # One line and one marker per result, in the order of the rows of _curve_numbers.
    panels = {
        "offset": (ax_y, plots.COLORS[0], "suspended"),
        "attack": (ax_a, plots.COLORS[0], None),
        "longitudinal": (ax_f, plots.COLORS[1], "longitudinal, outer wheel"),
        "lateral": (ax_f, plots.COLORS[2], "lateral, both wheels"),
    }
    lines = {
        name: ax.plot(_RADII, rolling, color=c, label=label)[0] for name, (ax, c, label) in panels.items()
    }
    markers = {name: ax.plot([600.0], [0.0], "o", color=c, ms=5)[0] for name, (ax, c, _) in panels.items()}
    for ax, label, limits in (
        (ax_y, "offset towards the outer rail (mm)", (0.0, 10.0)),
        (ax_a, "angle of attack (mrad)", (-0.5, 4.5)),
        (ax_f, "creep force (kN)", (-6.0, 80.0)),
    ):
        ax.set_xscale("log")
        ax.set_xticks(_RADIUS_TICKS, [f"{r:.0f}" for r in _RADIUS_TICKS])
        ax.set_xticks([], minor=True)
        ax.set_xlim(_RADII[0], _RADII[-1])
        ax.set_ylim(*limits)
        ax.set_xlabel("curve radius R (m)")
        ax.set_ylabel(label)
    ax_y.legend(loc="upper right")
    ax_f.legend(loc="upper right")
    live.animate(*lines.values(), *markers.values())

    def redraw(v):
        R, deficiency = float(v["radius"]), 1e-3 * float(v["deficiency_mm"])
        k_psi, k_y = 1e6 * float(v["yaw_stiffness"]), 1e6 * float(v["lateral_stiffness"])
        sweep = _curve_sweep(deficiency, k_psi, k_y)
        (state,) = _curve_states(_curve_system(k_psi, k_y), [R], deficiency)
        here = _curve_numbers([state])[:, 0]
        for (name, line), row, value in zip(lines.items(), sweep, here, strict=True):
            line.set_ydata(row)
            markers[name].set_data([R], [value])
        y0 = 1e3 * wheelset.pure_rolling_offset(ws.rolling_radius, ws.half_gauge, ws.conicity, R)
        status.value = (
            f"R = {R:.0f} m at {3.6 * state.speed:.0f} km/h ({1e3 * _CURVE_CANT:.0f} mm cant, "
            f"a_q = {state.unbalanced_acceleration:.2f} m/s²): offset {here[0]:.2f} mm (free {y0:.2f} mm) · "
            f"angle of attack {here[1]:.2f} mrad · creep forces {here[2]:.1f} kN back on the outer wheel, "
            f"{here[3]:.1f} kN outwards"
        )

    return redraw


CURVED_WHEELSET = Recipe(
    _curved_wheelset_controls,
    _curved_wheelset_setup,
    {"nrows": 1, "ncols": 3, "figsize": (11.0, 3.4)},
    static={"yaw_stiffness": [0.0, 2.0, 5.0, 10.0, 20.0, 30.0, 45.0, 62.8, 80.0]},
    title="Offset, angle of attack and creep forces of a suspended wheelset against the curve radius",
)


def curved_wheelset():
    """The steady state of a suspended wheelset on a curve, against the radius from 300 m to 5 km.

    The wheelset of chapter 5 (the Manchester benchmark's, on a cone of 0.15) on its
    primary suspension to a frame that follows the curve; every curve has 100 mm of cant
    and the speed is the one that gives the chosen cant deficiency. Left: the offset
    towards the outer rail beside the free wheelset's pure-rolling offset r₀a/(λR);
    middle: the angle of attack; right: the longitudinal creep force on the outer wheel
    (backwards) and the lateral creep force on the wheelset (outwards). A marker and the
    status line give the values at the chosen radius. Controls: radius R (m), cant
    deficiency I (mm), primary yaw stiffness k_ψ (MN·m/rad) and lateral stiffness k_y (MN/m).

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return CURVED_WHEELSET.build()


BENCH_MOVES = [
    ("ch05 klingel λ", KLINGEL, "conicity", [0.05, 0.1, 0.2, 0.3, 0.4, 0.15]),
    ("ch05 wheelset_roots k_ψ", WHEELSET_ROOTS, "yaw_stiffness", [1.0, 2.0, 4.0, 8.0, 12.0, 3.0]),
    ("ch05 wheelset_roots λ", WHEELSET_ROOTS, "conicity", [0.05, 0.1, 0.2, 0.3, 0.4, 0.15]),
    ("ch05 hunting_wheelset V", HUNTING_WHEELSET, "speed_kmh", [100.0, 150.0, 200.0, 250.0, 300.0, 150.0]),
    ("ch05 hunting_wheelset phase", HUNTING_WHEELSET, "phase_deg", [30.0, 90.0, 180.0, 270.0, 330.0, 0.0]),
    ("ch05 curved_wheelset k_ψ", CURVED_WHEELSET, "yaw_stiffness", [5.0, 10.0, 20.0, 40.0, 80.0, 62.8]),
    ("ch05 curved_wheelset R", CURVED_WHEELSET, "radius", [400.0, 800.0, 1500.0, 3000.0, 600.0]),
]
