"""Direct integration of linear systems: central difference, Houbolt, Wilson-θ, Newmark-β and HHT-α.

For a linear system with a constant step every scheme here is a linear
recursion ``z₊ = A z + B₀ f(t) + B₁ f(t + Δt)`` on a small state z (two or three
vectors of n entries). Each scheme's step is written once, in
:mod:`raildyn.integrators.recursions` (Bathe's tables {Bathe 1996, §9.2, Tables 9.1–9.3});
feeding it identity blocks gives ``A``, ``B₀`` and ``B₁`` with the effective stiffness
factorized once. The run is then one matrix–vector product a step, and the same
``A`` on the test oscillator is the amplification matrix of
:mod:`raildyn.integrators.amplification`. A run that blows up raises
:class:`raildyn.errors.SolverError` naming the scheme's stability limit (``_divergence``).
Newmark with γ = 2β (average acceleration among them) on a classically damped system
(ΦᵀCΦ diagonal, as for Rayleigh damping) runs mode by mode instead, each mode a second-order
digital filter over the whole history: the same answer to rounding, with O(n) work a step.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg
from scipy.linalg.blas import dgemv as gemv

from raildyn._checks import scalar
from raildyn.integrators._common import (
    IntegrationResult,
    Problem,
    completed,
    equilibrium_acceleration,
    problem,
    sampled_load,
    scale,
)
from raildyn.integrators._divergence import diverged
from raildyn.integrators.recursions import (  # the steps: importable from here for one more issue
    RecursionMatrices,  # noqa: F401
    _check_newmark,
    _recursion,
    _solver,
    central_difference_step,
    houbolt_step,
    newmark_step,
    recursion_matrices,  # noqa: F401
    wilson_step,
)
from raildyn.vibration import first_order_matrix

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.signal

__all__ = [
    "average_acceleration",
    "central_difference",
    "hht_alpha",
    "houbolt",
    "linear_acceleration",
    "newmark",
    "wilson",
]

# How often (in steps) the recursion looks for a blow-up: often enough that a state growing even
# a hundredfold a step is caught long before it overflows, rarely enough to cost nothing.
_CHECK_EVERY = 16


def _recur(A, B0, B1, z0, load, steps: int, bound: float):
    """Run z₊ = A z + B₀ f_k + B₁ f_{k+1}; return the states (rows) and the first bad row or None."""
    Z = np.empty((steps + 1, A.shape[0]))
    Z[0] = z0
    G = None if load is None else load[:steps] @ B0.T + load[1 : steps + 1] @ B1.T
    A = np.ascontiguousarray(A)
    product = np.empty(A.shape[0])
    for k in range(steps):
        if G is None:
            np.dot(A, Z[k], out=Z[k + 1])
        else:
            np.dot(A, Z[k], out=product)
            np.add(product, G[k], out=Z[k + 1])
        if k % _CHECK_EVERY == _CHECK_EVERY - 1 or k == steps - 1:
            first = max(0, k + 1 - _CHECK_EVERY)
            peak = np.abs(Z[first : k + 2]).max(axis=1)
            bad = np.flatnonzero(~(peak <= bound))
            if bad.size:
                return Z[: first + bad[0]], first + bad[0]
    return Z, None


def _two_step(p: Problem, load, gamma, beta, A, B0, B1, a0, bound):
    """Newmark with γ = 2β (the trapezoidal rule among them) as a recursion on displacements alone.

    Eliminating v and a from Newmark's relations and equilibrium leaves
    (M + γΔtC + βΔt²K) x₊ − (2M − (1−2γ)ΔtC − (½−2β+γ)Δt²K) x + (M − (1−γ)ΔtC + (½+β−γ)Δt²K) x₋
    = Δt² [β f₊ + (½−2β+γ) f + (½+β−γ) f₋] {Hughes 2000, §9.1}: one n × 2n product a step
    instead of 2n × 2n. With γ = 2β the velocity then follows from the displacements alone,
    v₊ = (1 − γ/β) v + (γ/β)(x₊ − x)/Δt, a scalar recursion run for every coordinate at once.
    """
    n, h, m = p.n, p.h, p.t.size
    M, C, K = p.M, p.C, p.K
    solve = _solver(M + gamma * h * C + beta * h * h * K)
    c1, c2 = 0.5 - 2 * beta + gamma, 0.5 + beta - gamma
    P1 = solve(2 * M - (1 - 2 * gamma) * h * C - c1 * h * h * K)
    P2 = -solve(M - (1 - gamma) * h * C + c2 * h * h * K)
    pair = np.ascontiguousarray(np.hstack([P2, P1]))  # acts on [x₋, x], two adjacent rows of X
    X = np.empty((m, n))
    X[0] = p.x0
    first = A @ np.r_[p.x0, p.v0, a0]
    if load is None:
        X[2:] = 0.0
    else:
        first += B0 @ load[0] + B1 @ load[1]
        # The load term of every step at once; each step then adds its product onto it in place.
        combined = beta * load[2:] + c1 * load[1:-1] + c2 * load[:-2]
        np.matmul(combined, (h * h) * solve(np.eye(n)).T, out=X[2:])
    X[1] = first[:n]
    pair_t = pair.T  # Fortran-ordered view: BLAS computes pairᵀᵀ y = pair y with no copy
    bad = None if np.abs(X[1]).max() <= bound else 1
    for k in range(1, m - 1 if bad is None else 1):
        gemv(1.0, pair_t, X[k - 1 : k + 1].reshape(-1), 1.0, X[k + 1], trans=1, overwrite_y=1)
        if k % _CHECK_EVERY == 0 or k == m - 2:
            start = max(1, k + 1 - _CHECK_EVERY)
            peak = np.abs(X[start : k + 2]).max(axis=1)
            over = np.flatnonzero(~(peak <= bound))
            if over.size:
                bad = start + over[0]
                break
    done = m if bad is None else bad
    return X[:done], _two_step_velocities(X[:done], p.v0, gamma / beta, h), bad


def _two_step_velocities(X, v0, ratio, h):
    """v₊ = (1 − γ/β) v + (γ/β)(x₊ − x)/Δt for every coordinate at once (γ = 2β)."""
    import scipy.signal

    v = np.empty_like(X)
    v[0] = v0
    if len(X) > 1:
        zi = ((1 - ratio) * v0)[None, :]
        v[1:] = scipy.signal.lfilter(
            [1.0], [1.0, ratio - 1.0], np.diff(X, axis=0) * (ratio / h), axis=0, zi=zi
        )[0]
    return v


def _classical_modes(p: Problem):
    """(ω², 2ξω, Φ) when the damping is classical (ΦᵀCΦ diagonal, C and K symmetric), else None.

    Φ holds the mass-normalised undamped modes. The tolerance (1e-10 of the largest
    modal damping) keeps rounding in a Rayleigh C from hiding its diagonal form.
    """
    K, C = p.K, p.C
    if not (
        np.allclose(K, K.T, rtol=0.0, atol=1e-12 * np.abs(K).max())
        and np.allclose(C, C.T, rtol=0.0, atol=1e-12 * max(np.abs(C).max(), 1e-300))
    ):
        return None
    # Through the Cholesky factor M = L Lᵀ: the standard symmetric problem of L⁻¹ K L⁻ᵀ, then Φ = L⁻ᵀ U.
    lower_inv = scipy.linalg.solve_triangular(np.linalg.cholesky(p.M), np.eye(p.n), lower=True)
    stiffness, shapes = np.linalg.eigh(lower_inv @ K @ lower_inv.T)
    phi = lower_inv.T @ shapes
    modal_c = phi.T @ C @ phi
    damping = np.diag(modal_c).copy()
    off = modal_c - np.diag(damping)
    if np.abs(off).max() > 1e-10 * max(np.abs(damping).max(), 1e-300):
        return None
    return stiffness, damping, phi


def _modal_two_step(p: Problem, load, gamma, beta, modes, bound):
    """Newmark (α = 0, γ = 2β) for classically damped systems, one uncoupled mode at a time.

    The scheme is linear, so it commutes with the modal transform: applied to
    q̈ + 2ξω q̇ + ω² q = φᵀf mode by mode it gives the coupled answer (to
    rounding). Each mode's two-step recursion (see :func:`_two_step`) is a
    second-order digital filter run by ``scipy.signal.lfilter`` over the whole
    history, and velocities and accelerations follow mode by mode too: O(n) work
    a step instead of an n × 2n product. Returns x, v, a (rows in time) and the
    first bad row or None.
    """
    import scipy.signal

    stiffness, damping, phi = modes
    n, h, m = p.n, p.h, p.t.size
    q0, qd0 = phi.T @ (p.M @ p.x0), phi.T @ (p.M @ p.v0)
    r = np.zeros((n, m)) if load is None else phi.T @ load.T  # modal loads, one row a mode
    # First step: Newmark's predictor–corrector on every mode at once {Bathe 1996, Table 9.3}.
    qdd0 = r[:, 0] - damping * qd0 - stiffness * q0
    q_pred = q0 + h * qd0 + h * h * (0.5 - beta) * qdd0
    qd_pred = qd0 + h * (1 - gamma) * qdd0
    qdd1 = (r[:, 1] - damping * qd_pred - stiffness * q_pred) / (
        1 + gamma * h * damping + beta * h * h * stiffness
    )
    q1 = q_pred + beta * h * h * qdd1
    c1, c2 = 0.5 - 2 * beta + gamma, 0.5 + beta - gamma
    a0 = 1 + gamma * h * damping + beta * h * h * stiffness
    a1 = -(2 - (1 - 2 * gamma) * h * damping - c1 * h * h * stiffness)
    a2 = 1 - (1 - gamma) * h * damping + c2 * h * h * stiffness
    drive = h * h * (beta * r[:, 2:] + c1 * r[:, 1:-1] + c2 * r[:, :-2])
    Q = np.empty((n, m))
    Q[:, 0], Q[:, 1] = q0, q1
    for j in range(n):
        den = [a0[j], a1[j], a2[j]]
        zi = scipy.signal.lfiltic([1.0], den, y=[q1[j], q0[j]])
        Q[j, 2:] = scipy.signal.lfilter([1.0], den, drive[j], zi=zi)[0]
    ratio = gamma / beta  # the velocity recursion of _two_step_velocities, along each mode's row
    Qd = np.empty_like(Q)
    Qd[:, 0] = qd0
    zi = ((1 - ratio) * qd0)[:, None]
    Qd[:, 1:] = scipy.signal.lfilter(
        [1.0], [1.0, ratio - 1.0], np.diff(Q, axis=1) * (ratio / h), axis=1, zi=zi
    )[0]
    Qdd = r - damping[:, None] * Qd - stiffness[:, None] * Q  # each mode in equilibrium
    X = (phi @ Q).T
    over = np.flatnonzero(~(np.abs(X).max(axis=1) <= bound))
    bad = int(over[0]) if over.size else None
    done = m if bad is None else bad
    return X[:done], (phi @ Qd[:, :done]).T, (phi @ Qdd[:, :done]).T, bad


def _finish(name, p: Problem, x, v, a, bad, limit_params) -> IntegrationResult:
    """Package the rows (m, n) into the result, or raise SolverError (holding the completed part)."""
    if bad is not None:
        raise diverged(name, p, bad, x, v, a, limit_params)
    return completed(name, p, x, v, a)


# ---------------------------------------------------------------------------
# Public integrators. Each raises raildyn.errors.SolverError, naming the scheme's stability limit and
# holding the completed part of the run as ``partial``, if the run blows up.


def newmark(M, C, K, t, x0, v0, force=None, *, gamma=0.5, beta=0.25) -> IntegrationResult:
    """Newmark-β integration of ``M x'' + C x' + K x = f(t)`` {Newmark 1959}.

    Δt is the spacing of ``t``. γ = ½, β = ¼ is the average (constant) acceleration
    method, unconditionally stable and second order; γ = ½, β = 1/6 the linear
    acceleration method, stable for ω Δt ≤ 2√3; γ > ½ adds numerical damping and
    drops the order to one {Bathe 1996, §9.2.4; Hughes 2000, §9.1}.

    Parameters
    ----------
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like, shape (n,), or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f(t) in N: sampled on ``t``, or ``force(t)`` returning n values.
    gamma, beta : float
        Newmark's parameters, γ in [½, 1.5], β in [0, 1].

    Returns
    -------
    IntegrationResult

    Raises
    ------
    raildyn.errors.SolverError
        If the run blows up: the message names the step, the time and the stability
        limit; ``partial`` holds the steps completed before.

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> r = newmark(1.0, 0.0, (2 * np.pi) ** 2, t, 1.0, 0.0)
    >>> round(float(r.x[0, -1]), 4)  # cos 2π = 1 after one period, less a 0.03 % period error
    1.0
    """
    gamma, beta = _check_newmark(gamma, beta)
    return _newmark_family(M, C, K, t, x0, v0, force, gamma, beta, 0.0, "newmark")


def _newmark_family(M, C, K, t, x0, v0, force, gamma, beta, alpha, name) -> IntegrationResult:
    """Newmark (α = 0) or HHT-α with checked parameters; the public functions below name the preset."""
    p = problem(M, C, K, t, x0, v0)
    with np.errstate(
        over="ignore", invalid="ignore", divide="ignore"
    ):  # an overflow is refused or reported below
        load = sampled_load(force, p)
        n, h = p.n, p.h
        a0 = equilibrium_acceleration(p, p.x0, p.v0, None if load is None else load[0])
        params = {"gamma": gamma, "beta": beta} if name == "newmark" else ({"alpha": alpha} if alpha else {})
        bound = scale(p, load)
        modes = _classical_modes(p) if alpha == 0.0 and gamma == 2 * beta and p.t.size > 2 else None
        if modes is not None:
            x, v, a, bad = _modal_two_step(p, load, gamma, beta, modes, bound)
            return _finish(name, p, x, v, a, bad, params)
        A, B0, B1 = _recursion(newmark_step(p.M, p.C, p.K, h, gamma, beta, alpha), 3 * n, n)
        if alpha == 0.0 and gamma == 2 * beta and p.t.size > 2:
            x, v, bad = _two_step(p, load, gamma, beta, A, B0, B1, a0, bound)
            # a from equilibrium: differencing v instead would lose digits as 1/(ωΔt) for slow modes.
            a = equilibrium_acceleration(p, x, v, None if load is None else load[: len(x)])
        elif alpha == 0.0:
            # Newmark's a₊ satisfies equilibrium at t + Δt, so a is a function of (x, v, f): eliminating it
            # leaves a recursion on (x, v) alone, two thirds the size. The lower rows of the first-order
            # matrix, −M⁻¹[K, C], give a from (x, v).
            E = np.vstack([np.eye(2 * n), first_order_matrix(p.M, p.C, p.K)[n:]])
            D = np.vstack([np.zeros((2 * n, n)), np.linalg.inv(p.M)])
            Ar, B0r, B1r = A[: 2 * n] @ E, A[: 2 * n] @ D + B0[: 2 * n], B1[: 2 * n]
            Z, bad = _recur(Ar, B0r, B1r, np.r_[p.x0, p.v0], load, p.t.size - 1, bound)
            x, v = Z[:, :n], Z[:, n:]
            a = equilibrium_acceleration(p, x, v, None if load is None else load[: len(Z)])
        else:
            Z, bad = _recur(A, B0, B1, np.r_[p.x0, p.v0, a0], load, p.t.size - 1, bound)
            x, v, a = Z[:, :n], Z[:, n : 2 * n], Z[:, 2 * n :]
        return _finish(name, p, x, v, a, bad, params)


def average_acceleration(M, C, K, t, x0, v0, force=None) -> IntegrationResult:
    """Newmark's average acceleration (trapezoidal) method, γ = ½, β = ¼.

    Unconditionally stable, second order, with no numerical damping: the spectral
    radius is 1 at every step {Bathe 1996, §9.4}. A classically damped system
    (ΦᵀCΦ diagonal) runs mode by mode; see :func:`newmark`.

    Parameters
    ----------
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like, shape (n,), or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f(t) in N: sampled on ``t``, or ``force(t)`` returning n values.

    Returns
    -------
    IntegrationResult

    Examples
    --------
    >>> r = average_acceleration(1.0, 0.0, 1.0, np.linspace(0.0, 10.0, 101), 1.0, 0.0)
    >>> round(float(0.5 * r.v[0, -1] ** 2 + 0.5 * r.x[0, -1] ** 2), 12)  # energy kept exactly
    0.5
    """
    return _newmark_family(M, C, K, t, x0, v0, force, 0.5, 0.25, 0.0, "average_acceleration")


def linear_acceleration(M, C, K, t, x0, v0, force=None) -> IntegrationResult:
    """Newmark's linear acceleration method, γ = ½, β = 1/6: stable for ω Δt ≤ 2√3.

    Parameters
    ----------
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like, shape (n,), or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f(t) in N: sampled on ``t``, or ``force(t)`` returning n values.

    Returns
    -------
    IntegrationResult
    """
    return _newmark_family(M, C, K, t, x0, v0, force, 0.5, 1 / 6, 0.0, "linear_acceleration")


def hht_alpha(M, C, K, t, x0, v0, force=None, *, alpha=-0.05) -> IntegrationResult:
    """HHT-α {Hilber, Hughes & Taylor 1977}: γ = ½ − α, β = (1 − α)²/4, α in [−⅓, 0].

    Second order and unconditionally stable, with numerical damping that grows
    with Δt/T up to a spectral radius (1 + α)/(1 − α) at Δt/T → ∞; α = 0 is the
    average acceleration method.

    Parameters
    ----------
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like, shape (n,), or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f(t) in N: sampled on ``t``, or ``force(t)`` returning n values.
    alpha : float
        α in [−⅓, 0].

    Returns
    -------
    IntegrationResult
    """
    alpha = scalar("alpha", alpha, low=-1 / 3, high=0.0)
    gamma, beta = 0.5 - alpha, (1 - alpha) ** 2 / 4
    if alpha == 0.0:
        return average_acceleration(M, C, K, t, x0, v0, force)
    return _newmark_family(M, C, K, t, x0, v0, force, gamma, beta, alpha, "hht_alpha")


def wilson(M, C, K, t, x0, v0, force=None, *, theta=1.4) -> IntegrationResult:
    """Wilson-θ {Wilson, Farhoomand & Bathe 1973}: unconditionally stable for θ_W ≥ 1.37 {Bathe 1996, §9.4}.

    The force at t + θ_W Δt is extrapolated linearly from its samples at t and t + Δt;
    θ_W = 1 is the linear acceleration method.

    Parameters
    ----------
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like, shape (n,), or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f(t) in N: sampled on ``t``, or ``force(t)`` returning n values.
    theta : float
        θ_W, Wilson's stretch of the step, in [1, 3].

    Returns
    -------
    IntegrationResult
    """
    theta = scalar("theta", theta, low=1.0, high=3.0)
    p = problem(M, C, K, t, x0, v0)
    with np.errstate(
        over="ignore", invalid="ignore", divide="ignore"
    ):  # an overflow is refused or reported below
        load = sampled_load(force, p)
        n = p.n
        a0 = equilibrium_acceleration(p, p.x0, p.v0, None if load is None else load[0])
        A, B0, B1 = _recursion(wilson_step(p.M, p.C, p.K, p.h, theta), 3 * n, n)
        Z, bad = _recur(A, B0, B1, np.r_[p.x0, p.v0, a0], load, p.t.size - 1, scale(p, load))
        x, v, a = Z[:, :n], Z[:, n : 2 * n], Z[:, 2 * n :]
        return _finish("wilson", p, x, v, a, bad, {"theta": theta})


def central_difference(M, C, K, t, x0, v0, force=None) -> IntegrationResult:
    """The central difference method: explicit, second order, stable for Δt ≤ T_min/π {Bathe 1996, §9.2.1}.

    It starts from the fictitious x(−Δt) = x₀ − Δt v₀ + ½Δt² a₀, and takes one
    step past the grid so that v and a at the last time use the same centred
    differences as the rest.

    Parameters
    ----------
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like, shape (n,), or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f(t) in N: sampled on ``t``, or ``force(t)`` returning n values.

    Returns
    -------
    IntegrationResult

    Raises
    ------
    raildyn.errors.SolverError
        Past the limit the run blows up; the error names the step, the time and the
        limit T_min/π, and holds the steps completed before as ``partial``.

    Examples
    --------
    >>> from raildyn.errors import SolverError
    >>> t = np.arange(200) * 0.35  # T = 1 s: past T/π = 0.318 s
    >>> try:
    ...     central_difference(1.0, 0.0, (2 * np.pi) ** 2, t, 1.0, 0.0)
    ... except SolverError as err:
    ...     print(err.step, err.partial.t.size == err.step, "T_min/pi = 0.31831 s" in str(err))
    21 True True
    """
    p = problem(M, C, K, t, x0, v0)
    with np.errstate(
        over="ignore", invalid="ignore", divide="ignore"
    ):  # an overflow is refused or reported below
        load = sampled_load(force, p)
        n, h = p.n, p.h
        a0 = equilibrium_acceleration(p, p.x0, p.v0, None if load is None else load[0])
        A, B0, B1 = _recursion(central_difference_step(p.M, p.C, p.K, h), 2 * n, n)
        padded = None if load is None else np.vstack([load, load[-1:]])
        z0 = np.r_[p.x0, p.x0 - h * p.v0 + 0.5 * h * h * a0]
        Z, bad = _recur(A, B0, B1, z0, padded, p.t.size, scale(p, load))
        x_next, x, x_prev = Z[1:, :n], Z[:-1, :n], Z[:-1, n:]
        v = (x_next - x_prev) / (2 * h)
        a = (x_next - 2 * x + x_prev) / (h * h)
        if bad is not None:
            bad = max(bad - 1, 0)
        return _finish("central_difference", p, x, v, a, bad, {})


def houbolt(M, C, K, t, x0, v0, force=None) -> IntegrationResult:
    """Houbolt's method {Houbolt 1950}: third-order backward differences, unconditionally stable.

    A three-step method: the first two steps are taken with the average
    acceleration method (also second order), as Houbolt's own start needs
    values before t₀.

    Parameters
    ----------
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like, shape (n,), or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f(t) in N: sampled on ``t``, or ``force(t)`` returning n values.

    Returns
    -------
    IntegrationResult
    """
    p = problem(M, C, K, t, x0, v0)
    with np.errstate(
        over="ignore", invalid="ignore", divide="ignore"
    ):  # an overflow is refused or reported below
        load = sampled_load(force, p)
        n, h, m = p.n, p.h, p.t.size
        head = average_acceleration(
            p.M, p.C, p.K, p.t[: min(m, 3)], p.x0, p.v0, None if load is None else load[:3].T
        )
        if m <= 3:
            return IntegrationResult(p.t, head.x, head.v, head.a, "houbolt", m - 1, 0)
        A, B0, B1 = _recursion(houbolt_step(p.M, p.C, p.K, h), 3 * n, n)
        z2 = np.r_[head.x[:, 2], head.x[:, 1], head.x[:, 0]]
        Z, bad = _recur(A, B0, B1, z2, None if load is None else load[2:], m - 3, scale(p, load))
        xs = np.vstack([head.x[:, :2].T, Z[:, :n]])  # x_0 … x_k
        x3 = xs[3:]
        v = (11 * x3 - 18 * xs[2:-1] + 9 * xs[1:-2] - 2 * xs[:-3]) / (6 * h)
        a = (2 * x3 - 5 * xs[2:-1] + 4 * xs[1:-2] - xs[:-3]) / (h * h)
        v = np.vstack([head.v.T, v])
        a = np.vstack([head.a.T, a])
        if bad is not None:
            bad = bad + 2
        return _finish("houbolt", p, xs, v, a, bad, {})
