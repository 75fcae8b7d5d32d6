"""Chapter 5 and 7 widgets driven without a browser: every control changes the picture, in place."""

import re

import ipywidgets
import matplotlib.pyplot as plt
import pytest

from raildyn import stability, wheelset
from raildyn.widgets import chapter05, chapter07

# For each factory: new values for each control, each different from its default.
CASES = {
    chapter05.klingel: dict(conicity=0.3, rolling_radius_mm=400.0, semi_wheelbase=1.0),
    chapter05.wheelset_roots: dict(conicity=0.3, yaw_stiffness=8.0, lateral_stiffness=3.0),
    chapter07.car_roots: dict(conicity=0.3, yaw_stiffness=20.0),
    chapter07.critical_curve: dict(yaw_stiffness=20.0, secondary_yaw_stiffness=1.0),
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


def _status(container):
    return container.children[-2].children[-1].value


def test_klingel_status_gives_the_wavelength():
    container, update = chapter05.klingel()
    update(conicity=0.1, rolling_radius_mm=500.0)
    expected = wheelset.kinematic_wavelength(0.5, 0.75, 0.1)
    assert f"{expected:.2f} m" in _status(container)


def test_wheelset_roots_status_gives_the_critical_speed():
    container, update = chapter05.wheelset_roots()
    update(conicity=0.2, yaw_stiffness=2.0, lateral_stiffness=1.0)
    ws = wheelset.Wheelset(conicity=0.2, yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)
    cs = stability.critical_speed(ws, (2.0, 120.0))
    # The widget's root is found to 0.05 m/s and printed to 0.1 m/s.
    shown = float(re.search(r"critical speed ([\d.]+) m/s", _status(container)).group(1))
    assert shown == pytest.approx(cs.speed, abs=0.1)


def test_free_wheelset_is_reported_unstable():
    container, update = chapter05.wheelset_roots()
    update(yaw_stiffness=0.0, lateral_stiffness=0.0)
    assert "unstable at the lowest speed" in _status(container)


@pytest.mark.parametrize("recipe", [chapter05.KLINGEL, chapter07.CAR_ROOTS], ids=["klingel", "car_roots"])
def test_static_counterpart_holds_one_distinct_frame_per_grid_value(recipe):
    page = recipe.static_html()
    frames = re.search(r"var frames = (\[.*?\]), sizes", page).group(1).split(",")
    ((_, values),) = recipe.static.items()
    assert len(frames) == len(values)
    assert len(set(frames)) == len(values)
