"""The one protocol of every linear model (raildyn.linear_model), held by one contract test.

Every linear model of the package is listed in MODELS; a model a later chapter adds joins the list.
Each is held to the protocol's promises, and its python-control StateSpace is checked against an
independent computation: the frequency response that python-control evaluates from (A, B, C, D)
against raildyn's batched solve of (K − ω²M + iωC) X = G_K + iωG_C on the second-order matrices.
"""

import dataclasses

import control
import numpy as np
import pytest

from raildyn import stability
from raildyn.linear_model import Assembler, LinearModel, LinearSystem, SystemMatrices, as_linear_system
from raildyn.vehicles import (
    COOPERRIDER_CAR,
    DEFAULT_LOCOMOTIVE,
    GDU_ORE_CAR,
    LATERAL_LOCOMOTIVE,
    LOADED_FREIGHT_CAR,
    MANCHESTER_CAR,
    MANCHESTER_VERTICAL,
    Bogie,
    LateralCar,
    VerticalFreightCar,
)
from raildyn.wheelset import Wheelset

MODELS = {
    "wheelset": Wheelset(),
    "bogie": Bogie(),
    "manchester car": MANCHESTER_CAR,
    "cooperrider car": COOPERRIDER_CAR,
    "vertical car": MANCHESTER_VERTICAL,
    "freight car": VerticalFreightCar(equivalent_damping=2.0e4),
    "gdu ore car": GDU_ORE_CAR.replace(equivalent_damping=2.0e4),
    "locomotive": DEFAULT_LOCOMOTIVE,
    "lateral locomotive": LATERAL_LOCOMOTIVE,
    "three-axle truck": LATERAL_LOCOMOTIVE.truck,
    "lateral freight car": LOADED_FREIGHT_CAR,
    "three-piece truck": LOADED_FREIGHT_CAR.truck,
}
SPEED = 30.0  # m/s, below every lateral model's critical speed


@pytest.fixture(params=list(MODELS), ids=list(MODELS))
def model(request):
    return MODELS[request.param]


def test_model_follows_the_protocol(model):
    assert isinstance(model, LinearModel)
    system = model.linear_system()
    assert isinstance(system, LinearSystem)
    assert as_linear_system(system) is system
    mats = model.matrices(SPEED)
    assert isinstance(mats, SystemMatrices) and mats.speed == SPEED
    n, q = system.size, system.n_inputs
    assert mats.M.shape == mats.C.shape == mats.K.shape == (n, n)
    assert mats.GK.shape == mats.GC.shape == (n, q) and q > 0
    assert len(mats.labels) == n and len(system.input_positions) == q
    np.testing.assert_array_equal(mats.M, mats.M.T)
    assert np.all(np.linalg.eigvalsh(mats.M) > 0)
    # the assembled arrays cannot be changed behind the model's back
    with pytest.raises(ValueError):
        system.K[0, 0] = 1.0


def test_speed_is_given_once_in_the_call(model):
    # C(V) = C₀ + C₁/V: the creep damping of a lateral model scales as 1/V exactly; a model without
    # creep gives the same C at every speed. M, K and the inputs never depend on V.
    system = model.linear_system()
    slow, fast = model.matrices(10.0), model.matrices(40.0)
    np.testing.assert_array_equal(slow.K, fast.K)
    np.testing.assert_array_equal(slow.GK, fast.GK)
    np.testing.assert_allclose(slow.C - fast.C, system.C1 * (1 / 10.0 - 1 / 40.0), rtol=1e-12, atol=1e-9)
    for bad in (0.0, -5.0, float("nan")):
        with pytest.raises(ValueError, match="speed"):
            model.matrices(bad)


def test_replace_gives_a_validated_variant(model):
    assert model.replace() == model
    first = dataclasses.fields(model)[0].name
    with pytest.raises(TypeError):
        model.replace(no_such_parameter=1.0)
    value = getattr(model, first)
    if isinstance(value, float):
        with pytest.raises(ValueError, match=first):
            model.replace(**{first: -1.0})


@pytest.mark.parametrize("derivative", [0, 1])
def test_state_space_matches_the_second_order_frequency_response(model, derivative):
    # python-control evaluates C(iωI − A)⁻¹B + D of the state space; raildyn's axle_frf solves the
    # second-order system. Both are exact linear algebra on matrices up to ~1e7 in condition:
    # 1e-8 of the response's largest entry.
    system = model.linear_system()
    out = system.labels[0]
    ss = model.state_space(SPEED, outputs=[out], derivative=derivative)
    omega = np.array([0.7, 6.0, 40.0])
    response = control.frequency_response(ss, omega)
    H_ss = np.asarray(response.complex).reshape(system.n_inputs, omega.size).T  # (n_ω, q)
    H_2nd = system.axle_frf(omega, SPEED, out, derivative)
    np.testing.assert_allclose(H_ss, H_2nd, atol=1e-8 * np.abs(H_2nd).max())


