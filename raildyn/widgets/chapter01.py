"""Chapter 1 widgets: free vibration and the root locus, forced response, modes, random response.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are :mod:`raildyn.vibration` and :mod:`raildyn.random_vibration`; this
module only turns control values into model calls and moves artists.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np
from matplotlib.legend import Legend

from raildyn import plots, random_vibration, vibration
from raildyn.widgets._core import Recipe, slider

__all__ = ["chain_modes", "forced_response", "free_vibration", "random_response"]

# Damping factors of the grey reference curves behind the live one.
_REFERENCE_XI = (0.05, 0.1, 0.2, 0.5, 1.0)


def _free_vibration_controls():
    return {
        "damping_ratio": slider("damping factor ξ", 0.1, 0.0, 2.0, 0.01),
        "natural_frequency": slider("ω_n (rad/s)", 2 * np.pi, 2.0, 20.0, 0.1),
        "x0": slider("x₀ (mm)", 10.0, -20.0, 20.0, 0.5, fmt=".1f"),
        "v0": slider("v₀ (mm/s)", 0.0, -200.0, 200.0, 5.0, fmt=".0f"),
    }


def _free_vibration_setup(live, status):
    ax_t, ax_s = live.axes[0]
    t = np.linspace(0.0, 5.0, 1000)  # s; a fixed axis keeps the cached picture valid on every move
    start = vibration.SDOF.from_modal(2 * np.pi, 0.1).free_vibration(t, 10.0, 0.0)  # the default controls
    hist = start.plot(ax_t)
    hist["peaks"].set_label("$x_1, x_2$ one period apart")
    ax_t.set_ylabel("displacement $x$ (mm)")
    ax_t.legend(loc="upper right")
    ax_t.set_ylim(-21, 21)
    ax_t.set_xlim(0, t[-1])
    locus = vibration.root_locus(1.0, np.linspace(0.0, 2.0, 401))
    art = locus.plot(ax_s, mark=np.zeros(2, complex), normalised=True)
    ax_s.set_xlim(-4.0, 0.5)
    ax_s.set_ylim(-1.3, 1.3)
    live.animate(hist["line"], hist["upper"], hist["lower"], hist["peaks"], art["roots"])

    def redraw(v):
        system = vibration.SDOF.from_modal(v["natural_frequency"], v["damping_ratio"])
        response = system.free_vibration(t, v["x0"], v["v0"], peaks=2)
        response.plot(artists=hist)
        roots = system.roots() / system.natural_frequency
        art["roots"].set_data(roots.real, roots.imag)
        art["roots"].set_visible(True)
        text = f"<b>{system.regime}</b>"
        if 0 < system.damping_ratio < 1:
            peaks = response.peaks
            measured = peaks.log_decrement if peaks.values[1] > 0 else np.inf
            text += (
                f" · ω_d = {system.damped_frequency:.3f} rad/s · δ = 2πξ/√(1−ξ²) = "
                f"{system.log_decrement:.4f} · ln(x₁/x₂) = {measured:.4f}"
            )
        else:
            hist["peaks"].set_data([], [])  # the undamped motion has no decay to read
        status.value = text

    return redraw


FREE_VIBRATION = Recipe(
    _free_vibration_controls,
    _free_vibration_setup,
    {"nrows": 1, "ncols": 2, "figsize": (9.0, 3.6), "gridspec_kw": {"width_ratios": [1.6, 1]}},
    static={"damping_ratio": [0.0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.3, 2.0]},
    title="Free response of an SDOF system and the locus of its roots",
)


def free_vibration():
    """Free response x(t) of an SDOF system beside the locus of its roots (book Figs. 1.4 and 1.5).

    Controls: damping factor ξ, natural frequency ω_n (rad/s), initial
    displacement x₀ (mm) and velocity v₀ (mm/s). The status line gives the
    regime, ω_d, the logarithmic decrement δ and ln(x₁/x₂) read off the curve.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return FREE_VIBRATION.build()


def _forced_response_setup(live, status):
    ax_m, ax_p, ax_tr = live.axes[0]
    r = np.linspace(0.0, 3.0, 601)
    for xi in _REFERENCE_XI:
        ax_m.plot(r, vibration.magnification_factor(r, xi), color="0.8", lw=0.8)
        ax_p.plot(r, np.degrees(vibration.phase_angle(r, xi)), color="0.8", lw=0.8)
        ax_tr.plot(r, vibration.transmissibility_ratio(r, xi), color="0.8", lw=0.8)
    mag = plots.frequency_curves(r, {"magnification": r * 0 + 1}, ax=ax_m)["magnification"]
    pha = plots.frequency_curves(r, {"phase": r * 0}, ax=ax_p)["phase"]
    tra = plots.frequency_curves(r, {"transmissibility": r * 0 + 1}, ax=ax_tr, logy=True)["transmissibility"]
    ax_m.set_ylim(0, 8)
    ax_m.set_ylabel(r"magnification $|X|k/F_0$")
    ax_p.set_ylim(0, 180)
    ax_p.set_yticks([0, 45, 90, 135, 180])
    ax_p.set_ylabel(r"phase lag $\phi$ (deg)")
    ax_tr.set_ylim(0.05, 30)
    ax_tr.set_ylabel("transmissibility $|X/Y|$")
    ax_tr.axvline(np.sqrt(2), ls=":", color="k", lw=1)
    live.animate(mag, pha, tra)

    def redraw(v):
        xi = v["damping_ratio"]
        m = vibration.magnification_factor(r, xi)
        mag.set_ydata(m)
        pha.set_ydata(np.degrees(vibration.phase_angle(r, xi)))
        tra.set_ydata(vibration.transmissibility_ratio(r, xi))
        status.value = (
            f"largest magnification on the plot {m.max():.3f} at r = {r[np.argmax(m)]:.3f}; "
            f"at r = 1 it is 1/(2ξ) = {1 / (2 * xi):.3f}"
        )

    return redraw


