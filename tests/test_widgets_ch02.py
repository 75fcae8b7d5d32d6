"""Chapter 2 widgets driven without a browser: every control changes the picture, in place."""

import re

import ipywidgets
import matplotlib.pyplot as plt
import pytest

from raildyn.widgets import chapter02

# For each factory: new values for each control, each different from its default.
CASES = {
    chapter02.scheme_response: dict(method="houbolt", dt_over_T=0.25, damping_ratio=0.05),
    chapter02.accuracy_chart: dict(method="central_difference", damping_ratio=0.1),
}


def _status(container):
    return container.children[-2].children[-1].value


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


def test_scheme_response_prints_errors_and_reports_instability():
    container, update = chapter02.scheme_response()
    update(method="average_acceleration", dt_over_T=0.1, damping_ratio=0.0)
    status = _status(container)
    # Average acceleration at Δt/T = 0.1: period elongation 0.2π/(2 arctan 0.1π) − 1 = 3.21 %, no decay.
    assert "largest error" in status and "+3.21 %" in status and "+0.00 %" in status
    update(method="central_difference", dt_over_T=0.5)
    assert "unstable" in _status(container) and "diverged at step" in _status(container)


def test_accuracy_chart_gives_the_stability_limit():
    container, update = chapter02.accuracy_chart()
    update(method="central_difference", damping_ratio=0.0)
    assert "Δt/T ≤ 0.3183" in _status(container)  # 1/π
    update(method="houbolt")
    assert "unconditionally stable" in _status(container)


@pytest.mark.parametrize(
    "recipe", [chapter02.SCHEME_RESPONSE, chapter02.ACCURACY_CHART], ids=["response", "chart"]
)
def test_static_counterpart_holds_one_distinct_frame_per_grid_value(recipe):
    page = recipe.static_html()
    frames = re.search(r"var frames = (\[.*?\]), sizes", page).group(1).split(",")
    ((name, values),) = recipe.static.items()
    assert 8 <= len(values) <= 16
    assert len(frames) == len(values) and len(set(frames)) == len(values)
