"""The flange as a second contact (a profile pair's two-point contact) and the contact geometry of a yawed
wheelset: the law's limits (the spring flange within the clearance, Nadal's limit at a saturated flange),
an independent composition of chapter 4's parts at both contacts, the engine on real profiles against
scipy, and the trace line against a yawed cone's closed form."""

import dataclasses

import numpy as np
import pytest

from raildyn import stability
from raildyn.contact import wheelset_creepages
from raildyn.contact.geometry import contact_geometry
from raildyn.contact.profiles import conical_wheel, s1002_wheel, uic60_rail
from raildyn.contact.saturation import saturation_scale
from raildyn.curving import quasi_static_curving
from raildyn.curving.climb import nadal_limit
from raildyn.track import balance_speed
from raildyn.vehicles import LateralCar
from raildyn.wheelset import NonlinearLateral, Wheelset, contact_forces, profile_contact, wheel_forces


@pytest.fixture(scope="module")
def pair():
    return profile_contact(s1002_wheel(), uic60_rail(1 / 40))


def test_a_profile_pair_is_a_two_point_contact_with_its_own_flange_radius(pair):
    # S1002 on UIC 60 at 1:40 jumps to its flange 6.5 mm off centre, where the flange contact lies 12.3 mm
    # above the tape circle's radius (the flange root; measured 12.33 mm).
    assert pair.two_point
    assert pair.flange_radius_excess == pytest.approx(12.3e-3, abs=0.1e-3)
    with pytest.raises(ValueError, match="flange_radius_excess"):
        dataclasses.replace(pair, flange_radius_excess=-1e-3)
    with pytest.raises(TypeError, match="two_point"):
        dataclasses.replace(pair, two_point="yes")


def test_within_the_clearance_the_two_point_contact_is_the_spring_flanges(pair):
    # Off the flange the second contact carries nothing: the same numbers to the last bit.
    spring = dataclasses.replace(pair, two_point=False)
    rng = np.random.default_rng(5)
    y = rng.uniform(-0.99, 0.99, 40) * pair.flange_clearance
    psi, ydot, psidot = rng.normal(0, 3e-3, 40), rng.normal(0, 0.05, 40), rng.normal(0, 0.05, 40)
    ws = Wheelset()
    for a, b in zip(contact_forces(ws, pair, y, psi, ydot, psidot, 40.0),
                    contact_forces(ws, spring, y, psi, ydot, psidot, 40.0), strict=True):  # fmt: skip
        np.testing.assert_array_equal(a, b)
    # On the flange they differ: the flange's creep forces and the tread it unloads.
    on = [1.5 * pair.flange_clearance, 2e-3, 0.0, 0.0]
    assert contact_forces(ws, pair, *on, 40.0)[1] != contact_forces(ws, spring, *on, 40.0)[1]


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_saturated_flange_bears_nadals_quotient(pair, sign):
    # With its creep force saturated at μN_f and purely lateral (no spin coefficients, no radius excess, no
    # yaw rate), the flange contact's own Y/V is Nadal's (tan ϑ − μ)/(1 + μ tan ϑ) when that force acts up
    # its flank, and (tan ϑ + μ)/(1 − μ tan ϑ) when down it: statics of a block on a slope, in closed form.
    ws = Wheelset(f23=0.0, f33=0.0)
    rail = dataclasses.replace(pair, flange_radius_excess=0.0, friction=0.3)
    y = sign * (pair.flange_clearance + 2e-3)
    wheel = 0 if sign > 0 else 1
    for yaw, climbing in ((sign * 0.02, True), (-sign * 0.02, False)):  # γ_y = −ψ, far past saturation
        f = wheel_forces(ws, rail, y, yaw, 0.0, 0.0, 40.0)
        quotient = abs(float(f.flange[wheel])) / float(f.flange_vertical[wheel])
        t, mu = np.tan(rail.flange_angle), rail.friction
        expected = nadal_limit(rail.flange_angle, mu) if climbing else (t + mu) / (1 - mu * t)
        assert quotient == pytest.approx(float(expected), rel=1e-12)


