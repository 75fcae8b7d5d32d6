"""Chapter 10 widgets driven without a browser: what they draw is the models' answer, checked against
an independent path where there is one (Frýba's series, the closed form against the march)."""

import numpy as np
import pytest
from widget_helpers import redrawn_frames, status_line

from raildyn.bridge import SimplySupportedBeam, codes, fryba_deflection, moving_force_response
from raildyn.bridge.trains import regular_train
from raildyn.constants import MAXIMUM_SPEED
from raildyn.widgets import chapter10

# ---------------------------------------------------------------------------
# One force crossing the beam


def test_explorer_draws_the_beam_as_frybas_series():
    # The drawn line comes from the modal march (Newmark, 20 steps a period of the third mode); Frýba's
    # undamped series (eq. 1.30 of Frýba 1972) over the same three modes is an independent path. The
    # scheme's period error at 20 steps a period is below 1 %, and the force's own term is slow: 2 % of
    # the static midspan deflection holds with room.
    container, update = chapter10.moving_load_explorer()
    update(speed_kmh=180.0, position=0.6, damping=0.0)
    left = container.live.figure.axes[0]
    shape, force = left.lines[3], left.lines[4]
    speed = 180.0 / 3.6
    run = chapter10._one_crossing(speed, 0.0)
    t = run.time[int(np.argmin(np.abs(run.time - 0.6 * 20.0 / speed)))]
    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=3)
    x = shape.get_xdata()
    series = np.array([fryba_deflection(beam, speed, 1.0e5, [t], position=xi)[0] for xi in x])
    static = 1e3 * beam.static_midspan_deflection(1.0e5)
    np.testing.assert_allclose(-shape.get_ydata(), 1e3 * series, rtol=0, atol=0.02 * static)
    # the force stands on the line, at v t
    assert force.get_xdata()[0] == pytest.approx(speed * t, rel=1e-12)
    assert -force.get_ydata()[0] == pytest.approx(1e3 * np.interp(speed * t, x, series), abs=0.02 * static)


def test_explorer_marks_the_closed_form_amplification_near_frybas_peak():
    container, update = chapter10.moving_load_explorer()
    # α = 0.619 at 350 km/h on the 3.93 Hz, 20 m beam: near the undamped peak (1.73 at α ≈ 0.62; the
    # beam tests hold moving_force_response to Frýba's series there)
    update(speed_kmh=350.0, damping=0.0)
    right = container.live.figure.axes[1]
    curve, mark = right.lines[4], right.lines[5]
    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=10)
    speed = 350.0 / 3.6
    alpha = speed / (2 * beam.frequencies_hz[0] * 20.0)
    assert mark.get_xdata()[0] == pytest.approx(alpha, rel=1e-12)
    # Frýba's series while the force is on (the peak comes before it leaves at α < 1), on a fine grid:
    # 4001 instants put the sampled peak within (π/4000)² / 2 ≈ 3e-7 of the true one of the slow term.
    t = np.linspace(0.0, 20.0 / speed, 4001)
    peak = np.abs(fryba_deflection(beam, speed, 1.0e5, t)).max() / beam.static_midspan_deflection(1.0e5)
    # moving_force_response samples 400 instants over twice the crossing: its sampled peak is within 0.1 %
    # here
    assert mark.get_ydata()[0] == pytest.approx(peak, rel=1e-3)
    assert peak == pytest.approx(1.73, abs=0.01)
    assert f"amplification {mark.get_ydata()[0]:.3f}" in status_line(container)
    # the bold curve is the closed form for the chosen damping, and the curve's peak is Frýba's
    update(damping=0.05)
    # the curve is computed on a 40 m span of the same section (α = 1.5 at 118 m/s, within
    # raildyn.constants.MAXIMUM_SPEED; the 20 m beam would need 236 m/s)
    long = SimplySupportedBeam(40.0, 1.0e10, 1.0e4, damping_ratio=0.05, modes=10)
    speeds = chapter10._ALPHAS * 2 * long.frequencies_hz[0] * 40.0
    np.testing.assert_allclose(
        curve.get_ydata(), moving_force_response(long, speeds, 1.0e5).amplification, rtol=1e-12
    )
    # ... which is the 20 m beam's curve, as the amplification depends on α alone: the same to rounding
    # (1e-9; measured below 1e-13) wherever the 20 m beam's speed is one raildyn accepts
    damped = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, damping_ratio=0.05, modes=10)
    short = chapter10._ALPHAS * 2 * damped.frequencies_hz[0] * 20.0
    within = short <= MAXIMUM_SPEED
    assert within.sum() > 200
    np.testing.assert_allclose(
        curve.get_ydata()[within],
        moving_force_response(damped, short[within], 1.0e5).amplification,
        rtol=1e-9,
    )
    undamped = chapter10._daf_curve(0.0)
    assert undamped.max() == pytest.approx(peak, rel=2e-3)  # the grid is 0.006 apart in α: flat at the top
    assert chapter10._ALPHAS[np.argmax(undamped)] == pytest.approx(0.62, abs=0.02)


