"""Chapter 4 widgets driven without a browser: every control changes the picture, in place."""

import re

import ipywidgets
import matplotlib.pyplot as plt
import pytest

from raildyn.widgets import chapter04

# For each factory: new values for each control, each different from its default.
CASES = {
    chapter04.hertz: dict(load_kn=150.0, wheel_radius_mm=400.0, rail_radius_mm=120.0),
    chapter04.creep_laws: dict(a_over_b=2.0, spin=1.0, friction=0.4, load_kn=60.0),
    chapter04.fastsim_patch: dict(xi_permille=3.0, eta_permille=-1.0, spin=0.5, friction=0.2),
    # A cone gives the same Δr(y) = 2λy on any rail and gauge, so the wheel changes last.
    chapter04.profiles: dict(rail="60E1 at 1:20", gauge_mm=1440.0, wheel="cone 1:20"),
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


def test_hertz_status_gives_the_circular_case():
    container, update = chapter04.hertz()
    # Wheel 460 mm on a 460 mm crown with a conical tread: A = B, so θ = 90° and m = n = 1.
    update(wheel_radius_mm=460.0, rail_radius_mm=460.0)
    status = container.children[-2].children[-1].value
    assert "θ = 90.0°" in status and "m = 1.000" in status


def test_fastsim_status_reports_full_sliding():
    container, update = chapter04.fastsim_patch()
    update(xi_permille=5.0, eta_permille=5.0, spin=0.0, friction=0.1)
    status = container.children[-2].children[-1].value
    assert "|F|/μN = 1.000" in status


@pytest.mark.parametrize("recipe", [chapter04.HERTZ, chapter04.FASTSIM_PATCH], ids=["hertz", "fastsim_patch"])
def test_static_counterpart_holds_one_distinct_frame_per_grid_value(recipe):
    page = recipe.static_html()
    frames = re.search(r"var frames = (\[.*?\]), sizes", page).group(1).split(",")
    ((name, values),) = recipe.static.items()
    assert len(frames) == len(values)
    assert len(set(frames)) == len(values)