def test_state_space_poles_are_the_stability_eigenvalues(model):
    poles = np.sort_complex(control.poles(model.state_space(SPEED)))
    ours = np.sort_complex(stability.eigenvalues_against_speed(model, [SPEED])[0])
    np.testing.assert_allclose(poles, ours, atol=1e-8 * np.abs(ours).max())


def test_acceleration_output_tied_to_the_track_by_a_damper_is_refused():
    # The vertical car's bogie is joined to the wheelsets by primary dampers: its acceleration per
    # metre of track grows without bound with frequency, so no proper StateSpace exists.
    with pytest.raises(ValueError, match="improper"):
        MANCHESTER_VERTICAL.state_space(SPEED, outputs=["bogie1 z"], derivative=2)
    ss = MANCHESTER_VERTICAL.state_space(SPEED, outputs=["body z"], derivative=2)
    omega = np.array([3.0, 12.0])
    H = np.asarray(control.frequency_response(ss, omega).complex).reshape(4, 2).T
    np.testing.assert_allclose(H, MANCHESTER_VERTICAL.linear_system().axle_frf(omega, SPEED, "body z", 2),
                               rtol=1e-8)  # fmt: skip


def test_as_linear_system_refuses_what_is_not_a_model():
    with pytest.raises(TypeError, match="LinearModel"):
        as_linear_system("car")


def test_linear_system_checks_its_matrices():
    one = np.eye(1)
    with pytest.raises(ValueError, match="positive definite"):
        LinearSystem(-one, one, one, one)
    with pytest.raises(ValueError, match="C0"):
        LinearSystem(one, np.eye(2), one, one)
    with pytest.raises(ValueError, match="input_kinds"):
        LinearSystem(one, one, one, one, GK=np.ones((1, 1)), input_kinds=("gauge",))


def test_linear_system_refuses_a_negative_mass_and_bad_fields():
    one = np.eye(1)
    with pytest.raises(ValueError, match="M must be positive definite"):
        LinearSystem(-one, one, one, one)
    with pytest.raises(ValueError, match="M must be symmetric"):
        LinearSystem(np.array([[2.0, 1.0], [0.0, 1.0]]), np.eye(2), np.eye(2), np.eye(2))
    with pytest.raises(TypeError, match="labels"):
        LinearSystem(one, one, one, one, labels="q")
    with pytest.raises(ValueError, match="input_rails"):
        LinearSystem(one, one, one, one, GK=one, input_rails=[2.0])
    with pytest.raises(ValueError, match="input_positions"):
        LinearSystem(one, one, one, one, GK=one, input_positions=[-1.0])
    with pytest.raises(TypeError, match="wheelsets"):
        LinearSystem(one, one, one, one, wheelsets=[(0, 0, "wheelset")])
    with pytest.raises(ValueError, match="speed"):
        SystemMatrices(one, one, one, np.zeros((1, 0)), np.zeros((1, 0)), ("q",), 0.0)


@pytest.mark.parametrize("bad", [1.0, "car", None])
def test_as_linear_system_names_its_parameter(bad):
    with pytest.raises(TypeError, match="model"):
        as_linear_system(bad)


def test_the_input_forces_carry_the_weight_and_are_minus_the_energys_gradient():
    # The vertical car at rest: the wheel forces (upwards on the wheels) sum to minus its weight, to rounding;
    # and for a displaced state they are −∂V/∂w of V = ½[q; w]ᵀ[[K, −G_K], [−G_Kᵀ, K_W]][q; w], by central
    # differences (exact for a quadratic, to rounding).
    from raildyn.vehicles import VerticalCar

    system = VerticalCar().linear_system()
    rest = system.static_deflection()
    zeros = np.zeros(system.n_inputs)
    forces = system.input_forces(rest, 0 * rest, zeros, zeros)
    assert forces.sum() == pytest.approx(system.gravity_load.sum(), rel=1e-12)
    rng = np.random.default_rng(3)
    q, w = rng.normal(size=system.size) * 1e-3, rng.normal(size=system.n_inputs) * 1e-3
    K_full = np.block([[system.K, -system.GK], [-system.GK.T, system.input_stiffness]])

    def energy(w_):
        x = np.concatenate([q, w_])
        return 0.5 * x @ K_full @ x

    h = 1e-6
    gradient = [(energy(w + h * e) - energy(w - h * e)) / (2 * h) for e in np.eye(system.n_inputs)]
    np.testing.assert_allclose(system.input_forces(q, 0 * q, w, 0 * w), -np.array(gradient), rtol=1e-6)


