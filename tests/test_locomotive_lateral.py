"""raildyn.vehicles.locomotive_lateral: the six-axle locomotive on two three-axle trucks, lateral.

Checked against: the vertical model of the same locomotive (masses and spacings), assemblies by hand,
the rigid three-axle truck's kinematic wavelength (derived in rigid_truck_wavelength's docstring),
python-control's poles, the truck alone under a body that does not move, and the nonlinear model.
"""

import control
import numpy as np
import pytest
from test_vehicles import with_masses

from raildyn import stability
from raildyn.constants import GRAVITY
from raildyn.linear_model import Assembler
from raildyn.vehicles import (
    DEFAULT_LOCOMOTIVE,
    LATERAL_LOCOMOTIVE,
    LateralLocomotive,
    ThreeAxleTruck,
    rigid_truck_wavelength,
)
from raildyn.wheelset import NonlinearLateral, kinematic_wavelength, rigid_bogie_wavelength

SPEED_RANGE = (1.0, 200.0)  # m/s, up to raildyn.constants.MAXIMUM_SPEED


def test_parameters_are_those_of_the_vertical_model_of_the_same_locomotive():
    # The vertical model (EMD SD40-2, representative): 167 t in all, body 133 t, truck 6.5 t, 3.5 t
    # unsprung per axle, truck centres 43 ft 6 in apart, 2.07 m between axles. The lateral model splits
    # the same masses: each 3 t motor half on its axle (3.5 t = 2.0 t wheelset + 1.5 t) and half on
    # the frame (6.5 t = 2.0 t frame + 3 × 1.5 t).
    loco, truck, ws = LATERAL_LOCOMOTIVE, LATERAL_LOCOMOTIVE.truck, LATERAL_LOCOMOTIVE.wheelset
    vertical = DEFAULT_LOCOMOTIVE
    assert loco.mass == pytest.approx(167_000.0, rel=1e-12)
    assert loco.mass == pytest.approx(vertical.body_mass + 2 * vertical.truck_mass + 6 * 3500.0, rel=1e-12)
    assert loco.body_mass == vertical.body_mass == 133_000.0
    assert (truck.motor_mass, truck.motor_axle_share) == (3000.0, 0.5)
    assert ws.mass + 0.5 * truck.motor_mass == pytest.approx(3500.0, rel=1e-12)
    assert truck.frame_mass + 3 * 0.5 * truck.motor_mass == pytest.approx(vertical.truck_mass, rel=1e-12)
    assert 2 * loco.semi_truck_spacing == pytest.approx((43 + 6 / 12) * 0.3048, rel=1e-12)
    assert truck.axle_spacing == vertical.axle_spacing == 2.07
    np.testing.assert_allclose(loco.axle_positions, vertical.axle_positions, rtol=1e-12)
    # 40 in wheels, new 1:20 treads; the weight over six axles.
    assert ws.rolling_radius == pytest.approx(0.508, rel=1e-12)
    assert ws.conicity == 0.05 and ws.half_gauge == 0.75
    assert ws.axle_load == pytest.approx(167_000.0 * GRAVITY / 6, rel=1e-12)
    # Roll per truck: the vertical model's secondary springs and dampers at ±1.0 m.
    assert loco.roll_stiffness == pytest.approx(vertical.secondary_stiffness, rel=1e-12)
    assert loco.roll_damping == pytest.approx(vertical.secondary_damping, rel=1e-12)
    # Primary (representative): end axles 10 MN/m laterally, 5 MN/m per axlebox at ±1.0 m in yaw; the
    # middle axle within its ±19 mm play held by soft centring springs of 0.3 MN/m.
    assert ws.lateral_stiffness == 10.0e6
    assert ws.yaw_stiffness == pytest.approx(2 * 5.0e6 * 1.0**2, rel=1e-12)
    assert truck.middle_lateral_stiffness == 0.3e6
    assert truck.middle_lateral_play == 0.019


