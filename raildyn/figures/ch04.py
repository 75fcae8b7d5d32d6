"""Chapter 4 figures: Hertz's m and n, the creep laws side by side, FASTSIM zones, profile geometry."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from raildyn import contact, plots
from raildyn.figures import new_figure, register

__all__: list[str] = []  # registry plug-ins: reached through raildyn.figures.make/show, not by name

# Every elastic constant is the default of raildyn.contact: the steel of raildyn.constants.


@register(
    "fig4.hertz",
    "Hertz's coefficients m and n against the angle θ, computed from the complete elliptic integrals, "
    "with the points of the classic table (Timoshenko & Goodier; Garg & Dukkipati ch. 4).",
    chapter=4,
)
def hertz_coefficients_figure() -> Figure:
    fig = new_figure(figsize=(5.5, 3.8))
    ax = fig.subplots()
    theta = np.linspace(5.0, 90.0, 341)
    coefficients = contact.hertz_coefficients(np.radians(theta))
    m, n = coefficients.m, coefficients.n
    ax.plot(theta, m, color=plots.COLORS[0], label="m")
    ax.plot(theta, n, color=plots.COLORS[1], label="n")
    table = {30: (2.731, 0.493), 45: (1.926, 0.604), 60: (1.486, 0.717), 75: (1.202, 0.846), 90: (1.0, 1.0)}
    ax.plot(
        list(table), [v[0] for v in table.values()], "o", color=plots.COLORS[0], mfc="none", label="table"
    )
    ax.plot(list(table), [v[1] for v in table.values()], "o", color=plots.COLORS[1], mfc="none")
    ax.set_yscale("log")
    ax.set_xlabel("θ (deg), cos θ = |B − A|/(A + B)")
    ax.set_ylabel("m, n")
    ax.legend()
    return fig


@register(
    "fig4.creep",
    "Lateral creep force against lateral creepage for a_c = 6 mm, b_c = 4 mm, N = 100 kN, μ = 0.3, no spin: "
    "Kalker's linear theory, Carter's 2-D law with Kalker's initial slope, Johnson–Vermeulen with its own "
    "(steeper) creep coefficients, the saturation of Shen, Hedrick and Elkins (Johnson–Vermeulen's cubic on "
    "Kalker's forces), Polach's method and FASTSIM.",
    chapter=4,
)
def creep_laws_figure() -> Figure:
    curves = contact.lateral_creep_curves(np.linspace(0, 0.01, 201), 100e3, 0.3, 6e-3, 4e-3)
    fig = new_figure(figsize=(6.0, 4.0))
    curves.plot(fig.subplots())
    return fig


@register(
    "fig4.adhesion",
    "Adhesion coefficient −F_x/N against longitudinal creepage by Polach's (2005) method with the "
    "parameters fitted to dry and to wet rail (friction falling with slip speed), at 10 and 30 m/s; "
    "a_c = 6 mm, b_c = 4 mm, N = 100 kN.",
    chapter=4,
)
def adhesion_figure() -> Figure:
    a, b, load = 6e-3, 4e-3, 100e3
    xi = np.geomspace(1e-4, 0.3, 300)
    fig = new_figure(figsize=(6.0, 4.0))
    ax = fig.subplots()
    for i, (name, cond) in enumerate((("dry", contact.POLACH_DRY), ("wet", contact.POLACH_WET))):
        for speed, style in ((10.0, "-"), (30.0, "--")):
            fx = contact.polach_adhesion(xi, 0.0, 0.0, load, speed, a, b, cond).fx
            ax.plot(
                100 * xi,
                -np.asarray(fx) / load,
                style,
                color=plots.COLORS[i],
                label=f"{name}, {speed:.0f} m/s",
            )
    ax.set_xscale("log")
    ax.set_xlabel("longitudinal creepage γ_x (%)")
    ax.set_ylabel("adhesion coefficient −F_x/N")
    ax.legend()
    return fig


@register(
    "fig4.fastsim",
    "FASTSIM traction over the contact ellipse (a_c = 6 mm, b_c = 4 mm, N = 100 kN, μ = 0.3) for γ_x = 1 ‰, "
    "γ_y = 0.5 ‰: adhesion at the leading edge (right), slip at the trailing edge.",
    chapter=4,
)
def fastsim_figure() -> Figure:
    r = contact.fastsim(1e-3, 0.5e-3, 0.0, 100e3, 0.3, 6e-3, 4e-3, n_x=24, n_y=24)
    fig = new_figure(figsize=(6.0, 3.8))
    ax = fig.subplots()
    r.plot_patch(ax)
    ax.set_title(f"F_x = {r.fx / 1e3:.1f} kN, F_y = {r.fy / 1e3:.1f} kN")
    return fig


@register(
    "fig4.profiles",
    "Rolling-radius difference Δr(y) and equivalent conicity λ_e(ŷ) (EN 15302) of the 1:20 and 1:40 cones "
    "and of S1002 on 60E1 rails inclined at 1:40 (gauge 1435 mm, tape circles 1500 mm apart).",
    chapter=4,
)
def profiles_figure() -> Figure:
    rail = contact.uic60_rail(1 / 40)
    wheels = [contact.conical_wheel(1 / 20), contact.conical_wheel(1 / 40), contact.s1002_wheel()]
    y = np.linspace(-10e-3, 10e-3, 401)
    amp = np.linspace(0.5e-3, 10e-3, 39)
    fig = new_figure(figsize=(8.0, 3.4))
    ax_r, ax_l = fig.subplots(1, 2)
    for i, wheel in enumerate(wheels):
        geometry = contact.contact_geometry(wheel, rail, y)
        geometry.plot_rolling_radius_difference(ax_r, label=wheel.name, color=plots.COLORS[i])
        geometry.plot_equivalent_conicity(amp, ax_l, label=wheel.name, color=plots.COLORS[i])
    ax_r.legend()
    return fig


@register(
    "fig4.conicity",
    "Equivalent conicity of S1002 on 60E1 rails inclined at 1:40 (gauge 1435 mm) against the amplitude: "
    "EN 15302's kinematic value (solid) and the first harmonic of Δr (dashed), with Δr(y) beside them. "
    "The two part where Δr jumps.",
    chapter=4,
)
def conicity_figure() -> Figure:
    geometry = contact.contact_geometry(
        contact.s1002_wheel(), contact.uic60_rail(1 / 40), np.linspace(-10e-3, 10e-3, 801)
    )
    amp = np.linspace(0.5e-3, 10e-3, 96)
    harmonic = contact.harmonic_conicity(geometry.shift, geometry.rolling_radius_difference, amp)
    fig = new_figure(figsize=(8.0, 3.4))
    ax_r, ax_l = fig.subplots(1, 2)
    geometry.plot_rolling_radius_difference(ax_r, color=plots.COLORS[2])
    geometry.plot_equivalent_conicity(amp, ax_l, label="EN 15302 (kinematic)", color=plots.COLORS[0])
    ax_l.plot(1e3 * amp, harmonic, "--", color=plots.COLORS[1], label="first harmonic")
    ax_l.legend()
    return fig
