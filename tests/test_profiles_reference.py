"""The contact geometry of S1002 on 60E1 at 1:40 against an independent computation, and the cone's limit.

No published table of Δr(y) and contact angles for S1002/60E1 1:40 with the wheelset's roll was at hand
(EN 15302's Annex E, in ``raildyn/contact/data``, tabulates other profiles, and is checked in
``tests/test_contact_conicity.py``). So the test computes the table a second way, by brute force, and
holds :func:`raildyn.contact.contact_geometry` to it:

* the wheelset is a rigid body, its wheel profiles sampled every 0.01 mm, turned through its roll φ
  exactly (cos φ, sin φ; the geometry rolls it to first order), shifted by y at rail level;
* for a given φ each wheel is lowered on to its rail: the axle height at which the highest point of
  rail under the wheel meets it, over every wheel sample (no contact search, no parabola);
* φ is found by bisection so that both wheels touch at one axle height (the geometry iterates a fixed
  point on the vertical gaps); the contact is the sample that touches, its angle the rail's slope there.

What both share is only the input: the sampled profiles and the track's placement of the rails.
"""

from __future__ import annotations

import numpy as np
import pytest

from raildyn.contact import (
    conical_wheel,
    contact_geometry,
    equivalent_conicity,
    kinematic_conicity,
    s1002_wheel,
    uic60_rail,
    worn_wheel,
)

FINE = 0.01e-3  # m, the wheel sampling of the brute force


def _lowered(wheel, rail, y, phi, u, r, gauge, tape):
    """The left wheel at shift y, roll φ: the axle height setting it on its rail, the touching sample, u_r."""
    centre = gauge / 2 + rail.gauge_face  # the rail's centre line, from the track centre
    eta, zeta = tape / 2 - u, -r  # wheel points in the axle's frame: outwards, upwards
    c, s = np.cos(phi), np.sin(phi)
    across = y - wheel.nominal_radius * s + eta * c - zeta * s  # y is the shift at rail level
    u_rail = centre - across
    inside = (u_rail >= rail.lateral[0]) & (u_rail <= rail.lateral[-1])
    need = np.where(inside, np.interp(u_rail, rail.lateral, rail.height) - (eta * s + zeta * c), -np.inf)
    k = int(np.argmax(need))
    return need[k], k, u_rail[k]


def brute_force(wheel, rail, shifts, *, gauge=1.435, tape=1.5, roll=True):
    """Δr, ϑ_L, ϑ_R, φ, u_L, u_R for each shift, by the rigid-body search of the module docstring."""
    u = np.arange(wheel.lateral[0], wheel.lateral[-1], FINE)
    r = np.interp(u, wheel.lateral, wheel.radius)
    slope = np.gradient(rail.height, rail.lateral)
    rows = []
    for y in np.atleast_1d(shifts):
        phi, low, high = 0.0, -0.02, 0.02
        for _ in range(60 if roll else 0):  # 0.04 rad / 2⁶⁰: far below any rounding
            phi = 0.5 * (low + high)
            left = _lowered(wheel, rail, y, phi, u, r, gauge, tape)[0]
            right = _lowered(wheel, rail, -y, -phi, u, r, gauge, tape)[
                0
            ]  # the right wheel is the mirror image
            low, high = (phi, high) if left > right else (low, phi)
        _, kl, ul = _lowered(wheel, rail, y, phi, u, r, gauge, tape)
        _, kr, ur = _lowered(wheel, rail, -y, -phi, u, r, gauge, tape)
        angle = [-np.arctan(np.interp(x, rail.lateral, slope)) for x in (ul, ur)]
        rows.append((r[kl] - r[kr], *angle, phi, u[kl], u[kr]))
    return np.array(rows).T


