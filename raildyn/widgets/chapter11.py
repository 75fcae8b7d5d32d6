"""Chapter 11 widgets: the chapter-10 prediction against the strain measured on Lerelva bridge, what
each agreement metric sees, and the Sobol' indices of the chapter-7 car's critical speed.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The models are
:mod:`raildyn.validation` (:func:`raildyn.validation.measured.lerelva_case` for the measured
case, :func:`raildyn.validation.metrics.compare` for the metrics,
:func:`raildyn.validation.uncertainty.sobol_indices` for the indices),
:func:`raildyn.bridge.beam.moving_force_response` for the prediction and
:func:`raildyn.stability.linear.critical_speed` for the car. This module only turns control
values into model calls and moves artists.
"""

from __future__ import annotations

import logging
from functools import lru_cache, partial

import ipywidgets as widgets
import numpy as np
from scipy import stats

from raildyn import plots
from raildyn.bridge import AxleSequence, SimplySupportedBeam, moving_force_response
from raildyn.stability import critical_speed
from raildyn.validation.measured import LERELVA_PANEL, NSB92_LOADS, NSB92_SPACINGS, lerelva_case
from raildyn.validation.metrics import compare
from raildyn.validation.uncertainty import sobol_indices
from raildyn.vehicles import LateralCar
from raildyn.widgets._core import Recipe, slider

__all__ = ["metrics_explorer", "prediction_vs_measurement", "sensitivity_bars"]

# ---------------------------------------------------------------------------
# The metrics as bars, shared by the two comparison widgets

# (label, attribute of Agreement, how it is drawn): 1 − r so that every bar is 0 for a perfect match
_METRICS = (
    ("NRMSE", "nrmse"),
    ("1 − r", "correlation"),
    ("Theil U", "theil_u"),
    ("S–G M", "magnitude"),
    ("S–G P", "phase"),
    ("S–G C", "combined"),
)
_BAR_TOP = 1.0  # the bars' axis: every metric is 0 for a perfect match; most stay below 1


def _metric_values(agreement) -> np.ndarray:
    """The six bar heights of an Agreement: NRMSE, 1 − r, U, M, P, C (dimensionless)."""
    values = [getattr(agreement, attr) for _, attr in _METRICS]
    values[1] = 1.0 - values[1]
    return np.array(values)


def _metric_panel(ax, reference=None):
    """Bars for the six metrics, their heights moved later (the values go in the status line)."""
    pos = np.arange(len(_METRICS))
    rects = ax.bar(pos, np.zeros(len(_METRICS)), width=0.6, color=plots.COLORS[0])
    if reference is not None:
        ax.plot(pos, reference, "_", color="k", ms=26, mew=2.5, zorder=4, label="the fitted case")
        ax.legend(loc="upper right", fontsize=7)
    ax.axhline(0.0, color="0.3", lw=0.8)
    ax.set_xticks(pos, [name for name, _ in _METRICS], fontsize=8)
    ax.set(ylim=(-0.6, _BAR_TOP + 0.15), ylabel="metric (0: perfect)")
    return list(rects)


def _move_bars(rects, values) -> None:
    """Bar heights; a bar beyond the axis is drawn to its edge (the status line has its value)."""
    for rect, value in zip(rects, values, strict=True):
        rect.set_height(float(np.clip(value, -0.6, _BAR_TOP)))


def _agreement_text(a) -> str:
    return (
        f"r = {a.correlation:.3f}, NRMSE ({a.normalisation}) {a.nrmse:.3f}, Theil U {a.theil_u:.3f}, "
        f"Sprague–Geers M {a.magnitude:+.3f}, P {a.phase:.3f}, C {a.combined:.3f}"
    )


# ---------------------------------------------------------------------------
# The chapter-10 prediction against the Lerelva strain

_MASS = 1.0e3  # kg/m: lerelva_case's assumed stringer and track mass (its docstring)
_MODES = 20  # as lerelva_case
_OVERSAMPLE = 4  # moving_force_response samples per record sample, as lerelva_case
_AXLES = AxleSequence(np.concatenate([[0.0], np.cumsum(NSB92_SPACINGS)]), np.array(NSB92_LOADS), "NSB 92")


