"""Chapter 5 figures: Klingel's kinematic path, the roots of the free and suspended wheelset, hunting."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from raildyn import plots, stability, wheelset
from raildyn.figures import new_figure, register

# A wheelset on soft primary springs, whose hunting speed (about 54 m/s) lies in the plotted range.
_SOFT = wheelset.Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)


@register(
    "fig5.kinematic_oscillation",
    "Kinematic oscillation of a coned wheelset (Klingel) and of two wheelsets held parallel in a rigid "
    "bogie: r₀ = 0.46 m, a = 0.75 m, λ = 0.15, half wheelbase 1.28 m. The rigid frame lengthens the "
    "wave by √(1 + b²/a²).",
    chapter=5,
)
def klingel_path() -> Figure:
    k = wheelset.kinematic_oscillation(0.46, 0.75, 0.15, 1.28)
    fig = new_figure(figsize=(7.0, 3.0))
    ax = fig.subplots()
    chart = k.plot(ax)
    chart["free"].set_label(f"free wheelset, L = {k.wavelength:.2f} m")
    chart["bogie"].set_label(f"rigid bogie, L = {k.rigid_bogie_wavelength:.2f} m")
    ax.legend(loc="upper right")
    return fig


@register(
    "fig5.damping_against_speed",
    "Damping factor of the two modes of a wheelset against speed (modes followed by MAC): without "
    "suspension the kinematic mode is unstable at every speed; on primary springs "
    "(k_ψ = 2 MN·m/rad, k_y = 1 MN/m) it loses stability at the critical speed, marked.",
    chapter=5,
)
def wheelset_damping() -> Figure:
    speeds = np.linspace(2.0, 100.0, 300)
    fig = new_figure(figsize=(7.0, 3.4))
    ax = fig.subplots()
    for ws, style, name in ((_SOFT.free(), ":", "free"), (_SOFT, "-", "suspended")):
        sweep = stability.mode_sweep(ws, speeds)
        for j in range(2):
            ax.plot(
                speeds * 3.6,
                sweep.damping_ratios[:, j],
                style,
                color=plots.COLORS[j],
                label=f"{name}, mode {j + 1}",
            )
    cs = stability.critical_speed(_SOFT, (2.0, 100.0))
    ax.plot(cs.speed * 3.6, 0.0, "kv", ms=8, label=f"critical speed {cs.speed * 3.6:.0f} km/h")
    ax.axhline(0, color="k", lw=0.8)
    ax.set_ylim(-0.3, 1.05)
    ax.set_xlabel("speed (km/h)")
    ax.set_ylabel("damping factor ξ")
    ax.legend(loc="upper right", ncol=2)
    return fig


@register(
    "fig5.limit_cycle",
    "The nonlinear wheelset (cone λ = 0.15, saturating creep, flange beyond 9.1 mm) above its linear "
    "critical speed: from a 1 mm start the lateral motion grows into a limit cycle.",
    chapter=5,
)
def nonlinear_limit_cycle() -> Figure:
    model = wheelset.NonlinearWheelset(_SOFT, wheelset.WheelRailContact())
    run = stability.simulate(model, 60.0, [1e-3, 0.0, 0.0, 0.0], 4.0)
    fig = new_figure(figsize=(7.0, 3.0))
    run.plot(fig.subplots(), flange_clearance=model.contact.flange_clearance)
    return fig
