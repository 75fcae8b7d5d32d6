"""Chapter 9 models: resistance, traction, couplers, longitudinal runs, lateral and vertical effects."""

import dataclasses

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn import train
from raildyn.constants import GRAVITY
from raildyn.train.resistance import MPH, SHORT_TON
from raildyn.train.vehicles import FT, LBF

HOPPER = train.VEHICLES["loaded hopper"]
LOCO = train.VEHICLES["SD40-2"]


# --- tier 2: published worked examples and data -------------------------------------------------


def test_davis_original_worked_example_7200_ton_train(reference):
    # Davis's original formula {davis1926}, R = 1.3 + 29/w + 0.045 V + 0.0005 A V²/(w n) lb/ton, worked by
    # hand for a 7,200-ton train of 143-ton four-axle cars (A = 88 ft², so 0.0005 A = 0.044) at 50 mph on
    # level tangent track, term by term over the whole train: 1.3 lb per ton, 29 lb per axle, 0.045 V lb
    # per ton and 0.044 V² lb per car (9,360 + 5,840.6 + 16,200 + 5,538.5 lbf). The code converts per ton
    # and per axle through w = 143/4; the two agree to the round-off of a few products (1e-12).
    cars = 7200 / 143
    per_car = train.davis_resistance(50.0, 143.0, 4, 88.0, units="US")
    by_hand = 1.3 * 7200 + 29 * 4 * cars + 0.045 * 50 * 7200 + 0.044 * 50**2 * cars
    assert 9360 + 5840.6 + 16200 + 5538 == pytest.approx(by_hand, abs=1.0)  # the terms as rounded above
    reference(
        9,
        "Davis resistance of a 7,200-ton train at 50 mph",
        "Davis's formula (1926) worked by hand, term by term",
        "closed form",
        abs(per_car * cars / by_hand - 1),
        1e-12,
    )


def test_davis_si_matches_us_units():
    # The SI call converts at the edge: same number to rounding.
    us = train.davis_resistance(40.0, 100.0, 4, 90.0, units="US")
    si = train.davis_resistance(40.0 * MPH, 100.0 * SHORT_TON, 4, 90.0 * FT**2)
    assert si == pytest.approx(us * LBF, rel=1e-12)


def test_modified_davis_closed_form():
    # 0.6 + 20/w + 0.01 V + K V²/(w n), K = 0.07, for a 130-ton four-axle car at 40 mph.
    w, n, v = 130 / 4, 4, 40.0
    per_ton = 0.6 + 20 / w + 0.01 * v + 0.07 * v**2 / (w * n)
    got = train.davis_resistance(v, 130.0, 4, 90.0, form="modified", units="US")
    assert got == pytest.approx(per_ton * 130, rel=1e-12)
    assert got < train.davis_resistance(v, 130.0, 4, 90.0, units="US")  # modern equipment rolls easier


def test_sd40_2_published_values():
    # 368,000 lb, 68 ft 10 in, six axles, 115,000 lbf starting effort {emd_sd40_2}.
    assert LOCO.mass == pytest.approx(166_922, rel=1e-4)
    assert LOCO.length == pytest.approx(20.98, abs=0.005)
    assert LOCO.axles == 6
    assert LOCO.max_tractive_effort / LBF == pytest.approx(115_000)


# --- tier 1: closed forms ------------------------------------------------------------------------


def test_tractive_effort_adhesion_then_constant_power():
    f, p = LOCO.max_tractive_effort, LOCO.rail_power
    crossover = p / f
    assert train.tractive_effort(0.5 * crossover, 8, f, p) == pytest.approx(f)
    v = np.linspace(1.5 * crossover, 30, 10)
    assert np.allclose(train.tractive_effort(v, 8, f, p) * v, p, rtol=1e-12)
    assert np.allclose(train.tractive_effort(v, 4, f, p), 0.5 * train.tractive_effort(v, 8, f, p))


def test_air_brake_signal_and_build_up():
    brake = train.AirBrake(start=2.0, propagation_speed=250.0, build_up_time=3.0)
    assert brake.arrival(1000.0) == pytest.approx(6.0)
    assert brake.fraction(5.9, 1000.0) == 0.0
    assert brake.fraction(9.0, 1000.0) == pytest.approx(1 - np.exp(-1.0), rel=1e-12)


def _steady_model(route=None, cars=30):
    consist = train.make_consist(f"2 SD40-2 + {cars} loaded hopper")
    return train.TrainModel(consist, route=route or train.Route.level(), front_start=500.0)


@pytest.mark.parametrize(("grade", "cars"), [(0.0, 30), (0.005, 15), (-0.001, 30)])
def test_quasi_static_forces_are_resistance_behind_each_coupler(grade, cars):
    speed = 15.0
    base = _steady_model(train.Route((0.0,), (grade,)), cars=cars)
    c = base.consist
    kinds = [v.kind for v in c.vehicles]
    resistance = np.array(
        [
            train.davis_resistance(speed, v.mass, v.axles, v.frontal_area, kind=k)
            for v, k in zip(c.vehicles, kinds, strict=True)
        ]
    ) + train.grade_force(c.mass, grade)
    # Choose the notch that balances the train so that it runs at constant speed.
    per_loco = train.tractive_effort(speed, 8, LOCO.max_tractive_effort, LOCO.rail_power)
    notch = 8 * resistance.sum() / (2 * per_loco)
    result = dataclasses.replace(base, notch=notch).quasi_static(speed)
    assert abs(result.acceleration) < 1e-12
    # Behind each coupler: the resistance of the vehicles there, less the pull of any locomotive there.
    net = resistance - np.where(c.locomotive, notch / 8 * per_loco, 0.0)
    behind = np.cumsum(net[::-1])[::-1][1:]
    # Independent sums of the same numbers: agreement to rounding.
    np.testing.assert_allclose(result.coupler_force, behind, rtol=1e-9)


def test_quasi_static_acceleration_is_net_force_over_mass():
    model = dataclasses.replace(_steady_model(), notch=8)
    qs = model.quasi_static(10.0)
    assert qs.acceleration == pytest.approx(qs.external_force.sum() / model.consist.total_mass)
    assert qs.coupler_force[0] > 0  # the locomotives pull the train


