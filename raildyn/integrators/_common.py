"""What every integrator shares: the result type, the failure, the input checks.

The problem is ``M x'' + C x' + K x = f`` with n degrees of freedom. ``M`` must be
symmetric positive definite; ``C`` and ``K`` may be non-symmetric (creep forces
couple a wheelset's lateral and yaw motions unsymmetrically). A single
oscillator may be given with scalars.

Failure policy (:mod:`raildyn.errors`): a run that blows up, a Newton iteration
that does not converge and a scipy solver that gives up all raise
:class:`raildyn.errors.SolverError` with the step, the time, the reason (naming
the stability limit of the scheme where one applies) and, as ``partial``, the
:class:`IntegrationResult` of the steps completed before the failure. A result
that is returned is a success.
"""

from __future__ import annotations

from dataclasses import dataclass

import matplotlib
import numpy as np
import scipy.linalg

from raildyn import plots
from raildyn._checks import array, scalar, square_matrix, time_grid
from raildyn.errors import SolverError
from raildyn.vibration import first_order_matrix

__all__ = ["Deviation", "ForceJacobian", "IntegrationResult", "Maxima"]

# A run is declared divergent when a state entry exceeds this multiple of the scale set by the
# initial conditions and the load: far beyond any response a stable linear system can give, yet
# reached by a geometric blow-up within a few dozen steps, long before the numbers overflow.
DIVERGENCE_FACTOR = 1.0e8

_QUANTITIES = {"x": ("displacement", "x"), "v": ("velocity", r"\dot x"), "a": ("acceleration", r"\ddot x")}


@dataclass(frozen=True)
class ForceJacobian:
    """The tangent of a force f(t, x, v): what a ``jacobian(t, x, v)`` callback may return.

    The integrators that take a ``jacobian`` accept this or the pair
    ``(wrt_displacement, wrt_velocity)``.

    Attributes
    ----------
    wrt_displacement : ndarray, shape (n, n)
        ∂f/∂x, N/m (N/rad for a rotation).
    wrt_velocity : ndarray, shape (n, n)
        ∂f/∂v, N·s/m (N·s/rad for a rotation).
    """

    wrt_displacement: np.ndarray
    wrt_velocity: np.ndarray


def force_tangent(value, n: int) -> tuple[np.ndarray, np.ndarray]:
    """∂f/∂x and ∂f/∂v from what a ``jacobian`` callback returned, checked to be finite (n, n) arrays."""
    if isinstance(value, ForceJacobian):
        pair = (value.wrt_displacement, value.wrt_velocity)
    elif isinstance(value, tuple | list) and len(value) == 2:
        pair = tuple(value)
    else:
        raise TypeError(
            "jacobian(t, x, v) must return a ForceJacobian or the pair (df/dx, df/dv), "
            f"got {type(value).__name__}"
        )
    return (
        array("jacobian(t, x, v) df/dx", pair[0], shape=(n, n)),
        array("jacobian(t, x, v) df/dv", pair[1], shape=(n, n)),
    )


@dataclass(frozen=True)
class Deviation:
    """The largest difference between two time histories, coordinate by coordinate.

    Attributes
    ----------
    displacement : ndarray, shape (n,)
        max |x − x_ref| of each coordinate, in the unit of x (m, or rad for a rotation).
    velocity : ndarray, shape (n,)
        max |v − v_ref|, m/s (rad/s).
    acceleration : ndarray, shape (n,)
        max |a − a_ref|, m/s² (rad/s²).
    times : ndarray, shape (k,)
        The times compared, s.
    """

    displacement: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    times: np.ndarray


@dataclass(frozen=True)
class Maxima:
    """The local maxima of one coordinate of a time history.

    Attributes
    ----------
    times : ndarray, shape (k,)
        Times of the maxima, s.
    values : ndarray, shape (k,)
        The quantity there, in its unit (m, m/s or m/s²; rad for a rotation).
    """

    times: np.ndarray
    values: np.ndarray


