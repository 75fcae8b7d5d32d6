"""What every integrator shares: the catalogue of schemes, the result type, the input checks.

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

import numpy as np
import scipy.linalg

from raildyn import _checks, plots
from raildyn._checks import array, scalar, square_matrix, time_grid
from raildyn._tables import Tabular
from raildyn.errors import SolverError
from raildyn.vibration import first_order_matrix

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib

__all__ = ["Deviation", "ForceJacobian", "IntegrationResult", "Maxima"]

# A run is declared divergent when a state entry exceeds this multiple of the scale set by the
# initial conditions and the load: far beyond any response a stable linear system can give, yet
# reached by a geometric blow-up within a few dozen steps, long before the numbers overflow.
DIVERGENCE_FACTOR = 1.0e8

# Every scheme the analysis knows, by name; the same names select the integrators.
METHODS = (
    "central_difference",
    "houbolt",
    "wilson",
    "newmark",
    "average_acceleration",
    "linear_acceleration",
    "hht_alpha",
    "forward_euler",
    "rk4",
    "abm",
)

# The parameters each scheme accepts, with their defaults.
PARAMETERS = {
    "central_difference": {},
    "houbolt": {},
    "wilson": {"theta": 1.4},
    "newmark": {"gamma": 0.5, "beta": 0.25},
    "average_acceleration": {},
    "linear_acceleration": {},
    "hht_alpha": {"alpha": -0.05},
    "forward_euler": {},
    "rk4": {},
    "abm": {},
}

# Schemes of the first-order form y = (x, x'): their force is f(t, x, v), not f(t).
FIRST_ORDER = ("forward_euler", "rk4", "abm")

_QUANTITIES = {"x": ("displacement", "x"), "v": ("velocity", r"\dot x"), "a": ("acceleration", r"\ddot x")}


@dataclass(frozen=True)
class ForceJacobian:
    """The tangent of a force f(t, x, v): what a ``jacobian(t, x, v)`` callback may return.

    The integrators that take a ``jacobian`` accept this or the pair
    ``(wrt_displacement, wrt_velocity)``.

    Attributes
    ----------
    wrt_displacement : ndarray, shape (n, n)
        ∂f/∂x, N/m (N/rad for a rotation): finite, any sign.
    wrt_velocity : ndarray, shape (n, n)
        ∂f/∂v, N·s/m (N·s/rad for a rotation): finite, any sign, the shape of ``wrt_displacement``.
    """

    wrt_displacement: np.ndarray
    wrt_velocity: np.ndarray

    def __post_init__(self):
        dx = square_matrix("wrt_displacement", self.wrt_displacement, symmetric=False)
        dv = square_matrix("wrt_velocity", self.wrt_velocity, size=dx.shape[0], symmetric=False)
        object.__setattr__(self, "wrt_displacement", dx)
        object.__setattr__(self, "wrt_velocity", dv)


def force_tangent(value, n: int, t: float, *, initial: str = "") -> tuple[np.ndarray, np.ndarray]:
    """∂f/∂x and ∂f/∂v from what a ``jacobian`` callback returned at time ``t``: two (n, n) arrays.

    A wrong type or shape is refused (TypeError, ValueError naming ``jacobian``). A non-finite
    tangent is refused too at the initial state (``initial`` says where: the caller's own x0
    and v0); later in a run it means the state has grown beyond what the force can represent,
    a :class:`raildyn.errors.SolverError`.
    """
    if isinstance(value, ForceJacobian):
        pair = (value.wrt_displacement, value.wrt_velocity)
    elif isinstance(value, tuple | list | np.ndarray) and len(value) == 2:
        pair = tuple(value)
    else:
        raise TypeError(
            "jacobian(t, x, v) must return a ForceJacobian or the pair (df/dx, df/dv), "
            f"got {type(value).__name__}"
        )
    out = []
    for what, part in zip(("df/dx", "df/dv"), pair, strict=True):
        try:
            part = np.asarray(part, dtype=float)
        except (TypeError, ValueError):
            raise TypeError(f"jacobian(t, x, v) must return numbers, its {what} is {part!r:.80}") from None
        if part.shape != (n, n):
            raise ValueError(f"jacobian(t, x, v) {what} must have shape {(n, n)}, got shape {part.shape}")
        if not np.isfinite(part).all():
            if initial:
                raise ValueError(f"jacobian(t, x, v) returned a non-finite {what} at {initial}")
            raise SolverError(
                f"jacobian(t, x, v) returned a non-finite {what} (the state outgrew it, or it fails there)",
                time=t,
            )
        out.append(part)
    return out[0], out[1]


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
        The times compared, s: at least one, strictly increasing.

    The three maxima are finite, >= 0 and of one shape (n,), n >= 1.
    """

    displacement: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    times: np.ndarray

    def __post_init__(self):
        n = None
        for name in ("displacement", "velocity", "acceleration"):
            value = array(name, getattr(self, name), ndim=1, shape=(n,), low=0.0, allow_empty=False)
            n = value.size
            object.__setattr__(self, name, value)
        object.__setattr__(self, "times", time_grid("times", self.times))