def test_explorer_says_when_the_force_has_left():
    container, update = chapter10.moving_load_explorer()
    update(speed_kmh=600.0, position=1.3)
    status = status_line(container)
    assert "(off the span)" in status
    force = container.live.figure.axes[0].lines[4]
    assert force.get_xdata()[0] == pytest.approx(26.0, abs=0.2)  # 1.3 L, to the march's step
    assert force.get_ydata()[0] == 0.0
    # At α = 1.06 the crossing lasts L/v = 1/(2f₁α), less than half the first mode's period: the
    # beam has not reached its peak when the force leaves, and the largest deflection comes after.
    assert "after it left" in status


# ---------------------------------------------------------------------------
# A regular train's resonances


def test_train_resonance_marks_n0_d_over_i_and_peaks_there():
    container, update = chapter10.train_resonance()
    update(coach_length=20.0, span=20.0, frequency_hz=4.0)
    ax = container.live.figure.axes[0]
    marks, line = ax.lines[:4], ax.lines[4]
    expected = 3.6 * codes.resonance_speeds(4.0, 20.0, 4)  # 288, 144, 96, 72 km/h
    np.testing.assert_allclose([m.get_xdata()[0] for m in marks], expected, rtol=1e-12)
    assert all(m.get_visible() for m in marks)
    # The largest amplification is at the first resonance, to the grid's 2.8 % spacing in speed.
    kmh = line.get_xdata()
    assert kmh[np.argmax(line.get_ydata())] == pytest.approx(expected[0], rel=0.03)
    # Independent of the widget's bands: the same train by the closed form with 10 000 samples at three
    # of the grid's speeds; the widget's sampling keeps its peaks within 1 % (its comment), so 1.5 %.
    EI = 1.0e4 * (2 * 4.0 * 20.0**2 / np.pi) ** 2  # f₁ = (π/(2L²))√(EI/m) = 4 Hz
    beam = SimplySupportedBeam(20.0, EI, 1.0e4, damping_ratio=0.01, modes=3)
    assert beam.frequencies_hz[0] == pytest.approx(4.0, rel=1e-12)
    axles = regular_train(10, 20.0, 2.5, 170e3)
    pick = [5, 40, int(np.argmax(line.get_ydata()))]
    reference = moving_force_response(beam, kmh[pick] / 3.6, axles, samples=10_000).amplification
    np.testing.assert_allclose(line.get_ydata()[pick], reference, rtol=0.015)


def test_train_resonance_cancels_at_one_and_a_half_coach_lengths():
    # cancellation_spans: the first resonance leaves nothing behind each axle when L/d = 1.5 (derived
    # in raildyn.bridge.codes from Frýba's single-force residual). At d = 18 m, L = 27 m and f₁ = 4 Hz
    # the build-up at f₁d = 259 km/h disappears; on 20 m it reaches about 8 (the figure's caption).
    container, update = chapter10.train_resonance()
    ax = container.live.figure.axes[0]
    v1 = 3.6 * 4.0 * 18.0  # km/h

    def at(kmh):
        line = ax.lines[4]
        return float(np.interp(kmh, line.get_xdata(), line.get_ydata()))

    update(coach_length=18.0, span=20.0, frequency_hz=4.0)
    resonant = (at(v1), at(1.15 * v1))
    update(span=27.0)
    cancelled = (at(v1), at(1.15 * v1))
    assert resonant[0] > 5.0 and resonant[0] > 2 * resonant[1]  # a peak at f₁d on 20 m
    # on 27 m no peak at all: the response still rises with speed past f₁d (towards the single
    # bogie's own α-peak), and stays below a fifth of the 20 m span's build-up
    assert cancelled[0] < cancelled[1]
    assert cancelled[0] < resonant[0] / 5
    assert "L = 27, 45, 63 m" in status_line(container)


def test_train_resonance_hides_resonances_off_the_axis():
    container, update = chapter10.train_resonance()
    update(coach_length=30.0, frequency_hz=8.0)  # f₁d = 864 km/h, f₁d/2 = 432: both beyond 420
    marks = container.live.figure.axes[0].lines[:4]
    assert [m.get_visible() for m in marks] == [False, False, True, True]


# ---------------------------------------------------------------------------
# Four models of one car


