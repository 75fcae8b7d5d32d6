"""Chapter 3 widgets: random track (spectrum, sample, time), jointed rail, and the impact at a dipped joint.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are :mod:`raildyn.track`, :mod:`raildyn.random_vibration` and :mod:`raildyn.bridge.impact`; this module
only turns control values into model calls and moves artists. Units at the
edge: speeds in km/h, irregularities in mm.
"""

from __future__ import annotations

from functools import cache

import ipywidgets as widgets
import numpy as np

from raildyn import bridge, plots, random_vibration, track
from raildyn.widgets._core import Recipe, slider

__all__ = ["dipped_joint", "jointed_rail", "random_track"]

# The eight track qualities the widget offers, by label: (spectrum family, class or level).
TRACKS = {f"FRA class {c}": ("fra", c) for c in track.FRA_CLASSES} | {
    "German low": ("german", "low"),
    "German high": ("german", "high"),
}
_SAMPLE_LENGTH, _DX = 1000.0, 0.25  # m: the seeded sample shown, and its spacing
_OMEGA_SPACE = np.geomspace(0.01, np.pi / _DX, 400)  # rad/m, up to the Nyquist wavenumber of the sample
_OMEGA_TIME = np.geomspace(0.5, 500.0, 400)  # rad/s


def _nice_ceiling(value: float) -> float:
    """The next number of the 1–2–5 sequence at or above ``value`` (> 0)."""
    exponent = np.floor(np.log10(value))
    for step in (1.0, 2.0, 5.0, 10.0):
        if step * 10**exponent >= value:
            return float(step * 10**exponent)
    return float(10 ** (exponent + 1))


def _random_track_controls():
    return {
        "track": widgets.Dropdown(options=list(TRACKS), value="FRA class 4", description="track"),
        "component": widgets.Dropdown(
            options=[
                ("vertical profile", "vertical"),
                ("alignment", "alignment"),
                ("cross-level", "cross_level"),
                ("gauge", "gauge"),
            ],
            value="vertical",
            description="component",
        ),
        "speed_kmh": slider("V (km/h)", 80.0, 20.0, 300.0, 5.0, fmt=".0f"),
        "shortest": slider("shortest L_w (m)", 1.5, 0.5, 10.0, 0.5, fmt=".1f"),
        "longest": slider("longest L_w (m)", 300.0, 20.0, 1000.0, 10.0, fmt=".0f"),
        "seed": widgets.IntSlider(value=1, min=0, max=20, description="seed"),
    }


