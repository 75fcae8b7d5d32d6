"""raildyn.integrators: convergence orders, stability limits, accuracy closed forms, nonlinear agreement.

Three tiers. Closed forms: the exact SDOF solution (raildyn.vibration), the
period of the average acceleration and central difference recursions, the
stability limits Δt/T = 1/π, √3/π, √2/π. Published statements: unconditional
stability of Houbolt and Wilson θ = 1.4, the conditional stability of θ < 1.37,
and the HHT-α high-frequency spectral radius (1 + α)/(1 − α) (Bathe 1996, §9.4;
Hilber, Hughes & Taylor 1977). Properties (hypothesis): discrete energy
conservation, spectral radius bounds.
"""

import numpy as np
import pytest
import scipy.integrate
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn import integrators as ri
from raildyn import vibration
from raildyn.errors import SolverError

TWO_PI = 2 * np.pi

# Scheme name -> its order of accuracy (Bathe 1996, §9.2; Hairer, Nørsett & Wanner 1993 for RK4 and ABM).
ORDERS = {
    "central_difference": 2,
    "houbolt": 2,
    "wilson": 2,
    "average_acceleration": 2,
    "linear_acceleration": 2,
    "hht_alpha": 2,
    "forward_euler": 1,
    "rk4": 4,
    "abm": 4,
}


def _sdof_error(method, steps, **params):
    """Max displacement error on the damped oscillator (T = 1 s, ξ = 0.05) under a constant force.

    The constant force is exactly represented by the sampled load of every scheme, and
    SDOF.forced_response is exact for it, so the error is the scheme's alone.
    """
    system = vibration.SDOF.from_modal(TWO_PI, 0.05)
    t = np.linspace(0.0, 2.0, steps + 1)
    f = np.full(t.size, 10.0)
    exact = system.forced_response(t, f, x0=1.0, v0=2.0)
    if method in ("forward_euler", "rk4", "abm", "newmark_newton"):
        force = lambda tk, x, v: np.array([10.0])  # noqa: E731
    else:
        force = f
    run = getattr(ri, method)
    r = run(system.mass, system.damping, system.stiffness, t, 1.0, 2.0, force, **params)
    return np.abs(r.x[0] - exact).max()


@pytest.mark.parametrize("method", list(ORDERS))
def test_measured_order_of_convergence(method):
    errors = [_sdof_error(method, n) for n in (200, 400, 800)]
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    # Δt/T ≤ 0.01 is deep in the asymptotic range: the measured order is within 0.1 of the
    # theoretical one (forward Euler, whose error constant is largest, within 0.2).
    slack = 0.2 if method == "forward_euler" else 0.1
    assert np.all(np.abs(orders - ORDERS[method]) < slack), f"{method}: measured orders {orders}"


@pytest.mark.parametrize(
    ("method", "params", "order"),
    [
        ("newmark", {"gamma": 0.6, "beta": 0.3025}, 1),
        ("newmark_newton", {}, 2),
        ("wilson", {"theta": 2.0}, 2),
    ],
)
def test_measured_order_with_parameters(method, params, order):
    # γ > ½ costs Newmark its second order (Hughes 2000, §9.1.1); Newton iterations do not change it.
    errors = [_sdof_error(method, n, **params) for n in (200, 400, 800)]
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(np.abs(orders - order) < 0.15), orders


def test_central_difference_stable_just_below_T_over_pi_and_diverging_just_above():
    # Undamped oscillator with T = 1 s: the limit is Δt = T/π (ω Δt = 2) (Bathe 1996, §9.4.1).
    stiffness = TWO_PI**2
    below = np.arange(3000) * (0.999 / np.pi)
    r = ri.central_difference(1.0, 0.0, stiffness, below, 1.0, 0.0)
    # Near the limit the discrete amplitude is 1/√(1 − (ωΔt/2)²) ≈ 22 times x0 at most: bounded.
    # (A returned result is a success: a failed run raises SolverError.)
    assert isinstance(r, ri.IntegrationResult) and r.steps == 2999 and np.abs(r.x).max() < 25.0
    above = np.arange(3000) * (1.001 / np.pi)
    with pytest.raises(SolverError, match=r"stable only for dt <= T_min/pi = 0\.31831") as info:
        ri.central_difference(1.0, 0.0, stiffness, above, 1.0, 0.0)
    assert 0 < info.value.step < 3000 and f"step {info.value.step}" in str(info.value)


