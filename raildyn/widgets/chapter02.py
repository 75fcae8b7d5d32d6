"""Chapter 2 widgets: a scheme's SDOF response against the exact one, and its accuracy chart.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are :mod:`raildyn.integrators` and :class:`raildyn.vibration.SDOF`; this
module only turns control values into model calls and moves artists. The accuracy
curves are drawn, and redrawn in place, by the methods of
:class:`raildyn.integrators.SchemeAccuracy` that the chapter's figures call too. A
scheme that blows up raises :class:`raildyn.errors.SolverError`; the widget draws
the part of the run completed before (the error's ``partial``).
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from raildyn import integrators, plots, vibration
from raildyn.errors import SolverError
from raildyn.widgets._core import Recipe, slider

__all__ = ["accuracy_chart", "scheme_response"]

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
    rho = integrators.scheme_accuracy("central_difference", _RATIOS).plot_spectral_radius(
        ax_r, color=plots.COLORS[0]
    )
    (mark,) = ax_r.plot([0.1], [1.0], "o", color=plots.COLORS[1], ms=7)
    ax_r.axhline(1.0, color="0.4", lw=0.8, ls=":")
    ax_r.set_xscale("log")
    ax_r.set_xlim(_RATIOS[0], _RATIOS[-1])
    ax_r.set_ylim(0.0, 1.6)
    live.animate(exact["line"], numeric, rho["line"], mark)

    def redraw(v):
        name, ratio, xi = v["method"], v["dt_over_T"], v["damping_ratio"]
        system = vibration.SDOF.from_modal(2 * np.pi, xi)
        exact["line"].set_ydata(system.free_response(system_t, 1.0, 0.0))
        t = np.arange(int(np.floor(_DURATION / ratio + 1e-9)) + 1) * ratio
        try:
            run, failure = (
                integrators.integrate(name, 1.0, system.damping, system.stiffness, t, 1.0, 0.0),
                None,
            )
        except SolverError as err:
            run, failure = err.partial, err  # draw what was computed before the blow-up
        x = run.x[0]
        numeric.set_data(run.t, np.clip(x, -10.0, 10.0))  # far outside the axes but finite for Agg
        integrators.scheme_accuracy(name, _RATIOS, xi).plot_spectral_radius(artists=rho)
        here = float(integrators.spectral_radius(name, ratio, xi))
        mark.set_data([ratio], [min(here, 1.58)])
        error = np.abs(x - system.free_response(run.t, 1.0, 0.0)).max()
        text = f"<b>{LABELS[name]}</b> · Δt/T = {ratio:.2f} · ρ = {here:.4f}"
        if failure is None:
            pe = integrators.period_elongation(name, ratio, xi)
            ad = integrators.amplitude_decay(name, ratio, xi)
            pe_text = "no oscillation" if np.isnan(pe) else f"{100 * pe:+.2f} %"
            text += (
                f" · largest error over 5 periods {error:.3g} x₀ · period elongation {pe_text}"
                f" · amplitude decay per period {100 * ad:+.2f} %"
            )
        else:
            text += f" · <b>unstable</b>: diverged at step {failure.step} (t = {failure.time:.2f} s)"
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

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return SCHEME_RESPONSE.build()


def _accuracy_chart_setup(live, status):
    ax_rho, ax_pe, ax_ad = live.axes[0]
    ratios = np.linspace(0.005, 0.4, 160)
    for ax in (ax_rho, ax_pe, ax_ad):
        ax.set_xlim(0, ratios[-1])
        ax.set_xlabel(r"$\Delta t/T$")
    # Grey reference: the average acceleration method (ρ = 1, no decay).
    integrators.scheme_accuracy("average_acceleration", ratios).plot_period_elongation(
        ax_pe, color="0.75", lw=1
    )
    ax_rho.axhline(1.0, color="0.4", lw=0.8, ls=":")
    start = integrators.scheme_accuracy("wilson", ratios)
    rho = start.plot_spectral_radius(ax_rho, color=plots.COLORS[0])
    pe = start.plot_period_elongation(ax_pe, color=plots.COLORS[1])
    ad = start.plot_amplitude_decay(ax_ad, color=plots.COLORS[2])
    ax_rho.set_ylim(0.0, 1.6)
    ax_pe.set_ylim(-30, 60)
    ax_ad.set_ylim(-20, 60)
    live.animate(rho["line"], pe["line"], ad["line"])

    def redraw(v):
        name, xi = v["method"], v["damping_ratio"]
        chart = integrators.scheme_accuracy(name, ratios, xi)
        chart.plot_spectral_radius(artists=rho)
        chart.plot_period_elongation(artists=pe)
        chart.plot_amplitude_decay(artists=ad)
        limit = chart.stability_limit_dt_over_T
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

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return ACCURACY_CHART.build()