def test_assembly_by_hand():
    loco = LATERAL_LOCOMOTIVE
    system = loco.linear_system()
    assert system.size == 19 and system.n_inputs == 12
    assert system.input_kinds == ("alignment",) * 6 + ("cross_level",) * 6
    np.testing.assert_allclose(system.input_positions, np.tile(loco.axle_positions, 2), rtol=1e-12)
    truck, ws = loco.truck, loco.wheelset
    on_axle = on_frame = 0.5 * truck.motor_mass
    d = truck.axle_spacing
    M = dict(zip(system.labels, np.diag(system.M), strict=True))
    assert M["frame1 y"] == pytest.approx(truck.frame_mass + 3 * on_frame, rel=1e-12)
    assert M["frame2 ψ"] == pytest.approx(truck.frame_yaw_inertia + on_frame * 2 * d**2, rel=1e-12)
    for k in (1, 2, 3):
        assert M[f"wheelset1{k} y"] == pytest.approx(ws.mass + on_axle, rel=1e-12)
        assert M[f"wheelset2{k} ψ"] == ws.yaw_inertia
    # The mass matrix's lateral entries add up to the whole locomotive.
    lateral = [i for i, label in enumerate(system.labels) if label.endswith(" y")]
    assert system.M[np.ix_(lateral, lateral)].sum() == pytest.approx(loco.mass, rel=1e-12)
    # Springs and dampers are symmetric; only creep and gravity terms break the symmetry of K.
    np.testing.assert_allclose(system.C0, system.C0.T, atol=1e-9)
    K_s = system.K.copy()
    for iy, ipsi, _ in system.wheelsets:
        K_s[iy, ipsi] = K_s[ipsi, iy] = 0.0
    np.testing.assert_allclose(K_s, K_s.T, rtol=1e-12, atol=1e-6)
    # The middle axle's lateral spring is its soft centring; the end axles' the full primary.
    i = system.labels.index
    assert system.K[i("wheelset12 y"), i("frame1 y")] == pytest.approx(-truck.middle_lateral_stiffness)
    assert system.K[i("wheelset11 y"), i("frame1 y")] == pytest.approx(-ws.lateral_stiffness)
    assert system.K[i("wheelset11 y"), i("frame1 ψ")] == pytest.approx(-ws.lateral_stiffness * d)
    assert system.K[i("wheelset12 y"), i("frame1 ψ")] == 0.0


def test_body_roll_terms_by_hand():
    # Roll stiffness on the body: two trucks' springs, less the weight's overturning moment m g h,
    # plus the lateral springs acting h below the centre: 2 k_y2 h².
    loco = LATERAL_LOCOMOTIVE
    system = loco.linear_system()
    i = system.labels.index("body φ")
    expected = (
        2 * loco.roll_stiffness
        - loco.body_mass * GRAVITY * loco.body_height
        + 2 * loco.truck.secondary_lateral_stiffness * loco.body_height**2
    )
    assert system.K[i, i] == pytest.approx(expected, rel=1e-12)


def test_rigid_truck_wavelength_formula():
    # Two axles at ±b: Klingel's rigid-bogie factor 1 + b²/a²; three at ±d and 0: 1 + 2d²/(3a²),
    # Σx²/(n a²) with Σx² = 2d² and n = 3 (the derivation is in the function's docstring).
    r0, a, lam, d = 0.508, 0.75, 0.05, 2.07
    free = kinematic_wavelength(r0, a, lam)
    assert rigid_truck_wavelength(r0, a, lam, d) == pytest.approx(free * np.sqrt(1 + 2 * d**2 / (3 * a**2)))
    # shorter than the two-axle bogie of the same length (the middle axle steers with no moment arm)
    assert free < rigid_truck_wavelength(r0, a, lam, d) < rigid_bogie_wavelength(r0, a, lam, d)


def _kinematic_truck(stiffness_factor):
    """A truck on the pure-creep wheelset of the derivation (f₁₁ = f₂₂, no spin, gravity or damping),
    its primary springs ``stiffness_factor`` times the default, free of any secondary restraint."""
    truck = ThreeAxleTruck(
        secondary_lateral_stiffness=0.0,
        secondary_lateral_damping=0.0,
        secondary_yaw_stiffness=0.0,
        secondary_yaw_damping=0.0,
    ).without_play()
    ws = truck.wheelset
    return truck.replace(
        f22=ws.f11,
        f23=0.0,
        f33=0.0,
        contact_angle=0.0,
        contact_angle_parameter=0.0,
        lateral_damping=0.0,
        yaw_damping=0.0,
        lateral_stiffness=stiffness_factor * ws.lateral_stiffness,
        yaw_stiffness=stiffness_factor * ws.yaw_stiffness,
    )


