"""The one step of each linear scheme, as a map on column blocks, and the recursion matrices it makes.

For a linear system with a constant step every direct scheme of :mod:`raildyn.integrators.linear`
is a linear recursion ``z₊ = A z + B₀ f(t) + B₁ f(t + Δt)`` on a small state z (two or three
vectors of n entries). Each scheme's step is written here once, as in Bathe's tables {Bathe 1996,
§9.2, Tables 9.1–9.3}, on matrices of column states: :func:`newmark_step` (with HHT-α),
:func:`wilson_step`, :func:`central_difference_step` and :func:`houbolt_step`. Feeding a step
identity blocks gives ``A``, ``B₀`` and ``B₁`` (:func:`recursion_matrices`): the runs of
:mod:`raildyn.integrators.linear` step with them, and the same ``A`` on the test oscillator is the
amplification matrix of :mod:`raildyn.integrators.amplification`. This module is the bottom of
the package's linear half: it imports nothing of the package, so both of those can import it.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import scipy.linalg

from raildyn import _checks
from raildyn._checks import scalar

__all__ = [
    "RecursionMatrices",
    "central_difference_step",
    "houbolt_step",
    "newmark_step",
    "recursion_matrices",
    "wilson_step",
]

Step = Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray]


def _solver(matrix: np.ndarray):
    """Factorize once; return a function solving ``matrix @ y = b`` for a vector or block b.

    A stack of matrices (k, n, n) (the test oscillator at k steps, for the analysis) is
    inverted once instead, so that one call serves every step size. A singular matrix is
    refused: the step has no unique answer.
    """
    singular = ValueError(
        "M, C, K and the step h (the spacing of t) give a singular effective matrix: the scheme's "
        "step has no unique answer"
    )
    if matrix.ndim > 2:
        try:
            inverse = np.linalg.inv(matrix)
        except np.linalg.LinAlgError:
            raise singular from None
        return lambda b: inverse @ b
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", scipy.linalg.LinAlgWarning)  # refused just below
        lu = scipy.linalg.lu_factor(matrix, check_finite=False)
    if np.any(np.diag(lu[0]) == 0.0):
        raise singular
    return lambda b: scipy.linalg.lu_solve(lu, b, check_finite=False)


def _stack(*parts) -> np.ndarray:
    """Stack state parts along the second-last axis, broadcasting any leading (batch) axes."""
    lead = np.broadcast_shapes(*(p.shape[:-2] for p in parts))
    return np.concatenate([np.broadcast_to(p, lead + p.shape[-2:]) for p in parts], axis=-2)


def _system(M, C, K, h):
    """Check the matrices (n, n) and the step (a float, or (k, 1, 1) for k steps) of a step function."""
    M = _checks.square_matrix("M", M, positive_definite=True)
    n = M.shape[0]
    C = _checks.square_matrix("C", C, size=n, symmetric=False)
    K = _checks.square_matrix("K", K, size=n, symmetric=False)
    h = _checks.array("h", h, low=0.0, low_open=True)
    if not (h.ndim == 0 or (h.ndim == 3 and h.shape[1:] == (1, 1) and h.size)):
        raise ValueError(f"h must be a float or an array of shape (k, 1, 1), got shape {h.shape}")
    return M, C, K, h


def _check_newmark(gamma, beta):
    """γ and β of Newmark's scheme, checked: γ in [0.5, 1.5], β in [0, 1]."""
    gamma = _checks.scalar("gamma", gamma, low=0.5, high=1.5)
    beta = _checks.scalar("beta", beta, low=0.0, high=1.0)
    return gamma, beta


def _effective(matrix: np.ndarray, *also: np.ndarray):
    """Factorize an effective matrix of a step; refuse it, or ``also``, if it overflowed."""
    if not all(np.isfinite(m).all() for m in (matrix, *also)):
        raise ValueError(
            "M, C, K and the step h (the spacing of t) give an effective matrix that overflows: "
            "their sizes are beyond double precision (1e308) for this scheme"
        )
    return _solver(matrix)


# ---------------------------------------------------------------------------
# One step of each scheme, on column blocks: Z (s, c), F0 = f(t) and F1 = f(t + h), (n, c).
# M, C, K and h may also carry a leading batch axis (k, ...) for the analysis of the test oscillator.