def test_divergence_keeps_the_completed_part_on_the_error():
    t = np.arange(500) * 0.5  # ωΔt = π > 2
    with pytest.raises(SolverError) as info:
        ri.central_difference(1.0, 0.0, TWO_PI**2, t, 1.0, 0.0)
    r = info.value.partial
    assert "diverged" in str(info.value)
    assert r.t.size < t.size and np.all(np.isfinite(r.x))


def test_rk4_divergence_names_its_limit():
    # Undamped, ω = 1000 rad/s: RK4 needs ωΔt <= 2√2, Δt <= 2.828 ms.
    with pytest.raises(SolverError, match=r"rk4 is stable only for dt <= 0\.00282843 s"):
        ri.rk4(1.0, 0.0, 1.0e6, np.linspace(0.0, 1.0, 101), 1.0, 0.0)


def test_rk4_limit_on_a_heavily_damped_mode_is_the_real_axis_one():
    # A creep-like damper: the mode λ = −c/m = −2000 1/s binds; RK4 reaches −2.785 on the real axis
    # (|1 + z + z²/2 + z³/6 + z⁴/24| = 1 at z ≈ −2.7853), so Δt <= 1.3926 ms.
    with pytest.raises(SolverError, match=r"stable only for dt <= 0\.001392"):
        ri.rk4(1.0, 2000.0, 1.0, np.linspace(0.0, 1.0, 201), 1.0, 0.0)


def test_unconditionally_stable_scheme_blames_the_system():
    # Negative damping: the exact solution grows, so no step can help.
    with pytest.raises(SolverError, match="unconditionally stable"):
        ri.average_acceleration(1.0, -1.0, 1.0, np.linspace(0.0, 1000.0, 10001), 1.0, 0.0)


def _energy(M, K, r):
    return 0.5 * np.einsum("it,ij,jt->t", r.v, M, r.v) + 0.5 * np.einsum("it,ij,jt->t", r.x, K, r.x)


def test_average_acceleration_conserves_energy_of_undamped_chain():
    chain = vibration.chain_matrices([1000.0, 800.0, 600.0], [1e6, 5e5, 2e5])
    M, K = chain.M, chain.K
    t = np.arange(2001) * 0.05  # Δt/T_min ≈ 0.4: large steps, still exact energy
    r = ri.average_acceleration(M, np.zeros((3, 3)), K, t, [0.01, -0.02, 0.03], [0.0, 0.1, 0.0])
    e = _energy(M, K, r)
    # The trapezoidal rule conserves this quadratic energy exactly; 2000 steps of rounding stay below 1e-12.
    assert np.abs(e / e[0] - 1).max() < 1e-12


@settings(deadline=None, max_examples=50)
@given(
    masses=st.lists(st.floats(10.0, 1e4), min_size=1, max_size=4),
    ratio=st.floats(0.05, 5.0),
    dt=st.floats(1e-4, 1.0),
    seed=st.integers(0, 1000),
)
def test_energy_conserved_for_any_chain_and_step(masses, ratio, dt, seed):
    n = len(masses)
    chain = vibration.chain_matrices(masses, np.full(n, 1e5) * ratio)
    M, K = chain.M, chain.K
    rng = np.random.default_rng(seed)
    r = ri.average_acceleration(
        M, np.zeros((n, n)), K, np.arange(201) * dt, rng.normal(size=n), rng.normal(size=n)
    )
    e = _energy(M, K, r)
    # Exact in exact arithmetic. The rounding of each step grows with (ωΔt)², here up to 10⁴
    # (ω = 100 rad/s, Δt = 1 s), so 200 steps may drift by ~1e-10: allow 1e-9.
    assert np.abs(e / e[0] - 1).max() < 1e-9