@lru_cache(maxsize=1)
def _case():
    """The measured case with its identification and prediction (about 1.5 s, kept)."""
    return lerelva_case()


def _default_frequency_hz() -> float:
    """f₁ of lerelva_case's stringer: EI = 1e8 N·m², m = 1 t/m over 4.17 m, 28.6 Hz."""
    return float(SimplySupportedBeam(LERELVA_PANEL, 1.0e8, _MASS).frequencies_hz[0])


def _stringer(frequency_hz: float, damping_ratio: float) -> SimplySupportedBeam:
    """The stringer panel as a simple span of 1 t/m whose EI gives f₁ = (π/(2L²))√(EI/m)."""
    EI = _MASS * (2 * frequency_hz * LERELVA_PANEL**2 / np.pi) ** 2
    return SimplySupportedBeam(LERELVA_PANEL, EI, _MASS, damping_ratio=damping_ratio, modes=_MODES)


@lru_cache(maxsize=256)
def _deflection(speed: float, frequency_hz: float, damping_ratio: float, gauge: int) -> np.ndarray:
    """The chapter-10 deflection at a gauge on the case's time base, times EI/EI₀ (m).

    Strain is c M/EI and the case fitted one factor c/EI₀ from deflection to strain at the assumed
    EI₀ (f₁ = 28.6 Hz); a deflection times EI/EI₀ keeps that factor whatever f₁ is chosen, so that
    f₁ changes only the dynamics. The time at which the train's centre passes the panel's middle is
    kept at the identified one: a changed speed stretches the passage about it.
    """
    case = _case()
    beam = _stringer(frequency_hz, damping_ratio)
    fitted = case.fit.speed
    centre = case.fit.value("arrival") + (beam.span + _AXLES.length) / (2 * fitted)
    arrival = centre - (beam.span + _AXLES.length) / (2 * speed)
    samples = int(np.ceil((2 * beam.span + _AXLES.length) / speed * case.record.rate_hz * _OVERSAMPLE))
    position = float(case.record.positions[gauge])
    r = moving_force_response(beam, speed, _AXLES, position=position, samples=samples)
    stiffer = beam.flexural_rigidity / _stringer(_default_frequency_hz(), damping_ratio).flexural_rigidity
    return stiffer * np.interp(case.time - arrival, r.time[0], r.deflection[0], left=0.0, right=0.0)


def _lerelva_controls():
    case = _case()
    kmh = round(3.6 * case.fit.speed, 1)
    return {
        "speed_kmh": slider("train speed V (km/h)", kmh, 50.0, 100.0, 0.5, fmt=".1f"),
        "scale": slider("strain scale (× fitted)", 1.0, 0.5, 1.5, 0.01),
        "frequency_hz": slider(
            "stringer f₁ (Hz)", round(_default_frequency_hz(), 1), 4.0, 60.0, 0.1, fmt=".1f"
        ),
        "damping": slider("damping ratio ξ (%)", 2.0, 0.0, 10.0, 0.5, fmt=".1f"),
        "gauge": widgets.Dropdown(
            options=[(name, i) for i, name in enumerate(case.record.channels)],
            value=0,
            description="gauge",
            layout=widgets.Layout(width="260px"),
        ),
    }


