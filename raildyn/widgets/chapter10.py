"""Chapter 10 widgets: a force crossing a beam beside its amplification curve, a regular train's
resonances against speed, four models of one car crossing the same bridge, and the track's receptance.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The models are
:mod:`raildyn.bridge`: :func:`raildyn.bridge.beam.moving_force_response` (the closed form, for the
amplification curves) and :func:`raildyn.bridge.coupled.crossing` (the modal march, for the
deflected beam and the coupled vehicles); the design rules are :mod:`raildyn.bridge.codes`. The
curves are drawn, and moved in place, by :func:`raildyn.bridge.beam.plot_amplification` (through
:meth:`~raildyn.bridge.beam.MovingForceResponse.plot`) and :meth:`raildyn.bridge.coupled.BridgeCrossing.plot`,
which the chapter's figures call too. This module only turns control values into model calls and
moves artists.
"""

from __future__ import annotations

from functools import lru_cache

import ipywidgets as widgets
import numpy as np

from raildyn import plots
from raildyn.bridge import (
    AxleSequence,
    SimplySupportedBeam,
    codes,
    crossing,
    moving_force_response,
    moving_mass,
    plot_amplification,
    sprung_mass,
    train,
    vehicle,
)
from raildyn.bridge.sleepers import DiscreteTrack
from raildyn.bridge.track import LayeredTrack
from raildyn.bridge.trains import regular_train
from raildyn.constants import GRAVITY
from raildyn.vehicles import VerticalCar
from raildyn.widgets._core import Recipe, slider

__all__ = ["load_models", "moving_load_explorer", "track_receptance", "train_resonance"]

# The bridge of the chapter: 20 m, EI = 10 GN·m², 10 t/m, so f₁ = 3.93 Hz (SimplySupportedBeam's
# defaults and docstring example).
_SPAN = 20.0  # m
_EI = 1.0e10  # N·m²
_MASS = 1.0e4  # kg/m
_FORCE = 1.0e5  # N: one 100 kN force
_SHAPE_X = np.linspace(0.0, _SPAN, 81)  # m: where the deflected beam is drawn


def _beam(modes: int, damping_ratio: float = 0.0, span: float = _SPAN, frequency_hz=None):
    """The chapter's beam, or one of another span tuned to ``frequency_hz`` (EI from f₁ = (π/2L²)√(EI/m))."""
    EI = _EI if frequency_hz is None else _MASS * (2 * frequency_hz * span**2 / np.pi) ** 2
    return SimplySupportedBeam(span, EI, _MASS, damping_ratio=damping_ratio, modes=modes)


def _alpha_speed(beam) -> float:
    """2 f₁ L, m/s: the speed at α = 1."""
    return 2.0 * float(beam.frequencies_hz[0]) * beam.span


# ---------------------------------------------------------------------------
# One force crossing the beam

_DAMPING = {"ξ = 0": 0.0, "ξ = 1 %": 0.01, "ξ = 2 %": 0.02, "ξ = 5 %": 0.05}
# α from 0.01 to 1.5: 250 points, 0.006 apart (none falls on the undamped resonance α = 1, where the
# closed form is finite only as a limit); the closed form with 10 modes, as the docstring example.
_ALPHAS = np.linspace(0.01, 1.5, 250)
# The amplification depends on α and the damping alone (Frýba 1972), so the curve is computed on a
# span twice as long of the same section (f₁ a quarter, α = 1 at 79 m/s): its α = 1.5 is met at
# 118 m/s, within raildyn.constants.MAXIMUM_SPEED, where the chapter's 20 m span would need 236 m/s.
_CURVE_SPAN = 2 * _SPAN
_CURVE_MODES = 10
_SHAPE_MODES = 3  # the drawn beam: the deflection converges as 1/j⁴, and the march is quick with three


@lru_cache(maxsize=len(_DAMPING))
def _daf_response(damping_ratio: float):
    """One force's crossing at every speed of ``_ALPHAS``, by the closed form (about 60 ms, kept)."""
    beam = _beam(_CURVE_MODES, damping_ratio, span=_CURVE_SPAN)
    return moving_force_response(beam, _ALPHAS * _alpha_speed(beam), _FORCE)