@pytest.mark.parametrize("ratio", [0.001, 0.01, 0.05, 0.1, 0.2, 0.3, 0.31])
def test_period_elongation_closed_forms(ratio, reference):
    omega_dt = TWO_PI * ratio
    # Average acceleration: ω̄Δt = 2 arctan(ωΔt/2); central difference: cos ω̄Δt = 1 − (ωΔt)²/2.
    aa = omega_dt / (2 * np.arctan(omega_dt / 2)) - 1
    cd = omega_dt / np.arccos(1 - omega_dt**2 / 2) - 1
    # The computed phase arg λ carries a rounding of ~1e-16 absolute, so PE = ωΔt/arg λ − 1 is good
    # to ~1e-16/(ωΔt) absolute: 1e-12 covers the smallest step here.
    assert ri.period_elongation("average_acceleration", ratio) == pytest.approx(aa, rel=1e-9, abs=1e-12)
    if ratio == 0.1:
        got = ri.period_elongation("average_acceleration", ratio)
        reference(
            2,
            "period elongation of average acceleration at Δt/T = 0.1",
            "2 arctan(ωΔt/2) (Bathe 1996)",
            "closed form",
            abs(got / aa - 1),
            1e-9,
        )
    assert ri.period_elongation("central_difference", ratio) == pytest.approx(cd, rel=1e-9, abs=1e-12)
    assert ri.amplitude_decay("average_acceleration", ratio) == pytest.approx(0.0, abs=1e-10)
    assert ri.amplitude_decay("central_difference", ratio) == pytest.approx(0.0, abs=1e-10)


@pytest.mark.parametrize("method", ["average_acceleration", "central_difference"])
def test_run_oscillates_at_the_closed_form_frequency(method):
    # Any solution of a two-term recursion with roots e^{±iθ} obeys x₊ + x₋ = 2 cos θ x:
    # read θ off the computed history and compare it with the closed form.
    ratio = 0.1
    t = np.arange(400) * ratio
    r = getattr(ri, method)(1.0, 0.0, TWO_PI**2, t, 1.0, 0.3)
    x = r.x[0]
    k = np.argmax(np.abs(x[1:-1])) + 1
    measured = (x[k + 1] + x[k - 1]) / (2 * x[k])
    w = TWO_PI * ratio
    expected = np.cos(2 * np.arctan(w / 2)) if method == "average_acceleration" else 1 - w**2 / 2
    assert measured == pytest.approx(expected, abs=1e-12)


def test_spectral_radius_of_the_average_acceleration_method_is_one():
    ratios = np.logspace(-3, 3, 50)
    assert np.allclose(ri.spectral_radius("average_acceleration", ratios), 1.0, atol=1e-12)


@pytest.mark.parametrize(
    ("method", "params"), [("houbolt", {}), ("wilson", {"theta": 1.4}), ("hht_alpha", {})]
)
def test_unconditionally_stable_schemes(method, params):
    # Bathe (1996), §9.4.2: Houbolt and Wilson θ = 1.4 are unconditionally stable; HHT-α too (HHT 1977).
    ratios = np.logspace(-3, 4, 300)
    assert np.all(ri.spectral_radius(method, ratios, **params) <= 1 + 1e-10)
    assert ri.stability_limit(method, **params) == np.inf


def test_wilson_below_137_is_only_conditionally_stable():
    # Bathe (1996), §9.4.2: Wilson-θ is unconditionally stable only for θ ≥ 1.37.
    assert np.isfinite(ri.stability_limit("wilson", theta=1.3))
    assert ri.stability_limit("wilson", theta=1.37) == np.inf


@pytest.mark.parametrize(
    ("method", "params", "limit"),
    [
        ("central_difference", {}, 1 / np.pi),
        ("linear_acceleration", {}, np.sqrt(3) / np.pi),  # ωΔt ≤ 2√3
        ("rk4", {}, np.sqrt(2) / np.pi),  # |ωΔt| ≤ 2√2 on the imaginary axis
        ("newmark", {"gamma": 0.6, "beta": 0.2}, 1 / np.sqrt(0.6 / 2 - 0.2) / TWO_PI),  # Ω = (γ/2 − β)^(−½)
        ("forward_euler", {}, 0.0),
    ],
)
def test_stability_limits_found_on_the_amplification_matrix(method, params, limit):
    assert ri.stability_limit(method, **params) == pytest.approx(limit, rel=1e-8, abs=1e-12)


