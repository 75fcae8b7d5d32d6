"""A figure's data as a table: what each panel draws, written beside the picture (``save_all(data=True)``,
``python -m raildyn figures --data``).

The table is read from the drawn figure itself, so it is exactly what the picture shows, for any
registered figure: each line's points, each scatter's points, each segment of a line collection, each
bar, each cell of a colour map, and the outline of each band of a filled contour map (or each contour
line), with its level. One row a point, in long form, with the panel's axis labels (which
carry the units) beside the numbers:

``panel, series, x label, x, y label, y, value label, value``

``value`` is filled for a colour map's cells and a contour map's outlines (the band's lower level, or
the line's level; the colour bar's label as its label) and left empty elsewhere. Text, arrows and
shading carry no data of their own and are left out.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.collections import LineCollection, PathCollection, QuadMesh
from matplotlib.container import BarContainer
from matplotlib.contour import ContourSet
from matplotlib.figure import Figure

from raildyn._tables import write_csv

COLUMNS = ("panel", "series", "x label", "x", "y label", "y", "value label", "value")


def _series_name(artist, fallback: str) -> str:
    label = str(artist.get_label() or "")
    return fallback if not label or label.startswith("_") else label


def _colour_label(mesh) -> str:
    """The label of the colour bar drawn for ``mesh``, if one is."""
    bar = getattr(mesh, "colorbar", None)
    return bar.ax.get_ylabel() or bar.ax.get_xlabel() if bar is not None else ""


def _points(
    panel: tuple[str, str, str], series: str, x, y, value_label: str = "", values=None
) -> list[tuple]:
    """Rows of one series: ``panel`` is (name, x label, y label); ``values`` one number a point, or None."""
    name, xl, yl = panel
    x, y = np.ravel(np.asarray(x, float)), np.ravel(np.asarray(y, float))
    v = [""] * x.size if values is None else [repr(float(a)) for a in np.ravel(values)]
    return [
        (name, series, xl, repr(float(a)), yl, repr(float(b)), value_label, c)
        for a, b, c in zip(x, y, v, strict=True)
    ]


def _collection_rows(panel, k: int, coll) -> list[tuple]:
    """Rows of one collection: a contour map's outlines, a colour map's cells, a scatter, line segments."""
    if isinstance(coll, ContourSet):
        rows = []
        for level, path in zip(coll.levels, coll.get_paths(), strict=False):
            xy = np.asarray(path.vertices, float).reshape(-1, 2)
            rows += _points(
                panel, f"level {level:g}", xy[:, 0], xy[:, 1], _colour_label(coll), np.full(len(xy), level)
            )
        return rows
    if isinstance(coll, QuadMesh):
        xy = coll.get_coordinates()  # (rows + 1, columns + 1, 2): the cells' corners
        centres = (xy[:-1, :-1] + xy[1:, 1:]) / 2
        name = _series_name(coll, f"map {k}")
        return _points(panel, name, centres[..., 0], centres[..., 1], _colour_label(coll), coll.get_array())
    if isinstance(coll, PathCollection):
        xy = np.asarray(coll.get_offsets(), float).reshape(-1, 2)
        return _points(panel, _series_name(coll, f"points {k}"), xy[:, 0], xy[:, 1])
    if isinstance(coll, LineCollection):
        rows = []
        for s, seg in enumerate(coll.get_segments(), start=1):
            seg = np.asarray(seg, float).reshape(-1, 2)
            rows += _points(panel, f"{_series_name(coll, f'segments {k}')} [{s}]", seg[:, 0], seg[:, 1])
        return rows
    return []  # shading (fill_between) and arrows: no data of their own


def rows(fig: Figure) -> list[tuple]:
    """The rows of ``fig``'s table, panel by panel (colour bars are not panels)."""
    bars = {mesh.colorbar.ax for ax in fig.axes for mesh in ax.collections if getattr(mesh, "colorbar", None)}
    out = []
    for p, ax in enumerate([ax for ax in fig.axes if ax not in bars], start=1):
        panel = (f"{p}: {ax.get_title()}" if ax.get_title() else str(p), ax.get_xlabel(), ax.get_ylabel())
        for k, line in enumerate(ax.get_lines(), start=1):
            if line.get_visible():
                out += _points(panel, _series_name(line, f"line {k}"), *line.get_data())
        for k, coll in enumerate(ax.collections, start=1):
            if coll.get_visible():
                out += _collection_rows(panel, k, coll)
        for k, container in enumerate(ax.containers, start=1):
            if isinstance(container, BarContainer):
                horizontal = container.orientation == "horizontal"
                for bar in container:  # a bar's centre and its end
                    x, y, w, h = bar.get_x(), bar.get_y(), bar.get_width(), bar.get_height()
                    tip = (x + w, y + h / 2) if horizontal else (x + w / 2, y + h)
                    out += _points(panel, _series_name(container, f"bars {k}"), [tip[0]], [tip[1]])
    return out


def write(fig: Figure, path: Path) -> Path:
    """Write ``fig``'s table to ``path`` as CSV with a header row (raildyn's one CSV writer); return the
    path."""
    table = rows(fig)
    columns = list(zip(*table, strict=True)) if table else [() for _ in COLUMNS]
    return write_csv(path, list(COLUMNS), columns)
