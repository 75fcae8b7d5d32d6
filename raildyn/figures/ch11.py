"""Chapter 11 figures, in the order the notebook shows them: a free decay identified by least squares
beside the logarithmic decrement, the strain measured on Lerelva bridge against the chapter-10
prediction, and the Sobol' indices of the chapter-7 car's critical speed.

The models are :mod:`raildyn.validation` (:func:`raildyn.validation.measured.lerelva_case`,
:func:`raildyn.validation.identification.free_decay`,
:func:`raildyn.validation.uncertainty.sobol_indices`) and
:func:`raildyn.stability.linear.critical_speed`. None of them mirrors a numbered figure of the book.
"""

from __future__ import annotations

import logging

import numpy as np
from matplotlib.figure import Figure
from scipy import stats

from raildyn import plots
from raildyn.figures import new_figure, register
from raildyn.stability import critical_speed
from raildyn.validation.identification import free_decay
from raildyn.validation.measured import lerelva_case
from raildyn.validation.uncertainty import sobol_indices
from raildyn.vehicles import LateralCar

# A free decay of the kind a bridge or a car body gives after an impulse: 2.5 Hz, 2 % damping, 4 s at
# 200 Hz, with white measurement noise of 5 % of the first amplitude.
_DECAY_HZ, _DECAY_ZETA, _DECAY_NOISE = 2.5, 0.02, 0.05
_DECAY_T = np.arange(0.0, 4.0, 0.005)
_DECAY_SEEDS = 20


def _decay_record(seed: int) -> np.ndarray:
    wn = 2 * np.pi * _DECAY_HZ
    wd = wn * np.sqrt(1 - _DECAY_ZETA**2)
    clean = np.exp(-_DECAY_ZETA * wn * _DECAY_T) * np.cos(wd * _DECAY_T)
    return clean + _DECAY_NOISE * np.random.default_rng(seed).standard_normal(_DECAY_T.size)


@register(
    "fig11.free_decay",
    "Identifying damping from a free decay (2.5 Hz, ξ = 2 %, white noise of 5 % of the first amplitude). "
    "Left: one record and the damped sinusoid fitted by least squares. Right: for twenty records with "
    "different noise, the fitted ξ with its 95 % confidence interval (from s²(JᵀJ)⁻¹ and Student's t) "
    "beside ξ from chapter 1's logarithmic decrement of the same record's maxima; the dashed line is the "
    "true value. The fit uses every sample and its intervals cover the truth; the decrement uses two "
    "maxima and scatters several times more.",
    chapter=11,
)
def free_decay_figure() -> Figure:
    fig = new_figure(figsize=(11.0, 3.8))
    left, right = fig.subplots(1, 2, width_ratios=(1.6, 1.0))
    fit = free_decay(_DECAY_T, _decay_record(0))
    fit.plot(left)
    left.set_title(
        f"fitted f = {fit.frequency_hz:.3f} Hz, ξ = {100 * fit.damping_ratio:.2f} % "
        f"({100 * fit.bounds('damping_ratio')[0]:.2f}–{100 * fit.bounds('damping_ratio')[1]:.2f} %)",
        fontsize="medium",
    )
    seeds = np.arange(_DECAY_SEEDS)
    for k, seed in enumerate(seeds):
        f = fit if seed == 0 else free_decay(_DECAY_T, _decay_record(int(seed)))
        low, high = f.bounds("damping_ratio")
        right.plot([k, k], [100 * low, 100 * high], color=plots.COLORS[0], lw=1.5)
        right.plot(
            [k],
            [100 * f.damping_ratio],
            "o",
            color=plots.COLORS[0],
            ms=4,
            label="least squares, 95 %" if k == 0 else None,
        )
        right.plot(
            [k + 0.3],
            [100 * f.decrement_damping_ratio],
            "s",
            color=plots.COLORS[1],
            ms=4,
            label="logarithmic decrement" if k == 0 else None,
        )
    right.axhline(100 * _DECAY_ZETA, color="k", ls="--", lw=1, label="true ξ")
    right.set(xlabel="record (noise seed)", ylabel="damping ratio ξ (%)")
    right.legend(fontsize=8, loc="upper right")
    return fig


