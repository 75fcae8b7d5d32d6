"""Integrators for ``M x'' + C x' + K x = f(t, x, x')``: first-order schemes, Newmark–Newton, a stiff solver.

The first-order schemes (forward Euler, classical Runge–Kutta, Adams–Bashforth–
Moulton) march the state y = (x, x') of y' = (x', M⁻¹(f − C x' − K x)). Newmark
with Newton–Raphson iterations solves the implicit equations of each step with
the tangent of the force, given or found by finite differences. The stiff solver
hands the same first-order system, with its Jacobian, to scipy's BDF or Radau
{Hairer & Wanner 1996}.

Every failure (a blow-up, a Newton iteration that does not converge, scipy giving
up) raises :class:`raildyn.errors.SolverError` with the step, the time, the reason
and the completed part of the run as ``partial``.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg

from raildyn import _checks
from raildyn._checks import integer, scalar
from raildyn.errors import SolverError
from raildyn.integrators._common import (
    IntegrationResult,
    completed,
    force_tangent,
    general_force,
    initial_state,
    partial_result,
    problem,
    sampled_load,
    scale,
)
from raildyn.integrators._divergence import diverged
from raildyn.vibration import first_order_matrix

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.integrate,
# raildyn.integrators.runner._failure

# Newton iterations a step may be allowed: the iteration converges quadratically near the
# answer, so a step that needs more than a few dozen will not converge at all.
MAX_ITERATIONS = 1000

# The smallest absolute tolerance of the stiff solver, in the units of the state (m, m/s, rad):
# below, it means nothing physical and only keeps the solver stepping finely near zero crossings.
MIN_ATOL = 1e-20

# Evaluations of the right-hand side the stiff solver may make: the budget of the one rule of
# raildyn.integrators.runner, here some 10 000 steps of Radau at three or four evaluations a step (a few
# seconds of work with a Python force). A run that needs more is following fast oscillations one by one
# rather than stepping over a stiff decay, which a fixed-step scheme does faster; it is reported as a
# failure rather than left to run for minutes.
MAX_STIFF_EVALUATIONS = 40_000

__all__ = ["abm", "forward_euler", "newmark_newton", "rk4", "stiff"]

# The stiff solvers of scipy.integrate that stiff() offers, by their class names there.
_STIFF = ("Radau", "BDF", "LSODA")


def _first_order(p, force, *, finite=True):
    """The right-hand side y' = g(t, y) with y = (x, v), and the acceleration a(t, x, v).

    With ``finite`` a force that turns non-finite raises SolverError (see
    :func:`~raildyn.integrators._common.general_force`); without, its value is passed on, for
    a solver that rejects the step and tries a shorter one.
    """
    n = p.n
    factor, lower = scipy.linalg.cho_factor(p.M)
    # LAPACK's solve with the factor, which scipy.linalg.cho_solve calls after checks that cost
    # twice the solve at every evaluation: the same numbers, bit for bit.
    (potrs,) = scipy.linalg.get_lapack_funcs(("potrs",), (factor,))
    f = general_force(force, p, finite=finite)

    def acceleration(t, x, v):
        # No finiteness check here: a state that blows up becomes non-finite, and the caller
        # reports that as a SolverError with the step at which it happened.
        return potrs(factor, f(t, x, v) - p.C @ v - p.K @ x, lower=lower)[0]

    def rhs(t, y):
        x, v = y[:n], y[n:]
        return np.concatenate([v, acceleration(t, x, v)])

    return rhs, acceleration


def _accelerations(acceleration, t, x, v) -> np.ndarray:
    """Rows of accelerations at the states (x, v) (rows); NaN where the force turned non-finite."""
    out = np.full(x.shape, np.nan)
    for k, (tk, xk, vk) in enumerate(zip(t, x, v, strict=False)):
        try:
            out[k] = acceleration(tk, xk, vk)
        except SolverError:
            pass
    return out


def _bound(p, force):
    load = None if force is None or callable(force) else sampled_load(force, p)
    return scale(p, load)


def _march(name, p, force, advance) -> IntegrationResult:
    """Run ``advance(k, Y) -> y_{k+1}`` over the grid, checking every step for a blow-up."""
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
    with np.errstate(over="ignore", invalid="ignore"):  # a blow-up is reported below, not warned about
        for k in range(m - 1):
            try:
                Y[k + 1] = advance(k, Y, counted)
            except SolverError as err:  # the force turned non-finite: the state outgrew it
                x, v = Y[: k + 1, :n], Y[: k + 1, n:]
                a = _accelerations(acceleration, p.t, x, v)
                partial = partial_result(name, p.t, x, v, a, state["evals"])
                raise SolverError(
                    f"{name.replace('_', ' ')}: {err.reason}",
                    step=k + 1,
                    time=float(p.t[k + 1]),
                    partial=partial,
                ) from None
            if not np.abs(Y[k + 1]).max() <= bound:
                bad = k + 1
                break
        done = m if bad is None else bad
        x, v = Y[:done, :n], Y[:done, n:]
        a = _accelerations(acceleration, p.t, x, v)
    if bad is not None:
        raise diverged(name, p, bad, x, v, a, {}, iterations=state["evals"])
    return completed(name, p, x, v, a, state["evals"])


def forward_euler(M, C, K, t, x0, v0, force=None) -> IntegrationResult:
    """Forward (explicit) Euler on y = (x, x'): first order; it amplifies every undamped oscillation.

    Parameters
    ----------
    M, C, K : array_like (n, n) or float
        Mass (kg; symmetric positive definite), damping (N·s/m), stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like (n,) or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f in N: sampled on ``t`` (linear in between), or ``force(t, x, v)`` returning n values.

    Returns
    -------
    IntegrationResult
        ``iterations`` counts the evaluations of the right-hand side.

    Raises
    ------
    raildyn.errors.SolverError
        If the run blows up; the message names the step limit set by the eigenvalues of
        the first-order system, and ``partial`` holds the steps completed before.
    """
    p = problem(M, C, K, t, x0, v0)
    h = p.h

    def advance(k, Y, g):
        return Y[k] + h * g(p.t[k], Y[k])

    return _march("forward_euler", p, force, advance)


def rk4(M, C, K, t, x0, v0, force=None) -> IntegrationResult:
    """Classical fourth-order Runge–Kutta on y = (x, x'); stable for ωΔt <= 2√2 when undamped.

    Parameters
    ----------
    M, C, K : array_like (n, n) or float
        Mass (kg; symmetric positive definite), damping (N·s/m), stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like (n,) or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f in N: sampled on ``t`` (linear in between), or ``force(t, x, v)`` returning n values.

    Returns
    -------
    IntegrationResult
        ``iterations`` counts the evaluations of the right-hand side (four a step).

    Raises
    ------
    raildyn.errors.SolverError
        If the run blows up (see :func:`forward_euler`).

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> r = rk4(1.0, 0.0, (2 * np.pi) ** 2, t, 1.0, 0.0, lambda tk, x, v: np.zeros(1))
    >>> round(float(r.x[0, -1]), 6), r.iterations  # cos 2π after one period
    (1.0, 400)
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

    return _march("rk4", p, force, advance)


def abm(M, C, K, t, x0, v0, force=None) -> IntegrationResult:
    """Adams–Bashforth–Moulton predictor–corrector, fourth order, in PECE mode.

    Predict with the four-step Adams–Bashforth formula, evaluate, correct with the
    three-step Adams–Moulton formula, evaluate: two evaluations a step against
    RK4's four {Hairer, Nørsett & Wanner 1993, §III.1}. The first three steps are
    taken with RK4.

    Parameters
    ----------
    M, C, K : array_like (n, n) or float
        Mass (kg; symmetric positive definite), damping (N·s/m), stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like (n,) or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f in N: sampled on ``t`` (linear in between), or ``force(t, x, v)`` returning n values.

    Returns
    -------
    IntegrationResult
        ``iterations`` counts the evaluations of the right-hand side.

    Raises
    ------
    raildyn.errors.SolverError
        If the run blows up (see :func:`forward_euler`).
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

    return _march("abm", p, force, advance)


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
) -> IntegrationResult:
    """Newmark-β with Newton–Raphson iterations for ``M x'' + C x' + K x = f(t, x, x')``.

    Each step solves r(a₊) = M a₊ + C v₊ + K x₊ − f(t₊, x₊, v₊) = 0 with
    x₊ = x + Δt v + Δt²[(½−β) a + β a₊] and v₊ = v + Δt[(1−γ) a + γ a₊], by Newton's
    method on the tangent M + γΔt (C − ∂f/∂v) + βΔt² (K − ∂f/∂x) {Bathe 1996, §9.5}.

    Parameters
    ----------
    M, C, K : array_like (n, n) or float
        Mass (kg; symmetric positive definite), damping (N·s/m), stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like (n,) or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f in N: sampled on ``t`` (linear in between), or ``force(t, x, v)``, possibly
        nonlinear, returning n values.
    jacobian : callable, optional
        ``jacobian(t, x, v)`` returning a :class:`ForceJacobian` or the pair (∂f/∂x, ∂f/∂v),
        each (n, n) (N/m, N·s/m). Without it, forward differences are used for a callable
        force (2n extra force evaluations per iteration); a force given as samples (or
        None) depends on t alone, so its tangent is zero.
    gamma, beta : float
        Newmark's parameters; γ in [½, 1.5], β in (0, 1].
    tol : float
        Convergence when the displacement correction is below tol × (|x₊|∞ + Δt |v₊|∞ + 1e-300);
        in [1e-13, 1) (below, rounding keeps Newton's method from ever getting there).
    max_iter : int
        Iterations allowed per step, in [1, 1000] (Newton's method converges quadratically
        near the answer: a step that needs more than a few dozen will not converge).

    Returns
    -------
    IntegrationResult
        ``iterations`` is the total number of Newton iterations.

    Raises
    ------
    raildyn.errors.SolverError
        If a step does not converge in ``max_iter`` iterations, its tangent is singular, the
        run blows up or the force (or its jacobian) turns non-finite; ``partial`` holds the
        steps completed before.
    ValueError
        If ``force`` or ``jacobian`` returns the wrong shape, or a non-finite value at the
        initial state (t₀, x0, v0).

    Examples
    --------
    >>> from raildyn.suspension import FrictionDamper
    >>> damper = FrictionDamper(friction_force=1.0e4, velocity_scale=1.0e-3)
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> r = newmark_newton(2.5e4, 0.0, 5.0e6, t, 0.03, 0.0, damper.force, jacobian=damper.jacobian)
    >>> r.steps, r.iterations > r.steps
    (100, True)
    """
    gamma = scalar("gamma", gamma, low=0.5, high=1.5)
    beta = scalar("beta", beta, low=0.0, high=1.0, low_open=True)
    tol = _checks.tolerance("tol", tol)
    max_iter = integer("max_iter", max_iter, low=1, high=MAX_ITERATIONS)
    if jacobian is not None:
        _checks.function("jacobian", jacobian)
    p = problem(M, C, K, t, x0, v0)
    f = general_force(force, p)
    n, h, m = p.n, p.h, p.t.size
    if jacobian is not None:
        with np.errstate(over="ignore", invalid="ignore"):  # a non-finite tangent is refused just below
            first = jacobian(p.t[0], p.x0, p.v0)
        force_tangent(first, n, p.t[0], initial=initial_state(p))
    X, V, A = np.empty((m, n)), np.empty((m, n)), np.empty((m, n))
    X[0], V[0] = p.x0, p.v0
    A[0] = np.linalg.solve(p.M, f(p.t[0], p.x0, p.v0) - p.C @ p.v0 - p.K @ p.x0)
    bound = _bound(p, force)
    iterations = 0
    if jacobian is None and not callable(force):  # f(t) alone: no tangent
        zero = np.zeros((n, n))

        def jacobian(t, x, v):
            return zero, zero

    def failed(k, reason):
        partial = partial_result("newmark_newton", p.t, X[: k + 1], V[: k + 1], A[: k + 1], iterations)
        return SolverError(f"newmark newton: {reason}", step=k + 1, time=float(p.t[k + 1]), partial=partial)

    with np.errstate(over="ignore", invalid="ignore"):  # an overflow is reported as a failure below
        for k in range(m - 1):
            t1 = p.t[k + 1]
            x_pred = X[k] + h * V[k] + h * h * (0.5 - beta) * A[k]
            v_pred = V[k] + h * (1 - gamma) * A[k]
            a = A[k].copy()
            converged = False
            for _ in range(max_iter):
                x, v = x_pred + beta * h * h * a, v_pred + gamma * h * a
                try:
                    fx = f(t1, x, v)
                    if jacobian is not None:
                        dfdx, dfdv = force_tangent(jacobian(t1, x, v), n, t1)
                    else:
                        dfdx, dfdv = _fd_jacobian(f, t1, x, v, fx)
                    r = p.M @ a + p.C @ v + p.K @ x - fx
                    tangent = p.M + gamma * h * (p.C - dfdv) + beta * h * h * (p.K - dfdx)
                    da = np.linalg.solve(tangent, -r)
                except SolverError as err:
                    raise failed(k, err.reason) from None
                except np.linalg.LinAlgError:
                    raise failed(k, "the tangent M + γΔt(C − ∂f/∂v) + βΔt²(K − ∂f/∂x) is singular") from None
                a = a + da
                iterations += 1
                size = np.abs(x).max() + h * np.abs(v).max() + 1e-300
                if beta * h * h * np.abs(da).max() <= tol * size:
                    converged = True
                    break
            if not converged:
                raise failed(
                    k,
                    f"Newton's method did not converge in {max_iter} iterations with "
                    f"dt = {h:.6g} s (last correction {beta * h * h * np.abs(da).max():.3g} against a "
                    f"tolerance of {tol * size:.3g}); shorten dt, allow more iterations or check the "
                    "jacobian",
                )
            X[k + 1], V[k + 1], A[k + 1] = x_pred + beta * h * h * a, v_pred + gamma * h * a, a
            if not np.abs(np.r_[X[k + 1], V[k + 1]]).max() <= bound:
                raise diverged(
                    "newmark_newton",
                    p,
                    k + 1,
                    X[: k + 1],
                    V[: k + 1],
                    A[: k + 1],
                    {"gamma": gamma, "beta": beta},
                    iterations=iterations,
                    analysed_as="newmark",
                )
    return completed("newmark_newton", p, X, V, A, iterations)


def stiff(
    M, C, K, t, x0, v0, force=None, *, jacobian=None, method="Radau", rtol=1e-8, atol=1e-12
) -> IntegrationResult:
    """Integrate with scipy's implicit variable-step solvers (``solve_ivp`` with BDF or Radau).

    The Jacobian of the first-order system is given to scipy: the linear part
    [[0, I], [−M⁻¹K, −M⁻¹C]] (:func:`raildyn.vibration.first_order_matrix`) plus,
    with ``jacobian``, the force's tangent.

    Parameters
    ----------
    M, C, K : array_like (n, n) or float
        Mass (kg; symmetric positive definite), damping (N·s/m), stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s: where the answer is wanted (scipy chooses its own steps).
    x0, v0 : array_like (n,) or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f in N: sampled on ``t`` (linear in between), or ``force(t, x, v)`` returning n values.
    jacobian : callable, optional
        As :func:`newmark_newton`. Without it a callable force leaves scipy to find the
        Jacobian by finite differences.
    method : {"Radau", "BDF", "LSODA"}
        scipy's solver.
    rtol, atol : float
        scipy's relative tolerance, in [1e-13, 1) (below, scipy would silently raise it), and
        absolute tolerance, in the units of the state (m, m/s), in [1e-20, 1) (below, it means
        nothing physical and only slows the solver near zero crossings).

    Returns
    -------
    IntegrationResult
        On the grid ``t`` (from each step's interpolant); ``steps`` is the number of steps
        scipy took (not the samples of ``t``), ``iterations`` the number of right-hand-side
        evaluations.

    Raises
    ------
    raildyn.errors.SolverError
        If scipy gives up (a step size that underflows, a state that is not finite) or the
        run needs more than 10 000 steps (it is then following fast oscillations one by
        one, which a fixed-step scheme does faster): the reason is scipy's message, ``step``
        the steps taken, ``time`` where it stopped, and ``partial`` the history on the grid
        ``t`` up to there.
    ValueError
        If ``force`` or ``jacobian`` returns the wrong shape, or a non-finite value at the
        initial state (t₀, x0, v0).

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 11)
    >>> r = stiff(1.0, 0.0, (2 * np.pi) ** 2, t, 1.0, 0.0, rtol=1e-10, atol=1e-12)
    >>> round(float(r.x[0, -1]), 7), r.method
    (1.0, 'stiff_radau')
    """
    import scipy.integrate

    from raildyn.integrators.runner import _failure

    _checks.choice("method", method, _STIFF)
    rtol, atol = _checks.tolerance("rtol", rtol), _checks.tolerance("atol", atol, low=MIN_ATOL)
    if jacobian is not None:
        _checks.function("jacobian", jacobian)
    p = problem(M, C, K, t, x0, v0)
    n, m = p.n, p.t.size
    rhs, acceleration = _first_order(p, force, finite=False)
    if jacobian is not None:
        with np.errstate(over="ignore", invalid="ignore"):  # a non-finite tangent is refused just below
            first = jacobian(p.t[0], p.x0, p.v0)
        force_tangent(first, n, p.t[0], initial=initial_state(p))
    base = first_order_matrix(p.M, p.C, p.K)
    Minv = np.linalg.inv(p.M)

    def jac(tk, y):
        if jacobian is None:
            return base
        dfdx, dfdv = force_tangent(jacobian(tk, y[:n], y[n:]), n, tk)
        extra = np.zeros_like(base)
        extra[n:] = Minv @ np.hstack([dfdx, dfdv])
        return base + extra

    uses_force_tangent = jacobian is not None or force is None or not callable(force)
    name = f"stiff_{method.lower()}"
    Y = np.empty((m, 2 * n))
    Y[0] = np.r_[p.x0, p.v0]
    filled, steps, reason = 1, 0, None
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow is reported as a failure below
        solver = getattr(scipy.integrate, method)(
            rhs, p.t[0], Y[0], p.t[-1], rtol=rtol, atol=atol, jac=jac if uses_force_tangent else None
        )
        while solver.status == "running" and reason is None:
            try:
                message = solver.step()
            except SolverError as err:
                reason = err.reason
                break
            except (ValueError, ArithmeticError, np.linalg.LinAlgError) as err:  # scipy's own, on a blow-up
                reason = str(err)
                break
            steps += 1
            if solver.status == "failed":
                reason = message
            elif not np.isfinite(solver.y).all():
                reason = "the state became non-finite"
            elif solver.nfev > MAX_STIFF_EVALUATIONS and solver.status == "running":
                reason = "budget"
            else:
                # The grid values come from each step's own interpolant, as solve_ivp's t_eval would give.
                upto = int(np.searchsorted(p.t, solver.t, side="right"))
                if upto > filled:
                    Y[filled:upto] = np.atleast_2d(solver.dense_output()(p.t[filled:upto]).T)
                    filled = upto
        x, v = Y[:filled, :n], Y[:filled, n:]
        a = _accelerations(acceleration, p.t, x, v)
    if reason is not None:
        partial = partial_result(name, p.t, x, v, a, int(solver.nfev))
        if reason == "budget":  # the runner's one budget rule and its one message
            raise _failure("budget", f"scipy's {method}", time=float(solver.t), step=steps,
                           limit=MAX_STIFF_EVALUATIONS, partial=partial)  # fmt: skip
        raise SolverError(
            f"scipy's {method} failed: {reason}", step=steps, time=float(solver.t), partial=partial
        )
    result = completed(name, p, x, v, a, int(solver.nfev))
    return IntegrationResult(result.t, result.x, result.v, result.a, name, steps, result.iterations)
