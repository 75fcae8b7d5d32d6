"""The drawing pieces every schematic of :mod:`raildyn.diagrams` shares: one spring, one dashpot, one
dimension line, one rigid block, the ground, and the quiet style they are drawn in.

Each piece has a pure function that returns the coordinates (``spring_xy``, ``dashpot_xy``, ...),
which a moving schematic calls again to update its artists in place, and a function that draws it
on an axes and returns the artists. Lengths are in the model's units (m) and the pictures are drawn
to scale, with equal aspect and no frame.
"""

from __future__ import annotations

import matplotlib
import numpy as np
from matplotlib.patches import FancyArrowPatch, Polygon

from raildyn import _checks, plots

LINE = {"color": "black", "lw": 0.9, "solid_capstyle": "round", "solid_joinstyle": "round"}
"""Thin black lines: every outline, spring and dashpot."""

FILL = "0.88"
"""Light grey: the fill of every rigid body."""

DIMENSION = "0.35"
"""Dark grey: dimension lines and their labels."""

COORDINATE = plots.COLORS[0]
"""The house blue: coordinates (y, ψ, z, θ, x) and motions, so the eye tells them from lengths."""

FORCE = plots.COLORS[1]
"""The house red: applied forces and the direction of travel."""


def style():
    """The rc context inside which every schematic draws (the house fonts; the caller's defaults kept)."""
    return matplotlib.rc_context({**plots.STYLE, "axes.grid": False})


def start(ax, size: tuple[float, float] | None = None):
    """The axes to draw on (new ones if None, a TypeError naming ``ax`` for anything else).

    New axes get a figure of ``size`` (inches) if given: a long car or a train wants a wide figure.
    """
    made = ax is None
    ax = plots.axes_or_new(ax)
    if made and size is not None:
        ax.figure.set_size_inches(*size)
    return ax


def finish(ax, margin: float = 0.06) -> None:
    """Equal aspect, no frame, limits around what is drawn."""
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_axis_off()
    ax.autoscale_view()
    ax.margins(margin)


def rotate(points, angle: float, centre=(0.0, 0.0)) -> np.ndarray:
    """Points (n, 2) turned by ``angle`` (rad, anticlockwise) about ``centre``."""
    p = np.asarray(points, dtype=float) - centre
    c, s = np.cos(angle), np.sin(angle)
    return p @ np.array([[c, s], [-s, c]]) + centre


def rectangle_xy(centre, width: float, height: float, angle: float = 0.0) -> np.ndarray:
    """The corners (4, 2) of a ``width`` × ``height`` rectangle about ``centre``, turned by ``angle``."""
    w, h = width / 2, height / 2
    corners = np.array([[-w, -h], [w, -h], [w, h], [-w, h]]) + centre
    return rotate(corners, angle, centre)


def block(ax, xy, *, fill: str = FILL, z: float = 1.0) -> Polygon:
    """A rigid body: a closed polygon, thin black outline, light grey fill."""
    patch = Polygon(
        np.asarray(xy, dtype=float), closed=True, facecolor=fill, edgecolor="black", lw=0.9, zorder=z
    )
    ax.add_patch(patch)
    return patch


def spring_xy(p0, p1, width: float, coils: int = 6, lead: float = 0.15) -> np.ndarray:
    """A zigzag spring from ``p0`` to ``p1`` (points (n, 2)); straight leads of ``lead`` of its length."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    axis = p1 - p0
    length = np.hypot(*axis)
    along = axis / length if length > 0 else np.array([0.0, 1.0])
    normal = np.array([-along[1], along[0]])
    n = 2 * coils
    s = np.concatenate([[0.0, lead], lead + (1 - 2 * lead) * (np.arange(n) + 0.5) / n, [1 - lead, 1.0]])
    offset = np.concatenate([[0.0, 0.0], 0.5 * width * (-1.0) ** np.arange(n), [0.0, 0.0]])
    return p0 + np.outer(s * length, along) + np.outer(offset, normal)


def spring(ax, p0, p1, width: float, coils: int = 6):
    """Draw a zigzag spring from ``p0`` to ``p1``; returns its Line2D."""
    xy = spring_xy(p0, p1, width, coils)
    (line,) = ax.plot(xy[:, 0], xy[:, 1], zorder=2, **LINE)
    return line


def dashpot_xy(p0, p1, width: float) -> np.ndarray:
    """A dashpot from ``p0`` (its rod) to ``p1`` (its cylinder), as one path with NaN breaks (n, 2)."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    axis = p1 - p0
    length = np.hypot(*axis)
    along = axis / length if length > 0 else np.array([0.0, 1.0])
    normal = np.array([-along[1], along[0]])
    w = width / 2

    def at(s, t):
        return p0 + s * length * along + t * normal

    gap = np.full(2, np.nan)
    path = [
        at(0, 0), at(0.55, 0), gap,  # the rod
        at(0.55, -0.8 * w), at(0.55, 0.8 * w), gap,  # the piston
        at(0.35, -w), at(0.75, -w), at(0.75, w), at(0.35, w), gap,  # the cylinder, open to the rod
        at(0.75, 0), at(1, 0),  # the cylinder's rod to p1
    ]  # fmt: skip
    return np.array(path)


def dashpot(ax, p0, p1, width: float):
    """Draw a dashpot from ``p0`` to ``p1``; returns its Line2D."""
    xy = dashpot_xy(p0, p1, width)
    (line,) = ax.plot(xy[:, 0], xy[:, 1], zorder=2, **LINE)
    return line