@dataclass(frozen=True)
class IntegrationResult:
    """The time history computed by one integrator (a returned result is a success).

    Attributes
    ----------
    t : ndarray, shape (m,)
        Times, s: the requested grid (in a :class:`raildyn.errors.SolverError`'s
        ``partial``, its completed part).
    x, v, a : ndarray, shape (n, m)
        Displacement (m), velocity (m/s) and acceleration (m/s²) of each degree of freedom.
    method : str
        The scheme's name.
    steps : int
        Time steps taken.
    iterations : int
        Newton iterations (implicit nonlinear schemes), else evaluations of the force
        (first-order schemes and the stiff solver); 0 for the linear recursions.
    """

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    a: np.ndarray
    method: str
    steps: int
    iterations: int

    def deviation_from(self, reference: IntegrationResult, *, after: float | None = None) -> Deviation:
        """The largest difference from a reference history, over the times the two share.

        The comparison runs on the coarser of the two grids (the reference's when
        they have as many samples), restricted to the span both cover, with the
        finer history interpolated linearly onto it: exact when the coarse grid's
        times lie on the fine one, as when one grid refines the other.

        Parameters
        ----------
        reference : IntegrationResult
            The history to compare with, with as many degrees of freedom.
        after : float, optional
            Compare only at times >= ``after``, s (to leave out a start-up transient).

        Returns
        -------
        Deviation
            max |x − x_ref|, max |v − v_ref|, max |a − a_ref| of each coordinate, and the times compared.

        Examples
        --------
        >>> t = np.linspace(0.0, 1.0, 201)
        >>> fine = IntegrationResult(t, np.sin(t)[None], np.cos(t)[None], -np.sin(t)[None], "exact", 200, 0)
        >>> x, v, a = fine.x[:, ::4] + 1e-3, fine.v[:, ::4], fine.a[:, ::4]
        >>> shifted = IntegrationResult(t[::4], x, v, a, "shifted", 50, 0)
        >>> round(float(shifted.deviation_from(fine).displacement[0]), 12)
        0.001
        """
        if not isinstance(reference, IntegrationResult):
            raise TypeError(f"reference must be an IntegrationResult, got {type(reference).__name__}")
        if reference.x.shape[0] != self.x.shape[0]:
            raise ValueError(
                f"reference must have {self.x.shape[0]} degrees of freedom, got {reference.x.shape[0]}"
            )
        lo, hi = max(self.t[0], reference.t[0]), min(self.t[-1], reference.t[-1])
        if after is not None:
            lo = max(lo, scalar("after", after))
        pick = [run for run in (reference, self) if np.any((run.t >= lo) & (run.t <= hi))]
        if hi < lo or not pick:
            raise ValueError(
                f"the two histories share no time at or after {lo:.6g} s: this one covers "
                f"[{self.t[0]:.6g}, {self.t[-1]:.6g}] s, the reference [{reference.t[0]:.6g}, "
                f"{reference.t[-1]:.6g}] s"
            )
        coarse = min(pick, key=lambda run: np.count_nonzero((run.t >= lo) & (run.t <= hi)))
        times = coarse.t[(coarse.t >= lo) & (coarse.t <= hi)]

        def sampled(run, values):
            if run is coarse:
                return values[:, (run.t >= lo) & (run.t <= hi)]
            return np.array([np.interp(times, run.t, row) for row in values])

        def largest(name):
            return np.abs(
                sampled(self, getattr(self, name)) - sampled(reference, getattr(reference, name))
            ).max(axis=1)

        return Deviation(largest("x"), largest("v"), largest("a"), times)

    def _row(self, dof, quantity) -> np.ndarray:
        if quantity not in _QUANTITIES:
            raise ValueError(f"quantity must be one of {sorted(_QUANTITIES)}, got {quantity!r}")
        n = self.x.shape[0]
        if isinstance(dof, bool) or not isinstance(dof, int | np.integer) or not 0 <= dof < n:
            raise ValueError(f"dof must be an integer in [0, {n - 1}], got {dof!r}")
        return getattr(self, quantity)[dof]

    def maxima(self, dof: int = 0, quantity: str = "x") -> Maxima:
        """The interior local maxima of one coordinate: samples above the one before and not below the next.

        Parameters
        ----------
        dof : int
            Index of the coordinate.
        quantity : {"x", "v", "a"}
            Displacement, velocity or acceleration.

        Returns
        -------
        Maxima
            Their times (s) and values, in time order (the end samples are never counted).

        Examples
        --------
        >>> t = np.linspace(0.0, 2.0, 201)
        >>> run = IntegrationResult(t, np.cos(2 * np.pi * t)[None], 0 * t[None], 0 * t[None], "cos", 200, 0)
        >>> run.maxima().times.tolist()
        [1.0]
        """
        y = self._row(dof, quantity)
        k = np.flatnonzero((y[1:-1] > y[:-2]) & (y[1:-1] >= y[2:])) + 1
        return Maxima(self.t[k], y[k])

    def plot(self, ax=None, *, dof: int = 0, quantity: str = "x", scale: float = 1.0, **style) -> dict:
        """Draw one coordinate's displacement, velocity or acceleration against time; return the artists.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (new axes on a new figure if None).
        dof : int
            Index of the coordinate.
        quantity : {"x", "v", "a"}
            Displacement, velocity or acceleration.
        scale : float
            Factor applied to the values (1e3 to draw metres as millimetres); say so in the label.
        **style
            Passed to ``Axes.plot`` (``label``, ``color``, ``lw``...).

        Returns
        -------
        dict
            ``{"line": Line2D}``.
        """
        y = self._row(dof, quantity)
        n = self.x.shape[0]
        scale = scalar("scale", scale)
        ax = plots.axes_or_new(ax)
        word, symbol = _QUANTITIES[quantity]
        with matplotlib.rc_context(plots.STYLE):
            (line,) = ax.plot(self.t, scale * y, **style)
            ax.set_xlabel("time $t$ (s)")
            if not ax.get_ylabel():
                ax.set_ylabel(f"{word} ${symbol}_{{{dof}}}$" if n > 1 else f"{word} ${symbol}$")
        return {"line": line}


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
    last = p.t.size - 2

    def sampled(t, x, v):
        # Linear between samples, every coordinate at once (np.interp's rule, held at the ends).
        k = min(max(int(np.searchsorted(p.t, t, side="right")) - 1, 0), last)
        w = min(max((t - p.t[k]) / (p.t[k + 1] - p.t[k]), 0.0), 1.0)
        return (1.0 - w) * table[k] + w * table[k + 1]

    return sampled


