"""Chapter 7 widgets: the car's roots against speed, and its critical speed against conicity.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are :mod:`raildyn.vehicles` and :mod:`raildyn.stability`; this
module only turns control values into model calls and moves artists.
"""

from __future__ import annotations

import numpy as np

from raildyn import plots, stability
from raildyn.vehicles import Car
from raildyn.widgets._core import Recipe, slider

_SPEEDS = np.linspace(5.0, 150.0, 60)  # m/s; enough points for smooth curves, few enough for 100 ms
_CAR = Car()


def _car(values) -> Car:
    return _CAR.replace(
        conicity=values["conicity"],
        yaw_stiffness=1e6 * values.get("yaw_stiffness", _CAR.wheelset.yaw_stiffness / 1e6),
    )


def _car_roots_controls():
    return {
        "conicity": slider("conicity λ", 0.15, 0.02, 0.5, 0.01),
        "yaw_stiffness": slider(
            "primary k_ψ (MN·m/rad)", _CAR.wheelset.yaw_stiffness / 1e6, 2.0, 120.0, 1.0, fmt=".0f"
        ),
    }


def _car_roots_setup(live, status):
    ax_s, ax_d = live.axes[0]
    n = _CAR.linear_system().size  # one root of each pair: the upper half-plane is drawn
    roots = ax_s.scatter(
        np.zeros(n * _SPEEDS.size),
        np.zeros(n * _SPEEDS.size),
        s=2,
        c=np.zeros(n * _SPEEDS.size),
        cmap="viridis",
        vmin=0,
        vmax=_SPEEDS[-1] * 3.6,
    )
    ax_s.axvline(0.0, color="k", lw=0.8)
    ax_s.set_xlim(-25, 5)
    ax_s.set_ylim(0, 70)
    ax_s.set_xlabel("Re λ (1/s)")
    ax_s.set_ylabel("Im λ (rad/s)")
    live.figure.colorbar(roots, ax=ax_s, label="speed (km/h)")
    modes = [ax_d.plot(_SPEEDS * 3.6, 0 * _SPEEDS, color="0.75", lw=0.8)[0] for _ in range(n)]
    (hunting,) = ax_d.plot(_SPEEDS * 3.6, 0 * _SPEEDS, color=plots.COLORS[1], lw=2, label="hunting mode")
    (mark,) = ax_d.plot([], [], "v", color="k", ms=8, label="critical speed")
    ax_d.axhline(0.0, color="k", lw=0.8)
    ax_d.set_xlim(0, _SPEEDS[-1] * 3.6)
    ax_d.set_ylim(-0.15, 0.5)
    ax_d.set_xlabel("speed (km/h)")
    ax_d.set_ylabel("damping factor ξ")
    ax_d.legend(loc="upper right")
    live.animate(roots, *modes, hunting, mark)

    def redraw(v):
        car = _car(v)
        system = car.linear_system()
        sweep = stability.mode_sweep(system, _SPEEDS)
        lam = sweep.eigenvalues
        roots.set_offsets(np.column_stack([lam.real.ravel(), lam.imag.ravel()]))
        roots.set_array(np.repeat(_SPEEDS * 3.6, lam.shape[1]))
        for line, xi in zip(modes, sweep.damping_ratios.T, strict=True):
            line.set_ydata(xi)
        worst = int(np.argmin(sweep.damping_ratios[-1]))
        hunting.set_ydata(sweep.damping_ratios[:, worst])
        cs = stability.critical_speed(system, (_SPEEDS[0], _SPEEDS[-1]), tol=0.05)
        if cs.found:
            mark.set_data([cs.speed * 3.6], [0.0])
            status.value = (
                f"critical speed {cs.speed:.1f} m/s = {cs.speed * 3.6:.0f} km/h, hunting at "
                f"{cs.frequency:.2f} Hz"
            )
        else:
            mark.set_data([], [])
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
    speed in colour, and the critical speed marked. Controls: conicity λ and
    the primary yaw stiffness of each wheelset k_ψ (MN·m/rad).
    """
    return CAR_ROOTS.build()


_CONICITIES = np.linspace(0.03, 0.5, 10)


def _critical_curve_setup(live, status):
    (ax,) = live.axes[0]
    (car_line,) = ax.plot(_CONICITIES, 0 * _CONICITIES, "o-", color=plots.COLORS[0], label="car")
    (bogie_line,) = ax.plot(
        _CONICITIES, 0 * _CONICITIES, "s--", color=plots.COLORS[1], label="bogie under a still body"
    )
    ax.set_xlim(0, 0.52)
    ax.set_ylim(0, 600)
    ax.set_xlabel("conicity λ")
    ax.set_ylabel("critical speed (km/h)")
    ax.legend(loc="upper right")
    live.animate(car_line, bogie_line)

    def redraw(v):
        base = _CAR.replace(
            yaw_stiffness=1e6 * v["yaw_stiffness"],
            secondary_yaw_stiffness=1e6 * v["secondary_yaw_stiffness"],
        )
        car_v, bogie_v = [], []
        for lam in _CONICITIES:
            car = base.replace(conicity=lam)
            car_v.append(stability.critical_speed(car, (1.0, 200.0), tol=0.1, scan=16).speed)
            bogie_v.append(stability.critical_speed(car.bogie, (1.0, 200.0), tol=0.1, scan=16).speed)
        car_v, bogie_v = 3.6 * np.array(car_v), 3.6 * np.array(bogie_v)
        car_line.set_ydata(np.where(np.isfinite(car_v), car_v, np.nan))
        bogie_line.set_ydata(np.where(np.isfinite(bogie_v), bogie_v, np.nan))
        i = int(np.argmin(np.abs(_CONICITIES - 0.15)))
        status.value = f"at λ ≈ {_CONICITIES[i]:.2f}: car {car_v[i]:.0f} km/h, bogie {bogie_v[i]:.0f} km/h"

    return redraw


CRITICAL_CURVE = Recipe(
    lambda: {
        "yaw_stiffness": slider(
            "primary k_ψ (MN·m/rad)", _CAR.wheelset.yaw_stiffness / 1e6, 2.0, 120.0, 1.0, fmt=".0f"
        ),
        "secondary_yaw_stiffness": slider(
            "secondary k_ψ2 (MN·m/rad)", _CAR.bogie.secondary_yaw_stiffness / 1e6, 0.0, 2.0, 0.02
        ),
    },
    _critical_curve_setup,
    {"nrows": 1, "ncols": 1, "figsize": (7.0, 3.6)},
    static={"yaw_stiffness": [2.0, 5.0, 10.0, 20.0, 40.0, 63.0, 90.0, 120.0]},
    title="Critical speed of the car and of its bogie against conicity",
)


def critical_curve():
    """Critical speed against conicity for the Manchester car and for its bogie alone.

    Controls: primary yaw stiffness k_ψ of each wheelset (MN·m/rad) and the
    secondary yaw stiffness of each bogie (MN·m/rad). Speeds above 720 km/h
    (no crossing below 200 m/s) are left blank.
    """
    return CRITICAL_CURVE.build()


BENCH_MOVES = [
    ("ch07 car_roots λ", CAR_ROOTS, "conicity", [0.05, 0.1, 0.2, 0.3, 0.4, 0.15]),
    ("ch07 car_roots k_ψ", CAR_ROOTS, "yaw_stiffness", [5.0, 10.0, 20.0, 40.0, 80.0, 63.0]),
    ("ch07 critical_curve k_ψ", CRITICAL_CURVE, "yaw_stiffness", [5.0, 10.0, 20.0, 40.0, 80.0, 63.0]),
]
