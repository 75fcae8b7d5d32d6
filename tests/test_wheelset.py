"""raildyn.wheelset: Klingel kinematics, the linear wheelset against closed forms, the nonlinear wheelset."""

import numpy as np
import pytest
import scipy.integrate
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn import contact, stability
from raildyn.linear_model import LinearSystem, as_linear_system
from raildyn.vehicles import Bogie
from raildyn.wheelset import (
    NonlinearLateral,
    NonlinearWheelset,
    WheelRailContact,
    Wheelset,
    contact_forces,
    creep_terms,
    kinematic_wavelength,
    rigid_bogie_wavelength,
    wickens_critical_speed,
)

# ---------------------------------------------------------------------------
# Closed forms


def test_klingel_wavelength_matches_the_integrated_kinematic_motion():
    # Rolling without slip: ẏ = Vψ, ψ̇ = −Vλy/(a r₀). Integrate and measure the distance between
    # upward zero crossings; the solver runs at rtol 1e-10, so 1e-6 relative is ample.
    r0, a, lam, V = 0.46, 0.75, 0.05, 20.0
    sol = scipy.integrate.solve_ivp(
        lambda t, z: [V * z[1], -V * lam * z[0] / (a * r0)],
        (0, 10.0),
        [0.0, 1e-3],
        rtol=1e-10,
        atol=1e-14,
        dense_output=True,
    )
    t = np.linspace(0, 10.0, 200001)
    y = sol.sol(t)[0]
    up = np.flatnonzero((y[:-1] < 0) & (y[1:] >= 0))
    # Linear interpolation of the crossing times.
    tc = t[up] - y[up] * (t[up + 1] - t[up]) / (y[up + 1] - y[up])
    wavelength = V * np.mean(np.diff(tc))
    assert wavelength == pytest.approx(kinematic_wavelength(r0, a, lam), rel=1e-6)


def test_klingel_wavelength_closed_form():
    # 2π√(r₀a/λ) by hand for r₀ = 0.5, a = 0.75, λ = 0.1: 2π√3.75 = 12.1673 m.
    assert kinematic_wavelength(0.5, 0.75, 0.1) == pytest.approx(2 * np.pi * np.sqrt(3.75), rel=1e-14)


def test_free_wheelset_tends_to_klingel_at_high_creep():
    # With creep coefficients 10⁴ times the default and no spin or gravity, the free wheelset's
    # oscillation is Klingel's; the error scales as 1/f, so 1e-3 relative is generous.
    ws = Wheelset(f11=1e11, f22=1e11, f23=0.0, f33=0.0, contact_angle=0.0, contact_angle_parameter=0.0).free()
    V = 10.0
    lam = stability.eigenvalues_against_speed(ws, [V])[0]
    omega = lam.imag[np.argmin(np.abs(lam.real))]
    expected = 2 * np.pi * V / kinematic_wavelength(ws.rolling_radius, ws.half_gauge, ws.conicity)
    assert abs(omega) == pytest.approx(expected, rel=1e-3)


def test_rigid_bogie_wavelength_from_a_stiff_bogie_at_low_speed():
    # Wickens' rigid-bogie wavelength assumes equal longitudinal and lateral creep coefficients,
    # a rigid frame and negligible inertia. A bogie with primary springs 10³ times the default at
    # 0.5 m/s (inertia forces ~ (ωV)² tiny) and no spin or gravity reproduces it; the residual comes
    # from the frame's inertia and elasticity, below 0.5 %.
    ws = Wheelset(f22=Wheelset().f11, f23=0.0, f33=0.0, contact_angle=0.0, contact_angle_parameter=0.0)
    ws = ws.replace(lateral_stiffness=1e3 * ws.lateral_stiffness, yaw_stiffness=1e3 * ws.yaw_stiffness)
    bogie = Bogie(
        wheelset=ws,
        secondary_lateral_stiffness=0.0,
        secondary_yaw_stiffness=0.0,
        secondary_lateral_damping=0.0,
    )
    V = 0.5
    lam = stability.eigenvalues_against_speed(bogie, [V])[0]
    oscillatory = lam[(np.abs(lam.imag) > 1e-3) & (np.abs(lam) < 10.0)]
    omega = np.abs(oscillatory.imag).min()
    L = rigid_bogie_wavelength(ws.rolling_radius, ws.half_gauge, ws.conicity, bogie.semi_wheelbase)
    assert 2 * np.pi * V / omega == pytest.approx(L, rel=5e-3)