def newmark_step(M, C, K, h, gamma, beta, alpha=0.0) -> Step:
    """Newmark-β (α = 0) or HHT-α on the state (x, v, a), acceleration form.

    HHT-α {Hilber, Hughes & Taylor 1977} weighs the elastic, damping and applied
    forces between t and t + Δt: M a₊ + (1+α)(C v₊ + K x₊ − f₊) − α(C v + K x − f) = 0,
    with Newmark's updates x₊ = x + Δt v + Δt²[(½−β) a + β a₊], v₊ = v + Δt[(1−γ) a + γ a₊].

    Parameters
    ----------
    M, C, K : ndarray, shape (n, n)
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m), finite;
        C and K may be non-symmetric, zero or negative.
    h : float or ndarray, shape (k, 1, 1)
        Time step, s, > 0; an array runs k steps at once (the test oscillator at k steps,
        for the analysis).
    gamma, beta : float
        Newmark's parameters, γ in [½, 1.5], β in [0, 1].
    alpha : float
        The HHT weight, in [−⅓, 0]; 0 for Newmark.

    Returns
    -------
    callable
        ``step(Z, F0, F1) -> Z₊`` on column blocks: states Z (s, c), loads F0 = f(t) and
        F1 = f(t + Δt) (n, c), in N.
    """
    M, C, K, h = _system(M, C, K, h)
    gamma, beta = _check_newmark(gamma, beta)
    alpha = scalar("alpha", alpha, low=-1 / 3, high=0.0)
    n = M.shape[-1]
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # an overflow is refused just below
        solve = _effective(M + (1 + alpha) * (gamma * h * C + beta * h * h * K))

    def step(Z, F0, F1):
        x, v, a = Z[..., :n, :], Z[..., n : 2 * n, :], Z[..., 2 * n :, :]
        x_pred = x + h * v + h * h * (0.5 - beta) * a
        v_pred = v + h * (1 - gamma) * a
        rhs = (1 + alpha) * F1 - alpha * F0
        rhs = rhs - C @ ((1 + alpha) * v_pred - alpha * v) - K @ ((1 + alpha) * x_pred - alpha * x)
        a_new = solve(rhs)
        return _stack(x_pred + beta * h * h * a_new, v_pred + gamma * h * a_new, a_new)

    return step


def wilson_step(M, C, K, h, theta) -> Step:
    """Wilson-θ on (x, v, a): linear acceleration over τ = θ_W Δt, equilibrium at t + τ {Bathe 1996, Tab 9.2}.

    Parameters
    ----------
    M, C, K : ndarray, shape (n, n)
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m), finite;
        C and K may be non-symmetric, zero or negative.
    h : float or ndarray, shape (k, 1, 1)
        Time step, s, > 0; an array runs k steps at once (for the analysis).
    theta : float
        Wilson's θ_W (τ = θ_W Δt), in [1, 3].

    Returns
    -------
    callable
        ``step(Z, F0, F1) -> Z₊`` on column blocks: states Z (s, c), loads F0 = f(t) and
        F1 = f(t + Δt) (n, c), in N.
    """
    M, C, K, h = _system(M, C, K, h)
    theta = scalar("theta", theta, low=1.0, high=3.0)
    n = M.shape[-1]
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # an overflow is refused just below
        tau = theta * h
        a0, a1 = 6 / tau**2, 3 / tau
        a2, a3 = 2 * a1, tau / 2
        a4, a5, a6 = a0 / theta, -a2 / theta, 1 - 3 / theta
        a7, a8 = h / 2, h * h / 6
        solve = _effective(K + a0 * M + a1 * C)

    def step(Z, F0, F1):
        x, v, a = Z[..., :n, :], Z[..., n : 2 * n, :], Z[..., 2 * n :, :]
        load = F0 + theta * (F1 - F0) + M @ (a0 * x + a2 * v + 2 * a) + C @ (a1 * x + 2 * v + a3 * a)
        x_tau = solve(load)
        a_new = a4 * (x_tau - x) + a5 * v + a6 * a
        v_new = v + a7 * (a_new + a)
        x_new = x + h * v + a8 * (a_new + 2 * a)
        return _stack(x_new, v_new, a_new)

    return step


def central_difference_step(M, C, K, h) -> Step:
    """Central difference on (x_n, x_{n−1}); equilibrium at t_n {Bathe 1996, Table 9.1}.

    Parameters
    ----------
    M, C, K : ndarray, shape (n, n)
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m), finite;
        C and K may be non-symmetric, zero or negative.
    h : float or ndarray, shape (k, 1, 1)
        Time step, s, > 0; an array runs k steps at once (for the analysis).

    Returns
    -------
    callable
        ``step(Z, F0, F1) -> Z₊`` on column blocks: states Z (s, c), loads F0 = f(t) and
        F1 = f(t + Δt) (n, c), in N.
    """
    M, C, K, h = _system(M, C, K, h)
    n = M.shape[-1]
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # an overflow is refused just below
        stiff = K - 2 * M / h**2
        lag = M / h**2 - C / (2 * h)
        solve = _effective(M / h**2 + C / (2 * h), stiff, lag)

    def step(Z, F0, F1):
        x, x_old = Z[..., :n, :], Z[..., n:, :]
        return _stack(solve(F0 - stiff @ x - lag @ x_old), x)

    return step


