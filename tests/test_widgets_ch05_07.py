"""Chapter 5 and 7 widgets driven without a browser: every control changes the picture, in place."""

import re

import numpy as np
import pytest
from widget_helpers import status_line

from raildyn import figures, stability, wheelset
from raildyn.curving import steady_curving
from raildyn.track import speed_for_deficiency
from raildyn.vehicles import (
    EMPTY_FREIGHT_CAR,
    LATERAL_LOCOMOTIVE,
    LOADED_FREIGHT_CAR,
    MANCHESTER_CAR,
    LateralCar,
)
from raildyn.widgets import chapter05, chapter07


def test_klingel_status_gives_the_wavelength():
    container, update = chapter05.klingel()
    update(conicity=0.1, rolling_radius_mm=500.0)
    expected = wheelset.kinematic_wavelength(0.5, 0.75, 0.1)
    assert f"{expected:.2f} m" in status_line(container)


def test_wheelset_roots_status_gives_the_critical_speed():
    container, update = chapter05.wheelset_roots()
    update(conicity=0.2, yaw_stiffness=2.0, lateral_stiffness=1.0)
    ws = wheelset.Wheelset(conicity=0.2, yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)
    cs = stability.critical_speed(ws, (2.0, 120.0))
    # The widget's root is found to 0.05 m/s and printed to 0.1 m/s.
    shown = float(re.search(r"critical speed ([\d.]+) m/s", status_line(container)).group(1))
    assert shown == pytest.approx(cs.speed, abs=0.1)


def test_free_wheelset_is_reported_unstable():
    container, update = chapter05.wheelset_roots()
    update(yaw_stiffness=0.0, lateral_stiffness=0.0)
    assert "unstable at the lowest speed" in status_line(container)


def test_curved_wheelset_shows_the_steady_state_of_the_suspended_wheelset():
    container, update = chapter05.curved_wheelset()
    update(radius=800.0, deficiency_mm=100.0, yaw_stiffness=10.0, lateral_stiffness=5.0)
    ws = wheelset.Wheelset(yaw_stiffness=10.0e6, lateral_stiffness=5.0e6)
    speed = speed_for_deficiency(800.0, 0.1, 0.1)  # the widget's curves all have 100 mm of cant
    state = steady_curving(ws, speed, 800.0, cant=0.1)
    status = status_line(container)
    assert f"{3.6 * state.speed:.0f} km/h" in status
    assert f"offset {1e3 * state.offset[0]:.2f} mm" in status
    assert f"angle of attack {1e3 * state.angle_of_attack[0]:.2f} mrad" in status
    assert f"{-1e-3 * state.longitudinal_creep_force[0]:.1f} kN back on the outer wheel" in status
    assert f"{1e-3 * state.lateral_creep_force[0]:.1f} kN outwards" in status
    # The markers sit at the chosen radius on the same numbers; the curves are steady_curving over
    # the widget's radii (the same calls, so equal to rounding).
    ax_y, ax_a, ax_f = container.live.figure.axes
    offset, attack, longitudinal, lateral = [ax_y.lines[1], ax_a.lines[0], *ax_f.lines[:2]]
    expected = {
        "offset": 1e3 * state.offset[0],
        "attack": 1e3 * state.angle_of_attack[0],
        "longitudinal": -1e-3 * state.longitudinal_creep_force[0],
        "lateral": 1e-3 * state.lateral_creep_force[0],
    }
    markers = [line for ax in (ax_y, ax_a, ax_f) for line in ax.lines if line.get_marker() == "o"]
    for marker, value in zip(markers, expected.values(), strict=True):
        assert marker.get_xdata()[0] == 800.0
        assert marker.get_ydata()[0] == pytest.approx(value, rel=1e-12)
    radii = offset.get_xdata()
    far = steady_curving(ws, speed_for_deficiency(radii[-1], 0.1, 0.1), radii[-1], cant=0.1)
    assert offset.get_ydata()[-1] == pytest.approx(1e3 * far.offset[0], rel=1e-12)
    assert attack.get_ydata()[-1] == pytest.approx(1e3 * far.angle_of_attack[0], rel=1e-12)
    assert longitudinal.get_ydata()[-1] == pytest.approx(-1e-3 * far.longitudinal_creep_force[0], rel=1e-12)
    assert lateral.get_ydata()[-1] == pytest.approx(1e-3 * far.lateral_creep_force[0], rel=1e-12)