def _kinematic_frequency_error(truck, speed):
    """Relative distance of the truck's slowest oscillation from V/L of the rigid three-axle truck."""
    ws = truck.wheelset
    expected = speed / rigid_truck_wavelength(
        ws.rolling_radius, ws.half_gauge, ws.conicity, truck.axle_spacing
    )
    lam = stability.eigenvalues_against_speed(truck, [speed])[0]
    oscillating = lam[lam.imag > 1e-6]
    nearest = oscillating[np.argmin(np.abs(oscillating.imag / (2 * np.pi) - expected))]
    return abs(nearest.imag / (2 * np.pi) - expected) / expected


def test_stiff_primary_tends_to_the_rigid_three_axle_truck():
    # At 5 m/s the kinematic oscillation (0.12 Hz) is far below every suspension mode and the creep
    # forces (f/V ~ 4 MN·s/m) dwarf the inertia forces, so its frequency is V/L of the rigid truck up
    # to the inertia and the primary's compliance, which vanishes as the springs stiffen: the error
    # falls with the stiffness (seen: 1.1 — the default truck's wheelsets yaw on their springs and
    # its slowest oscillation is another — then 1.3e-2 at 10 times and 2.6e-6 at 1000 times).
    errors = [_kinematic_frequency_error(_kinematic_truck(s), 5.0) for s in (1.0, 10.0, 1000.0)]
    assert errors[-1] < 1e-4
    assert errors[0] > errors[1] > errors[2]
    # and it is not the two-axle bogie's wavelength (a 10 % longer wave): the test can tell them apart
    ws = _kinematic_truck(1000.0).wheelset
    two = 5.0 / rigid_bogie_wavelength(ws.rolling_radius, ws.half_gauge, ws.conicity, 2.07)
    three = 5.0 / rigid_truck_wavelength(ws.rolling_radius, ws.half_gauge, ws.conicity, 2.07)
    assert abs(two - three) / three > 0.05


def test_eigenvalues_are_python_control_poles():
    # control.ss built here from M, C(V), K (not raildyn's state_space): the same eigenproblem in
    # another code path, to 1e-8 of the largest modulus (round-off on a 38 × 38 matrix).
    for speed in (20.0, 80.0, 120.0):
        mats = LATERAL_LOCOMOTIVE.matrices(speed)
        n = mats.M.shape[0]
        Minv = np.linalg.inv(mats.M)
        A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ mats.K, -Minv @ mats.C]])
        poles = np.sort_complex(control.ss(A, np.zeros((2 * n, 1)), np.eye(2 * n)[:1], 0.0).poles())
        ours = np.sort_complex(stability.eigenvalues_against_speed(LATERAL_LOCOMOTIVE, [speed])[0])
        np.testing.assert_allclose(ours, poles, atol=1e-8 * np.abs(ours).max())


def _bisect_on_control_poles(model, low, high, tol=0.01):
    """First upward zero of python-control's largest real pole: a 5 m/s scan, then bisection."""

    def g(speed):
        mats = model.matrices(speed)
        n = mats.M.shape[0]
        Minv = np.linalg.inv(mats.M)
        A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ mats.K, -Minv @ mats.C]])
        return control.ss(A, np.zeros((2 * n, 1)), np.eye(2 * n)[:1], 0.0).poles().real.max()

    speeds = np.arange(low, high + 5.0, 5.0)
    values = [g(v) for v in speeds]
    i = next(k for k in range(len(values) - 1) if values[k] < 0.0 <= values[k + 1])
    a, b = speeds[i], speeds[i + 1]
    while b - a > tol:
        mid = 0.5 * (a + b)
        a, b = (a, mid) if g(mid) >= 0.0 else (mid, b)
    return 0.5 * (a + b)


