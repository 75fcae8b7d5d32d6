"""raildyn.stability's critical speed and mode tracking against the plain procedures they shorten.

critical_speed solves M once for all its state matrices and stops its scan at the first upward
crossing; neither may change the answer. The reference here scans every speed with the public
:func:`raildyn.stability.largest_real_part` (A(V) from ``LinearSystem.state_matrices``) and refines
the first bracket by Brent's method to 1e-9 m/s: critical_speed must land within its own tolerance
of that zero. track_modes builds its pairing costs at once and
skips the Hungarian algorithm where the pairing is plain; the reference runs it at every step.
"""

import numpy as np
import pytest
import scipy.optimize

from raildyn import stability
from raildyn.vehicles import LateralCar
from raildyn.wheelset import Wheelset


def _full_scan(model, speed_range, tol, scan):
    system = model.linear_system()
    V = np.linspace(*speed_range, scan)
    g = stability.largest_real_part(system, V)
    if g[0] >= 0.0:
        return "unstable at the lowest speed", V[0]
    up = np.flatnonzero((g[:-1] < 0.0) & (g[1:] >= 0.0))
    if up.size == 0:
        return "stable over the range", np.inf
    i = int(up[0])
    f = lambda v: stability.largest_real_part(system, [v])[0]  # noqa: E731
    return "crossing", scipy.optimize.brentq(f, V[i], V[i + 1], xtol=tol)


MODELS = [
    (Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6), (1.0, 200.0)),  # crossing near 55 m/s
    (Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6), (60.0, 200.0)),  # unstable at the start
    (Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6), (1.0, 40.0)),  # stable over the range
    (LateralCar(), (1.0, 200.0)),
    (LateralCar().replace(conicity=0.03), (1.0, 200.0)),  # a crossing high in the range
    (LateralCar().replace(conicity=0.5, yaw_stiffness=5.0e6), (1.0, 200.0)),
    (LateralCar().bogie, (1.0, 200.0)),
]


@pytest.mark.parametrize("scan", [8, 16, 64, 101])
@pytest.mark.parametrize(("model", "speed_range"), MODELS)
def test_critical_speed_is_the_first_upward_zero_of_a_full_scan_to_its_tolerance(model, speed_range, scan):
    cs = stability.critical_speed(model, speed_range, tol=0.01, scan=scan)
    # The reference brackets the same zero from every speed of the scan and refines it by Brent's
    # method to 1e-9 m/s: the search must land within its own tol of it.
    status, speed = _full_scan(model, speed_range, 1e-9, scan)
    assert cs.status == status
    assert abs(cs.speed - speed) <= 0.01 if np.isfinite(speed) else cs.speed == speed


def test_the_statuses_of_the_cases_above_are_all_met():
    statuses = {stability.critical_speed(m, r, scan=16).status for m, r in MODELS}
    assert statuses == {"crossing", "unstable at the lowest speed", "stable over the range"}


def _track_step_by_step(lam, vec):
    """track_modes' rule in its plain form: at each speed the MAC with the previous speed's tracked
    vectors, the distance as a tie-breaker, and the Hungarian algorithm."""
    lam, vec = lam.copy(), vec.copy()
    for i in range(1, lam.shape[0]):
        similarity = stability.mac(vec[i - 1], vec[i])
        scale = np.maximum(np.abs(lam[i - 1])[:, None], 1.0)
        distance = np.abs(lam[i - 1][:, None] - lam[i][None, :]) / scale
        _, order = scipy.optimize.linear_sum_assignment((1.0 - similarity) + 0.5 * distance)
        lam[i], vec[i] = lam[i, order], vec[i][:, order]
    return lam, vec


@pytest.mark.parametrize(
    ("model", "speeds"),
    [
        (LateralCar(), np.linspace(5.0, 150.0, 60)),
        (LateralCar().replace(conicity=0.4, yaw_stiffness=5.0e6), np.linspace(5.0, 150.0, 60)),
        (Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6), np.linspace(1.0, 120.0, 240)),
        (Wheelset(yaw_stiffness=0.0, lateral_stiffness=0.0), np.linspace(1.0, 100.0, 100)),
    ],
)
def test_track_modes_pairs_as_the_hungarian_algorithm_at_every_step(model, speeds):
    # track_modes builds all costs at once and skips the Hungarian algorithm where each mode's cheapest
    # partner is distinct and strict; the pairing must be the step-by-step one exactly.
    lam, vec = np.linalg.eig(model.linear_system().state_matrices(speeds))
    tracked = stability.track_modes(lam, vec)
    expected_lam, expected_vec = _track_step_by_step(lam, vec)
    np.testing.assert_array_equal(tracked.eigenvalues, expected_lam)
    np.testing.assert_array_equal(tracked.vectors, expected_vec)


@pytest.mark.parametrize(("model", "speed_range"), [MODELS[0], MODELS[3], MODELS[6]])
def test_a_tolerance_below_round_off_still_ends_at_the_zero(model, speed_range):
    # tol far below the spacing of floats near V_c: the search ends where its bracket can shrink no
    # more (a few units in the last place), at Brent's zero to the round-off of g itself.
    cs = stability.critical_speed(model, speed_range, tol=1e-300, scan=16)
    _, speed = _full_scan(model, speed_range, 1e-12, 16)
    assert abs(cs.speed - speed) <= 1e-9 * speed