def _kernel_cases():
    hilly = train.Route((0.0, 400.0, 900.0), grade=(0.0, 0.01, -0.004), curvature=(0.0, 1 / 300, -1 / 600))
    base = train.braking_model(12, 2)
    cases = {
        "braking on level track": (base, 4.0),
        "before the application": (dataclasses.replace(base, air_brake=train.AirBrake(start=9.0)), 4.0),
        "grade and curves": (dataclasses.replace(base, route=hilly, front_start=600.0), 4.0),
        "traction": (dataclasses.replace(base, air_brake=None, notch=6, route=hilly, front_start=500.0), 1.0),
        "dynamic brake": (dataclasses.replace(base, air_brake=None, dynamic_brake=0.7), 1.0),
        "no slack, no resistance": (
            dataclasses.replace(base, gear=train.DraftGear(slack=0.0), resistance=False),
            2.0,
        ),
        "no solid stiffness": (
            dataclasses.replace(base, gear=train.DraftGear(solid_stiffness=0.0), davis_form="modified"),
            2.0,
        ),
    }
    return [pytest.param(model, t, id=name) for name, (model, t) in cases.items()]


@pytest.mark.parametrize(("model", "t"), _kernel_cases())
def test_compiled_rhs_equals_numpy_reference(model, t):
    # Random states that put couplers in the gap, the blend, both branches and the solid part,
    # at speeds either side of zero: the compiled loop and numpy agree to round-off.
    rng = np.random.default_rng(11)
    n = model.size
    for _ in range(20):
        y = model.initial_state(rng.uniform(-1.0, 25.0), 0.0)
        y[1:n] = rng.uniform(-0.12, 0.12, n - 1)
        y[n:] += rng.normal(0.0, 0.3, n)
        fast, ref = model.rhs(t, y), model.rhs_numpy(t, y)
        np.testing.assert_allclose(fast, ref, rtol=1e-12, atol=1e-12 * np.abs(ref).max())


@pytest.mark.parametrize(("model", "t"), _kernel_cases())
def test_integrators_rhs_unpacks_the_model_as_packed(model, t):
    # The integrator's right-hand side reads the model from one row of floats: the same numbers.
    from raildyn.train import _kernel

    rng = np.random.default_rng(12)
    n = model.size
    data, out = _kernel.pack(*model._packed), np.empty(2 * n)
    for _ in range(5):
        y = model.initial_state(rng.uniform(-1.0, 25.0), 0.0)
        y[1:n] = rng.uniform(-0.12, 0.12, n - 1)
        _kernel.rhs_dopri(t, y, 0, data, out)
        np.testing.assert_array_equal(out, model.rhs(t, y))
    assert data[0, _kernel.H_NON_FINITE] == 0


def test_integrators_rhs_leaves_a_non_finite_force_for_the_integrator_to_reject():
    # The integrator rejects a step whose error norm is NaN; the right-hand side must not hide an
    # overflow, and counts it for the message of a run that stops there.
    from raildyn.train import _kernel

    model = _overflowing(train.braking_model(2, 1), row="ROW_A2")  # a2 v² overflows
    data, out = _kernel.pack(*model._packed), np.empty(2 * model.size)
    for t in (0.5, 1.5):
        _kernel.rhs_dopri(t, model.initial_state(20.0), 0, data, out)
    assert np.isnan(out).all()  # as solve_ivp is given it (an infinite force would make the first step 0)
    assert data[0, _kernel.H_NON_FINITE] == 2 and data[0, _kernel.H_LAST_NON_FINITE] == 1.5


def _free_model(slack, cars=6):
    consist = train.make_consist(f"{cars} loaded hopper")
    return train.TrainModel(consist, gear=train.DraftGear(slack=slack), resistance=False)


def test_momentum_conserved_without_external_force():
    model = _free_model(0.03)
    rng = np.random.default_rng(3)
    y0 = model.initial_state(10.0, 0.0)
    y0[model.size :] += rng.uniform(-0.5, 0.5, model.size)
    run = _run_from(model, y0, 20.0)
    momentum = model.consist.mass @ run.speed
    # Coupler forces cancel in pairs, and Runge–Kutta keeps linear invariants: rounding only.
    assert np.abs(momentum - momentum[0]).max() < 1e-10 * momentum[0]
    assert np.abs(run.coupler_force).max() > 1e4  # the couplers did act


def _run_from(model, y0, duration, samples=2001):
    from scipy.integrate import solve_ivp

    sol = solve_ivp(
        model.rhs,
        (0, duration),
        y0,
        t_eval=np.linspace(0, duration, samples),
        rtol=1e-9,
        atol=1e-10,
        vectorized=True,
    )
    return model.run_from_states(sol.t, sol.y, sol.nfev)


def test_no_coupler_force_while_gaps_open():
    # Slack centred, speeds differing so little that no gap closes in 10 s (the largest drift,
    # 0.8 mm/s × 10 s = 8 mm, stays inside the 15 mm half gap minus the 1 mm blend).
    model = _free_model(0.03)
    y0 = model.initial_state(12.0, 0.0)
    y0[model.size :] += np.array([0.0, 0.4, -0.4, 0.4, -0.4, 0.0]) * 1e-3
    run = _run_from(model, y0, 10.0)
    assert np.all(run.coupler_force == 0.0)
    np.testing.assert_allclose(
        run.speed, np.broadcast_to(run.speed[:, :1], run.speed.shape), rtol=0, atol=1e-12
    )


def test_run_in_peak_grows_with_slack():
    # Dynamic brake on the locomotive of a stretched train: the wagons run in. More slack,
    # a faster closing speed at each coupler, a larger impact.
    peaks = []
    for slack in (0.0, 0.025, 0.05, 0.1):
        model = train.braking_model(20, 1, slack=slack)
        model = dataclasses.replace(model, air_brake=None, dynamic_brake=1.0)
        run = train.simulate(model, 15.0, 15.0, initial_extension=slack / 2, samples=3001)
        peaks.append(run.max_compression.max())
    assert np.all(np.diff(peaks) > 0.05 * peaks[0]), peaks