def _daf_curve(damping_ratio: float) -> np.ndarray:
    """The amplification of one force against ``_ALPHAS``."""
    return _daf_response(damping_ratio).amplification


@lru_cache(maxsize=64)
def _one_crossing(speed: float, damping_ratio: float):
    """The modal march of the force over the three-mode beam, on until the force is half a span past."""
    return crossing(
        _beam(_SHAPE_MODES, damping_ratio),
        AxleSequence([0.0], [_FORCE]),
        speed,
        free_time=0.5 * _SPAN / speed,
    )


def _explorer_controls():
    return {
        "speed_kmh": slider("speed V (km/h)", 250.0, 20.0, 700.0, 5.0, fmt=".0f"),
        "position": slider("force at x/L", 0.5, 0.0, 1.5, 0.01),
        "damping": widgets.Dropdown(
            options=list(_DAMPING.items()),
            value=0.0,
            description="damping",
            layout=widgets.Layout(width="200px"),
        ),
    }


def _explorer_setup(live, status):
    left, right = live.axes[0]
    static = 1e3 * _beam(1).static_midspan_deflection(_FORCE)  # mm
    top = _alpha_speed(_beam(1))
    # the beam: supports, the static midspan level, the deflected line and the force on it
    left.plot([0.0, _SPAN], [0.0, 0.0], color="0.75", lw=1)
    left.plot([0.0, _SPAN], [0.0, 0.0], "^", color="k", ms=9)
    left.axhline(-static, ls="--", color="0.4", lw=1)
    left.text(0.3, -static, " static midspan deflection PL³/48EI", va="bottom", fontsize=8, color="0.3")
    (shape,) = left.plot(_SHAPE_X, 0 * _SHAPE_X, color=plots.COLORS[0], lw=2.5)
    (force,) = left.plot([_SPAN / 2], [0.0], "v", color=plots.COLORS[1], ms=12)
    left.set_xlim(-0.5, 1.5 * _SPAN + 0.5)
    left.set_ylim(-2.0 * static, 2.0 * static)
    left.set(xlabel="x (m)", ylabel="deflection, downwards drawn down (mm)")
    left.set_title(f"{_SPAN:.0f} m beam, f₁ = {_beam(1).frequencies_hz[0]:.2f} Hz, 100 kN", fontsize="medium")
    # the amplification curves: all four dampings faint, the chosen one bold
    alpha_speed = _alpha_speed(_beam(1, span=_CURVE_SPAN))
    for value in _DAMPING.values():
        _daf_response(value).plot(right, alpha_speed=alpha_speed, color="0.8", lw=1)
    chosen = _daf_response(0.0).plot(
        right, alpha_speed=alpha_speed, color=plots.COLORS[0], lw=2, label="chosen damping"
    )
    curve = chosen["line"]
    (mark,) = right.plot([0.0], [1.0], "o", color=plots.COLORS[1], ms=8, label="chosen speed")
    right.axhline(1.0, color="0.6", lw=0.8)
    right.set(xlim=(0.0, 1.5), ylim=(0.9, 1.85), xlabel="α = V/(2f₁L)", ylabel="dynamic amplification")
    speed_axis = right.secondary_xaxis("top", functions=(lambda a: 3.6 * top * a, lambda k: k / (3.6 * top)))
    speed_axis.set_xlabel("V (km/h)")
    right.legend(loc="lower right", fontsize=8)
    live.animate(shape, force, curve, mark)

    def redraw(v):
        kmh, where, zeta = float(v["speed_kmh"]), float(v["position"]), float(v["damping"])
        speed = kmh / 3.6
        alpha = speed / top
        run = _one_crossing(speed, zeta)
        k = int(np.argmin(np.abs(run.time - where * _SPAN / speed)))
        w = run.modal[k, 0] @ _beam(_SHAPE_MODES).mode_shapes(_SHAPE_X)
        shape.set_ydata(-1e3 * w)
        x = speed * run.time[k]
        on = x <= _SPAN
        force.set_data([x], [-1e3 * np.interp(x, _SHAPE_X, w) if on else 0.0])
        _daf_response(zeta).plot(alpha_speed=alpha_speed, artists=chosen)
        closed = moving_force_response(_beam(_CURVE_MODES, zeta), speed, _FORCE)
        daf = float(closed.amplification[0])
        mark.set_data([alpha], [daf])
        peak = int(np.argmax(np.abs(closed.deflection[0])))
        at = speed * closed.time[0, peak]
        when = f"with the force at x = {at:.1f} m" if at <= _SPAN else f"{at - _SPAN:.1f} m after it left"
        status.value = (
            f"V = {kmh:.0f} km/h, α = {alpha:.3f} · amplification {daf:.3f} (closed form, "
            f"{_CURVE_MODES} modes): largest midspan deflection {1e3 * closed.deflection[0, peak]:.3f} mm "
            f"{when} · drawn: the force at x = {x:.1f} m{'' if on else ' (off the span)'}, "
            f"midspan {1e3 * float(np.interp(_SPAN / 2, _SHAPE_X, w)):.3f} mm"
        )

    return redraw