def _random_track_setup(live, status):
    ax_s, ax_x, ax_t = live.axes[0]
    x_shown = np.arange(int(_SAMPLE_LENGTH / _DX)) * _DX
    # Spatial spectrum: every track quality in grey behind the chosen one, and the sample's Welch estimate.
    others = [ax_s.loglog(_OMEGA_SPACE, _OMEGA_SPACE, color="0.82", lw=0.8)[0] for _ in TRACKS]
    (chosen,) = ax_s.loglog(_OMEGA_SPACE, _OMEGA_SPACE, color=plots.COLORS[0], label="spectrum $S(\\Omega)$")
    (welch,) = ax_s.loglog([1, 2], [1, 1], color=plots.COLORS[1], lw=0.9, label="Welch, 1 km sample")
    edges = [ax_s.axvline(1.0, color="k", ls=":", lw=1) for _ in range(2)]
    ax_s.set_xlim(_OMEGA_SPACE[0], _OMEGA_SPACE[-1])
    ax_s.set_ylim(1e-12, 10.0)  # spans every spectrum offered over these wavenumbers
    ax_s.set_xlabel(r"wavenumber $\Omega$ (rad/m)")
    ax_s.set_ylabel(r"$S(\Omega)$ (m$^2$/(rad/m))")
    ax_s.legend(loc="lower left")
    # The sample along the first kilometre, in mm.
    (sample_line,) = ax_x.plot(x_shown, 0 * x_shown, color=plots.COLORS[0], lw=0.8)
    ax_x.set_xlim(0, _SAMPLE_LENGTH)
    ax_x.set_xlabel("distance $x$ (m)")
    ax_x.set_ylabel("irregularity (mm)")
    # The same spectrum in time at speed V.
    (temporal,) = ax_t.loglog(_OMEGA_TIME, _OMEGA_TIME, color=plots.COLORS[2], label=r"$S(\omega/V)/V$")
    band_t = [ax_t.axvline(1.0, color="k", ls=":", lw=1) for _ in range(2)]
    ax_t.set_xlim(_OMEGA_TIME[0], _OMEGA_TIME[-1])
    ax_t.set_ylim(1e-14, 1.0)
    ax_t.set_xlabel(r"circular frequency $\omega = V\Omega$ (rad/s)")
    ax_t.set_ylabel(r"$S_t(\omega)$ (m$^2$ s/rad)")
    ax_t.legend(loc="lower left")
    live.animate(*others, chosen, welch, *edges, sample_line, temporal, *band_t)

    def redraw(v):
        spectrum, grade = TRACKS[v["track"]]
        component = v["component"]
        for line, (fam, g) in zip(others, TRACKS.values(), strict=True):
            line.set_ydata(track.track_psd(fam, component, g)(_OMEGA_SPACE))
        shortest, longest = v["shortest"], max(v["longest"], 2.0 * v["shortest"])
        lo, hi = track.wavelength_band((shortest, longest))
        V = v["speed_kmh"] / 3.6
        for line, value in zip(edges, (lo, hi), strict=True):
            line.set_xdata([value, value])
        for line, value in zip(band_t, (V * lo, V * hi), strict=True):
            line.set_xdata([value, value])
        psd = track.track_psd(spectrum, component, grade)
        chosen.set_ydata(psd(_OMEGA_SPACE))
        sample = track.synthesize_irregularity(psd, _SAMPLE_LENGTH, _DX, (shortest, longest), v["seed"])
        estimate = random_vibration.welch_psd(sample.z, _DX, nperseg=1024)
        w_est, s_est = estimate.omega, estimate.psd
        inside = (w_est >= sample.band[0]) & (w_est <= sample.band[1])
        welch.set_data(w_est[inside], np.where(s_est[inside] > 0, s_est[inside], np.nan))
        sample_line.set_ydata(1e3 * sample.z)
        # Limits in 1–2–5 steps of 4σ: they move with the track and band, not with the seed or the speed.
        limit = _nice_ceiling(4e3 * sample.rms)
        ax_x.set_ylim(-limit, limit)
        temporal.set_ydata(track.temporal_psd(psd, V)(_OMEGA_TIME))
        analytic = track.band_variance(spectrum, component, grade, sample.band)
        f_lo, f_hi = V * lo / (2 * np.pi), V * hi / (2 * np.pi)
        status.value = (
            f"RMS over L_w ∈ [{shortest:g}, {longest:g}] m: analytic {1e3 * np.sqrt(analytic):.2f} mm · "
            f"1 km sample {1e3 * sample.measured_rms:.2f} mm · at {v['speed_kmh']:.0f} km/h "
            f"this band excites {f_lo:.2f}–{f_hi:.1f} Hz"
        )

    return redraw


RANDOM_TRACK = Recipe(
    _random_track_controls,
    _random_track_setup,
    {"nrows": 1, "ncols": 3, "figsize": (11.0, 3.6)},
    static={"track": list(TRACKS)},
    title="Track spectrum, a seeded 1 km sample and the spectrum in time at speed V",
)


