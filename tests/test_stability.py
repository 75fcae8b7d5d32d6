"""raildyn.stability: batched eigenvalues, mode tracking, critical speed, maps and nonlinear hunting."""

import control
import numpy as np
import pytest
import scipy.linalg
from hypothesis import example, given, settings
from hypothesis import strategies as st

from raildyn import stability, vibration
from raildyn.linear_model import LinearSystem, as_linear_system
from raildyn.vehicles import Bogie, LateralCar
from raildyn.wheelset import NonlinearWheelset, Wheelset

SOFT = Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)  # a wheelset that hunts below 60 m/s


def _negative_damping_oscillator(c0, c1, k=4.0):
    """m q̈ + (c₁/V − c₀) q̇ + k q = 0: unstable exactly for V > c₁/c₀."""
    one = np.array([[1.0]])
    return LinearSystem(one, -c0 * one, c1 * one, k * one, labels=("q",))


# ---------------------------------------------------------------------------
# Eigenvalues


@pytest.mark.parametrize("model", [SOFT, Bogie(), LateralCar()], ids=["wheelset", "bogie", "car"])
def test_batched_eigenvalues_agree_with_python_control_poles(model, reference):
    # The same state space through python-control (to_control from raildyn.vibration): the sorted
    # poles agree to 1e-8 of the largest, the accuracy of a balanced nonsymmetric eigen-solver.
    speeds = [5.0, 40.0, 90.0]
    batched = stability.eigenvalues_against_speed(model, speeds)
    system = as_linear_system(model)
    for V, lam in zip(speeds, batched, strict=True):
        mats = system.matrices(V)
        M, C, K = mats.M, mats.C, mats.K
        poles = control.poles(vibration.to_control(M, C, K, np.ones((system.size, 1))))
        scale = np.abs(poles).max()
        gap = np.abs(np.sort_complex(lam) - np.sort_complex(poles)).max() / scale
        reference(
            7,
            f"eigenvalues of the {type(model).__name__.lower()} at {V:g} m/s",
            "python-control poles",
            "python-control",
            gap,
            1e-8,
        )


@settings(deadline=None, max_examples=50)
@given(speed=st.floats(0.5, 200.0), conicity=st.floats(0.01, 0.5))
def test_batched_eigenvalues_agree_with_complex_modes(speed, conicity):
    # raildyn.vibration.complex_modes solves each speed on its own (scipy.linalg.eig).
    ws = SOFT.replace(conicity=conicity)
    lam = stability.eigenvalues_against_speed(ws, [speed])[0]
    mats = as_linear_system(ws).matrices(speed)
    M, C, K = mats.M, mats.C, mats.K
    ref = vibration.complex_modes(M, C, K).eigenvalues
    np.testing.assert_allclose(np.sort_complex(lam), np.sort_complex(ref), atol=1e-9 * np.abs(ref).max())


# ---------------------------------------------------------------------------
# Mode tracking


def test_mode_tracking_keeps_labels_through_a_crossing():
    # Two uncoupled modes: q₁ with k = 4 and damping 3/V, whose damped frequency
    # √(4 − 2.25/V²) rises through that of q₂ (√3, undamped) at V = 1.5 m/s. Sorting by
    # frequency swaps them there; MAC tracking must not.
    M = np.eye(2)
    system = LinearSystem(M, np.zeros((2, 2)), np.diag([3.0, 0.0]), np.diag([4.0, 3.0]), labels=("q1", "q2"))
    speeds = np.linspace(1.2, 3.0, 60)
    sweep = stability.mode_sweep(system, speeds)
    j1 = sweep.labels.index("q1")
    j2 = sweep.labels.index("q2")
    expected1 = np.sqrt(4.0 - 2.25 / speeds**2) / (2 * np.pi)
    # Each column stays on its own coordinate and follows its own closed-form frequency (1e-10 Hz).
    np.testing.assert_allclose(sweep.frequencies_hz[:, j1], expected1, atol=1e-10)
    np.testing.assert_allclose(sweep.frequencies_hz[:, j2], np.sqrt(3.0) / (2 * np.pi), atol=1e-10)
    assert np.all(np.abs(sweep.shapes[:, 1, j1]) < 1e-12)
    # The naive order by frequency does swap at the crossing, so the test has teeth.
    naive = np.sort(sweep.frequencies_hz, axis=1)
    assert not np.allclose(naive[:, 0], sweep.frequencies_hz[:, j1])