def _lerelva_setup(live, status):
    history, bars = live.axes[0]
    case = _case()
    t = case.time
    (measured,) = history.plot(t, 0 * t, color="0.35", lw=0.9, label="measured (Slettebak 2016)")
    (predicted,) = history.plot(
        t, 0 * t, color=plots.COLORS[1], lw=1.8, ls="--", label="chapter-10 prediction"
    )
    top = 1e6 * max(np.abs(case.measured).max(), np.abs(case.predicted).max())
    history.set(xlim=(t[0], t[-1]), ylim=(-0.45 * top, 1.6 * top), xlabel="time (s)", ylabel="strain (µε)")
    history.legend(loc="upper right", fontsize=8)
    history.set_title(
        f"Lerelva bridge, stringer panel {LERELVA_PANEL:.2f} m, NSB class 92 unit (8 axles)",
        fontsize="medium",
    )
    reference = [_metric_values(a) for a in case.agreement]
    rects = _metric_panel(bars, reference[0])
    (ref_marks,) = [line for line in bars.lines if line.get_label() == "the fitted case"]
    bars.set_title("agreement at this gauge", fontsize="medium")
    live.animate(measured, predicted, *rects, ref_marks)
    fitted_kmh = 3.6 * case.fit.speed

    def redraw(v):
        kmh, factor = float(v["speed_kmh"]), float(v["scale"])
        f1, zeta, gauge = float(v["frequency_hz"]), float(v["damping"]) / 100.0, int(v["gauge"])
        m = case.measured[gauge]
        p = factor * case.scale * _deflection(kmh / 3.6, f1, zeta, gauge)
        measured.set_ydata(1e6 * m)
        predicted.set_ydata(1e6 * p)
        agreement = compare(m, p, t)
        _move_bars(rects, _metric_values(agreement))
        ref_marks.set_ydata(reference[gauge])
        alpha = (kmh / 3.6) / (2 * f1 * LERELVA_PANEL)
        status.value = (
            f"{case.record.channels[gauge]} · V = {kmh:.1f} km/h (identified {fitted_kmh:.1f}), "
            f"α = V/(2f₁L) = {alpha:.3f} · {_agreement_text(agreement)}"
        )

    return redraw


PREDICTION_VS_MEASUREMENT = Recipe(
    _lerelva_controls,
    _lerelva_setup,
    {"nrows": 1, "ncols": 2, "figsize": (12.0, 3.9), "width_ratios": (2.2, 1.0)},
    static={"speed_kmh": [60.0, 66.0, 70.0, 72.0, 74.0, 75.5, 77.0, 79.0, 82.0, 86.0, 92.0]},
    title="Measured strain on Lerelva bridge against the chapter-10 prediction, with the agreement metrics",
)


def prediction_vs_measurement():
    """The chapter-10 prediction of the strain on Lerelva bridge against the measurement, metrics live.

    The strain measured at midspan of a 4.17 m stringer panel of Lerelva bridge and 1 m either
    side as an NSB class 92 unit crossed (:func:`raildyn.validation.measured.lerelva_case`:
    Slettebak 2016) beside the chapter-10 prediction: the unit's eight nominal axle loads crossing
    the panel as a simply supported span (:func:`raildyn.bridge.beam.moving_force_response`, 20 modes,
    1 t/m), turned into strain by the one factor the case fitted, times the chosen scale. A
    speed other than the identified one (75.5 km/h) stretches the passage about the moment the
    unit's centre passes the panel's middle. Left: the two records at the chosen gauge. Right:
    the metrics of :func:`raildyn.validation.metrics.compare` (NRMSE over the range, 1 − r,
    Theil's U, the Sprague–Geers M, P and C), each 0 for a perfect match, beside the fitted
    case's values. Controls: speed V (km/h), strain scale, the stringer's first frequency f₁
    (Hz, through EI), its damping ratio ξ (%) and the gauge.

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``speed_kmh``, ``scale``, ``frequency_hz``,
        ``damping``, ``gauge`` 0 to 2), redraws and returns the PNG frame.
    """
    return PREDICTION_VS_MEASUREMENT.build()


# ---------------------------------------------------------------------------
# What each metric sees: a synthetic record and a prediction off by a gain, a delay and noise

_SYNTH_T = np.linspace(0.0, 2.0, 1001)  # s: 2 ms a sample
_SYNTH_SEED = 11  # the noise's seed: one fixed realisation, scaled by the slider


def _synthetic(t) -> np.ndarray:
    """The 'measured' record: a decaying 5 Hz transient starting at 0.2 s, 1 at most (dimensionless).

    The form e^(−a(t−τ)) sin 2πf(t−τ), a decay rate a (here 2 1/s), of Schwer's (2007) comparison of
    validation metrics.
    """
    s = np.clip(t - 0.2, 0.0, None)
    return np.exp(-2.0 * s) * np.sin(2 * np.pi * 5.0 * s)


@lru_cache(maxsize=1)
def _noise() -> np.ndarray:
    return np.random.default_rng(_SYNTH_SEED).standard_normal(_SYNTH_T.size)


