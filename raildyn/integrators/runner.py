"""The integration runner of the package's nonlinear models: bounded runs of y' = f(t, y).

Who calls it: :mod:`raildyn.stability` (the nonlinear runs of every lateral vehicle, limit
cycles, the shooting of periodic orbits) and :mod:`raildyn.train` (the longitudinal run of a
whole train). Two engines, one set of rules:

* :func:`dormand_prince` and :func:`dormand_prince_batch` run the Dormand–Prince 5(4) pair in
  compiled code (numba), with the steps, error norm, first step and quartic dense output of
  ``scipy.integrate.solve_ivp(method="RK45")`` (Dormand & Prince 1980; Shampine 1986), so a run
  takes the steps scipy would take without scipy's Python cost per evaluation. The right-hand
  side is a numba function compiled to :data:`RHS_SIGNATURE`, ``rhs(t, y, member, data, out)``:
  ``data`` holds one row of floats per parameter set, ``member`` picks the row, and the
  derivative is written into ``out``. A non-finite derivative makes the error norm NaN, so the
  step is rejected and retried smaller, as scipy does.
* :func:`solve_ivp` runs any of scipy's ``solve_ivp`` methods on a Python ``fun(t, y)``.

**The one budget rule.** Every run is bounded by a number of evaluations of its right-hand
side: ``budget``, an int or an :class:`EvaluationBudget` that several runs of one task share
(each run may use what is left; what it uses is spent). No budget exceeds
:data:`MAX_EVALUATIONS`. The caller sets it from what its problem needs.

**The one failure rule.** Running out of the budget, a step size that falls below the spacing
of floating-point numbers, a state that becomes non-finite and scipy giving up all raise
:class:`raildyn.errors.SolverError` here, with the step (accepted steps, where counted), the
time reached (s) and the reason; ``partial`` holds the :class:`Trajectory` of the output times
passed, where there are any. Bad input raises ``ValueError``/``TypeError`` before any work.
A returned result is a success. Units: times in s, the state in the caller's units.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.errors import SolverError
from raildyn.integrators import _dopri

__all__ = [
    "MAX_EVALUATIONS",
    "RHS_SIGNATURE",
    "EvaluationBudget",
    "Trajectory",
    "dormand_prince",
    "dormand_prince_batch",
    "solve_ivp",
]

#: The signature every compiled right-hand side is compiled to: ``void(t, y, member, data, out)``
#: with float64 ``t``, C-contiguous float64 ``y`` (n,), int64 ``member``, C-contiguous float64
#: ``data`` (members, L) and ``out`` (n,).
RHS_SIGNATURE = _dopri.RHS_SIGNATURE

#: The largest budget of evaluations of a right-hand side one run (or one task) may have: about
#: 50 times what an hour of a 100-car emergency stop takes (2 × 10⁶), the longest run raildyn makes.
MAX_EVALUATIONS = 100_000_000

# The methods of scipy.integrate.solve_ivp, by name.
_SCIPY_METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")
_NON_FINITE = ("raise", "reject")
# What solve_ivp's **options may hold (scipy's own keywords, those of its methods included).
_SCIPY_OPTIONS = frozenset(
    {"t_eval", "dense_output", "events", "vectorized", "args", "first_step", "max_step", "min_step",
     "jac", "jac_sparsity", "lband", "uband"}
)  # fmt: skip


class EvaluationBudget:
    """Evaluations of a right-hand side that the runs of one task may make, shared among them.

    Parameters
    ----------
    limit : int
        The most evaluations, 1 to :data:`MAX_EVALUATIONS`.

    Attributes
    ----------
    limit : int
        The most evaluations.
    used : int
        The evaluations made so far (0 at the start).

    Examples
    --------
    >>> budget = EvaluationBudget(1000)
    >>> budget.spend(400)
    600
    >>> budget.used, budget.left
    (400, 600)
    """

    def __init__(self, limit: int):
        self.limit = _checks.integer("limit", limit, low=1, high=MAX_EVALUATIONS)
        self.used = 0

    def __repr__(self) -> str:
        return f"EvaluationBudget(limit={self.limit}, used={self.used})"

    @property
    def left(self) -> int:
        """The evaluations still allowed, >= 0."""
        return max(self.limit - self.used, 0)

    def spend(self, count: int) -> int:
        """Count ``count`` evaluations made (they may take ``used`` past ``limit``: a run found so).

        Parameters
        ----------
        count : int
            Evaluations made, >= 0.

        Returns
        -------
        int
            The evaluations still allowed (:attr:`left`), >= 0.
        """
        self.used += _checks.integer("count", count, low=0)
        return self.left


def _budget(value) -> EvaluationBudget:
    """``budget`` as an :class:`EvaluationBudget`: a new one for an int, the caller's own shared one."""
    if isinstance(value, EvaluationBudget):
        return value
    return EvaluationBudget(_checks.integer("budget", value, low=1, high=MAX_EVALUATIONS))