def random_track():
    """Random track: pick a track quality and component, see its spectrum, a sample and its excitation.

    Controls: track (FRA class 1–6, German low/high disturbance), component,
    speed V (km/h), the wavelength band kept (m) and the seed. Left: S(Ω) with
    every other track quality in grey, the band edges dotted and the Welch
    estimate of the sample; middle: the seeded 1 km sample (mm); right: the
    spectrum met in time at V, S(ω/V)/V. The status line gives the band RMS,
    analytic beside the sample's.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return RANDOM_TRACK.build()


def _jointed_rail_controls():
    return {
        "half_width": slider("dip half-length ℓ_j (m)", 2.0, 0.5, 5.9, 0.1, fmt=".1f"),
        "depth_mm": slider("dip depth h_j (mm)", 8.0, 0.0, 20.0, 0.5, fmt=".1f"),
        "arrangement": widgets.Dropdown(
            options=[("staggered", "staggered"), ("in phase", "in_phase")],
            value="staggered",
            description="joints",
        ),
        "speed_kmh": slider("V (km/h)", 60.0, 10.0, 160.0, 5.0, fmt=".0f"),
    }


def _jointed_rail_setup(live, status):
    ax_p, ax_h = live.axes[0]
    L = track.RAIL_LENGTH
    x = np.linspace(0.0, 3 * L, 1200)
    profiles = track.jointed_track(x, 0.008, 2.0).plot(ax_p)  # the default controls
    ax_p.set_xlim(0, x[-1])
    ax_p.set_ylim(-21, 21)
    ax_p.legend(loc="lower right", ncols=3)
    # Harmonics of the periodic inputs seen at speed V, at the frequencies nV/L: bounce (mean of the
    # rails) and roll (cross-level). The frequency axis is fixed; the bars move along it with the speed.
    n_harm, width = 12, 0.3  # harmonics shown; bar width in Hz
    f_axis = np.arange(1, n_harm + 1, dtype=float)
    bounce = ax_h.bar(f_axis, 0 * f_axis, width=width, color=plots.COLORS[0], label="bounce (mean)")
    roll = ax_h.bar(f_axis, 0 * f_axis, width=width, color=plots.COLORS[2], label="cross-level")
    ax_h.set_xlim(0, 25)
    ax_h.set_ylim(0, 12)
    ax_h.set_xlabel("frequency $nV/L$ (Hz)")
    ax_h.set_ylabel("amplitude (mm)")
    ax_h.legend(loc="upper right")
    live.animate(*profiles.values(), *bounce.patches, *roll.patches)
    period = np.linspace(0.0, L, 2048, endpoint=False)

    def redraw(v):
        depth, a = 1e-3 * v["depth_mm"], min(v["half_width"], L / 2)
        track.jointed_track(x, depth, a, arrangement=v["arrangement"]).plot(artists=profiles)
        one = track.jointed_track(period, depth, a, arrangement=v["arrangement"])
        for bars, signal in ((bounce, one.vertical), (roll, one.cross_level)):
            for bar, h in zip(bars.patches, 1e3 * track.harmonic_amplitudes(signal, n_harm), strict=True):
                bar.set_height(h)
        f1 = track.passing_frequency(v["speed_kmh"] / 3.6)
        for n, (b, r) in enumerate(zip(bounce.patches, roll.patches, strict=True), start=1):
            b.set_x(n * f1 - width)
            r.set_x(n * f1)
        status.value = (
            f"first harmonic nV/L = {f1:.2f} Hz at {v['speed_kmh']:.0f} km/h (L = {L} m); "
            f"slope jump at each joint 4h_j/ℓ_j = {4e3 * depth / a:.1f} mm/m"
        )

    return redraw


JOINTED_RAIL = Recipe(
    _jointed_rail_controls,
    _jointed_rail_setup,
    {"nrows": 1, "ncols": 2, "figsize": (10.0, 3.6), "gridspec_kw": {"width_ratios": [1.6, 1]}},
    static={"half_width": [0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 5.9]},
    title="Jointed rail with dipped joints and the harmonics of its bounce and roll inputs",
)


def jointed_rail():
    """Jointed rail with cusp-shaped dipped joints, staggered or in phase, and its harmonics.

    Controls: half-length ℓ_j and depth h_j of each dip, joint arrangement, speed
    (km/h). Left: both rails and the cross-level over three rail lengths; right:
    the Fourier amplitudes of the bounce (mean) and roll (cross-level) inputs,
    placed at their frequencies nV/L in Hz.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return JOINTED_RAIL.build()


# --------------------------------------------------------------------------- a dipped joint's impact

