"""Chapter 9 widgets driven without a browser: every control changes the picture, in place."""

import numpy as np
import pytest

from raildyn import train
from raildyn.widgets import chapter09


def test_braking_widget_reports_the_model_peak():
    container, update = chapter09.braking_run_widget()
    update(slack_mm=25.0, cars=50, signal_speed=250.0, speed_kmh=72.0)
    peak = chapter09.braking_run(50, 25.0, 250.0, 72.0).peak
    force, coupler = peak.force, peak.coupler
    status = container.children[-2].children[-1].value
    assert f"peak {abs(force) / 1e3:.0f} kN" in status and f"coupler {coupler} " in status


def test_string_lining_marker_is_on_the_curve():
    container, update = chapter09.string_lining()
    update(radius=300.0, force_kn=1000.0)
    mark = container.live.figure.axes[0].lines[-1]
    consist = train.make_consist("3 loaded hopper")
    expected = train.coupler_effects(consist, [1e6, 1e6], curvature=1 / 300).l_over_v[1, 0]
    assert np.asarray(mark.get_ydata())[0] == pytest.approx(expected)


def test_static_grids_are_small():
    for recipe in (chapter09.BRAKING_RUN, chapter09.STRING_LINING):
        assert len(recipe.static) == 1 and 8 <= len(next(iter(recipe.static.values()))) <= 16


def test_braking_widget_envelope_is_the_runs_own_plot_moved_in_place():
    # The envelope is drawn by TrainRun.plot_envelope and moved in place on later changes:
    # its x data are the coupler positions of the consist chosen, its y data the run's envelope.
    container, update = chapter09.braking_run_widget()
    ax = container.live.figure.axes[0]
    lines = list(ax.lines)
    update(cars=20, slack_mm=50.0, signal_speed=150.0, speed_kmh=40.0)
    assert list(ax.lines) == lines
    run = chapter09.braking_run(20, 50.0, 150.0, 40.0)
    draft, buff, peak = lines[:3]
    np.testing.assert_array_equal(
        draft.get_xdata(), train.make_consist("2 SD40-2 + 20 loaded hopper").coupler_offsets
    )
    np.testing.assert_array_equal(draft.get_ydata(), run.max_tension / 1e3)
    np.testing.assert_array_equal(buff.get_ydata(), -run.max_compression / 1e3)
    assert peak.get_xdata()[0] == run.peak.offset
    status = container.children[-2].children[-1].value
    assert (
        f"{run.peak.kind} at coupler {run.peak.coupler} ({run.peak.offset:.0f} m behind the front)" in status
    )


@pytest.mark.parametrize(
    ("changes", "error", "match"),
    [
        ({"cars": [10, 10]}, TypeError, "cars must be an integer"),  # was "unhashable type" from the cache
        ({"cars": 201}, ValueError, r"cars must be an integer in \[1, 200\]"),
        ({"slack_mm": -1.0}, ValueError, "slack_mm must be in"),  # was blamed on slack
        ({"slack_mm": None}, TypeError, "slack_mm must be a real number"),
        ({"signal_speed": 400.0}, ValueError, r"signal_speed must be in \[10.0, 343.0\]"),
        ({"speed_kmh": 0.0}, ValueError, "speed_kmh must be in"),  # was a run of a standing train
    ],
)
def test_braking_run_refuses_bad_input_naming_the_parameter(changes, error, match):
    args = {"cars": 10, "slack_mm": 25.0, "signal_speed": 250.0, "speed_kmh": 72.0} | changes
    with pytest.raises(error, match=match):
        chapter09.braking_run(**args)