def test_the_two_point_law_is_chapter_4s_parts_at_each_contact(pair):
    # An independent composition in numpy of raildyn.contact's public laws at both contacts of each wheel:
    # the creepages (the flange's at its radius and angle), Kalker's coefficients scaled by each contact's
    # load (c ∝ N^(1/3)), Shen–Hedrick–Elkins at μN of each contact, the flange's normal force H/sin ϑ_f,
    # its vertical load off the tread, the treads' normal forces −Q_L ϑ_L + Q_R ϑ_R.
    ws, V = Wheelset(), 35.0
    rng = np.random.default_rng(17)
    n = 60
    y = rng.uniform(-12e-3, 12e-3, n)
    psi, ydot, psidot = rng.normal(0, 3e-3, n), rng.normal(0, 0.05, n), rng.normal(0, 0.05, n)
    a, r0, W, mu = ws.half_gauge, ws.rolling_radius, ws.axle_load, pair.friction
    angle = pair.flange_angle
    side = np.sign(y)
    H = -pair.flange_stiffness * side * np.maximum(np.abs(y) - pair.flange_clearance, 0.0)
    N_f = np.abs(H) / np.sin(angle)

    def forces(creep, load, limit, spin_coefficients=True):
        n23 = ws.f23 * load ** (3 / 3) if spin_coefficients else 0.0
        fx = -ws.f11 * load ** (2 / 3) * creep.longitudinal
        fy = -ws.f22 * load ** (2 / 3) * creep.lateral - n23 * creep.spin
        mz = n23 * creep.lateral - ws.f33 * load ** (4 / 3) * creep.spin
        loaded = limit > 0
        scale = np.zeros_like(fx)
        scale[loaded] = saturation_scale(np.hypot(fx, fy)[loaded] / limit[loaded])
        return scale * fx, scale * fy, scale * mz

    rf = r0 + pair.flange_radius_excess
    flange = wheelset_creepages(V, ydot, psi, psidot, rf, rf, r0, a, angle, angle)
    k = np.where(y > 0, 0, 1)
    pick = lambda v: np.take_along_axis(np.asarray(v), k[None, :], axis=0)[0]  # noqa: E731
    both = np.stack([N_f, N_f])
    fxf, fyf, mzf = (pick(v) for v in forces(flange, both / (W / 2), mu * both))
    V_f = np.abs(H) / np.tan(angle) + side * fyf * np.sin(angle)
    lost = np.where(H != 0, np.minimum(V_f, W / 2), 0.0)
    load = np.ones((2, n))
    load[k, np.arange(n)] -= lost / (W / 2)
    dr, dd = pair.rolling_radius_difference(y), pair.contact_angle_difference(y)
    theta, centred = pair.tread_angles(y), pair.tread_angles(0.0)
    tread = wheelset_creepages(V, ydot, psi, psidot, r0 + dr / 2, r0 - dr / 2, r0, a, theta[0], theta[1])
    centred_spin = np.array([1.0, -1.0])[:, None] * np.sin(centred)[:, None] / r0
    tread = dataclasses.replace(tread, spin=tread.spin + centred_spin)
    fx, fy, mz = forces(tread, load, mu * load * W / 2)
    lateral = fy.sum(axis=0) - W / 2 * dd + H + fyf * np.cos(angle) + side * lost * pick(theta)
    yaw = a * (fx[1] - fx[0]) + mz.sum(axis=0) + W * a * ws.contact_angle * psi - side * a * fxf + mzf
    ours = contact_forces(ws, pair, y, psi, ydot, psidot, V)
    assert np.any(H != 0) and np.any(H == 0)
    # Round-off of sums of terms up to some 1e5 N: 1e-9 of the largest force.
    np.testing.assert_allclose(ours[0], lateral, rtol=0, atol=1e-9 * np.abs(lateral).max())
    np.testing.assert_allclose(ours[1], yaw, rtol=0, atol=1e-9 * np.abs(yaw).max())


def test_in_a_tight_curve_the_flange_wears_and_steers(pair):
    # Two contacts on the leading outer wheel: the flange's slip at its larger radius adds to the wear
    # number, and its longitudinal creep force yaws the wheelset away from the rail (Garg & Dukkipati 1984,
    # ch. 8). Within the clearance (a gentle curve) nothing changes.
    car = LateralCar()
    spring = dataclasses.replace(pair, two_point=False)
    tight = [quasi_static_curving(car.nonlinear(contact=c), balance_speed(300.0, 0.1) + 5, 300.0, 0.1)
             for c in (spring, pair)]  # fmt: skip
    assert tight[0].flange_contact[0] and tight[1].flange_contact[0]
    assert tight[1].wear_number[0] > 1.1 * tight[0].wear_number[0]
    gentle = [quasi_static_curving(car.nonlinear(contact=c), 20.0, 3000.0, 0.0) for c in (spring, pair)]
    assert not gentle[0].flange_contact.any()
    np.testing.assert_array_equal(gentle[0].wear_number, gentle[1].wear_number)


