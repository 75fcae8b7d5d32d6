"""Chapter 1 figures: the root locus (book Fig. 1.4) and the underdamped decay (Fig. 1.5)."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from raildyn import vibration
from raildyn.figures import new_figure, register

__all__: list[str] = []  # registry plug-ins: reached through raildyn.figures.make/show, not by name


@register(
    "fig1.4",
    "Locus of the characteristic roots s₁, s₂ of an SDOF system as the damping factor ξ grows from 0: "
    "a quarter circle of radius ω_n while ξ < 1, the double root −ω_n at ξ = 1, then two real roots, "
    "one tending to 0 and the other to −∞.",
    chapter=1,
    book_figure="1.4",
)
def root_locus_figure() -> Figure:
    fig = new_figure(figsize=(5.5, 4.2))
    ax = fig.subplots()
    xi = np.r_[np.linspace(0.0, 1.0, 201), np.linspace(1.0, 4.0, 301)[1:]]
    vibration.root_locus(1.0, xi).plot(ax, normalised=True)
    for value in (0.0, 0.5, 1.0, 2.0):
        s = vibration.root_locus(1.0, [value]).roots[0]
        ax.plot(s.real, s.imag, "k.", ms=6)
        ax.annotate(f"ξ = {value:g}", (s[0].real, s[0].imag), textcoords="offset points", xytext=(6, 4))
    ax.set_xlim(-4.2, 0.6)
    ax.set_title("Roots of $s^2 + 2\\xi\\omega_n s + \\omega_n^2 = 0$")
    return fig


@register(
    "fig1.5",
    "Free response of an underdamped SDOF system (ξ = 0.1, ω_n = 2π rad/s, x₀ = 1, v₀ = 0) inside its "
    "envelope A e^{−ξω_n t}; the peaks x₁ and x₂ are one damped period T_d apart and ln(x₁/x₂) = δ.",
    chapter=1,
    book_figure="1.5",
)
def underdamped_response_figure() -> Figure:
    system = vibration.SDOF.from_modal(2 * np.pi, 0.1)
    response = system.free_vibration(np.linspace(0.0, 4.0, 1200), 1.0, 0.0, peaks=3)
    fig = new_figure(figsize=(6.5, 3.6))
    ax = fig.subplots()
    response.plot(ax)
    (t1, t2), (x1, x2) = response.peaks.times[1:], response.peaks.values[1:]  # clear of the axis
    ax.annotate("$x_1$", (t1, x1), textcoords="offset points", xytext=(4, 6))
    ax.annotate("$x_2$", (t2, x2), textcoords="offset points", xytext=(4, 6))
    ax.annotate("", (t1, -0.85), (t2, -0.85), arrowprops={"arrowstyle": "<->"})
    ax.text(0.5 * (t1 + t2), -0.8, "$T_d = 2\\pi/\\omega_d$", ha="center", va="bottom")
    ax.set_title(
        f"δ = ln(x₁/x₂) = {response.peaks.log_decrement:.4f};  2πξ/√(1−ξ²) = {system.log_decrement:.4f}"
    )
    return fig