def test_a_system_with_a_direct_input_force_does_not_know_its_reaction():
    asm = Assembler(["z"], n_inputs=1)
    asm.mass("z", 1.0)
    asm.element({"z": 1.0}, 10.0)
    asm.track_force("z", 0, 5.0)
    with pytest.raises(ValueError, match="input_stiffness"):
        asm.system().input_forces([0.0], [0.0], [0.0], [0.0])


# ---------------------------------------------------------------------------
# The affine family (raildyn.linear_model.AffineFamily), and chapter 7's curve widget's families


def _wheelset_family(lam, k):
    return Wheelset(conicity=lam, yaw_stiffness=k, lateral_stiffness=1.0e6)


def _car_family(lam, k, ks):
    return LateralCar().replace(conicity=lam, yaw_stiffness=k, secondary_yaw_stiffness=ks)


# Chapter 7's critical-speed curve: every corner of its controls, the defaults, points off the grid.
_CURVE_POINTS = [
    (0.03, 2.0e6, 0.0),
    (0.5, 120.0e6, 2.0e6),
    (0.15, 62.8e6, 1.0e6),
    (0.41, 7.0e6, 0.37e6),
    (0.08, 95.0e6, 1.9e6),
]


def _families():
    """(family, make, points): a wheelset's, and the car's and bogie's of chapter 7's curve widget."""
    from raildyn.linear_model import AffineFamily
    from raildyn.widgets import chapter07

    car, bogie = chapter07._curve_families()
    return [
        # inside, and beyond ``origin`` and ``far``
        (AffineFamily(_wheelset_family, (0.03, 1.0e6), (0.5, 5.0e6)), _wheelset_family,
         [(0.1, 2.0e6), (0.45, 4.5e6), (0.02, 8.0e6)]),
        (car, _car_family, _CURVE_POINTS),
        (bogie, lambda *p: _car_family(*p).bogie, _CURVE_POINTS),
    ]  # fmt: skip


@pytest.mark.parametrize("case", [0, 1, 2], ids=["wheelset", "chapter 7 car", "chapter 7 bogie"])
def test_an_affine_family_gives_the_assembled_matrices(case):
    family, make, points = _families()[case]
    assert family.affine
    stacks = family.stacks(points)
    for k, p in enumerate(points):
        assembled = make(*p).linear_system()
        for name in ("M", "C0", "C1", "K"):
            theirs = getattr(assembled, name)
            np.testing.assert_allclose(stacks[name][k], theirs, rtol=0.0, atol=1e-12 * np.abs(theirs).max())


def test_an_affine_family_knows_what_stays_put_and_what_it_assembled():
    from raildyn.linear_model import AffineFamily

    family = AffineFamily(_wheelset_family, (0.03, 1.0e6), (0.5, 5.0e6))
    assert family.constant("M") and not family.constant("K")
    # the systems it assembled: the origin, each parameter moved alone, and the halfway check
    assert sorted(family.assembled) == [(0.03, 1.0e6), (0.03, 5.0e6), (0.265, 3.0e6), (0.5, 1.0e6)]
    assert isinstance(family.assembled[(0.5, 1.0e6)], LinearSystem)


@pytest.mark.parametrize(
    "make",
    [
        # ε following λ² rather than λ: a curve along one parameter
        lambda lam, k: Wheelset(conicity=lam, contact_angle_parameter=lam**2, yaw_stiffness=k),
        # the yaw stiffness scaled by the conicity: affine in each alone, not in both
        lambda lam, k: Wheelset(conicity=lam, yaw_stiffness=k * lam),
    ],
    ids=["curve", "product"],
)
def test_a_family_off_the_plane_is_assembled_at_every_point(make):
    from raildyn.linear_model import AffineFamily

    family = AffineFamily(make, (0.03, 1.0e6), (0.5, 5.0e6))
    assert not family.affine and not family.constant("M")
    points = [(0.1, 2.0e6), (0.3, 4.0e6)]
    stacks = family.stacks(points)
    for k, p in enumerate(points):
        np.testing.assert_array_equal(stacks["K"][k], make(*p).linear_system().K)