def _solve_ivp_reference(model, duration, extension, samples):
    """The run of simulate's defaults (RK45, rtol 1e-7) through scipy's solve_ivp: the reference."""
    from raildyn.train import longitudinal

    n = model.size
    atol = np.r_[1e-3, np.full(n - 1, 1e-6), np.full(n, 1e-5)]
    y0 = model.initial_state(20.0, extension)
    t_eval = np.linspace(0.0, duration, samples)
    return longitudinal._integrate_solve_ivp(model, y0, t_eval, 1e-7, atol, "RK45", np.inf, None)


# The compiled Dormand-Prince pair has RK45's step control and dense output, so it takes solve_ivp's
# steps; but the two round differently (solve_ivp's error norm goes through BLAS), and a braking train
# magnifies round-off: once the slack runs in again and near the stop, an error norm within round-off
# of 1 flips a step between accepted and rejected. solve_ivp's own run with the initial speeds changed
# by one part in 2^52 strays as far (measured over 60 s, 10 and 20 cars: 40 and 6 evaluations more or
# fewer, speeds up to 1e-5 to 4e-4 of the initial speed apart near the stop, as the compiled run).
# So the steps and samples are compared over the run-in, where both stay within round-off, and the
# whole stop by what the book reads from it: the peak and the stop time.
@pytest.mark.parametrize("cars, span", [(20, 20.0), (150, 30.0)])
def test_compiled_rk45_takes_the_steps_of_solve_ivp(cars, span):
    model = train.braking_model(cars, 2)
    extension = model.gear.slack / 2
    samples = round(10 * span) + 1
    run = train.simulate(model, span, 20.0, initial_extension=extension, samples=samples)
    ref = _solve_ivp_reference(model, span, extension, samples)
    assert run.evaluations == ref.evaluations
    for name in ("position", "speed"):
        a, b = getattr(run, name), getattr(ref, name)
        assert np.abs(a - b).max() <= 1e-9 * np.abs(b).max(), name
    # The force is the draft gear's stiffness times a difference of extensions (mm): it magnifies
    # their round-off (measured 2.5e-8 of the peak for 20 cars).
    assert np.abs(run.coupler_force - ref.coupler_force).max() <= 1e-7 * np.abs(ref.coupler_force).max()
    assert (run.peak.coupler, run.peak.time, run.peak.kind) == (
        ref.peak.coupler,
        ref.peak.time,
        ref.peak.kind,
    )
    assert run.peak.force == pytest.approx(ref.peak.force, rel=1e-9)


def test_compiled_rk45_stops_the_train_as_solve_ivp_does():
    model = train.braking_model(20, 2)
    extension = model.gear.slack / 2
    run = train.simulate(model, 60.0, 20.0, initial_extension=extension, samples=601)
    ref = _solve_ivp_reference(model, 60.0, extension, 601)
    assert run.evaluations == pytest.approx(ref.evaluations, rel=0.01)  # 4058 against 4082
    assert (run.peak.coupler, run.peak.time, run.peak.kind) == (
        ref.peak.coupler,
        ref.peak.time,
        ref.peak.kind,
    )
    assert run.peak.force == pytest.approx(ref.peak.force, rel=1e-9)
    assert run.stop_time() == ref.stop_time() is not None


def test_a_run_in_chunks_takes_the_steps_of_one_run(monkeypatch):
    # The progress bar moves between chunks of steps; a chunk resumes exactly where the last stopped.
    from raildyn.train import longitudinal

    model = train.braking_model(10, 1)
    whole = train.simulate(model, 20.0, 20.0, samples=201)
    monkeypatch.setattr(longitudinal, "_CHUNK", 7)
    pieces = train.simulate(model, 20.0, 20.0, samples=201, progress=True)
    assert pieces.evaluations == whole.evaluations
    np.testing.assert_array_equal(pieces.speed, whole.speed)
    np.testing.assert_array_equal(pieces.coupler_force, whole.coupler_force)


def test_other_methods_run_through_solve_ivp():
    from scipy.integrate import solve_ivp

    model = train.braking_model(10, 1)
    run = train.simulate(model, 20.0, 20.0, samples=201, method="DOP853")
    n = model.size
    atol = np.r_[1e-3, np.full(n - 1, 1e-6), np.full(n, 1e-5)]
    t_eval = np.linspace(0.0, 20.0, 201)
    ref = solve_ivp(model.rhs, (0.0, 20.0), model.initial_state(20.0), "DOP853", t_eval, rtol=1e-7, atol=atol)
    assert run.evaluations == ref.nfev
    np.testing.assert_array_equal(run.speed, ref.y[n:])


def test_simulation_converges_with_tolerance():
    # The default rtol against one 100× tighter: peak coupler force within 0.5 %.
    model = train.braking_model(20, 1)
    a = train.simulate(model, 20.0, 20.0, initial_extension=0.0125, samples=4001)
    b = train.simulate(model, 20.0, 20.0, initial_extension=0.0125, samples=4001, rtol=1e-9)
    assert a.peak.force == pytest.approx(b.peak.force, rel=5e-3)
    assert a.peak.coupler == b.peak.coupler


def test_energy_lost_per_hysteresis_loop_is_loop_area():
    # Two free wagons meet at 1 m/s at the edge of a wide gap; after they part (and before the
    # gap closes on the other side) the lost kinetic energy must equal the area of the
    # force–deflection loop the coupler traced.
    gear = train.DraftGear(slack=0.2)
    consist = train.make_consist("2 loaded hopper")
    model = train.TrainModel(consist, gear=gear, resistance=False)
    y0 = np.r_[0.0, -0.098, -0.5, 0.5]  # the rear wagon catches up with the front one
    run = _run_from(model, y0, 0.5, samples=20001)
    m = consist.mass
    lost = 0.5 * m @ run.speed[:, 0] ** 2 - 0.5 * m @ run.speed[:, -1] ** 2
    delta = run.position[0] - run.position[1] - consist.length.mean()
    area = np.trapezoid(run.coupler_force[0], delta)  # work done on the gear over the loop
    assert lost == pytest.approx(area, rel=1e-4)  # trapezoid on 20 001 points, error ~1e-6
    # Against the slow-loop closed form (k_l − k_u) U²/2 at the largest deflection: the tanh
    # blend of the branches over 0.02 m/s (of a 1 m/s impact) shifts it by a few per cent.
    u_max = -delta.min() - 0.1
    assert lost == pytest.approx(gear.loop_energy(u_max), rel=0.05)
    # Restitution of the two branches: relative speed after / before = sqrt(k_u/k_l), to the same 5 %.
    ratio = abs(run.speed[0, -1] - run.speed[1, -1]) / 1.0
    assert ratio == pytest.approx(np.sqrt(gear.unloading_stiffness / gear.loading_stiffness), rel=0.05)


