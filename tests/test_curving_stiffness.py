"""Self-steering (raildyn.curving.stiffness): bending and shear stiffness, the closed-form steady curving of
two wheelsets joined by them, and the trade-off between stability and curving."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp  # solves the equilibrium symbolically (a dependency: the derivations' tool)
from matplotlib.figure import Figure

from raildyn.curving import steady_curving
from raildyn.curving.stiffness import (
    BendingShear,
    SelfSteeringCurving,
    StabilityCurving,
    bending_shear_stiffness,
    self_steering_curving,
    stability_and_curving,
)
from raildyn.stability import critical_speed
from raildyn.track import balance_speed
from raildyn.vehicles import Bogie, LateralCar
from raildyn.wheelset import Wheelset, pure_rolling_offset

# No spin, no gravitational stiffness: the assumptions of the closed form (Wickens 2003, ch. 7).
_PLAIN = dict(f23=0.0, f33=0.0, contact_angle=0.0, contact_angle_parameter=0.0)
# Primary (yaw N·m/rad, lateral N/m) pairs per wheelset: soft to stiff in yaw, soft to stiff in shear.
_PAIRS = [(1.0e6, 1.0e6), (5.0e6, 2.0e7), (31.4e6, 3.9e6), (62.8e6, 7.77e6), (2.0e8, 5.0e7)]


def _free_frame_bogie(k_psi: float, k_y: float) -> Bogie:
    """The Manchester bogie with no secondary suspension and the closed form's contact."""
    ws = Wheelset(**_PLAIN, yaw_stiffness=k_psi, lateral_stiffness=k_y)
    return Bogie(wheelset=ws, secondary_lateral_stiffness=0.0, secondary_yaw_stiffness=0.0)


# ---------------------------------------------------------------------------
# Bending and shear stiffness


def test_bending_and_shear_stiffness_are_the_frame_at_its_least_strain_energy():
    # Symbolic: minimise the primary springs' energy over the frame (y_f, ψ_f) and compare with
    # ½k_b(ψ₁ − ψ₂)² + ½k_s(y₁ − y₂ − b(ψ₁ + ψ₂))²; exact (sympy's simplify gives 0).
    y1, y2, p1, p2, yf, pf = sp.symbols("y1 y2 psi1 psi2 y_f psi_f", real=True)
    ky, kp, b = sp.symbols("k_y k_psi b", positive=True)
    U = (
        ky * ((y1 - yf - b * pf) ** 2 + (y2 - yf + b * pf) ** 2) + kp * ((p1 - pf) ** 2 + (p2 - pf) ** 2)
    ) / 2
    frame = sp.solve([sp.diff(U, yf), sp.diff(U, pf)], [yf, pf], dict=True)[0]
    kb = kp / 2
    ks = ky * kp / (2 * (kp + b**2 * ky))
    expected = kb * (p1 - p2) ** 2 / 2 + ks * (y1 - y2 - b * (p1 + p2)) ** 2 / 2
    assert sp.simplify(U.subs(frame) - expected) == 0
    for k_psi, k_y in _PAIRS:
        bogie = _free_frame_bogie(k_psi, k_y)
        s = bending_shear_stiffness(bogie)
        values = {kp: k_psi, ky: k_y, b: bogie.semi_wheelbase}
        assert s.bending == pytest.approx(float(kb.subs(values)), rel=1e-14)
        assert s.shear == pytest.approx(float(ks.subs(values)), rel=1e-14)


def test_no_primary_stiffness_gives_no_shear_stiffness():
    s = bending_shear_stiffness(Bogie().replace(yaw_stiffness=0.0, lateral_stiffness=0.0))
    assert (s.bending, s.shear) == (0.0, 0.0)
    s = bending_shear_stiffness(Bogie().replace(lateral_stiffness=0.0))
    assert s.shear == 0.0 and s.bending > 0.0


# ---------------------------------------------------------------------------
# The closed-form steady curving


