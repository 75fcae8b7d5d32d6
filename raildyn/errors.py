"""The one failure of raildyn's solvers: :class:`SolverError`.

Failure policy (every solver path: the integrators of chapter 2, the nonlinear
wheelset and vehicle runs, limit cycles, shooting, the train simulation, the
freight car's explicit run): a run that cannot give a trustworthy answer —
a diverging explicit scheme, a step size that underflows, an iteration that does
not converge, a state that becomes non-finite — raises :class:`SolverError`.
A result that is returned is always a success, so results carry no ``success``
flag. The exception says where and why: ``step`` (the step index, or None where
the solver has no fixed steps), ``time`` (s, or the speed-sweep position the
message names) and ``reason``; where a partial history helps a reader (a
scheme blowing up in the chapter 2 widget), ``partial`` holds it.

Bad *input* is not a solver failure: it raises ``ValueError`` or ``TypeError``
before any computation starts.
"""

from __future__ import annotations

from raildyn import _checks

__all__ = ["SolverError"]


class SolverError(ArithmeticError):
    """A solver that could not produce a trustworthy answer.

    Parameters
    ----------
    reason : str
        What went wrong, in words (it is also the exception's message); not empty.
    step : int or None
        Index of the step at which it happened, >= 0, or None.
    time : float or None
        Time (s) at which it happened, finite (any sign), or None.
    partial : object or None
        The part of the result computed before the failure, where that is useful (any
        object: a diverged history may hold NaN).

    Examples
    --------
    >>> err = SolverError("the state became non-finite", step=12, time=0.06)
    >>> err.step, err.time
    (12, 0.06)
    >>> str(err)
    'the state became non-finite (step 12, t = 0.06 s)'
    """

    def __init__(self, reason: str, *, step: int | None = None, time: float | None = None, partial=None):
        if not isinstance(reason, str):
            raise TypeError(f"reason must be a string, got {reason!r:.80} of type {type(reason).__name__}")
        if not reason:
            raise ValueError("reason must say what went wrong, got an empty string")
        if step is not None:
            step = _checks.integer("step", step, low=0)
        if time is not None:
            time = _checks.scalar("time", time)
        where = []
        if step is not None:
            where.append(f"step {step}")
        if time is not None:
            where.append(f"t = {time:.6g} s")
        super().__init__(f"{reason} ({', '.join(where)})" if where else reason)
        self.reason = reason
        self.step = step
        self.time = time
        self.partial = partial
