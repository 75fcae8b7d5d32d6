"""Integrators for ``M x'' + C x' + K x = f(t, x, x')``: first-order schemes, Newmark–Newton, a stiff solver.

The first-order schemes (forward Euler, classical Runge–Kutta, Adams–Bashforth–
Moulton) march the state y = (x, x') of y' = (x', M⁻¹(f − C x' − K x)). Newmark
with Newton–Raphson iterations solves the implicit equations of each step with
the tangent of the force, given or found by finite differences. The stiff solver
hands the same first-order system, with its Jacobian, to scipy's BDF or Radau
{Hairer & Wanner 1996}.
"""

from __future__ import annotations

import numpy as np
import scipy.integrate
import scipy.linalg

from raildyn._checks import integer, positive, scalar
from raildyn.integrators._common import (
    IntegrationResult,
    check_on_divergence,
    divergence,
    general_force,
    problem,
    sampled_load,
    scale,
)


def _first_order(p, force):
    """The right-hand side y' = g(t, y) with y = (x, v), and M's Cholesky factor."""
    n = p.n
    chol = scipy.linalg.cho_factor(p.M)
    f = general_force(force, p)

    def acceleration(t, x, v):
        return scipy.linalg.cho_solve(chol, f(t, x, v) - p.C @ v - p.K @ x)

    def rhs(t, y):
        x, v = y[:n], y[n:]
        return np.concatenate([v, acceleration(t, x, v)])

    return rhs, acceleration


def _bound(p, force):
    load = None if force is None or callable(force) else sampled_load(force, p)
    return scale(p, load)


def _march(name, p, force, advance, on_divergence) -> IntegrationResult:
    """Run ``advance(k, Y) -> y_{k+1}`` over the grid, checking every step for a blow-up."""
    on_divergence = check_on_divergence(on_divergence)
    rhs, acceleration = _first_order(p, force)
    n, m = p.n, p.t.size
    Y = np.empty((m, 2 * n))
    Y[0] = np.r_[p.x0, p.v0]
    bound = _bound(p, force)
    state = {"evals": 0}

    def counted(t, y):
        state["evals"] += 1
        return rhs(t, y)

    bad = None
    for k in range(m - 1):
        Y[k + 1] = advance(k, Y, counted)
        if not np.abs(Y[k + 1]).max() <= bound:
            bad = k + 1
            break
    done = m if bad is None else bad
    x, v = Y[:done, :n], Y[:done, n:]
    a = np.array([acceleration(tk, xk, vk) for tk, xk, vk in zip(p.t[:done], x, v, strict=True)])
    if bad is not None:
        err = divergence(name, p, bad, {})
        if on_divergence == "raise":
            raise err
        return IntegrationResult(p.t[:done], x.T, v.T, a.T, name, done - 1, state["evals"], False, str(err))
    return IntegrationResult(p.t, x.T, v.T, a.T, name, m - 1, state["evals"], True, "completed")


def forward_euler(M, C, K, t, x0, v0, force=None, *, on_divergence="raise") -> IntegrationResult:
    """Forward (explicit) Euler on y = (x, x'): first order; it amplifies every undamped oscillation.

    Parameters
    ----------
    M, C, K : array_like (n, n) or float
        Mass (kg; symmetric positive definite), damping (N·s/m), stiffness (N/m).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like (n,) or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f in N: sampled on ``t`` (linear in between), or ``force(t, x, v)`` returning n values.
    on_divergence : {"raise", "stop"}

    Returns
    -------
    IntegrationResult
        ``iterations`` counts the evaluations of the right-hand side.
    """
    p = problem(M, C, K, t, x0, v0)
    h = p.h

    def advance(k, Y, g):
        return Y[k] + h * g(p.t[k], Y[k])

    return _march("forward_euler", p, force, advance, on_divergence)


def rk4(M, C, K, t, x0, v0, force=None, *, on_divergence="raise") -> IntegrationResult:
    """Classical fourth-order Runge–Kutta on y = (x, x'); stable for ωΔt <= 2√2 when undamped.

    Arguments as :func:`forward_euler`.
    """
    p = problem(M, C, K, t, x0, v0)
    h = p.h

    def advance(k, Y, g):
        tk, y = p.t[k], Y[k]
        k1 = g(tk, y)
        k2 = g(tk + h / 2, y + h / 2 * k1)
        k3 = g(tk + h / 2, y + h / 2 * k2)
        k4 = g(tk + h, y + h * k3)
        return y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)

    return _march("rk4", p, force, advance, on_divergence)