MOVING_LOAD_EXPLORER = Recipe(
    _explorer_controls,
    _explorer_setup,
    {"nrows": 1, "ncols": 2, "figsize": (11.0, 3.8)},
    static={"speed_kmh": [60.0, 120.0, 180.0, 250.0, 300.0, 345.0, 400.0, 460.0, 520.0, 600.0, 700.0]},
    title="A 100 kN force crossing a 20 m beam: the deflected beam and the dynamic amplification against α",
)


def moving_load_explorer():
    """A force crossing a simply supported beam: the deflected beam, and the amplification against α.

    The beam is 20 m long with EI = 10 GN·m² and 10 t/m (f₁ = 3.93 Hz); one 100 kN force
    crosses it at the chosen speed. Left: the beam's deflected line when the force stands at
    the chosen fraction of the span (beyond 1 the force has left and the beam vibrates
    freely), from the modal march of :func:`raildyn.bridge.coupled.crossing` with three modes;
    the static midspan deflection PL³/48EI is dashed. Right: the dynamic amplification (largest
    midspan deflection over the static one) against α = V/(2f₁L), by the closed form of
    :func:`raildyn.bridge.beam.moving_force_response` with ten modes, for four damping ratios (the chosen
    one bold), with the chosen speed marked. Controls: speed V (km/h), the force's position x/L
    and the damping ratio ξ.

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``speed_kmh``, ``position``, ``damping`` one of 0,
        0.01, 0.02, 0.05), redraws and returns the PNG frame.
    """
    return MOVING_LOAD_EXPLORER.build()


# ---------------------------------------------------------------------------
# A regular train's resonances

_TRAIN_COACHES = 10  # articulated: 11 two-axle bogies at the coach length
_TRAIN_BOGIE = 2.5  # m between a bogie's axles
_TRAIN_AXLE = 170.0e3  # N: HSLM-A1's axle force (EN 1991-2 Table E.4)
_TRAIN_DAMPING = 0.01  # EN 1991-2 Table 6.6: 1 % for steel and composite spans of 20 m and more
_TRAIN_MODES = 3  # mode 2 has a node at midspan; mode 3 adds about 1 % to the static midspan deflection
_TRAIN_KMH = (60.0, 420.0)
# 72 speeds evenly spaced in log v (2.8 % apart; a resonance peak of eleven bogies is about 10 % wide),
# run in two bands, each with enough samples for 10 a period of the first mode and 40 an axle's
# crossing at its slowest speed: against 10 000 samples the largest amplification is then within 1 %
# over the sliders' ranges (measured at their corners).
_TRAIN_SPEEDS = np.geomspace(_TRAIN_KMH[0], _TRAIN_KMH[1], 72) / 3.6
_TRAIN_BANDS = 2  # each call also finds the static peak anew (half its cost): few bands
_ORDERS = 4  # resonance orders marked