def test_wheelset_matrices_by_hand():
    # The entries written out from the equations of motion in the docstring of creep_terms.
    ws = Wheelset()
    V = 25.0
    mats = ws.matrices(V)
    M, C, K = mats.M, mats.C, mats.K
    a, r0, lam, W = ws.half_gauge, ws.rolling_radius, ws.conicity, ws.axle_load
    np.testing.assert_allclose(M, np.diag([ws.mass, ws.yaw_inertia]))
    C_hand = np.array(
        [
            [2 * ws.f22 / V + ws.lateral_damping, 2 * ws.f23 / V],
            [-2 * ws.f23 / V, 2 * a**2 * ws.f11 / V + 2 * ws.f33 / V + ws.yaw_damping],
        ]
    )
    # With the spin of the contact-angle difference: 2f₂₃εy/(a r₀) laterally, 2f₃₃εy/(a r₀) in yaw.
    eps = ws.contact_angle_parameter
    spin = np.array([2 * ws.f23, 2 * ws.f33]) * eps / (a * r0)
    K_hand = np.array(
        [
            [ws.lateral_stiffness + W * eps / a - spin[0], -2 * ws.f22],
            [2 * a * ws.f11 * lam / r0 - spin[1], ws.yaw_stiffness + 2 * ws.f23 - W * a * ws.contact_angle],
        ]
    )
    np.testing.assert_allclose(C, C_hand, rtol=1e-14)
    np.testing.assert_allclose(K, K_hand, rtol=1e-14)


def test_kalker_coefficients_scale_with_the_patch():
    # f₁₁ ∝ c², f₂₃ ∝ c³, f₃₃ ∝ c⁴: doubling both semi-axes multiplies them by 4, 8 and 16. The
    # wheelset takes its coefficients from raildyn.contact, the one source of Kalker's law.
    def coefficients(a, b):
        f = contact.creep_coefficients(a, b, 8e10, 0.3)
        return np.array([f.f11, f.f22, f.f23, f.f33])

    np.testing.assert_allclose(coefficients(6e-3, 8e-3) / coefficients(3e-3, 4e-3), [4, 4, 8, 16], rtol=1e-14)


def test_default_creep_coefficients_are_kalkers_on_the_hertz_patch():
    # One source for the law: the default wheelset's f₁₁ … f₃₃ are raildyn.contact's Kalker
    # coefficients on raildyn.contact's Hertz patch under half the axle load (r₀ = 0.46 m, a rail
    # crowned with r₀), for the steel of raildyn.constants; identical numbers, so 1e-14.
    ws = Wheelset()
    patch = contact.hertz_contact(ws.axle_load / 2, 0.46, np.inf, 0.46, 2.1e11, 0.3)
    f = contact.creep_coefficients(patch.a, patch.b, 2.1e11 / 2.6, 0.3)
    np.testing.assert_allclose([ws.f11, ws.f22, ws.f23, ws.f33], [f.f11, f.f22, f.f23, f.f33], rtol=1e-14)


# ---------------------------------------------------------------------------
# Suspended wheelset: Wickens' high-creep critical speed