def test_critical_speed_plausible_and_as_python_control_finds_it():
    # The same speed to 0.1 m/s from raildyn's batched scan and Brent's method and from bisection on
    # python-control's poles. The range: a freight locomotive on new 1:20 treads (λ = 0.05) must not
    # hunt in service (the SD40-2's top speed is some 30 m/s), and with its stiff primary yaw
    # (10 MN·m/rad per axle) its trucks are close to rigid ones, whose hunting a small conicity pushes
    # far up; worn treads (λ = 0.2) bring it down towards service speeds, as locomotive hunting on
    # worn wheels is met in practice. The hunting frequency lies between the rigid truck's kinematic
    # frequency and the free wheelset's (Wickens 2003, ch. 3).
    cs = stability.critical_speed(LATERAL_LOCOMOTIVE, SPEED_RANGE)
    assert cs.found
    assert 60.0 < cs.speed < 150.0
    reference = _bisect_on_control_poles(LATERAL_LOCOMOTIVE, 80.0, 120.0)
    assert cs.speed == pytest.approx(reference, abs=0.1)
    ws = LATERAL_LOCOMOTIVE.wheelset
    rigid = cs.speed / rigid_truck_wavelength(ws.rolling_radius, ws.half_gauge, ws.conicity, 2.07)
    free = cs.speed / kinematic_wavelength(ws.rolling_radius, ws.half_gauge, ws.conicity)
    assert rigid < cs.frequency_hz < free
    # a truck hunting mode: the frame's lateral motion is the largest entry of the mode shape
    assert cs.coordinates[int(np.argmax(np.abs(cs.mode_shape)))] in ("frame1 y", "frame2 y")
    worn = stability.critical_speed(LATERAL_LOCOMOTIVE.replace(conicity=0.2), SPEED_RANGE)
    assert 30.0 < worn.speed < 0.5 * cs.speed


def test_heavy_body_leaves_each_truck_as_the_truck_under_a_straight_body():
    # A body 10⁶ times heavier all but stands still: each truck then hunts as the truck alone under a
    # body running straight (ThreeAxleTruck.linear_system), the same critical speed to the 0.01 m/s
    # tol. (Heavier still, the body's own modes, damped at c/2m, sink into the round-off of the
    # eigenvalues and may read as unstable.) The body's height is 0, or its weight would overturn it.
    # A body 10⁶ times heavier lies outside the plausible masses the model accepts, so the masses
    # are replaced in its assembled equations (tests/test_vehicles.py's with_masses).
    loco = LATERAL_LOCOMOTIVE.replace(body_height=0.0)
    heavy = with_masses(
        loco,
        {
            "body y": 1e6 * loco.body_mass,
            "body ψ": 1e6 * loco.body_yaw_inertia,
            "body φ": 1e6 * loco.body_roll_inertia,
        },
    )
    v_loco = stability.critical_speed(heavy, SPEED_RANGE).speed
    v_truck = stability.critical_speed(loco.truck, SPEED_RANGE).speed
    assert v_loco == pytest.approx(v_truck, abs=0.02)


def test_middle_axle_play_raises_the_critical_speed_a_little():
    # Measured: 101.5 m/s with the play (soft centring, 0.3 MN/m) against 99.6 m/s with the middle
    # axle held as the end ones (10 MN/m). The middle axle sits at the truck centre, where the frame's
    # yaw does not move it laterally, so its lateral spring acts only in the frame's lateral motion,
    # which dominates this hunting mode. Through that spring the frame receives the middle wheelset's
    # lateral creep force, 2f₂₂ψ from its yaw: the non-conservative coupling of yaw into lateral
    # motion that feeds hunting. Within its play the middle axle passes little of it on (its motion
    # lags the frame's in the mode shape), so the frame hunts a little later. The effect is small: two
    # of three axles, and the frame's yaw, are unchanged; it vanishes in the rigid-truck limit, where
    # a laterally free middle axle rolls on the same kinematic path as the frame.
    with_play = stability.critical_speed(LATERAL_LOCOMOTIVE, SPEED_RANGE)
    without = stability.critical_speed(LATERAL_LOCOMOTIVE.without_play(), SPEED_RANGE)
    assert 1.0 < with_play.speed - without.speed < 0.05 * without.speed
    i = with_play.coordinates.index
    lag = np.angle(with_play.mode_shape[i("wheelset12 y")] / with_play.mode_shape[i("frame1 y")])
    lag_held = np.angle(without.mode_shape[i("wheelset12 y")] / without.mode_shape[i("frame1 y")])
    assert abs(lag) > 5 * abs(lag_held)