def test_static_loop_area_matches_loop_energy():
    gear = train.DraftGear()
    loop = gear.static_loop(0.06, points=2001)
    u, f = loop.deflection, loop.force
    area = 0.5 * abs(np.dot(u, np.roll(f, -1)) - np.dot(f, np.roll(u, -1)))  # shoelace
    assert area == pytest.approx(gear.loop_energy(0.06), rel=1e-9)


def test_slack_blend_error_is_bounded_and_zero_inside_gap():
    gear = train.DraftGear(slack=0.02, smoothing=0.001)
    inside = np.linspace(-0.009, 0.009, 101)
    assert np.all(gear.force(inside, np.zeros_like(inside)) == 0.0)
    d = np.linspace(0.0, 0.05, 5001)
    exact = gear.unloading_stiffness * np.maximum(d - 0.01, 0.0)
    smooth = gear.force(d, -np.ones_like(d))  # firmly on the unloading branch
    assert np.abs(smooth - exact).max() <= gear.unloading_stiffness * gear.smoothing / 4 * (1 + 1e-9)


# --- lateral and vertical ------------------------------------------------------------------------


def test_string_lining_tension_on_curve():
    consist = train.make_consist("3 loaded hopper")
    radius, force = 150.0, 400e3
    effects = train.coupler_effects(consist, [force, force], curvature=1 / radius)
    theta = HOPPER.length / (2 * radius)  # the track turns L/(2R) between car centre and joint
    # Equal tensions at both ends: each truck of the middle car carries F sin θ, inward.
    np.testing.assert_allclose(effects.lateral_force[1], -force * np.sin(theta), rtol=1e-12)
    np.testing.assert_allclose(effects.l_over_v[1], force * np.sin(theta) / (HOPPER.mass * GRAVITY / 4))
    # A string under tension T on a circle carries T/R per unit length: the middle car, T L/R.
    assert -effects.lateral_force[1].sum() == pytest.approx(force * HOPPER.length / radius, rel=1e-3)
    assert list(effects.mode) == ["string-lining"] * 2
    buff = train.coupler_effects(consist, [-force, -force], curvature=1 / radius)
    assert list(buff.mode) == ["jack-knifing"] * 2
    assert np.all(buff.lateral_force[1] > 0)  # pushed toward the outside


def test_unequal_end_forces_go_mostly_to_the_near_truck():
    consist = train.make_consist("3 loaded hopper")
    e = train.coupler_effects(consist, [400e3, 0.0], curvature=1 / 200)
    # Car 0 has only its rear coupler loaded: beam on two supports.
    y = -400e3 * np.sin(HOPPER.length / 400)
    lever = HOPPER.length / HOPPER.truck_centres
    np.testing.assert_allclose(e.lateral_force[0], [0.5 * y * (1 - lever), 0.5 * y * (1 + lever)])
    assert e.lateral_force[0].sum() == pytest.approx(y)


def test_vertical_unloading_in_sags_and_crests():
    consist = train.make_consist("3 loaded hopper")
    sag = train.coupler_effects(consist, [300e3, 300e3], vertical_curvature=1 / 2000)
    crest = train.coupler_effects(consist, [-300e3, -300e3], vertical_curvature=-1 / 2000)
    assert np.all(sag.unloading[1] > 0) and np.allclose(sag.unloading, crest.unloading)
    expected = 300e3 * np.sin(HOPPER.length / 4000) / (HOPPER.mass * GRAVITY / 2)
    np.testing.assert_allclose(sag.unloading[1], expected)


# --- tier 3: properties --------------------------------------------------------------------------


@settings(deadline=None, max_examples=50)
@given(
    st.floats(-0.15, 0.15, allow_nan=False),
    st.floats(-2.0, 2.0, allow_nan=False),
    st.one_of(st.just(0.0), st.floats(0.003, 0.08)),
)
def test_coupler_force_is_odd_and_between_branches(delta, rate, slack):
    gear = train.DraftGear(slack=slack, smoothing=min(0.001, 0.4 * slack) if slack > 0 else 0.001)
    f = gear.force(delta, rate)
    assert gear.force(-delta, -rate) == pytest.approx(-f, abs=1e-6)
    u = gear.deflection(delta)
    solid = gear.solid_stiffness * max(u - gear.travel, 0.0)
    lo = gear.unloading_stiffness * u + solid
    hi = gear.loading_stiffness * u + solid
    assert lo * (1 - 1e-12) <= abs(f) <= hi * (1 + 1e-12)
    assert f * delta >= 0  # a coupler never pushes when stretched or pulls when compressed


@settings(deadline=None, max_examples=50)
@given(st.integers(1, 40), st.floats(0.0, 30.0), st.floats(0.0, 8.0))
def test_quasi_static_front_and_rear_balance(cars, speed, notch):
    model = dataclasses.replace(_steady_model(cars=cars), notch=notch)
    qs = model.quasi_static(speed)
    m = model.consist.mass
    # The last coupler carries what the last vehicle needs: its own force minus m a.
    assert qs.coupler_force[-1] == pytest.approx(
        -(qs.external_force[-1] - m[-1] * qs.acceleration), rel=1e-9, abs=1e-6
    )


# --- bad input -----------------------------------------------------------------------------------