def test_suspended_wheelset_critical_speed_tends_to_wickens_high_creep_limit(reference):
    # Wickens (1965; 2003, ch. 3): as f₁₁ = f₂₂ = f → ∞ with no spin, gravity or suspension
    # damping, V_c² = (a r₀/λ)(k_ψ + a²k_y)/(I + m a²). The expansion in 1/f leaves an error that
    # must fall at least tenfold per tenfold f (it falls about a hundredfold: the O(1/f) term
    # vanishes on the stability boundary) and be below 1e-5 relative at 10³ × the default f.
    base = Wheelset(
        yaw_stiffness=4.0e6,
        lateral_stiffness=1.0e6,
        f22=Wheelset().f11,
        f23=0.0,
        f33=0.0,
        contact_angle=0.0,
        contact_angle_parameter=0.0,
        lateral_damping=0.0,
        yaw_damping=0.0,
    )
    target = wickens_critical_speed(base)
    errors = []
    for scale in (1.0, 10.0, 100.0, 1000.0):
        ws = base.replace(f11=scale * base.f11, f22=scale * base.f22)
        cs = stability.critical_speed(ws, (0.5 * target, 2.0 * target), tol=1e-7)
        assert cs.found
        errors.append(abs(cs.speed - target) / target)
    reference(
        5,
        "critical speed of the suspended wheelset, creep ×1000",
        "Wickens' high-creep limit (1965)",
        "closed form",
        errors[-1],
        1e-5,
    )
    assert all(later < 0.1 * earlier for earlier, later in zip(errors[:-1], errors[1:], strict=False))


def test_wickens_closed_form_by_hand():
    # (a r₀/λ)(k_ψ + a²k_y)/(I + m a²) with a = 0.75, r₀ = 0.46, λ = 0.15, k_ψ = 4e6, k_y = 1e6,
    # I = 1120, m = 1813: 2.3 · 4.5625e6 / 2139.8 = 4904.1 → V_c = 70.03 m/s.
    ws = Wheelset(yaw_stiffness=4.0e6, lateral_stiffness=1.0e6)
    expected = np.sqrt(0.75 * 0.46 / 0.15 * (4.0e6 + 0.5625e6) / (1120 + 1813 * 0.5625))
    assert wickens_critical_speed(ws) == pytest.approx(expected, rel=1e-14)


@settings(deadline=None, max_examples=50)
@given(
    conicity=st.floats(0.02, 0.5),
    creep_scale=st.floats(0.2, 5.0),
    speed=st.floats(1.0, 150.0),
)
def test_unsuspended_wheelset_is_unstable_at_every_speed(conicity, creep_scale, speed):
    # Wickens: without suspension the kinematic oscillation is always negatively damped.
    # Gravitational stiffness and spin are off (the classical result is for creep alone).
    ws = Wheelset(
        conicity=conicity,
        f11=creep_scale * 1.2e7,
        f22=creep_scale * 1.06e7,
        f23=0.0,
        f33=0.0,
        contact_angle=0.0,
        contact_angle_parameter=0.0,
    ).free()
    assert stability.largest_real_part(ws, [speed])[0] > 0.0


def test_default_unsuspended_wheelset_is_unstable_over_the_whole_range():
    # With the default gravitational stiffness and spin as well.
    g = stability.largest_real_part(Wheelset().free(), np.linspace(1.0, 150.0, 300))
    assert np.all(g > 0.0)


# ---------------------------------------------------------------------------
# Nonlinear wheelset


def _jacobian(rhs, x0, h=1e-9):
    f0 = rhs(0.0, x0)
    J = np.empty((x0.size, x0.size))
    for j in range(x0.size):
        dx = np.zeros_like(x0)
        dx[j] = h
        J[:, j] = (rhs(0.0, x0 + dx) - rhs(0.0, x0 - dx)) / (2 * h)
    return J, f0