@lru_cache(maxsize=256)
def _envelope(coach_length: float, span: float, frequency_hz: float) -> np.ndarray:
    """The amplification against ``_TRAIN_SPEEDS`` for the regular train over the tuned beam."""
    beam = _beam(_TRAIN_MODES, _TRAIN_DAMPING, span, frequency_hz)
    axles = regular_train(_TRAIN_COACHES, coach_length, _TRAIN_BOGIE, _TRAIN_AXLE)
    travel = 2 * span + axles.length  # m: from the first axle's arrival to the last's leaving plus a span
    parts = []
    for speeds in np.array_split(_TRAIN_SPEEDS, _TRAIN_BANDS):
        samples = max(10 * frequency_hz * travel / speeds[0], 40 * travel / span)
        samples = int(np.clip(np.ceil(samples), 200, 2000))
        parts.append(moving_force_response(beam, speeds, axles, samples=samples).amplification)
    return np.concatenate(parts)


def _resonance_controls():
    return {
        "coach_length": slider("coach length d (m)", 18.0, 15.0, 30.0, 0.5, fmt=".1f"),
        "span": slider("span L (m)", 20.0, 10.0, 40.0, 0.5, fmt=".1f"),
        "frequency_hz": slider("first frequency f₁ (Hz)", 4.0, 2.0, 8.0, 0.1, fmt=".1f"),
    }


def _resonance_setup(live, status):
    (ax,) = live.axes[0]
    kmh = 3.6 * _TRAIN_SPEEDS
    marks = [
        ax.axvline(kmh[0], color=plots.COLORS[1], lw=1.2, ls=(0, (4, 2 * i)), label=f"V = f₁d/{i}")
        for i in range(1, _ORDERS + 1)
    ]
    drawn = plot_amplification(
        _TRAIN_SPEEDS, _envelope(18.0, 20.0, 4.0), ax, color=plots.COLORS[0], lw=2, label="amplification"
    )
    line = drawn["line"]
    ax.axhline(1.0, color="0.6", lw=0.8)
    ax.set(xlim=_TRAIN_KMH, xlabel="V (km/h)", ylabel="largest midspan deflection / static")
    ax.set_yscale("log")
    ax.set_ylim(0.8, 40.0)
    ax.set_yticks([1, 2, 5, 10, 20], ["1", "2", "5", "10", "20"])
    ax.set_title(
        f"{_TRAIN_COACHES} articulated coaches ({_TRAIN_COACHES + 1} bogies of {_TRAIN_BOGIE:g} m, "
        f"{_TRAIN_AXLE / 1e3:.0f} kN an axle), {100 * _TRAIN_DAMPING:.0f} % damping",
        fontsize="medium",
    )
    ax.legend(loc="upper left", fontsize=8, ncol=2)
    live.animate(line, *marks)

    def redraw(v):
        d, L, f1 = float(v["coach_length"]), float(v["span"]), float(v["frequency_hz"])
        daf = _envelope(d, L, f1)
        plot_amplification(_TRAIN_SPEEDS, daf, artists=drawn)
        resonances = codes.resonance_speeds(f1, d, _ORDERS)
        for mark, speed in zip(marks, resonances, strict=True):
            mark.set_xdata([3.6 * speed, 3.6 * speed])
            mark.set_visible(bool(_TRAIN_KMH[0] <= 3.6 * speed <= _TRAIN_KMH[1]))
        top = int(np.argmax(daf))
        cancel = codes.cancellation_spans(d, 1, 3)
        status.value = (
            f"d = {d:.1f} m, L = {L:.1f} m, f₁ = {f1:.1f} Hz · resonances V = f₁d/i: "
            + ", ".join(f"{3.6 * s:.0f}" for s in resonances)
            + f" km/h · largest amplification {daf[top]:.2f} at {3.6 * _TRAIN_SPEEDS[top]:.0f} km/h · "
            f"L/d = {L / d:.2f}: the first resonance cancels at L/d = "
            f"{', '.join(f'{c / d:g}' for c in cancel)} "
            f"(L = {', '.join(f'{c:.0f}' for c in cancel)} m)"
        )

    return redraw