def _symbolic_solution():
    """The four equilibrium equations of two wheelsets joined by k_b and k_s, solved by sympy.

    Local coordinates (y to the left, towards the curve's centre; ψ anticlockwise from the
    local tangent), a curve to the left of radius R at balance speed. Creep: lateral 2f₂₂ψ,
    yaw −2af₁₁(a/R + λy/r₀) (linear, no spin). The springs act on the coordinates in the
    vehicle's axes, where the wheelsets at x = ±b meet the track turned by ±b/R: the relative
    yaw is ψ₁ − ψ₂ + 2b/R, and the shear, y₁ − y₂ − b(ψ₁ + ψ₂), is the same in both axes.
    """
    y1, y2, p1, p2 = sp.symbols("y1 y2 psi1 psi2", real=True)
    kb, ks, b, R, a, r0, lam, f11, f22 = sp.symbols("k_b k_s b R a r_0 lambda f11 f22", positive=True)
    U = kb * (p1 - p2 + 2 * b / R) ** 2 / 2 + ks * (y1 - y2 - b * (p1 + p2)) ** 2 / 2
    equations = []
    for y, p in ((y1, p1), (y2, p2)):
        equations.append(2 * f22 * p - sp.diff(U, y))
        equations.append(-2 * a * f11 * (a / R + lam * y / r0) - sp.diff(U, p))
    solution = sp.solve(equations, [y1, y2, p1, p2], dict=True)
    assert len(solution) == 1  # a linear system with one solution
    symbols = (kb, ks, b, R, a, r0, lam, f11, f22)
    return sp.lambdify(symbols, [solution[0][q] for q in (y1, y2, p1, p2)]), symbols


def test_self_steering_curving_is_the_symbolic_solution_of_the_four_equations():
    # The closed form coded by hand against sympy's solution of the same equations, to round-off
    # (rtol 1e-12: a few operations on numbers of order 1e-3).
    solve, _ = _symbolic_solution()
    for k_psi, k_y in _PAIRS:
        bogie = _free_frame_bogie(k_psi, k_y)
        ws, k = bogie.wheelset, bending_shear_stiffness(bogie)
        for radius in (250.0, 600.0, 3000.0):
            y1, y2, p1, p2 = solve(
                k.bending,
                k.shear,
                bogie.semi_wheelbase,
                radius,
                ws.half_gauge,
                ws.rolling_radius,
                ws.conicity,
                ws.f11,
                ws.f22,
            )
            closed = self_steering_curving(bogie, radius)
            # offsets and angles of attack are positive towards the outer rail (to the right)
            np.testing.assert_allclose(closed.offset, [-y1, -y2], rtol=1e-12)
            np.testing.assert_allclose(closed.angle_of_attack, [-p1, -p2], rtol=1e-12)


@pytest.mark.parametrize(("k_psi", "k_y"), _PAIRS)
def test_steady_curving_of_the_bogie_reproduces_the_closed_form(k_psi, k_y, reference):
    # The "published linear steady-curving result" of issue 17: the closed form for two wheelsets
    # joined by a bending and a shear stiffness is derived here (test above, by sympy) by the
    # method of Wickens (2003, ch. 7) after Boocock (1969) — we do not quote the published
    # expressions. raildyn's 6-coordinate Bogie (frame included, no secondary suspension, no spin
    # or gravitational stiffness, at balance speed) must give the same state to round-off: rtol
    # 1e-9 on a solve of a 6 × 6 system whose stiffnesses span about 8 decades.
    bogie = _free_frame_bogie(k_psi, k_y)
    for radius, cant in ((300.0, 0.15), (600.0, 0.1), (2500.0, 0.05)):
        state = steady_curving(bogie, balance_speed(radius, cant), radius, cant)
        assert abs(state.unbalanced_acceleration) < 1e-12
        closed = self_steering_curving(bogie, radius)
        np.testing.assert_allclose(state.offset, closed.offset, rtol=1e-9)
        np.testing.assert_allclose(state.angle_of_attack, closed.angle_of_attack, rtol=1e-9)
    gap = np.abs(state.angle_of_attack / closed.angle_of_attack - 1).max()
    reference(
        8,
        f"bogie's angle of attack, k_ψ = {k_psi / 1e6:.3g} MN·m/rad, k_y = {k_y / 1e6:.3g} MN/m",
        "two wheelsets in bending and shear (Wickens 2003)",
        "closed form",
        gap,
        1e-9,
    )


