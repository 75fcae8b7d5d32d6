"""Chapter 6 widgets: ride of a passenger car on random track, and a freight car rocking on jointed rail.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are :mod:`raildyn.vehicles` (:func:`raildyn.vehicles.ride_comparison.ride_run`, the ride two ways) and
:mod:`raildyn.ride`; this module turns control values into model calls and moves artists. Units at
the edge: km/h, mm, degrees, kN.
"""

from __future__ import annotations

from functools import lru_cache

import ipywidgets as widgets
import numpy as np

from raildyn import _checks, plots, ride, track, vehicles

# Moved to raildyn.vehicles (the ride of a vehicle two ways is a model computation); re-exported here
# for one issue, then it goes from this module.
from raildyn.vehicles import (
    GDU_ORE_CAR,
    MANCHESTER_VERTICAL,
    RideRun,
    VerticalFreightCar,
    periodic_profile,
    rock_and_roll,
)

__all__ = [
    "RideRun",
    "ride_quality",
    "ride_run",
    "rock_and_roll_widget",
    "unloading_sweep",
    "wheel_unloading",
]

TRACKS = {f"FRA class {c}": ("fra", c) for c in track.FRA_CLASSES} | {
    "German low": ("german", "low"),
    "German high": ("german", "high"),
}
_F = np.linspace(0.05, 30.0, 1200)  # Hz: the response spectrum's grid
_RUN_LENGTH, _DX, _BAND = 1500.0, 0.25, (1.0, 300.0)  # m: the seeded track of the time run
_DT = 0.01  # s
_SETTLE = 10.0  # s dropped from the time run before its RMS is taken
_VEHICLE = MANCHESTER_VERTICAL.linear_system()
# km/h: the speeds ride_run takes. Below 10 km/h the 1.5 km run would need over 54,000 steps of
# 0.01 s; 400 km/h is twice the top speed of a car of this kind.
_SPEEDS_KMH = (10.0, 400.0)


def _ride_controls():
    from raildyn.widgets._core import slider

    return {
        "track": widgets.Dropdown(options=list(TRACKS), value="FRA class 4", description="track"),
        "speed_kmh": slider("V (km/h)", 120.0, 40.0, 200.0, 10.0, fmt=".0f"),
        "seed": widgets.IntSlider(value=1, min=0, max=20, description="seed"),
    }


@lru_cache(maxsize=64)
def _track_sample(track_label: str, seed: int):
    """The seeded 1.5 km sample of the track, as a periodic profile (kept: a speed move reuses it)."""
    spectrum, grade = TRACKS[track_label]
    psd = track.track_psd(spectrum, "vertical", grade)
    z = track.synthesize_irregularity(psd, _RUN_LENGTH, _DX, _BAND, seed).z.reshape(-1)
    return periodic_profile(z, _DX)


def ride_run(track_label: str, speed_kmh: float, seed: int) -> RideRun:
    """The widget's values turned into :func:`raildyn.vehicles.ride_comparison.ride_run`: spectrum and run.

    The car is ``raildyn.vehicles.MANCHESTER_VERTICAL`` (body centre, vertical); the spectrum is
    taken on 0.05–30 Hz, and the run follows a 1.5 km track synthesized from the same spectrum
    (wavelengths 1–300 m, 0.25 m samples), repeated periodically, in steps of 0.01 s with the
    first 10 s dropped.

    Parameters
    ----------
    track_label : str
        A key of ``TRACKS``: ``"FRA class 1"`` … ``"FRA class 6"``, ``"German low"``,
        ``"German high"``.
    speed_kmh : float
        Speed of the car, km/h, 10–400 (below 10 km/h the run would need over 54,000
        time steps; 400 km/h is twice the top speed of a car of this kind).
    seed : int
        Seed of the synthesized track (>= 0); the same seed gives the same run.

    Returns
    -------
    RideRun
        The spectrum and its ride measures, and the run and its measures.
    """
    _checks.choice("track_label", track_label, TRACKS)
    speed_kmh = _checks.scalar("speed_kmh", speed_kmh, low=_SPEEDS_KMH[0], high=_SPEEDS_KMH[1])
    seed = _checks.integer("seed", seed, low=0)
    spectrum, grade = TRACKS[track_label]
    psd = track.track_psd(spectrum, "vertical", grade)
    sample = _track_sample(track_label, seed)
    return vehicles.ride_run(_VEHICLE, psd, speed_kmh / 3.6, sample, _F, dt=_DT, settle=_SETTLE)


