"""What the animations of :mod:`raildyn.animations` share: the figure they draw on, the frames' times
picked from a run's samples, the exaggeration a picture states, and the trace with its moving cursor."""

from __future__ import annotations

import numpy as np

from raildyn import _checks, plots

# The frames' size: 6.4 × 3.6 in at 64 dpi (410 × 230 px) keeps a frame with its trace near 8 kB, so that
# 40 frames stay near 400 kB of HTML (base64 adds a third).
SIZE = (6.4, 3.6)
DPI = 64
NICE = (1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0, 2000.0, 5000.0, 10000.0)


def figure(rows: int = 2, heights=(2.2, 1.0), size=SIZE):
    """A figure outside pyplot (so that nothing is shown twice in a notebook) with ``rows`` axes."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=size, dpi=DPI, layout="constrained")
    axes = fig.subplots(rows, 1, height_ratios=heights[:rows]) if rows > 1 else [fig.subplots()]
    return fig, list(np.atleast_1d(axes))


def frame_count(frames) -> int:
    return _checks.integer("frames", frames, low=2, high=400)


def picks(t: np.ndarray, start: float, stop: float, frames: int) -> np.ndarray:
    """Indices of the samples of ``t`` nearest to ``frames`` times evenly spread over [start, stop]."""
    wanted = np.linspace(start, stop, frames)
    return np.clip(np.searchsorted(t, wanted), 0, t.size - 1)


def exaggeration(largest: float, room: float) -> float:
    """The largest round factor (1, 2, 5, 10, …) that draws ``largest`` within ``room``."""
    if largest <= 0.0:
        return 1.0
    fits = [f for f in NICE if f * largest <= room]
    return fits[-1] if fits else 1.0


def trace(ax, t, curves: dict, *, ylabel: str, xlabel: str = "t (s)", window=None):
    """The run's curves over its whole time, the animated window shaded, and a cursor to move."""
    import matplotlib

    with matplotlib.rc_context(plots.STYLE):
        for k, (name, values) in enumerate(curves.items()):
            ax.plot(t, values, color=plots.COLORS[k], lw=1.0, label=name)
        if window is not None:
            ax.axvspan(*window, color="0.9", zorder=0)
        cursor = ax.axvline(t[0], color="0.2", lw=0.8)
        ax.set_xlim(t[0], t[-1])
        ax.set_xlabel(xlabel, fontsize=8)
        ax.set_ylabel(ylabel, fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(alpha=0.3)
        if len(curves) > 1:
            ax.legend(fontsize=7, loc="upper left", frameon=False, ncols=len(curves))
    return cursor


def artists(*groups) -> list:
    """The artists in ``groups`` (artists, or lists, tuples and dicts of them, nested), each once."""
    from matplotlib.artist import Artist

    found: list = []

    def walk(item):
        if isinstance(item, Artist):
            if all(item is not a for a in found):
                found.append(item)
        elif isinstance(item, dict):
            for value in item.values():
                walk(value)
        elif isinstance(item, list | tuple):
            for value in item:
                walk(value)

    for group in groups:
        walk(group)
    return found
