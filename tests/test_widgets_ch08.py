"""Chapter 8 widgets driven without a browser: the numbers shown are the models', moved in place."""

import re

import numpy as np
import pytest
from widget_helpers import redrawn_frames, status_line

from raildyn.curving import climb, curve_entry, quasi_static_curving
from raildyn.track import balance_speed, cant_deficiency
from raildyn.vehicles import Bogie, LateralCar
from raildyn.widgets import chapter08

# ---------------------------------------------------------------------------
# The car in plan


def test_curving_plan_shows_the_cars_quasi_static_equilibrium():
    container, update = chapter08.curving_plan()
    ax = container.live.figure.axes[0]
    axles = [line for line in ax.lines if line.get_marker() == "o"]
    before = [line.get_xydata().copy() for line in axles]
    update(radius=800.0, speed_kmh=90.0, cant_mm=50.0)
    state = quasi_static_curving(LateralCar().nonlinear(), 90.0 / 3.6, 800.0, 0.05)
    status = status_line(container)
    deficiency = 1e3 * cant_deficiency(90.0 / 3.6, 800.0, 0.05)
    assert f"cant deficiency {deficiency:.0f} mm" in status
    assert f"leading outer wheel Y/Q = {state.derailment_quotient[0, 1]:.3f}" in status
    for k, (alpha, y, flange) in enumerate(
        zip(state.angle_of_attack, state.offset, state.flange_contact, strict=True)
    ):
        contact = "flange" if flange else "treads"
        assert f"{k + 1}: α {1e3 * alpha:+.2f} mrad, y {1e3 * y:+.1f} mm, {contact}, creep Tx" in status
        tx, ty = state.longitudinal_creep_force[k], state.lateral_creep_force[k]
        assert f"Tx {1e-3 * tx:+.1f} kN, Ty {1e-3 * ty:+.1f} kN" in status
    # The axles are SteadyCurving.plot's, moved in place: the same artists, at the new state, red on a flange.
    assert [line for line in ax.lines if line.get_marker() == "o"] == axles
    assert all(not np.array_equal(b, line.get_xydata()) for b, line in zip(before, axles, strict=True))
    a, scale = 0.75, 50.0  # the plot's half gauge and the widget's exaggeration
    # The widget solves from its last equilibrium, this test from the linear state: the two meet within
    # the search's tolerance (forces to 1e-9 of the weight, about 1e-9 m), so rel 1e-6 on the drawing.
    for line, x, y, alpha in zip(axles, state.positions, state.offset, state.angle_of_attack, strict=True):
        dx = a * np.sin(scale * alpha)
        np.testing.assert_allclose(line.get_xdata(), [x - dx, x + dx], rtol=1e-6)
        np.testing.assert_allclose(line.get_ydata(), [-scale * y + a, -scale * y - a], rtol=1e-6)
    colours = [line.get_color() for line in axles]
    assert colours == [chapter08._FLANGING if f else chapter08._ROLLING for f in state.flange_contact]
    labels = [t.get_text() for t in ax.texts]
    assert labels == [
        f"{1e3 * al:+.2f} mrad\n{1e3 * y:+.1f} mm"
        for y, al in zip(state.offset, state.angle_of_attack, strict=True)
    ]


def test_curving_plan_gives_the_published_numbers_at_the_balance_speed():
    # quasi_static_curving's example and the closing note of issue 17: 600 m, 100 mm cant, 71.3 km/h: the
    # leading wheelsets flange at 3.8 mrad, Y/Q 0.286. The widget starts at 71 km/h (0.3 km/h below);
    # the angle moves by less than 0.05 mrad and Y/Q by less than 0.005 over that change.
    container, _ = chapter08.curving_plan()
    status = status_line(container)
    assert re.search(r"1: α \+3\.8\d mrad, y \+[\d.]+ mm, flange", status)
    assert re.search(r"3: α \+3\.[5-8]\d mrad, y \+[\d.]+ mm, flange", status)
    quotient = float(re.search(r"Y/Q = ([\d.]+)", status).group(1))
    assert quotient == pytest.approx(0.286, abs=0.005)


