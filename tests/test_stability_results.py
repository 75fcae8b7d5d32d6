"""The results of raildyn.stability: field names that carry their units, and the charts they draw.

A chart drawn by both a figure and a widget is drawn by one method of its result
(``ModeSweep.plot``, ``CriticalSpeedMap.plot`` / ``plot_curves``, ``BifurcationDiagram.plot``);
given the artists of an earlier call it moves them in place and draws nothing new.
"""

import numpy as np
import pytest
from matplotlib.figure import Figure

from raildyn import stability
from raildyn.linear_model import LinearSystem
from raildyn.wheelset import NonlinearWheelset, Wheelset

SOFT = Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)  # hunts above about 55 m/s
STIFF = SOFT.replace(yaw_stiffness=4.0e6)
SPEEDS = np.linspace(2.0, 100.0, 40)


def _artist_count(fig: Figure) -> int:
    return sum(len(ax.lines) + len(ax.collections) + len(ax.texts) for ax in fig.axes)


# ---------------------------------------------------------------------------
# Units in the field names


def test_frequency_fields_say_hertz():
    # m q̈ + (c₁/V − c₀) q̇ + 4 q = 0 crosses at V = c₁/c₀ = 50 m/s with λ = ±2j: 2/2π Hz, not 2 rad/s.
    one = np.array([[1.0]])
    system = LinearSystem(one, -0.2 * one, 10.0 * one, 4.0 * one, labels=("q",))
    cs = stability.critical_speed(system, (1.0, 100.0))
    assert cs.frequency_hz == pytest.approx(2.0 / (2 * np.pi), rel=1e-3)
    assert not hasattr(cs, "frequency")  # one name, the one that says its unit
    sweep = stability.mode_sweep(system, [10.0, 50.0])
    # At 50 m/s the damping vanishes: |Im λ| = 2 rad/s exactly (to round-off).
    assert sweep.frequencies_hz[-1, 0] == pytest.approx(2.0 / (2 * np.pi), rel=1e-12)
    assert not hasattr(sweep, "frequencies")


def test_limit_cycle_and_diagram_frequencies_are_in_hertz():
    cycle = stability.limit_cycle_amplitude(NonlinearWheelset(SOFT), 60.0, duration=2.0)
    # The hunting of this wheelset (≈ 33 rad/s at its critical speed) is near 5.5 Hz.
    assert 4.0 < cycle.frequency_hz < 7.0
    fields = stability.BifurcationDiagram.__dataclass_fields__
    assert "frequencies_hz" in fields and "frequencies" not in fields


# ---------------------------------------------------------------------------
# ModeSweep.plot


def test_mode_sweep_plot_draws_roots_modes_and_the_critical_speed():
    sweep = stability.mode_sweep(SOFT, SPEEDS)
    cs = stability.critical_speed(SOFT, (SPEEDS[0], SPEEDS[-1]))
    fig = Figure()
    ax_s, ax_d = fig.subplots(1, 2)
    drawn = sweep.plot((ax_s, ax_d), critical=cs)
    lam = sweep.eigenvalues
    np.testing.assert_array_equal(
        drawn["roots"].get_offsets(), np.column_stack([lam.real.ravel(), lam.imag.ravel()])
    )
    np.testing.assert_array_equal(drawn["roots"].get_array(), np.repeat(3.6 * SPEEDS, lam.shape[1]))
    assert len(drawn["modes"]) == lam.shape[1]
    for line, xi in zip(drawn["modes"], sweep.damping_ratios.T, strict=True):
        np.testing.assert_array_equal(line.get_xydata(), np.column_stack([3.6 * SPEEDS, xi]))
    np.testing.assert_array_equal(drawn["hunting"].get_ydata(), sweep.damping_ratios[:, sweep.hunting_mode])
    assert sweep.damping_ratios[-1, sweep.hunting_mode] < 0, "the hunting mode is unstable at the top speed"
    assert drawn["critical"].get_xydata().tolist() == [[3.6 * cs.speed, 0.0]]
    assert drawn["critical_text"].get_text() == f"{3.6 * cs.speed:.0f} km/h, {cs.frequency_hz:.2f} Hz"
    # The default windows: near the imaginary axis, below 70 rad/s; ξ from −0.15 to 0.5.
    assert ax_s.get_xlim() == (-25.0, 5.0) and ax_s.get_ylim() == (0.0, 70.0)
    assert ax_d.get_ylim() == (-0.15, 0.5)
    assert ax_d.get_xlabel() == "speed (km/h)" and ax_s.get_ylabel() == "Im $s_r$ (rad/s)"


