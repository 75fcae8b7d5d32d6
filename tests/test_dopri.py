"""The compiled Dormand–Prince integrator (raildyn.integrators._dopri) against scipy's RK45.

Both take the same steps by construction (same tableau, error norm, step factors and first step),
so they are held to the same number of evaluations and to agreement near rounding: 1e-11 of the
solution's scale, the round-off of a few thousand steps summed in a different order.
"""

import numba
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from raildyn.integrators import _dopri


@numba.njit(_dopri.RHS_SIGNATURE, cache=True)
def van_der_pol(t, y, member, data, out):
    mu = data[member, 0]
    out[0] = y[1]
    out[1] = mu * (1.0 - y[0] * y[0]) * y[1] - y[0]


@numba.njit(_dopri.RHS_SIGNATURE, cache=True)
def blows_up(t, y, member, data, out):
    # y' = y², y(0) = 1: y = 1/(1 - t) leaves every float before t = 1.
    out[0] = y[0] * y[0]


MUS = np.array([0.5, 1.0, 3.0])
T_OUT = np.linspace(0.0, 20.0, 201)
ATOL = np.full(2, 1e-9)


def _scipy(mu):
    return solve_ivp(
        lambda t, y: [y[1], mu * (1 - y[0] ** 2) * y[1] - y[0]],
        (0.0, 20.0), [2.0, 0.0], rtol=1e-7, atol=1e-9, t_eval=T_OUT, max_step=0.05,
    )  # fmt: skip


def _run(member, max_steps=1 << 62):
    data = MUS[:, None].copy()
    y, f = np.array([2.0, 0.0]), np.empty(2)
    h = _dopri.start(van_der_pol, data, member, 0.0, y, 20.0, 1e-7, ATOL, 0.05, f)
    counts = np.array([2, 10**9, 0, 0, 0])
    out = np.zeros((2, T_OUT.size))
    t, status = 0.0, _dopri.PAUSED
    while status == _dopri.PAUSED:
        status, t, h = _dopri.advance(
            van_der_pol, data, member, t, y, f, h, 20.0, 1e-7, ATOL, 0.05, T_OUT, np.array([0, 1]), out,
            counts, max_steps,
        )  # fmt: skip
    return status, t, counts, out


@pytest.mark.parametrize("member", range(3))
def test_takes_scipys_steps_and_gives_its_dense_output(member):
    ref = _scipy(MUS[member])
    status, t, counts, out = _run(member)
    assert status == _dopri.DONE and t == 20.0
    assert counts[0] == ref.nfev
    assert counts[2] == T_OUT.size
    assert np.abs(out - ref.y).max() < 1e-11 * np.abs(ref.y).max()


def test_a_paused_run_resumes_on_the_same_steps():
    whole = _run(1)
    pieces = _run(1, max_steps=7)
    assert pieces[2][0] == whole[2][0]
    np.testing.assert_array_equal(pieces[3], whole[3])


def test_a_batch_runs_each_member_on_its_own_steps():
    states = np.tile([2.0, 0.0], (3, 1))
    out = np.zeros((3, 1, T_OUT.size))
    counts = np.zeros((3, 5), np.int64)
    counts[:, 1] = 10**9
    status, reached = np.zeros(3, np.int64), np.zeros(3)
    _dopri.advance_batch(
        van_der_pol, MUS[:, None].copy(), 20.0, states, 1e-7, ATOL, 0.05, T_OUT, np.array([0]), out, counts,
        status, reached,
    )  # fmt: skip
    for m in range(3):
        ref = _scipy(MUS[m])
        assert status[m] == _dopri.DONE and reached[m] == 20.0 and counts[m, 0] == ref.nfev
        assert np.abs(out[m, 0] - ref.y[0]).max() < 1e-11 * np.abs(ref.y).max()
        assert np.abs(states[m] - ref.y[:, -1]).max() < 1e-11 * np.abs(ref.y).max()