def equilibrium_acceleration(p: Problem, x, v, load) -> np.ndarray:
    """a = M⁻¹(f − C v − K x) for one state or for rows of states, shape (m, n)."""
    # The lower rows of the first-order matrix are −M⁻¹[K, C]: with them (and M's explicit inverse,
    # M being symmetric positive definite and, in practice, well conditioned) the m solves become
    # matrix products, fast for long histories.
    n = p.n
    lower = first_order_matrix(p.M, p.C, p.K)[n:]
    out = x @ lower[:, :n].T
    out += v @ lower[:, n:].T
    if load is not None:
        out += load @ np.linalg.inv(p.M).T
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


def completed(name: str, p: Problem, x, v, a, iterations: int = 0) -> IntegrationResult:
    """The result of a run over the whole grid, from rows (m, n) of x, v and a."""
    m = p.t.size
    return IntegrationResult(p.t, x[:m].T, v[:m].T, a[:m].T, name, m - 1, iterations)


def diverged(
    name: str, p: Problem, step: int, x, v, a, params, *, iterations=0, analysed_as=None
) -> SolverError:
    """The failure of a run that blew up at ``step``: the reason names the stability limit of the scheme.

    ``x``, ``v``, ``a`` hold the rows (m, n) computed before ``step``; the completed part
    becomes the error's ``partial`` result.
    """
    done = min(len(x), len(v), len(a), step)
    partial = IntegrationResult(
        p.t[:done], x[:done].T, v[:done].T, a[:done].T, name, max(done - 1, 0), iterations
    )
    time = float(p.t[0] + step * p.h)
    return SolverError(divergence_reason(name, p, params, analysed_as), step=step, time=time, partial=partial)


def divergence_reason(method: str, p: Problem, params, analysed_as: str | None = None) -> str:
    """Why a run of ``method`` blew up, naming its stability limit on this system."""
    from raildyn.integrators.analysis import stability_limit

    h = p.h
    name = method.replace("_", " ")
    head = f"{name} diverged with dt = {h:.6g} s"
    if method in ("forward_euler", "rk4", "abm"):
        return _first_order_reason(method, p, head)
    wmax = highest_frequency(p.M, p.K)
    if wmax == 0.0:
        return f"{head}; the system has no stiffness, so the growth is its own"
    t_min = 2 * np.pi / wmax
    ratio = stability_limit(analysed_as or method, **(params or {}))
    if np.isfinite(ratio) and ratio > 0:
        bound = ratio * t_min
        rule = f"dt <= {ratio:.4g} T_min" if method != "central_difference" else "dt <= T_min/pi"
        if h > bound:
            return (
                f"{head}: {name} is stable only for {rule} = {bound:.6g} s "
                f"(T_min = {t_min:.6g} s, the period of the highest undamped mode); reduce dt"
            )
        return (
            f"{head}, inside its stability limit {rule} = {bound:.6g} s (T_min = {t_min:.6g} s): "
            "the equations themselves have a growing solution, or the force is too stiff for this step"
        )
    if ratio == 0:
        return (
            f"{head}: {name} amplifies every undamped oscillation whatever the step "
            f"(T_min = {t_min:.6g} s); use a stable scheme"
        )
    return (
        f"{head}: {name} is unconditionally stable for linear systems, so the "
        "equations themselves have a growing solution (an unstable system) or the force is too stiff"
    )


def _first_order_reason(method, p: Problem, head) -> str:
    """The reason for a first-order scheme: its limit is set by the eigenvalues of the first-order system."""
    from raildyn.integrators.analysis import first_order_step_limit

    lam = np.linalg.eigvals(first_order_matrix(p.M, p.C, p.K))
    decaying = lam[lam.real <= 1e-12 * np.abs(lam).max()]
    if decaying.size == 0:
        return f"{head}: every mode of the system grows; the growth is its own"
    limits = np.array([first_order_step_limit(method, z) for z in decaying])
    worst = int(np.argmin(limits))
    bound, z = limits[worst], decaying[worst]
    name = method.replace("_", " ")
    where = f"the eigenvalue {z.real:.6g}{z.imag:+.6g}j 1/s of the first-order system"
    if bound == 0.0:
        return f"{head}: {name} amplifies {where} at any step; use another scheme"
    if p.h > bound:
        return (
            f"{head}: {name} is stable only for dt <= {bound:.6g} s here, set by {where} "
            f"(dt |lambda| <= {bound * abs(z):.4g}); reduce dt"
        )
    return (
        f"{head}, inside its stability limit dt <= {bound:.6g} s: the equations themselves have a "
        "growing solution, or the force is too stiff for this step"
    )