TRAIN_RESONANCE = Recipe(
    _resonance_controls,
    _resonance_setup,
    {"nrows": 1, "ncols": 1, "figsize": (9.0, 3.8)},
    static={"span": [10.0, 15.0, 18.0, 20.0, 22.5, 25.0, 27.0, 30.0, 35.0, 40.0]},
    title="A regular train's dynamic amplification on a simply supported span against speed",
)


def train_resonance():
    """A train of regularly spaced bogies over a span: the amplification against speed, resonances marked.

    Ten articulated coaches of length d (eleven two-axle bogies d apart, 2.5 m between a
    bogie's axles, 170 kN an axle; :func:`raildyn.bridge.trains.regular_train`) cross a simply
    supported span L of 10 t/m whose EI gives the chosen f₁, with 1 % damping and three modes.
    The largest midspan deflection over the static one, for 80 speeds from 40 to 420 km/h, comes
    from the closed form of :func:`raildyn.bridge.beam.moving_force_response`; the resonance speeds
    V = f₁d/i (:func:`raildyn.bridge.codes.resonance_speeds`) are marked, and the status line
    gives the spans at which the first resonance cancels
    (:func:`raildyn.bridge.codes.cancellation_spans`). Controls: coach length d (m), span L (m)
    and first frequency f₁ (Hz).

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``coach_length``, ``span``, ``frequency_hz``), redraws
        and returns the PNG frame.
    """
    return TRAIN_RESONANCE.build()


# ---------------------------------------------------------------------------
# Four models of one car

_CAR = VerticalCar()  # the Manchester benchmark car in the vertical plane (Iwnicki 1998)
_WHEELSET_MASS = 1813.0  # kg (Iwnicki 1998, as raildyn.wheelset.Wheelset)
_MODELS_DAMPING = 0.01
_MODELS_MODES = 3
_RUN_ON = 10.0  # m run after the last axle has left, at every speed (so the x-axis stays)
_MODEL_NAMES = ("moving forces", "moving masses", "sprung masses", "vertical car")


@lru_cache(maxsize=1)
def _car_models() -> dict:
    """The car as four moving loads of rising fidelity, each with the car's axle loads and spacing."""
    car = vehicle(_CAR, _WHEELSET_MASS)
    gaps = np.diff(car.positions)
    # Biggs's sprung mass at each axle: a quarter of the body and half a bogie frame on the primary
    # and the secondary springs in series (per axle: the primary's whole, half the bogie's secondary),
    # damped by half the bogie's secondary damper; its bounce is 1.0 Hz.
    body = _CAR.body_mass / 4 + _CAR.bogie_mass / 2
    spring = 1.0 / (1.0 / _CAR.primary_stiffness + 2.0 / _CAR.secondary_stiffness)
    quarter = sprung_mass(body, spring, _CAR.secondary_damping / 2, _WHEELSET_MASS)
    return {
        "moving forces": car.axles,
        "moving masses": train([moving_mass(w / GRAVITY) for w in car.static_loads], gaps),
        "sprung masses": train([quarter] * car.positions.size, gaps),
        "vertical car": car,
    }


@lru_cache(maxsize=128)
def _model_runs(speed: float) -> dict:
    """Each model's crossing of the chapter's beam (1 % damping, three modes) at ``speed``."""
    beam = _beam(_MODELS_MODES, _MODELS_DAMPING)
    return {
        name: crossing(beam, load, speed, free_time=_RUN_ON / speed) for name, load in _car_models().items()
    }


def _models_controls():
    return {"speed_kmh": slider("speed V (km/h)", 200.0, 40.0, 350.0, 5.0, fmt=".0f")}


