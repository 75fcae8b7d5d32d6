"""raildyn.curving.climb: Nadal's limit, Weinstock's axle-sum criterion, the wheel-climb check."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib.figure import Figure

from raildyn.curving.climb import (
    MAXIMUM_FRICTION,
    WheelClimb,
    nadal_limit,
    plot_nadal_limit,
    weinstock_limit,
    wheel_climb,
)

angles = st.floats(math.radians(1.0), math.radians(89.0))
frictions = st.floats(0.0, MAXIMUM_FRICTION)

# ---------------------------------------------------------------------------
# Nadal: closed forms and published values


@settings(max_examples=200, deadline=None)
@given(angles)
def test_without_friction_nadal_is_tan_delta(delta):
    assert nadal_limit(delta, 0.0) == pytest.approx(math.tan(delta), rel=1e-15)


@settings(max_examples=200, deadline=None)
@given(angles, frictions, st.floats(1e3, 1e6))
def test_nadal_is_the_force_balance_at_the_flange(delta, mu, N):
    # Flange contact at δ, normal force N and friction μN down the flange (resisting climb, at the
    # limit of sliding). Their lateral and vertical resultants: Y = N sin δ − μN cos δ,
    # Q = N cos δ + μN sin δ; Y/Q is Nadal's quotient (rounding: 1e-13 of tan δ's scale).
    Y = N * math.sin(delta) - mu * N * math.cos(delta)
    Q = N * math.cos(delta) + mu * N * math.sin(delta)
    assert nadal_limit(delta, mu) == pytest.approx(Y / Q, abs=1e-13 * (1 + math.tan(delta)))


def test_published_values():
    # Wu & Wilson (2006), in Iwnicki (ed.), Handbook of Railway Vehicle Dynamics, ch. 8: a 75° flange
    # with μ = 0.5 has Nadal's limit 1.13 (given to 3 figures: ±0.005).
    assert nadal_limit(math.radians(75.0), 0.5) == pytest.approx(1.13, abs=0.005)
    # The Y/Q limit 1.2 of UIC 518 / EN 14363 is Nadal's for δ = 70° and μ = 0.36 (2 figures: ±0.05;
    # the formula gives 1.2003).
    assert nadal_limit(math.radians(70.0), 0.36) == pytest.approx(1.2, abs=0.005)


def test_by_hand():
    # tan 60° = √3; μ = 0.25: (√3 − 0.25)/(1 + 0.25√3) = 1.0339.
    r3 = math.sqrt(3.0)
    assert nadal_limit(math.pi / 3, 0.25) == pytest.approx((r3 - 0.25) / (1 + 0.25 * r3), rel=1e-15)
    # μ = tan δ: friction balances the slope, the limit is 0; beyond, negative.
    assert nadal_limit(math.atan(0.5), 0.5) == pytest.approx(0.0, abs=1e-15)
    assert nadal_limit(math.atan(0.5), 0.6) < 0


@settings(max_examples=200, deadline=None)
@given(angles, angles, frictions, frictions)
def test_nadal_grows_with_the_flange_angle_and_falls_with_friction(d1, d2, m1, m2):
    lo_d, hi_d = sorted((d1, d2))
    lo_m, hi_m = sorted((m1, m2))
    assert nadal_limit(lo_d, m1) <= nadal_limit(hi_d, m1) + 1e-12
    assert nadal_limit(d1, hi_m) <= nadal_limit(d1, lo_m) + 1e-12


def test_nadal_is_vectorised():
    delta = np.radians([60.0, 65.0, 70.0, 75.0])[:, None]
    mu = np.array([0.1, 0.3, 0.5])
    out = nadal_limit(delta, mu)
    assert out.shape == (4, 3)
    assert out[2, 1] == nadal_limit(math.radians(70.0), 0.3)
    assert isinstance(nadal_limit(1.2, 0.3), float)


# ---------------------------------------------------------------------------
# Weinstock


@settings(max_examples=200, deadline=None)
@given(angles, frictions, frictions)
def test_weinstock_is_nadal_plus_the_other_friction_and_never_below_it(delta, mu, mu2):
    w = weinstock_limit(delta, mu, mu2)
    assert w == pytest.approx(nadal_limit(delta, mu) + mu2, rel=1e-15, abs=1e-15)
    assert w >= nadal_limit(delta, mu)
    assert weinstock_limit(delta, mu) == pytest.approx(nadal_limit(delta, mu) + mu, rel=1e-15, abs=1e-15)


def test_weinstock_at_the_published_nadal_value():
    # 75° and μ = 0.5 on both wheels: the 1.13 of Wu & Wilson (2006) plus the other wheel's 0.5.
    assert weinstock_limit(math.radians(75.0), 0.5) == pytest.approx(1.63, abs=0.005)


# ---------------------------------------------------------------------------
# The check of an axle's forces


def test_wheel_climb_of_one_axle():
    # Flanging wheel 0: Y/Q = 45/60 = 0.75; the other −20/50 = −0.4; axle sum 1.15.
    r = wheel_climb([45e3, -20e3], [60e3, 50e3], math.radians(70.0), 0.3, 0.2)
    assert isinstance(r, WheelClimb)
    assert np.allclose(r.wheel_quotient, [0.75, -0.4], rtol=1e-15)
    assert r.flanging_wheel == 0
    assert r.flange_quotient == pytest.approx(0.75, rel=1e-15)
    assert r.axle_sum == pytest.approx(1.15, rel=1e-15)
    assert r.nadal_limit == nadal_limit(math.radians(70.0), 0.3)
    assert r.weinstock_limit == pytest.approx(r.nadal_limit + 0.2, rel=1e-15)
    assert not r.nadal_exceeded and not r.weinstock_exceeded


def test_the_flanging_wheel_is_the_one_of_larger_quotient():
    r = wheel_climb([-10e3, 70e3], [60e3, 55e3], math.radians(68.0), 0.5)
    assert r.flanging_wheel == 1
    assert r.flange_quotient == pytest.approx(70 / 55, rel=1e-15)
    assert bool(r.nadal_exceeded) == (70 / 55 > nadal_limit(math.radians(68.0), 0.5))


def test_a_history_of_forces_is_checked_row_by_row():
    Y = np.array([[10e3, -5e3], [40e3, -30e3], [-2e3, 75e3]])
    Q = np.full((3, 2), 60e3)
    r = wheel_climb(Y, Q, math.radians(70.0), 0.4)
    assert r.wheel_quotient.shape == (3, 2)
    assert list(r.flanging_wheel) == [0, 0, 1]
    assert np.allclose(r.axle_sum, np.abs(Y / Q).sum(axis=1), rtol=1e-15)
    # Nadal at 70°, μ = 0.4: 1.1178; the third row's 1.25 passes it.
    assert list(r.nadal_exceeded) == [False, False, True]


def test_plots_return_their_artists():
    ax = Figure().subplots()
    lines = plot_nadal_limit(ax, friction=(0.0, 0.3), flange_angle=np.radians([60.0, 70.0]))
    assert set(lines) == {"friction 0", "friction 0.3"}
    x, y = lines["friction 0"].get_data()
    assert np.allclose(x, [60.0, 70.0]) and np.allclose(y, np.tan(np.radians([60.0, 70.0])), rtol=1e-14)
    r = wheel_climb([45e3, -20e3], [60e3, 50e3], math.radians(70.0), 0.3)
    artists = r.plot(Figure().subplots())
    assert set(artists) == {"flange", "axle_sum", "nadal", "weinstock"}
    assert artists["nadal"].get_ydata()[0] == r.nadal_limit


# ---------------------------------------------------------------------------
# Bad input, by name


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: nadal_limit(70.0, 0.3), "flange_angle"),  # degrees by mistake
        (lambda: nadal_limit(0.0, 0.3), "flange_angle"),
        (lambda: nadal_limit(1.2, -0.1), "friction"),
        (lambda: nadal_limit(1.2, 30.0), "friction"),  # a percentage by mistake
        (lambda: nadal_limit([1.1, 1.2], [0.1, 0.2, 0.3]), "friction"),
        (lambda: weinstock_limit(1.2, 0.3, 1.5), "other_friction"),
        (lambda: wheel_climb([1e3, 2e3], [6e4, 0.0], 1.2, 0.3), "vertical"),
        (lambda: wheel_climb([1e3, 2e3, 3e3], [6e4, 6e4, 6e4], 1.2, 0.3), "lateral"),
        (lambda: wheel_climb([1e3, 2e3], [[6e4, 6e4]], 1.2, 0.3), "vertical"),
        (lambda: wheel_climb([1e3, math.nan], [6e4, 6e4], 1.2, 0.3), "lateral"),
        (lambda: plot_nadal_limit(Figure().subplots(), friction=[[0.1, 0.2]]), "friction"),
        (lambda: plot_nadal_limit(Figure().subplots(), flange_angle=[1.2, 1.1]), "flange_angle"),
    ],
)
def test_bad_input_is_refused_by_name(call, name):
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        call()


def test_wrong_types_are_type_errors():
    with pytest.raises(TypeError, match="friction"):
        nadal_limit(1.2, "0.3")
    with pytest.raises(TypeError, match="ax"):
        plot_nadal_limit(ax="axes")
