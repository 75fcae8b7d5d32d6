"""The coupled crossing (raildyn.bridge.coupled): Frýba's series, the limits that join the models of
increasing fidelity, the energy balance, the vehicle on a rigid bridge against an independent integrator,
trains, and bad input."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.integrate
from scipy.interpolate import CubicSpline

from raildyn.bridge import SimplySupportedBeam, fryba_deflection, moving_force_response
from raildyn.bridge.coupled import crossing
from raildyn.bridge.loads import AxleSequence, moving_load, moving_mass, sprung_mass, train, vehicle
from raildyn.constants import GRAVITY
from raildyn.errors import SolverError
from raildyn.vehicles import VerticalCar

BEAM = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=5)  # f₁ = 3.93 Hz, 200 t
FORCE = AxleSequence([0.0], [1.0e5])
CAR = vehicle(VerticalCar(), 1813.0)  # the Manchester car, its wheelsets riding on the rail


def test_a_moving_force_is_frybas_series_with_the_schemes_second_order_error(reference):
    # Newmark's average acceleration is second order: halving h divides the error by 4 (3.5 to 4.5 allows
    # for the higher terms); at h = 1e-4 s it is below 2e-5 of the peak (measured 1.1e-5).
    v = 30.0
    errors = []
    for h in (4e-4, 2e-4, 1e-4):
        run = crossing(BEAM, FORCE, v, time_step=h)
        on = run.time <= BEAM.span / v
        series = fryba_deflection(BEAM, v, 1.0e5, run.time[on])
        errors.append(np.abs(run.deflection[on] - series).max() / np.abs(series).max())
    assert 3.5 < errors[0] / errors[1] < 4.5 and 3.5 < errors[1] / errors[2] < 4.5
    reference(
        10, "coupled march, moving force, h = 1e-4 s", "Frýba 1972 series", "closed form", errors[-1], 2e-5
    )


def test_an_axle_sequence_is_the_sum_of_its_axles_in_either_solution():
    # The closed form's superposition against the coupled march of the same four forces, with damping; the
    # march's error is of order (ω h)² ≈ 1e-4 of the peak at h = 1e-4 s on the fifth mode (measured 3e-5).
    beam = BEAM.__class__(20.0, 1.0e10, 1.0e4, damping_ratio=0.02, modes=5)
    coach = AxleSequence([0.0, 2.5, 17.5, 20.0], [1.0e5] * 4)
    closed = moving_force_response(beam, 25.0, coach, samples=4001)
    run = crossing(beam, coach, 25.0, time_step=1e-4, free_time=0.0)
    expected = np.interp(run.time, closed.time[0], closed.deflection[0])
    assert np.abs(run.deflection - expected).max() < 1e-4 * np.abs(expected).max()


def test_slowly_the_amplification_is_one():
    # The free vibration a force leaves behind is of order α of its static deflection (0.8 α for one force,
    # measured at α ≤ 0.008 with the closed form): a coach's four axles at α = 0.002 stay within 1 % of 1,
    # and the amplification grows with the speed.
    f1 = BEAM.frequencies_hz[0]
    slow, faster = (crossing(BEAM, CAR.axles, a * 2 * f1 * BEAM.span).amplification for a in (0.002, 0.02))
    assert slow == pytest.approx(1.0, abs=0.01)
    assert faster > slow


def test_the_static_reference_is_the_beam_formula_on_the_modes_kept():
    # The modal static deflection under a force at midspan is PL³/48EI times the share of Σ_odd j⁻⁴ = π⁴/96
    # that five modes keep (Frýba 1972, ch. 1): to 1e-6, the grid's miss of the exact midspan position
    # (the peak is flat there, so the error is of order (vh/L)²).
    run = crossing(BEAM, FORCE, 10.0, free_time=0.0)
    kept = sum(j**-4.0 for j in (1, 3, 5)) / (np.pi**4 / 96)
    expected = BEAM.static_midspan_deflection(1.0e5) * kept
    assert np.abs(run.static_deflection).max() == pytest.approx(expected, rel=1e-6)


def test_a_vanishing_moving_mass_is_a_moving_force():
    # The mass's inertia enters the beam's modal mass in the ratio m/(ρL): the moving mass's deflection tends
    # to the force mg's in proportion to that ratio (measured 1.4 times it; at most 5 times it allowed), so
    # the difference falls a hundredfold from 1000 kg to 10 kg (the lightest body raildyn accepts,
    # raildyn.constants.PLAUSIBLE_RANGES["mass"]).
    gaps = []
    for mass in (10.0, 1000.0):
        run = crossing(BEAM, moving_mass(mass), 40.0, time_step=2e-4)
        force = crossing(BEAM, AxleSequence([0.0], [mass * GRAVITY]), 40.0, time_step=2e-4)
        gap = np.abs(run.deflection - force.deflection).max() / np.abs(force.deflection).max()
        ratio = mass / (BEAM.mass_per_length * BEAM.span)
        assert 0.1 * ratio < gap < 5 * ratio
        gaps.append(gap)
    assert gaps[1] / gaps[0] == pytest.approx(100.0, rel=0.05)


def test_a_heavy_moving_mass_lowers_the_beam_and_its_frequency():
    # A mass of 20 % of the beam's rides on it: the loaded beam is slower, so the free vibration after the
    # mass has gone is the beam's own, and its peak differs from the massless force's.
    heavy = crossing(BEAM, moving_mass(0.2 * 1.0e4 * 20.0), 40.0)
    force = crossing(BEAM, AxleSequence([0.0], [0.2 * 2.0e5 * GRAVITY]), 40.0)
    assert abs(heavy.amplification - force.amplification) > 0.01


@pytest.mark.parametrize("stiffness", [1e9, 1e11])
def test_a_stiff_sprung_mass_is_a_moving_mass(stiffness):
    # Biggs's sprung mass with a spring far stiffer than the beam (its bounce at 35 and 350 Hz against
    # the beam's 3.9 Hz) rides as a rigid mass: the difference falls as the spring stiffens (tolerance:
    # the ratio of the beam's to the body's frequency squared, 1.3e-2 and 1.3e-4, times 2).
    m = 2.0e4
    run = crossing(BEAM, sprung_mass(m, stiffness), 30.0, time_step=1e-4)
    rigid = crossing(BEAM, moving_mass(m), 30.0, time_step=1e-4)
    ratio = (BEAM.frequencies_hz[0] / (np.sqrt(stiffness / m) / (2 * np.pi))) ** 2
    scale = np.abs(rigid.deflection).max()
    assert np.abs(run.deflection - rigid.deflection).max() < 2 * ratio * scale


def test_a_soft_sprung_mass_is_almost_a_moving_force():
    # On a soft spring (0.5 Hz, far below the beam's 3.9 Hz) the body barely moves while it crosses: the
    # wheel force stays within 5 % of the weight, and the beam deflects within 3 % of the moving force's.
    m = 2.0e4
    load = sprung_mass(m, m * (2 * np.pi * 0.5) ** 2)
    run = crossing(BEAM, load, 30.0)
    force = crossing(BEAM, AxleSequence([0.0], [m * GRAVITY]), 30.0)
    on = run.time <= BEAM.span / 30.0
    assert np.abs(run.contact_forces[on, 0] / (m * GRAVITY) - 1).max() < 0.05
    assert abs(run.amplification / force.amplification - 1) < 0.03


def _energy(run, beam, load):
    """The beam's and the vehicle's mechanical energy at each time (the vehicle's gravity included)."""
    b, bd = run.modal[:, 0], run.modal[:, 1]
    omega = 2 * np.pi * beam.frequencies_hz
    mu = beam.modal_masses
    beam_energy = 0.5 * (bd**2 * mu).sum(axis=1) + 0.5 * (b**2 * mu * omega**2).sum(axis=1)
    x = run.speed * run.time[:, None] - load.positions[None, :]
    phi = np.stack([beam.mode_shapes(xj, 0).T for xj in x.T], axis=1)  # (k, a, modes)
    dphi = np.stack([beam.mode_shapes(xj, 1).T for xj in x.T], axis=1)
    u = -(phi @ b[:, :, None])[..., 0]  # rail heights under the axles, up
    ud = -(phi @ bd[:, :, None])[..., 0] - run.speed * (dphi @ b[:, :, None])[..., 0]
    s = load.system
    q, qd = run.vehicle[:, 0], run.vehicle[:, 1]
    full = np.block([[s.K, -s.GK], [-s.GK.T, s.input_stiffness]])
    state = np.concatenate([q, u], axis=1)
    vehicle_energy = (
        0.5 * np.einsum("ki,ij,kj->k", qd, s.M, qd)
        + 0.5 * np.einsum("ki,ij,kj->k", state, full, state)
        + 0.5 * (ud**2 * load.unsprung_masses).sum(axis=1)
        + u @ load.static_loads  # the weight on the wheels, lowered with the rail
    )
    slope = (dphi @ b[:, :, None])[..., 0]  # w′ under each axle
    return beam_energy + vehicle_energy, slope


def test_the_undamped_coupled_system_conserves_energy_but_for_the_pull(reference):
    # Undamped beam and car: the energy of the two changes only by the work of the horizontal force that
    # keeps the speed constant on the sloping beam, −∫ Σ F_j v w′(x_j) dt (368 J here). The scheme's and the
    # trapezoid's errors in the balance stay below 0.1 % of the largest energy exchanged (measured 0.014 %).
    car = VerticalCar(primary_damping=0.0, secondary_damping=0.0)
    load = vehicle(car, 1813.0)
    run = crossing(BEAM, load, 35.0, time_step=1e-4, free_time=0.2)
    energy, slope = _energy(run, BEAM, load)
    power = -(run.contact_forces * slope).sum(axis=1) * run.speed
    work = scipy.integrate.cumulative_trapezoid(power, run.time, initial=0.0)
    exchanged = np.abs(energy - energy[0]).max()
    assert exchanged > 0
    reference(
        10,
        "coupled Manchester car on an undamped span: energy",
        "work of the pulling force",
        "closed form",
        np.abs(energy - energy[0] - work).max() / exchanged,
        1e-3,
        "of exchanged",
    )


def test_a_vehicles_static_loads_carry_its_weight():
    # The suspension's static reactions plus the wheelsets: the car's whole mass times g, to rounding.
    car = VerticalCar()
    total = car.body_mass + 2 * car.bogie_mass + 4 * 1813.0
    assert CAR.static_loads.sum() == pytest.approx(total * GRAVITY, rel=1e-12)
    np.testing.assert_allclose(CAR.positions, car.axle_positions)


def test_the_car_on_a_rigid_bridge_answers_the_irregularity_as_on_rigid_track(reference):
    # A bridge 1000 times stiffer than usual barely moves; the car then sees only the irregularity. scipy's
    # RK45 on M q̈ + C q̇ + K q = G_K u + G_C u̇ (the same rail under each axle, delayed) is independent of the
    # coupled Newmark march: the body's acceleration agrees to 2 % of its peak (the march's (ωh)² error on
    # the wheelset-to-bogie modes near 30 Hz, and the stiff beam's own small motion).
    stiff = SimplySupportedBeam(20.0, 1.0e13, 1.0e4, modes=3)
    x = np.linspace(-30.0, 30.0, 601)
    z = 2e-3 * np.sin(2 * np.pi * x / 8.0) * np.exp(-(((x - 5.0) / 6.0) ** 2))
    v = 25.0
    run = crossing(stiff, CAR, v, irregularity=(x, z), time_step=2e-4, free_time=0.0)
    spline = CubicSpline(x, z)
    system = CAR.system
    mats = system.matrices(v)
    d = CAR.positions

    def rhs(t, y):
        n = system.size
        xa = v * t - d
        u, ud = spline(xa), v * spline(xa, 1)
        force = mats.GK @ u + mats.GC @ ud - mats.C @ y[n:] - mats.K @ y[:n]
        return np.concatenate([y[n:], np.linalg.solve(mats.M, force)])

    sol = scipy.integrate.solve_ivp(
        rhs, (0, run.time[-1]), np.zeros(12), t_eval=run.time, rtol=1e-9, atol=1e-12
    )
    n = system.size
    accel = np.array([rhs(t, y)[n] for t, y in zip(sol.t, sol.y.T, strict=True)])
    body = run.vehicle_acceleration("body z")
    reference(
        10,
        "Manchester car on a stiff bridge over an irregularity: body acceleration",
        "the car on rigid track by RK45 (scipy)",
        "scipy",
        np.abs(body - accel).max() / np.abs(accel).max(),
        0.02,
    )


def test_a_train_is_its_cars_one_behind_the_other():
    # Two cars with a gap: the axles line up, the weights add, and with the cars far apart (a 300 m gap on a
    # 20 m span) the second car's crossing repeats the first's once the first's free vibration has died out
    # (5 % damping over the 7 s between them leaves e^{−2π·0.05·3.93·7} ≈ 2e-4 of it): to 1 % of the peak.
    damped = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, damping_ratio=0.05, modes=3)
    pair = train([CAR, CAR], 300.0)
    np.testing.assert_allclose(pair.positions[4:], CAR.positions + CAR.length + 300.0)
    assert pair.static_loads.sum() == pytest.approx(2 * CAR.static_loads.sum())
    v = 40.0
    run = crossing(damped, pair, v, time_step=2e-4, free_time=0.0)
    one = crossing(damped, CAR, v, time_step=2e-4, free_time=0.0)
    shift = int(round((CAR.length + 300.0) / v / 2e-4))
    second = run.deflection[shift:]
    k = min(second.size, one.time.size)
    assert np.abs(second[:k] - one.deflection[:k]).max() < 0.01 * np.abs(one.deflection).max()