def test_bad_input():
    with pytest.raises(ValueError, match="mass"):
        dataclasses.replace(HOPPER, mass=-1.0)
    with pytest.raises(ValueError, match="count must be >= 1"):
        train.make_consist("0 loaded hopper")
    with pytest.raises(ValueError, match="cars"):
        train.braking_model(cars=0)
    with pytest.raises(ValueError, match="vehicles must hold 1 to 1000 vehicles, got 0"):
        train.Consist(())
    with pytest.raises(ValueError, match="unknown vehicle type 'tank car'"):
        train.make_consist("2 SD40-2 + 10 tank car")
    with pytest.raises(ValueError, match="form"):
        train.davis_resistance(10.0, 1e5, 4, 9.0, form="newer")
    with pytest.raises(ValueError, match="mass"):
        train.davis_resistance(10.0, -1e5, 4, 9.0)
    with pytest.raises(ValueError, match="unloading_stiffness"):
        train.DraftGear(loading_stiffness=1e6, unloading_stiffness=2e6)
    with pytest.raises(ValueError, match="propagation_speed"):
        train.AirBrake(propagation_speed=0.0)
    with pytest.raises(ValueError, match="notch"):
        train.tractive_effort(5.0, 9, 1e5, 1e6)
    with pytest.raises(ValueError, match="positions"):
        train.Route((0.0, 0.0), (0.0, 0.01))
    with pytest.raises(ValueError, match="curvature"):
        train.coupler_angles(train.make_consist("3 loaded hopper"), [0.01])
    with pytest.raises(ValueError, match="duration"):
        train.simulate(train.braking_model(2, 1), -1.0, 10.0)


# --- regressions and the shape of the API (issue 14) -------------------------------------------


@pytest.mark.parametrize(
    "state",
    [np.zeros(3), np.zeros(205), np.zeros((3, 4)), np.zeros((204, 2, 2)), np.zeros(())],
    ids=["short", "long", "short batch", "3-D", "scalar"],
)
def test_rhs_refuses_a_state_of_the_wrong_shape(state):
    # The compiled kernel read past the end of a 3-entry state and returned 204 numbers that
    # changed from call to call. The shape is now checked before any compiled code runs.
    model = train.braking_model(100, 2)
    for rhs in (model.rhs, model.rhs_numpy):
        with pytest.raises(ValueError, match=r"state y must have shape \(204") as info:
            rhs(1.0, state)
        assert str(np.shape(state)) in str(info.value)


def test_rhs_refuses_a_non_finite_state():
    model = train.braking_model(10, 1)
    y = model.initial_state(20.0)
    y[3] = np.nan
    with pytest.raises(ValueError, match="state y must contain only finite numbers"):
        model.rhs(0.0, y)
    with pytest.raises(ValueError, match="state y must contain only finite numbers"):
        model.rhs(0.0, np.column_stack([model.initial_state(20.0), y]))
    with pytest.raises(ValueError, match="t must be a finite number"):
        model.rhs(np.inf, model.initial_state(20.0))


def test_rhs_of_a_right_state_is_repeatable():
    model = train.braking_model(100, 2)
    y = model.initial_state(20.0, 0.01)
    first = model.rhs(1.0, y)
    assert first.shape == (204,)
    np.testing.assert_array_equal(model.rhs(1.0, y), first)
    np.testing.assert_array_equal(model.rhs(1.0, list(y)), first)  # a list is converted


def _overflowing(model, row=None, segment_curvature=None):
    """``model`` with a force that overflows, set in its compiled tables.

    The public constructors refuse values that make a force overflow (a curvature within
    ±0.1 1/m, speeds within ±200 m/s), so the solver's failure path is reached by writing
    one into the tables the compiled right-hand side reads.
    """
    from raildyn.train import _kernel

    table, _, route = model._packed
    if row is not None:
        table[getattr(_kernel, row)] = 1e308
    if segment_curvature is not None:
        route[2, 1] = segment_curvature
    return model


def test_simulation_running_into_an_overflow_raises_solver_error_at_that_time():
    # Beyond 200 m the route has a curvature (1e308 /m) whose resistance overflows to infinity.
    # Trial steps that overshoot are rejected; when the front vehicle's centre gets there the
    # step shrinks to nothing and the run stops with SolverError at the time it arrived.
    from raildyn.errors import SolverError

    route = train.Route((0.0, 200.0), (0.0, 0.0), curvature=(0.0, 0.01))
    model = _overflowing(train.braking_model(5, 1, route=route), segment_curvature=1e308)
    with pytest.raises(SolverError, match="not finite") as info:
        train.simulate(model, 20.0, 20.0, samples=201)
    err = info.value
    assert not hasattr(train.TrainRun, "success")
    # The same train on level track, identical until it reaches 200 m, sampled every 1 ms.
    level = train.simulate(train.braking_model(5, 1), 20.0, 20.0, samples=20001)
    arrival = np.interp(err.time, level.t, level.position[0])
    # Where it stopped, to within what it travels in 1 ms (the run's step there is far smaller).
    assert arrival == pytest.approx(200.0, abs=0.02)
    assert err.partial.t[-1] <= err.time < err.partial.t[-1] + 0.1  # the last output before the stop
    np.testing.assert_allclose(err.partial.speed, level.speed[:, : err.partial.t.size * 100 : 100], rtol=1e-5)


def test_a_run_starting_at_an_overflow_fails_as_solve_ivp_does(monkeypatch):
    # The front starts 1 mm before a curvature whose resistance overflows: the first step's trial
    # evaluation already meets it. An infinite force there would make the compiled first step zero;
    # as NaN (what solve_ivp is given) it is solve_ivp's, and both approach the overflow in the same
    # shrinking steps until the evaluation budget (made small here) runs out at the same time.
    import dataclasses

    from raildyn.errors import SolverError
    from raildyn.train import longitudinal

    monkeypatch.setattr(longitudinal, "_MAX_EVALUATIONS", 3000)
    route = train.Route((0.0, 200.0), (0.0, 0.0), curvature=(0.0, 0.01))
    model = train.braking_model(5, 1, route=route)
    ahead = 200.0 - 1e-3 - model.initial_state(20.0)[0]
    model = _overflowing(
        dataclasses.replace(model, front_start=model.front_start + ahead), segment_curvature=1e308
    )
    with pytest.raises(
        SolverError, match="more than 3000 evaluations of the right-hand side.*not finite"
    ) as compiled:
        train.simulate(model, 2.0, 20.0)
    n = model.size
    atol = np.r_[1e-3, np.full(n - 1, 1e-6), np.full(n, 1e-5)]
    with pytest.raises(SolverError, match="more than 3000") as ref:
        longitudinal._integrate_solve_ivp(
            model, model.initial_state(20.0), np.linspace(0.0, 2.0, 601), 1e-7, atol, "RK45", np.inf, None
        )
    assert compiled.value.time == pytest.approx(ref.value.time, rel=1e-9)
    assert compiled.value.time == pytest.approx(5e-5, rel=1e-4)  # 1 mm at 20 m/s, where the overflow is