def _ride_setup(live, status):
    ax_s, ax_t = live.axes[0]
    (psd_line,) = ax_s.semilogy(_F, _F, color=plots.COLORS[0], label="car-body acceleration")
    (weighted,) = ax_s.semilogy(_F, _F, color=plots.COLORS[1], ls="--", label="Sperling-weighted")
    ax_s.set_xlim(0, _F[-1])
    ax_s.set_ylim(1e-6, 1.0)
    ax_s.set_xlabel("frequency (Hz)")
    ax_s.set_ylabel(r"PSD ((m/s$^2$)$^2$/Hz)")
    ax_s.legend(loc="upper right")
    t_max = 60.0
    (hist,) = ax_t.plot([0, t_max], [0, 0], color=plots.COLORS[2], lw=0.7)
    ax_t.set_xlim(0, t_max)
    ax_t.set_ylim(-3.0, 3.0)
    ax_t.set_xlabel("time (s)")
    ax_t.set_ylabel(r"acceleration (m/s$^2$)")
    live.animate(psd_line, weighted, hist)
    spectrum = {"line": psd_line}  # moved by ResponseSpectrum.plot, the chart of figure 6.ride

    def redraw(v):
        run = ride_run(v["track"], v["speed_kmh"], v["seed"])
        fd, t, a, td = run.frequency_domain, run.t, run.acceleration, run.time_domain
        run.spectrum.plot(artists=spectrum)
        weighted.set_ydata(np.maximum(ride.sperling_weighting(_F) ** 2 * run.spectrum.psd_per_hz, 1e-12))
        shown = t <= t_max
        hist.set_data(t[shown], a[shown])
        status.value = (
            f"{v['track']} at {v['speed_kmh']:.0f} km/h · frequency domain: RMS {fd.rms:.3f} m/s², "
            f"Wz {fd.wz:.2f}, ISO 2631 W_k {fd.iso_rms:.3f} m/s² · seeded run "
            f"(λ {_BAND[0]:g}–{_BAND[1]:g} m): RMS {td.rms:.3f} m/s², Wz {td.wz:.2f}"
        )

    return redraw


def _ride_recipe():
    from raildyn.widgets._core import Recipe

    return Recipe(
        _ride_controls,
        _ride_setup,
        {"nrows": 1, "ncols": 2, "figsize": (11.0, 3.6)},
        static={"speed_kmh": [40.0, 60.0, 80.0, 100.0, 120.0, 140.0, 160.0, 180.0, 200.0]},
        title="Car-body acceleration spectrum, ride index and a seeded time run against speed",
    )


RIDE = _ride_recipe()


