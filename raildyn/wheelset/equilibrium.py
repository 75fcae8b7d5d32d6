"""A nonlinear model's equilibria at rest on circular arcs: the one Newton's method (book chapter 8).

:func:`~raildyn.wheelset.arc_newton` solves :meth:`~raildyn.wheelset.NonlinearLateral.arc_forces` = 0
for a batch of states at once, each at its own speed, curvature and unbalanced acceleration. It is
written once for every model: the forces and their Jacobian come from the compiled engine where it
holds the model, and from numpy where the model holds a Python force law.
:mod:`raildyn.curving.quasi_static` builds its curving states and maps on it, continuing the points it
leaves from their neighbours.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn.wheelset.nonlinear import NonlinearLateral

__all__ = ["arc_newton"]

_HALVINGS = 12  # the line search's tries, the step halved between them (the last is 2⁻¹¹ of the full one)


def arc_newton(model, q, speed, curvature, unbalanced_acceleration, *, tolerance, steps=30):
    """Newton's method towards the model's equilibria on arcs, every column of q at once.

    Each step solves J Δq = −r for every column whose largest residual is above ``tolerance``,
    and halves its step (up to eleven times) until the sum of its squared residuals falls; a
    column stops where no step improves it or its Jacobian is singular, so that a caller can
    take it over by other means (continuation, another method).

    Parameters
    ----------
    model : NonlinearLateral
        With its wheelsets placed along the vehicle (alignment inputs).
    q : array_like, (n, P)
        The starting states, one column per point, finite.
    speed, curvature, unbalanced_acceleration : float or array_like, (P,)
        V (m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]), κ (1/m) and a_q (m/s²) of each
        point, as for :meth:`~raildyn.wheelset.NonlinearLateral.arc_forces`.
    tolerance : float
        The largest residual force of a converged point, N (> 0).
    steps : int
        The most Newton steps, in [1, 1000].

    Returns
    -------
    q : ndarray, (n, P)
        The states reached.
    converged : ndarray of bool, (P,)
        Where every residual is within ``tolerance``.

    Examples
    --------
    >>> from raildyn.vehicles import Bogie
    >>> model = Bogie().nonlinear()
    >>> q, ok = arc_newton(model, np.zeros((model.system.size, 2)), 20.0, [1 / 600, 1 / 300], 0.3,
    ...                    tolerance=1e-3)
    >>> ok.tolist()
    [True, True]
    """
    _checks.instance("model", model, NonlinearLateral)
    q = _checks.array("q", q, shape=(model.system.size, None), allow_empty=False)
    q, V, kappa, a_q = model._on_arcs(q, speed, curvature, unbalanced_acceleration)
    tolerance = _checks.positive("tolerance", tolerance)
    steps = _checks.integer("steps", steps, low=1, high=1000)
    P = q.shape[1]
    q = q.copy()
    V, kappa, a_q = (np.broadcast_to(v, (P,)) for v in (V, kappa, a_q))
    # A state far off the rails may overflow a sum of squares, a degenerate Jacobian give NaN steps: such a
    # column only stops improving, and the converged flags say so.
    with np.errstate(all="ignore"):
        return _newton(model, q, V, kappa, a_q, tolerance, steps)


def _newton(model, q, V, kappa, a_q, tolerance, steps):
    """The iteration of :func:`arc_newton` on checked arguments, in place on q."""
    n = q.shape[0]
    r = model._forces_on_arcs(q, V, kappa, a_q)
    active = np.abs(r).max(axis=0) > tolerance  # a NaN residual is not above: its column stops
    for _ in range(steps):
        if not active.any():
            break
        cols = np.flatnonzero(active)
        J = model._jacobians_on_arcs(q[:, cols], V[cols], kappa[cols], a_q[cols]).reshape(cols.size, n, n)
        try:
            step = np.linalg.solve(J, -r[:, cols].T[:, :, None])[:, :, 0].T
        except np.linalg.LinAlgError:  # a singular Jacobian somewhere: the caller takes over
            break
        finite = np.all(np.isfinite(step), axis=0)
        merit = (r[:, cols] ** 2).sum(axis=0)
        improved = np.zeros(cols.size, dtype=bool)
        trying = np.flatnonzero(finite)  # the columns (of cols) whose step has not yet improved them
        alpha = 1.0
        for _ in range(_HALVINGS):
            if trying.size == 0:
                break
            at = cols[trying]
            trial = q[:, at] + alpha * step[:, trying]
            r_trial = model._forces_on_arcs(trial, V[at], kappa[at], a_q[at])
            better = (r_trial**2).sum(axis=0) < merit[trying]
            q[:, at[better]], r[:, at[better]] = trial[:, better], r_trial[:, better]
            improved[trying[better]] = True
            trying = trying[~better]
            alpha *= 0.5
        active[cols[~improved]] = False
        active[cols] &= np.abs(r[:, cols]).max(axis=0) > tolerance
    return q, np.abs(r).max(axis=0) <= tolerance