def test_moment_and_acceleration_are_the_modes_derivatives():
    # Midspan moment against EI times the closed-form curvature of the same modes: the same sum, so they agree
    # to rounding; the deck acceleration against the central second difference of the deflection, to the
    # scheme's consistency (Newmark's average acceleration is exactly the trapezoid of the accelerations).
    run = crossing(BEAM, FORCE, 30.0, time_step=1e-4)
    shapes = BEAM.mode_shapes([10.0], 2)[:, 0]
    np.testing.assert_allclose(run.moment, -BEAM.flexural_rigidity * run.modal[:, 0] @ shapes, rtol=1e-12)
    h = run.time[1] - run.time[0]
    second = (run.deflection[2:] - 2 * run.deflection[1:-1] + run.deflection[:-2]) / h**2
    mean = (run.deck_acceleration[2:] + 2 * run.deck_acceleration[1:-1] + run.deck_acceleration[:-2]) / 4
    np.testing.assert_allclose(second, mean, atol=1e-8 * np.abs(mean).max())


def test_bad_input_is_refused_by_name():
    with pytest.raises(ValueError, match="speed"):
        crossing(BEAM, FORCE, -1.0)
    with pytest.raises(TypeError, match="load"):
        crossing(BEAM, 1.0e5, 10.0)
    with pytest.raises(TypeError, match="beam"):
        crossing("beam", FORCE, 10.0)
    with pytest.raises(ValueError, match="irregularity x"):
        crossing(BEAM, CAR, 10.0, irregularity=(np.linspace(0, 20, 50), np.zeros(50)))
    with pytest.raises(ValueError, match="time_step"):
        crossing(BEAM, FORCE, 10.0, time_step=1e-9)
    with pytest.raises(ValueError, match="positions"):
        AxleSequence([0.0, 2.0, 1.0], [1.0] * 3)
    with pytest.raises(ValueError, match="mass"):
        moving_mass(0.0)
    with pytest.raises(ValueError, match="gaps"):
        train([CAR, CAR, CAR], [1.0])