def test_curved_wheelset_without_suspension_rolls_at_the_pure_rolling_offset():
    container, update = chapter05.curved_wheelset()
    update(deficiency_mm=0.0, yaw_stiffness=0.0, lateral_stiffness=0.0)
    ax_y = container.live.figure.axes[0]
    free, suspended = ax_y.lines[:2]
    np.testing.assert_array_equal(free.get_xdata(), suspended.get_xdata())
    expected = [1e3 * wheelset.pure_rolling_offset(0.46, 0.75, 0.15, R) for R in free.get_xdata()]
    np.testing.assert_allclose(free.get_ydata(), expected, rtol=1e-12)
    # At the balance speed the free wheelset departs from r0 a/(λR) only through the spin creep and
    # the gravitational stiffness, both small on this cone: 0.01 % here, held to 0.1 %.
    np.testing.assert_allclose(suspended.get_ydata(), expected, rtol=1e-3)
    # A stiff yaw suspension holds the lone wheelset square to the radius: it cannot steer out to its
    # rolling line, and the outer wheel's longitudinal creep grows towards f11 a/R.
    update(yaw_stiffness=80.0, lateral_stiffness=7.8)
    assert ax_y.lines[1].get_ydata()[0] < 0.2 * expected[0]


# ---------------------------------------------------------------------------
# Chapter 7


def test_car_roots_status_and_chart_give_the_critical_speed():
    container, update = chapter07.car_roots()
    update(conicity=0.2, yaw_stiffness=20.0)
    car = LateralCar().replace(conicity=0.2, yaw_stiffness=20.0e6)
    # The widget's root is found to 0.05 m/s over its own speed range; the same call here.
    cs = stability.critical_speed(car, (5.0, 150.0), tol=0.05)
    shown = re.search(
        r"critical speed ([\d.]+) m/s = \d+ km/h, hunting at ([\d.]+) Hz", status_line(container)
    )
    assert float(shown.group(1)) == pytest.approx(cs.speed, abs=0.1)
    assert float(shown.group(2)) == pytest.approx(cs.frequency_hz, abs=0.01)
    # The chart (ModeSweep.plot, moved in place) marks the same speed and names it beside the marker.
    ax_d = container.live.figure.axes[1]
    assert [t.get_text() for t in ax_d.texts] == [f"{3.6 * cs.speed:.0f} km/h, {cs.frequency_hz:.2f} Hz"]


def test_car_roots_draws_the_chart_of_figure_7_1():
    # One method draws both: the same windows, labels and artists in the widget and the figure.
    container, _ = chapter07.car_roots()
    widget = container.live.figure.axes
    figure = figures.make("fig7.root_locus").axes
    for mine, theirs in zip(widget[:2], figure[:2], strict=True):
        assert mine.get_xlabel() == theirs.get_xlabel() and mine.get_ylabel() == theirs.get_ylabel()
        assert mine.get_ylim() == theirs.get_ylim()
        assert len(mine.lines) == len(theirs.lines) and len(mine.texts) == len(theirs.texts)
    assert widget[0].get_xlim() == figure[0].get_xlim()


def test_critical_curve_follows_the_critical_speed_map():
    container, update = chapter07.critical_curve()
    update(yaw_stiffness=20.0, secondary_yaw_stiffness=1.0)
    conicities = chapter07._CONICITIES
    base = LateralCar().replace(secondary_yaw_stiffness=1.0e6)
    expected = stability.critical_speed_map(
        lambda lam, k: base.replace(conicity=lam, yaw_stiffness=k),
        conicities,
        [20.0e6],
        (1.0, 200.0),
        tol=0.1,
        scan=16,
        progress=False,
    )
    car_line = container.live.figure.axes[0].lines[0]
    # The widget's systems are the map's to round-off (1e-12), which can turn a step of the bracketed
    # search the other way: each answer lies within tol = 0.1 m/s of the same zero, so within 2 tol.
    np.testing.assert_allclose(car_line.get_ydata(), 3.6 * expected.speeds[0], rtol=0.0, atol=3.6 * 0.2)
    i = int(np.argmin(np.abs(conicities - 0.15)))
    assert f"car {car_line.get_ydata()[i]:.0f} km/h" in status_line(container)
    assert abs(car_line.get_ydata()[i] - 3.6 * expected.speeds[0, i]) <= 3.6 * 0.2