def _explorer_controls():
    return {
        "gain": slider("gain", 1.0, 0.5, 1.5, 0.01),
        "delay_ms": slider("delay (ms)", 20.0, -100.0, 100.0, 2.0, fmt=".0f"),
        "noise": slider("noise RMS (% of peak)", 0.0, 0.0, 30.0, 1.0, fmt=".0f"),
    }


def _explorer_setup(live, status):
    history, bars = live.axes[0]
    t = _SYNTH_T
    m = _synthetic(t)
    history.plot(t, m, color="0.35", lw=1.2, label="measured")
    (predicted,) = history.plot(t, m, color=plots.COLORS[1], lw=1.4, ls="--", label="prediction")
    history.set(xlim=(0.0, 2.0), ylim=(-1.8, 1.8), xlabel="time (s)", ylabel="signal")
    history.legend(loc="upper right", fontsize=8)
    history.set_title("prediction = gain × measured(t − delay) + noise", fontsize="medium")
    rects = _metric_panel(bars)
    bars.set_title("what each metric sees", fontsize="medium")
    live.animate(predicted, *rects)

    def redraw(v):
        gain, delay, noise = float(v["gain"]), float(v["delay_ms"]) / 1e3, float(v["noise"]) / 100.0
        p = gain * _synthetic(t - delay) + noise * _noise()
        predicted.set_ydata(p)
        agreement = compare(m, p, t)
        _move_bars(rects, _metric_values(agreement))
        status.value = f"gain {gain:.2f}, delay {1e3 * delay:.0f} ms, noise {100 * noise:.0f} % · " + (
            _agreement_text(agreement)
        )

    return redraw


METRICS_EXPLORER = Recipe(
    _explorer_controls,
    _explorer_setup,
    {"nrows": 1, "ncols": 2, "figsize": (12.0, 3.6), "width_ratios": (2.2, 1.0)},
    static={"delay_ms": [-100.0, -60.0, -40.0, -20.0, 0.0, 10.0, 20.0, 40.0, 60.0, 100.0]},
    title="A synthetic record and a prediction off by a gain, a delay and noise, with the metrics",
)


def metrics_explorer():
    """What each agreement metric sees: a known record against a prediction off by gain, delay, noise.

    The 'measured' record is a decaying 5 Hz transient, e^(−2(t−0.2)) sin 2π·5(t−0.2) after
    0.2 s (the kind of signal Schwer (2007) compares metrics on); the prediction is the same
    signal times a gain, delayed, plus white noise (one fixed realisation, scaled). The metrics
    of :func:`raildyn.validation.metrics.compare` are drawn as bars, each 0 for a perfect match:
    the Sprague–Geers magnitude error M sees only the gain (M = gain − 1 exactly), the phase
    error P only the delay and the noise, the correlation neither gain nor offset. Controls:
    gain, delay (ms) and the noise's RMS (% of the signal's peak).

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``gain``, ``delay_ms``, ``noise``), redraws and
        returns the PNG frame.
    """
    return METRICS_EXPLORER.build()


# ---------------------------------------------------------------------------
# Sobol' indices of the car's critical speed

_CAR = LateralCar()  # the Manchester benchmark car (Iwnicki 1998), chapter 7
# m/s: the default car's critical speed is 77.9 m/s, and ±10 % on the conicity moves it by about ±5 %;
# a narrow bracket and a 16-speed scan cost 9 ms a call against 15 ms for (1, 150) m/s and 64.
_SPEED_RANGE = (50.0, 110.0)
_SCAN = 16
_SPREAD = 0.10  # ±10 %, uniform
_SOBOL_N = 32  # base samples: N (d + 2) = 224 critical speeds, about 3 s on one core
_SOBOL_SEED = 2026
_PARAMETERS = {  # name: (where the default lives, label)
    "lateral_stiffness": ("wheelset", "primary lateral k_py"),
    "yaw_stiffness": ("wheelset", "primary yaw k_pψ"),
    "secondary_lateral_stiffness": ("bogie", "secondary lateral k_sy"),
    "secondary_yaw_stiffness": ("bogie", "secondary yaw k_sψ"),
    "conicity": ("wheelset", "conicity λ"),
}
_OUTPUTS = {"critical speed (km/h)": "speed_kmh", "hunting frequency there (Hz)": "frequency_hz"}
_KINDS = {"first order S_i": "first", "total S_Ti": "total", "interactions S_Ti − S_i": "interactions"}