FORCED_RESPONSE = Recipe(
    lambda: {"damping_ratio": slider("damping factor ξ", 0.1, 0.02, 1.0, 0.01)},
    _forced_response_setup,
    {"nrows": 1, "ncols": 3, "figsize": (10.0, 3.4)},
    static={"damping_ratio": [0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.7, 1.0]},
    title="Magnification factor, phase lag and transmissibility against frequency ratio",
)


def forced_response():
    """Magnification factor, phase and transmissibility against r = ω/ω_n for a chosen ξ.

    Grey curves show ξ = 0.05, 0.1, 0.2, 0.5 and 1 for reference; the dotted line
    marks r = √2, where the transmissibility is 1 whatever the damping.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return FORCED_RESPONSE.build()


def _chain_modes_controls():
    return {
        "dof": widgets.Dropdown(options=[2, 3], value=3, description="masses"),
        "initial": widgets.Dropdown(
            options=["mass 1 displaced", "last mass displaced", "mode 1 shape", "mode 2 shape"],
            value="last mass displaced",
            description="start",
        ),
        "mass_ratio": slider("m_i/m₁", 1.0, 0.2, 3.0, 0.05),
        "stiffness_ratio": slider("k_i/k₁", 1.0, 0.2, 3.0, 0.05),
        "damping_ratio": slider("modal ξ", 0.02, 0.0, 0.2, 0.005, fmt=".3f"),
    }


def _chain_modes_setup(live, status):
    ax_m, ax_x = live.axes[0]
    t = np.linspace(0.0, 2.0, 800)
    shape_lines = [ax_m.plot([], [], "o-", color=plots.COLORS[i])[0] for i in range(3)]
    resp_lines = [ax_x.plot(t, 0 * t, color=plots.COLORS[i], label=f"mass {i + 1}")[0] for i in range(3)]
    ax_m.axhline(0, color="0.4", lw=0.8)
    ax_m.set_xlabel("mass number (0 = ground)")
    ax_m.set_ylabel("mode shape (largest entry 1)")
    ax_m.set_ylim(-1.15, 1.15)
    ax_x.set_xlabel("time $t$ (s)")
    ax_x.set_ylabel("displacement (mm)")
    ax_x.set_xlim(0, t[-1])
    ax_x.legend(loc="upper right")
    ax_m.set_xlim(-0.2, 3.2)
    # One legend per chain length, both kept on the axes and shown in turn, so that a change
    # of the number of masses does not redraw the fixed parts of the figure.
    names = [f"mode {j + 1}" for j in range(3)]
    legends = {n: Legend(ax_m, shape_lines[:n], names[:n], loc="lower left") for n in (2, 3)}
    for legend in legends.values():
        ax_m.add_artist(legend)
    live.animate(*shape_lines, *resp_lines, *legends.values())

    def redraw(v):
        n = v["dof"]
        masses = 1000.0 * np.r_[1.0, np.full(n - 1, v["mass_ratio"])]
        springs = 1.0e6 * np.r_[1.0, np.full(n - 1, v["stiffness_ratio"])]
        chain = vibration.chain_matrices(masses, springs, grounded=True)
        modes = vibration.modal_analysis(chain.M, chain.K)
        x0 = np.zeros(n)
        if v["initial"] == "mass 1 displaced":
            x0[0] = 10.0
        elif v["initial"] == "last mass displaced":
            x0[-1] = 10.0
        else:
            shape = modes.mode_shapes[:, int(v["initial"][5]) - 1]
            x0 = 10.0 * shape / np.abs(shape).max()
        x = vibration.modal_superposition(chain.M, chain.K, t, x0=x0, damping_ratios=v["damping_ratio"])
        shapes = modes.mode_shapes / np.abs(modes.mode_shapes).max(axis=0)  # each drawn with largest entry 1
        for j in range(3):
            visible = j < n
            shape_lines[j].set_visible(visible)
            resp_lines[j].set_visible(visible)
            if visible:
                shape_lines[j].set_data(np.arange(n + 1), np.r_[0.0, shapes[:, j]])
                resp_lines[j].set_ydata(x[j])
        for count, legend in legends.items():
            legend.set_visible(count == n)
        # Limits in steps of 5 mm, so that most moves keep the axes (and the cached picture).
        limit = 5.0 * np.ceil(1.15 * np.abs(x).max() / 5.0)
        ax_x.set_ylim(-limit, limit)
        freqs = ", ".join(f"{f:.2f}" for f in modes.natural_frequencies_hz)
        status.value = f"natural frequencies: {freqs} Hz"

    return redraw


CHAIN_MODES = Recipe(
    _chain_modes_controls,
    _chain_modes_setup,
    {"nrows": 1, "ncols": 2, "figsize": (9.5, 3.6)},
    static={"stiffness_ratio": [0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0]},
    title="Mode shapes of a spring-mass chain and the motion of each mass",
)


def chain_modes():
    """Modes of a fixed–free spring–mass chain of two or three masses and their superposition.

    Controls: number of masses, the ratio of every later mass and spring to the
    first (m₁ = 1000 kg, k₁ = 1 MN/m), a modal damping factor and the starting
    shape. Left: the mode shapes, each scaled to a largest entry of 1; right:
    each mass's displacement from modal superposition.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return CHAIN_MODES.build()


