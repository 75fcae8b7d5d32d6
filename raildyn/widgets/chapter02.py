"""Chapter 2 widgets: a scheme's SDOF response against the exact one, and its accuracy chart.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are :mod:`raildyn.integrators` and :class:`raildyn.vibration.SDOF`; this
module only turns control values into model calls and moves artists.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from raildyn import integrators, plots, vibration
from raildyn.widgets._core import Recipe, slider

# Readable names for the dropdowns, in the order the chapter introduces the schemes.
LABELS = {
    "central_difference": "central difference",
    "houbolt": "Houbolt",
    "wilson": "Wilson θ = 1.4",
    "average_acceleration": "Newmark, average acceleration",
    "linear_acceleration": "Newmark, linear acceleration",
    "hht_alpha": "HHT-α, α = −0.05",
    "forward_euler": "forward Euler",
    "rk4": "Runge–Kutta 4",
    "abm": "Adams–Bashforth–Moulton 4",
}

_DURATION = 5.0  # s: five periods of the T = 1 s oscillator
_RATIOS = np.logspace(-2, 0, 160)  # Δt/T on the spectral-radius axis


def _scheme_dropdown(value: str) -> widgets.Dropdown:
    return widgets.Dropdown(
        options=[(label, name) for name, label in LABELS.items()],
        value=value,
        description="scheme",
        style={"description_width": "initial"},
        layout=widgets.Layout(width="360px"),
    )


def _scheme_response_controls():
    return {
        "method": _scheme_dropdown("central_difference"),
        "dt_over_T": slider("Δt/T", 0.1, 0.01, 0.6, 0.01),
        "damping_ratio": slider("damping factor ξ", 0.0, 0.0, 0.2, 0.01),
    }


def _scheme_response_setup(live, status):
    ax_t, ax_r = live.axes[0]
    system_t = np.linspace(0.0, _DURATION, 1001)
    exact = plots.time_history(system_t, np.cos(2 * np.pi * system_t), ax=ax_t, label="exact", color="0.55")
    (numeric,) = ax_t.plot([], [], "o-", color=plots.COLORS[1], ms=3, lw=1.2, label="scheme")
    ax_t.set_xlim(0, _DURATION)
    ax_t.set_ylim(-2.0, 2.0)
    ax_t.set_ylabel("displacement $x/x_0$")
    ax_t.set_title("free vibration, T = 1 s, $x_0 = 1$, $v_0 = 0$")
    ax_t.legend(loc="upper right")
    (rho,) = ax_r.semilogx(_RATIOS, np.ones_like(_RATIOS), color=plots.COLORS[0])
    (mark,) = ax_r.plot([0.1], [1.0], "o", color=plots.COLORS[1], ms=7)
    ax_r.axhline(1.0, color="0.4", lw=0.8, ls=":")
    ax_r.set_xlim(_RATIOS[0], _RATIOS[-1])
    ax_r.set_ylim(0.0, 1.6)
    ax_r.set_xlabel(r"$\Delta t/T$")
    ax_r.set_ylabel(r"spectral radius $\rho(A)$")
    live.animate(exact["line"], numeric, rho, mark)

    def redraw(v):
        name, ratio, xi = v["method"], v["dt_over_T"], v["damping_ratio"]
        system = vibration.SDOF.from_modal(2 * np.pi, xi)
        exact["line"].set_ydata(system.free_response(system_t, 1.0, 0.0))
        t = np.arange(int(np.floor(_DURATION / ratio + 1e-9)) + 1) * ratio
        run = integrators.integrate(
            name, 1.0, system.damping, system.stiffness, t, 1.0, 0.0, on_divergence="stop"
        )
        x = run.x[0]
        numeric.set_data(run.t, np.clip(x, -10.0, 10.0))  # far outside the axes but finite for Agg
        curve = integrators.spectral_radius(name, _RATIOS, xi)
        rho.set_ydata(np.minimum(curve, 10.0))
        here = float(integrators.spectral_radius(name, ratio, xi))
        mark.set_data([ratio], [min(here, 1.58)])
        error = np.abs(x - system.free_response(run.t, 1.0, 0.0)).max()
        text = f"<b>{LABELS[name]}</b> · Δt/T = {ratio:.2f} · ρ = {here:.4f}"
        if run.success:
            pe = integrators.period_elongation(name, ratio, xi)
            ad = integrators.amplitude_decay(name, ratio, xi)
            pe_text = "no oscillation" if np.isnan(pe) else f"{100 * pe:+.2f} %"
            text += (
                f" · largest error over 5 periods {error:.3g} x₀ · period elongation {pe_text}"
                f" · amplitude decay per period {100 * ad:+.2f} %"
            )
        else:
            text += f" · <b>unstable</b>: diverged at step {run.steps + 1} (t = {run.t[-1]:.2f} s)"
        status.value = text

    return redraw


SCHEME_RESPONSE = Recipe(
    _scheme_response_controls,
    _scheme_response_setup,
    {"nrows": 1, "ncols": 2, "figsize": (9.5, 3.6), "gridspec_kw": {"width_ratios": [1.7, 1]}},
    static={"dt_over_T": [0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.33, 0.4, 0.5]},
    title="A time-integration scheme on the SDOF oscillator against the exact response",
)


def scheme_response():
    """Free vibration of the T = 1 s oscillator by a chosen scheme beside the exact response.

    Controls: scheme, step Δt/T and damping factor ξ. Left: x(t)/x₀ over five
    periods (grey: exact, red: the scheme's samples); right: the spectral radius
    of the scheme against Δt/T with the current step marked. The status line
    gives the largest error, the period elongation and the amplitude decay, or
    the step at which an unstable run blew up.
    """
    return SCHEME_RESPONSE.build()


def _accuracy_chart_setup(live, status):
    ax_rho, ax_pe, ax_ad = live.axes[0]
    ratios = np.linspace(0.005, 0.4, 160)
    for ax in (ax_rho, ax_pe, ax_ad):
        ax.set_xlim(0, ratios[-1])
        ax.set_xlabel(r"$\Delta t/T$")
    # Grey reference: the average acceleration method (ρ = 1, no decay).
    ax_pe.plot(
        ratios, 100 * integrators.period_elongation("average_acceleration", ratios), color="0.75", lw=1
    )
    ax_rho.axhline(1.0, color="0.4", lw=0.8, ls=":")
    (rho,) = ax_rho.plot(ratios, np.ones_like(ratios), color=plots.COLORS[0])
    (pe,) = ax_pe.plot(ratios, np.zeros_like(ratios), color=plots.COLORS[1])
    (ad,) = ax_ad.plot(ratios, np.zeros_like(ratios), color=plots.COLORS[2])
    ax_rho.set_ylim(0.0, 1.6)
    ax_rho.set_ylabel(r"spectral radius $\rho(A)$")
    ax_pe.set_ylim(-30, 60)
    ax_pe.set_ylabel("period elongation (%)")
    ax_ad.set_ylim(-20, 60)
    ax_ad.set_ylabel("amplitude decay per period (%)")
    live.animate(rho, pe, ad)

    def redraw(v):
        name, xi = v["method"], v["damping_ratio"]
        curve = integrators.spectral_radius(name, ratios, xi)
        rho.set_ydata(np.minimum(curve, 10.0))
        pe.set_ydata(100 * integrators.period_elongation(name, ratios, xi))
        ad.set_ydata(np.clip(100 * integrators.amplitude_decay(name, ratios, xi), -1e3, 1e3))
        limit = integrators.stability_limit(name, xi)
        if np.isinf(limit):
            rule = "unconditionally stable"
        elif limit == 0:
            rule = "unstable at every step (ρ > 1)"
        else:
            rule = f"stable for Δt/T ≤ {limit:.4f}"
        status.value = f"<b>{LABELS[name]}</b>, ξ = {xi:.2f}: {rule} · grey: average acceleration"

    return redraw


ACCURACY_CHART = Recipe(
    lambda: {
        "method": _scheme_dropdown("wilson"),
        "damping_ratio": slider("damping factor ξ", 0.0, 0.0, 0.2, 0.01),
    },
    _accuracy_chart_setup,
    {"nrows": 1, "ncols": 3, "figsize": (10.0, 3.3)},
    static={"method": list(LABELS)},
    title="Spectral radius, period elongation and amplitude decay of a scheme against Δt/T",
)


def accuracy_chart():
    """Spectral radius, period elongation and amplitude decay of a chosen scheme against Δt/T.

    The three accuracy measures of Bathe's Figs. 9.2–9.3 for one scheme at a time,
    with the damping factor ξ of the oscillator as a second control; the status
    line gives the stability limit found on the amplification matrix.
    """
    return ACCURACY_CHART.build()
