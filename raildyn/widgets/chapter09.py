"""Chapter 9 widgets: an emergency braking run of a freight train, and string-lining L/V on a curve.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are in :mod:`raildyn.train`; this module turns control values into model
calls, caches the braking runs (each is a whole-train integration, about half a
second) and moves artists.
"""

from __future__ import annotations

from functools import lru_cache

import ipywidgets as widgets
import numpy as np

from raildyn import _checks, plots, train
from raildyn.widgets._core import Recipe, slider

__all__ = ["braking_run", "braking_run_widget", "string_lining"]

DURATION = 40.0  # s of the braking run shown: the application, the run-in and the settling
SLACK_GRID = [0, 10, 20, 25, 30, 40, 50, 60, 75]  # mm, precomputed for the page without a kernel
# The domain of braking_run (its docstring gives the reasons).
_MAX_CARS = 200
_MAX_SLACK_MM = 200.0
_MAX_SIGNAL_SPEED = 343.0  # m/s, the speed of sound in air at 20 °C
_MIN_SIGNAL_SPEED = 10.0  # m/s (36 km/h): a slower brake signal would be outrun by the train
_MAX_SPEED_KMH = 200.0


def braking_run(cars: int, slack_mm: float, signal_speed: float, speed_kmh: float) -> train.TrainRun:
    """The emergency braking run of 2 SD40-2 + ``cars`` loaded hoppers, stretched at the start (cached).

    Parameters
    ----------
    cars : int
        Number of loaded hoppers, 1–200 (a 3.6 km train, whose run takes a few seconds).
    slack_mm : float
        Slack of every coupler, mm, 0 or 2–200 (draft gear has up to about 75 mm; the gap's edge
        is rounded over 1 mm each side); the run starts with every coupler stretched.
    signal_speed : float
        Speed of the brake-pipe signal, m/s, 10 <= c <= 343 (a pressure wave in the
        pipe is not faster than sound in air, and one slower than 10 m/s would be outrun by
        the train).
    speed_kmh : float
        Initial speed of the train, km/h, 0 < V <= 200 (a braking run starts moving;
        200 km/h is far above any freight train).

    Returns
    -------
    raildyn.train.TrainRun
        The first ``DURATION`` seconds after the emergency application, 401 samples.
    """
    cars = _checks.integer("cars", cars, low=1, high=_MAX_CARS)
    slack_mm = _checks.scalar("slack_mm", slack_mm, low=0.0, high=_MAX_SLACK_MM)
    if 0.0 < slack_mm < 2.0:  # the draft gear rounds the edge of the gap over 1 mm each side
        raise ValueError(
            f"slack_mm must be 0 or at least 2 mm (twice the gap's 1 mm rounding), got {slack_mm!r}"
        )
    signal_speed = _checks.scalar("signal_speed", signal_speed, low=_MIN_SIGNAL_SPEED, high=_MAX_SIGNAL_SPEED)
    speed_kmh = _checks.scalar("speed_kmh", speed_kmh, low=0.0, low_open=True, high=_MAX_SPEED_KMH)
    return _braking_run(cars, slack_mm, signal_speed, speed_kmh)


@lru_cache(maxsize=64)
def _braking_run(cars: int, slack_mm: float, signal_speed: float, speed_kmh: float) -> train.TrainRun:
    """:func:`braking_run` for checked arguments, cached (each run is a whole-train integration)."""
    model = train.braking_model(cars, 2, slack=slack_mm / 1000, propagation_speed=signal_speed)
    return train.simulate(model, DURATION, speed_kmh / 3.6, initial_extension=slack_mm / 2000, samples=401)


def _braking_controls():
    return {
        "cars": widgets.IntSlider(
            value=50,
            min=10,
            max=100,
            step=10,
            description="wagons",
            continuous_update=False,
            style={"description_width": "initial"},
            layout=widgets.Layout(width="360px"),
        ),  # fmt: skip
        "slack_mm": slider("slack e per coupler (mm)", 25.0, 0.0, 75.0, 5.0, fmt=".0f", continuous=False),
        "signal_speed": slider(
            "brake signal speed (m/s)", 250.0, 100.0, 300.0, 10.0, fmt=".0f", continuous=False
        ),
        "speed_kmh": slider("initial speed (km/h)", 72.0, 20.0, 100.0, 4.0, fmt=".0f", continuous=False),
    }


