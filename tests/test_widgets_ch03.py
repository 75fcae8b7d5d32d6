"""Chapter 3 widgets driven without a browser: every control changes the picture, in place."""

import re

import numpy as np
import pytest
from widget_helpers import status_line

from raildyn import track
from raildyn.widgets import chapter03


def test_random_track_status_gives_the_analytic_band_rms():
    container, update = chapter03.random_track()
    update(track="FRA class 4", component="vertical", shortest=2.0, longest=200.0)
    band = track.wavelength_band((2.0, 200.0))
    expected = 1e3 * np.sqrt(track.band_variance("fra", "vertical", 4, band))
    analytic, sampled = (
        float(s) for s in re.findall(r"(?:analytic|sample) ([0-9.]+) mm", status_line(container))
    )
    assert analytic == pytest.approx(expected, abs=0.006)  # printed to 0.01 mm
    assert sampled == pytest.approx(analytic, abs=0.011)  # the sample's mean square is the band integral


def test_random_track_german_gauge_has_its_spectrum():
    container, update = chapter03.random_track()
    low = update(track="German low", component="gauge")
    high = update(track="German high")
    assert low != high and "RMS" in status_line(container)


def test_jointed_rail_harmonics_vanish_for_roll_when_in_phase():
    container, update = chapter03.jointed_rail()
    update(arrangement="in_phase")
    ax_h = container.live.axes[0][1]
    roll = ax_h.containers[1]
    assert max(bar.get_height() for bar in roll.patches) == pytest.approx(0.0, abs=1e-9)
    assert "Hz" in status_line(container)


def test_dipped_joint_draws_the_run_it_reports():
    container, update = chapter03.dipped_joint()
    update(speed_kmh=120.0, dip_mrad=12.0)
    _, run = chapter03._joint_run(120.0, 12.0, 900.0)
    (ax,) = container.live.axes[0]
    force, peaks = ax.lines[0], ax.lines[1]
    # The drawn curve is the model's run, in kN against ms since the joint, and the marks its P1 and P2.
    assert np.allclose(force.get_ydata(), 1e-3 * run.contact_force[:, 0])
    assert np.allclose(sorted(peaks.get_ydata()), sorted(1e-3 * np.array(run.peaks(chapter03._JOINT_X))))
    p1, p2 = run.peaks(chapter03._JOINT_X)
    assert f"P1 {1e-3 * p1:.0f} kN" in status_line(container)
    # A steeper dip at the same speed gives a larger P2 (P2 − Q₀ grows with 2αV).
    assert chapter03._joint_run(120.0, 16.0, 900.0)[1].peaks(chapter03._JOINT_X)[1] > p2