def test_simulation_solver_stop_raises_solver_error():
    # A largest step below the spacing of floating-point numbers: solve_ivp cannot take one.
    from raildyn.errors import SolverError

    with pytest.raises(SolverError, match="step size is less than spacing") as info:
        train.simulate(train.braking_model(2, 1), 1.0, 20.0, max_step=1e-323)
    assert info.value.time == pytest.approx(0.0, abs=1e-300)
    assert info.value.partial is None or info.value.partial.t[-1] == 0.0
    with pytest.raises(SolverError, match="not finite at the start") as info:
        train.simulate(_overflowing(train.braking_model(2, 1), row="ROW_A2"), 1.0, 20.0)  # a2 v² overflows
    assert info.value.time == 0.0 and info.value.step == 0


def test_simulate_checks_its_tolerances_and_method():
    model = train.braking_model(2, 1)
    with pytest.raises(ValueError, match="atol"):
        train.simulate(model, 1.0, 10.0, atol=0.0)  # solve_ivp hangs on zero states with atol = 0
    with pytest.raises(ValueError, match=r"atol must have shape \(6"):
        train.simulate(model, 1.0, 10.0, atol=np.ones(5))
    with pytest.raises(ValueError, match="rtol"):
        train.simulate(model, 1.0, 10.0, rtol=1e-20)
    with pytest.raises(ValueError, match="method must be one of"):
        train.simulate(model, 1.0, 10.0, method="Euler")
    with pytest.raises(ValueError, match="max_step"):
        train.simulate(model, 1.0, 10.0, max_step=0.0)
    with pytest.raises(TypeError, match="gear must be a DraftGear"):
        train.TrainModel(model.consist, gear=0.025)


def test_dynamic_brake_corner_speeds_have_one_definition(monkeypatch):
    # The compiled kernel reads the corner speeds that forces.py defines, through the model:
    # change them there and the kernel, the numpy reference and the law all move together.
    from raildyn.train import _kernel, forces

    assert not hasattr(_kernel, "DYNAMIC_PEAK") and not hasattr(_kernel, "DYNAMIC_FADE")
    assert (forces.DYNAMIC_BRAKE_PEAK_SPEED, forces.DYNAMIC_BRAKE_FADE_SPEED) == (8.0, 20.0)
    monkeypatch.setattr(forces, "DYNAMIC_BRAKE_PEAK_SPEED", 5.0)
    monkeypatch.setattr(forces, "DYNAMIC_BRAKE_FADE_SPEED", 12.0)
    model = dataclasses.replace(
        train.braking_model(3, 1), air_brake=None, dynamic_brake=1.0, resistance=False, gear=train.DraftGear()
    )
    for speed in (4.0, 6.0, 15.0):  # below the new peak, between the two peaks, above the new fade
        y = model.initial_state(speed)
        fast, ref = model.rhs(0.0, y), model.rhs_numpy(0.0, y)
        np.testing.assert_allclose(fast, ref, rtol=1e-12)
        expected = train.dynamic_brake_force(
            speed, 1.0, LOCO.max_dynamic_brake, peak_speed=5.0, fade_speed=12.0
        )
        # The locomotive (vehicle 0) alone carries the brake; couplers centred, no force in them.
        assert -fast[model.size] * LOCO.mass == pytest.approx(expected, rel=1e-12)


def test_coupler_offsets_are_the_joints_between_vehicles():
    consist = train.make_consist("2 SD40-2 + 3 loaded hopper + 1 empty hopper")
    offsets = consist.coupler_offsets
    assert offsets.shape == (consist.couplers,)
    centres, half = consist.centre_offsets, 0.5 * consist.length
    np.testing.assert_allclose(offsets, centres[:-1] + half[:-1], rtol=1e-15)
    np.testing.assert_allclose(offsets, centres[1:] - half[1:], rtol=1e-15)
    assert offsets[0] == pytest.approx(LOCO.length)
    model = train.braking_model(4, 2)
    np.testing.assert_array_equal(model.quasi_static(10.0).coupler_offsets, model.consist.coupler_offsets)
    run = train.simulate(model, 1.0, 10.0, samples=3)
    np.testing.assert_array_equal(run.coupler_offsets, model.consist.coupler_offsets)


def test_frozen_dataclasses_declare_every_attribute():
    # No hidden attributes: whatever an instance holds is a declared field.
    model = train.braking_model(3, 1, route=train.Route((0.0, 50.0), (0.0, 0.01)))
    run = train.simulate(model, 2.0, 10.0, samples=5)
    objects = [model, model.consist, model.route, model.gear, model.air_brake, run, run.peak]
    objects += [model.quasi_static(5.0), model.gear.static_loop(0.05)]
    objects += [train.coupler_effects(model.consist, [1e5, 1e5, 1e5], curvature=0.002)]
    for obj in objects:
        assert dataclasses.is_dataclass(obj) and obj.__dataclass_params__.frozen, type(obj).__name__
        declared = {f.name for f in dataclasses.fields(obj)}
        assert set(vars(obj)) <= declared, (type(obj).__name__, set(vars(obj)) - declared)
    assert not hasattr(train.Consist, "__getattr__") or train.Consist.__getattr__ is object.__getattr__


def test_peak_is_a_result_with_its_place_and_kind():
    run = train.simulate(train.braking_model(10, 1), 20.0, 15.0, initial_extension=0.0125, samples=401)
    peak = run.peak
    j, k = np.unravel_index(np.argmax(np.abs(run.coupler_force)), run.coupler_force.shape)
    assert (peak.force, peak.coupler, peak.time) == (run.coupler_force[j, k], j, run.t[k])
    assert peak.offset == run.coupler_offsets[j]
    assert peak.kind == ("buff" if peak.force < 0 else "draft")
    assert train.CouplerPeak(1.0, 0, 1.0, 0.0).kind == "draft"
    assert train.CouplerPeak(-1.0, 0, 1.0, 0.0).kind == "buff"