@pytest.fixture(scope="module")
def s1002_table():
    wheel, rail = s1002_wheel(), uic60_rail(1 / 40)
    y = np.arange(-6.5, 6.51, 0.5) * 1e-3  # the S1002 wheelset flanges 6.5 to 6.75 mm off centre
    return y, brute_force(wheel, rail, y), contact_geometry(wheel, rail, y)


def test_s1002_on_60e1_treads_agree_with_the_brute_force(s1002_table):
    # On the treads (|y| <= 5 mm; the contact angle stays under 7°, r' = tan ϑ <= 0.12) the two locate
    # each contact to within the sum of their grids, the geometry's 0.05 mm search (parabola-refined) and
    # the brute force's 0.01 mm samples (measured <= 0.025 mm apart), so Δr agrees within 0.06 mm × 0.12
    # = 7 µm (measured 2.2 µm) and the angle within the rail's curvature times that, 0.06 mm / 80 mm =
    # 0.043° (measured 0.02°). The roll φ = (e_L − e_R)/T agrees
    # within 1e-3 of itself (measured 1e-4: the first-order roll's error is O(φ²)).
    y, (dr, left, right, phi, ul, _), g = s1002_table
    tread = np.abs(y) <= 5e-3
    assert np.max(np.abs(dr - g.rolling_radius_difference)[tread]) < 7e-6
    assert np.max(np.abs(np.degrees(left - g.contact_angle[0]))[tread]) < 0.043
    assert np.max(np.abs(np.degrees(right - g.contact_angle[1]))[tread]) < 0.043
    assert np.max(np.abs(ul - g.wheel_position[0])[tread]) < 0.06e-3
    assert np.max(np.abs(phi - g.roll)[tread]) < 1e-3 * np.max(np.abs(phi[tread]))


def test_s1002_on_60e1_flange_root_agrees_with_the_brute_force(s1002_table):
    # Past the jump to the flange root (5.5 to 6.5 mm, angles 18° to 28°: r' up to 0.55), the same 0.06 mm
    # gives Δr within 0.06 mm × 0.55 = 33 µm (measured 23 µm, 0.5 % of Δr) and, on the rail's R13 gauge
    # corner, the angle within 0.06 mm / 13 mm = 0.26° (measured 0.23°).
    y, (dr, left, _, phi, _, _), g = s1002_table
    root = np.abs(y) > 5e-3
    assert np.max(np.abs(dr - g.rolling_radius_difference)[root]) < 33e-6
    assert np.max(np.abs(np.degrees(left - g.contact_angle[0]))[root]) < 0.26
    assert np.max(np.abs(phi - g.roll)[root]) < 0.01 * np.max(np.abs(phi[root]))


def test_s1002_on_60e1_at_1_in_20_agrees_with_the_brute_force():
    # At 1:20 the rail's inclination matches the tread's taper: the contact stays on the tread, under 1.1°,
    # out to 6 mm. The tread bounds of the 1:40 case hold (measured 0.6 µm and 0.017°).
    wheel, rail = s1002_wheel(), uic60_rail(1 / 20)
    y = np.arange(-6.0, 6.01, 1.0) * 1e-3
    dr, left, right, _, _, _ = brute_force(wheel, rail, y)
    g = contact_geometry(wheel, rail, y)
    assert np.max(np.abs(dr - g.rolling_radius_difference)) < 7e-6
    assert np.max(np.abs(np.degrees(left - g.contact_angle[0]))) < 0.043
    assert np.max(np.abs(np.degrees(right - g.contact_angle[1]))) < 0.043


def test_the_brute_force_table_has_the_s1002_landmarks(s1002_table):
    # The brute force's own table shows what a reader of chapter 4 expects of new S1002 on 60E1 1:40: an
    # odd Δr, the contact jumping from the tread (under 7°) to the flange root (over 18°) between 5 and
    # 5.5 mm, and a restoring Δr of about 0.94 mm at 3 mm.
    y, (dr, left, right, _, _, _), _ = s1002_table
    np.testing.assert_allclose(dr, -dr[::-1], atol=1e-12)
    np.testing.assert_allclose(left, right[::-1], atol=1e-12)
    assert np.degrees(left[y == 5e-3][0]) < 7 and np.degrees(left[np.isclose(y, 5.5e-3)][0]) > 18
    assert dr[np.isclose(y, 3e-3)][0] == pytest.approx(0.94e-3, abs=0.01e-3)


