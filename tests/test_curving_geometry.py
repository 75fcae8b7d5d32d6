"""raildyn.curving.geometry: cant, cant deficiency, balance speed; curves with clothoid transitions."""

import math

import numpy as np
import pytest
import scipy.integrate
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib.figure import Figure

from raildyn.constants import GRAVITY, STANDARD_RAIL_SPACING
from raildyn.track import (
    CANT_GRADIENT_LIMIT,
    MAXIMUM_CANT,
    MINIMUM_RADIUS,
    Curve,
    balance_speed,
    cant_deficiency,
    equilibrium_cant,
    speed_for_deficiency,
    unbalanced_acceleration,
)

radii = st.floats(MINIMUM_RADIUS, 1e5)
cants = st.floats(0.0, MAXIMUM_CANT)
speeds = st.floats(0.0, 100.0)

# ---------------------------------------------------------------------------
# Cant and speed: closed forms


def test_equilibrium_cant_by_hand():
    # G V²/(g R) for V = 40 m/s, R = 1000 m, G = 1.5 m: 2400/9806.65 m, to rounding.
    assert equilibrium_cant(40.0, 1000.0) == pytest.approx(2400.0 / (GRAVITY * 1000.0), rel=1e-15)


def test_equilibrium_cant_is_en_13803s_11_8_v2_over_r():
    # EN 13803 states the equilibrium cant of standard-gauge track as 11.8 V²/R (mm, V in km/h,
    # R in m), from G = 1500 mm: 1500/(3.6² g) = 11.7996..., which the standard rounds to 11.8.
    coefficient = equilibrium_cant(1 / 3.6, MINIMUM_RADIUS) * 1000 * MINIMUM_RADIUS
    assert round(coefficient, 1) == 11.8
    # So 160 km/h on 1500 m needs 201.4 mm (11.8 · 160²/1500 = 201.39 mm, within 11.8's rounding of 4e-3).
    assert equilibrium_cant(160 / 3.6, 1500.0) * 1000 == pytest.approx(11.8 * 160**2 / 1500, rel=4e-3)


def test_at_the_balance_speed_deficiency_and_acceleration_vanish():
    # One convention (small angle): V_b = √(gRD/G) gives I = 0 and a_q = g I/G = 0 to rounding.
    R, D = 600.0, 0.12
    Vb = balance_speed(R, D)
    assert Vb == pytest.approx(math.sqrt(GRAVITY * R * D / STANDARD_RAIL_SPACING), rel=1e-15)
    assert cant_deficiency(Vb, R, D) == pytest.approx(0.0, abs=1e-15)
    assert unbalanced_acceleration(Vb, R, D) == pytest.approx(0.0, abs=1e-14)
    # The exact in-plane acceleration there is −g sin φ (1 − cos φ): O(φ³), 3.9e-5 g at φ = 0.08.
    phi = math.asin(D / STANDARD_RAIL_SPACING)
    exact = unbalanced_acceleration(Vb, R, D, exact=True)
    assert exact == pytest.approx(-GRAVITY * math.sin(phi) * (1 - math.cos(phi)), rel=1e-10)


def test_standing_still_the_deficiency_is_minus_the_cant():
    # V = 0: a cant excess equal to the cant, and a_q = −g D/G (small angle) or −g sin φ (exact).
    assert cant_deficiency(0.0, 800.0, 0.15) == -0.15
    assert unbalanced_acceleration(0.0, 800.0, 0.15) == pytest.approx(-GRAVITY * 0.1, rel=1e-15)
    assert unbalanced_acceleration(0.0, 800.0, 0.15, exact=True) == pytest.approx(-GRAVITY * 0.1, rel=1e-15)


def test_infinite_radius_limit_needs_no_cant():
    # D_eq = G V²/(g R) → 0 as 1/R.
    R = np.array([1e3, 1e6, 1e9, 1e12])
    d = equilibrium_cant(50.0, R)
    assert np.allclose(d * R, d[0] * R[0], rtol=1e-14)
    assert d[-1] < 1e-9


def test_unbalanced_acceleration_by_hand():
    # 120 km/h, R = 600 m, D = 0.1 m: V²/R = 1.85185 m/s², g D/G = 0.65378 m/s²: small form their difference.
    V, R, D, G = 120 / 3.6, 600.0, 0.1, 1.5
    assert unbalanced_acceleration(V, R, D) == pytest.approx(V**2 / R - GRAVITY * D / G, rel=1e-14)
    phi = math.asin(D / G)
    expected = V**2 / R * math.cos(phi) - GRAVITY * math.sin(phi)
    assert unbalanced_acceleration(V, R, D, exact=True) == pytest.approx(expected, rel=1e-14)