@pytest.mark.parametrize("alpha", [-0.05, -0.1, -0.3])
def test_hht_alpha_high_frequency_spectral_radius(alpha):
    # ρ → (1 + α)/(1 − α) as Δt/T → ∞ (Hilber, Hughes & Taylor 1977); at Δt/T = 10⁵ within 1e-6.
    rho = ri.spectral_radius("hht_alpha", 1e5, alpha=alpha)
    assert rho == pytest.approx((1 + alpha) / (1 - alpha), abs=1e-6)


def test_rk4_spectral_radius_closed_form():
    w = TWO_PI * np.array([0.05, 0.2, 0.44])
    rho = np.sqrt(1 - w**6 / 72 + w**8 / 576)  # |Σ_{k≤4} (iωΔt)^k/k!|
    assert np.allclose(ri.spectral_radius("rk4", w / TWO_PI), rho, rtol=1e-12)


def test_amplification_matrix_of_central_difference():
    A = ri.amplification_matrix("central_difference", 0.1)
    w2 = (TWO_PI * 0.1) ** 2
    assert np.allclose(A, [[2 - w2, -1.0], [1.0, 0.0]], atol=1e-13)
    assert ri.amplification_matrix("rk4", [0.1, 0.2]).shape == (2, 2, 2)


@settings(deadline=None, max_examples=50)
@given(ratio=st.floats(1e-3, 1e3), xi=st.floats(0.0, 0.9))
def test_damped_unconditional_schemes_never_amplify(ratio, xi):
    for method in ("houbolt", "wilson", "average_acceleration", "hht_alpha"):
        assert ri.spectral_radius(method, ratio, xi) <= 1 + 1e-9


def test_numerical_damping_ranks_as_in_bathe():
    # Bathe (1996), Fig. 9.3: at Δt/T = 0.1 Houbolt damps more than Wilson θ = 1.4, which damps more
    # than average acceleration (none); the period errors of all three are positive.
    ad = {m: ri.amplitude_decay(m, 0.1) for m in ("houbolt", "wilson", "average_acceleration")}
    assert ad["houbolt"] > ad["wilson"] > 0.05 > abs(ad["average_acceleration"])
    assert all(ri.period_elongation(m, 0.1) > 0 for m in ad)


def test_wilson_with_theta_one_is_linear_acceleration():
    t = np.linspace(0.0, 3.0, 301)
    a = ri.wilson(2.0, 0.3, 50.0, t, 0.1, 0.0, np.sin(t), theta=1.0)
    b = ri.linear_acceleration(2.0, 0.3, 50.0, t, 0.1, 0.0, np.sin(t))
    assert np.allclose(a.x, b.x, rtol=0, atol=1e-13)


def test_hht_alpha_zero_is_average_acceleration_and_integrate_dispatches():
    t = np.linspace(0.0, 3.0, 301)
    a = ri.hht_alpha(2.0, 0.3, 50.0, t, 0.1, 0.0, alpha=0.0)
    b = ri.integrate("average_acceleration", 2.0, 0.3, 50.0, t, 0.1, 0.0)
    assert np.array_equal(a.x, b.x)


def test_mdof_newmark_matches_modal_superposition():
    chain = vibration.chain_matrices([1000.0, 1000.0, 500.0], [2e6, 1e6, 1e6])
    M, K = chain.M, chain.K
    t = np.linspace(0.0, 2.0, 20001)
    x0 = np.array([0.01, 0.0, -0.01])
    exact = vibration.modal_superposition(M, K, t, x0=x0)
    r = ri.average_acceleration(M, np.zeros((3, 3)), K, t, x0, np.zeros(3))
    w_max = vibration.modal_analysis(M, K).natural_frequencies[-1]
    # Phase error ≈ (ωΔt)²/12 · ω t per mode: bound it for the fastest mode over 2 s.
    bound = (w_max * 1e-4) ** 2 / 12 * w_max * 2.0 * 0.01 * 3
    assert np.abs(r.x - exact).max() < bound


# ---------------------------------------------------------------------------
# Nonlinear: a Duffing spring with a smooth friction damper, two degrees of freedom.