def test_equivalent_conicity_of_s1002_agrees_with_the_brute_force():
    # EN 15302's kinematic method on the brute force's Δr (0.1 mm apart, odd) and on the geometry's own
    # table (801 shifts): the centred contact jumps near y = 0.3 mm, which the coarser table places within
    # 0.1 mm; measured 0.01 % at 3 mm and 0.1 % at 2 mm: tolerance 0.5 %.
    wheel, rail = s1002_wheel(), uic60_rail(1 / 40)
    half = np.arange(0.0, 3.0001, 0.1) * 1e-3
    dr = brute_force(wheel, rail, half)[0]
    y, table = np.concatenate([-half[:0:-1], half]), np.concatenate([-dr[:0:-1], dr])
    amplitudes = [2e-3, 3e-3]
    expected = kinematic_conicity(y, table, amplitudes)
    np.testing.assert_allclose(equivalent_conicity(wheel, rail, amplitudes), expected, rtol=5e-3)
    assert expected[1] == pytest.approx(0.174, abs=0.001)  # λ_e(3 mm) of new S1002 on 60E1 1:40


@pytest.mark.parametrize("slope", [1 / 20, 1 / 40])
def test_a_cone_gives_the_cones_delta_r(slope):
    # The limit: without roll, each wheel of a cone touches where the rail's slope is the cone's, the same
    # rail point on both sides, so Δr = λ(u_L − u_R) = 2λy exactly; the brute force's samples are 0.01 mm
    # apart, so its Δr is exact to λ × 0.01 mm ≤ 0.5 µm, the geometry's to rounding (1e-12).
    cone, rail = conical_wheel(slope), uic60_rail(1 / 40)
    y = np.linspace(-5e-3, 5e-3, 11)
    np.testing.assert_allclose(brute_force(cone, rail, y, roll=False)[0], 2 * slope * y, atol=slope * FINE)
    np.testing.assert_allclose(
        contact_geometry(cone, rail, y, roll=False).rolling_radius_difference, 2 * slope * y, atol=1e-12
    )
    # With roll the two computations still agree (the cone's contact moves on the R300 crown by Rφ): the
    # same 0.06 mm bound on a slope λ, λ × 0.06 mm ≤ 3 µm (measured 1.5 µm).
    rolled = brute_force(cone, rail, y)[0]
    np.testing.assert_allclose(
        rolled, contact_geometry(cone, rail, y).rolling_radius_difference, atol=slope * 0.06e-3
    )


def test_a_measured_worn_wheel_agrees_with_the_brute_force():
    # A measured profile, PCHIP-resampled, is no easier than the standard one: the worn wheel on 60E1 1:40
    # (tape circles 1.4874 m apart, its own wheelset) jumps between two tread contacts at 3 mm. Away from the
    # jump, Δr within the tread bound above (7 µm; measured 1.2 µm), the angle within 0.043° (measured
    # 0.016°).
    wheel, rail = worn_wheel(), uic60_rail(1 / 40)
    y = np.array([-8.0, -6.0, -4.0, -2.0, -1.0, 0.0, 1.0, 2.0, 4.0, 6.0, 8.0]) * 1e-3
    dr, left, _, _, _, _ = brute_force(wheel, rail, y, tape=1.4874)
    g = contact_geometry(wheel, rail, y, tape_distance=1.4874)
    assert np.max(np.abs(dr - g.rolling_radius_difference)) < 7e-6
    assert np.max(np.abs(np.degrees(left - g.contact_angle[0]))) < 0.043
