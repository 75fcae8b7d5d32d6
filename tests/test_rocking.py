"""The rocking freight car with wheels that lift (raildyn.vehicles.rocking, rocking_runs)."""

import numpy as np
import pytest
from widget_helpers import widgets_of

from raildyn.constants import GRAVITY
from raildyn.errors import SolverError
from raildyn.suspension import coulomb_friction
from raildyn.vehicles import RockingFreightCar, VerticalFreightCar, rocking_run, rocking_runs, rocking_sweep
from raildyn.vehicles import _rocking_kernel as kernel

CAR = RockingFreightCar()
ZERO = np.zeros(18)


def _free_march(car, q0, v0, dt, duration):
    """The compiled march on level track from (q0, v0), every step's state kept: (t, q, v, element table)."""
    mass, dofs, ei, ef, _ = car._tables()
    steps = int(round(duration / dt))
    table = np.zeros((4, 11))  # level rails
    hist = np.zeros((steps + 1, 16))
    roll = np.zeros(steps + 1)
    state = np.zeros((steps + 1, 36))
    status = kernel.march(
        mass,
        dofs,
        ei,
        ef,
        car.velocity_scale,
        10.0,
        np.array([0.0, 1.7, 12.4, 14.1]),
        11.9,
        1.19,
        table,
        dt,
        steps,
        1,
        steps + 1,
        q0,
        v0,
        np.arange(16),
        2,
        hist,
        roll,
        state,
        np.zeros((2, 17)),
        np.zeros(19, dtype=np.int64),
    )
    assert status == -1
    return np.arange(steps + 1) * dt, state[:, :18], state[:, 18:], hist


def _energy(car, q, v):
    """Kinetic energy plus every element's potential (springs, contacts, weights), J."""
    mass, _, ei, ef, _ = car._tables()
    _, _, delta = kernel.evaluate(car, q, v, np.zeros(8), np.zeros(8))
    P0, k = ef[:, kernel.PRELOAD], ef[:, kernel.STIFFNESS]
    one_sided = ei[:, kernel.KIND] == 1
    elastic = P0 + k * delta
    with np.errstate(divide="ignore", invalid="ignore"):
        contact = np.where(elastic > 0, elastic**2 / (2 * k), 0.0)
    U = np.where(one_sided, contact, P0 * delta + 0.5 * k * delta**2)
    return 0.5 * np.sum(mass * v * v) + U.sum()


def test_static_wheel_loads_sum_to_the_weight_and_are_equal_per_side():
    gen, element = CAR.forces(ZERO, ZERO)
    # the preloads balance the weights at rest: the generalized forces vanish to rounding of the
    # forces themselves (about 1e-16 of the weight)
    assert np.abs(gen).max() < 1e-12 * CAR.weight
    wheels = element[:8].reshape(4, 2)
    assert wheels.sum() == pytest.approx(CAR.weight, rel=1e-14)
    np.testing.assert_allclose(wheels[:, 0], wheels[:, 1], rtol=1e-14)
    np.testing.assert_allclose(wheels, CAR.static_wheel_load, rtol=1e-14)
    # the car's weight, counted part by part: body, two bolsters, four wheelsets
    c = CAR.car
    assert CAR.weight == pytest.approx(GRAVITY * (c.body_mass + 2 * 342.0 + 4 * 2004.0), rel=1e-12)
    # and the march on level track keeps it there (a preload out of balance would set it moving)
    run = rocking_run(CAR, 10.0, depth=0.0, cycles=4)
    assert run.peak_unloading < 1e-9
    np.testing.assert_allclose(run.wheel_loads, CAR.static_wheel_load, rtol=1e-9)
    assert run.lift_fraction == run.plate_lift_fraction == run.bearer_contact_fraction == 0.0


def test_linearisation_is_the_jacobian_of_the_force_law():
    # The analytic K (k g gᵀ + P₀ ∇²δ) against central differences of the kernel's law: agreement to
    # the differences' error, h² f''' ~ 1e-10 of K's scale at h = 1e-7 m.
    lin = CAR.linearized()
    h = 1e-7
    K = np.zeros((18, 18))
    for i in range(18):
        dq = np.zeros(18)
        dq[i] = h
        K[:, i] = -(CAR.forces(dq, ZERO)[0] - CAR.forces(-dq, ZERO)[0]) / (2 * h)
    assert np.abs(K - lin.K).max() < 1e-8 * np.abs(lin.K).max()
    np.testing.assert_allclose(lin.K, lin.K.T, atol=1e-9 * np.abs(lin.K).max())


