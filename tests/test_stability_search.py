"""The public batched critical-speed search (raildyn.stability.search) and the affine family that feeds it."""

import numpy as np
import pytest

from raildyn import stability
from raildyn.linear_model import AffineFamily
from raildyn.stability import CriticalSpeeds, StateMatrices, critical_speeds
from raildyn.vehicles import Bogie
from raildyn.wheelset import Wheelset


def _wheelset(lam, k):
    return Wheelset(conicity=lam, yaw_stiffness=k, lateral_stiffness=1.0e6)


def test_state_matrices_are_those_of_the_system_at_every_speed():
    system = Bogie().linear_system()
    state = StateMatrices.of(system)
    speeds = np.array([5.0, 30.0, 90.0])
    ours = state.state_matrices(speeds)
    theirs = system.state_matrices(speeds)
    # the blocks M⁻¹K, M⁻¹C are solved once here and at each call there: the same up to round-off
    np.testing.assert_allclose(ours, theirs, rtol=1e-12, atol=1e-12 * np.abs(theirs).max())
    growth = state.largest_real_part(speeds)
    np.testing.assert_allclose(growth, np.linalg.eigvals(theirs).real.max(axis=1), rtol=1e-9, atol=1e-9)


def test_the_search_of_many_systems_gives_each_one_its_own_critical_speed_in_order():
    # two sizes mixed (a wheelset of 2 coordinates, a bogie of 6): grouped by size, returned in order
    models = [_wheelset(0.1, 1.0e6), Bogie(), _wheelset(0.2, 3.0e6), Bogie().replace(conicity=0.3)]
    found = critical_speeds(models, (1.0, 200.0), tol=0.01)
    for model, v, status in zip(models, found.speeds, found.status, strict=True):
        one = stability.critical_speed(model, (1.0, 200.0), tol=0.01)
        assert status == one.status
        # both narrow the same bracket below 2 tol; the stacks differ from one system by round-off only
        assert v == pytest.approx(one.speed, abs=0.02)
    assert found.found.all()


def test_an_affine_familys_stack_gives_the_critical_speeds_of_its_assembled_members():
    family = AffineFamily(_wheelset, (0.05, 1.0e6), (0.4, 5.0e6))
    points = [(0.1, 2.0e6), (0.25, 4.0e6), (0.38, 1.5e6)]
    found = critical_speeds(StateMatrices(**family.stacks(points)), (1.0, 200.0), tol=0.01)
    for p, v in zip(points, found.speeds, strict=True):
        # the plane reproduces each member's matrices to 1e-12: the same bracket, within 2 tol
        assert v == pytest.approx(
            stability.critical_speed(_wheelset(*p), (1.0, 200.0), tol=0.01).speed, abs=0.02
        )


def test_stable_and_unstable_systems_get_their_status():
    stiff = _wheelset(0.02, 5.0e7)  # a stiff yaw spring, a flat cone: stable up to 30 m/s
    found = critical_speeds([stiff, _wheelset(0.1, 1.0e6)], (1.0, 30.0), tol=0.05)
    assert found.status[0] == "stable over the range" and found.speeds[0] == np.inf
    # V_c = 52.8 m/s: max Re s_r is 0.93 1/s at 60 m/s
    low = critical_speeds([_wheelset(0.1, 1.0e6)], (60.0, 70.0), tol=0.05)
    assert low.status == ("unstable at the lowest speed",) and low.speeds[0] == 60.0


@pytest.mark.parametrize(
    ("call", "error", "match"),
    [
        (lambda s: s.state_matrices([20.0]), ValueError, "which must name a system"),
        (
            lambda s: s.state_matrices([20.0], which=[2]),
            ValueError,
            r"which must hold whole numbers in \[0, 1\]",
        ),
        (lambda s: s.largest_real_part([20.0, 30.0], which=[0]), ValueError, "which must have shape"),
        (lambda s: critical_speeds(s, (1.0, 200.0), scan=4), ValueError, "scan"),
        (lambda s: critical_speeds("car"), TypeError, "systems must be"),
        (lambda s: critical_speeds([]), TypeError, "systems must be"),
        (lambda s: critical_speeds([_wheelset(0.1, 1e6), "car"]), TypeError, r"systems\[1\]"),
    ],
)
def test_bad_input_is_refused_by_name(call, error, match):
    family = AffineFamily(_wheelset, (0.05, 1.0e6), (0.4, 5.0e6))
    with pytest.raises(error, match=match):
        call(StateMatrices(**family.stacks([(0.1, 2.0e6), (0.2, 3.0e6)])))


def test_state_matrices_refuse_matrices_that_are_not_a_system():
    M, K = np.eye(2), np.eye(2)
    with pytest.raises(ValueError, match="M must be positive definite"):
        StateMatrices(-M, K, K, K)
    with pytest.raises(ValueError, match="must hold as many systems"):
        StateMatrices(M, np.stack([K, K]), np.stack([K, K, K]), K)
    with pytest.raises(ValueError, match="K must be 2 × 2"):
        StateMatrices(M, np.eye(3), K, K)
    with pytest.raises(ValueError, match="speeds must be inf exactly where"):
        CriticalSpeeds(np.array([np.inf]), ("crossing",))


def test_a_family_names_the_point_where_make_failed():
    with pytest.raises(ValueError, match="make failed at origin"):
        AffineFamily(_wheelset, (-0.05, 1.0e6), (0.4, 5.0e6))
    with pytest.raises(ValueError, match="far must differ from origin"):
        AffineFamily(_wheelset, (0.05, 1.0e6), (0.4, 1.0e6))