@dataclass(frozen=True)
class Maxima(Tabular):
    """The local maxima of one coordinate of a time history.

    Attributes
    ----------
    times : ndarray, shape (k,)
        Times of the maxima, s, strictly increasing (k may be 0: no maximum).
    values : ndarray, shape (k,)
        The quantity there, in its unit (m, m/s or m/s²; rad for a rotation), finite.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("times", "s"), ("values", "m, m/s or m/s²; rad for a rotation"))

    times: np.ndarray
    values: np.ndarray

    def __post_init__(self):
        times = array("times", self.times, ndim=1)
        if times.size:
            times = time_grid("times", times)
        object.__setattr__(self, "times", times)
        values = array("values", self.values)
        if values.shape != times.shape:
            raise ValueError(
                f"times and values must have the same shape, got {times.shape} and {values.shape}"
            )
        object.__setattr__(self, "values", values)


@dataclass(frozen=True)
class IntegrationResult(Tabular):
    """The time history computed by one integrator (a returned result is a success).

    Attributes
    ----------
    t : ndarray, shape (m,)
        Times, s: the requested grid (in a :class:`raildyn.errors.SolverError`'s
        ``partial``, its completed part).
    x, v, a : ndarray, shape (n, m)
        Displacement (m), velocity (m/s) and acceleration (m/s²) of each degree of freedom.
    method : str
        The scheme's name (a label: any text).
    steps : int
        Time steps taken, >= 0.
    iterations : int
        Newton iterations (implicit nonlinear schemes), else evaluations of the force
        (first-order schemes and the stiff solver); 0 for the linear recursions; >= 0.

    All numbers finite; t strictly increasing, and x, v, a of shape (n, m) with n >= 1.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("t", "s"), ("x", "m"), ("v", "m/s"), ("a", "m/s²"))
    _scalars = (("steps", "-"), ("iterations", "-"))
    _by_row = ("x", "v", "a")

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    a: np.ndarray
    method: str
    steps: int
    iterations: int

    def __post_init__(self):
        t = array("t", self.t, ndim=1)
        if t.size:
            t = time_grid("t", t)
        object.__setattr__(self, "t", t)
        n = None
        for name in ("x", "v", "a"):
            value = array(name, getattr(self, name), ndim=2)
            if value.shape[1] != t.size or (n is not None and value.shape[0] != n):
                raise ValueError(
                    f"{name} must have shape (n, m): n degrees of freedom as in x, m = {t.size} samples as "
                    f"in t; got shape {value.shape}"
                )
            if value.shape[0] == 0:
                raise ValueError(
                    f"{name} must hold at least one degree of freedom (a row), got shape {value.shape}"
                )
            n = value.shape[0]
            object.__setattr__(self, name, value)
        _checks.instance("method", self.method, str, "string")
        object.__setattr__(self, "steps", _checks.integer("steps", self.steps, low=0))
        object.__setattr__(self, "iterations", _checks.integer("iterations", self.iterations, low=0))

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
            Compare only at times >= ``after``, s, any finite time (to leave out a start-up
            transient).

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
        _checks.instance("reference", reference, IntegrationResult)
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
        _checks.choice("quantity", quantity, _QUANTITIES)
        dof = _checks.integer("dof", dof, low=0, high=self.x.shape[0] - 1)
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
            Factor applied to the values, finite and nonzero (1e3 to draw metres as
            millimetres, negative to flip the sign); say so in the label.
        **style
            Passed to ``Axes.plot`` (``label``, ``color``, ``lw``...); an unknown property is
            refused with a TypeError naming it.

        Returns
        -------
        dict
            ``{"line": Line2D}``.
        """
        import matplotlib

        y = self._row(dof, quantity)
        n = self.x.shape[0]
        scale = scalar("scale", scale)
        if scale == 0.0:
            raise ValueError("scale must be nonzero (it multiplies the values drawn), got 0.0")
        ax = plots.axes_or_new(ax)
        word, symbol = _QUANTITIES[quantity]
        with matplotlib.rc_context(plots.STYLE):
            (line,) = draw_line(ax, self.t, scale * y, style)
            ax.set_xlabel("time $t$ (s)")
            if not ax.get_ylabel():
                ax.set_ylabel(f"{word} ${symbol}_{{{dof}}}$" if n > 1 else f"{word} ${symbol}$")
        return {"line": line}


def draw_line(ax, x, y, style) -> list:
    """``ax.plot(x, y, **style)``, an unknown style property refused with a TypeError naming it."""
    try:
        return ax.plot(x, y, **style)
    except AttributeError as err:  # matplotlib's answer to an unknown property: "... keyword argument 'lw2'"
        raise TypeError(f"unknown plot style: {err}") from None


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
        values = [_checks.returned("force", force(tk), at=f"t = {tk:.6g} s") for tk in p.t]
        wrong = [v.shape for v in values if v.size != p.n]
        if wrong:
            raise ValueError(f"force(t) must return {p.n} values, returned shape {wrong[0]}")
        return np.array([v.reshape(p.n) for v in values])
    raw = _checks.array("force", force)
    if raw.ndim == 1 and p.n == 1:
        raw = raw[None, :]
    return array("force", raw, shape=(p.n, p.t.size)).T.copy()


def general_force(force, p: Problem, *, finite: bool = True):
    """A force f(t, x, v) as a callable, from None, a sampled array (linear in t) or a callable.

    A callable is checked at the initial state (t₀, x0, v0): there a wrong shape or a
    non-finite value is refused with a ValueError naming ``force`` and the state. Later
    in the run a wrong shape is refused the same way, and a non-finite value, which means
    the state has outgrown the force, raises :class:`raildyn.errors.SolverError` (with
    ``finite``; without, it is passed on to a solver that rejects the step).
    """
    if force is None:
        zero = np.zeros(p.n)
        return lambda t, x, v: zero
    if callable(force):
        n = p.n

        def checked(t, x, v):
            out = np.asarray(force(t, x, v), dtype=float)
            if out.size != n:
                raise ValueError(
                    f"force(t, x, v) must return {n} values, returned shape {out.shape} at t = {t:.6g} s"
                )
            out = out.reshape(n)
            if finite and not np.isfinite(out).all():
                raise SolverError(
                    "force(t, x, v) returned a non-finite value (the state outgrew it, or it fails there)",
                    time=t,
                )
            return out

        with np.errstate(over="ignore", invalid="ignore"):  # a non-finite value is refused just below
            first = force(p.t[0], p.x0, p.v0)
        _checks.returned("force", first, at=initial_state(p))
        return checked
    table = sampled_load(force, p)
    last = p.t.size - 2

    def sampled(t, x, v):
        # Linear between samples, every coordinate at once (np.interp's rule, held at the ends).
        k = min(max(int(np.searchsorted(p.t, t, side="right")) - 1, 0), last)
        w = min(max((t - p.t[k]) / (p.t[k + 1] - p.t[k]), 0.0), 1.0)
        return (1.0 - w) * table[k] + w * table[k + 1]

    return sampled


def initial_state(p: Problem) -> str:
    """Where a callback is first called, in words for a message: the caller's t₀, x0 and v0."""
    return f"the initial state (t = {p.t[0]:.6g} s, x0 = {p.x0.tolist()}, v0 = {p.v0.tolist()})"


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
    # Capped at the largest float, so that an overflow to inf is caught as well.
    return min(DIVERGENCE_FACTOR * size, np.finfo(float).max) if size > 0 else np.finfo(float).max