def _models_setup(live, status):
    histories, bars, comfort = live.axes[0]
    length = _car_models()["vertical car"].length
    first = _model_runs(200.0 / 3.6)
    xs = _SPAN + length + _RUN_ON
    # each model's deflection, the slow crossing (dashed) drawn once with the first
    charts = [
        first[name].plot(histories, static=i == 0, color=plots.COLORS[i], lw=1.6, label=name)
        for i, name in enumerate(_MODEL_NAMES)
    ]
    # the slow crossing is the same at every speed: drawn once, not moved (it is no animated artist)
    charts = [{"line": chart["line"]} for chart in charts]
    lines = [chart["line"] for chart in charts]
    histories.set(xlim=(0.0, xs), ylim=(11.0, -10.0), xlabel="leading axle's position (m)")
    histories.set_ylabel("midspan deflection (mm)")
    histories.legend(loc="upper left", fontsize=7, ncol=2)  # above the line: upward, where little goes
    histories.set_title("midspan, downwards drawn down", fontsize="medium")
    rects = bars.bar(range(4), [1.0] * 4, color=plots.COLORS[:4], width=0.6)
    arema = 1.0 + codes.arema_impact_factor(_SPAN)
    phi2 = codes.en1991_dynamic_factor(_SPAN)
    bars.axhline(arema, color="0.3", ls=":", lw=1.2, label="AREMA 1 + I")
    bars.axhline(phi2, color="0.3", ls="--", lw=1.2, label="EN 1991-2 Φ₂")
    (annex,) = bars.plot([-0.45, 3.45], [1.0, 1.0], color=plots.COLORS[4], lw=1.6, label="EN 1991-2 Annex C")
    bars.set_xticks(range(4), ["force", "mass", "sprung", "car"])
    bars.set(ylim=(0.0, 3.8), ylabel="dynamic amplification")  # the bars reach 2.75 at most
    bars.legend(loc="upper center", fontsize=7)
    bars.set_title("midspan amplification", fontsize="medium")
    levels = codes.COMFORT_ACCELERATION_LIMITS
    for (name, value), style in zip(levels.items(), (":", "--", "-"), strict=True):
        comfort.axhline(value, color="0.4", ls=style, lw=1)
        comfort.text(xs, value, f"{name} ", fontsize=7, va="bottom", ha="right", color="0.3")
    body_charts = [
        first[_MODEL_NAMES[i]].plot(
            comfort, quantity="body acceleration", color=plots.COLORS[i], lw=1.4, label=_MODEL_NAMES[i]
        )
        for i in (2, 3)
    ]
    body = [chart["line"] for chart in body_charts]
    comfort.set(xlim=(0.0, xs), ylim=(-0.6, 2.2), xlabel="leading axle's position (m)")
    comfort.set_ylabel("body acceleration (m/s²)")
    comfort.legend(loc="center right", fontsize=7)
    comfort.set_title("car body, EN 1990 comfort levels", fontsize="medium")
    live.animate(*lines, *rects, annex, *body)
    f1 = float(_beam(1).frequencies_hz[0])

    def redraw(v):
        kmh = float(v["speed_kmh"])
        speed = kmh / 3.6
        runs = _model_runs(speed)
        dafs = []
        for chart, rect, name in zip(charts, rects, _MODEL_NAMES, strict=True):
            run = runs[name]
            run.plot(artists=chart)
            rect.set_height(run.amplification)
            dafs.append(run.amplification)
        factor = codes.en1991_real_train_factor(speed, _SPAN, f1)
        annex.set_ydata([factor, factor])
        peaks = []
        for chart, name in zip(body_charts, ("sprung masses", "vertical car"), strict=True):
            runs[name].plot(quantity="body acceleration", artists=chart)
            peaks.append(float(np.abs(runs[name].body_acceleration).max()))
        status.value = (
            f"V = {kmh:.0f} km/h (α = {speed / (2 * f1 * _SPAN):.3f}; the bogies' resonance f₁·19 m at "
            f"{3.6 * f1 * 2 * _CAR.semi_bogie_spacing:.0f} km/h) · amplification: "
            + ", ".join(f"{name} {daf:.3f}" for name, daf in zip(_MODEL_NAMES, dafs, strict=True))
            + f" · Annex C {factor:.3f}, Φ₂ {phi2:.3f}, AREMA {arema:.3f} · largest body acceleration: "
            f"sprung masses {peaks[0]:.3f}, car {peaks[1]:.3f} m/s²"
        )

    return redraw


LOAD_MODELS = Recipe(
    _models_controls,
    _models_setup,
    {"nrows": 1, "ncols": 3, "figsize": (13.0, 3.8)},
    static={"speed_kmh": [60.0, 100.0, 140.0, 180.0, 200.0, 220.0, 250.0, 270.0, 290.0, 320.0, 350.0]},
    title="One car crossing a 20 m span as moving forces, moving masses, sprung masses and the full car",
)


