"""Chapter 6 figures: car-body acceleration spectra and ride index against speed, and freight-car rocking."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from raildyn import plots, ride, track
from raildyn.figures import new_figure, register
from raildyn.vehicles import MANCHESTER_VERTICAL, VerticalFreightCar, response_spectrum, rock_and_roll


@register(
    "fig6.ride_spectra",
    "Vertical acceleration at the centre of the car body of the Manchester benchmark vehicle "
    "(Iwnicki 1998) on FRA class 4 track: PSD per Hz at 80, 100 and 120 km/h (left), within the "
    "80 mph (129 km/h) class 4 allows passenger trains, and Sperling's ride index Wz against speed "
    "(right) for FRA classes 3–6, each up to the passenger speed its class allows (49 CFR 213.9, "
    "213.307), and for the German spectra.",
    chapter=6,
)
def ride_spectra() -> Figure:
    fig = new_figure(figsize=(9.5, 3.8))
    ax_s, ax_w = fig.subplots(1, 2)
    vehicle = MANCHESTER_VERTICAL.linear_system()
    f = np.linspace(0.05, 30.0, 1500)
    w = 2 * np.pi * f
    for i, kmh in enumerate((80, 100, 120)):  # class 4 allows passenger trains up to 129 km/h
        spec = response_spectrum(vehicle, track.track_psd("fra", "vertical", 4), kmh / 3.6, w)
        spec.plot(ax_s, color=plots.COLORS[i], label=f"{kmh} km/h")
    ax_s.set_ylim(1e-6, 1.0)
    ax_s.legend()
    speeds = np.linspace(40.0, 200.0, 17)  # km/h
    grades = [("fra", c) for c in (3, 4, 5, 6)] + [("german", "high"), ("german", "low")]
    for i, (family, grade) in enumerate(grades):
        # an FRA class runs only as fast as it allows passenger trains; the German spectra have no class
        top = 3.6 * track.fra_speed_limit(grade) if family == "fra" else speeds[-1]
        kmh = np.append(speeds[speeds < top], top)
        wz = [
            ride.ride_quality(
                response_spectrum(vehicle, track.track_psd(family, "vertical", grade), v / 3.6, w).psd, w
            ).wz
            for v in kmh
        ]
        label = f"FRA {grade}" if family == "fra" else f"German {grade}"
        style = "-" if family == "fra" else "--"
        ax_w.plot(kmh, wz, style, color=plots.COLORS[i % 4], label=label)
    ax_w.set_xlabel("speed (km/h)")
    ax_w.set_ylabel("Sperling Wz")
    ax_w.legend(ncols=2, fontsize="small")
    return fig


@register(
    "fig6.rock_and_roll",
    "Steady roll amplitude of a loaded hopper car on friction-damped three-piece trucks over staggered "
    "11.9 m rails with 20 mm dipped joints, against speed, for three wedge friction forces; the dotted "
    "line marks the roll resonance of the springs alone, V = f_φ L.",
    chapter=6,
)
def rock_figure() -> Figure:
    fig = new_figure(figsize=(6.5, 3.8))
    ax = fig.subplots()
    speeds = np.linspace(20.0, 70.0, 16) / 3.6
    for i, friction in enumerate((2e3, 6e3, 15e3)):
        r = rock_and_roll(VerticalFreightCar(wedge_friction=friction), speeds, cycles=12)
        # the springs alone set the resonance, the same for every friction: marked once
        r.plot(ax, color=plots.COLORS[i], label=f"{friction / 1e3:.0f} kN per nest", resonance=i == 0)
    ax.legend()
    return fig