def test_mode_sweep_plot_moves_its_artists_in_place():
    first = stability.mode_sweep(SOFT, SPEEDS)
    second = stability.mode_sweep(STIFF, SPEEDS)
    fig = Figure()
    axes = fig.subplots(1, 2)
    drawn = first.plot(axes, critical=stability.critical_speed(SOFT, (2.0, 100.0)))
    count, limits = _artist_count(fig), [ax.axis() for ax in axes]
    cs = stability.critical_speed(STIFF, (2.0, 100.0))
    again = second.plot(critical=cs, artists=drawn)
    assert again is drawn
    assert _artist_count(fig) == count, "nothing new is drawn"
    assert [ax.axis() for ax in axes] == limits, "the view stays put"
    lam = second.eigenvalues
    np.testing.assert_array_equal(
        drawn["roots"].get_offsets(), np.column_stack([lam.real.ravel(), lam.imag.ravel()])
    )
    for line, xi in zip(drawn["modes"], second.damping_ratios.T, strict=True):
        np.testing.assert_array_equal(line.get_ydata(), xi)
    np.testing.assert_array_equal(drawn["hunting"].get_ydata(), second.damping_ratios[:, second.hunting_mode])
    assert drawn["critical"].get_xydata().tolist() == [[3.6 * cs.speed, 0.0]]
    assert drawn["critical_text"].xy == (3.6 * cs.speed, 0.0)
    assert drawn["critical_text"].get_text() == f"{3.6 * cs.speed:.0f} km/h, {cs.frequency_hz:.2f} Hz"
    # No crossing in the range: the marker and its text are emptied, not left at the old speed.
    stable = stability.critical_speed(STIFF, (2.0, 20.0))
    second.plot(critical=stable, artists=drawn)
    assert drawn["critical"].get_xydata().size == 0 and drawn["critical_text"].get_text() == ""


def test_mode_sweep_plot_refuses_artists_of_another_model():
    fig = Figure()
    drawn = stability.mode_sweep(SOFT, SPEEDS).plot(fig.subplots(1, 2))
    one = np.array([[1.0]])
    single = stability.mode_sweep(LinearSystem(one, 0 * one, one, one), SPEEDS)
    with pytest.raises(ValueError, match="artists were drawn for 2 modes"):
        single.plot(artists=drawn)


def test_mode_sweep_plot_on_new_axes_and_fitted_windows():
    drawn = stability.mode_sweep(SOFT, SPEEDS).plot(real_limits=None, imag_limits=None, damping_limits=None)
    ax_s = drawn["roots"].axes
    assert ax_s.get_xlim() != (-25.0, 5.0)  # fitted to the data, not the vehicle window
    assert len(ax_s.figure.axes) == 3  # roots, damping factors and the colour bar


# ---------------------------------------------------------------------------
# CriticalSpeedMap


def _map(yaw_stiffnesses, scan=16):
    return stability.critical_speed_map(
        lambda lam, k: SOFT.replace(conicity=lam, yaw_stiffness=k),
        [0.1, 0.2, 0.4],
        yaw_stiffnesses,
        (1.0, 150.0),
        x_name="conicity λ",
        y_name="k_ψ (N·m/rad)",
        scan=scan,
        progress=False,
    )


def test_critical_speed_map_passes_scan_to_each_search():
    # The coarse scan only brackets the root; Brent's method then meets the same tolerance (0.05 m/s).
    coarse, fine = _map([2e6], scan=8), _map([2e6], scan=64)
    np.testing.assert_allclose(coarse.speeds, fine.speeds, atol=0.1)
    single = stability.critical_speed(SOFT.replace(conicity=0.2), (1.0, 150.0), tol=0.05, scan=8).speed
    assert coarse.speeds[0, 1] == single
    with pytest.raises(ValueError, match="scan"):
        _map([2e6], scan=2)


def test_plot_curves_draws_one_blank_free_line_per_row_and_moves_it():
    grid = stability.CriticalSpeedMap(
        np.array([0.1, 0.2, 0.4]),
        np.array([1.0, 2.0]),
        np.array([[80.0, 60.0, np.inf], [90.0, 70.0, 50.0]]),
        "λ",
        "k",
    )
    fig = Figure()
    ax = fig.subplots()
    drawn = grid.plot_curves(ax, color="k")
    assert [line.get_label() for line in drawn["lines"]] == ["k = 1", "k = 2"]
    np.testing.assert_array_equal(drawn["lines"][0].get_ydata(), [288.0, 216.0, np.nan])  # km/h, inf blank
    assert ax.get_ylabel() == "critical speed (km/h)" and ax.get_xlabel() == "λ"
    count = _artist_count(fig)
    moved = stability.CriticalSpeedMap(grid.x, grid.y, grid.speeds / 2, "λ", "k")
    moved.plot_curves(artists=drawn)
    assert _artist_count(fig) == count
    np.testing.assert_array_equal(drawn["lines"][1].get_ydata(), [162.0, 126.0, 90.0])
    with pytest.raises(ValueError, match="artists were drawn for 2 lines"):
        stability.CriticalSpeedMap(grid.x, grid.y[:1], grid.speeds[:1], "λ", "k").plot_curves(artists=drawn)