def test_stop_time_is_the_first_sample_below_the_threshold_or_none():
    run = train.simulate(train.braking_model(10, 1), 60.0, 15.0, samples=601)
    stop = run.stop_time()
    k = int(np.searchsorted(run.t, stop))
    assert run.t[k] == stop and abs(run.speed[0, k]) < 0.01 <= abs(run.speed[0, k - 1])
    assert run.stop_time(vehicle=-1, threshold=0.5) < stop
    # A run that has not stopped: None, not the first time of the run (which argmax would give).
    assert train.simulate(train.braking_model(10, 1), 5.0, 15.0, samples=51).stop_time() is None
    with pytest.raises(ValueError, match="vehicle"):
        run.stop_time(vehicle=11)
    with pytest.raises(ValueError, match="threshold"):
        run.stop_time(threshold=0.0)


def test_balancing_speed_is_where_traction_meets_resistance_and_grade():
    consist = train.make_consist("2 SD40-2 + 60 loaded hopper")
    climb = train.TrainModel(consist, route=train.Route((0.0,), (0.01,)), notch=8)
    v = climb.balancing_speed()
    assert abs(climb.quasi_static(v).acceleration) < 1e-9
    # Independently: two locomotives' effort equals the Davis and grade resistance of the train.
    pull = 2 * train.tractive_effort(v, 8, LOCO.max_tractive_effort, LOCO.rail_power)
    resist = sum(
        train.davis_resistance(v, u.mass, u.axles, u.frontal_area, kind=u.kind) for u in consist.vehicles
    ) + float(train.grade_force(consist.mass, 0.01).sum())
    # Brent's method stops within 1e-9 m/s; the slope of the net force is ~1e5 N per m/s.
    assert pull == pytest.approx(resist, rel=1e-7)
    with pytest.raises(ValueError, match="bracket the balancing speed"):
        climb.balancing_speed(20.0, 30.0)


def test_limiting_coupler_force_gives_the_l_over_v_asked_for():
    hoppers = train.make_consist("3 loaded hopper")
    f = train.limiting_coupler_force(hoppers, 1 / 150, 0.5)
    theta = train.coupler_angles(hoppers, 1 / 150)[0]
    assert f == pytest.approx(0.5 * HOPPER.mass * GRAVITY / 4 / np.sin(theta), rel=1e-12)
    check = train.coupler_effects(hoppers, [f, f], curvature=1 / 150).l_over_v[1]
    assert check.max() == pytest.approx(0.5, rel=1e-12)
    # An empty hopper between two loaded ones: the same geometry, a lighter car.
    mixed = train.make_consist("loaded hopper + empty hopper + loaded hopper")
    empty = train.VEHICLES["empty hopper"]
    assert train.limiting_coupler_force(mixed, 1 / 150, 0.5) == pytest.approx(f * empty.mass / HOPPER.mass)
    with pytest.raises(ValueError, match="curvature"):
        train.limiting_coupler_force(hoppers, 0.0, 0.5)
    with pytest.raises(ValueError, match="l_over_v"):
        train.limiting_coupler_force(hoppers, 0.01, -0.5)


def test_run_envelope_plot_draws_and_moves_the_same_artists():
    import matplotlib.pyplot as plt

    model = train.braking_model(10, 1)
    a = train.simulate(model, 10.0, 15.0, initial_extension=0.0125, samples=101)
    b = train.simulate(model, 10.0, 10.0, initial_extension=-0.0125, samples=101)
    fig, ax = plt.subplots()
    artists = a.plot_envelope(ax)
    assert set(artists) == {"draft", "buff", "peak"}
    np.testing.assert_array_equal(artists["draft"].get_xdata(), model.consist.coupler_offsets)
    np.testing.assert_array_equal(artists["draft"].get_ydata(), a.max_tension / 1e3)
    np.testing.assert_array_equal(artists["buff"].get_ydata(), -a.max_compression / 1e3)
    lines = len(ax.lines)
    moved = b.plot_envelope(artists=artists)
    assert moved is artists and len(ax.lines) == lines  # updated in place, nothing new drawn
    np.testing.assert_array_equal(artists["buff"].get_ydata(), -b.max_compression / 1e3)
    assert artists["peak"].get_xdata()[0] == b.peak.offset
    assert artists["peak"].get_ydata()[0] == b.peak.force / 1e3
    wave = a.plot_wave(limit=500.0)
    assert wave["mesh"].get_clim() == (-500.0, 500.0)
    plt.close("all")


def test_quasi_static_and_loop_plots_draw_their_data():
    import matplotlib.pyplot as plt

    qs = train.braking_model(10, 2).quasi_static(10.0)
    line = qs.plot(label="level")["line"]
    np.testing.assert_array_equal(line.get_xdata(), qs.coupler_offsets)
    np.testing.assert_array_equal(line.get_ydata(), qs.coupler_force / 1e3)
    loop = train.DraftGear().static_loop(0.06)
    assert loop.energy == train.DraftGear().loop_energy(0.06)
    drawn = loop.plot()["line"]
    np.testing.assert_array_equal(drawn.get_xdata(), 1e3 * loop.deflection)
    plt.close("all")


def test_run_from_states_checks_its_input():
    model = train.braking_model(2, 1)
    y = np.column_stack([model.initial_state(10.0)] * 3)
    run = model.run_from_states([0.0, 1.0, 2.0], y, 7)
    assert run.evaluations == 7 and run.speed.shape == (3, 3)
    with pytest.raises(ValueError, match=r"y must have shape \(6, 2\)"):
        model.run_from_states([0.0, 1.0], y)
    with pytest.raises(ValueError, match="strictly increasing"):
        model.run_from_states([0.0, 2.0, 1.0], y)


# --- issue 15: every public call refuses bad input clearly -------------------------------------


@pytest.mark.parametrize(
    "settings",
    [{"atol": float("nan")}, {"atol": 0.0}, {"atol": 1e-300}, {"rtol": float("inf")}, {"rtol": 0.0}],
    ids=["atol nan", "atol 0", "atol tiny", "rtol inf", "rtol 0"],
)
def test_simulate_refuses_tolerances_that_would_run_forever(settings):
    # atol = NaN ran forever and atol = 0 or rtol = inf ran past 15 s: now refused up front.
    (name,) = settings
    with pytest.raises(ValueError, match=rf"^{name} must"):
        train.simulate(train.braking_model(3, 1), 2.0, 15.0, **settings)