def _braking_setup(live, status):
    ax_env, ax_t = live.axes[0]
    for value in SLACK_GRID:  # precompute the grid of the static page and of a quick drag
        braking_run(50, float(value), 250.0, 72.0)
    envelope = braking_run(50, 25.0, 250.0, 72.0).plot_envelope(ax_env)  # drawn once, then moved
    ax_env.set_xlim(0, 1800)
    ax_env.set_ylim(-1600, 700)
    (front,) = ax_t.plot([], [], color=plots.COLORS[2], lw=1.0, label="coupler 1 (behind the locomotives)")
    (worst,) = ax_t.plot([], [], color="k", label="coupler with the peak")
    (rear,) = ax_t.plot([], [], color=plots.COLORS[3], lw=1.0, label="last coupler")
    ax_t.axhline(0, color="0.4", lw=0.8)
    ax_t.set_xlim(0, DURATION)
    ax_t.set_ylim(-1600, 700)
    ax_t.set_xlabel("time after the emergency application (s)")
    ax_t.set_ylabel("coupler force (kN)")
    ax_t.legend(loc="lower right")
    live.animate(*envelope.values(), front, worst, rear)

    def redraw(v):
        run = braking_run(
            int(v["cars"]), float(v["slack_mm"]), float(v["signal_speed"]), float(v["speed_kmh"])
        )
        run.plot_envelope(artists=envelope)
        peak = run.peak
        front.set_data(run.t, run.coupler_force[1] / 1e3)
        worst.set_data(run.t, run.coupler_force[peak.coupler] / 1e3)
        rear.set_data(run.t, run.coupler_force[-1] / 1e3)
        consist = train.make_consist(f"2 SD40-2 + {int(v['cars'])} loaded hopper")
        brake = train.AirBrake(propagation_speed=float(v["signal_speed"]))
        status.value = (
            f"peak {abs(peak.force) / 1e3:.0f} kN {peak.kind} at coupler {peak.coupler} "
            f"({peak.offset:.0f} m behind the front) at t = {peak.time:.1f} s · the brake signal reaches "
            f"the rear after {brake.arrival(consist.train_length):.1f} s"
        )

    return redraw


BRAKING_RUN = Recipe(
    _braking_controls,
    _braking_setup,
    {"nrows": 1, "ncols": 2, "figsize": (10.0, 3.8)},
    static={"slack_mm": SLACK_GRID},
    title="Coupler forces of a freight train in emergency braking: envelope along the train and histories",
)


def braking_run_widget():
    """Emergency braking of 2 SD40-2 + N loaded hoppers: coupler-force envelope and histories.

    Controls: number of wagons, slack per coupler (mm), brake-signal speed (m/s)
    and initial speed (km/h); each new combination is one whole-train integration
    (debounced: it runs when a slider is released), repeated ones come from a cache.
    The envelope is drawn by ``TrainRun.plot_envelope`` and moved in place.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return BRAKING_RUN.build()


def _lining_controls():
    return {
        "radius": slider("curve radius (m)", 200.0, 100.0, 1000.0, 10.0, fmt=".0f"),
        "force_kn": slider("coupler force (kN, + draft)", 800.0, -1500.0, 1500.0, 50.0, fmt=".0f"),
    }


_LINING = train.make_consist("3 loaded hopper")
_FORCES = np.linspace(-1500e3, 1500e3, 121)


def _lv(radius):
    """Truck-side L/V of the middle hopper for every force in _FORCES, both couplers equal."""
    return np.array(
        [train.coupler_effects(_LINING, [f, f], curvature=1 / radius).l_over_v[1, 0] for f in _FORCES]
    )


def _lining_setup(live, status):
    (ax,) = live.axes[0]
    for radius in (150, 300, 600):
        ax.plot(_FORCES / 1e3, _lv(radius), color="0.8", lw=0.8)
        ax.annotate(f"R = {radius} m", (1500, _lv(radius)[-1]), fontsize=7, ha="right", va="bottom")
    (curve,) = ax.plot([], [], color=plots.COLORS[0], label="truck-side L/V, middle hopper")
    (mark,) = ax.plot([], [], "o", color="k", mfc="w", mew=2, ms=7)
    ax.set_xlim(-1500, 1500)
    ax.set_ylim(0, 0.5)
    ax.set_xlabel("coupler force (kN): ← buff (jack-knifing) · draft (string-lining) →")
    ax.set_ylabel("truck-side L/V")
    ax.legend(loc="upper center")
    live.animate(curve, mark)

    def redraw(v):
        lv = _lv(v["radius"])
        curve.set_data(_FORCES / 1e3, lv)
        f = v["force_kn"] * 1e3
        effects = train.coupler_effects(_LINING, [f, f], curvature=1 / v["radius"])
        mark.set_data([v["force_kn"]], [effects.l_over_v[1, 0]])
        angle = np.degrees(train.coupler_angles(_LINING, 1 / v["radius"])[0])
        mode = effects.mode[0] or "no coupler force"
        status.value = (
            f"{mode}: coupler angle {angle:.2f}° · lateral force per truck "
            f"{abs(effects.lateral_force[1, 0]) / 1e3:.1f} kN · L/V = {effects.l_over_v[1, 0]:.3f}"
        )

    return redraw


STRING_LINING = Recipe(
    _lining_controls,
    _lining_setup,
    {"nrows": 1, "ncols": 1, "figsize": (7.0, 3.6)},
    static={"radius": [100, 150, 200, 300, 400, 600, 800, 1000]},
    title="Truck-side L/V of a hopper from the lateral components of its coupler forces on a curve",
)


def string_lining():
    """Truck-side L/V of a hopper between two hoppers on a curve, against the coupler force.

    Controls: curve radius (m) and coupler force (kN, + draft). Grey curves:
    R = 150, 300 and 600 m.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return STRING_LINING.build()
