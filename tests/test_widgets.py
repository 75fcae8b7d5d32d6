"""Chapter widgets driven without a browser: every control changes the picture, in place."""

import ipywidgets
import matplotlib.pyplot as plt
import pytest

from raildyn.widgets import chapter01

# For each factory: new values for each control, each different from its default.
CASES = {
    chapter01.free_vibration: dict(damping_ratio=1.4, natural_frequency=12.0, x0=-5.0, v0=100.0),
    chapter01.forced_response: dict(damping_ratio=0.5),
    chapter01.chain_modes: dict(
        dof=2, initial="mode 1 shape", mass_ratio=2.0, stiffness_ratio=0.5, damping_ratio=0.1
    ),
    chapter01.random_response: dict(frequency_hz=3.0, damping_ratio=0.3, seed=7),
}


@pytest.mark.parametrize("factory", list(CASES), ids=lambda f: f.__name__)
def test_each_control_changes_the_frame(factory):
    container, update = factory()
    assert isinstance(container, ipywidgets.VBox)
    first = update()
    assert first.startswith(b"\x89PNG"), "a frame is a PNG image"
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
    assert container.children[-1] is image, "the figure widget was rebuilt instead of updated"
    assert plt.get_fignums() == before, "a widget opened a pyplot figure"


def test_reset_restores_the_first_frame():
    container, update = chapter01.forced_response()
    start = update()
    update(damping_ratio=0.7)
    reset = next(
        w
        for row in container.children[:-1]
        for w in getattr(row, "children", [])
        if isinstance(w, ipywidgets.Button)
    )
    reset.click()
    assert container.children[-1].value == start


def test_update_rejects_unknown_control():
    _, update = chapter01.forced_response()
    with pytest.raises(ValueError, match="unknown control"):
        update(zeta=0.3)


def test_free_vibration_status_reports_the_decrement():
    container, update = chapter01.free_vibration()
    update(damping_ratio=0.1)
    status = container.children[-2].children[-1].value
    # δ read off the curve and 2πξ/√(1−ξ²) = 0.6315 for ξ = 0.1 must both be printed.
    assert "0.6315" in status and "underdamped" in status


@pytest.mark.parametrize(
    "recipe", [chapter01.FREE_VIBRATION, chapter01.FORCED_RESPONSE], ids=["free_vibration", "forced_response"]
)
def test_static_counterpart_holds_one_distinct_frame_per_grid_value(recipe):
    import re

    page = recipe.static_html()
    frames = re.search(r"var frames = (\[.*?\]), sizes", page).group(1).split(",")
    ((name, values),) = recipe.static.items()
    assert len(frames) == len(values), "one frame per grid value"
    assert len(set(frames)) == len(values), "every grid value gives a different picture"
    assert 8 <= len(values) <= 16
    # The range input starts at the control's default value.
    start = values.index(recipe.defaults()[name])
    assert f'value="{start}"' in page


def test_display_bundle_carries_the_kernel_free_html():
    container, _ = chapter01.forced_response()
    bundle = container._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert 'class="raildyn-static"' in bundle["text/html"]


def test_static_grid_must_name_one_or_two_controls():
    from raildyn.widgets._static import frames_html

    with pytest.raises(ValueError, match="one or two controls"):
        frames_html(lambda **v: b"", {}, {}, alt="x")


@pytest.mark.parametrize("factory", list(CASES), ids=lambda f: f.__name__)
def test_blitted_frame_equals_a_full_redraw(factory):
    """After several moves, the frame drawn on the cached background equals a full redraw, pixel for pixel."""
    import io

    import numpy as np
    from PIL import Image

    container, update = factory()
    for name, value in CASES[factory].items():
        blitted = update(**{name: value})
    container.live.invalidate()
    full = container.live.render()
    pixels = [np.asarray(Image.open(io.BytesIO(png))) for png in (blitted, full)]
    assert np.array_equal(*pixels)