# A shorter, coarser track than the model's default keeps each run near 20 ms: 30 sleepers with 8 quiet
# bays at each end, 4 elements a bay (the P1 and P2 forces move by well under 1 % from the default's).
_IMPACT_TRACK = bridge.DiscreteTrack(bays=30, quiet_bays=8, elements_per_bay=4)
_JOINT_X = float(_IMPACT_TRACK.sleeper_positions[15]) + 0.5 * _IMPACT_TRACK.sleeper_spacing  # midway
_RAMP, _AFTER = 0.5, 0.025  # m of the falling leg; s run after the joint


@cache
def _lumped():
    return bridge.lumped_track(_IMPACT_TRACK, _JOINT_X)


def _joint_run(speed_kmh: float, dip_mrad: float, unsprung_kg: float):
    V = speed_kmh / 3.6
    half = 0.5e-3 * dip_mrad
    wheel = bridge.Wheel(unsprung_mass=unsprung_kg)
    joint = bridge.DippedJoint(_JOINT_X, (half, half), _RAMP)
    run = bridge.wheel_on_track(wheel, V, joint, track=_IMPACT_TRACK, start=_JOINT_X - _RAMP - 0.05,
                                distance=_RAMP + 0.05 + V * _AFTER, time_step=2e-5)  # fmt: skip
    return wheel, run


def _dipped_joint_controls():
    return {
        "speed_kmh": slider("V (km/h)", 100.0, 40.0, 200.0, 10.0, fmt=".0f"),
        "dip_mrad": slider("dip angle 2α (mrad)", 8.0, 2.0, 20.0, 1.0, fmt=".0f"),
        "unsprung_kg": slider("unsprung mass m_w (kg)", 900.0, 400.0, 2000.0, 50.0, fmt=".0f"),
    }


def _dipped_joint_setup(live, status):
    (ax,) = live.axes[0]
    wheel, run = _joint_run(100.0, 8.0, 900.0)
    drawn = run.plot(ax, position=_JOINT_X)
    ax.set_xlim(-8.0, 1000 * _AFTER)
    ax.set_ylim(0.0, 300.0)
    ax.legend(loc="upper right")
    live.animate(*drawn.values())

    def redraw(v):
        wheel, run = _joint_run(v["speed_kmh"], v["dip_mrad"], v["unsprung_kg"])
        run.plot(position=_JOINT_X, artists=drawn)
        p1, p2 = run.peaks(_JOINT_X)
        k, m, c = _lumped()
        estimate = bridge.jenkins_p2(wheel, v["speed_kmh"] / 3.6, 1e-3 * v["dip_mrad"], m, k, c)
        lost = run.contact_loss_time[0]
        status.value = (
            f"Q₀ {1e-3 * wheel.static_load:.1f} kN · P1 {1e-3 * p1:.0f} kN · P2 {1e-3 * p2:.0f} kN "
            f"(Jenkins et al.: {1e-3 * estimate:.0f} kN)"
            + (f" · the wheel leaves the rail for {1e3 * lost:.1f} ms" if lost > 0 else "")
        )

    return redraw


DIPPED_JOINT = Recipe(
    _dipped_joint_controls,
    _dipped_joint_setup,
    {"nrows": 1, "ncols": 1, "figsize": (8.0, 3.6)},
    static={"dip_mrad": [2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 15.0, 20.0]},
    title="A wheel over a dipped joint: the wheel–rail force with its P1 and P2 peaks",
)


def dipped_joint():
    """A wheel rolling over a dipped rail joint on a track of discrete sleepers: the force history.

    The wheel (:class:`raildyn.bridge.impact.Wheel`, the Manchester car's static load) runs over a
    joint whose two legs fall and rise at α each (total angle 2α), midway between two sleepers of a
    :class:`raildyn.bridge.sleepers.DiscreteTrack`. Controls: speed (km/h), the dip angle 2α (mrad)
    and the unsprung mass (kg). The figure gives the wheel–rail force against the time since the
    joint, P1 and P2 marked; the status line gives both, Jenkins et al.'s estimate of P2
    (:func:`raildyn.bridge.impact.jenkins_p2` on :func:`raildyn.bridge.impact.lumped_track`) and how
    long the wheel leaves the rail, if it does.

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``speed_kmh``, ``dip_mrad``, ``unsprung_kg``), redraws and
        returns the PNG frame.
    """
    return DIPPED_JOINT.build()