def houbolt_step(M, C, K, h) -> Step:
    """Houbolt on (x_n, x_{n−1}, x_{n−2}): backward differences, equilibrium at t_{n+1} {Houbolt 1950}.

    Parameters
    ----------
    M, C, K : ndarray, shape (n, n)
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m), finite;
        C and K may be non-symmetric, zero or negative.
    h : float or ndarray, shape (k, 1, 1)
        Time step, s, > 0; an array runs k steps at once (for the analysis).

    Returns
    -------
    callable
        ``step(Z, F0, F1) -> Z₊`` on column blocks: states Z (s, c), loads F0 = f(t) and
        F1 = f(t + Δt) (n, c), in N.
    """
    M, C, K, h = _system(M, C, K, h)
    n = M.shape[-1]
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # an overflow is refused just below
        a0, a1, a2, a3 = 2 / h**2, 11 / (6 * h), 5 / h**2, 3 / h
        a4, a5, a6, a7 = -2 * a0, -a3 / 2, a0 / 2, a3 / 9
        solve = _effective(K + a0 * M + a1 * C, a2 * M, a3 * C)

    def step(Z, F0, F1):
        x, x1, x2 = Z[..., :n, :], Z[..., n : 2 * n, :], Z[..., 2 * n :, :]
        load = F1 + M @ (a2 * x + a4 * x1 + a6 * x2) + C @ (a3 * x + a5 * x1 + a7 * x2)
        return _stack(solve(load), x, x1)

    return step


@dataclass(frozen=True)
class RecursionMatrices:
    """The matrices of a linear step z₊ = A z + B₀ f(t) + B₁ f(t + Δt).

    Attributes
    ----------
    A : ndarray, shape (s, s) or (k, s, s)
        The amplification matrix (dimensionless in consistent units of the state).
    B0, B1 : ndarray, shape (s, n) or (k, s, n)
        The response of the state to a unit load at the start and at the end of the step,
        in the state's units per N.

    All finite, of the shapes above (n >= 1).
    """

    A: np.ndarray
    B0: np.ndarray
    B1: np.ndarray

    def __post_init__(self):
        A = _checks.array("A", self.A)
        if A.ndim not in (2, 3) or A.shape[-1] != A.shape[-2] or A.size == 0:
            raise ValueError(f"A must be a square matrix (s, s) or a stack (k, s, s), got shape {A.shape}")
        object.__setattr__(self, "A", A)
        for name in ("B0", "B1"):
            B = _checks.array(name, getattr(self, name))
            if B.shape[:-1] != A.shape[:-1] or B.shape[-1] == 0 or B.shape[-1] != np.shape(self.B0)[-1]:
                raise ValueError(
                    f"{name} must have shape {A.shape[:-1] + ('n',)}: the rows (and stack) of A and "
                    f"n >= 1 columns as B0; got shape {B.shape}"
                )
            object.__setattr__(self, name, B)


def _recursion(step: Step, size: int, n: int):
    """A, B₀, B₁ of a checked step (with any leading stack axis of h): the step on identity blocks."""
    eye, zs, zn = np.eye(size), np.zeros((n, size)), np.zeros((size, n))
    zf = np.zeros((n, n))
    return step(eye, zs, zs), step(zn, np.eye(n), zf), step(zn, zf, np.eye(n))


def recursion_matrices(step: Step, size: int, n: int) -> RecursionMatrices:
    """A, B₀, B₁ of a linear step, found by applying it to identity blocks.

    Parameters
    ----------
    step : callable
        A step from :func:`newmark_step`, :func:`wilson_step`, :func:`central_difference_step`
        or :func:`houbolt_step`, for one step size (a float h), or any linear
        ``step(Z, F0, F1)`` returning finite blocks of shape (s, c).
    size : int
        Length s of the scheme's state: 2n or 3n.
    n : int
        Degrees of freedom, >= 1.

    Returns
    -------
    RecursionMatrices

    Examples
    --------
    >>> step = central_difference_step(np.eye(1), np.zeros((1, 1)), np.eye(1), 0.1)
    >>> recursion_matrices(step, 2, 1).A.round(6).tolist()  # [[2 − ω²Δt², −1], [1, 0]]
    [[1.99, -1.0], [1.0, 0.0]]
    """
    _checks.function("step", step)
    n = _checks.integer("n", n, low=1)
    size = _checks.integer("size", size, low=1)
    if size not in (2 * n, 3 * n):
        raise ValueError(
            f"size must be 2n or 3n, the state of a scheme on n = {n} degrees of freedom; got {size}"
        )
    try:
        A, B0, B1 = _recursion(step, size, n)
    except ValueError as err:
        raise ValueError(f"step does not act on a state of size {size} with n = {n} loads: {err}") from None
    A = _checks.returned("step", A, shape=(size, size), at="the identity block")
    B0 = _checks.returned("step", B0, shape=(size, n), at="a unit load at the start")
    B1 = _checks.returned("step", B1, shape=(size, n), at="a unit load at the end")
    return RecursionMatrices(A, B0, B1)