@pytest.mark.slow  # scipy's RK45 on the same equations, seconds
def test_a_car_on_real_profiles_hunts_alike_through_the_engine_and_scipy(pair):
    # The Manchester car on S1002/UIC 60 with its flange as a second contact: the compiled engine against
    # scipy's RK45 on the numpy right-hand side. Their right-hand sides agree at round-off
    # (tests/test_engine.py); integrated, the flange's kinks tip the step choices apart, so both run at rtol
    # 1e-8, where they agree to 5e-7 of the motion (measured; at 1e-6 scipy's run is 1.1e-4 off both):
    # held to 1e-5.
    model = NonlinearLateral(LateralCar().nonlinear().system, pair)
    kwargs = dict(duration=2.0, initial_displacement=8e-3, rtol=1e-8)
    compiled = stability.limit_cycle_amplitude(model, 90.0, engine="compiled", **kwargs)
    reference = stability.limit_cycle_amplitude(model, 90.0, engine="scipy", **kwargs)
    assert compiled.amplitude > pair.flange_clearance  # its wheels run on their flanges
    assert compiled.amplitude == pytest.approx(reference.amplitude, rel=1e-5)
    assert compiled.frequency_hz == pytest.approx(reference.frequency_hz, rel=1e-5)


# ---------------------------------------------------------------------------
# A yawed wheelset's contact geometry


@pytest.mark.parametrize("yaw", [0.01, -0.02])
def test_a_yawed_cone_touches_along_its_trace_line(yaw):
    # A cone of slope λ yawed by ψ, without roll: each wheel shows the rail the line u_e = u cos ψ +
    # (T/2)(1 − cos ψ) − r λ tan ψ sin ψ, so a shift y moves the contact by y/(cos ψ − λ² tan ψ sin ψ) along
    # the wheel and Δr = 2λy/(cos ψ − λ² tan ψ sin ψ); the contact leads the axle by r λ sin ψ on the left
    # wheel and lags it as much on the right (closed forms, to the search's 1e-9 m).
    lam, y = 0.05, np.array([-3e-3, 1e-3, 4e-3])
    g = contact_geometry(conical_wheel(lam), uic60_rail(1 / 40), y, roll=False, yaw=yaw)
    stretch = np.cos(yaw) - lam**2 * np.tan(yaw) * np.sin(yaw)
    np.testing.assert_allclose(g.rolling_radius_difference, 2 * lam * y / stretch, rtol=0, atol=1e-9)
    np.testing.assert_allclose(g.lead, g.rolling_radius * lam * np.sin(yaw) * np.array([[1.0], [-1.0]]),
                               rtol=1e-9)  # fmt: skip
    assert g.yaw == yaw


def test_yaw_changes_the_geometry_at_second_order_and_leads_at_first():
    # S1002 on UIC 60: Δr and the contact angles are even in ψ and change as ψ² (doubling ψ quadruples the
    # change, to within the next order: measured 4.0 ± 0.1); the lead is odd in ψ and grows as ψ.
    wheel, rail = s1002_wheel(), uic60_rail(1 / 40)
    y = np.linspace(-5e-3, 5e-3, 11)
    flat = contact_geometry(wheel, rail, y)
    np.testing.assert_array_equal(flat.lead, 0.0)
    g = {psi: contact_geometry(wheel, rail, y, yaw=psi) for psi in (-0.01, 0.005, 0.01)}
    even = g[-0.01].rolling_radius_difference, g[0.01].rolling_radius_difference
    np.testing.assert_allclose(*even, atol=1e-12)
    np.testing.assert_allclose(g[-0.01].lead, -g[0.01].lead, atol=1e-12)
    change = {psi: np.abs(g[psi].rolling_radius_difference - flat.rolling_radius_difference).max()
              for psi in (0.005, 0.01)}  # fmt: skip
    assert change[0.01] / change[0.005] == pytest.approx(4.0, abs=0.3)
    assert np.abs(g[0.01].lead).max() / np.abs(g[0.005].lead).max() == pytest.approx(2.0, rel=0.01)
    # At 10 mrad Δr moves by under 1 % of itself here: the tables of the models are taken at ψ = 0.
    assert change[0.01] < 0.01 * np.abs(flat.rolling_radius_difference).max()