@pytest.mark.parametrize(
    ("vehicle", "model"),
    [
        ("passenger car", MANCHESTER_CAR),
        ("freight car, empty", EMPTY_FREIGHT_CAR),
        ("freight car, loaded", LOADED_FREIGHT_CAR),
        ("locomotive", LATERAL_LOCOMOTIVE),
    ],
)
def test_vehicle_comparison_marks_each_vehicles_critical_speed(vehicle, model):
    container, update = chapter07.vehicle_comparison()
    update(vehicle=vehicle, conicity=0.2)
    cs = stability.critical_speed(model.replace(conicity=0.2), (1.0, 200.0), tol=0.05)
    shown = re.search(
        r"critical speed ([\d.]+) m/s = \d+ km/h, hunting at ([\d.]+) Hz", status_line(container)
    )
    assert shown and status_line(container).startswith(vehicle)
    assert float(shown.group(1)) == pytest.approx(cs.speed, abs=0.1)
    assert float(shown.group(2)) == pytest.approx(cs.frequency_hz, abs=0.01)
    curves_ax, shape_ax = container.live.figure.axes
    # Four fixed curves (one per vehicle), the chosen one drawn over them, and the marker at (λ, V_c).
    fixed = {line.get_label(): line for line in curves_ax.lines[:4]}
    assert list(fixed) == list(chapter07.VEHICLES)
    highlight, marker = curves_ax.lines[4:6]
    np.testing.assert_array_equal(highlight.get_ydata(), fixed[vehicle].get_ydata())
    assert marker.get_xdata()[0] == 0.2 and marker.get_ydata()[0] == pytest.approx(3.6 * cs.speed, abs=0.4)
    # The bars are the mode shape of that critical speed, grouped; the largest is 1.
    heights = [bar.get_height() for bar in shape_ax.patches]
    assert max(heights) == pytest.approx(1.0)
    body_y = heights[[g for g, _, _ in chapter07._GROUPS].index("body y")]
    assert body_y == pytest.approx(cs.amplitude("body y"), abs=1e-6)


def test_vehicle_comparison_curves_are_the_critical_speeds_against_conicity():
    container, _ = chapter07.vehicle_comparison()
    curves = container.live.figure.axes[0].lines[:4]
    for line, model in zip(curves, chapter07.VEHICLES.values(), strict=True):
        lam = chapter07._COMPARE_CONICITIES[[0, 5, -1]]
        expected = [
            stability.critical_speed(model.replace(conicity=x), (1.0, 200.0), tol=0.05).speed for x in lam
        ]
        np.testing.assert_allclose(line.get_ydata()[[0, 5, -1]], 3.6 * np.array(expected), rtol=1e-12)
    # Empty freight car lowest, at every conicity on the curve.
    speeds = np.array([line.get_ydata() for line in curves])
    assert np.all(speeds[1] == speeds.min(axis=0))


def test_klingel_widget_and_figure_draw_the_same_kinematic_oscillation():
    # One chart, KinematicOscillation.plot: the widget moves the figure's lines to its wavelengths.
    container, update = chapter05.klingel()
    update(conicity=0.15, rolling_radius_mm=460.0, semi_wheelbase=1.28)
    k = wheelset.kinematic_oscillation(0.46, 0.75, 0.15, 1.28)
    fig = figures.make("fig5.kinematic_oscillation")
    figure_free = fig.axes[0].get_lines()[0]
    x = figure_free.get_xdata()
    np.testing.assert_allclose(
        figure_free.get_ydata(), 5.0 * np.sin(2 * np.pi * x / k.wavelength), atol=1e-12
    )
    assert f"{k.wavelength:.2f} m" in status_line(container)