def _uniform(value: float):
    """Uniform on value × [1 − spread, 1 + spread]."""
    return stats.uniform(value * (1 - _SPREAD), 2 * _SPREAD * value)


# Every critical speed computed, by its parameters (the five of _PARAMETERS in order): both outputs of
# one critical_speed call. Module-level, so that a model sent to an in-process dask worker (pickled
# by reference) finds the evaluations of the first output's run when the second output's asks again.
_CAR_OUTPUTS: dict = {}


def _car_output(output: str, **params) -> float:
    """One output of the car with the given stiffnesses and conicity.

    ``output`` is 'speed_kmh' (the critical speed, km/h) or 'frequency_hz' (the hunting frequency
    there, Hz).
    """
    key = tuple(float(params[name]) for name in _PARAMETERS)
    if key not in _CAR_OUTPUTS:
        r = critical_speed(_CAR.replace(**params), _SPEED_RANGE, scan=_SCAN)
        if r.status != "crossing":
            raise ValueError(
                f"no critical speed within {_SPEED_RANGE} m/s for {params} (status {r.status!r})"
            )
        _CAR_OUTPUTS[key] = {"speed_kmh": 3.6 * r.speed, "frequency_hz": r.frequency_hz}
    return _CAR_OUTPUTS[key][output]


@lru_cache(maxsize=1)
def _sobol_study() -> dict:
    """Sobol' indices of both outputs, and the outputs over every evaluation, computed once.

    The car's critical speed and the hunting frequency there come from one
    :func:`raildyn.stability.linear.critical_speed` call; both runs of
    :func:`raildyn.validation.uncertainty.sobol_indices` draw the same samples (the same seed) on
    an in-process dask client with one thread, so the second is answered from the first's
    evaluations (kept in ``_CAR_OUTPUTS``).
    """
    from distributed import Client

    defaults = {name: getattr(getattr(_CAR, part), name) for name, (part, _) in _PARAMETERS.items()}
    distributions = {name: _uniform(value) for name, value in defaults.items()}
    results = {}
    with Client(
        processes=False, n_workers=1, threads_per_worker=1, dashboard_address=":0", silence_logs=logging.ERROR
    ) as client:
        for output in _OUTPUTS.values():
            results[output] = sobol_indices(
                partial(_car_output, output),
                distributions,
                _SOBOL_N,
                rng=_SOBOL_SEED,
                client=client,
                bootstrap=500,
            )
    values = {output: np.array([v[output] for v in _CAR_OUTPUTS.values()]) for output in _OUTPUTS.values()}
    return {"sobol": results, "values": values, "evaluations": len(_CAR_OUTPUTS)}


def _kind_values(result, kind: str) -> tuple[np.ndarray, np.ndarray]:
    """The chosen index and its interval (rows: lower, upper), (d,) and (2, d)."""
    if kind == "first":
        return result.first_order, result.first_order_interval.T
    if kind == "total":
        return result.total, result.total_interval.T
    # S_Ti − S_i has no bootstrap interval of its own here: the two intervals' extremes bound it
    gap = result.total - result.first_order
    low = result.total_interval[:, 0] - result.first_order_interval[:, 1]
    high = result.total_interval[:, 1] - result.first_order_interval[:, 0]
    return gap, np.vstack([low, high])


def _sensitivity_controls():
    return {
        "output": widgets.Dropdown(
            options=list(_OUTPUTS.items()),
            value="speed_kmh",
            description="output",
            layout=widgets.Layout(width="330px"),
        ),
        "kind": widgets.Dropdown(
            options=list(_KINDS.items()),
            value="first",
            description="index",
            layout=widgets.Layout(width="300px"),
        ),
    }