def test_mode_labels_follow_kinetic_energy_not_amplitude():
    # Lateral (kg) and yaw (kg·m²) coordinates coupled through K. scipy's undamped modes of (K, M):
    # the 6.2 Hz mode moves ψ more than y in numbers, but y holds 95 % of its kinetic energy.
    M = np.diag([1000.0, 10.0])
    K = np.array([[2.0e6, -2.0e5], [-2.0e5, 1.0e5]])
    w2, phi = scipy.linalg.eigh(K, M)
    energy = np.diag(M)[:, None] * phi**2
    assert np.argmax(np.abs(phi[:, 0])) == 1 and np.argmax(energy[:, 0]) == 0  # the case has teeth
    system = LinearSystem(M, np.zeros((2, 2)), np.zeros((2, 2)), K, labels=("y", "ψ"))
    sweep = stability.mode_sweep(system, [1.0, 2.0])
    np.testing.assert_allclose(sweep.frequencies_hz[0], np.sqrt(w2) / (2 * np.pi), rtol=1e-10)
    assert sweep.labels == ("y", "ψ")


def test_mode_sweep_damping_ratio_crosses_zero_at_the_critical_speed():
    # The hunting mode's damping ratio changes sign between the two sweep speeds around V_c.
    cs = stability.critical_speed(SOFT, (5.0, 120.0))
    speeds = np.linspace(5.0, 120.0, 300)
    sweep = stability.mode_sweep(SOFT, speeds)
    below, above = speeds < cs.speed, speeds > cs.speed
    unstable = sweep.damping_ratios < 0
    assert not unstable[below].any()
    assert unstable[above].any(axis=0).sum() == 1, "one mode loses stability"


# ---------------------------------------------------------------------------
# Critical speed


@settings(deadline=None, max_examples=50)
@given(c0=st.floats(0.05, 2.0), v=st.floats(2.5, 95.0))
@example(c0=0.7547967965219685, v=95.0)  # c₁/c₀ rounds above V: the range once passed 200 m/s
def test_critical_speed_of_negative_damping_oscillator(c0, v):
    # Closed form: damping c₁/V − c₀ vanishes at V = c₁/c₀; the root is found to tol = 0.01 m/s.
    # The root V is drawn up to 95 m/s, so the range searched, up to 2V + 10, stays within
    # raildyn.constants.MAXIMUM_SPEED (200 m/s). The range is set from the drawn V itself: c₁/c₀ may
    # round above it (95 m/s gave 200.00000000000003, refused).
    c1 = c0 * v
    expected = c1 / c0
    cs = stability.critical_speed(_negative_damping_oscillator(c0, c1), (1.0, 2.0 * v + 10.0))
    assert cs.found
    assert abs(cs.speed - expected) <= 0.01
    assert cs.frequency_hz == pytest.approx(2.0 / (2 * np.pi), rel=1e-3)


def test_critical_speed_brackets_the_sign_change():
    cs = stability.critical_speed(LateralCar(), (1.0, 200.0))
    g = stability.largest_real_part(LateralCar(), [cs.speed - 0.05, cs.speed + 0.05])
    assert g[0] < 0.0 < g[1]


def test_critical_speed_statuses():
    # c₁/c₀ = 100 m/s: found in (1, 150), not in (1, 90).
    crossing = stability.critical_speed(_negative_damping_oscillator(0.1, 10.0), (1.0, 150.0))
    assert crossing.found and crossing.speed == pytest.approx(100.0, abs=0.01)
    never = stability.critical_speed(_negative_damping_oscillator(0.1, 10.0), (1.0, 90.0))
    assert never.status == "stable over the range" and never.speed == np.inf
    always = stability.critical_speed(Wheelset().free(), (1.0, 100.0))
    assert always.status == "unstable at the lowest speed" and always.speed == 1.0


def test_critical_speed_falls_with_conicity():
    # Klingel frequency rises with √λ, so the hunting speed of a bogie falls as λ grows.
    speeds = [
        stability.critical_speed(Bogie().replace(conicity=lam), (1.0, 200.0)).speed
        for lam in (0.05, 0.2, 0.4)
    ]
    assert speeds[0] > speeds[1] > speeds[2]


def test_critical_speed_map_matches_single_calls():
    bogie = Bogie()

    def factory(lam, k):
        return bogie.replace(conicity=lam, yaw_stiffness=k)

    result = stability.critical_speed_map(
        factory, [0.1, 0.3], [5e6, 5e7], (1.0, 200.0), x_name="λ", y_name="k_ψ", progress=False
    )
    assert result.speeds.shape == (2, 2)
    single = stability.critical_speed(factory(0.3, 5e7), (1.0, 200.0)).speed
    assert result.speeds[1, 1] == pytest.approx(single, abs=0.1)