def abm(M, C, K, t, x0, v0, force=None, *, on_divergence="raise") -> IntegrationResult:
    """Adams–Bashforth–Moulton predictor–corrector, fourth order, in PECE mode.

    Predict with the four-step Adams–Bashforth formula, evaluate, correct with the
    three-step Adams–Moulton formula, evaluate: two evaluations a step against
    RK4's four {Hairer, Nørsett & Wanner 1993, §III.1}. The first three steps are
    taken with RK4. Arguments as :func:`forward_euler`.
    """
    p = problem(M, C, K, t, x0, v0)
    h = p.h
    history: list[np.ndarray] = []  # f at the accepted points, newest last

    def advance(k, Y, g):
        tk, y = p.t[k], Y[k]
        if len(history) == k:
            history.append(g(tk, y))
        if k < 3:
            k1 = history[k]
            k2 = g(tk + h / 2, y + h / 2 * k1)
            k3 = g(tk + h / 2, y + h / 2 * k2)
            k4 = g(tk + h, y + h * k3)
            return y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        f0, f1, f2, f3 = history[k], history[k - 1], history[k - 2], history[k - 3]
        pred = y + h / 24 * (55 * f0 - 59 * f1 + 37 * f2 - 9 * f3)
        fp = g(tk + h, pred)
        return y + h / 24 * (9 * fp + 19 * f0 - 5 * f1 + f2)

    return _march("abm", p, force, advance, on_divergence)


def _fd_jacobian(f, t, x, v, fx):
    """∂f/∂x and ∂f/∂v by forward differences, steps scaled to each entry."""
    n = x.size
    dfdx, dfdv = np.empty((n, n)), np.empty((n, n))
    for j in range(n):
        for vec, out in ((x, dfdx), (v, dfdv)):
            d = 1.5e-8 * max(abs(vec[j]), 1e-6)  # √eps relative, with a floor for entries at zero
            moved = vec.copy()
            moved[j] += d
            out[:, j] = ((f(t, moved, v) if vec is x else f(t, x, moved)) - fx) / d
    return dfdx, dfdv


def newmark_newton(
    M,
    C,
    K,
    t,
    x0,
    v0,
    force=None,
    *,
    jacobian=None,
    gamma=0.5,
    beta=0.25,
    tol=1e-10,
    max_iter=20,
    on_divergence="raise",
) -> IntegrationResult:
    """Newmark-β with Newton–Raphson iterations for ``M x'' + C x' + K x = f(t, x, x')``.

    Each step solves r(a₊) = M a₊ + C v₊ + K x₊ − f(t₊, x₊, v₊) = 0 with
    x₊ = x + Δt v + Δt²[(½−β) a + β a₊] and v₊ = v + Δt[(1−γ) a + γ a₊], by Newton's
    method on the tangent M + γΔt (C − ∂f/∂v) + βΔt² (K − ∂f/∂x) {Bathe 1996, §9.5}.

    Parameters
    ----------
    M, C, K, t, x0, v0, force
        As :func:`forward_euler`; ``force(t, x, v)`` may be nonlinear.
    jacobian : callable, optional
        ``jacobian(t, x, v) -> (∂f/∂x, ∂f/∂v)``, each (n, n) (N/m, N·s/m). Without it, forward
        differences are used (2n extra force evaluations per iteration).
    gamma, beta : float
        Newmark's parameters; γ in [½, 1.5], β in (0, 1].
    tol : float
        Convergence when the displacement correction is below tol × (|x₊|∞ + Δt |v₊|∞ + 1e-300).
    max_iter : int
        Iterations allowed per step; more raises :class:`DivergenceError`.
    on_divergence : {"raise", "stop"}

    Returns
    -------
    IntegrationResult
        ``iterations`` is the total number of Newton iterations.
    """
    gamma = scalar("gamma", gamma, low=0.5, high=1.5)
    beta = scalar("beta", beta, low=0.0, high=1.0, low_open=True)
    tol = positive("tol", tol)
    max_iter = integer("max_iter", max_iter, low=1)
    on_divergence = check_on_divergence(on_divergence)
    p = problem(M, C, K, t, x0, v0)
    f = general_force(force, p)
    n, h, m = p.n, p.h, p.t.size
    X, V, A = np.empty((m, n)), np.empty((m, n)), np.empty((m, n))
    X[0], V[0] = p.x0, p.v0
    A[0] = np.linalg.solve(p.M, f(p.t[0], p.x0, p.v0) - p.C @ p.v0 - p.K @ p.x0)
    bound = _bound(p, force)
    iterations, bad, reason = 0, None, ""
    for k in range(m - 1):
        t1 = p.t[k + 1]
        x_pred = X[k] + h * V[k] + h * h * (0.5 - beta) * A[k]
        v_pred = V[k] + h * (1 - gamma) * A[k]
        a = A[k].copy()
        converged = False
        for _ in range(max_iter):
            x, v = x_pred + beta * h * h * a, v_pred + gamma * h * a
            fx = f(t1, x, v)
            r = p.M @ a + p.C @ v + p.K @ x - fx
            dfdx, dfdv = jacobian(t1, x, v) if jacobian is not None else _fd_jacobian(f, t1, x, v, fx)
            tangent = p.M + gamma * h * (p.C - np.asarray(dfdv)) + beta * h * h * (p.K - np.asarray(dfdx))
            da = np.linalg.solve(tangent, -r)
            a = a + da
            iterations += 1
            size = np.abs(x).max() + h * np.abs(v).max() + 1e-300
            if beta * h * h * np.abs(da).max() <= tol * size:
                converged = True
                break
        X[k + 1], V[k + 1], A[k + 1] = x_pred + beta * h * h * a, v_pred + gamma * h * a, a
        if not converged or not np.abs(np.r_[X[k + 1], V[k + 1]]).max() <= bound:
            bad = k + 1
            reason = "" if converged else f"; Newton's method did not converge in {max_iter} iterations"
            break
    if bad is not None:
        err = divergence("newmark_newton", p, bad, {"gamma": gamma, "beta": beta}, analysed_as="newmark")
        err.args = (str(err) + reason,)
        if on_divergence == "raise":
            raise err
        return IntegrationResult(
            p.t[:bad], X[:bad].T, V[:bad].T, A[:bad].T, "newmark_newton", bad - 1, iterations, False, str(err)
        )
    return IntegrationResult(p.t, X.T, V.T, A.T, "newmark_newton", m - 1, iterations, True, "completed")