def _sensitivity_setup(live, status):
    (ax,) = live.axes[0]
    study = _sobol_study()
    names = [label for _, label in _PARAMETERS.values()]
    pos = np.arange(len(names))
    rects = list(ax.bar(pos, np.zeros(len(names)), width=0.6, color=plots.COLORS[0]))
    whiskers = [ax.plot([p, p], [0.0, 0.0], color="0.15", lw=1.5)[0] for p in pos]
    ax.axhline(0.0, color="0.3", lw=0.8)
    ax.set_xticks(pos, names, fontsize=8)
    ax.set(ylim=(-0.3, 1.4), ylabel="Sobol' index (bar) and its 95 % interval")
    ax.set_title(
        f"the Manchester car, ±{100 * _SPREAD:.0f} % uniform scatter on each parameter, "
        f"N = {_SOBOL_N} ({study['evaluations']} critical speeds)",
        fontsize="medium",
    )
    live.animate(*rects, *whiskers)

    def redraw(v):
        output, kind = str(v["output"]), str(v["kind"])
        result = study["sobol"][output]
        values, interval = _kind_values(result, kind)
        for rect, whisker, value, low, high in zip(rects, whiskers, values, *interval, strict=True):
            rect.set_height(float(value))
            rect.set_color(plots.COLORS[{"first": 0, "total": 1, "interactions": 2}[kind]])
            whisker.set_ydata([low, high])
        y = study["values"][output]
        what, unit = ("critical speed", "km/h") if output == "speed_kmh" else ("hunting frequency", "Hz")
        status.value = (
            f"{what}: mean {y.mean():.2f} {unit}, standard deviation {y.std(ddof=1):.2f} {unit} "
            f"over {y.size} evaluations · Σ S_i = {result.first_order.sum():.2f}, "
            f"Σ S_Ti = {result.total.sum():.2f} · largest {kind} index: "
            f"{names[int(np.argmax(values))]} ({values.max():.2f})"
        )

    return redraw


SENSITIVITY_BARS = Recipe(
    _sensitivity_controls,
    _sensitivity_setup,
    {"nrows": 1, "ncols": 1, "figsize": (9.0, 3.8)},
    static={"output": list(_OUTPUTS.values()), "kind": list(_KINDS.values())},
    title="Sobol' indices of the chapter-7 car's critical speed and hunting frequency",
)


def sensitivity_bars():
    """Sobol' indices of the chapter-7 car's linear critical speed under ±10 % parameter scatter.

    The Manchester car (:class:`raildyn.vehicles.lateral.LateralCar`) with its primary lateral and yaw
    stiffnesses, its secondary lateral and yaw stiffnesses and the conicity each uniform within
    ±10 % of the default. :func:`raildyn.validation.uncertainty.sobol_indices` (N = 32, 224
    evaluations of :func:`raildyn.stability.linear.critical_speed`, about 3 s, on an in-process
    dask client closed after) gives the first-order and total indices of two outputs, the
    critical speed and the hunting frequency at it, computed once when the first widget is built
    and kept. The bars show the chosen index, the whiskers its 95 % bootstrap interval (for the
    interactions S_Ti − S_i, the bounds the two intervals allow). N = 32 is few: the intervals
    are wide, and an estimate may dip below zero. Controls: output and index.

    Returns
    -------
    container : ipywidgets.VBox
        The controls, the status line and the figure, to display.
    update : callable
        ``update(**values)`` sets controls (``output`` one of "speed_kmh", "frequency_hz";
        ``kind`` one of "first", "total", "interactions"), redraws and returns the PNG frame.
    """
    return SENSITIVITY_BARS.build()


BENCH_MOVES = [
    (
        "ch11 prediction_vs_measurement v",
        PREDICTION_VS_MEASUREMENT,
        "speed_kmh",
        [65.0, 70.0, 80.0, 85.0, 90.0, 75.5],
    ),
    (
        "ch11 prediction_vs_measurement f₁",
        PREDICTION_VS_MEASUREMENT,
        "frequency_hz",
        [5.0, 8.0, 12.0, 20.0, 40.0, 28.6],
    ),
    ("ch11 metrics_explorer delay", METRICS_EXPLORER, "delay_ms", [-80.0, -40.0, 0.0, 30.0, 60.0, 20.0]),
    ("ch11 metrics_explorer noise", METRICS_EXPLORER, "noise", [5.0, 10.0, 15.0, 20.0, 25.0, 0.0]),
    (
        "ch11 sensitivity_bars kind",
        SENSITIVITY_BARS,
        "kind",
        ["total", "interactions", "first", "total", "interactions", "first"],
    ),
]