def test_small_free_rocking_has_the_frequency_of_the_linearisation():
    # Free vibration from the rocking mode's shape, wedges and dampers off, small enough (0.1 mrad of
    # body roll) that no contact opens: the march's zero crossings against the eigenvalue. RK4's phase
    # error (ω Δt)⁴/120 ~ 1e-10 and the crossings' interpolation error (~1e-6) are far inside 1e-4.
    car = CAR.replace(car=CAR.car.replace(wedge_friction=0.0), contact_damping=0.0, track_damping=0.0)
    lin = car.linearized()
    w2, vec = np.linalg.eig(np.linalg.solve(lin.M, lin.K))
    f_lin = car.roll_frequency()
    k = int(np.argmin(np.abs(np.sqrt(np.abs(w2.real)) / (2 * np.pi) - f_lin)))
    shape = vec[:, k].real / vec[2, k].real * 1e-4
    t, q, v, hist = _free_march(car, shape, ZERO, 5e-4, 8.0)
    assert (hist[:, 8:12] > 0).all() and (hist[:, 12:16] == 0).all() and (hist[:, :8] > 0).all()
    roll = q[:, 2]
    i = np.flatnonzero(np.sign(roll[:-1]) != np.sign(roll[1:]))
    crossings = t[i] - roll[i] * (t[i + 1] - t[i]) / (roll[i + 1] - roll[i])
    f_march = (len(crossings) - 1) / (2 * (crossings[-1] - crossings[0]))
    assert f_march == pytest.approx(f_lin, rel=1e-4)


def test_rigid_trucks_give_the_body_only_model():
    # Stiff plates, bearers' rims, lateral nests and track (1e12 N/m), a 10 kg bolster and the plate at
    # the spring plane: the body sits on the nests alone and turns about the spring plane, as
    # VerticalFreightCar holds it. Its bounce 4k/m, pitch (4kl² − mgh)/(I_θ + mh²) and roll
    # (4kd² − mgh)/(I_φ + mh²) must appear among the model's frequencies; what is left of the trucks
    # moves them by the height offsets (1e-4 m of 1.5) and the stiffness ratios (~1e-5): 1e-4.
    body = VerticalFreightCar()
    stiff = 1e12
    car = RockingFreightCar(
        car=body,
        bolster_mass=10.0,
        bolster_roll_inertia=1.0,
        spring_plane_height=0.6,
        bolster_height=0.60005,
        centre_plate_height=0.6001,
        centre_plate_stiffness=stiff,
        plate_lateral_stiffness=stiff,
        nest_lateral_stiffness=stiff,
        track_stiffness=stiff,
    )
    f = car.natural_frequencies()
    ref = body.natural_frequencies()
    for name in ("bounce_hz", "pitch_hz", "roll_hz"):
        target = getattr(ref, name)
        assert np.min(np.abs(f - target)) / target < 3e-4, name
    assert car.roll_frequency() == pytest.approx(ref.roll_hz, rel=3e-4)
    # With the default trucks the laterally soft nests let the body sway: it rocks lower.
    assert CAR.roll_frequency() < 0.8 * ref.roll_hz


def test_plate_lifts_at_the_hand_computed_moment():
    # At the plate's lift-off both trucks' right edges carry the body's weight m g, the left edges
    # nothing and the side bearers are still open; the body's roll balance about its centre of gravity
    # then reads M = m g (r_p − (h_G − h_p) φ): the weight above the plate helps to lift it. The root
    # finder's tolerance (1e-7 of W a_r) bounds the error.
    M = CAR.plate_lift_moment()
    state = CAR.static_roll(M)
    assert (state.bearer_loads == 0).all()
    m = CAR.car.body_mass
    h = CAR.cg_height_above_rail - CAR.centre_plate_height
    hand = m * GRAVITY * (CAR.centre_plate_radius - h * state.body_roll)
    assert M == pytest.approx(hand, rel=1e-5)
    assert state.body_roll > 0 and M < m * GRAVITY * CAR.centre_plate_radius