# ---------------------------------------------------------------------------
# Chapter 5: the hunting wheelset in plan


def _least_damped(ws, speed):
    """The least-damped oscillatory root (Im λ > 0) and its eigenvector, from the state matrix itself."""
    lam, vec = np.linalg.eig(ws.linear_system().state_matrices([speed])[0])
    oscillatory = np.flatnonzero(lam.imag > 0)
    j = oscillatory[np.argmin(-lam.real[oscillatory] / np.abs(lam[oscillatory]))]
    return lam[j], vec[:2, j]


def test_hunting_wheelset_status_gives_the_least_damped_mode():
    container, update = chapter05.hunting_wheelset()
    ws = chapter05._HUNTING_WHEELSET
    cs = stability.critical_speed(ws, (2.0, 120.0))
    for kmh in (120.0, 250.0):
        update(speed_kmh=kmh)
        lam, _ = _least_damped(ws, kmh / 3.6)
        status = status_line(container)
        assert f"f = {lam.imag / (2 * np.pi):.2f} Hz" in status
        assert f"ξ = {-lam.real / abs(lam):.3f}" in status
        assert f"× {np.exp(2 * np.pi * lam.real / lam.imag):.2f} per cycle" in status
        # Below the critical speed the mode decays, above it grows.
        assert ("decays" in status) == (kmh / 3.6 < cs.speed)


@pytest.mark.parametrize("phase", [0.0, 90.0, 225.0])
def test_hunting_wheelset_draws_the_mode_in_plan(phase):
    container, update = chapter05.hunting_wheelset()
    ws, speed = chapter05._HUNTING_WHEELSET, 250 / 3.6
    update(speed_kmh=250.0, phase_deg=phase)
    lam, v = _least_damped(ws, speed)
    # Re(v e^{λt}) at ωt = phase, with t = 0 where y is real (the eigenvector scaled by its y), up to
    # one real scale (the widget draws the largest |y| of the cycle as 4 mm): the drawn ψ/y is the
    # eigenvector's, to round-off.
    t = np.radians(phase) / lam.imag
    y, psi = np.real(v / v[0] * np.exp(lam * t))
    plan_ax, time_ax = container.live.figure.axes
    y_line, psi_line = time_ax.lines[:2]
    k = int(np.argmin(np.abs(y_line.get_xdata() - phase)))
    drawn_y, drawn_psi = 1e-3 * y_line.get_ydata()[k], 1e-3 * psi_line.get_ydata()[k]
    assert drawn_psi * y == pytest.approx(psi * drawn_y, rel=1e-9, abs=1e-12)
    assert max(np.abs(y_line.get_ydata())) == pytest.approx(4.0, rel=1e-12)
    # The axle in plan stands at 20 y and is turned by 20 ψ (the widget's exaggeration).
    axle = next(
        p.get_xy()[:4]
        for p in plan_ax.patches
        if np.isclose(np.linalg.norm(p.get_xy()[3] - p.get_xy()[0]), 2 * ws.half_gauge + 0.3)
    )
    centre = axle.mean(axis=0)
    side = axle[3] - axle[0]
    assert centre[1] == pytest.approx(20.0 * drawn_y, abs=1e-12)
    assert np.arctan2(-side[0], side[1]) == pytest.approx(20.0 * drawn_psi, abs=1e-12)


def test_hunting_wheelset_sways_like_klingels_wheelset():
    # At a moderate speed the hunting mode is the kinematic oscillation, ψ a quarter period out of
    # phase with y and |ψ|/|y| = 2π/L. Finite creep and the springs make it only nearly so: within
    # 10 % and 10° here (the mode of this wheelset at 150 km/h is 4 % and 5° away).
    ws = chapter05._HUNTING_WHEELSET
    _, v = _least_damped(ws, 150 / 3.6)
    L = wheelset.kinematic_wavelength(ws.rolling_radius, ws.half_gauge, ws.conicity)
    ratio = v[1] / v[0]
    assert abs(ratio) == pytest.approx(2 * np.pi / L, rel=0.1)
    assert abs(abs(np.degrees(np.angle(ratio))) - 90.0) < 10.0
