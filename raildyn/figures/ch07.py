"""Chapter 7 figures: the car's roots against speed, a critical-speed map and a bifurcation diagram."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from raildyn import plots, stability
from raildyn.figures import new_figure, register
from raildyn.vehicles import Car


@register(
    "fig7.1",
    "Manchester benchmark car on a cone (λ = 0.15): the roots of its 15 coordinates from 18 to 540 km/h "
    "(left, coloured by speed) and the damping factor of every mode against speed (right); the hunting "
    "mode crosses zero at the linear critical speed.",
    chapter=7,
)
def car_roots() -> Figure:
    system = Car().linear_system()
    speeds = np.linspace(5.0, 150.0, 200)
    sweep = stability.mode_sweep(system, speeds)
    cs = stability.critical_speed(system, (5.0, 150.0))
    fig = new_figure(figsize=(10.0, 3.8))
    ax_s, ax_d = fig.subplots(1, 2)
    lam = sweep.eigenvalues
    art = ax_s.scatter(lam.real.ravel(), lam.imag.ravel(), s=2, c=np.repeat(speeds * 3.6, lam.shape[1]))
    fig.colorbar(art, ax=ax_s, label="speed (km/h)")
    ax_s.axvline(0, color="k", lw=0.8)
    ax_s.set_xlim(-25, 5)
    ax_s.set_ylim(0, 70)
    ax_s.set_xlabel("Re λ (1/s)")
    ax_s.set_ylabel("Im λ (rad/s)")
    worst = int(np.argmin(sweep.damping_ratios[-1]))
    for j in range(lam.shape[1]):
        ax_d.plot(speeds * 3.6, sweep.damping_ratios[:, j], color="0.75", lw=0.8)
    ax_d.plot(speeds * 3.6, sweep.damping_ratios[:, worst], color=plots.COLORS[1], lw=2, label="hunting mode")
    ax_d.plot(cs.speed * 3.6, 0, "kv", ms=8, label=f"V_c = {cs.speed * 3.6:.0f} km/h ({cs.frequency:.2f} Hz)")
    ax_d.axhline(0, color="k", lw=0.8)
    ax_d.set_ylim(-0.15, 0.5)
    ax_d.set_xlabel("speed (km/h)")
    ax_d.set_ylabel("damping factor ξ")
    ax_d.legend(loc="upper right")
    return fig


@register(
    "fig7.2",
    "Linear critical speed of the Manchester car against conicity and the primary yaw stiffness of each "
    "wheelset; the published stiffness (62.8 MN·m/rad) is dashed.",
    chapter=7,
)
def critical_speed_map() -> Figure:
    car = Car()
    conicity = np.linspace(0.05, 0.5, 8)
    stiffness = np.geomspace(2e6, 1.2e8, 8)
    result = stability.critical_speed_map(
        lambda lam, k: car.replace(conicity=lam, yaw_stiffness=k),
        conicity,
        stiffness,
        (1.0, 200.0),
        x_name="λ",
        y_name="k_ψ",
        tol=0.1,
        progress=False,
    )
    fig = new_figure(figsize=(6.5, 4.0))
    ax = fig.subplots()
    levels = np.arange(50, 751, 50)
    cs = ax.contourf(
        result.x, result.y / 1e6, np.minimum(result.speeds * 3.6, 750), levels=levels, cmap="viridis"
    )
    fig.colorbar(cs, ax=ax, label="critical speed (km/h)")
    ax.axhline(car.wheelset.yaw_stiffness / 1e6, color="w", ls="--")
    ax.set_yscale("log")
    ax.set_xlabel("conicity λ")
    ax.set_ylabel("primary yaw stiffness $k_\\psi$ (MN·m/rad)")
    return fig


@register(
    "fig7.3",
    "Bifurcation diagram of the Manchester car on a cone (λ = 0.15, saturating creep, flange beyond "
    "9.1 mm): amplitude of the leading wheelset's lateral motion along a speed ramp-down (filled: "
    "sustained hunting; open: decaying), with the linear and nonlinear critical speeds. The car hunts "
    "on its flanges well below the linear critical speed.",
    chapter=7,
)
def bifurcation() -> Figure:
    car = Car()
    diagram = stability.bifurcation_diagram(
        car.nonlinear(), np.linspace(50.0, 95.0, 6), duration=5.0, refine=2, progress=False
    )
    linear = stability.critical_speed(car, (5.0, 150.0))
    fig = new_figure(figsize=(6.5, 3.6))
    ax = fig.subplots()
    V, amp, hunt = diagram.speeds * 3.6, diagram.amplitudes * 1e3, diagram.hunting
    ax.plot(V[hunt], amp[hunt], "o-", color=plots.COLORS[0], label="limit cycle")
    ax.plot(V[~hunt], amp[~hunt], "o", mfc="none", color=plots.COLORS[0], label="motion dies away")
    ax.axvline(
        linear.speed * 3.6, color=plots.COLORS[1], ls="--", label=f"linear V_c {linear.speed * 3.6:.0f} km/h"
    )
    ax.axvline(
        diagram.nonlinear_critical_speed * 3.6,
        color=plots.COLORS[2],
        ls=":",
        label=f"nonlinear V_c {diagram.nonlinear_critical_speed * 3.6:.0f} km/h",
    )
    ax.set_xlabel("speed (km/h)")
    ax.set_ylabel("amplitude of $y$ (mm)")
    ax.legend(loc="center right")
    return fig