M2 = np.diag([2.0, 1.0])
C2 = np.array([[0.4, -0.1], [-0.1, 0.1]])
K2 = np.array([[300.0, -100.0], [-100.0, 100.0]])


def _nonlinear_force(t, x, v):
    # Hardening spring on mass 1, tanh-regularized Coulomb friction on mass 2, a harmonic drive.
    return np.array([-5e4 * x[0] ** 3 + 2.0 * np.sin(5 * t), -0.5 * np.tanh(v[1] / 0.05)])


def _nonlinear_jacobian(t, x, v):
    dfdx = np.array([[-1.5e5 * x[0] ** 2, 0.0], [0.0, 0.0]])
    dfdv = np.array([[0.0, 0.0], [0.0, -0.5 / 0.05 * (1 - np.tanh(v[1] / 0.05) ** 2)]])
    return dfdx, dfdv


def _reference(t):
    def rhs(tk, y):
        x, v = y[:2], y[2:]
        return np.r_[v, np.linalg.solve(M2, _nonlinear_force(tk, x, v) - C2 @ v - K2 @ x)]

    sol = scipy.integrate.solve_ivp(
        rhs, (t[0], t[-1]), [0.05, 0.0, 0.0, 0.2], "DOP853", t_eval=t, rtol=1e-12, atol=1e-14
    )
    return sol.y[:2]


def test_rk4_and_abm_agree_with_solve_ivp_on_a_nonlinear_problem():
    t = np.linspace(0.0, 2.0, 4001)
    ref = _reference(t)
    for method, tol in (("rk4", 1e-9), ("abm", 1e-8)):
        r = getattr(ri, method)(M2, C2, K2, t, [0.05, 0.0], [0.0, 0.2], _nonlinear_force)
        # Fourth order at Δt = 5e-4 s with ω Δt ≈ 0.01: errors ~ (ωΔt)⁴ × amplitude ≈ 1e-10 m.
        assert np.abs(r.x - ref).max() < tol, method
        assert r.iterations > 0


def test_newmark_newton_converges_to_solve_ivp_at_second_order():
    errors = []
    for steps in (1000, 2000, 4000):
        t = np.linspace(0.0, 2.0, steps + 1)
        r = ri.newmark_newton(
            M2, C2, K2, t, [0.05, 0.0], [0.0, 0.2], _nonlinear_force, jacobian=_nonlinear_jacobian
        )
        errors.append(np.abs(r.x - _reference(t)).max())
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(np.abs(orders - 2) < 0.15), orders
    # Phase error of the trapezoidal rule ≈ (ωΔt)²/12 per radian: with ω ≲ 20 rad/s, Δt = 5e-4 s over
    # 2 s that is ≈ 3e-5 rad of a 0.05 m motion, ≈ 2e-6 m; allow 1e-5 m.
    assert errors[-1] < 1e-5


def test_newmark_newton_finite_difference_jacobian_matches_the_analytic_one():
    t = np.linspace(0.0, 1.0, 501)
    a = ri.newmark_newton(
        M2, C2, K2, t, [0.05, 0.0], [0.0, 0.2], _nonlinear_force, jacobian=_nonlinear_jacobian
    )
    b = ri.newmark_newton(M2, C2, K2, t, [0.05, 0.0], [0.0, 0.2], _nonlinear_force)
    # Both iterate until the correction is below 1e-10 of the state; the converged steps agree to that.
    assert np.abs(a.x - b.x).max() < 1e-9
    assert a.iterations >= a.steps


def test_newmark_newton_on_a_linear_system_equals_linear_newmark():
    t = np.linspace(0.0, 2.0, 201)
    a = ri.newmark_newton(M2, C2, K2, t, [0.05, 0.0], [0.0, 0.2])
    b = ri.average_acceleration(M2, C2, K2, t, [0.05, 0.0], [0.0, 0.2])
    assert np.abs(a.x - b.x).max() < 1e-12
    assert a.iterations <= 2 * a.steps  # a linear step converges in one Newton iteration (plus the check)