def test_wheel_lifts_at_the_moment_balance_of_the_rigid_car():
    # On rigid trucks and track nothing leans, so the left wheels unload when the lateral force's moment
    # about the right rail, Σ m a_y h, equals the weight's, W a_r: a_y = g a_r / h̄ with h̄ the car's
    # centre of gravity above the rail (the car's moment balance about the rail).
    stiff = 1e9
    rigid = RockingFreightCar(
        car=VerticalFreightCar(nest_stiffness=stiff),
        side_bearer_gap=0.0,
        centre_plate_stiffness=stiff,
        side_bearer_stiffness=stiff,
        plate_lateral_stiffness=stiff,
        nest_lateral_stiffness=stiff,
        track_stiffness=stiff,
    )
    m_c, m_b, m_w = rigid.car.body_mass, rigid.bolster_mass, rigid.wheelset_mass
    h_bar = (
        m_c * rigid.cg_height_above_rail + 2 * m_b * rigid.bolster_height + 4 * m_w * rigid.wheel_radius
    ) / (m_c + 2 * m_b + 4 * m_w)
    hand = GRAVITY * rigid.half_rail_spacing / h_bar
    # at 1e9 N/m the joints still let the body lean by some 2 mrad, moving its centre of gravity, 2.1 m up,
    # 4 mm over the right rail: 0.5 % of a_r; 1 %
    a_lift = rigid.wheel_lift_acceleration()
    assert a_lift == pytest.approx(hand, rel=1e-2)
    state = rigid.static_roll(lateral_acceleration=0.999 * a_lift)
    assert state.wheel_loads[:, 0].max() < 0.01 * rigid.static_wheel_load
    # the flexible car leans over the right rail and lifts a wheel sooner
    soft = CAR.wheel_lift_acceleration()
    assert soft < 0.9 * CAR.half_rail_spacing * GRAVITY / h_bar
    state = CAR.static_roll(lateral_acceleration=0.999 * soft)
    assert (state.bearer_loads[:, 1] > 0).all() and (state.plate_loads[:, 0] == 0).all()


def test_energy_is_conserved_without_damping_and_only_falls_with_it():
    # A hard start (20 mrad of body roll, 20 mm of bounce) that lifts the plates and closes the bearers.
    # Without wedges and dampers the energy stays within the march's error, which the contacts' onsets,
    # met between steps, make first order in the step: 2e-4 of the energy put in at 0.02 ms, and at
    # least twice that at 0.05 ms (2.5 for a first-order error), so the drift is the step's, not the
    # law's. With wedges and dampers the energy never rises by more than that error.
    q0 = np.zeros(18)
    q0[2], q0[0] = 0.02, 0.02
    elastic = CAR.replace(car=CAR.car.replace(wedge_friction=0.0), contact_damping=0.0, track_damping=0.0)
    E_rest = _energy(elastic, ZERO, ZERO)
    drift = {}
    for dt in (5e-5, 2e-5):
        t, q, v, hist = _free_march(elastic, q0, ZERO, dt, 1.5)
        assert (hist[:, 8:12] == 0).any() and (hist[:, 12:16] > 0).any()  # plates lifted, bearers closed
        E = np.array([_energy(elastic, q[i], v[i]) for i in range(0, t.size, int(round(2.5e-3 / dt)))])
        put_in = E[0] - E_rest
        drift[dt] = np.abs(E - E[0]).max() / put_in
    assert put_in > 0
    assert drift[2e-5] < 2e-4
    assert drift[5e-5] > 2 * drift[2e-5]
    t, q, v, hist = _free_march(CAR, q0, ZERO, 2e-5, 1.5)
    E = np.array([_energy(CAR, q[i], v[i]) for i in range(0, t.size, 125)])
    assert np.diff(E).max() < 2e-4 * put_in
    assert E[-1] - E_rest < 0.2 * put_in  # and the wedges and contacts take most of it


def test_the_kernel_rubs_with_the_suspension_law():
    # Each nest's force less its spring is the wedges' F tanh(v/v_ε) of raildyn.suspension
    rate = np.linspace(-0.1, 0.1, 9)
    _, _, ei, ef, names = CAR._tables()
    nest = names.index("nest 1L")
    for r in rate:
        v = np.zeros(18)
        v[4] = -r  # the bolster going down closes the nest at r
        _, element = CAR.forces(ZERO, v)
        rub = element[nest] - ef[nest, kernel.PRELOAD]
        assert rub == pytest.approx(
            float(coulomb_friction(r, CAR.car.wedge_friction, velocity_scale=CAR.velocity_scale)), abs=1e-9
        )


def test_rocking_peaks_near_the_linear_resonance_and_lifts_wheels_there():
    sweep = rocking_sweep(CAR, np.array([20.0, 26.0, 28.0, 30.0, 34.0, 40.0]) / 3.6, cycles=12)
    V_res = CAR.roll_resonance_speed()
    # the friction-damped peak leans to lower speeds (the wedges stiffen the car at small amplitude
    # and let it go at large): within 15 % of f L
    assert abs(sweep.peak_speed - V_res) < 0.15 * V_res
    assert sweep.peak_unloading.max() == 1.0 and sweep.lift_fraction.max() > 0
    k = int(np.argmax(sweep.lift_fraction))
    assert sweep.plate_lift_fraction[k] > 0 and sweep.bearer_contact_fraction[k] > 0
    assert sweep.lift_fraction[0] == 0 and sweep.lift_fraction[-1] == 0
    run = sweep.runs[k]
    assert run.lift_distance == pytest.approx(run.lift_fraction * 11.9)
    assert run.side_loads.shape == (run.t.size, 2, 2)
    np.testing.assert_allclose(run.truck_loads.sum(axis=1), run.wheel_loads.sum(axis=(1, 2)))