@settings(max_examples=200, deadline=None)
@given(speeds, radii, cants, st.floats(0.9, 1.8))
def test_exact_and_small_angle_accelerations_agree_to_second_order(V, R, D, G):
    # exact = small · cos φ − g sin φ (1 − cos φ), an identity (rounding: 1e-12 of the larger terms);
    # hence |exact − small| ≤ (|small| + g sin φ)(1 − cos φ) ≤ (|small| + g φ) φ²/2.
    small = unbalanced_acceleration(V, R, D, G)
    exact = unbalanced_acceleration(V, R, D, G, exact=True)
    s = D / G
    c = math.sqrt(1 - s * s)
    scale = V**2 / R + GRAVITY
    assert exact == pytest.approx(small * c - GRAVITY * s * (1 - c), abs=1e-12 * scale)
    assert abs(exact - small) <= (abs(small) + GRAVITY * s) * (1 - c) + 1e-12 * scale


@settings(max_examples=200, deadline=None)
@given(radii, cants, st.floats(-1.0, 1.0))
def test_speed_for_deficiency_inverts_the_deficiency(R, D, fraction):
    # I from −D (standing) to D + 0.3 m; the round trip holds to rounding (1e-12 m on metres of cant).
    I = -D + (fraction + 1.0) / 2.0 * (2 * D + 0.3)  # noqa: E741
    V = speed_for_deficiency(R, D, I)
    if V <= 200.0:
        assert cant_deficiency(V, R, D) == pytest.approx(I, abs=1e-12)
    assert speed_for_deficiency(R, D, 0.0) == pytest.approx(balance_speed(R, D), rel=1e-15)


@settings(max_examples=100, deadline=None)
@given(radii, cants, speeds, speeds)
def test_deficiency_grows_with_speed(R, D, V1, V2):
    lo, hi = sorted((V1, V2))
    assert cant_deficiency(lo, R, D) <= cant_deficiency(hi, R, D)


def test_arrays_broadcast_like_the_single_numbers():
    V = np.array([10.0, 30.0, 50.0])[:, None]
    R = np.array([300.0, 1000.0])
    out = cant_deficiency(V, R, 0.1)
    assert out.shape == (3, 2)
    for i in range(3):
        for j in range(2):
            assert out[i, j] == cant_deficiency(float(V[i, 0]), float(R[j]), 0.1)
    assert isinstance(balance_speed(600.0, 0.1), float)
    assert balance_speed([600.0, 2400.0], 0.1)[1] == pytest.approx(2 * balance_speed(600.0, 0.1), rel=1e-15)


# ---------------------------------------------------------------------------
# The curve: closed forms


def test_segment_ends_and_deflection():
    c = Curve(radius=600.0, cant=0.1, transition_length=60.0, arc_length=200.0, straight=50.0)
    assert c.length == 370.0
    # Total deflection (L + arc)/R; the clothoid turns L/(2R), the arc arc/R.
    assert c.heading(c.length) == pytest.approx(260.0 / 600.0, rel=1e-15)
    assert c.heading(1e4) == pytest.approx(260.0 / 600.0, rel=1e-15)
    assert c.heading(-5.0) == 0.0 and c.y(-5.0) == 0.0 and c.x(-5.0) == -5.0


@pytest.mark.parametrize("R, L", [(600.0, 60.0), (150.0, 90.0), (4000.0, 250.0)])
def test_clothoid_ends_at_heading_l_over_2r_and_curvature_1_over_r(R, L):
    c = Curve(radius=R, cant=0.1, transition_length=L, arc_length=100.0, straight=20.0)
    s0, s1 = 20.0, 20.0 + L
    assert c.heading(s1) == pytest.approx(L / (2 * R), rel=1e-15)
    assert c.curvature(s1) == pytest.approx(1 / R, rel=1e-15)
    # Curvature linear in the distance: a quarter of the way along, a quarter of 1/R.
    assert c.curvature(s0 + L / 4) == pytest.approx(1 / (4 * R), rel=1e-14)
    # The exit mirrors the entry.
    u = np.linspace(0.0, L, 7)
    assert np.allclose(c.curvature(c.length - u), c.curvature(s0 + u), rtol=1e-14, atol=0)