def test_the_rigid_bogie_and_the_radial_limits():
    # A rigid bogie (k_b, k_s → ∞): α = b/R and the offset r₀a(1 + b²f₂₂/(a²f₁₁))/(λR) (Wickens 2003,
    # ch. 7; Garg & Dukkipati 1984, ch. 8). With k = 1e14 the angle's remainder is of order κ/(k_b k_s)
    # ≈ 1e-10 (rtol 1e-8), the offsets' of order f₂₂α/k_s ≈ 1e-9 m on 13.5 mm (rtol 1e-6).
    bogie = _free_frame_bogie(1.0e14, 1.0e14)
    ws, b, R = bogie.wheelset, bogie.semi_wheelbase, 600.0
    closed = self_steering_curving(bogie, R)
    np.testing.assert_allclose(closed.angle_of_attack, [b / R, -b / R], rtol=1e-8)
    y0 = pure_rolling_offset(ws.rolling_radius, ws.half_gauge, ws.conicity, R)
    rigid = y0 * (1 + b**2 * ws.f22 / (ws.half_gauge**2 * ws.f11))
    np.testing.assert_allclose(closed.offset, [rigid, rigid], rtol=1e-6)
    # A very soft bending stiffness (k_ψ = 1 N·m/rad): the wheelsets turn radial and roll at the
    # pure-rolling offset; the remainders are of order k_b/κ ≈ 1e-7 relative (rtol 1e-6).
    soft = self_steering_curving(_free_frame_bogie(1.0, 1.0e7), R)
    assert np.abs(soft.angle_of_attack).max() < 1e-6 * b / R
    np.testing.assert_allclose(soft.offset, [y0, y0], rtol=1e-6)


def test_the_angle_of_attack_grows_with_the_bending_stiffness():
    R = 600.0
    alphas = [
        self_steering_curving(_free_frame_bogie(k, 7.77e6), R).angle_of_attack[0]
        for k in np.geomspace(1e5, 1e9, 9)
    ]
    assert np.all(np.diff(alphas) > 0) and 0 < alphas[0] < alphas[-1] < 1.28 / R


def test_self_steering_curving_refuses_bad_input():
    with pytest.raises(TypeError, match="bogie"):
        self_steering_curving(LateralCar(), 600.0)
    with pytest.raises(ValueError, match="radius"):
        self_steering_curving(Bogie(), -1.0)
    with pytest.raises(ValueError, match="conicity"):
        self_steering_curving(Bogie().replace(conicity=0.0), 600.0)
    with pytest.raises(ValueError, match="shear"):
        self_steering_curving(Bogie().replace(lateral_stiffness=0.0), 600.0)
    with pytest.raises(ValueError, match="bending"):
        BendingShear(-1.0, 1.0)
    with pytest.raises(ValueError, match="offset"):
        SelfSteeringCurving(600.0, BendingShear(1.0, 1.0), np.array([np.nan, 0.0]), np.zeros(2))


# ---------------------------------------------------------------------------
# The trade-off


_KS = np.geomspace(2.0e6, 50.0e6, 8)  # N·m/rad per wheelset, below the car's own 62.8 MN·m/rad


@pytest.fixture(scope="module")
def tradeoff() -> StabilityCurving:
    # The Manchester car at its balance speed in a 600 m curve with 100 mm of cant.
    return stability_and_curving(LateralCar(), _KS, balance_speed(600.0, 0.1), 600.0, 0.1, tol=0.01)


def test_tradeoff_agrees_with_critical_speed_and_steady_curving_one_by_one(tradeoff):
    # The batched critical speeds against chapter 7's critical_speed (both to tol = 0.01 m/s, so they may
    # differ by 2 tol), and the batched steady states against steady_curving (one linear solve each:
    # round-off, rtol 1e-9).
    car = LateralCar()
    for k, v, alpha in zip(_KS, tradeoff.critical_speed, tradeoff.angle_of_attack, strict=True):
        model = car.replace(yaw_stiffness=float(k))
        assert v == pytest.approx(critical_speed(model, (1.0, 150.0), tol=0.01).speed, abs=0.02)
        state = steady_curving(model, tradeoff.speed, 600.0, 0.1)
        assert alpha == pytest.approx(state.angle_of_attack[int(np.argmax(state.positions))], rel=1e-9)
    assert tradeoff.status == ("crossing",) * _KS.size


def test_a_stiffer_yaw_raises_the_critical_speed_and_the_angle_of_attack(tradeoff):
    # The trade-off: k_ψ holds the wheelsets against the kinematic oscillation (Wickens' V_c² grows with
    # k_ψ, chapter 5) and, through the bending stiffness k_b = k_ψ/2, against the relative yaw 2b/R they
    # need to stand radial in the curve (self_steering_curving). Both rise over 2–50 MN·m/rad; the car's
    # critical speed levels off near its own 62.8 MN·m/rad, where the body's modes take over.
    assert np.all(np.diff(tradeoff.critical_speed) > 0)
    assert np.all(np.diff(tradeoff.angle_of_attack) > 0)
    b, R = LateralCar().bogie.semi_wheelbase, 600.0
    assert tradeoff.angle_of_attack[-1] < b / R


