"""Chapter 2 figures: spectral radius, period elongation and amplitude decay of the schemes against Δt/T.

The companion's version of the accuracy plots of Bathe, *Finite Element
Procedures* (1996), Figs. 9.2 and 9.3, computed from the amplification matrices of
:mod:`raildyn.integrators` and drawn by :class:`raildyn.integrators.SchemeAccuracy`,
whose methods the chapter 2 widgets call too.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from raildyn import integrators, plots
from raildyn.figures import new_figure, register

# The schemes drawn, with their labels, in one colour each.
_SCHEMES = {
    "central_difference": "central difference",
    "houbolt": "Houbolt",
    "wilson": "Wilson θ = 1.4",
    "average_acceleration": "Newmark, average acceleration",
    "hht_alpha": "HHT-α, α = −0.05",
    "rk4": "Runge–Kutta 4",
}
_STYLES = dict(zip(_SCHEMES, [*plots.COLORS, "0.3"], strict=True))


@register(
    "fig2.spectral_radius",
    "Spectral radius ρ(A) of the amplification matrix of each scheme against Δt/T for the undamped "
    "oscillator: the central difference and Runge–Kutta 4 leave ρ = 1 at Δt/T = 1/π and √2/π and become "
    "unstable; Houbolt, Wilson θ = 1.4 and HHT-α stay below 1 at every step, the average acceleration "
    "method sits on ρ = 1 (after Bathe 1996, Fig. 9.2).",
    chapter=2,
)
def spectral_radius_figure() -> Figure:
    fig = new_figure(figsize=(6.5, 4.0))
    ax = fig.subplots()
    ratios = np.logspace(-2, 2, 400)
    for name, label in _SCHEMES.items():
        integrators.scheme_accuracy(name, ratios).plot_spectral_radius(ax, color=_STYLES[name], label=label)
    ax.set_xscale("log")
    ax.axhline(1.0, color="0.4", lw=0.8, ls=":")
    ax.axvline(1 / np.pi, color=_STYLES["central_difference"], lw=0.8, ls="--")
    ax.set_ylim(0.0, 1.6)
    ax.legend(loc="lower left", ncols=2)
    return fig


@register(
    "fig2.period_elongation",
    "Period elongation (T̄ − T)/T and amplitude decay per period of each scheme against Δt/T for the "
    "undamped oscillator (after Bathe 1996, Fig. 9.3). The central difference shortens the period; the "
    "implicit schemes lengthen it; only Houbolt, Wilson-θ and HHT-α damp the motion numerically.",
    chapter=2,
)
def accuracy_figure() -> Figure:
    fig = new_figure(figsize=(9.0, 3.8))
    ax_pe, ax_ad = fig.subplots(1, 2)
    ratios = np.linspace(0.002, 0.3, 300)
    for name, label in _SCHEMES.items():
        if name == "rk4":
            continue
        chart = integrators.scheme_accuracy(name, ratios)
        chart.plot_period_elongation(ax_pe, color=_STYLES[name], label=label)
        chart.plot_amplitude_decay(ax_ad, color=_STYLES[name], label=label)
    for ax in (ax_pe, ax_ad):
        ax.set_xlim(0, 0.3)
    ax_pe.set_ylim(-30, 40)
    ax_ad.set_ylim(-2, 60)
    ax_pe.legend(loc="upper left")
    return fig
