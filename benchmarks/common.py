"""What every benchmark file shares: the result of one case, a timer, and a generic widget case.

A benchmark file is ``benchmarks/bench_<topic>.py`` with a function
``cases(repeats) -> list[Case]``; ``run.py`` finds and runs them all.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass

import ipywidgets as widgets
import numpy as np

from raildyn.widgets import LiveFigure, Recipe


@dataclass
class Case:
    """One timed task beside its baseline, both measured in the same run (seconds per repeat)."""

    name: str
    raildyn: list[float]
    baseline: list[float]
    goal: str
    baseline_name: str = "baseline"

    @property
    def ratio(self) -> float:
        return statistics.median(self.baseline) / statistics.median(self.raildyn)


def timed(fn: Callable[[int], object], repeats: int) -> list[float]:
    """Wall times of ``fn(i)`` for i = 0 … repeats−1."""
    times = []
    for i in range(repeats):
        start = time.perf_counter()
        fn(i)
        times.append(time.perf_counter() - start)
    return times


def fresh_frame(recipe: Recipe, **values) -> bytes:
    """One frame of a widget drawn on a brand-new figure: the naive baseline of the widget cases.

    The same model and plot code as the live widget (the recipe's ``setup`` and
    its ``redraw``), but a new figure, new axes and a full draw for every change,
    the way ``ipywidgets.interact`` redraws.
    """
    live = LiveFigure(**recipe.figure)
    redraw = recipe.setup(live, widgets.HTML())
    redraw({**recipe.defaults(), **values})
    return live.render()


def widget_case(
    label: str, recipe, control: str, values: list, repeats: int, goal: str = "median ≤ 30 ms, ≥ 3× faster"
) -> Case:
    """A widget's update (model + redraw of the same figure) against a new figure per change.

    The baseline is :func:`fresh_frame`: the same model and plot code on a
    brand-new figure each time, the way ``interact`` redraws. Every widget is held to one goal, the
    slowest at 30 ms (issue 22).
    """
    _, update = recipe.build()
    moves = [{control: v} for v in values]
    update(**moves[-1])  # warm the caches before timing
    live = timed(lambda i: update(**moves[i % len(moves)]), repeats)
    naive = timed(lambda i: fresh_frame(recipe, **moves[i % len(moves)]), repeats)
    return Case(f"widget {label}", live, naive, goal, "new figure per change")


def _critical_speed_on_pole_grid(model, speed_range: tuple[float, float], n: int = 1000) -> float:
    """The baseline: python-control's poles at each of ``n`` speeds, the first zero crossing interpolated."""
    import control

    from raildyn import vibration

    system = model.linear_system()
    speeds = np.linspace(*speed_range, n)
    B = np.ones((system.size, 1))
    g = np.empty(n)
    for i, V in enumerate(speeds):
        mats = system.matrices(V)
        g[i] = control.poles(vibration.to_control(mats.M, mats.C, mats.K, B)).real.max()
    k = int(np.flatnonzero((g[:-1] < 0) & (g[1:] >= 0))[0])
    return float(speeds[k] - g[k] * (speeds[k + 1] - speeds[k]) / (g[k + 1] - g[k]))


def critical_speed_case(name: str, model, speed_range: tuple[float, float], repeats: int) -> Case:
    """A linear model's critical speed by :func:`raildyn.stability.critical_speed` against the pole grid.

    Both answers must agree within 0.1 m/s (the grid's spacing over 200 m/s or less; its linear
    interpolation is far better than that) before the timing counts. raildyn builds the model's
    system afresh on each repeat, as the baseline does.
    """
    from raildyn import stability

    ours = stability.critical_speed(model.linear_system(), speed_range).speed
    theirs = _critical_speed_on_pole_grid(model, speed_range)
    if abs(ours - theirs) > 0.1:
        raise AssertionError(
            f"critical speeds of the {name} disagree: raildyn {ours:.3f}, python-control grid "
            f"{theirs:.3f} m/s"
        )
    fast = timed(lambda i: stability.critical_speed(model.linear_system(), speed_range), repeats)
    slow = timed(lambda i: _critical_speed_on_pole_grid(model, speed_range), max(1, repeats // 3))
    return Case(
        f"critical speed of the {name} ({ours:.2f} m/s)",
        fast,
        slow,
        "≥ 20× faster at equal accuracy (0.1 m/s)",
        "python-control poles, 1000-point grid",
    )