def load_models():
    """One car crossing the chapter's beam as four models: forces, masses, sprung masses, the full car.

    The Manchester car in the vertical plane (:class:`raildyn.vehicles.vertical.VerticalCar`, 1813 kg
    wheelsets) on its four axles crosses the 20 m beam (f₁ = 3.93 Hz, 1 % damping, three modes)
    as four moving loads with the same axle loads and spacing: constant forces; rigid masses
    (each axle's whole load riding on the rail); Biggs's sprung masses (a quarter of the body and
    half a bogie on the primary and secondary springs in series above each wheelset); and the
    full car (:func:`raildyn.bridge.loads.vehicle`), each by
    :func:`raildyn.bridge.coupled.crossing`. Left: the midspan deflection against the leading
    axle's position, beside the slow crossing. Middle: each model's amplification, beside
    AREMA's impact and EN 1991-2's Φ₂ for the span and Annex C's factor for a real train at the
    speed (:mod:`raildyn.bridge.codes`). Right: the body's vertical acceleration (the full car's;
    the mean of the four sprung masses) beside EN 1990's comfort levels. Control: speed V (km/h).

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets the control (``speed_kmh``), redraws and returns the PNG frame.
    """
    return LOAD_MODELS.build()


# ---------------------------------------------------------------------------
# The track's receptance

_TRACK = LayeredTrack()  # UIC 60 on concrete sleepers and ballast (LayeredTrack's source)
_TRACK_F = np.geomspace(10.0, 3000.0, 400)  # Hz
# The same track on discrete sleepers, drawn midway between two sleepers and above one. Four elements a bay
# (the pinned–pinned peak 0.8 % above the default six's) and 300 frequencies keep both curves within the
# update's 30 ms: two banded solves a frequency.
_DISCRETE = dict(elements_per_bay=4)
_DISCRETE_F = np.geomspace(10.0, 3000.0, 300)  # Hz


@lru_cache(maxsize=1)
def _pinned_pinned() -> float:
    """The discrete track's pinned–pinned frequency, Hz: the rail's and the spacing's (the pads and ballast
    move it by under 1 %), so computed once."""
    return DiscreteTrack(**_DISCRETE).resonances().pinned_pinned


def _track_controls():
    return {
        "pad_mn": slider("pad stiffness k_p (MN/m)", 225.0, 50.0, 1000.0, 25.0, fmt=".0f"),
        "ballast_mn": slider("ballast stiffness k_b (MN/m)", 20.0, 10.0, 200.0, 5.0, fmt=".0f"),
    }