@pytest.mark.parametrize("centred_angle", [0.0, 0.15])
def test_nonlinear_wheelset_linearises_to_the_linear_model(centred_angle):
    # The Jacobian at the centred state (central differences, h = 1 nm) equals A(V) of the linear
    # model, the spin of the contact-angle difference included; the saturation's slope is 1 − O(u) and
    # the flange is inactive, so 1e-5 relative. The nonlinear spin ψ̇ cos ϑ/V ∓ sin ϑ/r₀ linearises to
    # cos ϑ₀ (ψ̇/V ∓ εy/(a r₀)), where the linear model takes cos ϑ₀ = 1: exact at ϑ₀ = 0, and at
    # ϑ₀ = 0.15 the spin's entries (f₂₃ in ÿ, f₃₃ in ψ̈) differ by 1 − cos ϑ₀ = 1.1 % of themselves.
    ws = Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6, contact_angle=centred_angle)
    model = NonlinearWheelset(ws, WheelRailContact())
    J, f0 = _jacobian(lambda t, x: model.rhs(t, x, 40.0), np.zeros(4))
    A = ws.linear_system().state_matrices([40.0])[0]
    np.testing.assert_allclose(f0, 0.0, atol=1e-12)
    if centred_angle == 0.0:
        np.testing.assert_allclose(J, A, rtol=1e-5, atol=1e-5 * np.abs(A).max())
        return
    a, r0, eps, V = ws.half_gauge, ws.rolling_radius, ws.contact_angle_parameter, 40.0
    spin = np.zeros((4, 4))  # the spin's entries of A: lateral force and yaw moment over the inertias
    spin[2, [0, 3]] = np.array([2 * ws.f23 * eps / (a * r0), -2 * ws.f23 / V]) / ws.mass
    spin[3, [0, 3]] = np.array([2 * ws.f33 * eps / (a * r0), -2 * ws.f33 / V]) / ws.yaw_inertia
    expected = A - (1 - np.cos(centred_angle)) * spin
    np.testing.assert_allclose(J, expected, rtol=1e-5, atol=1e-5 * np.abs(A).max())


def test_generic_nonlinear_model_equals_the_wheelset_one():
    # NonlinearLateral over the suspended wheelset is the same model as NonlinearWheelset.
    ws = Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)
    contact = WheelRailContact()
    a = NonlinearWheelset(ws, contact)
    b = NonlinearLateral(ws.linear_system(), contact)
    rng = np.random.default_rng(3)
    for _ in range(20):
        x = rng.normal(size=4) * np.array([8e-3, 5e-3, 0.3, 0.2])
        np.testing.assert_allclose(b.rhs(0.0, x, 55.0), a.rhs(0.0, x, 55.0), rtol=1e-12, atol=1e-9)


@settings(deadline=None, max_examples=50)
@given(force=st.floats(0.0, 1e7), limit=st.floats(1e3, 1e5))
def test_saturated_force_never_exceeds_friction_limit(force, limit):
    # Shen–Hedrick–Elkins, the law the nonlinear wheelset takes from raildyn.contact: F_sat ≤ μN,
    # F_sat ≤ F (it never amplifies). Unit f₁₁ and μ = 1, so the linear force is the creepage.
    unit = contact.CreepCoefficients(1.0, 1.0, 0.0, 0.0)
    sat = abs(float(contact.shen_hedrick_elkins(force, 0.0, 0.0, limit, 1.0, unit).fx))
    assert sat <= limit * (1 + 1e-12)
    assert sat <= force * (1 + 1e-12)


