"""The frame machinery of the widgets (raildyn.plots.Blitter): its PNG encoder, scatters drawn without hidden
markers."""

import io

import numpy as np
import pytest
from PIL import Image

from raildyn import plots
from raildyn.plots import _png
from raildyn.widgets._core import LiveFigure


def _pixels(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)))


@pytest.mark.parametrize("shape", [(1, 1), (3, 7), (304, 800)])
def test_png_holds_the_pixels_exactly(shape):
    rgba = np.random.default_rng(shape[1]).integers(0, 256, (*shape, 4), dtype=np.uint8)
    frame = _png(rgba)
    picture = Image.open(io.BytesIO(frame))
    assert picture.format == "PNG" and picture.mode == "RGBA"
    np.testing.assert_array_equal(np.asarray(picture), rgba)


def _scatter_figure(**style):
    """A live figure whose moving scatter has most of its points outside the window."""
    live = LiveFigure(figsize=(4.0, 3.0))
    ax = live.axes[0, 0]
    rng = np.random.default_rng(1)
    xy = rng.normal(scale=3.0, size=(600, 2))
    points = live.animate(ax.scatter(xy[:, 0], xy[:, 1], **style))
    ax.set_xlim(-1.0, 1.0)
    ax.set_ylim(-1.0, 1.0)
    return live, points, xy


@pytest.mark.parametrize(
    ("style", "thinned"),
    [
        ({"s": 40, "c": "C0"}, True),  # big markers: the ones just outside the window show in part
        ({"s": 2, "c": np.linspace(0.0, 1.0, 600), "vmin": 0.0, "vmax": 1.0}, True),
        ({"s": np.linspace(1.0, 60.0, 600), "c": "C1"}, False),  # sizes point by point: drawn whole
        # scatter sets the norm's limits from all the values at once, so a subset keeps the colours
        ({"s": 20, "c": np.linspace(0.0, 1.0, 600)}, True),
        ({"s": 20, "c": "C2", "linewidths": np.linspace(0.5, 2.0, 600)}, False),  # widths point by point
    ],
)
def test_a_scatter_draws_the_same_pixels_without_its_hidden_markers(style, thinned, monkeypatch):
    live, points, xy = _scatter_figure(**style)
    drawn = []
    plain = live.figure.draw_artist
    monkeypatch.setattr(live.figure, "draw_artist", lambda a: drawn.append(len(a.get_offsets())) or plain(a))
    frame = live.render()
    assert (drawn[-1] < len(xy)) == thinned, f"{drawn[-1]} of {len(xy)} points drawn"
    np.testing.assert_array_equal(points.get_offsets(), xy, "the artist keeps all its points")
    monkeypatch.setattr(plots, "_draw_points_in_view", lambda figure, artist: figure.draw_artist(artist))
    live.invalidate()
    whole = live.render()
    assert drawn[-1] == len(xy)
    np.testing.assert_array_equal(_pixels(frame), _pixels(whole))