@pytest.mark.parametrize("method", ["Radau", "BDF"])
def test_stiff_solver_agrees_with_solve_ivp(method):
    t = np.linspace(0.0, 2.0, 401)
    r = ri.stiff(
        M2,
        C2,
        K2,
        t,
        [0.05, 0.0],
        [0.0, 0.2],
        _nonlinear_force,
        jacobian=_nonlinear_jacobian,
        method=method,
        rtol=1e-10,
        atol=1e-13,
    )
    # A tolerance of 1e-10 keeps the global error near 1e-8 of the 0.05 m amplitude. (A returned
    # result is a success: scipy's failures raise SolverError.)
    assert isinstance(r, ri.IntegrationResult) and np.abs(r.x - _reference(t)).max() < 1e-7
    assert r.steps > 0 and r.iterations > r.steps


# ---------------------------------------------------------------------------
# Bad input


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"t": np.array([0.0, 0.0, 0.1])}, "strictly increasing"),
        ({"t": np.array([0.0, -0.1, -0.2])}, "strictly increasing"),
        ({"t": np.array([0.0, 0.1, 0.3])}, "uniformly spaced"),
        ({"x0": [1.0, 2.0, 3.0]}, "x0 must have shape"),
        ({"K": np.eye(3)}, "K must be 2x2"),
        ({"M": np.array([[1.0, 0.0], [0.0, -1.0]])}, "M must be positive definite"),
        ({"force": np.zeros((2, 5))}, "force must have shape"),
    ],
)
def test_bad_input_is_refused(kwargs, match):
    args = {
        "M": np.eye(2),
        "C": np.zeros((2, 2)),
        "K": np.eye(2),
        "t": np.linspace(0, 1, 11),
        "x0": [1.0, 0.0],
        "v0": [0.0, 0.0],
    }
    args.update(kwargs)
    force = args.pop("force", None)
    for method in ("average_acceleration", "central_difference", "rk4"):
        with pytest.raises(ValueError, match=match):
            getattr(ri, method)(**args, force=force)


def test_bad_parameters_are_refused():
    t = np.linspace(0, 1, 11)
    with pytest.raises(ValueError, match=r"gamma must be in \[0.5"):
        ri.newmark(1.0, 0.0, 1.0, t, 1.0, 0.0, gamma=0.4)
    with pytest.raises(ValueError, match=r"gamma must be in \[0.5"):
        ri.spectral_radius("newmark", 0.1, gamma=0.45, beta=0.25)
    with pytest.raises(ValueError, match="theta must be in"):
        ri.wilson(1.0, 0.0, 1.0, t, 1.0, 0.0, theta=0.5)
    with pytest.raises(ValueError, match="alpha must be in"):
        ri.hht_alpha(1.0, 0.0, 1.0, t, 1.0, 0.0, alpha=-0.5)
    with pytest.raises(TypeError, match="on_divergence"):  # one failure policy: the option is gone
        ri.rk4(1.0, 0.0, 1.0, t, 1.0, 0.0, on_divergence="ignore")
    with pytest.raises(ValueError, match="method must be one of"):
        ri.spectral_radius("leapfrog", 0.1)
    with pytest.raises(ValueError, match="method must be one of"):
        ri.integrate("leapfrog", 1.0, 0.0, 1.0, t, 1.0, 0.0)
    with pytest.raises(ValueError, match="dt_over_T must be > 0"):
        ri.amplification_matrix("rk4", 0.0)
    with pytest.raises(ValueError, match="damping_ratio must be in"):
        ri.period_elongation("rk4", 0.1, damping_ratio=1.0)
    with pytest.raises(TypeError, match="takes the parameters none, got unknown theta"):
        ri.spectral_radius("houbolt", 0.1, theta=1.4)
    with pytest.raises(TypeError, match="got unknown lam"):  # like any unexpected keyword
        ri.integrate("wilson", 1.0, 0.0, 1.0, t, 1.0, 0.0, lam=1.0)
    with pytest.raises(ValueError, match=r"method must be one of \['BDF', 'LSODA', 'Radau'\]"):
        ri.stiff(1.0, 0.0, 1.0, t, 1.0, 0.0, method="RK45")