def test_flange_force_acts_only_beyond_the_clearance():
    ws, contact = Wheelset(), WheelRailContact()
    d = contact.flange_clearance
    inside, _ = contact_forces(ws, contact, 0.99 * d, 0.0, 0.0, 0.0, 30.0)
    outside, _ = contact_forces(ws, contact, d + 1e-3, 0.0, 0.0, 0.0, 30.0)
    a, r0, eps, th0 = ws.half_gauge, ws.rolling_radius, ws.contact_angle_parameter, ws.contact_angle
    gravity = -ws.axle_load * eps / a
    limit = contact.friction * ws.axle_load / 2

    def spin(y):
        # Each wheel's lateral spin force f₂₃|sin(ϑ₀ ± εy/a) − sin ϑ₀|/r₀ (outwards on both, away from the
        # centre), beside its longitudinal creep force f₁₁λy/r₀ of the rolling-radius difference;
        # Shen–Hedrick–Elkins scales both by F_sat/F with F_sat = μN(u − u²/3 + u³/27), u = F/(μN) < 3.
        lateral = ws.f23 * np.abs(np.sin(th0 + np.array([1, -1]) * eps * y / a) - np.sin(th0)) / r0
        u = np.hypot(ws.f11 * ws.conicity * y / r0, lateral) / limit
        assert np.all(u < 3)
        return float(np.sum(lateral * (1 - u / 3 + u**2 / 27)))

    # Inside: gravity and the spin of the contact-angle difference (ψ = ẏ = ψ̇ = 0).
    assert inside == pytest.approx(gravity * 0.99 * d + spin(0.99 * d), rel=1e-12)
    expected = gravity * (d + 1e-3) + spin(d + 1e-3) - contact.flange_stiffness * 1e-3
    assert outside == pytest.approx(expected, rel=1e-12)


# ---------------------------------------------------------------------------
# Bad input


def test_bad_input():
    with pytest.raises(ValueError, match="conicity"):
        Wheelset(conicity=-0.1)
    with pytest.raises(ValueError, match="conicity"):
        kinematic_wavelength(0.46, 0.75, 0.0)
    with pytest.raises(ValueError, match="rolling_radius"):
        kinematic_wavelength(-0.46, 0.75, 0.1)
    with pytest.raises(ValueError, match="speed"):
        Wheelset().matrices(0.0)
    with pytest.raises(ValueError, match="speed"):
        Wheelset().matrices(-3.0)
    with pytest.raises(ValueError, match="mass"):
        Wheelset(mass=0.0)
    with pytest.raises(ValueError, match="friction"):
        WheelRailContact(friction=0.0)
    with pytest.raises(TypeError, match="rolling_radius_difference"):
        WheelRailContact(rolling_radius_difference=0.3)
    with pytest.raises(ValueError, match="speed"):
        NonlinearWheelset().rhs(0.0, np.zeros(4), 0.0)
    with pytest.raises(TypeError, match="LinearModel"):
        as_linear_system("wheelset")


def test_lateral_system_speeds_must_be_positive():
    system = Wheelset().linear_system()
    assert isinstance(system, LinearSystem)
    with pytest.raises(ValueError, match="speeds"):
        system.state_matrices([10.0, 0.0])


def test_creep_terms_vanish_with_the_creep_coefficients():
    terms = creep_terms(Wheelset(f11=0.0, f22=0.0, f23=0.0, f33=0.0))
    assert not terms.C1.any() and not terms.K_creep.any()


def test_conicity_beyond_its_range_is_blamed_on_the_conicity():
    # The contact angle follows the conicity by default: the message used to blame contact_angle.
    with pytest.raises(ValueError, match="conicity") as err:
        Wheelset(conicity=0.6)
    assert "contact_angle" not in str(err.value)


def test_the_right_hand_side_refuses_a_wrong_state():
    model = NonlinearWheelset()
    with pytest.raises(ValueError, match=r"state must have shape \(4,\)"):
        model.rhs(0.0, np.zeros(3), 30.0)
    with pytest.raises(ValueError, match="state"):
        model.rhs(0.0, [np.nan, 0.0, 0.0, 0.0], 30.0)
    with pytest.raises(ValueError, match="state"):
        NonlinearLateral(Wheelset().linear_system()).rhs(0.0, np.zeros((2, 4)), 30.0)


def test_contact_checks_its_callbacks_once():
    with pytest.raises(ValueError, match="rolling_radius_difference"):
        WheelRailContact(rolling_radius_difference=lambda y: np.full_like(y, np.nan))
    with pytest.raises(ValueError, match="contact_angle_difference"):
        WheelRailContact(contact_angle_difference=lambda y: np.zeros(2))
    with pytest.raises(TypeError, match="contact"):
        NonlinearWheelset(contact="flange")