def test_curving_plan_says_why_the_car_has_no_equilibrium():
    container, update = chapter08.curving_plan()
    ax = container.live.figure.axes[0]
    update(radius=150.0, speed_kmh=140.0, cant_mm=0.0)
    assert "no equilibrium" in status_line(container) and "overturns" in status_line(container)
    axles = [line for line in ax.lines if line.get_marker() == "o"]
    assert not any(line.get_visible() for line in axles)
    assert ax.texts[0].get_text() == "no equilibrium"
    update(radius=600.0, speed_kmh=71.0, cant_mm=100.0)
    assert all(line.get_visible() for line in axles) and "no equilibrium" not in status_line(container)


# ---------------------------------------------------------------------------
# Nadal's limit


def test_nadal_chart_draws_the_limit_and_the_cars_quotient():
    container, update = chapter08.nadal_chart()
    ax = container.live.figure.axes[0]
    update(flange_angle=65.0, friction=0.2, radius=400.0, speed_kmh=80.0)
    limit, at_angle, level, car = ax.lines[len(chapter08._REFERENCE_FRICTIONS) :][:4]
    angles = limit.get_xdata()
    np.testing.assert_allclose(limit.get_ydata(), climb.nadal_limit(np.radians(angles), 0.2), rtol=1e-12)
    nadal = climb.nadal_limit(np.radians(65.0), 0.2)
    assert at_angle.get_xdata()[0] == 65.0 and at_angle.get_ydata()[0] == pytest.approx(nadal, rel=1e-12)
    state = quasi_static_curving(
        LateralCar().nonlinear(), 80.0 / 3.6, 400.0, 0.1, flange_angle=np.radians(65.0)
    )
    quotient = state.derailment_quotient[0, 1]
    # the widget's equilibrium from its last one, this from the linear state: within the search's tolerance
    assert car.get_xdata()[0] == 65.0 and car.get_ydata()[0] == pytest.approx(quotient, rel=1e-6)
    np.testing.assert_allclose(level.get_ydata(), [quotient, quotient], rtol=1e-6)
    axle = climb.wheel_climb(state.wheel_lateral[0], state.wheel_vertical[0], np.radians(65.0), 0.2)
    status = status_line(container)
    assert f"Y/Q = {quotient:.3f}, Nadal's limit at ϑ_f = 65.0°, μ = 0.20: {nadal:.3f}" in status
    assert "below Nadal's limit: no climb" in status
    assert f"Σ|Y/Q| = {axle.axle_sum:.3f} against Weinstock's {axle.weinstock_limit:.3f}" in status
    assert ax.texts[-1].get_text() == f"R = 400 m, V = 80 km/h: Y/Q {quotient:.2f} < {nadal:.2f}: no climb"


def test_nadal_chart_flags_a_wheel_above_the_limit():
    # A sharp curve at speed, a shallow flange and high friction: Y/Q about 0.70 against a limit of 0.66.
    container, update = chapter08.nadal_chart()
    update(flange_angle=60.0, friction=0.5, radius=200.0, speed_kmh=100.0)
    assert "above Nadal's limit: the flange may climb" in status_line(container)
    assert container.live.figure.axes[0].texts[-1].get_text().endswith("may climb")


# ---------------------------------------------------------------------------
# Curve entry


def test_curve_entry_speed_draws_the_run_and_its_quasi_static_end():
    container, update = chapter08.curve_entry_speed()
    ax = container.live.figure.axes[0]
    lines = list(ax.lines[:2])
    before = [line.get_ydata().copy() for line in lines]
    update(speed_kmh=100.0)
    bogie = Bogie().nonlinear()
    run = curve_entry(bogie, 100.0 / 3.6, chapter08.ENTRY_CURVE)  # made afresh, not the widget's cache
    state = quasi_static_curving(bogie, 100.0 / 3.6, 600.0, 0.1)
    assert list(ax.lines[:2]) == lines
    for line, row in zip(lines, run.flange_force, strict=True):
        np.testing.assert_allclose(line.get_xdata(), run.distance, rtol=1e-12)
        np.testing.assert_allclose(line.get_ydata(), 1e-3 * row, rtol=1e-9, atol=1e-9)
    assert not np.array_equal(before[0], lines[0].get_ydata())
    dashed = [line for line in ax.lines if line.get_linestyle() == "--"]
    np.testing.assert_allclose([d.get_ydata()[0] for d in dashed], 1e-3 * state.flange_force, rtol=1e-12)
    # The run settles on the 30 m arc to the quasi-static flange force: within 0.5 % of it (the solver's
    # relative tolerance is 1e-6; what is left is the motion still dying away).
    assert run.flange_force[0, -1] == pytest.approx(state.flange_force[0], rel=5e-3)
    status = status_line(container)
    assert f"at the end {1e-3 * run.flange_force[0, -1]:.2f} kN" in status
    assert f"quasi-static {1e-3 * state.flange_force[0]:.2f} kN" in status