def test_bad_input():
    with pytest.raises(ValueError, match="speeds"):
        stability.eigenvalues_against_speed(SOFT, [])
    with pytest.raises(ValueError, match="speeds"):
        stability.eigenvalues_against_speed(SOFT, [10.0, -1.0])
    with pytest.raises(ValueError, match="speed_range"):
        stability.critical_speed(SOFT, (50.0, 50.0))
    with pytest.raises(ValueError, match="speed_range"):
        stability.critical_speed(SOFT, (0.0, 50.0))
    with pytest.raises(ValueError, match="speed_range"):
        stability.critical_speed(SOFT, [])
    with pytest.raises(ValueError, match="increasing"):
        stability.mode_sweep(SOFT, [30.0, 20.0])
    with pytest.raises(TypeError, match="model"):
        stability.critical_speed("car", (1.0, 50.0))
    with pytest.raises(ValueError, match="speed"):
        stability.limit_cycle_amplitude(NonlinearWheelset(SOFT), 0.0)


# ---------------------------------------------------------------------------
# Nonlinear hunting


def test_limit_cycle_amplitude_converged_in_step_size():
    # Halving the largest step changes the limit-cycle amplitude by less than 0.5 %: the cycle
    # (≈ 5 Hz) is resolved by > 100 steps, and RK45 at rtol 1e-6 adds less than that.
    model = NonlinearWheelset(SOFT)
    coarse = stability.limit_cycle_amplitude(model, 60.0, max_step=2e-3)
    fine = stability.limit_cycle_amplitude(model, 60.0, max_step=1e-3)
    assert coarse.hunting() and fine.hunting()
    assert fine.amplitude == pytest.approx(coarse.amplitude, rel=5e-3)
    assert fine.frequency_hz == pytest.approx(coarse.frequency_hz, rel=5e-3)


def test_limit_cycle_decays_well_below_the_critical_speed():
    cycle = stability.limit_cycle_amplitude(NonlinearWheelset(SOFT), 30.0, initial_displacement=2e-3)
    assert not cycle.hunting()


def test_nonlinear_critical_speed_of_the_wheelset_not_above_the_linear_one():
    # This wheelset's bifurcation is close to supercritical, so the two speeds nearly meet. Near a
    # supercritical Hopf point the cycle shrinks to zero and the time to settle on it diverges, so a
    # 6 s run resolves the end of the branch to about 1 m/s only: that is the allowed excess.
    linear = stability.critical_speed(SOFT, (5.0, 120.0)).speed
    diagram = stability.bifurcation_diagram(
        NonlinearWheelset(SOFT), np.linspace(40.0, 70.0, 7), duration=6.0, refine=4, progress=False
    )
    assert np.isfinite(diagram.nonlinear_critical_speed)
    assert diagram.nonlinear_critical_speed <= linear + 1.0
    assert diagram.hunting[0], "the highest speed hunts"


def test_nonlinear_critical_speed_of_the_default_car_not_above_the_linear_one():
    # The default car (Manchester vehicle, cone λ = 0.15, flange at 9.1 mm) hunts on its flanges
    # at 75 m/s, well below its linear critical speed of about 84 m/s (a subcritical bifurcation).
    car = LateralCar()
    linear = stability.critical_speed(car, (1.0, 200.0)).speed
    cycle = stability.limit_cycle_amplitude(car.nonlinear(), 0.9 * linear)
    assert cycle.hunting()
    assert cycle.amplitude > car.nonlinear().contact.flange_clearance


def test_shooting_finds_the_cycle_that_direct_integration_settles_on():
    # Two independent computations of the same limit cycle: 8 s of RK45 from a flange-touching
    # start, and Newton shooting with DOP853 at rtol 1e-10. The run's amplitude still carries the
    # decay of its transient (about 1e-4 relative here), its frequency the step of its zero
    # crossings (2 ms in 0.17 s); 1e-3 covers both.
    model = NonlinearWheelset(SOFT)
    run = stability.limit_cycle_amplitude(model, 60.0)
    orbit = stability.periodic_orbit(model, 60.0, run.state, 1.0 / run.frequency_hz)
    assert orbit.amplitude == pytest.approx(run.amplitude, rel=1e-3)
    assert orbit.period == pytest.approx(1.0 / run.frequency_hz, rel=1e-3)
    assert orbit.residual < 1e-8
    # An autonomous system always has the multiplier 1 (a shift along the orbit). Central finite
    # differences of trajectories integrated on one shared step sequence give it to a few 1e-6
    # (seen: 3e-6; one-sided differences on separate step sequences gave only ~1e-3); 1e-4.
    assert np.min(np.abs(orbit.multipliers - 1.0)) < 1e-4
    assert orbit.stable, "the cycle that a simulation settles on is stable"