def stiff(
    M, C, K, t, x0, v0, force=None, *, jacobian=None, method="Radau", rtol=1e-8, atol=1e-12
) -> IntegrationResult:
    """Integrate with scipy's implicit variable-step solvers (``solve_ivp`` with BDF or Radau).

    The Jacobian of the first-order system is given to scipy: the linear part
    [[0, I], [−M⁻¹K, −M⁻¹C]] plus, with ``jacobian``, the force's tangent.

    Parameters
    ----------
    M, C, K, t, x0, v0, force, jacobian
        As :func:`newmark_newton`.
    method : {"Radau", "BDF", "LSODA"}
    rtol, atol : float
        scipy's relative and absolute tolerances (> 0).

    Returns
    -------
    IntegrationResult
        ``steps`` is the number of steps scipy took (not the samples of ``t``),
        ``iterations`` the number of right-hand-side evaluations; ``success`` and
        ``message`` are scipy's.
    """
    if method not in ("Radau", "BDF", "LSODA"):
        raise ValueError(f"method must be 'Radau', 'BDF' or 'LSODA', got {method!r}")
    rtol, atol = positive("rtol", rtol), positive("atol", atol)
    p = problem(M, C, K, t, x0, v0)
    n = p.n
    rhs, acceleration = _first_order(p, force)
    Minv = np.linalg.inv(p.M)
    base = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ p.K, -Minv @ p.C]])

    def jac(tk, y):
        if jacobian is None:
            return base
        dfdx, dfdv = jacobian(tk, y[:n], y[n:])
        extra = np.zeros_like(base)
        extra[n:] = Minv @ np.hstack([dfdx, dfdv])
        return base + extra

    uses_force_tangent = jacobian is not None or force is None or not callable(force)
    sol = scipy.integrate.solve_ivp(
        rhs,
        (p.t[0], p.t[-1]),
        np.r_[p.x0, p.v0],
        method=method,
        dense_output=True,
        rtol=rtol,
        atol=atol,
        jac=jac if uses_force_tangent else None,
    )
    name = f"stiff_{method.lower()}"
    if not sol.success:
        return IntegrationResult(
            sol.t,
            sol.y[:n],
            sol.y[n:],
            np.full((n, sol.t.size), np.nan),
            name,
            sol.t.size - 1,
            int(sol.nfev),
            False,
            sol.message,
        )
    # The grid values come from each step's own interpolant, as solve_ivp's t_eval would give.
    y = sol.sol(p.t)
    x, v = y[:n], y[n:]
    a = np.array([acceleration(tk, x[:, k], v[:, k]) for k, tk in enumerate(p.t)]).T
    return IntegrationResult(p.t, x, v, a, name, sol.t.size - 1, int(sol.nfev), True, sol.message)
