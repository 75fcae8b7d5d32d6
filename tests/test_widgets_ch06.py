"""Chapter 6 widgets driven without a browser: the status lines carry the models' numbers."""

import dataclasses
import re

import numpy as np
import pytest
from widget_helpers import status_line, widgets_of

from raildyn import ride, track
from raildyn.vehicles import MANCHESTER_VERTICAL, response_spectrum
from raildyn.widgets import chapter06


def test_ride_status_gives_the_frequency_domain_index_and_a_matching_run():
    container, update = chapter06.ride_quality()
    update(track="FRA class 4", speed_kmh=120.0, seed=3)
    text = status_line(container)
    rms_fd, rms_td = (float(x) for x in re.findall(r"RMS ([0-9.]+) m/s²", text))
    wz_fd, wz_td = (float(x) for x in re.findall(r"Wz ([0-9.]+)", text))
    w = np.linspace(0.2, 2 * np.pi * 30, 3000)

    def fra4(omega):
        return track.fra_psd("vertical", 4, omega)

    spec = response_spectrum(
        MANCHESTER_VERTICAL.linear_system(), fra4, 120 / 3.6, w, "body z", 2, component="vertical"
    )
    want = ride.ride_quality(spec.psd, w)
    # printed to 3 decimals and 2 decimals; grids of 1200 and 3000 points agree to < 0.1 %
    assert rms_fd == pytest.approx(want.rms, abs=2e-3)
    assert wz_fd == pytest.approx(want.wz, abs=0.011)
    # one 1.5 km sample of the band 1–300 m: the RMS matches within 5 % (the band holds all but
    # the longest waves, which the body follows without accelerating)
    assert rms_td == pytest.approx(rms_fd, rel=0.05)
    assert wz_td == pytest.approx(wz_fd, abs=0.05)


@widgets_of("chapter06")  # the rocking sweep is made once, with chapter 6's other widget tests
@pytest.mark.parametrize("label", list(chapter06.FREIGHT_CARS))
def test_rock_widget_marks_the_resonance_speed(label):
    container, update = chapter06.rock_and_roll_widget()
    update(car=label, speed_kmh=40.0)
    resonance = float(
        re.search(r"roll resonance \(springs alone\) at ([0-9.]+) km/h", status_line(container))[1]
    )
    assert resonance == pytest.approx(3.6 * chapter06.FREIGHT_CARS[label].roll_resonance_speed(), abs=0.51)
    ax = container.live.axes[0][0]
    amp = ax.lines[0].get_ydata()
    # the sweep's largest amplitude lies within one grid step (2.5 km/h) of the marked resonance
    peak = chapter06._ROCK_SPEEDS_KMH[int(np.argmax(amp))]
    assert abs(peak - resonance) <= 2.5


def test_ride_run_gives_a_frozen_result_whose_measures_are_those_of_its_parts():
    run = chapter06.ride_run("FRA class 4", 120.0, 3)
    assert isinstance(run, chapter06.RideRun)
    with pytest.raises(dataclasses.FrozenInstanceError):
        run.t = None
    # the run starts at 0 once the settling is dropped, one acceleration per time
    assert run.t[0] == pytest.approx(0.0, abs=1e-9) and run.t.shape == run.acceleration.shape
    assert run.spectrum.speed == pytest.approx(120.0 / 3.6, rel=1e-12)
    # the measures are recomputed from the fields the result carries (same code, same data: 1e-9)
    fd = ride.ride_quality(run.spectrum.psd, run.spectrum.omega)
    assert fd.rms == pytest.approx(run.frequency_domain.rms, rel=1e-9)
    assert fd.wz == pytest.approx(run.frequency_domain.wz, rel=1e-9)
    td = ride.ride_quality_history(run.acceleration, 0.01)  # the run's 10 ms step
    assert td.rms == pytest.approx(run.time_domain.rms, rel=1e-9)
    assert td.wz == pytest.approx(run.time_domain.wz, rel=1e-9)


@pytest.mark.parametrize(
    ("changes", "error", "match"),
    [
        ({"track_label": "FRA class 9"}, ValueError, "track_label must be one of"),
        ({"speed_kmh": 0.0}, ValueError, "speed_kmh"),
        ({"speed_kmh": float("nan")}, ValueError, "speed_kmh"),
        ({"seed": -1}, ValueError, "seed"),
        ({"seed": 1.5}, TypeError, "seed"),
        ({"track_label": None}, TypeError, "track_label must be a string"),
        ({"speed_kmh": 1e300}, ValueError, r"speed_kmh must be in \[10.0, 400.0\]"),  # was a speed error
    ],
)
def test_ride_run_refuses_bad_input_naming_the_parameter(changes, error, match):
    args = {"track_label": "FRA class 4", "speed_kmh": 120.0, "seed": 1} | changes
    with pytest.raises(error, match=match):
        chapter06.ride_run(**args)


def test_a_ride_run_result_is_validated():
    run = chapter06.ride_run("FRA class 4", 200.0, 1)
    with pytest.raises(ValueError, match="t must be strictly increasing"):
        dataclasses.replace(run, t=run.t[::-1])
    with pytest.raises(ValueError, match="acceleration must have shape"):
        dataclasses.replace(run, acceleration=run.acceleration[1:])
    with pytest.raises(TypeError, match="spectrum must be a ResponseSpectrum"):
        dataclasses.replace(run, spectrum=None)
