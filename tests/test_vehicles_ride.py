"""The ride of a vehicle two ways (raildyn.vehicles.ride_run): the spectrum's measures beside a run's."""

import numpy as np
import pytest

from raildyn import ride, track
from raildyn.vehicles import MANCHESTER_VERTICAL, RideRun, periodic_profile, response_spectrum, ride_run

PSD = track.track_psd("fra", "vertical", 4)
F = np.linspace(0.05, 30.0, 1200)
V = 120.0 / 3.6


def _profile(length=1500.0, seed=3):
    z = track.synthesize_irregularity(PSD, length, 0.25, (1.0, 300.0), seed).z.reshape(-1)
    return periodic_profile(z, 0.25)


def test_the_measures_are_those_of_the_spectrum_and_of_the_run():
    run = ride_run(MANCHESTER_VERTICAL, PSD, V, _profile(), F)
    assert isinstance(run, RideRun)
    w = 2 * np.pi * F
    spec = response_spectrum(MANCHESTER_VERTICAL, PSD, V, w, "body z", derivative=2)
    # the same call, the same numbers (1e-12: the same arithmetic)
    np.testing.assert_allclose(run.spectrum.psd, spec.psd, rtol=1e-12)
    fd = ride.ride_quality(spec.psd, w)
    assert run.frequency_domain.wz == pytest.approx(fd.wz, rel=1e-12)
    td = ride.ride_quality_history(run.acceleration, 0.01)
    assert run.time_domain.rms == pytest.approx(td.rms, rel=1e-12)
    # from rest, 10 s dropped, one period of 1.5 km at 33.3 m/s: 45 s in steps of 0.01 s
    assert run.t[0] == pytest.approx(0.0, abs=1e-9)
    assert run.t[-1] == pytest.approx(1500.0 / V, abs=0.011)
    # one 1.5 km sample of the band 1–300 m: its RMS within 5 % of the spectrum's (the band holds all
    # but the longest waves, which the body follows without accelerating)
    assert run.time_domain.rms == pytest.approx(run.frequency_domain.rms, rel=0.05)


def test_the_widget_runs_the_model_function():
    from raildyn.widgets import chapter06

    theirs = chapter06.ride_run("FRA class 4", 120.0, 3)
    ours = ride_run(MANCHESTER_VERTICAL.linear_system(), PSD, V, _profile(), F)
    np.testing.assert_array_equal(theirs.acceleration, ours.acceleration)
    assert theirs.frequency_domain == ours.frequency_domain


@pytest.mark.parametrize(
    ("changes", "error", "match"),
    [
        ({"profile": np.zeros(10)}, TypeError, "profile must be a PeriodicProfile"),
        ({"frequencies_hz": [1.0]}, ValueError, "frequencies_hz must hold two"),
        ({"frequencies_hz": [2.0, 1.0]}, ValueError, "frequencies_hz"),
        ({"dt": 1e-6}, ValueError, "dt and settle must give at most"),
        ({"dt": 50.0}, ValueError, "dt and settle must leave two steps"),
        ({"settle": -1.0}, ValueError, "settle"),
        ({"speed": 0.0}, ValueError, "speed"),
    ],
)
def test_bad_input_is_refused_by_name(changes, error, match):
    args = {
        "vehicle": MANCHESTER_VERTICAL,
        "psd": PSD,
        "speed": V,
        "profile": _profile(300.0),
        "frequencies_hz": F,
    }
    with pytest.raises(error, match=match):
        ride_run(**(args | changes))
