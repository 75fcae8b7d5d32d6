"""Chapter 9 widgets driven without a browser: every control changes the picture, in place."""

import numpy as np
import pytest

from raildyn import train
from raildyn.widgets import chapter09


def test_braking_widget_reports_the_model_peak():
    container, update = chapter09.braking_run_widget()
    update(slack_mm=25.0, cars=50, signal_speed=250.0, speed_kmh=72.0)
    force, coupler, _ = chapter09.braking_run(50, 25.0, 250.0, 72.0).peak()
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