def test_failures_are_reported_not_hidden():
    data = np.zeros((1, 1))
    empty = np.zeros((1, 0))
    for budget, expected in ((10**9, _dopri.TOO_SMALL_STEP), (50, _dopri.OVER_BUDGET)):
        y, f = np.array([1.0]), np.empty(1)
        h = _dopri.start(blows_up, data, 0, 0.0, y, 2.0, 1e-6, np.full(1, 1e-9), np.inf, f)
        counts = np.array([2, budget, 0, 0, 0])
        status, t, _ = _dopri.advance(
            blows_up, data, 0, 0.0, y, f, h, 2.0, 1e-6, np.full(1, 1e-9), np.inf, np.zeros(0),
            np.zeros(0, np.int64), empty, counts, 1 << 62,
        )  # fmt: skip
        assert status == expected
        assert t < 1.0 + 1e-3  # the blow-up time (the last steps overshoot it in floating point)
        assert counts[0] <= budget


# ------------------------------------------------------------- the public runner over the kernel


def test_the_runner_takes_scipys_steps_and_counts_them():
    from raildyn.integrators import runner

    ref = _scipy(MUS[1])
    budget = runner.EvaluationBudget(10**6)
    run = runner.dormand_prince(
        van_der_pol,
        MUS[:, None],
        [2.0, 0.0],
        T_OUT,
        rtol=1e-7,
        atol=ATOL,
        max_step=0.05,
        member=1,
        budget=budget,
    )
    assert run.evaluations == ref.nfev == budget.used
    assert np.abs(run.y - ref.y).max() < 1e-11 * np.abs(ref.y).max()  # as the kernel's own test
    batch = runner.dormand_prince_batch(
        van_der_pol, MUS[:, None], np.tile([2.0, 0.0], (3, 1)), T_OUT, rtol=1e-7, atol=ATOL, max_step=0.05
    )
    assert batch[1].evaluations == ref.nfev
    np.testing.assert_array_equal(batch[1].y, run.y)
    np.testing.assert_array_equal(batch[1].end, run.end)


def test_the_runners_two_engines_fail_by_one_rule():
    # y' = y², y(0) = 1 blows up at t = 1: both engines stop there, and say so with SolverError.
    from raildyn.errors import SolverError
    from raildyn.integrators import runner

    with pytest.raises(SolverError, match="step size is less than spacing") as compiled:
        runner.dormand_prince(blows_up, [[0.0]], [1.0], [0.0, 0.5, 2.0], label="the blow-up")
    assert compiled.value.time < 1.0 + 1e-3 and compiled.value.step > 0
    assert compiled.value.partial.t.tolist() == [0.0, 0.5]  # the output times it passed
    assert compiled.value.partial.y[0, 1] == pytest.approx(2.0, rel=1e-5)  # 1/(1 - t)
    with pytest.raises(SolverError, match="the blow-up needed more than 50 evaluations") as over:
        runner.dormand_prince(blows_up, [[0.0]], [1.0], [0.0, 2.0], budget=50, label="the blow-up")
    assert over.value.time < 1.0
    # scipy's engine, under the same budget: the same words.
    with pytest.raises(SolverError, match="needed more than 50 evaluations"):
        runner.solve_ivp(lambda t, y: y * y, (0.0, 2.0), [1.0], budget=50)
    with pytest.raises(SolverError, match="non-finite|spacing|failed"):
        runner.solve_ivp(lambda t, y: y * y, (0.0, 2.0), [1.0])
    # A budget shared by a task: what one run spends, the next cannot.
    shared = runner.EvaluationBudget(100)
    runner.solve_ivp(lambda t, y: -y, (0.0, 1.0), [1.0], budget=shared)
    assert 0 < shared.used < 100
    with pytest.raises(SolverError, match=f"more than {shared.left} evaluations"):
        runner.solve_ivp(lambda t, y: -y, (0.0, 50.0), [1.0], budget=shared, rtol=1e-10, atol=1e-12)


def test_the_runner_refuses_what_it_cannot_run():
    from raildyn.integrators import runner

    with pytest.raises(TypeError, match="rhs must be a numba function"):
        runner.dormand_prince(lambda t, y, m, d, o: None, [[0.0]], [1.0], [0.0, 1.0])
    with pytest.raises(ValueError, match="t_eval must hold at least two increasing times"):
        runner.dormand_prince(blows_up, [[0.0]], [1.0], [1.0, 0.0])
    with pytest.raises(ValueError, match="fun returned a non-finite value at the start"):
        runner.solve_ivp(lambda t, y: y * np.nan, (0.0, 1.0), [1.0])
    with pytest.raises(ValueError, match="budget must be"):
        runner.solve_ivp(lambda t, y: -y, (0.0, 1.0), [1.0], budget=0)