def test_critical_speed_map_plot_draws_contours_in_kmh():
    grid = stability.CriticalSpeedMap(
        np.array([0.1, 0.2, 0.4]),
        np.array([1.0, 2.0]),
        np.array([[80.0, 60.0, np.inf], [90.0, 70.0, 50.0]]),
        "λ",
        "k",
    )
    drawn = grid.plot(Figure().subplots())
    # Default levels: every 50 km/h up to the largest finite speed (90 m/s = 324 km/h), rounded up.
    np.testing.assert_array_equal(drawn["contours"].levels, np.arange(0.0, 351.0, 50.0))
    assert drawn["colorbar"].ax.get_ylabel() == "critical speed (km/h)"
    assert drawn["contours"].axes.get_xlabel() == "λ" and drawn["contours"].axes.get_ylabel() == "k"


# ---------------------------------------------------------------------------
# BifurcationDiagram.plot


def test_bifurcation_diagram_plot_splits_hunting_from_decaying_runs():
    diagram = stability.BifurcationDiagram(
        speeds=np.array([80.0, 70.0, 60.0]),
        amplitudes=np.array([8e-3, 6e-3, 1e-5]),
        frequencies_hz=np.array([2.0, 1.9, 0.0]),
        hunting=np.array([True, True, False]),
        nonlinear_critical_speed=65.0,
        threshold=2e-4,
    )
    drawn = diagram.plot(Figure().subplots(), linear_critical_speed=75.0)
    np.testing.assert_allclose(drawn["cycles"].get_xydata(), [[288.0, 8.0], [252.0, 6.0]])
    np.testing.assert_allclose(drawn["decaying"].get_xydata(), [[216.0, 0.01]])
    assert drawn["linear"].get_xdata()[0] == pytest.approx(270.0)
    assert drawn["nonlinear"].get_xdata()[0] == pytest.approx(234.0)
    never = stability.BifurcationDiagram(
        diagram.speeds, diagram.amplitudes, diagram.frequencies_hz, np.zeros(3, bool), np.inf, 2e-4
    )
    assert drawn["linear_text"].get_text() == "270 km/h" and drawn["nonlinear_text"].get_text() == "234 km/h"
    # No cycle, no linear speed given: both critical-speed marks are hidden, here and in place.
    hidden = never.plot(Figure().subplots())
    assert not hidden["nonlinear"].get_visible() and not hidden["linear_text"].get_visible()
    moved = never.plot(artists=drawn)
    assert moved is drawn and not drawn["nonlinear"].get_visible() and not drawn["linear"].get_visible()
    assert drawn["cycles"].get_xydata().size == 0 and drawn["decaying"].get_xydata().shape == (3, 2)
    diagram.plot(artists=drawn, linear_critical_speed=75.0)
    assert drawn["nonlinear"].get_visible() and drawn["nonlinear"].get_xdata()[0] == pytest.approx(234.0)
    with pytest.raises(ValueError, match="linear_critical_speed"):
        diagram.plot(Figure().subplots(), linear_critical_speed=np.inf)
    with pytest.raises(TypeError, match="artists"):
        diagram.plot(artists=[1])


def test_simulate_is_the_run_limit_cycle_amplitude_measures():
    # One integration for the figures and the limit-cycle measure: the run's last quarter gives the
    # amplitude that limit_cycle_amplitude reports (the same numbers, so 1e-12).
    model = NonlinearWheelset(Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6))
    start = np.array([12e-3, 0.0, 0.0, 0.0])
    run = stability.simulate(model, 60.0, start, 2.0)
    cycle = stability.limit_cycle_amplitude(model, 60.0, duration=2.0, initial_state=start)
    tail = run.t >= 1.5
    assert 0.5 * np.ptp(run.lateral[tail]) == pytest.approx(cycle.amplitude, rel=1e-12)
    drawn = run.plot(flange_clearance=9.1e-3)
    np.testing.assert_allclose(drawn["line"].get_ydata(), 1e3 * run.lateral)
    with pytest.raises(ValueError, match="duration"):
        stability.simulate(model, 60.0, start, 0.0)
    with pytest.raises(ValueError, match="initial_state"):
        stability.simulate(model, 60.0, start[:3], 1.0)


def test_critical_speed_carries_the_shape_of_the_mode_that_loses_stability():
    # The shape at V_c against the eigenvector found independently by scipy.linalg.eig of the
    # state matrix at that speed (same normalisation: largest displacement entry 1): 1e-8.
    import scipy.linalg

    from raildyn.vehicles import LateralCar

    car = LateralCar()
    crit = stability.critical_speed(car, (1.0, 200.0))
    mats = car.matrices(crit.speed)
    lam, vec = scipy.linalg.eig(mats.state_matrix())
    j = int(np.argmin(np.abs(lam - crit.eigenvalue)))
    n = mats.M.shape[0]
    ref = vec[:n, j] / vec[:n, j][np.argmax(np.abs(vec[:n, j]))]
    np.testing.assert_allclose(crit.mode_shape, ref, atol=1e-8)
    assert crit.coordinates == car.linear_system().labels
    assert max(crit.amplitude(name) for name in crit.coordinates) == pytest.approx(1.0, rel=1e-12)
    with pytest.raises(ValueError, match="coordinate"):
        crit.amplitude("roof z")
    none = stability.critical_speed(car, (1.0, 5.0))
    assert none.status == "stable over the range" and np.all(np.isnan(none.mode_shape))