def test_yaw_beyond_the_trace_lines_reach_is_refused():
    with pytest.raises(ValueError, match="yaw"):
        contact_geometry(s1002_wheel(), uic60_rail(1 / 40), 0.0, yaw=0.05)
    with pytest.raises(ValueError, match="yaw"):
        contact_geometry(s1002_wheel(), uic60_rail(1 / 40), 0.0, yaw=float("nan"))


def test_beyond_the_clearance_the_flanging_wheels_tread_holds_its_contact(pair):
    # The flanging wheel's rail gives way: its tread contact stays where it was at y = e, so the angles keep
    # their values there (before, the tables ran on along their last slope, to a 62° "tread" at 12 mm), and
    # Δr grows only by the other wheel rolling along its tread, tan ϑ_R(e) per metre.
    e = pair.flange_clearance
    for y in (e + 2e-3, e + 6e-3, e + 30e-3):
        np.testing.assert_allclose(pair.tread_angles(y), pair.tread_angles(e), rtol=0, atol=1e-15)
        np.testing.assert_allclose(pair.tread_angles(-y), pair.tread_angles(-e), rtol=0, atol=1e-15)
        slope = (pair.rolling_radius_difference(y) - pair.rolling_radius_difference(e)) / (y - e)
        assert slope == pytest.approx(np.tan(pair.tread_angles(e)[1]), rel=1e-9)
    assert pair.tread_angles(e)[0] < np.radians(40.0)  # a tread, not a flange


@pytest.mark.parametrize("name", ["Bogie", "LateralCar", "LateralFreightCar", "LateralLocomotive"])
@pytest.mark.parametrize("worn", [False, True])
def test_every_lateral_vehicle_runs_on_real_profiles_with_two_point_contact(name, worn):
    # Each vehicle's nonlinear model takes a profile pair's contact: new S1002 on 60E1, or the measured worn
    # North American pair on its own track. Past the flange its forces are the two-point law's (they differ
    # from the spring flange's), and where the compiled engine holds the model (all but the freight car and
    # the locomotive, whose wedges are Python force laws) it evaluates the same right-hand side.
    from raildyn import vehicles
    from raildyn.contact import worn_rail, worn_wheel

    if worn:
        pair = profile_contact(worn_wheel(), worn_rail(), gauge=1.4351, tape_distance=1.4874)
    else:
        pair = profile_contact(s1002_wheel(), uic60_rail(1 / 40))
    model = getattr(vehicles, name)().nonlinear(contact=pair)
    spring = model.replace(contact=dataclasses.replace(pair, two_point=False))
    state = np.zeros(model.state_size)
    iy = model.system.wheelsets[0][0]
    state[iy] = pair.flange_clearance + 2e-3  # the leading wheelset on its left flange
    half = model.state_size // 2
    state[half + iy] = 0.02
    ours = model.rhs(0.0, state, 30.0)
    assert np.all(np.isfinite(ours))
    assert not np.allclose(ours, spring.rhs(0.0, state, 30.0))
    if model.compiled_reason is None:
        compiled = model.compiled_rhs(30.0)
        out = np.empty_like(state)
        compiled.kernel(0.0, state, 0, compiled.row[None, :].copy(), out)
        np.testing.assert_allclose(out, ours, rtol=0, atol=1e-13 * np.abs(ours).max())
    else:
        assert name in ("LateralFreightCar", "LateralLocomotive")


def test_a_pairs_tables_are_made_once(pair):
    # Asked again (with another friction), profile_contact hands back the same tables; another gauge, or a
    # profile that differs in one sample, gets its own.
    again = profile_contact(s1002_wheel(), uic60_rail(1 / 40), friction=0.4)
    assert again.rolling_radius_difference is pair.rolling_radius_difference and again.friction == 0.4
    wider = profile_contact(s1002_wheel(), uic60_rail(1 / 40), gauge=1.437)
    assert wider.rolling_radius_difference is not pair.rolling_radius_difference
    assert wider.flange_clearance > pair.flange_clearance
    worn = s1002_wheel()
    radius = worn.radius.copy()
    radius[100] -= 1e-6
    touched = dataclasses.replace(worn, radius=radius)
    assert (
        profile_contact(touched, uic60_rail(1 / 40)).rolling_radius_difference
        is not pair.rolling_radius_difference
    )