def test_load_models_bars_are_the_crossings_and_forces_match_the_closed_form():
    container, update = chapter10.load_models()
    update(speed_kmh=150.0)
    histories, bars, comfort = container.live.figure.axes
    runs = chapter10._model_runs(150.0 / 3.6)
    heights = [rect.get_height() for rect in bars.patches]
    np.testing.assert_allclose(heights, [runs[n].amplification for n in chapter10._MODEL_NAMES], rtol=1e-12)
    # The moving forces by the march against the closed form of moving_force_response over the same three
    # modes: two independent paths. The march keeps 20 steps a period of the third mode (period error < 1 %)
    # and the closed form samples 4000 instants; their peaks agree within 1.5 %.
    car = chapter10._car_models()["moving forces"]
    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, damping_ratio=0.01, modes=3)
    closed = moving_force_response(beam, 150.0 / 3.6, car, samples=4000)
    peak = np.abs(closed.deflection).max()
    assert np.abs(runs["moving forces"].deflection).max() == pytest.approx(peak, rel=0.015)
    # The slow crossing is drawn by the three modes' flexibility; the beam formula's static peak
    # (moving_force_response's .static) differs from it by the modes left out: 1/5⁴ + 1/7⁴ … ≈ 0.2 %.
    dashed = histories.lines[0]
    assert 1e-3 * np.max(dashed.get_ydata()) == pytest.approx(closed.static, rel=5e-3)
    # Annex C's line moves with the speed; AREMA's and Φ₂ stay
    annex = bars.lines[2]
    factor = codes.en1991_real_train_factor(150.0 / 3.6, 20.0, beam.frequencies_hz[0])
    np.testing.assert_allclose(annex.get_ydata(), [factor, factor], rtol=1e-12)
    status = status_line(container)
    assert f"Φ₂ {codes.en1991_dynamic_factor(20.0):.3f}" in status
    assert f"AREMA {1 + codes.arema_impact_factor(20.0):.3f}" in status


def test_load_models_body_acceleration_and_comfort_levels():
    container, update = chapter10.load_models()
    update(speed_kmh=270.0)
    comfort = container.live.figure.axes[2]
    levels = sorted(line.get_ydata()[0] for line in comfort.lines[:3])
    assert levels == sorted(codes.COMFORT_ACCELERATION_LIMITS.values())
    runs = chapter10._model_runs(270.0 / 3.6)
    car_line = comfort.lines[4]
    np.testing.assert_allclose(car_line.get_ydata(), runs["vertical car"].vehicle_acceleration("body z"))
    # the four sprung masses' mean: each is one quarter of the body
    sprung = runs["sprung masses"]
    mean = np.mean([sprung.vehicle_acceleration(f"{k}: body z") for k in range(1, 5)], axis=0)
    np.testing.assert_allclose(comfort.lines[3].get_ydata(), mean, rtol=1e-12)
    # A level track and a 20 m bridge: the body stays well inside very good comfort (EN 1990 A2.9)
    assert np.abs(car_line.get_ydata()).max() < codes.comfort_acceleration_limit("very good")


def test_sprung_masses_approach_the_forces_and_the_car_at_low_speed():
    # At 40 km/h (α = 0.07) every model is nearly quasi-static: each amplification within 3 % of 1 plus
    # the same small ripple; the moving masses, heavier on the beam, still within 3 % of the forces.
    runs = chapter10._model_runs(40.0 / 3.6)
    dafs = np.array([runs[n].amplification for n in chapter10._MODEL_NAMES])
    assert np.all(np.abs(dafs / dafs[0] - 1.0) < 0.03)


# ---------------------------------------------------------------------------
# Speed


@pytest.mark.parametrize(
    ("label", "recipe", "control", "values"),
    chapter10.BENCH_MOVES,
    ids=[move[0].removeprefix("ch10 ") for move in chapter10.BENCH_MOVES],
)
def test_each_update_redraws(label, recipe, control, values):
    # How fast (the widget goal, median ≤ 30 ms) is for `make bench`: benchmarks/bench_ch10_bridge.py
    _, update = recipe.build()
    frames = redrawn_frames(update, control, values)
    assert len(frames) == len(values)


# ---------------------------------------------------------------------------
# The figures draw the same models


def test_daf_figure_shows_frybas_peak():
    from raildyn import figures

    ax = figures.make("fig10.daf_single_force").axes[0]
    undamped = ax.lines[0]
    i = int(np.argmax(undamped.get_ydata()))
    # the undamped peak of one moving force: 1.73 near α = 0.62 (Frýba 1972, ch. 1; held to his series
    # in the beam's tests); the figure's grid is 0.005 apart in α, flat at the top to 1e-4
    assert undamped.get_ydata()[i] == pytest.approx(1.73, abs=0.005)
    assert undamped.get_xdata()[i] == pytest.approx(0.62, abs=0.02)
    # damping lowers the peak: 2 % below the undamped, 5 % below 2 %
    peaks = [line.get_ydata().max() for line in (undamped, ax.lines[2], ax.lines[3])]
    assert peaks[0] > peaks[1] > peaks[2]