@pytest.mark.parametrize("R, L", [(600.0, 60.0), (200.0, 100.0)])
def test_clothoid_end_point_against_its_series(R, L):
    # The clothoid's end, from the series of cos and sin of θ = u²/(2RL) integrated term by term:
    # x = Σ (−1)ⁿ L^(2n+1) / ((4n+1) (2n)! (2R)^(2n))     = L − L³/(40R²) + L⁵/(3456R⁴) − …
    # y = Σ (−1)ⁿ L^(2n+2) / ((4n+3) (2n+1)! (2R)^(2n+1)) = L²/(6R) − L⁴/(336R³) + …
    # (the classical transition-curve series; L²/(6R) is the cubic parabola's offset). Both
    # alternate with falling terms, so four terms are within the fifth: the tolerance.
    c = Curve(radius=R, cant=0.0, transition_length=L, arc_length=10.0, straight=0.0)
    n = np.arange(5)
    factorial = np.array([math.factorial(k) for k in range(10)], dtype=float)
    x_terms = (-1.0) ** n * L ** (2 * n + 1) / ((4 * n + 1) * factorial[2 * n] * (2 * R) ** (2 * n))
    y_terms = (-1.0) ** n * L ** (2 * n + 2) / ((4 * n + 3) * factorial[2 * n + 1] * (2 * R) ** (2 * n + 1))
    assert x_terms[1] == pytest.approx(-(L**3) / (40 * R**2), rel=1e-15)
    assert y_terms[0] == pytest.approx(L**2 / (6 * R), rel=1e-15)
    assert c.x(L) == pytest.approx(sum(x_terms[:4]), abs=abs(x_terms[4]) + 1e-12)
    assert c.y(L) == pytest.approx(sum(y_terms[:4]), abs=abs(y_terms[4]) + 1e-12)


def test_the_arc_keeps_its_distance_from_its_centre():
    c = Curve()
    s1, s2 = 110.0, 310.0
    th1 = c.heading(s1)
    cx, cy = c.x(s1) - c.radius * math.sin(th1), c.y(s1) + c.radius * math.cos(th1)
    s = np.linspace(s1, s2, 41)
    # closed form on a 600 m radius: rounding of a few 1e-13 m
    assert np.allclose(np.hypot(c.x(s) - cx, c.y(s) - cy), c.radius, rtol=0, atol=1e-9)


def _integrated_plan(c: Curve, s: np.ndarray):
    """x, y by quadrature of cos θ and sin θ, with the segment ends as break points."""
    ends = [e for e in c.ends() if e > 0]
    out = []
    for t in s:
        if t <= 0:
            out.append((t, 0.0))
            continue
        pts = [e for e in ends if e < t] or None
        opts = dict(points=pts, epsabs=1e-13, epsrel=1e-13, limit=200)
        x = scipy.integrate.quad(lambda u: math.cos(c.heading(u)), 0.0, t, **opts)[0]
        y = scipy.integrate.quad(lambda u: math.sin(c.heading(u)), 0.0, t, **opts)[0]
        out.append((x, y))
    return np.array(out).T


@pytest.mark.parametrize(
    "curve",
    [
        Curve(),
        Curve(radius=150.0, cant=0.15, transition_length=80.0, arc_length=60.0, straight=10.0),
        Curve(radius=2000.0, cant=0.18, transition_length=0.0, arc_length=300.0, straight=0.0),
        Curve(radius=300.0, cant=0.1, transition_length=120.0, arc_length=0.0, straight=30.0),
    ],
)
def test_plan_coordinates_against_integration_of_the_heading(curve):
    # Gauss–Kronrod on smooth pieces (the break points split at the curvature's kinks) is accurate to
    # ~1e-13 relative over a few hundred metres; Fresnel's integrals (Cephes) to ~1e-15 relative of
    # a = √(πRL) ≈ 300 m. 1e-8 m leaves a margin of more than 100 over both.
    s = np.linspace(-10.0, curve.length + 40.0, 37)
    xi, yi = _integrated_plan(curve, s)
    assert np.abs(curve.x(s) - xi).max() < 1e-8
    assert np.abs(curve.y(s) - yi).max() < 1e-8


def test_heading_is_the_integral_of_the_curvature():
    # Central differences of θ against κ: error h²/6 · κ'' (κ'' = 0 inside a piece); 1e-9 1/m covers
    # the rounding of θ (1e-16) over 2h = 2e-3 m.
    c = Curve()
    s = np.linspace(1.0, 369.0, 200)
    s = s[np.min(np.abs(s[:, None] - np.array(c.ends())[None, :]), axis=1) > 1e-2]
    h = 1e-3
    derivative = (c.heading(s + h) - c.heading(s - h)) / (2 * h)
    assert np.allclose(derivative, c.curvature(s), rtol=0, atol=1e-9)


def test_infinite_radius_limit_is_a_straight():
    # R = 1e12 m: κ ≤ 1e-12 1/m, and y ≤ s²/(2R) ≈ 1e-7 m after 400 m.
    c = Curve(radius=1e12, cant=0.1)
    s = np.linspace(0.0, 400.0, 81)
    assert np.abs(c.curvature(s)).max() <= 1e-12
    assert np.abs(c.y(s)).max() <= 400.0**2 / (2 * 1e12) + 1e-15
    assert np.allclose(c.x(s), s, rtol=0, atol=1e-9)