def test_curve_entry_speed_shows_the_other_quantities_on_their_own_axis():
    container, update = chapter08.curve_entry_speed()
    ax = container.live.figure.axes[0]
    update(quantity="angle_of_attack", speed_kmh=60.0)
    assert ax.get_ylabel() == "angle of attack (mrad)"
    run, state = chapter08._entry_runs()[60.0]
    np.testing.assert_allclose(ax.lines[0].get_ydata(), 1e3 * run.angle_of_attack[0], rtol=1e-12)
    low, high = ax.get_ylim()
    assert low < 1e3 * run.angle_of_attack.min() and high > 1e3 * run.angle_of_attack.max()
    update(quantity="offset")
    assert ax.get_ylabel() == "offset (mm)"
    assert f"quasi-static {1e3 * state.offset[0]:.2f} mm" in status_line(container)


# ---------------------------------------------------------------------------
# Speed


def test_curve_entry_speed_runs_once_and_then_comes_from_the_cache():
    # The time of the first build (the four runs) and of a cached one is benchmarks/bench_ch08_curving.py's.
    chapter08._entry_runs.cache_clear()
    chapter08.curve_entry_speed()
    info = chapter08._entry_runs.cache_info()
    assert (info.hits, info.misses, info.currsize) == (0, 1, 1)
    assert sorted(chapter08._entry_runs()) == sorted(chapter08.ENTRY_SPEEDS)  # a run at every speed
    chapter08._entry_runs.cache_clear()
    chapter08.curve_entry_speed()
    chapter08.curve_entry_speed()
    info = chapter08._entry_runs.cache_info()
    assert (info.hits, info.misses) == (1, 1)  # the second widget reuses the runs of the first


@pytest.mark.parametrize(
    ("label", "recipe", "control", "values"),
    chapter08.BENCH_MOVES,
    ids=[move[0].removeprefix("ch08 ") for move in chapter08.BENCH_MOVES],
)
def test_each_update_redraws(label, recipe, control, values):
    # How fast (the widget goal, median ≤ 30 ms) is for `make bench`: benchmarks/bench_ch08_curving.py
    _, update = recipe.build()
    frames = redrawn_frames(update, control, values)
    assert len(frames) == len(values)


# ---------------------------------------------------------------------------
# The stability–curving trade-off


def test_stiffness_tradeoff_draws_the_models_critical_speeds_and_angles_of_attack():
    from raildyn.curving.stiffness import stability_and_curving

    container, update = chapter08.stiffness_tradeoff()
    update(conicity=0.25, radius=900.0)
    ks = chapter08._TRADEOFF_STIFFNESSES
    speed = balance_speed(900.0, 0.1)  # the widget's curves all have 100 mm of cant
    expected = stability_and_curving(
        LateralCar().replace(conicity=0.25), ks, speed, 900.0, 0.1, speed_range=(1.0, 150.0), tol=0.25, scan=8
    )
    left, right = container.live.figure.axes
    # The same call as the widget's: equal to rounding.
    np.testing.assert_allclose(left.lines[0].get_ydata(), 3.6 * expected.critical_speed, rtol=1e-12)
    np.testing.assert_allclose(right.lines[0].get_ydata(), 1e3 * expected.angle_of_attack, rtol=1e-12)
    np.testing.assert_allclose(left.lines[0].get_xdata(), ks / 1e6)
    # The status line reads both at the grid's point nearest the car's own k_ψ (62.8 MN·m/rad).
    i = int(np.argmin(np.abs(ks - LateralCar().wheelset.yaw_stiffness)))
    status = status_line(container)
    assert f"critical speed {3.6 * expected.critical_speed[i]:.0f} km/h" in status
    assert f"angle of attack {1e3 * expected.angle_of_attack[i]:.2f} mrad" in status
    # The trade-off itself: both rise with k_ψ up to the car's own stiffness.
    below = ks <= LateralCar().wheelset.yaw_stiffness
    assert np.all(np.diff(expected.critical_speed[below]) > 0)
    assert np.all(np.diff(expected.angle_of_attack[below]) > 0)