def _failure(kind: str, label: str, *, time: float, step=None, limit=None, detail="", partial=None):
    """The one place where a run that cannot finish becomes a :class:`SolverError`."""
    if kind == "budget":
        reason = (
            f"{label} needed more than {limit} evaluations of the right-hand side, its budget (a stiff "
            "motion, tolerances or a max_step too tight for the duration, or a task's shared budget spent)"
        )
    elif kind == "step":
        reason = (
            f"{label} stopped: the required step size is less than spacing between numbers (10 spacings "
            "of floating-point numbers at t; the state running away to non-finite values, or a force "
            "that overflows)"
        )
    elif kind == "non-finite":
        reason = f"{label}: the state became non-finite"
    else:
        reason = f"{label} failed: {kind}"
    if detail:
        reason += f". {detail}"
    return SolverError(reason, step=step, time=float(time), partial=partial)


@dataclass(frozen=True)
class Trajectory(Tabular):
    """A run sampled at its output times (or, in a failure's ``partial``, those it passed).

    Attributes
    ----------
    t : ndarray, shape (m,)
        Output times, s, increasing (m may be 0 in nothing but a failure's ``partial``).
    y : ndarray, shape (k, m)
        The rows of the state kept, at those times, in the caller's units; finite.
    end : ndarray, shape (n,)
        The whole state at the last time reached, finite.
    evaluations : int
        Evaluations of the right-hand side made, >= 0.
    steps : int
        Steps accepted, >= 0.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("t", "s"), ("y", "caller's units"))
    _scalars = (("evaluations", "-"), ("steps", "-"))
    _by_row = ("y",)

    t: np.ndarray
    y: np.ndarray
    end: np.ndarray
    evaluations: int
    steps: int

    def __post_init__(self):
        t = _checks.array("t", self.t, ndim=1)
        if t.size > 1 and np.any(np.diff(t) < 0):
            raise ValueError(f"t must be increasing, got {self.t!r:.80}")
        y = _checks.array("y", self.y, ndim=2)
        if y.shape[0] == 0:
            raise ValueError(f"y must hold at least one row of the state, got shape {y.shape}")
        if y.shape[1] != t.size:
            raise ValueError(f"y must have shape (k, {t.size}) (a column per time in t), got {y.shape}")
        object.__setattr__(self, "t", t)
        object.__setattr__(self, "y", y)
        object.__setattr__(self, "end", _checks.array("end", self.end, ndim=1, allow_empty=False))
        object.__setattr__(self, "evaluations", _checks.integer("evaluations", self.evaluations, low=0))
        object.__setattr__(self, "steps", _checks.integer("steps", self.steps, low=0))


def _compiled(rhs):
    """``rhs`` checked to be a numba function that can be compiled to :data:`RHS_SIGNATURE`."""
    import numba.core.registry

    if not isinstance(rhs, numba.core.registry.CPUDispatcher):
        raise TypeError(
            "rhs must be a numba function compiled to raildyn.integrators.runner.RHS_SIGNATURE, "
            f"got {rhs!r:.80} of type {type(rhs).__name__}"
        )
    if tuple(RHS_SIGNATURE.args) in [tuple(sig) for sig in rhs.signatures]:
        return rhs
    try:
        rhs.compile(RHS_SIGNATURE.args)
    except Exception as err:  # numba's typing errors: the function does not fit the signature
        raise TypeError(f"rhs cannot be compiled to RHS_SIGNATURE: {str(err).splitlines()[0]}") from None
    return rhs


def _settings(data, t_eval, rtol, atol, max_step, n, rows):
    """The checked common arguments of the compiled runs."""
    data = np.ascontiguousarray(_checks.array("data", data, ndim=2, allow_empty=False))
    t_eval = _checks.array("t_eval", t_eval, ndim=1)
    if t_eval.size < 2 or np.any(np.diff(t_eval) <= 0):
        raise ValueError(f"t_eval must hold at least two increasing times, s, got {t_eval!r:.80}")
    rtol = _checks.tolerance("rtol", rtol)
    if np.ndim(atol) == 0:
        atol = np.full(n, _checks.tolerance("atol", atol))
    else:
        atol = _checks.array("atol", atol, shape=(n,))
        for a in atol:
            _checks.tolerance("atol", a)
        atol = np.array(atol, dtype=float)
    if max_step is None or (isinstance(max_step, float) and max_step == math.inf):
        max_step = math.inf  # unlimited
    else:
        max_step = _checks.positive("max_step", max_step)
    if rows is None:
        rows = np.arange(n)
    else:
        rows = np.asarray(_checks.array("rows", rows, ndim=1, low=0), dtype=np.int64)
        if rows.size and rows.max() >= n:
            raise ValueError(f"rows must pick rows of a state of {n} entries, got {rows.tolist()!r:.80}")
    return data, np.ascontiguousarray(t_eval), rtol, atol, max_step, rows


def dormand_prince(
    rhs,
    data,
    y0,
    t_eval,
    *,
    rtol: float = 1e-6,
    atol=1e-9,
    max_step: float | None = None,
    rows=None,
    member: int = 0,
    budget=1_000_000,
    label: str = "the integration",
    progress: Callable[[float], None] | None = None,
    chunk: int = 2000,
) -> Trajectory:
    """Integrate ``y' = rhs(t, y)`` from ``t_eval[0]`` to ``t_eval[-1]`` with compiled RK45, bounded.

    Parameters
    ----------
    rhs : numba function
        The right-hand side, compiled to :data:`RHS_SIGNATURE`.
    data : array_like, shape (members, L)
        The parameters ``rhs`` reads, one row per parameter set; finite.
    y0 : array_like, shape (n,)
        The state at ``t_eval[0]``, finite, in the model's units.
    t_eval : array_like, shape (m,)
        Output times, s, at least two, strictly increasing.
    rtol : float
        Relative tolerance, in [1e-13, 1).
    atol : float or array_like (n,)
        Absolute tolerance, in the state's units, each in [1e-13, 1).
    max_step : float, optional
        Largest step, s (> 0); unlimited by default (None or inf).
    rows : array_like of int, optional
        The rows of the state to sample (default all).
    member : int
        The row of ``data`` the run uses, 0 to members − 1.
    budget : int or EvaluationBudget
        The most evaluations of ``rhs``, 1 to :data:`MAX_EVALUATIONS` (see the module's rule).
    label : str
        What the run is, for a failure's message (e.g. "the run at V = 60 m/s").
    progress : callable, optional
        ``progress(t)`` is called with the time reached (s) every ``chunk`` steps.
    chunk : int
        Steps between calls of ``progress``, >= 1 (a chunk resumes on the steps of one run).

    Returns
    -------
    Trajectory
        The sampled rows, the end state, the evaluations and the steps.

    Raises
    ------
    raildyn.errors.SolverError
        If the budget runs out or the step falls below the spacing of floating-point numbers.

    Examples
    --------
    >>> import numba
    >>> @numba.njit(RHS_SIGNATURE)
    ... def decay(t, y, member, data, out):
    ...     out[0] = -data[member, 0] * y[0]
    >>> run = dormand_prince(decay, [[2.0]], [1.0], [0.0, 1.0], rtol=1e-10, atol=1e-12)
    >>> round(float(run.y[0, -1]), 8), round(float(np.exp(-2.0)), 8)
    (0.13533528, 0.13533528)
    """
    rhs = _compiled(rhs)
    y = np.array(_checks.array("y0", y0, ndim=1, allow_empty=False), dtype=float)
    data, t_eval, rtol, atol, max_step, rows = _settings(data, t_eval, rtol, atol, max_step, y.size, rows)
    member = _checks.integer("member", member, low=0, high=data.shape[0] - 1)
    budget = _budget(budget)
    _checks.instance("label", label, str, "string")
    if progress is not None:
        _checks.function("progress", progress)
    chunk = _checks.integer("chunk", chunk, low=1)
    t0, t1 = float(t_eval[0]), float(t_eval[-1])
    f = np.empty(y.size)
    limit = budget.left
    # [evaluations, budget, next sample, accepted steps, rejected steps]; start makes two evaluations.
    counts = np.array([2, limit, 0, 0, 0], dtype=np.int64)
    y_out = np.empty((rows.size, t_eval.size))
    status, t = _dopri.PAUSED, t0
    with np.errstate(all="ignore"):  # a non-finite stage is rejected by the error norm, not warned of
        h = _dopri.start(rhs, data, member, t0, y, t1, rtol, atol, max_step, f)
        while status == _dopri.PAUSED:
            status, t, h = _dopri.advance(
                rhs, data, member, t, y, f, h, t1, rtol, atol, max_step, t_eval, rows, y_out, counts, chunk
            )
            if progress is not None:
                progress(t)
    budget.spend(int(counts[0]))
    done, steps = int(counts[2]), int(counts[3])
    if status == _dopri.DONE:
        return Trajectory(t_eval, y_out, y, int(counts[0]), steps)
    raise _failure(
        "budget" if status == _dopri.OVER_BUDGET else "step",
        label,
        time=t,
        step=steps,
        limit=limit,
        partial=_partial(t_eval[:done], y_out[:, :done], y, int(counts[0]), steps),
    )


def _partial(t, y, end, evaluations, steps) -> Trajectory | None:
    """The finite samples a failed run passed, or None where there are none.

    ``end`` is the state reached; where it is not finite, the last sample stands in for it when
    the samples hold the whole state, else there is no partial run to give.
    """
    keep = np.isfinite(y).all(axis=0)
    if not keep.any():
        return None
    t, y = t[keep], y[:, keep]
    if not np.isfinite(end).all():
        if y.shape[0] != end.size:
            return None
        end = y[:, -1]
    return Trajectory(t, y, end, evaluations, steps)


def dormand_prince_batch(
    rhs,
    data,
    states,
    t_eval,
    *,
    rtol: float = 1e-6,
    atol=1e-9,
    max_step: float | None = None,
    rows=None,
    budget=1_000_000,
    labels=None,
) -> list[Trajectory]:
    """:func:`dormand_prince` for every member of a batch at once, each on its own steps, on all cores.

    Member ``i`` starts from ``states[i]`` at ``t_eval[0] = 0`` with the parameters of row ``i`` of
    ``data``. The members run in threads (the compiled integrator releases the GIL).

    Parameters
    ----------
    rhs : numba function
        The right-hand side, compiled to :data:`RHS_SIGNATURE`.
    data : array_like, shape (k, L)
        One row of parameters per member; finite.
    states : array_like, shape (k, n)
        Each member's state at t = 0, finite.
    t_eval : array_like, shape (m,)
        Output times, s, from 0, at least two, strictly increasing.
    rtol : float
        Relative tolerance, in [1e-13, 1).
    atol : float or array_like (n,)
        Absolute tolerance, in the state's units, each in [1e-13, 1).
    max_step : float, optional
        Largest step, s (> 0); unlimited by default (None or inf).
    rows : array_like of int, optional
        The rows of the state to sample (default all).
    budget : int or EvaluationBudget
        The most evaluations of ``rhs`` each member may make (for a shared budget, what is left,
        and all members' evaluations are spent from it), 1 to :data:`MAX_EVALUATIONS`.
    labels : sequence of str, optional
        What each member's run is, for a failure's message; default "member i".

    Returns
    -------
    list of Trajectory
        One per member, in order.

    Raises
    ------
    raildyn.errors.SolverError
        For the first member (in order) whose run could not finish, as :func:`dormand_prince`.
    """
    rhs = _compiled(rhs)
    states = np.array(_checks.array("states", states, ndim=2, allow_empty=False), dtype=float)
    k, n = states.shape
    data, t_eval, rtol, atol, max_step, rows = _settings(data, t_eval, rtol, atol, max_step, n, rows)
    if data.shape[0] != k:
        raise ValueError(f"data must have a row per member of states ({k}), got {data.shape[0]} rows")
    if t_eval[0] != 0.0:
        raise ValueError(f"t_eval must start at 0 s (every member starts there), got {t_eval[0]!r}")
    budget = _budget(budget)
    labels = [f"member {i}" for i in range(k)] if labels is None else _checks.strings("labels", labels, k)
    limit = budget.left
    out = np.zeros((k, rows.size, t_eval.size))
    counts = np.zeros((k, 5), np.int64)
    counts[:, 1] = limit
    status, reached = np.zeros(k, np.int64), np.zeros(k)
    with np.errstate(all="ignore"):
        _dopri.advance_batch(
            rhs, data, float(t_eval[-1]), states, rtol, atol, max_step, t_eval, rows, out, counts, status,
            reached,
        )  # fmt: skip
    budget.spend(int(counts[:, 0].sum()))
    for i in range(k):
        if status[i] != _dopri.DONE:
            done = int(counts[i, 2])
            raise _failure(
                "budget" if status[i] == _dopri.OVER_BUDGET else "step",
                labels[i],
                time=reached[i],
                step=int(counts[i, 3]),
                limit=limit,
                partial=_partial(
                    t_eval[:done], out[i][:, :done], states[i], int(counts[i, 0]), int(counts[i, 3])
                ),
            )
    return [Trajectory(t_eval, out[i], states[i], int(counts[i, 0]), int(counts[i, 3])) for i in range(k)]


def solve_ivp(
    fun,
    t_span,
    y0,
    *,
    method: str = "RK45",
    rtol: float = 1e-6,
    atol=1e-9,
    budget=1_000_000,
    label: str = "the integration",
    non_finite: str = "raise",
    progress: Callable[[float], None] | None = None,
    **options,
):
    """``scipy.integrate.solve_ivp`` bounded by a budget of evaluations, under the failure rule.

    Parameters
    ----------
    fun : callable
        ``fun(t, y)``, the right-hand side: an array of the shape of ``y``, finite at the start
        (checked there: a ValueError naming ``fun`` otherwise).
    t_span : pair of float
        (t0, t1), s, finite, t0 < t1.
    y0 : array_like, shape (n,)
        The state at t0, finite.
    method : {"RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA"}
        scipy's method.
    rtol : float
        Relative tolerance, in [1e-13, 1).
    atol : float or array_like (n,)
        Absolute tolerance, in the state's units, each in [1e-13, 1).
    budget : int or EvaluationBudget
        The most evaluations of ``fun``, 1 to :data:`MAX_EVALUATIONS` (see the module's rule).
    label : str
        What the run is, for a failure's message (e.g. "the run at V = 60 m/s").
    non_finite : {"raise", "reject"}
        What a non-finite state or derivative does: "raise" ends the run with
        :class:`~raildyn.errors.SolverError` at once; "reject" hands scipy a NaN derivative, so
        the trial step is rejected and retried smaller (as :func:`dormand_prince` does), and a
        failure then says at how many trial stages and when it last happened.
    progress : callable, optional
        ``progress(t)`` is called with each time at which ``fun`` gave a finite derivative, s.
    **options
        Passed to ``scipy.integrate.solve_ivp`` (``t_eval``, ``max_step``, ``events``...); another
        name is refused with a TypeError naming it.

    Returns
    -------
    scipy.integrate OdeResult
        scipy's result, its ``success`` true and ``y`` finite.

    Raises
    ------
    raildyn.errors.SolverError
        If the budget runs out, the state becomes non-finite or scipy gives up.

    Examples
    --------
    >>> sol = solve_ivp(lambda t, y: -2.0 * y, (0.0, 1.0), [1.0], rtol=1e-10, atol=1e-12)
    >>> round(float(sol.y[0, -1]), 8)
    0.13533528
    """
    import scipy.integrate

    _checks.function("fun", fun)
    span = _checks.array("t_span", t_span, shape=(2,))
    if not span[0] < span[1]:
        raise ValueError(f"t_span must be (t0, t1) with t0 < t1, s, got {t_span!r}")
    y0 = _checks.array("y0", y0, ndim=1, allow_empty=False)
    _checks.choice("method", method, _SCIPY_METHODS)
    rtol = _checks.tolerance("rtol", rtol)
    if np.ndim(atol) == 0:
        atol = _checks.tolerance("atol", atol)
    else:
        atol = _checks.array("atol", atol, shape=(y0.size,))
        for a in atol:
            _checks.tolerance("atol", a)
    budget = _budget(budget)
    _checks.instance("label", label, str, "string")
    _checks.choice("non_finite", non_finite, _NON_FINITE)
    if progress is not None:
        _checks.function("progress", progress)
    unknown = sorted(set(options) - _SCIPY_OPTIONS)
    if unknown:
        raise TypeError(f"solve_ivp got unknown options {unknown}; scipy's are {sorted(_SCIPY_OPTIONS)}")
    limit, reject = budget.left, non_finite == "reject"
    state = {"calls": 0, "t": float(span[0]), "blocked": 0, "last": math.nan}

    def detail():
        if not state["blocked"]:
            return ""
        return (
            f"The right-hand side was not finite at {state['blocked']} trial stages, the last at "
            f"t = {state['last']:.6g} s"
        )

    def bounded(t, y):
        state["t"] = t
        state["calls"] += 1
        if state["calls"] > limit:
            raise _failure("budget", label, time=t, limit=limit, detail=detail())
        if not reject and not math.isfinite(y.sum()):
            raise _failure("non-finite", label, time=t)
        if state["calls"] == 1:  # at the caller's start: what fun returns there is the caller's input
            where = f"the start of {label} (t = {t:.6g} s)"
            out = _checks.returned("fun", fun(t, y), shape=y.shape, at=where)
        else:
            out = np.asarray(fun(t, y), dtype=float)
        if not math.isfinite(out.sum()):
            if not reject:
                raise _failure("non-finite", label, time=t)
            state["blocked"] += 1
            state["last"] = t
            return np.full_like(out, np.nan)
        if progress is not None:
            progress(t)
        return out

    try:
        # An overflow inside the step control is no warning to the user: the state it leads to is
        # caught in bounded(), which ends the run with a SolverError (through scipy, to the caller).
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            sol = scipy.integrate.solve_ivp(
                bounded, tuple(span), y0, method=method, rtol=rtol, atol=atol, **options
            )
    finally:
        budget.spend(min(state["calls"], limit))
    if not sol.success:
        raise _failure(
            f"scipy's {method} stopped: {sol.message}", label, time=sol.t[-1], detail=detail(),
            partial=_scipy_partial(sol, options),
        )  # fmt: skip
    if not np.isfinite(sol.y).all():
        raise _failure("non-finite", label, time=sol.t[-1], detail=detail())
    return sol


def _scipy_partial(sol, options) -> Trajectory | None:
    """The output times a run that scipy gave up passed (with ``t_eval``), or None."""
    if "t_eval" not in options or not sol.t.size or not np.isfinite(sol.y).all():
        return None
    return Trajectory(sol.t, sol.y, sol.y[:, -1], int(sol.nfev), max(sol.t.size - 1, 0))
