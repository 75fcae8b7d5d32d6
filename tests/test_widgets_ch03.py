"""Chapter 3 widgets driven without a browser: every control changes the picture, in place."""

import io
import re

import ipywidgets
import matplotlib.pyplot as plt
import numpy as np
import pytest
from PIL import Image

from raildyn import track
from raildyn.widgets import chapter03

CASES = {
    chapter03.random_track: dict(
        track="FRA class 2", component="alignment", speed_kmh=160.0, shortest=3.0, longest=150.0, seed=4
    ),
    chapter03.jointed_rail: dict(half_width=3.5, depth_mm=12.0, arrangement="in_phase", speed_kmh=100.0),
}


@pytest.mark.parametrize("factory", list(CASES), ids=lambda f: f.__name__)
def test_each_control_changes_the_frame(factory):
    container, update = factory()
    assert isinstance(container, ipywidgets.VBox)
    first = update()
    assert first.startswith(b"\x89PNG")
    for name, value in CASES[factory].items():
        frame = update(**{name: value})
        assert frame != first, f"moving {name} did not change the picture"
        first = frame


@pytest.mark.parametrize("factory", list(CASES), ids=lambda f: f.__name__)
def test_widget_reuses_its_figure_and_leaves_pyplot_alone(factory):
    before = plt.get_fignums()
    container, update = factory()
    image = container.children[-1]
    update(**CASES[factory])
    assert container.children[-1] is image
    assert plt.get_fignums() == before


@pytest.mark.parametrize("factory", list(CASES), ids=lambda f: f.__name__)
def test_blitted_frame_equals_a_full_redraw(factory):
    container, update = factory()
    for name, value in CASES[factory].items():
        blitted = update(**{name: value})
    container.live.invalidate()
    full = container.live.render()
    pixels = [np.asarray(Image.open(io.BytesIO(png))) for png in (blitted, full)]
    assert np.array_equal(*pixels)


def _status(container):
    return container.children[-2].children[-1].value


def test_random_track_status_gives_the_analytic_band_rms():
    container, update = chapter03.random_track()
    update(track="FRA class 4", component="vertical", shortest=2.0, longest=200.0)
    band = track.wavelength_band((2.0, 200.0))
    expected = 1e3 * np.sqrt(track.band_variance("fra", "vertical", 4, band))
    analytic, sampled = (
        float(s) for s in re.findall(r"(?:analytic|sample) ([0-9.]+) mm", _status(container))
    )
    assert analytic == pytest.approx(expected, abs=0.006)  # printed to 0.01 mm
    assert sampled == pytest.approx(analytic, abs=0.011)  # the sample's mean square is the band integral


def test_random_track_german_gauge_is_reported_missing():
    container, update = chapter03.random_track()
    update(track="German low", component="gauge")
    assert "no German gauge spectrum" in _status(container)


def test_jointed_rail_harmonics_vanish_for_roll_when_in_phase():
    container, update = chapter03.jointed_rail()
    update(arrangement="in_phase")
    ax_h = container.live.axes[0][1]
    roll = ax_h.containers[1]
    assert max(bar.get_height() for bar in roll.patches) == pytest.approx(0.0, abs=1e-9)
    assert "Hz" in _status(container)


@pytest.mark.parametrize(
    "recipe", [chapter03.RANDOM_TRACK, chapter03.JOINTED_RAIL], ids=["random", "jointed"]
)
def test_static_counterpart_holds_one_distinct_frame_per_grid_value(recipe):
    page = recipe.static_html()
    frames = re.search(r"var frames = (\[.*?\]), sizes", page).group(1).split(",")
    ((name, values),) = recipe.static.items()
    assert len(frames) == len(values) and len(set(frames)) == len(values)
    assert 8 <= len(values) <= 16
