"""Chapter 6 widgets driven without a browser: the status lines carry the models' numbers."""

import re

import numpy as np
import pytest

from raildyn import ride, track
from raildyn.vehicles import MANCHESTER_VERTICAL, response_spectrum
from raildyn.widgets import chapter06


def _status(container):
    return container.children[-2].children[-1].value


def test_ride_status_gives_the_frequency_domain_index_and_a_matching_run():
    container, update = chapter06.ride_quality()
    update(track="FRA class 4", speed_kmh=120.0, seed=3)
    text = _status(container)
    rms_fd, rms_td = (float(x) for x in re.findall(r"RMS ([0-9.]+) m/s²", text))
    wz_fd, wz_td = (float(x) for x in re.findall(r"Wz ([0-9.]+)", text))
    w = np.linspace(0.2, 2 * np.pi * 30, 3000)
    spec = response_spectrum(
        MANCHESTER_VERTICAL.linear_system(), lambda o: track.fra_psd("vertical", 4, o), 120 / 3.6, w, "body z", 2
    )
    want = ride.ride_quality(spec.psd, w)
    # printed to 3 decimals and 2 decimals; grids of 1200 and 3000 points agree to < 0.1 %
    assert rms_fd == pytest.approx(want.rms, abs=2e-3)
    assert wz_fd == pytest.approx(want.wz, abs=0.011)
    # one 1.5 km sample of the band 1–300 m: the RMS matches within 5 % (the band holds all but
    # the longest waves, which the body follows without accelerating)
    assert rms_td == pytest.approx(rms_fd, rel=0.05)
    assert wz_td == pytest.approx(wz_fd, abs=0.05)


@pytest.mark.parametrize("label", list(chapter06.FREIGHT_CARS))
def test_rock_widget_marks_the_resonance_speed(label):
    container, update = chapter06.rock_and_roll_widget()
    update(car=label, speed_kmh=40.0)
    resonance = float(re.search(r"roll resonance \(springs alone\) at ([0-9.]+) km/h", _status(container))[1])
    assert resonance == pytest.approx(3.6 * chapter06.FREIGHT_CARS[label].roll_resonance_speed(), abs=0.51)
    ax = container.live.axes[0][0]
    amp = ax.lines[0].get_ydata()
    # the sweep's largest amplitude lies within one grid step (2.5 km/h) of the marked resonance
    peak = chapter06._ROCK_SPEEDS_KMH[int(np.argmax(amp))]
    assert abs(peak - resonance) <= 2.5
