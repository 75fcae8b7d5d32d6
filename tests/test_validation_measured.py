"""The measured Lerelva case (raildyn.validation.measured): the extract's provenance and shape, the identified
speed against two independent estimates, the identified axle pattern against the NSB 92 drawing, and the
chapter-10 prediction's agreement with the measured strain, stated as numbers."""

from __future__ import annotations

import importlib.util
import subprocess
from pathlib import Path

import numpy as np
import pytest

from raildyn.validation.measured import (
    LERELVA_PANEL,
    NSB92_LOADS,
    NSB92_SPACINGS,
    LerelvaCase,
    lerelva_case,
    lerelva_strain,
)

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "raildyn" / "validation" / "data"
MIRROR = Path("/work/.mirror/torholmslettebak+master2016/repo")


@pytest.fixture(scope="module")
def case() -> LerelvaCase:
    return lerelva_case()


def test_the_extract_is_small_and_says_where_it_comes_from():
    # The limit: at most 1 MB stored; the README gives the source, the commit and the terms.
    assert sum(p.stat().st_size for p in DATA.iterdir()) <= 1_000_000
    readme = (DATA / "README.md").read_text()
    for needed in ("https://github.com/torholmslettebak/master2016", "7f6deef", "Slettebak", "no licence"):
        assert needed in readme
    rec = lerelva_strain()
    assert rec.strain.shape == (3, 2560) and rec.time.shape == (2560,)
    assert rec.rate_hz == 256.0
    np.testing.assert_allclose(np.diff(rec.time), 1 / 256, rtol=1e-12)
    assert rec.time[0] == 12.0
    assert rec.channels == ("midspan", "towards Trondheim (1 m)", "towards Heimdal (1 m)")
    assert rec.units == ("strain",) * 3
    # the gauges: midspan of the 25/6 m panel and 1 m either side (Slettebak 2016, §3.3)
    np.testing.assert_allclose(
        rec.positions, [LERELVA_PANEL / 2, LERELVA_PANEL / 2 - 1, LERELVA_PANEL / 2 + 1]
    )
    assert "7f6deef" in rec.provenance and "no licence" in rec.provenance


@pytest.mark.skipif(not MIRROR.exists(), reason="the source repository is not on this machine")
def test_the_extract_is_what_the_script_makes_from_the_source():
    # Re-run the extraction on the raw file: the stored float32 values equal the script's float64 output
    # to float32 rounding (6e-8 relative; the offsets of ~1.5e-3 dominate each value).
    spec = importlib.util.spec_from_file_location("extract_lerelva", ROOT / "scripts" / "extract_lerelva.py")
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    try:
        raw = script.read_raw(MIRROR, script.RUN)
    except subprocess.CalledProcessError:
        pytest.skip("the source record is not in this copy of the repository")
    made = script.extract(raw)
    np.testing.assert_allclose(lerelva_strain().strain, made["strain"].astype(float), rtol=1e-7, atol=0.0)


def test_the_identified_speed_agrees_with_the_bogie_timing(case):
    # Independent estimate: the drawing's 40.65 m from the first to the last bogie centre over the time
    # between the first and last strain maxima at midspan (one per bogie, found on the record low-passed
    # at 8 Hz). Each maximum's time is uncertain by about ±10 ms (the bogie's two axles carry unequal
    # loads and the stringer rings at some 30 Hz), ±1 % of the 1.95 s between them: 3 % allows for both
    # maxima. Measured: 20.97 m/s (weigh-in-motion) against 20.73 m/s, 1.2 % apart.
    assert case.fit.speed == pytest.approx(case.peak_speed, rel=0.03)
    assert 15.0 < case.fit.speed < 30.0  # 54-108 km/h: a suburban unit near Trondheim, not a stray root


def test_the_cross_correlation_lag_reads_fast_for_gauges_on_one_short_panel_and_the_model_says_why(case):
    # The lag of the two gauges 2 m apart gives 36.9 m/s, 1.76 times the speed: on a 4.17 m panel the two
    # gauges' influence lines are not shifted copies of one another (a triangle with its apex at the gauge:
    # its centroid moves by a third of the gauge's move), so the lag is shorter than 2 m / v. The same
    # estimator applied to the fitted model's strains reads 35.2 m/s: the influence line explains the bias.
    # Tolerance 10 %: the model's humps are narrower than the measured ones and lack their negative lobes,
    # which moves the correlation's peak by a fraction of a sample (one sample, 3.9 ms, is 7 % of the lag).
    assert case.lag_speed > 1.3 * case.fit.speed
    assert case.model_lag_speed == pytest.approx(case.lag_speed, rel=0.10)


