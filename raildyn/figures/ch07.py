"""Chapter 7 figures: a critical-speed map, a bifurcation diagram and the car's roots against speed (the
notebook shows the roots with the widget that draws the same picture, so that one comes last).

Each chart is drawn by the method of its result in :mod:`raildyn.stability`
(:meth:`~raildyn.stability.linear.ModeSweep.plot`, :meth:`~raildyn.stability.linear.CriticalSpeedMap.plot`,
:meth:`~raildyn.stability.bifurcation.BifurcationDiagram.plot`), which the chapter's widgets call too.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from raildyn import stability
from raildyn.figures import new_figure, register
from raildyn.vehicles import LateralCar


@register(
    "fig7.critical_speed_map",
    "Linear critical speed of the Manchester car against conicity and the primary yaw stiffness of each "
    "wheelset; the published stiffness (62.8 MN·m/rad) is dashed.",
    chapter=7,
)
def critical_speed_map() -> Figure:
    car = LateralCar()
    conicity = np.linspace(0.05, 0.5, 8)
    stiffness = np.geomspace(2.0, 120.0, 8)  # MN·m/rad
    result = stability.critical_speed_map(
        lambda lam, k: car.replace(conicity=lam, yaw_stiffness=1e6 * k),
        conicity,
        stiffness,
        (1.0, 200.0),
        x_name="conicity λ",
        y_name="primary yaw stiffness $k_\\psi$ (MN·m/rad)",
        tol=0.1,
        progress=False,
    )
    fig = new_figure(figsize=(6.5, 4.0))
    ax = fig.subplots()
    result.plot(ax, levels=np.arange(50, 751, 50))
    ax.axhline(car.wheelset.yaw_stiffness / 1e6, color="w", ls="--")
    ax.set_yscale("log")
    return fig


@register(
    "fig7.bifurcation",
    "Bifurcation diagram of the Manchester car on a cone (λ = 0.15, saturating creep, flange beyond "
    "9.1 mm): amplitude of the leading wheelset's lateral motion along a speed ramp-down (filled: "
    "sustained hunting; open: decaying), with the linear and nonlinear critical speeds. The car hunts "
    "on its flanges well below the linear critical speed.",
    chapter=7,
)
def bifurcation() -> Figure:
    car = LateralCar()
    # The full ramp (11 speeds, 8 s each, 4 bisections): half a second on the compiled engine.
    diagram = stability.bifurcation_diagram(car.nonlinear(), np.linspace(50.0, 100.0, 11), progress=False)
    linear = stability.critical_speed(car, (5.0, 150.0))
    fig = new_figure(figsize=(6.5, 3.6))
    diagram.plot(fig.subplots(), linear_critical_speed=linear.speed)
    return fig


@register(
    "fig7.root_locus",
    "Manchester benchmark car on a cone (λ = 0.15): the roots of its 15 coordinates from 18 to 540 km/h "
    "(left, coloured by speed) and the damping factor of every mode against speed (right); the hunting "
    "mode crosses zero at the linear critical speed.",
    chapter=7,
)
def car_roots() -> Figure:
    system = LateralCar().linear_system()
    speeds = np.linspace(5.0, 150.0, 200)
    sweep = stability.mode_sweep(system, speeds)
    cs = stability.critical_speed(system, (5.0, 150.0))
    fig = new_figure(figsize=(10.0, 3.8))
    sweep.plot(fig.subplots(1, 2), critical=cs)
    return fig
