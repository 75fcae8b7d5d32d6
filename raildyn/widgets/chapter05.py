"""Chapter 5 widgets: Klingel's kinematic oscillation, and the suspended wheelset's roots against speed.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are :mod:`raildyn.wheelset` and :mod:`raildyn.stability`; this module only
turns control values into model calls and moves artists.
"""

from __future__ import annotations

import numpy as np

from raildyn import stability, wheelset
from raildyn.widgets._core import Recipe, slider

__all__ = ["klingel", "wheelset_roots"]

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


BENCH_MOVES = [
    ("ch05 klingel λ", KLINGEL, "conicity", [0.05, 0.1, 0.2, 0.3, 0.4, 0.15]),
    ("ch05 wheelset_roots k_ψ", WHEELSET_ROOTS, "yaw_stiffness", [1.0, 2.0, 4.0, 8.0, 12.0, 3.0]),
    ("ch05 wheelset_roots λ", WHEELSET_ROOTS, "conicity", [0.05, 0.1, 0.2, 0.3, 0.4, 0.15]),
]