def test_simulate_refuses_a_huge_speed_duration_or_sample_count_naming_it():
    model = train.braking_model(3, 1)
    # 1e300 m/s ended in an IndexError while the failure message was written.
    with pytest.raises(ValueError, match=r"initial_speed must be in \[-200.0, 200.0\], got 1e\+300"):
        train.simulate(model, 2.0, 1e300)
    with pytest.raises(ValueError, match="initial_extension must be in"):
        train.simulate(model, 2.0, 15.0, initial_extension=5.0)
    with pytest.raises(ValueError, match="duration must be in"):
        train.simulate(model, 1e300, 15.0)  # ran until the fuzz test's timer stopped it
    with pytest.raises(ValueError, match="samples must be an integer in"):
        train.simulate(model, 2.0, 15.0, samples=10**12)  # a MemoryError before
    with pytest.raises(TypeError, match="method must be a string"):
        train.simulate(model, 2.0, 15.0, method=None)


def test_simulate_is_bounded_by_its_evaluation_budget(monkeypatch):
    from raildyn.errors import SolverError
    from raildyn.train import longitudinal

    monkeypatch.setattr(longitudinal, "_MAX_EVALUATIONS", 50)
    with pytest.raises(SolverError, match="more than 50 evaluations of the right-hand side") as info:
        train.simulate(train.braking_model(3, 1), 2.0, 15.0, max_step=1e-3)
    assert 0.0 < info.value.time < 2.0


def test_coupler_angles_refuse_a_curve_no_vehicle_fits_on():
    consist = train.make_consist("3 loaded hopper")
    # κ = 0.57 1/m gave angles of 9.28 rad; a 16 m hopper cannot sit on a curve of 1.75 m radius.
    with pytest.raises(ValueError, match=r"curvature must be at most 2/L = 0\.1238 1/m") as info:
        train.coupler_angles(consist, 0.57)
    assert "longer than the curve's diameter" in str(info.value)
    assert np.abs(train.coupler_angles(consist, 2 / HOPPER.length)).max() <= 1.0  # the limit itself
    with pytest.raises(ValueError, match="vertical_curvature must be at most"):
        train.coupler_effects(consist, [1e5, 1e5], vertical_curvature=-1.0)


def test_route_grade_and_curvature_have_a_stated_limit():
    with pytest.raises(ValueError, match=r"grade must be within ±0.15 "):
        train.Route((0.0, 100.0), (0.0, 10.0))  # a 1000 % grade was accepted
    with pytest.raises(ValueError, match=r"curvature must be within ±0.1 1/m"):
        train.Route((0.0,), (0.0,), curvature=(0.5,))
    with pytest.raises(TypeError, match="grade must be a sequence"):
        train.Route((0.0,), None)
    with pytest.raises(ValueError, match=r"grade must be within ±0.15 "):
        train.grade_force(1e5, -0.2)
    assert train.Route((0.0,), (-0.15,)).grade_at(5.0) == -0.15


def test_davis_resistance_counts_whole_axles():
    with pytest.raises(ValueError, match="axles must be whole numbers, got 2.5"):
        train.davis_resistance(20.0, 1e5, 2.5, 9.0)
    assert train.davis_resistance(20.0, 1e5, 4.0, 9.0) == train.davis_resistance(20.0, 1e5, 4, 9.0)
    with pytest.raises(ValueError, match=r"speed must be within ±447"):
        train.davis_resistance(500.0, 143.0, 4, 88.0, units="US")


def test_make_consist_has_a_stated_size_limit_and_names_its_description():
    with pytest.raises(ValueError, match="description asks for more than 1000 vehicles"):
        train.make_consist("10000000 loaded hopper")  # built ten million vehicles before
    assert len(train.make_consist("2 SD40-2 + 998 loaded hopper")) == 1000
    with pytest.raises(ValueError, match="description asks for more than 1000"):
        train.make_consist("2 SD40-2 + 999 loaded hopper")
    with pytest.raises(ValueError, match="description names an unknown vehicle type 'tank car'"):
        train.make_consist("tank car")
    with pytest.raises(TypeError, match="description must be a string"):
        train.make_consist(None)
    with pytest.raises(TypeError, match="vehicles must be a dict"):
        train.make_consist("loaded hopper", vehicles="abc")
    with pytest.raises(ValueError, match="cars must be an integer in"):
        train.braking_model(10**12, 1)
    with pytest.raises(ValueError, match="locomotives must be an integer in"):
        train.braking_model(999, 2)


def test_user_built_and_result_classes_check_their_fields():
    with pytest.raises(ValueError, match="davis_form must be one of"):
        train.TrainModel(train.make_consist("2 loaded hopper"), davis_form="newer")  # blamed "form"
    with pytest.raises(TypeError, match="description must be a string"):
        train.Consist((HOPPER,), None)
    with pytest.raises(ValueError, match="coupler_force must have shape"):
        train.TrainRun(np.zeros(2), np.zeros((2, 2)), np.zeros((2, 2)), np.zeros((2, 2)), np.zeros(1), 0)
    with pytest.raises(TypeError, match="evaluations must be an integer"):
        train.TrainRun(np.zeros(2), np.zeros((2, 2)), np.zeros((2, 2)), np.zeros((1, 2)), np.zeros(1), 1.5)
    with pytest.raises(ValueError, match="force must be a finite number"):
        train.CouplerPeak(float("nan"), 0, 1.0, 0.0)
    with pytest.raises(ValueError, match="extension must be within ±1.0 m"):
        train.DraftGear().force(1e300, 0.0)  # overflowed to inf
    with pytest.raises(ValueError, match="x \\(the coupler extensions it gives\\) must be within"):
        train.braking_model(2, 1).coupler_forces([0.0, -1e300, -2e300], np.zeros(3))
    with pytest.raises(ValueError, match=r"low must be in \[0.0, 200.0\]"):
        train.braking_model(2, 1).balancing_speed(1e300)  # blamed high
    with pytest.raises(ValueError, match="low must be < high"):
        train.braking_model(2, 1).balancing_speed(30.0, 20.0)
