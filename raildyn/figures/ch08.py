"""Chapter 8 figures: the car's wheelsets in plan in a curve, Nadal's limit with the car's Y/Q, and a
bogie's entry into a curve.

Each chart is drawn by the method of its result in :mod:`raildyn.curving`
(:meth:`~raildyn.curving.steady.SteadyCurving.plot`, :meth:`~raildyn.curving.entry.CurveEntry.plot`,
:func:`~raildyn.curving.climb.plot_nadal_limit`), which the chapter's widgets call too. None of
them mirrors a numbered figure of the book.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from raildyn import plots
from raildyn.curving import climb, curve_entry, quasi_static_curving
from raildyn.figures import new_figure, register
from raildyn.track import Curve, balance_speed, cant_deficiency, speed_for_deficiency
from raildyn.vehicles import Bogie, LateralCar

_RADIUS = 600.0  # m
_CANT = 0.1  # m
_DEFICIENCY = 0.1  # m


@register(
    "fig8.curving_plan",
    "The Manchester car with saturating creep and flanges in a 600 m curve with 100 mm of cant, in "
    "quasi-static equilibrium, drawn in plan on the straightened track (offsets and angles of attack "
    "× 50; red: an axle on its flange): at the balance speed (top) and at 100 mm of cant deficiency "
    "(bottom). The leading wheelset of each bogie runs on its flange at a positive angle of attack; the "
    "trailing one rolls on its treads at a small negative angle of attack.",
    chapter=8,
)
def curving_plan() -> Figure:
    car = LateralCar().nonlinear()
    speeds = (
        balance_speed(_RADIUS, _CANT),
        speed_for_deficiency(_RADIUS, _CANT, _DEFICIENCY),
    )
    fig = new_figure(figsize=(10.0, 6.4))
    for ax, speed in zip(fig.subplots(2, 1, sharex=True), speeds, strict=True):
        state = quasi_static_curving(car, speed, _RADIUS, _CANT)
        chart = state.plot(ax)
        for axle, flanging in zip(chart["axles"], state.flange_contact, strict=True):
            axle.set_color(plots.COLORS[1] if flanging else plots.COLORS[0])
        deficiency = 1e3 * cant_deficiency(speed, _RADIUS, _CANT)
        ax.set_title(
            f"{3.6 * speed:.0f} km/h, cant deficiency {abs(deficiency):.0f} mm: "
            f"leading outer wheel Y/Q = {state.derailment_quotient[0, 1]:.2f}",
            fontsize="medium",
        )
    return fig


@register(
    "fig8.nadal_limit",
    "Nadal's limit of the flanging wheel's L/V against the flange angle for three coefficients of "
    "friction at the flange, with the Manchester car's leading outer wheel Y/Q (quasi-static, 70° "
    "flange angle, 100 mm of cant) in a 600 m curve at the balance speed and at 100 mm of cant "
    "deficiency, and in a 300 m curve at 100 mm of deficiency: far below every limit.",
    chapter=8,
)
def nadal_limit() -> Figure:
    car = LateralCar().nonlinear()
    fig = new_figure(figsize=(6.5, 4.0))
    ax = fig.subplots()
    climb.plot_nadal_limit(ax, friction=(0.1, 0.3, 0.5))
    delta = 70.0  # deg, quasi_static_curving's default flange angle
    cases = (
        (_RADIUS, balance_speed(_RADIUS, _CANT), "600 m, balance speed", "o"),
        (
            _RADIUS,
            speed_for_deficiency(_RADIUS, _CANT, _DEFICIENCY),
            "600 m, 100 mm deficiency",
            "s",
        ),
        (300.0, speed_for_deficiency(300.0, _CANT, _DEFICIENCY), "300 m, 100 mm deficiency", "D"),
    )
    for radius, speed, label, marker in cases:
        state = quasi_static_curving(car, speed, radius, _CANT, flange_angle=np.radians(delta))
        ax.plot(
            [delta],
            [state.derailment_quotient[0, 1]],
            marker,
            color="k",
            mfc="white",
            ms=7,
            label=f"car: {label}, {3.6 * speed:.0f} km/h",
        )
    ax.set_ylim(0.0, 3.0)
    ax.legend(fontsize=8, loc="upper left")
    return fig


@register(
    "fig8.curve_entry",
    "The Manchester car's bogie with saturating creep and flanges entering a 600 m curve with 100 mm "
    "of cant by a 50 m clothoid with a linear cant ramp, at 100 km/h (97 mm of cant deficiency): each "
    "wheelset's flange force (left) and angle of attack (right) against the distance of the bogie's "
    "centre, the ends of the transition dotted, and the quasi-static values dashed. The leading "
    "wheelset takes up its flange force along the transition and settles on the arc to the "
    "quasi-static equilibrium.",
    chapter=8,
)
def curve_entry_figure() -> Figure:
    bogie = Bogie().nonlinear()
    curve = Curve(radius=_RADIUS, cant=_CANT, transition_length=50.0, arc_length=30.0, straight=0.0)
    speed = 100.0 / 3.6
    run = curve_entry(bogie, speed, curve)
    state = quasi_static_curving(bogie, speed, _RADIUS, _CANT)
    fig = new_figure(figsize=(11.0, 3.6))
    for ax, quantity, scale in zip(
        fig.subplots(1, 2), ("flange_force", "angle_of_attack"), (1e-3, 1e3), strict=True
    ):
        chart = run.plot(ax, quantity=quantity)
        for k, (line, value) in enumerate(zip(chart["lines"], getattr(state, quantity), strict=True)):
            ax.axhline(
                scale * value,
                ls="--",
                lw=1.0,
                color=line.get_color(),
                label="quasi-static" if k == 0 else None,
            )
        ax.set_xlim(run.distance[0], run.distance[-1])
        ax.legend(fontsize=8, loc="center left")
    return fig