def test_cant_ramp_gradient_and_twist():
    c = Curve(radius=600.0, cant=0.12, transition_length=80.0, arc_length=100.0, straight=50.0)
    assert c.cant_at(50.0 + 40.0) == pytest.approx(0.06, rel=1e-15)
    assert c.cant_at(200.0) == 0.12 and c.cant_at(0.0) == 0.0
    # dD/ds = D/L = 1.5 mm/m on the entry, −1.5 mm/m on the exit, within EN 13803's 2.25 mm/m.
    assert c.cant_gradient(60.0) == pytest.approx(1.5e-3, rel=1e-15)
    assert c.cant_gradient(260.0) == pytest.approx(-1.5e-3, rel=1e-15)
    assert c.cant_gradient(200.0) == 0.0
    assert c.cant_gradient(60.0) < CANT_GRADIENT_LIMIT
    # The twist over a 2.5 m wheelbase wholly on the ramp equals the gradient (a linear ramp).
    assert c.twist(70.0, base=2.5) == pytest.approx(1.5e-3, rel=1e-12)
    # Straddling the ramp's end it is less: axles at 131 and 128.5 m, 1 m of ramp in the base.
    assert c.twist(131.0, base=2.5) == pytest.approx(1.5e-3 * 1.5 / 2.5, rel=1e-12)


def test_no_transition_steps_the_cant_and_the_twist_stays_finite():
    c = Curve(radius=800.0, cant=0.1, transition_length=0.0, arc_length=100.0, straight=20.0)
    assert c.cant_at(20.0) == 0.0 and c.cant_at(20.0 + 1e-9) == 0.1
    assert np.all(c.cant_gradient(np.linspace(0, 150, 31)) == 0.0)
    assert c.twist(21.0, base=3.0) == pytest.approx(0.1 / 3.0, rel=1e-15)  # 33 mm/m over 3 m


def test_replace_checks_again():
    c = Curve().replace(radius=800.0)
    assert c.radius == 800.0 and c.cant == Curve().cant
    with pytest.raises(ValueError, match="radius"):
        Curve().replace(radius=10.0)


@pytest.mark.parametrize("view", ["plan", "curvature", "cant"])
def test_plot_returns_its_artists(view):
    ax = Figure().subplots()
    artists = Curve().plot(ax, view=view)
    assert set(artists) == {"line", "ends"}
    assert artists["line"].axes is ax
    assert len(artists["ends"].get_xdata()) == 4


def test_plot_plan_draws_the_coordinates():
    c = Curve()
    line = c.plot(Figure().subplots())["line"]
    x, y = line.get_data()
    assert np.allclose(y[-1], c.y(c.length + max(0.1 * c.length, 10.0)), atol=1e-9)


# ---------------------------------------------------------------------------
# Bad input, by name


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: equilibrium_cant(30.0, 0.0), "radius"),
        (lambda: equilibrium_cant(30.0, 40.0), "radius"),  # below the 50 m minimum
        (lambda: equilibrium_cant(-1.0, 600.0), "speed"),
        (lambda: equilibrium_cant(250.0, 600.0), "speed"),  # above 200 m/s: km/h by mistake?
        (lambda: equilibrium_cant(30.0, 600.0, 3.0), "rail_spacing"),
        (lambda: cant_deficiency(30.0, 600.0, 0.25), "cant"),  # beyond the 0.2 m limit
        (lambda: cant_deficiency(30.0, 600.0, -0.01), "cant"),
        (lambda: cant_deficiency([30.0, 40.0], [600.0, 700.0, 800.0], 0.1), "radius"),
        (lambda: balance_speed(600.0, math.nan), "cant"),
        (lambda: speed_for_deficiency(600.0, 0.1, -0.15), "deficiency"),
        (lambda: Curve(radius=-600.0), "radius"),
        (lambda: Curve(cant=0.3), "cant"),
        (lambda: Curve(transition_length=-1.0), "transition_length"),
        (lambda: Curve(arc_length=-1.0), "arc_length"),
        (lambda: Curve(straight=math.inf), "straight"),
        (lambda: Curve().curvature([0.0, math.nan]), "s"),
        (lambda: Curve().x([]), "s"),
        (lambda: Curve().twist(10.0, base=0.0), "base"),
        (lambda: Curve().plot(Figure().subplots(), view="elevation"), "view"),
    ],
)
def test_bad_input_is_refused_by_name(call, name):
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        call()


def test_wrong_types_are_type_errors():
    with pytest.raises(TypeError, match="exact"):
        unbalanced_acceleration(30.0, 600.0, 0.1, exact="yes")
    with pytest.raises(TypeError, match="radius"):
        Curve(radius="600")
    with pytest.raises(TypeError, match="ax"):
        Curve().plot(ax="axes")