def ground(ax, x0: float, x1: float, y: float, depth: float, *, below: bool = True) -> list:
    """A hatched ground line from ``x0`` to ``x1`` at height ``y`` (hatches below it, or above)."""
    (line,) = ax.plot([x0, x1], [y, y], **LINE)
    n = max(int((x1 - x0) / depth), 2)
    xs = np.linspace(x0, x1, n + 1)[:-1] + 0.5 * (x1 - x0) / n
    sign = -1.0 if below else 1.0
    hatch = np.full((3 * n, 2), np.nan)
    hatch[0::3] = np.column_stack([xs, np.full(n, y)])
    hatch[1::3] = np.column_stack([xs - 0.6 * depth, np.full(n, y + sign * depth)])
    (lines,) = ax.plot(hatch[:, 0], hatch[:, 1], color="black", lw=0.6)
    return [line, lines]


def dimension(ax, p0, p1, text: str, *, offset=(0.0, 0.0), side: float = 1.0, size: float = 9):
    """A dimension line with arrows at both ends between ``p0`` and ``p1`` moved by ``offset``, labelled.

    Extension lines join the points to the dimension line when ``offset`` is not zero. Returns
    ``(arrow, text)``; ``arrow.set_positions`` and ``text.set_position`` move them.
    """
    p0 = np.asarray(p0, float) + offset
    p1 = np.asarray(p1, float) + offset
    arrow = FancyArrowPatch(
        p0, p1, arrowstyle="<|-|>", mutation_scale=7, color=DIMENSION, lw=0.7, shrinkA=0, shrinkB=0, zorder=3
    )
    ax.add_patch(arrow)
    if np.any(np.asarray(offset) != 0):
        for p in (p0, p1):
            q = p - np.asarray(offset, float) * 0.9
            ax.plot([q[0], p[0]], [q[1], p[1]], color=DIMENSION, lw=0.5)
    label = ax.annotate(
        text,
        dimension_label_xy(p0, p1),
        xytext=_normal_offset(p0, p1, side),
        ha="center",
        va="center",
        textcoords="offset points",
        color=DIMENSION,
        fontsize=size,
        zorder=4,
    )
    return arrow, label


def dimension_label_xy(p0, p1) -> np.ndarray:
    """Where a dimension's label sits: the middle of its line."""
    return 0.5 * (np.asarray(p0, float) + np.asarray(p1, float))


def _normal_offset(p0, p1, side: float) -> tuple[float, float]:
    d = np.asarray(p1, float) - np.asarray(p0, float)
    n = np.array([-d[1], d[0]]) / max(np.hypot(*d), 1e-300)
    return tuple(7.0 * side * n)


def arrow(ax, p0, p1, *, color: str = COORDINATE, lw: float = 1.1, z: float = 5) -> FancyArrowPatch:
    """A single arrow from ``p0`` to ``p1`` (a coordinate, a force, the direction of travel)."""
    patch = FancyArrowPatch(
        p0, p1, arrowstyle="-|>", mutation_scale=9, color=color, lw=lw, shrinkA=0, shrinkB=0, zorder=z
    )
    ax.add_patch(patch)
    return patch


def arc_xy(centre, radius: float, start: float, extent: float, n: int = 40) -> np.ndarray:
    """Points (n, 2) on a circular arc from angle ``start`` through ``extent`` (rad)."""
    t = start + extent * np.linspace(0.0, 1.0, n)
    return np.asarray(centre, float) + radius * np.column_stack([np.cos(t), np.sin(t)])


def rotation(ax, centre, radius: float, start: float, extent: float, *, color: str = COORDINATE):
    """A curved arrow for a rotation (ψ, θ, the angles of a rigid body); returns ``(line, head)``."""
    xy = arc_xy(centre, radius, start, extent)
    (line,) = ax.plot(xy[:-3, 0], xy[:-3, 1], color=color, lw=1.1, zorder=5)
    head = arrow(ax, xy[-4], xy[-1], color=color)
    return line, head


def label(ax, xy, text: str, *, color: str = "black", size: float = 9, **kw):
    """A label at ``xy`` (data coordinates), centred unless ``ha``/``va`` say otherwise."""
    kw = {"ha": "center", "va": "center", **kw}
    return ax.text(xy[0], xy[1], text, color=color, fontsize=size, zorder=6, **kw)


def note(ax, xy, text: str, *, points: float, size: float = 7):
    """A small grey note centred under ``xy`` (data coordinates), its top ``points`` below it.

    Set in points, not in data units, so that it clears the labels above it at any figure size.
    """
    return ax.annotate(
        text, xy, xytext=(0.0, -points), textcoords="offset points", ha="center", va="top",
        color=DIMENSION, fontsize=size, zorder=6,
    )  # fmt: skip


def wheel_xy(centre, radius: float, n: int = 60) -> np.ndarray:
    """A wheel seen from the side: a circle (n, 2)."""
    return arc_xy(centre, radius, 0.0, 2 * np.pi, n)


def amount(name: str, value, *, low: float = 0.0, high: float | None = None) -> float:
    """A finite drawing parameter in [low, high]: a ValueError/TypeError naming ``name`` otherwise."""
    return _checks.scalar(name, value, low=low, high=high)


def si(value: float, unit: str) -> str:
    """A value with its unit and an SI prefix, short (``400 kN/m``)."""
    for factor, prefix in ((1e9, "G"), (1e6, "M"), (1e3, "k"), (1.0, "")):
        if abs(value) >= factor or factor == 1.0:
            return f"{value / factor:.3g} {prefix}{unit}"
    return f"{value:.3g} {unit}"  # pragma: no cover
