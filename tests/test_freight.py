"""Tests for the freight car on three-piece trucks (raildyn.vehicles.freight).

Tiers: closed forms (static deflection, bounce/pitch/roll frequencies, 4 F X per
cycle and its smoothing deficit, the wedge's force balance), symmetry (joints in
phase cannot roll the car), the nonlinear rocking peak at the predicted speed for
both parameter sets, the GDU ore car value by value against its source with two
consistency checks of that source, and bad input.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.constants import GRAVITY
from raildyn.integrators import stable_step
from raildyn.vehicles import response as resp
from raildyn.vehicles.freight import (
    GDU_ORE_CAR,
    LABELS,
    RockAndRoll,
    VerticalFreightCar,
    rock_and_roll,
)
from raildyn.vehicles.wedges import WedgeFriction, wedge_energy_per_cycle, wedge_friction_force
from raildyn.vibration import modal_analysis

CAR = VerticalFreightCar()


def test_static_deflection_is_quarter_weight_over_nest():
    q = CAR.linear_system().static_deflection()
    # four equal nests share the weight: δ = m g / 4k (0.06 m by construction); rounding only
    assert q[0] == pytest.approx(-CAR.body_mass * GRAVITY / (4 * CAR.nest_stiffness), rel=1e-12)
    np.testing.assert_allclose(q[1:], 0.0, atol=1e-15)


def test_natural_frequencies_match_closed_forms(reference):
    v = CAR.linear_system()
    got = np.sort(modal_analysis(v.M, v.K).natural_frequencies) / (2 * np.pi)
    f = CAR.natural_frequencies()
    want = np.sort([f.bounce_hz, f.pitch_hz, f.roll_hz])
    # bounce, pitch and roll are uncoupled for a symmetric car: eigenvalues of a diagonal pencil
    reference(
        6,
        "freight car's bounce, pitch and roll frequencies",
        "uncoupled closed forms",
        "closed form",
        np.abs(got / want - 1).max(),
        1e-12,
    )


def test_roll_stiffness_loses_the_weight_term():
    k, b = CAR.nest_stiffness, CAR.semi_spring_spacing
    assert CAR.roll_stiffness == pytest.approx(
        4 * k * b**2 - CAR.body_mass * GRAVITY * CAR.cg_height, rel=1e-14
    )
    # the resonance sits where one cross-level cycle per rail meets f_roll
    assert CAR.roll_resonance_speed(11.9) == pytest.approx(CAR.natural_frequencies().roll_hz * 11.9)


@pytest.mark.parametrize("car", [CAR, GDU_ORE_CAR], ids=["hopper", "GDU"])
def test_pitch_turns_about_the_spring_plane_as_the_roll_does(car):
    # Pitch about the transverse axis in the spring plane (the centre plates hold the body along the
    # track): the weight h above it takes m g h from 4 k l², and the inertia is I_θ + m h², written
    # here from the class docstring; the pitch frequency is then √((4kl² − mgh)/(I_θ + mh²))/(2π).
    k, l, m, h = car.nest_stiffness, car.semi_truck_spacing, car.body_mass, car.cg_height
    stiffness, inertia = 4 * k * l**2 - m * GRAVITY * h, car.body_pitch_inertia + m * h**2
    mats = car.matrices(10.0)
    pitch = LABELS.index("body θ")
    assert mats.K[pitch, pitch] == pytest.approx(stiffness, rel=1e-14)
    assert mats.M[pitch, pitch] == pytest.approx(inertia, rel=1e-14)
    hz = car.natural_frequencies().pitch_hz
    assert hz == pytest.approx(np.sqrt(stiffness / inertia) / (2 * np.pi), rel=1e-14)
    # Raising the centre of gravity lowers both the pitch and the roll frequencies.
    taller = car.replace(cg_height=h + 0.2).natural_frequencies()
    assert taller.pitch_hz < hz and taller.roll_hz < car.natural_frequencies().roll_hz


def test_wedge_energy_is_four_f_x():
    F, X, f = 8.0e3, 0.012, 1.3
    # ideal Coulomb: ∮ F sgn(v) v dt = F · (total travel 4X); midpoint rule, crossings between nodes
    assert wedge_energy_per_cycle(F, X, f) == pytest.approx(4 * F * X, rel=1e-15)  # the closed form


@settings(max_examples=50, deadline=None)
@given(F=st.floats(1e2, 5e4), X=st.floats(1e-2, 5e-2), f=st.floats(0.5, 5.0), eps=st.floats(1e-4, 2e-3))
def test_property_smooth_wedge_deficit(F, X, f, eps):
    """F tanh(v/ε) dissipates less than 4FX by F ε² π²/(6 X ω²) to leading order.

    Near each of the two velocity zeros per cycle v ≈ Xω² s, and ∫₀^∞ u(1 − tanh u) du = π²/24;
    the next term is smaller by (ε/(Xω))² <= 0.004 here, so 2 % of the deficit (plus quadrature).
    """
    w = 2 * np.pi * f
    E = wedge_energy_per_cycle(F, X, f, velocity_scale=eps, n=200_000)
    deficit = 4 * F * X - E
    predicted = F * eps**2 * np.pi**2 / (6 * X * w**2)
    assert deficit == pytest.approx(predicted, rel=0.02, abs=1e-9 * F * X)


def test_in_phase_joints_do_not_roll_the_car():
    v = CAR.replace(equivalent_damping=2e4).linear_system()
    w = np.linspace(0.5, 30, 50)
    # vertical irregularity (both rails alike) gives no roll: the two nests of a truck cancel exactly
    assert np.abs(resp.track_frf(v, w, 10.0, "body φ")).max() == 0.0
    # cross-level does
    assert np.abs(resp.track_frf(v, w, 10.0, "body φ", component="cross_level")).max() > 0


def test_truck_spacing_filters_the_roll_input():
    # Cross-level of wavelength L reaches the two trucks 2s apart; roll does not couple to bounce or
    # pitch, so only the phase between the trucks depends on s: |H(s)| ∝ |cos(2πs/L)| at that wave.
    L, V = 11.9, 12.0
    w = np.array([2 * np.pi * V / L])
    base = GDU_ORE_CAR.replace(wedge_friction=0.0)

    def roll_gain(s):
        v = base.replace(semi_truck_spacing=s, equivalent_damping=2e4).linear_system()
        return abs(resp.track_frf(v, w, V, "body φ", component="cross_level")[0])

    s = GDU_ORE_CAR.semi_truck_spacing
    assert roll_gain(s) / roll_gain(L / 2) == pytest.approx(abs(np.cos(2 * np.pi * s / L)), rel=1e-9)
    # the GDU car's truck centres (5.41 m) lie near half a rail length: 14 % of the input survives
    assert abs(np.cos(2 * np.pi * s / L)) == pytest.approx(0.142, abs=1e-3)
    for car in (GDU_ORE_CAR, CAR, GDU_ORE_CAR.replace(semi_truck_spacing=4.0)):
        ratio = roll_gain(car.semi_truck_spacing) / roll_gain(L / 2)
        assert car.roll_input_factor(L) == pytest.approx(ratio, rel=1e-9)
    assert roll_gain(L / 4) < 1e-12 * roll_gain(L / 2)


@pytest.mark.parametrize("car", [CAR, GDU_ORE_CAR], ids=["hopper", "gdu"])
def test_rocking_peaks_near_the_roll_resonance(car):
    Vr = car.roll_resonance_speed()
    speeds = Vr * np.array([0.6, 0.8, 1.0, 1.2, 1.4])
    r = rock_and_roll(car, speeds, cycles=16)
    # the friction shifts and blunts the peak but, on a 20 % speed grid, it stays at the linear resonance
    assert int(np.argmax(r.roll_amplitude)) == 2
    assert r.roll_amplitude[2] > 2 * max(r.roll_amplitude[0], r.roll_amplitude[-1])
    assert r.resonance_speed == pytest.approx(Vr)


def test_gdu_ore_car_values_match_the_source():
    """leo-bart/doutorado-repo @ 247ba5c: input.in, src/system.cpp, src/ridecontroltruck.cpp."""
    c = GDU_ORE_CAR
    assert c.body_mass == 116200.0  # BOX_MASS
    assert (c.body_roll_inertia, c.body_pitch_inertia) == (130000.0, 640000.0)  # BOX_Izz, BOX_Ixx
    assert 2 * c.semi_truck_spacing == pytest.approx(5.410, abs=1e-12)  # CAR_WHEEL_BASE
    assert 2 * c.semi_truck_wheelbase == pytest.approx(1.828, abs=1e-12)  # TRUCK_WHEEL_BASE
    assert 2 * c.semi_spring_spacing == pytest.approx(2.278, abs=1e-12)  # sideFrameLateralDistance
    assert c.nest_stiffness == 9 * 527833.0  # nine coils of bolsterSpringStiffness
    # centre of gravity 2.152 m above the rail, spring tops at seat 0.238 + loaded length 0.267
    assert c.cg_height == pytest.approx(2.152 - 0.238 - 0.267, abs=1e-12)
    # two wedges of 344 kN/m springs, 0.1857 -> 0.1381 m, on a 37.5° slope with μ = 0.10
    wedges = wedge_friction_force(344000.0 * (0.1857 - 0.1381), np.radians(37.5), 0.10)
    down, up = wedges.bolster_down, wedges.bolster_up
    assert c.wedge_friction == pytest.approx(0.5 * (down + up), rel=1e-12)
    assert 4.3e3 < c.wedge_friction < 4.4e3


def test_gdu_springs_carry_the_body_at_their_loaded_length():
    # The source's free (0.327 m) and loaded (0.267 m) coil lengths, given to the millimetre, differ
    # by the static deflection under this body: 60 mm against m g / 4k = 59.99 mm (1 mm in 60 = 1.7 %).
    q = GDU_ORE_CAR.linear_system().static_deflection()
    assert -q[0] == pytest.approx(0.327 - 0.267, rel=0.017)


def test_gdu_inertia_reading_agrees_with_the_authors_labelled_set():
    c = GDU_ORE_CAR
    width, height = 3.113, 1.908  # the body box of src/system.cpp
    # a uniform box of that size has the roll inertia we read off the source, within 1 %
    assert c.body_roll_inertia == pytest.approx(c.body_mass * (width**2 + height**2) / 12, rel=0.01)
    # the same author's labelled set for this car (leo-bart/mbsim-wagons @ 0360902, input2.in: mass
    # 138 547.5 kg, BOX_Iroll 179 997, BOX_Ipitch 942 567.5 kg·m²) has radii of gyration within 12 %
    k_roll, k_pitch = np.sqrt(179997.0 / 138547.5), np.sqrt(942567.5 / 138547.5)
    assert np.sqrt(c.body_roll_inertia / c.body_mass) == pytest.approx(k_roll, rel=0.12)
    assert np.sqrt(c.body_pitch_inertia / c.body_mass) == pytest.approx(k_pitch, rel=0.12)
    # while the literal reading of the axis labels puts the roll radius twice too far out
    assert np.sqrt(c.body_pitch_inertia / c.body_mass) > 1.8 * k_roll


@settings(max_examples=50, deadline=None)
@given(
    P=st.floats(1e3, 5e4),
    alpha=st.floats(np.radians(20.0), np.radians(70.0)),
    mu=st.floats(0.0, 0.3),
    n=st.integers(1, 4),
)
def test_property_wedge_friction_balances_the_wedge(P, alpha, mu, n):
    if np.tan(alpha) <= mu + 0.05:
        return
    wedges = wedge_friction_force(P, alpha, mu, wedges=n)
    down, up = wedges.bolster_down, wedges.bolster_up
    for sign, got in ((1.0, down), (-1.0, up)):
        # unknowns: column normal N, slope normal N_b; horizontal N = N_b cos α; vertical
        # P + sign·μN = N_b sin α (column friction with the spring when the bolster goes down)
        A = np.array([[1.0, -np.cos(alpha)], [sign * mu, -np.sin(alpha)]])
        N, _ = np.linalg.solve(A, [0.0, -P])
        assert got == pytest.approx(n * mu * N, rel=1e-10, abs=1e-9)
    assert down >= up


def test_bad_input():
    with pytest.raises(ValueError, match="body_mass"):
        VerticalFreightCar(body_mass=0.0)
    with pytest.raises(ValueError, match="wedge_friction"):
        VerticalFreightCar(wedge_friction=-1.0)
    with pytest.raises(ValueError, match="roll stiffness"):
        VerticalFreightCar(cg_height=20.0)
    with pytest.raises(ValueError, match="speeds"):
        rock_and_roll(CAR, [-1.0])
    with pytest.raises(ValueError, match="amplitude"):
        wedge_energy_per_cycle(1.0, 0.0, 1.0)
    with pytest.raises(ValueError, match="equivalent_damping"):
        CAR.replace(equivalent_damping=-1.0)
    with pytest.raises(ValueError, match="spring_force"):
        wedge_friction_force(-1.0, 0.6, 0.1)
    with pytest.raises(ValueError, match="slope_angle"):
        wedge_friction_force(1e4, np.pi / 2, 0.1)
    with pytest.raises(ValueError, match="locks the wedge"):
        wedge_friction_force(1e4, np.radians(5.0), 0.1)
    with pytest.raises(ValueError, match="wedges"):
        wedge_friction_force(1e4, 0.6, 0.1, wedges=0)
    with pytest.raises(ValueError, match="rail_length"):
        CAR.roll_input_factor(0.0)


def test_issue_15_bad_input_is_refused_by_name():
    with pytest.raises(TypeError, match="car must be a VerticalFreightCar"):
        rock_and_roll("loaded hopper", [25.0], cycles=4)
    with pytest.raises(ValueError, match="speeds must not be empty"):
        rock_and_roll(CAR, [], cycles=4)
    with pytest.raises(TypeError, match="progress must be True or False"):
        rock_and_roll(CAR, [25.0], cycles=4, progress="yes")
    # a run that would tabulate 10¹² cycles of track is refused before it starts, naming its causes
    with pytest.raises(ValueError, match="cycles = 1000000000000 .* at most 5e\\+05"):
        rock_and_roll(CAR, [25.0], cycles=10**12)
    with pytest.raises(ValueError, match="rail_length"):
        rock_and_roll(CAR, [25.0], rail_length=1e300, half_width=1.0, cycles=4)
    # a roll stiffness that overflows, or a body so heavy that it topples, names every field involved
    # (the spacing and the mass within their plausible ranges: an overflowing 4 k d², a 1000 t body 3 m up)
    with pytest.raises(ValueError, match="semi_spring_spacing .* finite and > 0"):
        VerticalFreightCar(nest_stiffness=1e308)
    with pytest.raises(ValueError, match="body_mass .* finite and > 0"):
        VerticalFreightCar(body_mass=1e6, cg_height=3.0)
    with pytest.raises(ValueError, match="semi_spring_spacing must be in"):
        VerticalFreightCar(semi_spring_spacing=1e300)
    with pytest.raises(ValueError, match="body_mass must be in"):
        VerticalFreightCar(body_mass=1e300)
    with pytest.raises(ValueError, match="semi_truck_wheelbase"):
        VerticalFreightCar(semi_truck_wheelbase=10.0)
    with pytest.raises(ValueError, match="n must be an integer in"):
        wedge_energy_per_cycle(1.0, 0.01, 1.0, n=10**12)
    with pytest.raises(ValueError, match="velocity_scale"):
        wedge_energy_per_cycle(1.0, 0.01, 1.0, velocity_scale=-1.0)
    # 4 F X stays finite for a huge amplitude: the integral is written as X ∮ F(v) cos φ dφ
    assert wedge_energy_per_cycle(6e3, 1e300, 2.0) == pytest.approx(4 * 6e3 * 1e300, rel=1e-6)
    with pytest.raises(ValueError, match="bolster_up"):
        WedgeFriction(4.9e3, float("nan"))
    r = rock_and_roll(CAR, [25.0], cycles=4)
    with pytest.raises(ValueError, match="roll_amplitude must be >= 0"):
        RockAndRoll(r.speeds, -r.roll_amplitude - 1.0, r.resonance_speed, r.t, r.roll)
    with pytest.raises(TypeError, match="artists must be a dict"):
        r.plot(artists="curve")
    with pytest.raises(TypeError, match="resonance must be True or False"):
        r.plot(resonance=None)


def test_rock_and_roll_refuses_a_step_at_which_rk4_goes_unstable():
    """Wrong answer fixed (issue 14): dt = 0.5 s gave a roll amplitude of 4.28 rad (dt = 2 s:
    7.7e10 rad) with no word; the converged answer is about 0.003 rad. The step is now checked
    against RK4's stability limit on the car with sticking wedges, before the run."""
    for dt in (0.5, 2.0):
        with pytest.raises(ValueError, match="dt must be at most"):
            rock_and_roll(VerticalFreightCar(), [5.0], cycles=4, dt=dt)
    # The limit is RK4's: the spectral radius of the step matrix P = Σ (hA)^k/k!, k ≤ 4, of the
    # linearised car crosses 1 there (computed here from the matrix, not from its eigenvalues).
    sticking = CAR.replace(equivalent_damping=CAR.wedge_friction / 0.002)
    mats = sticking.matrices(1.0)
    limit = stable_step("rk4", mats.M, mats.C, mats.K)
    A = mats.state_matrix()

    def radius(h):
        P, term = np.eye(A.shape[0]), np.eye(A.shape[0])
        for k in range(1, 5):
            term = term @ (h * A) / k
            P = P + term
        return np.abs(np.linalg.eigvals(P)).max()

    assert radius(0.999 * limit) <= 1.0 + 1e-9
    assert radius(1.01 * limit) > 1.0
    # a step just inside the limit is stable and near the converged amplitude: RK4's O(h⁴) error
    # at 0.9 of its limit against a step four times smaller (seen: 0.2 %), so 1 %
    near = rock_and_roll(CAR, [8.0], cycles=8, dt=0.9 * limit).roll_amplitude[0]
    fine = rock_and_roll(CAR, [8.0], cycles=8, dt=0.9 * limit / 4).roll_amplitude[0]
    assert np.isfinite(near) and near < 0.05
    assert near == pytest.approx(fine, rel=0.01)


def test_rock_and_roll_plot_draws_degrees_against_kmh_and_moves_in_place():
    import matplotlib.pyplot as plt

    a = rock_and_roll(CAR, [6.0, 9.0], cycles=4)
    b = rock_and_roll(CAR.replace(wedge_friction=2e3), [6.0, 9.0], cycles=4)
    fig, ax = plt.subplots()
    artists = a.plot(ax)
    x, y = artists["curve"].get_data()
    np.testing.assert_allclose(x, [21.6, 32.4], rtol=1e-15)
    np.testing.assert_allclose(y, np.degrees(a.roll_amplitude), rtol=1e-15)
    assert artists["resonance"].get_xdata()[0] == pytest.approx(3.6 * CAR.roll_resonance_speed(), rel=1e-15)
    curve = artists["curve"]
    assert b.plot(artists=artists)["curve"] is curve
    np.testing.assert_allclose(curve.get_ydata(), np.degrees(b.roll_amplitude), rtol=1e-15)
    assert "resonance" not in a.plot(ax, resonance=False)
    plt.close(fig)
