"""Chapter 9 figures: resistance and tractive effort, quasi-static coupler forces, draft-gear hysteresis."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from raildyn import plots, train
from raildyn.figures import new_figure, register


@register(
    "fig9.tractive_effort",
    "Tractive effort of one SD40-2 by notch (adhesion-limited at low speed, constant power above) against "
    "the Davis resistance of 2 SD40-2 + 100 loaded hoppers on level track, original and modified (AREA) "
    "forms; where the curves cross is the balancing speed.",
    chapter=9,
)
def traction_and_resistance() -> Figure:
    loco = train.VEHICLES["SD40-2"]
    consist = train.make_consist("2 SD40-2 + 100 loaded hopper")
    v = np.linspace(0.0, 30.0, 301)
    fig = new_figure(figsize=(6.5, 3.8))
    ax = fig.subplots()
    for k, notch in enumerate((2, 4, 6, 8)):
        effort = 2 * train.tractive_effort(v, notch, loco.max_tractive_effort, loco.rail_power)
        ax.plot(
            3.6 * v,
            effort / 1e3,
            color=plots.COLORS[0],
            alpha=0.4 + 0.2 * k,
            label=f"2 × SD40-2, notch {notch}",
        )
    for form, style in (("original", "-"), ("modified", "--")):
        total = sum(
            train.davis_resistance(v, u.mass, u.axles, u.frontal_area, kind=u.kind, form=form)
            for u in consist.vehicles
        )
        ax.plot(3.6 * v, total / 1e3, style, color=plots.COLORS[1], label=f"train resistance, {form} Davis")
    ax.set_ylim(0, 1100)
    ax.set_xlabel("speed (km/h)")
    ax.set_ylabel("force (kN)")
    ax.legend(loc="upper right", ncols=2)
    return fig


@register(
    "fig9.draft_gear_loop",
    "Force–deflection loop of a friction draft gear beyond its slack: the loading branch, the drop to the "
    "unloading branch at the largest deflection, and the energy absorbed (the shaded area, (k_l − k_u)U²/2).",
    chapter=9,
)
def draft_gear_loop() -> Figure:
    gear = train.DraftGear()
    fig = new_figure(figsize=(5.5, 3.6))
    ax = fig.subplots()
    loop = gear.static_loop(0.06)
    loop.plot(ax)
    d = np.linspace(-0.1, 0.1, 801)
    ax.plot(
        1e3 * gear.deflection(d),
        np.abs(gear.force(d, np.sign(d))) / 1e3,
        color="0.6",
        lw=0.8,
    )
    ax.set_title(f"energy absorbed {loop.energy / 1e3:.1f} kJ per cycle to 60 mm")
    return fig


@register(
    "fig9.coupler_forces",
    "Quasi-static coupler forces along 2 SD40-2 + 100 loaded hoppers (1.66 km) at 30 km/h and notch 8 with "
    "the front 800 m past a change of grade: on level track, over a crest (+0.5 % then −0.5 %) and through a "
    "sag (−0.5 % then +0.5 %). A uniform grade only changes the common acceleration; a change of grade "
    "under the train moves force between the two parts.",
    chapter=9,
)
def quasi_static_forces() -> Figure:
    consist = train.make_consist("2 SD40-2 + 100 loaded hopper")
    fig = new_figure(figsize=(6.5, 3.6))
    ax = fig.subplots()
    routes = {
        "level": train.Route.level(),
        "crest": train.Route((0.0, 1000.0), (0.005, -0.005)),
        "sag": train.Route((0.0, 1000.0), (-0.005, 0.005)),
    }
    for k, (name, route) in enumerate(routes.items()):
        model = train.TrainModel(consist, route=route, notch=8, front_start=1800.0)
        qs = model.quasi_static(30 / 3.6)
        qs.plot(ax, label=f"{name}, a = {qs.acceleration:+.3f} m/s²", color=plots.COLORS[k])
    ax.axhline(0, color="0.4", lw=0.8)
    ax.axvline(800.0, color="0.6", ls=":", lw=1)
    ax.legend(loc="upper right")
    return fig