def _random_response_setup(live, status):
    mass, level, f_max, dt, n = 1000.0, 1.0e4, 20.0, 0.01, 40_000  # kg, N²/(rad/s), Hz, s, samples
    omega = np.linspace(0.0, 2 * np.pi * f_max, 4000)
    band = (0.0, 2 * np.pi * f_max)
    t = np.arange(n) * dt
    ax_f, ax_t = live.axes[0]
    exact = plots.spectrum(omega[1:], np.ones(omega.size - 1), ax=ax_f, label="analytic $|H|^2 G_0$")["line"]
    (welch,) = ax_f.loglog([1, 2], [1, 1], color=plots.COLORS[1], lw=1, label="Welch estimate of the sample")
    ax_f.set_ylabel(r"response PSD (m$^2$ s/rad)")
    ax_f.set_xlim(0.3, omega[-1])
    ax_f.set_ylim(1e-12, 1.0)  # spans every spectrum the sliders can reach
    ax_f.legend(loc="lower left")
    shown = t < 10.0
    # The sample is drawn in units of its analytic RMS σ, so the axes never move.
    sample = plots.time_history(t[shown], 0 * t[shown], ax=ax_t, envelope=np.ones(shown.sum()))
    ax_t.set_ylabel(r"$x/\sigma$ ($\sigma$: analytic RMS)")
    ax_t.set_xlim(0, 10)
    ax_t.set_ylim(-4.5, 4.5)
    live.animate(exact, welch, sample["line"])

    def redraw(v):
        system = vibration.SDOF.from_modal(2 * np.pi * v["frequency_hz"], v["damping_ratio"], mass=mass)
        response = random_vibration.response_psd(system.receptance(omega), np.full(omega.size, level))
        force = random_vibration.synthesize(lambda w: np.full_like(w, level), dt, n, v["seed"], band=band)
        x = system.forced_response(t, force)
        x = x[t > 20 / (system.damping_ratio * system.natural_frequency)]  # drop the start-up transient
        estimate = random_vibration.welch_psd(x, dt, nperseg=2048)
        sigma = random_vibration.rms(response, omega)
        exact.set_ydata(response[1:])
        welch.set_data(estimate.omega[1:], estimate.psd[1:])
        sample["line"].set_ydata(x[: shown.sum()] / sigma)
        white = np.sqrt(
            random_vibration.sdof_white_noise_mean_square(mass, system.damping, system.stiffness, level)
        )
        status.value = (
            f"RMS: analytic (band-limited) {1e3 * sigma:.3f} mm · white-noise closed form "
            f"{1e3 * white:.3f} mm · sample {1e3 * x.std():.3f} mm"
        )

    return redraw


RANDOM_RESPONSE = Recipe(
    lambda: {
        "frequency_hz": slider("f_n (Hz)", 1.5, 0.5, 5.0, 0.1, fmt=".1f"),
        "damping_ratio": slider("damping factor ξ", 0.1, 0.02, 0.5, 0.01),
        "seed": widgets.IntSlider(value=1, min=0, max=20, description="seed"),
    },
    _random_response_setup,
    {"nrows": 1, "ncols": 2, "figsize": (9.5, 3.6)},
    static={"damping_ratio": [0.02, 0.04, 0.06, 0.1, 0.15, 0.2, 0.3, 0.5]},
    title="Response spectrum and a sample of an SDOF system under random force",
)


def random_response():
    """A band-limited white force through an SDOF system: analytic RMS beside a seeded sample.

    The force has a flat one-sided PSD G₀ up to 20 Hz. Left: the response PSD
    |H|²G₀ with the Welch estimate of one 400 s sample; right: 10 s of the sample
    in units of the analytic RMS σ, with the ±σ lines. Controls: natural frequency (Hz),
    damping factor ξ, and the random seed.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return RANDOM_RESPONSE.build()