def ride_quality():
    """Passenger car on random track: car-body acceleration spectrum, RMS and Sperling's Wz.

    Controls: track quality, speed (km/h), seed. Left: the car-body (centre)
    acceleration PSD per Hz and its Sperling-weighted part; right: a seeded time
    run over a synthesized track of the same quality. The status line gives the
    frequency-domain RMS, Wz and ISO 2631 weighted RMS beside the run's.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return RIDE.build()


# --------------------------------------------------------------------------- freight car rock and roll

_ROCK_SPEEDS_KMH = np.linspace(20.0, 70.0, 21)  # 2.5 km/h: the resonance peaks are narrow
FREIGHT_CARS = {"286K hopper (derived)": VerticalFreightCar(), "GDU ore car (Baruffaldi)": GDU_ORE_CAR}


def _rock_controls():
    from raildyn.widgets._core import slider

    return {
        "car": widgets.Dropdown(options=list(FREIGHT_CARS), value="286K hopper (derived)", description="car"),
        "speed_kmh": slider("V (km/h)", 40.0, 20.0, 70.0, 5.0, fmt=".0f"),
        "friction_kn": slider("wedge friction (kN per nest)", 6.0, 2.0, 20.0, 2.0, fmt=".0f"),
        "depth_mm": slider("joint dip hⱼ (mm)", 20.0, 5.0, 30.0, 5.0, fmt=".0f"),
    }


@lru_cache(maxsize=32)
def _rock_sweep(car_label: str, friction_kn: float, depth_mm: float):
    """The roll over the widget's speeds, integrated together: 14 rail lengths at 20 km/h, so that
    every history covers the 30 s the right panel shows."""
    car = FREIGHT_CARS[car_label].replace(wedge_friction=1e3 * friction_kn)
    return rock_and_roll(car, _ROCK_SPEEDS_KMH / 3.6, depth=1e-3 * depth_mm, cycles=14)


def _rock_setup(live, status):
    ax_a, ax_t = live.axes[0]
    (curve,) = ax_a.plot(_ROCK_SPEEDS_KMH, 0 * _ROCK_SPEEDS_KMH, "o-", color=plots.COLORS[0], ms=3)
    resonance = ax_a.axvline(40.0, color="k", ls=":", lw=1, label="roll resonance $f_\\phi L$")
    (marker,) = ax_a.plot([40.0], [0.0], "s", color=plots.COLORS[1], ms=7, label="chosen speed")
    ax_a.set_xlim(_ROCK_SPEEDS_KMH[0] - 2, _ROCK_SPEEDS_KMH[-1] + 2)
    ax_a.set_ylim(0, 5.0)
    ax_a.set_xlabel("speed (km/h)")
    ax_a.set_ylabel("roll amplitude (deg)")
    ax_a.legend(loc="upper right")
    (hist,) = ax_t.plot([0, 1], [0, 0], color=plots.COLORS[2], lw=0.9)
    ax_t.set_xlim(0, 30)
    ax_t.set_ylim(-5.0, 5.0)
    ax_t.set_xlabel("time (s)")
    ax_t.set_ylabel("body roll (deg)")
    live.animate(curve, resonance, marker, hist)
    sweep_artists = {"curve": curve, "resonance": resonance}  # moved by RockAndRoll.plot (figure 6.rock)

    def redraw(v):
        sweep = _rock_sweep(v["car"], v["friction_kn"], v["depth_mm"])
        sweep.plot(artists=sweep_artists)
        v_res = 3.6 * sweep.resonance_speed
        # The chosen speed is one of the sweep's (a 5 km/h slider on its 2.5 km/h grid): its history
        # and amplitude come from the same run.
        k = int(np.argmin(np.abs(_ROCK_SPEEDS_KMH - v["speed_kmh"])))
        shown = sweep.t <= 30
        hist.set_data(sweep.t[shown], np.degrees(sweep.roll[k][shown]))
        here = float(np.degrees(sweep.roll_amplitude[k]))
        marker.set_data([v["speed_kmh"]], [here])
        status.value = (
            f"roll resonance (springs alone) at {v_res:.0f} km/h; at {v['speed_kmh']:.0f} km/h the steady "
            f"roll amplitude is {here:.2f}° ({v['friction_kn']:.0f} kN per nest, {v['depth_mm']:.0f} mm dips)"
        )

    return redraw


def _rock_recipe():
    from raildyn.widgets._core import Recipe

    return Recipe(
        _rock_controls,
        _rock_setup,
        {"nrows": 1, "ncols": 2, "figsize": (11.0, 3.6)},
        static={"speed_kmh": [20.0, 25.0, 30.0, 35.0, 40.0, 45.0, 50.0, 55.0, 60.0, 65.0, 70.0]},
        title="Freight car rocking on staggered jointed rail: roll amplitude against speed",
    )


ROCK = _rock_recipe()


def rock_and_roll_widget():
    """Freight car on staggered jointed rail: roll amplitude against speed and the roll history.

    Controls: the car (the derived 286K hopper or the GDU ore car of
    :data:`raildyn.vehicles.freight.GDU_ORE_CAR`, whose own wedges give 4.3 kN),
    speed (km/h), wedge friction per nest (kN), joint dip depth (mm).
    Left: steady roll amplitude over 20–70 km/h with the roll resonance of the
    springs alone dotted and the chosen speed marked; right: the roll history.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return ROCK.build()


# ---------------------------------------------------------------------- wheel unloading of the rocking car

_UNLOADING_SPEEDS_KMH = np.arange(18.0, 46.1, 2.0)  # the grid the widget runs at construction
_UNLOADING_CYCLES = 12  # rail lengths a run lasts; its second half gives the measures
_MPH = 1.609344  # km/h per mph
SERVICE_BAND_MPH = (12.0, 24.0)
"""Speeds at which loaded freight cars rock on jointed rail in service, mph: G. Wolf, "Rock 'til you
drop: starting and stopping harmonic rock and roll", Interface Journal, February 2005."""


