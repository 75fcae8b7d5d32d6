"""Chapter 2: Newmark average acceleration on a 100-DOF chain, and the chapter's widget updates.

raildyn factorizes the effective stiffness once and runs each step as one product
with a precomputed matrix; the baseline is the loop a student writes from
Bathe's table, solving the full effective system at every step. Both must give
the same displacements to 1e-10 (relative to the largest). scipy's RK45 is then
timed at the loosest tolerance that is as accurate as Newmark on this problem.
"""

from __future__ import annotations

import numpy as np
import scipy.integrate

from benchmarks.common import Case, timed, widget_case
from raildyn import integrators, vibration
from raildyn.widgets import chapter02

DOF, STEPS, DT = (
    100,
    10_000,
    0.05,
)  # masses, steps, s (Δt = T_min/2: an implicit scheme steps over the top modes)


def chain_problem():
    """A fixed–free chain of 100 × 1000 kg on 1 MN/m springs, 2 % Rayleigh damping, a sine at the tip."""
    chain = vibration.chain_matrices(np.full(DOF, 1000.0), np.full(DOF, 1.0e6))
    M, K = chain.M, chain.K
    modes = vibration.modal_analysis(M, K).natural_frequencies
    coefficients = vibration.rayleigh_coefficients(modes[0], modes[-1], 0.02, 0.02)
    C = vibration.rayleigh_damping(M, K, coefficients.alpha, coefficients.beta)
    t = np.arange(STEPS + 1) * DT
    force = np.zeros((DOF, t.size))
    force[-1] = 1.0e3 * np.sin(3.0 * t)  # N; 3 rad/s drives the lowest few modes
    return M, C, K, t, force


def student_newmark(M, C, K, t, force, gamma=0.5, beta=0.25):
    """Newmark's method step by step as in Bathe (1996), Table 9.3, with a full solve each step."""
    h = t[1] - t[0]
    a0, a1, a2 = 1 / (beta * h * h), gamma / (beta * h), 1 / (beta * h)
    a3, a4, a5 = 1 / (2 * beta) - 1, gamma / beta - 1, h / 2 * (gamma / beta - 2)
    a6, a7 = h * (1 - gamma), gamma * h
    n = M.shape[0]
    x, v = np.zeros((n, t.size)), np.zeros((n, t.size))
    acc = np.linalg.solve(M, force[:, 0])
    keff = K + a0 * M + a1 * C
    for k in range(t.size - 1):
        rhs = (
            force[:, k + 1]
            + M @ (a0 * x[:, k] + a2 * v[:, k] + a3 * acc)
            + C @ (a1 * x[:, k] + a4 * v[:, k] + a5 * acc)
        )
        x[:, k + 1] = np.linalg.solve(keff, rhs)
        new = a0 * (x[:, k + 1] - x[:, k]) - a2 * v[:, k] - a3 * acc
        v[:, k + 1] = v[:, k] + a6 * acc + a7 * new
        acc = new
    return x


def _scipy(M, C, K, t, rtol, method="RK45", atol=None):
    """The same chain through solve_ivp as a first-order system (the tip force written in closed form)."""
    n = M.shape[0]
    A = vibration.first_order_matrix(M, C, K)
    tip = np.linalg.inv(M)[:, -1]

    def rhs(tk, y):
        dy = A @ y
        dy[n:] += tip * 1.0e3 * np.sin(3.0 * tk)
        return dy

    atol = 1e-9 * rtol if atol is None else atol
    sol = scipy.integrate.solve_ivp(
        rhs, (t[0], t[-1]), np.zeros(2 * n), method, t_eval=t, rtol=rtol, atol=atol
    )
    return sol.y[:n]


def cases(repeats: int):
    M, C, K, t, force = chain_problem()
    zeros = np.zeros(DOF)
    ours = integrators.average_acceleration(M, C, K, t, zeros, zeros, force).x
    theirs = student_newmark(M, C, K, t, force)
    misfit = np.abs(ours - theirs).max() / np.abs(theirs).max()
    if misfit > 1e-10:
        raise AssertionError(
            f"raildyn and the per-step Newmark differ by {misfit:.2e} (relative), not <= 1e-10"
        )
    # Reference: DOP853 far tighter than either; then the loosest RK45 tolerance as accurate as Newmark.
    reference = _scipy(M, C, K, t, 1e-11, "DOP853", atol=1e-14)
    size = np.abs(reference).max()
    target = np.abs(ours - reference).max() / size
    rtol = next(
        r
        for r in 10.0 ** -np.arange(3, 12)
        if np.abs(_scipy(M, C, K, t, r) - reference).max() / size <= target
    )
    fast = timed(lambda i: integrators.average_acceleration(M, C, K, t, zeros, zeros, force), repeats)
    slow = timed(lambda i: student_newmark(M, C, K, t, force), max(3, repeats // 3))
    rk = timed(lambda i: _scipy(M, C, K, t, rtol), max(3, repeats // 3))
    label = f"Newmark AA, {DOF}-DOF chain, {STEPS} steps (agree to {misfit:.0e}; error {target:.1e})"
    return [
        Case(label, fast, slow, "≥ 10× faster, same answer to 1e-10", "per-step np.linalg.solve"),
        Case(label, fast, rk, "report", f"solve_ivp RK45 rtol={rtol:.0e} (equal accuracy)"),
        *[widget_case(name, recipe, control, values, repeats) for name, recipe, control, values in MOVES],
    ]


# Control values a student might drag through.
MOVES = [
    ("scheme_response Δt/T", chapter02.SCHEME_RESPONSE, "dt_over_T", [0.02, 0.05, 0.1, 0.2, 0.3, 0.4]),
    (
        "scheme_response scheme",
        chapter02.SCHEME_RESPONSE,
        "method",
        ["central_difference", "houbolt", "wilson", "average_acceleration", "rk4"],
    ),
    ("accuracy_chart scheme", chapter02.ACCURACY_CHART, "method", ["houbolt", "wilson", "hht_alpha", "rk4"]),
]