@settings(deadline=None, max_examples=50)
@given(seed=st.integers(0, 2**31 - 1), factor=st.complex_numbers(min_magnitude=0.1, max_magnitude=10.0))
def test_mac_is_one_for_scaled_vectors_and_symmetric(seed, factor):
    # MAC is invariant to complex scaling, lies in [0, 1] (Cauchy–Schwarz) and is symmetric.
    rng = np.random.default_rng(seed)
    a = rng.normal(size=(5, 3)) + 1j * rng.normal(size=(5, 3))
    b = rng.normal(size=(5, 3)) + 1j * rng.normal(size=(5, 3))
    np.testing.assert_allclose(np.diag(stability.mac(a, factor * a)), 1.0, rtol=1e-12)
    m = stability.mac(a, b)
    assert np.all((m >= 0) & (m <= 1 + 1e-12))
    np.testing.assert_allclose(m, stability.mac(b, a).T, rtol=1e-12)


def test_critical_speed_map_rejects_an_empty_grid():
    with pytest.raises(ValueError, match="x must not be empty"):
        stability.critical_speed_map(lambda x, y: SOFT, [], [1.0], progress=False)


# ---------------------------------------------------------------------------
# Bad input: the cases of issue 15


@pytest.mark.parametrize("rtol", [np.nan, np.inf, 0.0, -1e-6, 1.0, 1e-14])
def test_a_bad_tolerance_is_refused_before_the_run(rtol):
    # rtol=nan used to run forever, and rtol=inf or a tiny one for minutes.
    with pytest.raises(ValueError, match="rtol"):
        stability.limit_cycle_amplitude(NonlinearWheelset(), 60.0, duration=1.0, rtol=rtol)
    with pytest.raises(ValueError, match="rtol"):
        stability.simulate(NonlinearWheelset(), 60.0, [1e-3, 0.0, 0.0, 0.0], 1.0, rtol=rtol)


def test_run_lengths_and_counts_have_stated_limits():
    model = NonlinearWheelset(SOFT)
    with pytest.raises(ValueError, match="duration"):
        stability.simulate(model, 60.0, [1e-3, 0.0, 0.0, 0.0], 1e300)
    with pytest.raises(ValueError, match="period"):
        stability.periodic_orbit(model, 60.0, [1e-2, 0.0, 0.0, 0.0], 1e300)
    with pytest.raises(ValueError, match="initial_displacement"):
        stability.limit_cycle_amplitude(model, 60.0, initial_displacement=0.0)
    with pytest.raises(ValueError, match="refine"):
        stability.bifurcation_diagram(model, [60.0], refine=10**12, progress=False)
    with pytest.raises(ValueError, match="scan"):
        stability.critical_speed(SOFT, (1.0, 100.0), scan=10**12)


def test_an_integration_has_a_bounded_number_of_evaluations(monkeypatch):
    from raildyn.errors import SolverError
    from raildyn.stability import nonlinear

    monkeypatch.setattr(nonlinear, "_MAX_EVALUATIONS", 500)
    with pytest.raises(SolverError, match="evaluations"):
        stability.simulate(NonlinearWheelset(SOFT), 60.0, [1e-3, 0.0, 0.0, 0.0], 1.0, max_step=1e-4)


def test_what_is_not_a_model_is_refused_by_name():
    with pytest.raises(TypeError, match="model"):
        stability.simulate("wheelset", 60.0, [1e-3, 0.0, 0.0, 0.0], 1.0)
    with pytest.raises(TypeError, match="factory"):
        stability.critical_speed_map(lambda x, y: "car", [1.0], [1.0], progress=False)
    with pytest.raises(ValueError, match=r"factory failed at x\[0\] = -1.0"):
        stability.critical_speed_map(lambda x, y: Wheelset(conicity=x), [-1.0], [1.0], progress=False)


def test_results_check_their_fields():
    with pytest.raises(ValueError, match="status"):
        stability.CriticalSpeed(50.0, 5.0, 1j, "unknown", np.ones(2), ("y", "ψ"))
    with pytest.raises(ValueError, match="speed"):
        stability.CriticalSpeed(np.nan, 5.0, 1j, "crossing", np.ones(2), ("y", "ψ"))
    with pytest.raises(ValueError, match="frequency_hz"):
        stability.LimitCycle(60.0, 0.01, np.nan, 1.0, np.zeros(4), 0.01, 8.0)
    with pytest.raises(ValueError, match="oscillation"):
        stability.LimitCycle(60.0, 0.01, 5.7, 1.0, np.zeros(4), -0.01, 8.0)
    with pytest.raises(ValueError, match="duration"):
        stability.LimitCycle(60.0, 0.01, 5.7, 1.0, np.zeros(4), 0.01, 0.0)
    with pytest.raises(TypeError, match="labels"):
        stability.ModeSweep(np.array([1.0]), np.ones((1, 1)), np.ones((1, 1)), np.ones((1, 1)),
                            np.ones((1, 1, 1)), "y", ("y",))  # fmt: skip