def test_the_identified_axle_pattern_against_the_nsb92_drawing(case):
    # With the spacings free, the record fixes the times between axles (d/v) but hardly v itself (the span
    # is the model's only length, and the real influence line is wider than the simple span's): the free
    # fit lands at 13.3 m/s with every spacing shrunk alike. At the independent bogie-timing speed the
    # distances between bogie centres (the mean of each bogie's two axles) come back within 2.1 % of the
    # drawing's 16.5, 7.65 and 16.5 m. Tolerance 5 %: ±10 ms on each bogie's time is ±0.2 m, 2.7 % of
    # 7.65 m. The wheelbases themselves (2.5 and 2.55 m) are shorter than the panel and are not resolved:
    # they come out 1.8-2.0 m, reported here and not asserted.
    d = np.concatenate([[0.0], np.cumsum(case.pattern_spacings)])
    centres = 0.5 * (d[0::2] + d[1::2])
    np.testing.assert_allclose(np.diff(centres), [16.5, 3.575 + 0.5 + 3.575, 16.5], rtol=0.05)
    assert case.pattern_spacings.shape == (len(NSB92_SPACINGS),)


def test_the_motor_car_is_the_heavier_by_about_the_nominal_ratio(case):
    # Loads in units of EI/c (the section is unknown), so only their ratios are checked: the motor car's
    # axles against the trailer's, 14 575/9 500 = 1.53 empty (Slettebak 2016, table of axle weights);
    # measured 1.45. Tolerance 20 %: passengers (unknown, up to about a quarter of a car's empty weight)
    # can move the ratio by that much.
    loads = case.fit.loads
    nominal = np.mean(NSB92_LOADS[4:]) / np.mean(NSB92_LOADS[:4])
    assert loads[4:].mean() / loads[:4].mean() == pytest.approx(nominal, rel=0.20)
    assert np.all(loads > 0.0)


def test_the_chapter10_prediction_against_the_measurement(case):
    # The prediction: moving_force_response of the NSB 92's nominal axle loads on the panel as a simple span,
    # at the identified speed and arrival, turned into strain by one fitted factor. Measured agreement
    # (midspan, towards Trondheim, towards Heimdal): correlation 0.97, 0.96, 0.89; NRMSE (range) 7.5 %, 5.7 %,
    # 12.4 %; Sprague-Geers combined 0.16, 0.07, 0.25. The misfit is the model's: the stringer is
    # continuous over the cross-girders (the measurement turns negative, to -30 µε, as axles load the
    # next panels; a simple span cannot) and rails and sleepers spread each axle. What is asserted is what
    # a right speed, pattern and influence line must give, whatever the section: every hump in phase
    # (correlation above 0.8) and within 20 % of the range. The same prediction at a speed 5 % off (its
    # time stretched about the arrival) falls below 0.8 at every gauge (0.51-0.79), so the check has teeth.
    for agreement in case.agreement:
        assert agreement.correlation > 0.8
        assert agreement.nrmse < 0.2
    t, arrival = case.time, case.fit.value("arrival")
    for factor in (0.95, 1.05):
        for predicted, measured in zip(case.predicted, case.measured, strict=True):
            off = np.interp(arrival + (t - arrival) * factor, t, predicted)
            assert np.corrcoef(off, measured)[0, 1] < 0.8
    assert case.scale > 0.0


def test_the_case_plots_measured_and_predicted(case):
    drawn = case.plot()
    assert len(drawn["measured"]) == len(drawn["predicted"]) == 3
    assert len(lerelva_strain().plot()["lines"]) == 3


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="run"):
        lerelva_strain("1603161142")  # the freight train: not in the snapshot, not kept
    with pytest.raises(ValueError, match="flexural_rigidity"):
        lerelva_case(flexural_rigidity=-1.0)