def test_play_element_is_the_clearance_law_and_replaces_the_linear_spring():
    truck = LATERAL_LOCOMOTIVE.truck
    kc, ky, g = truck.middle_lateral_stiffness, truck.wheelset.lateral_stiffness, truck.middle_lateral_play
    element = truck.play_element("1")
    assert element.coordinates == {"wheelset12 y": 1.0, "frame1 y": -1.0}
    assert (element.stiffness, element.damping) == (kc, 0.0)
    u = np.array([-0.03, -g, -0.005, 0.0, 0.005, g, 0.03])
    expected = kc * u + ky * np.sign(u) * np.maximum(np.abs(u) - g, 0.0)
    np.testing.assert_allclose(element.force(u, 0.0 * u), expected, rtol=1e-12)
    assert truck.without_play().play_element() is None  # no play: the linear spring holds the axle
    # Within the play the law is the linear spring it replaces (its slope there): the locomotive with
    # the two play elements moves as the same system with its linear springs kept (no elements), to
    # round-off, at any state whose middle axles stay within the play (here within 10 mm).
    model = LATERAL_LOCOMOTIVE.nonlinear()
    assert len(model.elements) == 2
    kept = NonlinearLateral(model.system, model.contact)
    state = 5e-3 * np.random.default_rng(1).uniform(-1.0, 1.0, model.state_size)
    reference = kept.rhs(0.0, state, 50.0)
    np.testing.assert_allclose(model.rhs(0.0, state, 50.0), reference, atol=1e-9 * np.abs(reference).max())
    # Beyond the play the stop acts: against the same truck with a wider play (never reached), only
    # the middle wheelset's and the frame's accelerations change, by ∓k_y (|u| − g)/m each.
    wide = LATERAL_LOCOMOTIVE.replace(middle_lateral_play=0.05).nonlinear()
    i, f = model.system.labels.index("wheelset12 y"), model.system.labels.index("frame1 y")
    state = np.zeros(model.state_size)
    state[i] = 0.03
    change = model.rhs(0.0, state, 50.0) - wide.rhs(0.0, state, 50.0)
    n, stop = model.system.size, ky * (0.03 - g)
    expected = np.zeros(model.state_size)
    expected[n + i] = -stop / model.system.M[i, i]
    expected[n + f] = stop / model.system.M[f, f]
    np.testing.assert_allclose(change, expected, atol=1e-9 * abs(expected).max())


def test_long_alignment_wave_is_followed_rigidly():
    # The alignment under all six wheelsets together, very slowly (1e-5 rad/s): every lateral
    # coordinate follows it one for one and nothing yaws or rolls (the creep and gravitational
    # stiffness act on y − y_a). The residual is the damping's lag, of order ω C/K: 6.7e-5 at
    # 1e-3 rad/s, so below 1e-6 at 1e-5 rad/s; 1e-5 allows for it.
    system = LATERAL_LOCOMOTIVE.linear_system()
    for label in system.labels:
        H = system.axle_frf([1e-5], 30.0, label)[0, :6].sum()
        assert abs(H - (1.0 if label.endswith(" y") else 0.0)) < 1e-5, label


def test_nonlinear_critical_speed_not_above_the_linear_one():
    # A bifurcation diagram (7 speeds from 0.8 to 1.1 × V_lin, 8 s each, 4 bisections to 0.3 m/s;
    # 40 s, too slow for the suite) put the nonlinear critical speed at 96.1 m/s, below the linear
    # 101.5 m/s: a subcritical bifurcation, the limit cycle (about 10 mm) running on the flanges
    # (9.1 mm). The middle axles' stops are not reached there: the same diagram with the play
    # linearised gave the same 96.1 m/s (without the play: 94.9 m/s nonlinear, 99.6 m/s linear).
    # Here one run between the two: at 0.97 V_lin the locomotive, started against its flange (12 mm), keeps
    # hunting on its flanges, so a limit cycle exists below the linear critical speed.
    linear = stability.critical_speed(LATERAL_LOCOMOTIVE, SPEED_RANGE).speed
    model = LATERAL_LOCOMOTIVE.nonlinear()
    cycle = stability.limit_cycle_amplitude(model, 0.97 * linear, duration=4.0)
    assert cycle.hunting()
    assert cycle.amplitude > model.contact.flange_clearance