@register(
    "fig11.lerelva_prediction",
    "Strain at the three gauges on the first stringer panel (4.17 m) of Lerelva bridge as a two-car NSB "
    "class 92 unit crossed at 75.5 km/h (thin: measured by Slettebak 2016, decimated to 256 Hz), and the "
    "chapter-10 prediction (dashed): the unit's eight nominal axle loads crossing the panel as a simply "
    "supported span, at the speed and arrival identified by weigh-in-motion, scaled to strain by one "
    "fitted factor. The humps of the four bogies agree in time and height (correlation 0.89 to 0.97); "
    "the measured humps are wider and dip below zero between them, because the real stringer is "
    "continuous over the cross-girders and the rails spread each axle's load, which a simple span "
    "loaded at points cannot show.",
    chapter=11,
)
def lerelva_figure() -> Figure:
    case = lerelva_case()
    fig = new_figure(figsize=(12.0, 3.8))
    axes = fig.subplots(1, 3, sharey=True)
    for i, (ax, name, agreement) in enumerate(zip(axes, case.record.channels, case.agreement, strict=True)):
        ax.plot(case.time, 1e6 * case.measured[i], color="0.35", lw=0.8, label="measured")
        ax.plot(case.time, 1e6 * case.predicted[i], color=plots.COLORS[1], lw=1.6, ls="--", label="predicted")
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_title(
            f"{name}\nr = {agreement.correlation:.2f}, NRMSE {agreement.nrmse:.3f}, "
            f"C = {agreement.combined:.2f}",
            fontsize="medium",
        )
        ax.set_xlabel("time (s)")
    axes[0].set_ylabel("strain (µε)")
    axes[0].legend(loc="upper left", fontsize=8)
    return fig


# The chapter-7 car, ±10 % uniform scatter on four stiffnesses and the conicity (as the chapter's
# widget and benchmark): N = 32 base samples, 224 critical speeds on an in-process dask client.
_CAR = LateralCar()
_SCATTERED = {
    "lateral_stiffness": "wheelset",
    "yaw_stiffness": "wheelset",
    "secondary_lateral_stiffness": "bogie",
    "secondary_yaw_stiffness": "bogie",
    "conicity": "wheelset",
}


def _speed_kmh(**params) -> float:
    """The car's linear critical speed, km/h."""
    r = critical_speed(_CAR.replace(**params), (50.0, 110.0), scan=16)  # 77.9 m/s ± 5 %: the widget's bracket
    if r.status != "crossing":
        raise ValueError(f"no critical speed within 50-110 m/s for {params} (status {r.status!r})")
    return 3.6 * r.speed


@register(
    "fig11.sobol_critical_speed",
    "Sobol' first-order and total indices, with 95 % bootstrap intervals, of the Manchester car's linear "
    "critical speed (280 km/h) when its primary lateral and yaw stiffnesses, its secondary lateral and "
    "yaw stiffnesses and the conicity each scatter uniformly by ±10 % (N = 32 base samples, 224 "
    "critical speeds). The conicity explains nearly all of the variance; first-order and total indices "
    "nearly agree, so the parameters hardly interact over this range. With so few samples the "
    "intervals are wide.",
    chapter=11,
)
def sobol_figure() -> Figure:
    from distributed import Client

    defaults = {name: getattr(getattr(_CAR, part), name) for name, part in _SCATTERED.items()}
    distributions = {name: stats.uniform(0.9 * value, 0.2 * value) for name, value in defaults.items()}
    with Client(
        processes=False, n_workers=1, threads_per_worker=1, dashboard_address=":0", silence_logs=logging.ERROR
    ) as client:
        result = sobol_indices(_speed_kmh, distributions, 32, rng=2026, client=client, bootstrap=500)
    fig = new_figure(figsize=(9.0, 3.8))
    ax = fig.subplots()
    result.plot(ax)
    ax.set_xticks(range(len(result.names)), [n.replace("_", " ") for n in result.names], fontsize=8)
    return fig