def test_smoothing_and_step_do_not_move_the_answer():
    # v_ε = 0.02 (default) against 0.01 and the default step against half of it at the resonance: the
    # peak ΔQ/Q within 3 % (the smoothing's own share; the step's is far smaller)
    base = rocking_run(CAR, 30 / 3.6, cycles=12)
    fine = rocking_run(CAR.replace(velocity_scale=0.01), 30 / 3.6, cycles=12)
    half = rocking_run(CAR, 30 / 3.6, cycles=12, dt=0.0004)
    assert fine.peak_unloading == pytest.approx(base.peak_unloading, rel=0.03)
    assert half.peak_unloading == pytest.approx(base.peak_unloading, rel=0.005)


@pytest.mark.parametrize(
    "field, value",
    [
        ("side_bearer_gap", -0.001),
        ("centre_plate_radius", 0.0),
        ("centre_plate_radius", -0.2),
        ("nest_lateral_stiffness", -1.0),
        ("track_stiffness", 0.0),
        ("centre_plate_stiffness", np.nan),
        ("velocity_scale", 5.0),
        ("bolster_mass", 0.0),
        ("contact_damping", -1.0),
    ],
)
def test_bad_parameters_are_refused_by_name(field, value):
    with pytest.raises(ValueError, match=field):
        CAR.replace(**{field: value})


def test_bad_geometry_and_run_settings_are_refused():
    with pytest.raises(ValueError, match="centre_plate_height"):
        CAR.replace(centre_plate_height=0.5)
    with pytest.raises(ValueError, match="side_bearer_spacing"):
        CAR.replace(side_bearer_spacing=1.2)
    with pytest.raises(ValueError, match="dt"):
        rocking_run(CAR, 8.0, dt=0.01)
    with pytest.raises(ValueError, match="speed"):
        rocking_run(CAR, -1.0)
    with pytest.raises(ValueError, match="depth"):
        rocking_run(CAR, 8.0, depth=0.5)
    with pytest.raises(ValueError, match="roll_moment"):
        CAR.static_roll(2 * CAR.weight)
    with pytest.raises(ValueError, match="lateral_acceleration"):
        CAR.static_roll(lateral_acceleration=20.0)
    with pytest.raises(TypeError, match="car"):
        rocking_run(VerticalFreightCar(), 8.0)


def test_a_run_that_diverges_raises_solver_error():
    # Past the step limit RK4 blows up; the march stops at the first non-finite state.
    L, cycles, _, out, table = rocking_runs._settings(CAR, 0.02, 1.0, 11.9, 4, None, 0.005)
    with pytest.raises(SolverError, match="non-finite") as err:
        rocking_runs._run(CAR, 8.0, L, cycles, 0.005, 0.005, table)
    assert err.value.step is not None and err.value.step > 0


def test_plots_draw_and_move():
    sweep = rocking_sweep(CAR, np.array([26.0, 30.0]) / 3.6, cycles=4)
    drawn = sweep.plot()
    assert drawn["unloading"].get_xdata()[1] == pytest.approx(30.0)
    run_art = sweep.runs[0].plot()
    sweep.runs[1].plot(artists=run_art)
    np.testing.assert_allclose(run_art["left"].get_ydata(), sweep.runs[1].side_loads[:, 0, 0] / 1e3)
    with pytest.raises(ValueError, match="truck"):
        sweep.runs[0].plot(truck=2)


@widgets_of("chapter06")  # the widget's sweep is made once, with chapter 6's other widget tests
def test_wheel_unloading_widget_shows_the_sweeps_numbers_and_moves():
    import re

    from widget_helpers import status_line

    from raildyn.widgets import chapter06

    container, update = chapter06.wheel_unloading()
    sweep = chapter06.unloading_sweep()
    first = update(speed_kmh=28.0)
    text = status_line(container)
    k = int(np.argmin(np.abs(sweep.speeds * 3.6 - 28.0)))
    assert float(re.search(r"peak ΔQ/Q ([0-9.]+)", text)[1]) == pytest.approx(
        sweep.peak_unloading[k], abs=0.006
    )
    assert float(re.search(r"f L = ([0-9.]+) km/h", text)[1]) == pytest.approx(
        3.6 * CAR.roll_resonance_speed(), abs=0.51
    )
    assert update(speed_kmh=40.0) != first
