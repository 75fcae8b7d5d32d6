"""Chapter 3 figures: the FRA and German track spectra, and jointed rail staggered or in phase."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from raildyn import plots, track
from raildyn.figures import new_figure, register


@register(
    "fig3.jointed_rail",
    "Jointed rail (rail length 11.9 m) with cusp-shaped dipped joints, depth 8 mm and half-width 2 m: "
    "joints staggered by half a rail length give a cross-level (roll) input alternating in sign at each "
    "joint; joints in phase give a pure bounce input and no cross-level.",
    chapter=3,
)
def jointed_rail() -> Figure:
    fig = new_figure(figsize=(8.0, 4.4))
    axes = fig.subplots(2, 1, sharex=True)
    L = track.RAIL_LENGTH
    x = np.linspace(0.0, 3 * L, 1500)
    for ax, arrangement in zip(axes, ("staggered", "in_phase"), strict=True):
        track.jointed_track(x, 0.008, 2.0, arrangement=arrangement).plot(ax)
        ax.set_title(f"joints {arrangement.replace('_', ' ')}")
        ax.set_ylim(-10, 10)
    axes[0].legend(loc="lower right", ncols=3)
    axes[0].set_xlabel("")
    axes[1].set_xlim(0, x[-1])
    return fig


__all__: list[str] = []  # registry plug-ins: reached through raildyn.figures.make/show, not by name


@register(
    "fig3.track_spectra",
    "One-sided spectra per rad/m of vertical profile (left) and cross-level (right) for the FRA track "
    "classes 1 (roughest) to 6 (Hamid & Yang 1981, k = 0.25) and the German low- and high-disturbance "
    "spectra; the dotted lines bound the wavelengths 1.524–304.8 m over which the FRA spectra were fitted.",
    chapter=3,
)
def track_spectra() -> Figure:
    fig = new_figure(figsize=(9.0, 3.8))
    axes = fig.subplots(1, 2, sharey=True)
    omega = np.geomspace(0.005, 20.0, 600)
    band = track.wavelength_band((1.524, 304.8))
    for ax, component, title in zip(
        axes, ("vertical", "cross_level"), ("vertical profile", "cross-level"), strict=True
    ):
        for c in track.FRA_CLASSES:
            shade = 0.15 + 0.12 * (c - 1)
            ax.loglog(
                omega,
                track.fra_psd(component, c, omega),
                color=(shade, shade, 0.55 + 0.07 * c),
                label=f"FRA class {c}",
            )
        for level, style in (("low", "--"), ("high", "-.")):
            ax.loglog(
                omega,
                track.german_psd(component, level, omega),
                ls=style,
                color=plots.COLORS[1],
                label=f"German {level}",
            )
        for edge in band:
            ax.axvline(edge, color="0.5", ls=":", lw=1)
        ax.set_title(title)
        ax.set_xlabel(r"wavenumber $\Omega$ (rad/m)")
    axes[0].set_ylabel(r"$S(\Omega)$ (m$^2$/(rad/m))")
    axes[0].set_ylim(1e-14, 10.0)
    axes[1].legend(loc="lower left", ncols=2)
    return fig
