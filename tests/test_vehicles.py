"""raildyn.vehicles: the bogie and the car against independent assemblies and limits."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn import stability
from raildyn.constants import GRAVITY
from raildyn.vehicles import MANCHESTER_CAR, Bogie, LateralCar
from raildyn.wheelset import Wheelset


def test_manchester_parameters_as_published():
    # Iwnicki (1998), Manchester benchmark vehicle 1: masses and inertias as tabulated.
    car = MANCHESTER_CAR
    assert (car.body_mass, car.body_yaw_inertia, car.body_roll_inertia) == (32000.0, 1.97e6, 5.68e4)
    assert (car.bogie.frame_mass, car.bogie.frame_yaw_inertia) == (2615.0, 3067.0)
    assert (car.wheelset.mass, car.wheelset.yaw_inertia) == (1813.0, 1120.0)
    assert 2 * car.bogie.semi_wheelbase == pytest.approx(2.56)
    assert 2 * car.semi_bogie_spacing == pytest.approx(19.0)


def test_car_has_fifteen_coordinates_and_symmetric_suspension():
    system = LateralCar().linear_system()
    assert system.size == 15
    # Springs and dampers are symmetric; only creep and gravity terms break the symmetry of K.
    np.testing.assert_allclose(system.C0, system.C0.T, atol=1e-9)
    K_s = system.K.copy()
    for iy, ipsi, _ in system.wheelsets:
        K_s[iy, ipsi] = K_s[ipsi, iy] = 0.0
    np.testing.assert_allclose(K_s, K_s.T, rtol=1e-12, atol=1e-6)
    assert np.trace(system.M) == pytest.approx(
        32000 + 1.97e6 + 5.68e4 + 2 * (2615 + 3067) + 4 * (1813 + 1120)
    )


def with_masses(model, masses):
    """The model's linear system with the mass (or inertia) of each coordinate in ``masses`` replaced.

    A body 10¹² times heavier than any vehicle lies outside the plausible masses the models accept
    (raildyn.constants.PLAUSIBLE_RANGES), so the limit is taken on the assembled equations: each
    such mass sits alone on the diagonal of M (checked), so replacing it is replacing the body's.
    """
    system = model.linear_system()
    M = system.M.copy()
    for label, mass in masses.items():
        i = system.labels.index(label)
        assert not np.delete(M[i], i).any(), f"{label} is coupled inertially to another coordinate"
        M[i, i] = mass
    return system.replace(M=M)


def test_bogie_with_locked_frame_is_two_suspended_wheelsets():
    # An enormous frame (10¹² kg) does not move: each wheelset then sees a fixed frame, and the
    # bogie's wheelset eigenvalues are those of the suspended wheelset (twice). Frame modes aside,
    # they agree to 1e-6 relative (the frame's motion is of order 1e-12 of the wheelset's).
    bogie = with_masses(Bogie(), {"frame y": 1e12, "frame ψ": 1e12})
    V = 50.0
    lam_bogie = stability.eigenvalues_against_speed(bogie, [V])[0]
    lam_ws = stability.eigenvalues_against_speed(Bogie().wheelset, [V])[0]
    for lam in lam_ws:
        close = np.sort(np.abs(lam_bogie - lam))[:2]
        assert np.all(close < 1e-6 * abs(lam)), "each wheelset eigenvalue appears twice"


def test_car_without_body_mass_effects_matches_bogie():
    # A car body 10¹² heavier than usual stands still: each bogie then behaves as a bogie under a
    # straight-running body, so the car's critical speed equals the bogie's (to the 0.01 m/s tol).
    # The body's height is set to 0, or its enormous weight would overturn it in roll.
    car = LateralCar(body_height=0.0)
    heavy = with_masses(car, {"body y": 1e12 * 32000, "body ψ": 1e12 * 1.97e6, "body φ": 1e12 * 5.68e4})
    v_car = stability.critical_speed(heavy, (1.0, 200.0)).speed
    v_bogie = stability.critical_speed(car.bogie, (1.0, 200.0)).speed
    assert v_car == pytest.approx(v_bogie, abs=0.02)


def test_body_roll_terms_by_hand():
    # Roll stiffness on the body: two bogies' springs and bars, less the weight's overturning
    # moment m g h, plus the lateral springs acting at h below the centre: 2 k_y2 h².
    car = LateralCar()
    system = car.linear_system()
    i = system.labels.index("body φ")
    expected = (
        2 * car.roll_stiffness
        - car.body_mass * GRAVITY * car.body_height
        + 2 * car.bogie.secondary_lateral_stiffness * car.body_height**2
    )
    assert system.K[i, i] == pytest.approx(expected, rel=1e-12)


@settings(deadline=None, max_examples=30)
@given(conicity=st.floats(0.03, 0.5))
def test_bogie_critical_speed_scales_as_inverse_root_conicity_in_the_high_creep_limit(conicity):
    # With creep forces dominant, the kinematic frequency is V√(λ/(a r₀ (1 + b²/a²))): all
    # frequencies scale with V√λ, so V_c √λ is the same for every λ when gravity and spin are off.
    # Real creep coefficients make this approximate; with 10³ × the default it holds to 1 %.
    def bogie(lam):
        ws = Wheelset(
            conicity=lam,
            f11=1.2e10,
            f22=1.06e10,
            f23=0.0,
            f33=0.0,
            contact_angle=0.0,
            contact_angle_parameter=0.0,
            lateral_damping=0.0,
            yaw_damping=0.0,
        )
        return Bogie(wheelset=ws, secondary_lateral_damping=0.0)

    # The high-creep critical speed is 86.5 m/s at λ = 0.1, so 158 m/s at the lowest λ drawn (0.03):
    # every one lies within raildyn.constants.MAXIMUM_SPEED.
    reference = stability.critical_speed(bogie(0.1), (1.0, 200.0)).speed * np.sqrt(0.1)
    value = stability.critical_speed(bogie(conicity), (1.0, 200.0)).speed * np.sqrt(conicity)
    assert value == pytest.approx(reference, rel=1e-2)


def test_with_reaches_every_level():
    car = LateralCar().replace(conicity=0.3, frame_mass=3000.0, body_mass=30000.0)
    assert car.wheelset.conicity == 0.3 and car.wheelset.contact_angle == 0.3
    assert car.bogie.frame_mass == 3000.0 and car.body_mass == 30000.0


def test_bad_input():
    with pytest.raises(ValueError, match="frame_mass"):
        Bogie(frame_mass=-1.0)
    with pytest.raises(ValueError, match="body_mass"):
        LateralCar(body_mass=0.0)
    with pytest.raises(ValueError, match="conicity"):
        LateralCar().replace(conicity=-0.1)
    with pytest.raises(TypeError, match="Wheelset"):
        Bogie(wheelset=3)
    with pytest.raises(ValueError, match="speed"):
        LateralCar().nonlinear().rhs(0.0, np.zeros(LateralCar().nonlinear().state_size), 0.0)


def test_issue_15_models_validate_their_fields():
    # a body whose weight, acting h above the secondary springs, outweighs 2 k_φ would topple
    with pytest.raises(ValueError, match="roll_stiffness .* body topples"):
        LateralCar(roll_stiffness=0.0)
    with pytest.raises(ValueError, match="semi_bogie_spacing must exceed"):
        LateralCar(semi_bogie_spacing=1.0)
    with pytest.raises(TypeError, match="bogie must be a Bogie"):
        LateralCar(bogie=None)
    with pytest.raises(TypeError, match="secondary_yaw_damping must be a real number"):
        Bogie(secondary_yaw_damping="0")
    # the threshold is where the car's roll diverges: just above it the car stands
    stands = LateralCar(roll_stiffness=0.51 * LateralCar().body_mass * GRAVITY * LateralCar().body_height)
    assert np.linalg.eigvals(stands.matrices(20.0).state_matrix()).real.max() < 0


def test_issue_15_assemble_refuses_by_name():
    from raildyn.linear_model import Assembler

    labels = ["frame y", "frame ψ", "wheelset1 y", "wheelset1 ψ", "wheelset2 y", "wheelset2 ψ"]
    for kwargs, word in (
        (dict(asm=None), "asm"),
        (dict(tag="2"), "tag"),
        (dict(body={"car y": 1.0}), "body"),
        (dict(body_yaw="body ψ"), "body_yaw"),
        (dict(first_input=3), "first_input"),
    ):
        call = dict(asm=Assembler(labels, n_inputs=4), tag="", body={}, body_yaw=None, first_input=0) | kwargs
        with pytest.raises((TypeError, ValueError), match=rf"\b{word}\b"):
            Bogie().assemble(**call)