@lru_cache(maxsize=1)
def unloading_sweep() -> vehicles.RockingSweep:
    """The rocking 286K hopper (:class:`raildyn.vehicles.RockingFreightCar`) over staggered 20 mm dipped
    joints on 11.9 m rails at 18, 20, … 46 km/h, 12 rail lengths each: the widget's runs, made once.

    Returns
    -------
    RockingSweep
    """
    return vehicles.rocking_sweep(
        vehicles.RockingFreightCar(), _UNLOADING_SPEEDS_KMH / 3.6, cycles=_UNLOADING_CYCLES
    )


def _unloading_controls():
    from raildyn.widgets._core import slider

    return {"speed_kmh": slider("V (km/h)", 30.0, 18.0, 46.0, 2.0, fmt=".0f")}


def _unloading_setup(live, status):
    sweep = unloading_sweep()
    ax_s, ax_t = live.axes[0]
    low, high = (_MPH * v for v in SERVICE_BAND_MPH)
    ax_s.axvspan(low, high, color="0.88", zorder=0, label="rock and roll in service (Wolf 2005)")
    sweep.plot(ax_s)
    (marker,) = ax_s.plot([30.0], [0.0], "s", color=plots.COLORS[2], ms=7, label="chosen speed")
    ax_s.set_xlim(_UNLOADING_SPEEDS_KMH[0] - 2, _UNLOADING_SPEEDS_KMH[-1] + 2)
    ax_s.legend(loc="upper right", fontsize="small")
    history = sweep.runs[0].plot(ax_t)
    ax_t.set_xlim(0, _UNLOADING_CYCLES * track.RAIL_LENGTH / (_UNLOADING_SPEEDS_KMH[0] / 3.6))
    ax_t.set_ylim(-10.0, 4.5 * sweep.runs[0].static_wheel_load / 1e3)
    ax_t.legend(loc="upper right", fontsize="small")
    live.animate(marker, *history.values())

    def redraw(v):
        k = int(np.argmin(np.abs(_UNLOADING_SPEEDS_KMH - v["speed_kmh"])))
        run = sweep.runs[k]
        run.plot(artists=history)
        marker.set_data([v["speed_kmh"]], [run.peak_unloading])
        status.value = (
            f"at {3.6 * run.speed:.0f} km/h: peak ΔQ/Q {run.peak_unloading:.2f}, a wheel off the rail "
            f"{100 * run.lift_fraction:.0f} % of the time ({run.lift_distance:.1f} m per rail), centre plate "
            f"on one edge {100 * run.plate_lift_fraction:.0f} %, side bearers closed "
            f"{100 * run.bearer_contact_fraction:.0f} %, roll ±{np.degrees(run.roll_amplitude):.1f}° · "
            f"rocking mode f L = {3.6 * sweep.resonance_speed:.0f} km/h"
        )

    return redraw


def _unloading_recipe():
    from raildyn.widgets._core import Recipe

    return Recipe(
        _unloading_controls,
        _unloading_setup,
        {"nrows": 1, "ncols": 2, "figsize": (11.0, 3.8)},
        static={"speed_kmh": [18.0, 22.0, 24.0, 26.0, 28.0, 30.0, 32.0, 34.0, 38.0, 42.0, 46.0]},
        title="Rocking freight car on staggered jointed rail: wheel unloading and wheel lift against speed",
    )


WHEEL_UNLOADING = _unloading_recipe()


def wheel_unloading():
    """The rocking freight car's wheels on staggered jointed rail: ΔQ/Q and wheel lift against speed.

    Control: speed (km/h, 18–46 in steps of 2; every speed is run once, when the widget is first
    built, by :func:`~raildyn.widgets.chapter06.unloading_sweep`). Left: the peak ΔQ/Q and the share of
    time with a wheel off the
    rail against speed, the rocking mode's speed f L dotted and the speeds at which cars rock in
    service shaded; right: the leading truck's side loads Q_L and Q_R at the chosen speed, the
    times a wheel is off its rail marked on the zero line.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return WHEEL_UNLOADING.build()
