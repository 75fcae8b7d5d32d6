"""The compiled time stepping of raildyn.vehicles.response against scipy.signal.lsim, its reference."""

import numpy as np
import pytest
from scipy import signal

from raildyn.vehicles import MANCHESTER_VERTICAL, periodic_profile, time_response
from raildyn.vehicles import response as resp


def _stable_system(rng, n, m):
    """A random stable state-space system: a shifted random A (every eigenvalue in the left half-plane)."""
    A = rng.normal(size=(n, n))
    A -= (np.linalg.eigvals(A).real.max() + 0.5) * np.eye(n)
    return A, rng.normal(size=(n, m)), rng.normal(size=(1, n)), rng.normal(size=(1, m))


@pytest.mark.parametrize("seed", range(4))
def test_first_order_hold_equals_lsim(seed):
    """Same matrix exponential and recurrence as lsim's interp=True: equal to round-off (1e-12 of the peak).

    The recurrence sums in another order than lsim's matrix products; over 2,000 steps of a stable
    system the differences stay at a few ulps of the largest state.
    """
    rng = np.random.default_rng(seed)
    n, m = rng.integers(1, 13), rng.integers(1, 9)
    A, B, C, D = _stable_system(rng, n, m)
    t = np.arange(2000) * 0.01
    U = np.cumsum(rng.normal(size=(t.size, m)), axis=0)
    reference = signal.lsim((A, B, C, D), U, t)[1]
    ours = resp._lsim(A, B, C, D, U, 0.01)
    assert np.abs(ours - reference).max() <= 1e-12 * np.abs(reference).max()


def test_one_sample_is_the_output_at_rest():
    rng = np.random.default_rng(7)
    A, B, C, D = _stable_system(rng, 3, 2)
    U = rng.normal(size=(1, 2))
    np.testing.assert_allclose(resp._lsim(A, B, C, D, U, 0.0), U @ D[0], rtol=1e-15)


@pytest.mark.parametrize("derivative", [0, 1, 2])
def test_time_response_equals_lsim_on_a_track(derivative):
    """The whole of time_response, its input terms and output rows, against lsim on the same system."""
    rng = np.random.default_rng(derivative)
    track = periodic_profile(1e-3 * rng.normal(size=400), 0.25)
    V, t = 30.0, np.arange(0.0, 4.0, 0.01)
    ours = time_response(MANCHESTER_VERTICAL, track.height, V, t, "body z", derivative, track.slope)
    system = MANCHESTER_VERTICAL.linear_system()
    n, mats = system.size, system.matrices(V)
    A = mats.state_matrix()
    B = np.vstack(
        [np.zeros((n, 2 * system.n_inputs)), np.linalg.solve(mats.M, np.hstack([mats.GK, mats.GC]))]
    )
    o = system.output_vector("body z")
    C = [np.concatenate([o, np.zeros(n)]), np.concatenate([np.zeros(n), o]), o @ A[n:]][derivative]
    D = o @ B[n:] if derivative == 2 else np.zeros(B.shape[1])
    x = V * t[:, None] - system.input_positions[None, :]
    U = np.hstack([track.height(x), V * track.slope(x)])
    reference = signal.lsim((A, B, C[None, :], D[None, :]), U, t)[1]
    assert np.abs(ours.y - reference).max() <= 1e-12 * np.abs(reference).max()