def test_a_diverging_run_raises_the_one_failure():
    # A negative-mass trick is refused up front, so divergence needs a non-finite input: a huge irregularity
    # that overflows. The partial result comes with the error.
    x = np.linspace(-30.0, 30.0, 61)
    with pytest.raises(SolverError) as info:
        crossing(BEAM, CAR, 10.0, irregularity=(x, 1e306 * np.sin(x)))
    assert info.value.partial is not None


def test_moving_forces_keep_the_sequence():
    load = moving_load(AxleSequence([0.0, 3.0], [1.0, 2.0], "pair"))
    assert load.name == "pair" and load.system is None
    np.testing.assert_array_equal(load.axles.loads, [1.0, 2.0])


def test_a_continuous_beam_of_one_span_crosses_as_the_simple_beam():
    # The same modes by two constructions (the continuous beam's exact modes are the simple beam's for one
    # span, to 1e-12, and scaled alike): the coupled crossings agree to 1e-9 of the peak.
    from raildyn.bridge.continuous import ContinuousBeam

    single = ContinuousBeam((20.0,), 1.0e10, 1.0e4, modes=5)
    ours, simple = (crossing(beam, CAR, 40.0, time_step=2e-4) for beam in (single, BEAM))
    assert np.abs(ours.deflection - simple.deflection).max() < 1e-9 * np.abs(simple.deflection).max()


def test_a_slow_force_over_two_spans_draws_the_influence_line():
    # Over two continuous 20 m spans a slow force bends the first span's middle as the static influence line
    # does (ContinuousBeam.static_deflection, by slope-deflection): to 1 % of the peak, the modes
    # kept (10) and the small dynamic part at α = 0.005 (order α). The second span lifts the first.
    from raildyn.bridge.continuous import ContinuousBeam

    two = ContinuousBeam((20.0, 20.0), 1.0e10, 1.0e4, modes=10)
    v = 0.005 * 2 * two.frequencies_hz[0] * 20.0
    run = crossing(two, FORCE, v, free_time=0.0)
    x = np.clip(v * run.time, 0.0, 40.0)
    line = two.static_deflection(10.0, x, 1.0e5)  # Maxwell: the force at x bends 10 m as one at 10 m bends x
    assert np.abs(run.deflection - line).max() < 0.01 * np.abs(line).max()
    assert run.deflection[x > 25.0].min() < 0.0