def test_a_bogie_under_a_still_body_shows_the_same_trade_off():
    # The bogie's critical speed levels off near 79 m/s above about 40 MN·m/rad (measured), so 1–30 here.
    r = stability_and_curving(Bogie(), np.geomspace(1e6, 3e7, 6), balance_speed(1000.0, 0.1), 1000.0, 0.1)
    assert np.all(np.diff(r.angle_of_attack) > 0)
    assert np.all(np.diff(r.critical_speed) > 0)


def test_a_range_with_no_crossing_gives_inf_and_its_status():
    r = stability_and_curving(LateralCar(), [20e6, 40e6], 20.0, 600.0, 0.05, speed_range=(1.0, 10.0), scan=8)
    assert np.all(np.isposinf(r.critical_speed))
    assert r.status == ("stable over the range",) * 2


def test_the_plot_moves_in_place(tradeoff):
    ax = Figure().subplots()
    artists = tradeoff.plot(ax)
    again = stability_and_curving(LateralCar(), _KS, 25.0, 800.0, 0.05, scan=8)
    assert again.plot(artists=artists) is artists
    np.testing.assert_allclose(artists["attack"].get_ydata(), 1e3 * again.angle_of_attack)
    np.testing.assert_allclose(artists["critical"].get_ydata(), 3.6 * again.critical_speed)
    assert len(ax.figure.axes) == 2  # the twin axis was made once


class _UnhashableCar(LateralCar):
    """The car that cannot be hashed, so that nothing of it is kept."""

    __hash__ = None


def test_a_new_curve_reuses_the_critical_speeds_and_an_unhashable_model_gets_the_same(monkeypatch):
    from raildyn.curving import stiffness

    stiffness._kept_critical_speeds.cache_clear()
    searches = []
    search = stiffness.critical_speeds
    monkeypatch.setattr(stiffness, "critical_speeds", lambda *a, **k: searches.append(1) or search(*a, **k))
    car = LateralCar().replace(conicity=0.21)
    first = stability_and_curving(car, _KS, balance_speed(600.0, 0.1), 600.0, 0.1, scan=8)
    other = stability_and_curving(car, _KS, balance_speed(1500.0, 0.1), 1500.0, 0.1, scan=8)
    assert len(searches) == 1  # the critical speeds do not depend on the curve
    np.testing.assert_array_equal(first.critical_speed, other.critical_speed)
    assert not np.array_equal(first.angle_of_attack, other.angle_of_attack)
    first.critical_speed[0] = -1.0  # each result has its own arrays: nothing kept is changed
    assert other.critical_speed[0] > 0
    plain = stability_and_curving(
        _UnhashableCar().replace(conicity=0.21), _KS, balance_speed(1500.0, 0.1), 1500.0, 0.1, scan=8
    )
    assert len(searches) == 2  # searched afresh
    np.testing.assert_array_equal(plain.critical_speed, other.critical_speed)
    np.testing.assert_array_equal(plain.angle_of_attack, other.angle_of_attack)


def test_stability_and_curving_refuses_bad_input():
    car = LateralCar()
    with pytest.raises(TypeError, match="model"):
        stability_and_curving(car.linear_system(), [1e6], 20.0, 600.0)
    with pytest.raises(ValueError, match="yaw_stiffnesses"):
        stability_and_curving(car, [2e6, 1e6], 20.0, 600.0)
    with pytest.raises(ValueError, match="yaw_stiffnesses"):
        stability_and_curving(car, [-1.0], 20.0, 600.0)
    with pytest.raises(ValueError, match="yaw_stiffnesses"):
        stability_and_curving(car, [], 20.0, 600.0)
    with pytest.raises(ValueError, match="radius"):
        stability_and_curving(car, [1e6], 20.0, 10.0)
    with pytest.raises(ValueError, match="speed"):
        stability_and_curving(car, [1e6], 0.0, 600.0)
    with pytest.raises(ValueError, match="cant"):
        stability_and_curving(car, [1e6], 20.0, 600.0, 0.5)
    with pytest.raises(ValueError, match="speed_range"):
        stability_and_curving(car, [1e6], 20.0, 600.0, speed_range=(10.0, 5.0))
    with pytest.raises(ValueError, match="scan"):
        stability_and_curving(car, [1e6], 20.0, 600.0, scan=2)
    with pytest.raises(ValueError, match="tol"):
        stability_and_curving(car, [1e6], 20.0, 600.0, tol=0.0)
    with pytest.raises(ValueError, match="critical_speed"):
        StabilityCurving(
            np.array([1.0]), np.array([np.inf]), ("crossing",), np.zeros(1), 1.0, 600.0, 0.0, (1, 2)
        )