def highest_frequency(M, K) -> float:
    """ω_max = √ of the largest |eigenvalue| of M⁻¹K, rad/s (sets the step limit of explicit schemes)."""
    lam = scipy.linalg.eigvals(K, M)
    return float(np.sqrt(np.abs(lam).max()))


def completed(name: str, p: Problem, x, v, a, iterations: int = 0) -> IntegrationResult:
    """The result of a run over the whole grid, from rows (m, n) of x, v and a.

    A history that is not finite everywhere (an acceleration that overflowed, say) is a
    failed run: :class:`raildyn.errors.SolverError` at its first non-finite sample.
    """
    m = p.t.size
    x, v, a = x[:m], v[:m], a[:m]
    finite = np.isfinite(x).all(axis=1) & np.isfinite(v).all(axis=1) & np.isfinite(a).all(axis=1)
    if not finite.all():
        k = int(np.argmin(finite))
        raise SolverError(
            f"{name.replace('_', ' ')}: the state became non-finite",
            step=k,
            time=float(p.t[k]),
            partial=partial_result(name, p.t, x, v, a, iterations),
        )
    return IntegrationResult(p.t, x.T, v.T, a.T, name, m - 1, iterations)


def partial_result(name: str, t, x, v, a, iterations: int = 0) -> IntegrationResult:
    """The completed part of a failed run, from rows (k, n): its leading finite samples."""
    done = min(len(t), len(x), len(v), len(a))
    finite = np.isfinite(x[:done]).all(axis=1) & np.isfinite(v[:done]).all(axis=1)
    finite &= np.isfinite(a[:done]).all(axis=1)
    if not finite.all():
        done = int(np.argmin(finite))
    return IntegrationResult(t[:done], x[:done].T, v[:done].T, a[:done].T, name, max(done - 1, 0), iterations)
