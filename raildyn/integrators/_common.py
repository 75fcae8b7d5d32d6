"""What every integrator shares: the result type, the divergence error, the input checks.

The problem is ``M x'' + C x' + K x = f`` with n degrees of freedom. ``M`` must be
symmetric positive definite; ``C`` and ``K`` may be non-symmetric (creep forces
couple a wheelset's lateral and yaw motions unsymmetrically). A single
oscillator may be given with scalars.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg

from raildyn._checks import array, square_matrix, time_grid

# A run is declared divergent when a state entry exceeds this multiple of the scale set by the
# initial conditions and the load: far beyond any response a stable linear system can give, yet
# reached by a geometric blow-up within a few dozen steps, long before the numbers overflow.
DIVERGENCE_FACTOR = 1.0e8


@dataclass(frozen=True)
class IntegrationResult:
    """The time history computed by one integrator.

    Attributes
    ----------
    t : ndarray, shape (m,)
        Times, s (the requested grid, or its completed part if the run stopped).
    x, v, a : ndarray, shape (n, m)
        Displacement (m), velocity (m/s) and acceleration (m/s²) of each degree of freedom.
    method : str
        The scheme's name.
    steps : int
        Time steps taken.
    iterations : int
        Newton iterations (implicit nonlinear schemes), else evaluations of the force
        (first-order schemes and the stiff solver); 0 for the linear recursions.
    success : bool
        False if the run stopped early (``on_divergence="stop"``) or scipy failed.
    message : str
        Why the run ended.
    """

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    a: np.ndarray
    method: str
    steps: int
    iterations: int
    success: bool
    message: str


class DivergenceError(ArithmeticError):
    """An integration whose solution blew up; the message names the step and the stability limit."""

    def __init__(self, message: str, step: int, time: float):
        super().__init__(message)
        self.step = step
        self.time = time


@dataclass(frozen=True)
class Problem:
    """The checked matrices, initial state and grid of one run."""

    M: np.ndarray
    C: np.ndarray
    K: np.ndarray
    t: np.ndarray
    x0: np.ndarray
    v0: np.ndarray

    @property
    def n(self) -> int:
        return self.M.shape[0]

    @property
    def h(self) -> float:
        return float((self.t[-1] - self.t[0]) / (self.t.size - 1))


def problem(M, C, K, t, x0, v0) -> Problem:
    """Check the matrices, the uniform time grid (>= 2 samples) and the initial state."""
    M = square_matrix("M", M, positive_definite=True)
    n = M.shape[0]
    C = square_matrix("C", C, size=n, symmetric=False)
    K = square_matrix("K", K, size=n, symmetric=False)
    t = time_grid("t", t, uniform=True)
    if t.size < 2:
        raise ValueError(f"t must hold at least two times (one step), got {t.size}")
    x0 = array("x0", np.atleast_1d(x0), shape=(n,))
    v0 = array("v0", np.atleast_1d(v0), shape=(n,))
    return Problem(M, C, K, t, x0, v0)


def sampled_load(force, p: Problem) -> np.ndarray | None:
    """An external load f(t) as an array of shape (m, n): row k is f(t_k); None for no load.

    ``force`` may be None, an array of shape (n, m) (or (m,) when n = 1), or a
    callable ``force(t)`` returning n forces.
    """
    if force is None:
        return None
    if callable(force):
        values = np.array([np.atleast_1d(np.asarray(force(tk), dtype=float)) for tk in p.t])
        return array("force(t)", values, shape=(p.t.size, p.n))
    raw = np.asarray(force, dtype=float)
    if raw.ndim == 1 and p.n == 1:
        raw = raw[None, :]
    return array("force", raw, shape=(p.n, p.t.size)).T.copy()


def general_force(force, p: Problem):
    """A force f(t, x, v) as a callable, from None, a sampled array (linear in t) or a callable."""
    if force is None:
        zero = np.zeros(p.n)
        return lambda t, x, v: zero
    if callable(force):

        def checked(t, x, v):
            return np.asarray(force(t, x, v), dtype=float).reshape(p.n)

        return checked
    table = sampled_load(force, p)
    return lambda t, x, v: np.array([np.interp(t, p.t, table[:, j]) for j in range(p.n)])


def equilibrium_acceleration(p: Problem, x, v, load) -> np.ndarray:
    """a = M⁻¹(f − C v − K x) for one state or for rows of states, shape (m, n)."""
    # M is symmetric positive definite and, in practice, well conditioned: its explicit inverse
    # turns the m solves into three matrix products, fast for long histories.
    Minv = np.linalg.inv(p.M)
    out = x @ (-(Minv @ p.K)).T
    out += v @ (-(Minv @ p.C)).T
    if load is not None:
        out += load @ Minv.T
    return out


def scale(p: Problem, load) -> float:
    """A size for the state above which the run is called divergent (see DIVERGENCE_FACTOR)."""
    span = p.t[-1] - p.t[0]
    size = max(np.abs(p.x0).max(), np.abs(p.v0).max() * max(span, 1.0), np.abs(p.v0).max())
    if load is not None:
        stiffest = np.abs(np.linalg.eigvals(np.linalg.solve(p.M, p.K))).max()
        mass = np.linalg.eigvalsh(p.M).min()
        peak = np.abs(load).max()
        size = max(size, peak * max(span, 1.0) ** 2 / mass, peak / max(stiffest * mass, 1e-300))
    return DIVERGENCE_FACTOR * size if size > 0 else np.inf


def highest_frequency(M, K) -> float:
    """ω_max = √ of the largest |eigenvalue| of M⁻¹K, rad/s (sets the step limit of explicit schemes)."""
    lam = scipy.linalg.eigvals(K, M)
    return float(np.sqrt(np.abs(lam).max()))


def divergence(method: str, p: Problem, step: int, params, analysed_as: str | None = None) -> DivergenceError:
    """The error for a run that blew up at ``step``, naming the stability limit of ``method``."""
    from raildyn.integrators.analysis import stability_limit

    h = p.h
    time = float(p.t[0] + step * h)
    head = f"{method.replace('_', ' ')} diverged at step {step} (t = {time:.6g} s) with dt = {h:.6g} s"
    if method in ("forward_euler", "rk4", "abm"):
        return _first_order_divergence(method, p, step, time, head)
    wmax = highest_frequency(p.M, p.K)
    if wmax == 0.0:
        return DivergenceError(f"{head}; the system has no stiffness, so the growth is its own", step, time)
    t_min = 2 * np.pi / wmax
    ratio = stability_limit(analysed_as or method, **(params or {}))
    if np.isfinite(ratio) and ratio > 0:
        bound = ratio * t_min
        rule = f"dt <= {ratio:.4g} T_min" if method != "central_difference" else "dt <= T_min/pi"
        if h > bound:
            msg = (
                f"{head}: {method.replace('_', ' ')} is stable only for {rule} = {bound:.6g} s "
                f"(T_min = {t_min:.6g} s, the period of the highest undamped mode); reduce dt"
            )
        else:
            msg = (
                f"{head}, inside its stability limit {rule} = {bound:.6g} s (T_min = {t_min:.6g} s): "
                "the equations themselves have a growing solution, or the force is too stiff for this step"
            )
    elif ratio == 0:
        msg = (
            f"{head}: {method.replace('_', ' ')} amplifies every undamped oscillation whatever the step "
            f"(T_min = {t_min:.6g} s); use a stable scheme"
        )
    else:
        msg = (
            f"{head}: {method.replace('_', ' ')} is unconditionally stable for linear systems, so the "
            "equations themselves have a growing solution (an unstable system) or the force is too stiff"
        )
    return DivergenceError(msg, step, time)


def _first_order_divergence(method, p: Problem, step, time, head) -> DivergenceError:
    """The error for a first-order scheme: its limit is set by the eigenvalues of the first-order system."""
    from raildyn.integrators.analysis import first_order_step_limit

    n = p.n
    Minv = np.linalg.inv(p.M)
    state = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ p.K, -Minv @ p.C]])
    lam = np.linalg.eigvals(state)
    decaying = lam[lam.real <= 1e-12 * np.abs(lam).max()]
    if decaying.size == 0:
        return DivergenceError(f"{head}: every mode of the system grows; the growth is its own", step, time)
    limits = np.array([first_order_step_limit(method, z) for z in decaying])
    worst = int(np.argmin(limits))
    bound, z = limits[worst], decaying[worst]
    name = method.replace("_", " ")
    where = f"the eigenvalue {z.real:.6g}{z.imag:+.6g}j 1/s of the first-order system"
    if bound == 0.0:
        msg = f"{head}: {name} amplifies {where} at any step; use another scheme"
    elif p.h > bound:
        msg = (
            f"{head}: {name} is stable only for dt <= {bound:.6g} s here, set by {where} "
            f"(dt |lambda| <= {bound * abs(z):.4g}); reduce dt"
        )
    else:
        msg = (
            f"{head}, inside its stability limit dt <= {bound:.6g} s: the equations themselves have a "
            "growing solution, or the force is too stiff for this step"
        )
    return DivergenceError(msg, step, time)


def check_on_divergence(value: str) -> str:
    if value not in ("raise", "stop"):
        raise ValueError(f"on_divergence must be 'raise' or 'stop', got {value!r}")
    return value