def _track_setup(live, status):
    (ax,) = live.axes[0]
    _TRACK.plot_receptance(_TRACK_F, ax, label="the default track", color="0.65")
    drawn = _TRACK.plot_receptance(_TRACK_F, ax, label="this track", color=plots.COLORS[0])
    marks = [ax.axvline(100.0, color=plots.COLORS[k], lw=1.0, ls=":") for k in (1, 2, 3)]
    discrete = DiscreteTrack(**_DISCRETE)
    above = float(discrete.sleeper_positions[discrete.bays // 2])
    midway = discrete.plot_receptance(
        _DISCRETE_F, ax, label="on sleepers, midway between two", color=plots.COLORS[4]
    )
    over = discrete.plot_receptance(
        _DISCRETE_F, ax, position=above, label="on sleepers, above one", color="0.2"
    )
    for line in (midway["receptance"], over["receptance"]):
        line.set_linewidth(1.0)
    pinned = _pinned_pinned()
    ax.axvline(pinned, color=plots.COLORS[4], lw=1.0, ls="--")
    ax.set_ylim(1e-10, 1e-7)
    ax.legend(loc="lower left", fontsize="small")
    live.animate(drawn["receptance"], *marks, midway["receptance"], over["receptance"])

    def redraw(v):
        pad, ballast = 1e6 * float(v["pad_mn"]), 1e6 * float(v["ballast_mn"])
        track = LayeredTrack(pad_stiffness=pad, ballast_stiffness=ballast)
        track.plot_receptance(_TRACK_F, artists=drawn)
        on_sleepers = DiscreteTrack(pad_stiffness=pad, ballast_stiffness=ballast, **_DISCRETE)
        on_sleepers.plot_receptance(_DISCRETE_F, artists=midway)
        on_sleepers.plot_receptance(_DISCRETE_F, position=above, artists=over)
        turns = track.resonances()
        for mark, f in zip(marks, (turns.full_track, turns.antiresonance, turns.rail_on_pads), strict=True):
            mark.set_visible(bool(np.isfinite(f)))
            if np.isfinite(f):
                mark.set_xdata([f, f])
        status.value = (
            f"static stiffness {1e-6 * track.static_stiffness:.1f} MN/m · "
            f"full track {turns.full_track:.0f} Hz"
            + (
                f" · antiresonance {turns.antiresonance:.0f} Hz · rail on pads {turns.rail_on_pads:.0f} Hz"
                if np.isfinite(turns.rail_on_pads)
                else " · one peak: the rail's resonance on its pads merged with it"
            )
            + f" · pinned–pinned {pinned:.0f} Hz (dashed)"
        )

    return redraw


TRACK_RECEPTANCE = Recipe(
    _track_controls,
    _track_setup,
    {"nrows": 1, "ncols": 1, "figsize": (7.5, 3.6)},
    static={"pad_mn": [50.0, 100.0, 150.0, 225.0, 300.0, 450.0, 600.0, 800.0, 1000.0]},
    title="The point receptance of a rail on pads, sleepers and ballast, smeared and on discrete sleepers",
)


def track_receptance():
    """A ballasted track's point receptance |α(f)| against frequency, its three turns marked.

    The rail on pads, sleepers and ballast of :class:`raildyn.bridge.track.LayeredTrack`; the
    default track is drawn in grey for comparison. Controls: the pad stiffness and the ballast
    stiffness (MN/m a rail seat). The dotted lines and the status line give the full-track
    resonance, the rail's resonance on its pads and the antiresonance between them
    (:meth:`~raildyn.bridge.track.LayeredTrack.resonances`; a soft pad on stiff ballast merges the
    first two), and the static stiffness. The same track on discrete sleepers
    (:class:`raildyn.bridge.sleepers.DiscreteTrack`, four elements a bay, 300 frequencies) is drawn
    midway between two sleepers and above one: near the pinned–pinned frequency (dashed) the first
    peaks and the second dips.

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``pad_mn``, ``ballast_mn``), redraws and returns the PNG frame.
    """
    return TRACK_RECEPTANCE.build()


BENCH_MOVES = [
    (
        "ch10 moving_load_explorer v",
        MOVING_LOAD_EXPLORER,
        "speed_kmh",
        [100.0, 200.0, 300.0, 400.0, 500.0, 250.0],
    ),
    ("ch10 moving_load_explorer x", MOVING_LOAD_EXPLORER, "position", [0.1, 0.3, 0.6, 0.9, 1.2, 0.5]),
    ("ch10 train_resonance d", TRAIN_RESONANCE, "coach_length", [16.0, 17.0, 19.0, 22.0, 26.0, 18.0]),
    ("ch10 train_resonance L", TRAIN_RESONANCE, "span", [12.0, 15.0, 25.0, 30.0, 35.0, 20.0]),
    ("ch10 train_resonance f₁", TRAIN_RESONANCE, "frequency_hz", [3.0, 3.5, 5.0, 6.0, 7.0, 4.0]),
    ("ch10 load_models v", LOAD_MODELS, "speed_kmh", [80.0, 120.0, 160.0, 240.0, 300.0, 200.0]),
    ("ch10 track_receptance k_p", TRACK_RECEPTANCE, "pad_mn", [100.0, 300.0, 500.0, 800.0, 150.0, 225.0]),
    ("ch10 track_receptance k_b", TRACK_RECEPTANCE, "ballast_mn", [15.0, 40.0, 80.0, 150.0, 30.0, 20.0]),
]