def test_replace_reaches_every_level():
    loco = LATERAL_LOCOMOTIVE.replace(conicity=0.2, frame_mass=2500.0, body_mass=120_000.0)
    assert loco.wheelset.conicity == 0.2 and loco.wheelset.contact_angle == 0.2
    assert loco.truck.frame_mass == 2500.0 and loco.body_mass == 120_000.0
    assert LATERAL_LOCOMOTIVE.without_play().truck.middle_lateral_stiffness == loco.wheelset.lateral_stiffness


def test_bad_input_is_refused_by_name():
    for kwargs, word in (
        (dict(frame_mass=-1.0), "frame_mass"),
        (dict(motor_axle_share=1.5), "motor_axle_share"),
        (dict(middle_lateral_play=-0.01), "middle_lateral_play"),
        (dict(axle_spacing=0.0), "axle_spacing"),
        (dict(motor_mass=float("nan")), "motor_mass"),
    ):
        with pytest.raises(ValueError, match=rf"\b{word}\b"):
            ThreeAxleTruck(**kwargs)
    with pytest.raises(TypeError, match="truck must be a ThreeAxleTruck"):
        LateralLocomotive(truck=None)
    with pytest.raises(ValueError, match="semi_truck_spacing must exceed"):
        LateralLocomotive(semi_truck_spacing=2.0)
    with pytest.raises(ValueError, match="roll_stiffness .* body topples"):
        LateralLocomotive(roll_stiffness=0.0)
    with pytest.raises(ValueError, match="conicity"):
        LATERAL_LOCOMOTIVE.replace(conicity=-0.1)
    with pytest.raises(ValueError, match="speed"):
        LATERAL_LOCOMOTIVE.nonlinear().rhs(0.0, np.zeros(LATERAL_LOCOMOTIVE.nonlinear().state_size), 0.0)
    for tag in (1, "3"):
        with pytest.raises((TypeError, ValueError), match="tag"):
            LATERAL_LOCOMOTIVE.truck.play_element(tag)
    with pytest.raises(TypeError, match="contact"):
        LATERAL_LOCOMOTIVE.nonlinear(contact=3)
    with pytest.raises(ValueError, match="axle_spacing"):
        rigid_truck_wavelength(0.5, 0.75, 0.05, -1.0)


def test_assemble_refuses_by_name():
    labels = ["frame y", "frame ψ"] + [f"wheelset{k} {q}" for k in (1, 2, 3) for q in "yψ"]
    for kwargs, word in (
        (dict(asm=None), "asm"),
        (dict(tag="2"), "tag"),
        (dict(body={"car y": 1.0}), "body"),
        (dict(body_yaw="body ψ"), "body_yaw"),
        (dict(first_input=1), "first_input"),
    ):
        call = dict(asm=Assembler(labels, n_inputs=6), tag="", body={}, body_yaw=None, first_input=0) | kwargs
        with pytest.raises((TypeError, ValueError), match=rf"\b{word}\b"):
            ThreeAxleTruck().assemble(**call)


def test_lateral_response_to_alignment_by_hand():
    # Chapter 6's response_spectrum takes the locomotive unchanged. For one alignment spectrum met by
    # all six wheelsets, the inputs are one process delayed by τ_j = d_j/V: the body's PSD is
    # |Σ_j H_j(ω) e^{−iωτ_j}|² S(ω/V)/V, built here from the second-order FRFs (axle_frf) alone.
    from raildyn.vehicles import response_spectrum

    def alignment(Omega):
        return 1e-7 / (0.01 + np.asarray(Omega) ** 2)  # m²/(rad/m), a small representative spectrum

    V, omega = 30.0, np.linspace(0.5, 60.0, 200)
    loco = LATERAL_LOCOMOTIVE
    result = response_spectrum(
        loco, alignment, V, omega, output="body y", derivative=2, component="alignment"
    )
    system = loco.linear_system()
    H = system.axle_frf(omega, V, "body y", derivative=2)[:, :6]
    delays = np.exp(-1j * omega[:, None] * system.input_positions[None, :6] / V)
    expected = np.abs((H * delays).sum(axis=1)) ** 2 * alignment(omega / V) / V
    # the same linear algebra by two routes: round-off only
    np.testing.assert_allclose(result.psd, expected, rtol=1e-8, atol=1e-12 * expected.max())