def test_trapezoidal_fast_path_matches_the_newton_stepper():
    # average_acceleration runs a displacement-only recursion; newmark_newton steps x, v, a directly.
    chain = vibration.chain_matrices([1000.0, 800.0, 600.0], [1e6, 5e5, 2e5])
    M, K = chain.M, chain.K
    C = 1e-3 * K + 0.2 * M
    t = np.linspace(0.0, 5.0, 1001)
    load = np.zeros((3, t.size))
    load[2] = 1e3 * np.sin(7 * t)
    fast = ri.average_acceleration(M, C, K, t, [0.01, 0.0, -0.01], [0.0, 0.05, 0.0], load)
    slow = ri.newmark_newton(M, C, K, t, [0.01, 0.0, -0.01], [0.0, 0.05, 0.0], load)
    # Same scheme, different arithmetic: rounding over 1000 steps stays below 1e-10 of each peak.
    for name in ("x", "v", "a"):
        ours, theirs = getattr(fast, name), getattr(slow, name)
        assert np.abs(ours - theirs).max() < 1e-10 * np.abs(theirs).max(), name


def test_chapter_two_figures_show_the_central_difference_limit():
    from raildyn import figures

    fig = figures.make("fig2.spectral_radius")
    line = next(ln for ln in fig.axes[0].lines if ln.get_label() == "central difference")
    ratios, rho = line.get_data()
    # The curve sits on ρ = 1 up to Δt/T = 1/π and rises just above it (grid steps of 2.3 %).
    rising = ratios[~(rho <= 1 + 1e-9)].min()
    assert rising == pytest.approx(1 / np.pi, rel=0.03) and rising > 1 / np.pi
    assert np.allclose(rho[ratios < 0.3], 1.0, atol=1e-12)
    assert "fig2.period_elongation" in figures.REGISTRY


# ---------------------------------------------------------------- the modal path for classical damping


def _rayleigh_chain(n=12):
    chain = vibration.chain_matrices(np.linspace(800.0, 1200.0, n), np.linspace(0.8e6, 1.2e6, n))
    M, K = chain.M, chain.K
    w = vibration.modal_analysis(M, K).natural_frequencies
    coefficients = vibration.rayleigh_coefficients(w[0], w[-1], 0.03, 0.03)
    C = vibration.rayleigh_damping(M, K, coefficients.alpha, coefficients.beta)
    return M, C, K


def test_modal_newmark_equals_the_coupled_recursion_for_classical_damping():
    """Newmark commutes with the modal transform, so both paths agree to rounding (1e-11 of the peak)."""
    from raildyn.integrators import _common, linear

    M, C, K = _rayleigh_chain()
    t = np.arange(2001) * 0.01
    rng = np.random.default_rng(3)
    force = rng.normal(size=(M.shape[0], t.size)) * 1e3
    p = _common.problem(M, C, K, t, rng.normal(size=12) * 1e-3, rng.normal(size=12) * 1e-2)
    load = _common.sampled_load(force, p)
    bound = _common.scale(p, load)
    modes = linear._classical_modes(p)
    assert modes is not None
    x_m, v_m, a_m, bad = linear._modal_two_step(p, load, 0.5, 0.25, modes, bound)
    a0 = _common.equilibrium_acceleration(p, p.x0, p.v0, load[0])
    rec = linear.recursion_matrices(linear.newmark_step(M, C, K, p.h, 0.5, 0.25), 3 * p.n, p.n)
    x_c, v_c, _ = linear._two_step(p, load, 0.5, 0.25, rec.A, rec.B0, rec.B1, a0, bound)
    assert bad is None
    assert np.abs(x_m - x_c).max() <= 1e-11 * np.abs(x_c).max()
    assert np.abs(v_m - v_c).max() <= 1e-11 * np.abs(v_c).max()
    a_c = _common.equilibrium_acceleration(p, x_c, v_c, load)
    assert np.abs(a_m - a_c).max() <= 1e-10 * np.abs(a_c).max()


def test_non_classical_damping_takes_the_coupled_path():
    from raildyn.integrators import _common, linear

    M, C, K = _rayleigh_chain()
    C = C.copy()
    C[0, 0] += 5e3  # a damper on the first mass alone: Φᵀ C Φ is no longer diagonal
    p = _common.problem(M, C, K, np.arange(11) * 0.01, np.zeros(12), np.zeros(12))
    assert linear._classical_modes(p) is None
