"""Shooting's integrations: many neighbouring trajectories of one nonlinear model on one sequence of steps.

A finite-difference monodromy matrix differences trajectories a millionth of the state apart; run
separately, each takes its own adaptive steps, and the difference carries the noise of two step
sequences. Here the trajectories are stacked into one state and integrated as one system:
:func:`flows` on the compiled engine (a right-hand side that calls the model's compiled kernel on
each column, :func:`stacked`) where it holds the model, on the model's numpy ``rhs`` otherwise.
Used by :mod:`raildyn.stability.continuation`. SI units.
"""

from __future__ import annotations

import numpy as np

from raildyn.stability.nonlinear import _MAX_EVALUATIONS, _integrate, _label

_ATOL = 1.0e-12  # the absolute tolerance of the runs, in the state's units


# The stacked right-hand sides built so far for kernels that give none of their own (each compiled once
# a process, in about 0.3 s: numba cannot cache a function that closes over another).
_STACKED = {}


def stacked(rhs):
    """A compiled right-hand side that evaluates ``rhs.kernel`` on each column of a stacked state: the
    model's own (``rhs.stacked``, cached by numba), or one built around the kernel.

    The last row of ``data`` lays the stack out: [n, the data row of column 0, of column 1, ...].
    """
    if rhs.stacked is not None:
        return rhs.stacked
    kernel = rhs.kernel
    if kernel not in _STACKED:
        import numba

        from raildyn.integrators.runner import RHS_SIGNATURE

        @numba.njit(RHS_SIGNATURE, error_model="numpy")
        def stacked(t, y, member, data, out):
            layout = data.shape[0] - 1
            n = int(data[layout, 0])
            for c in range(y.size // n):
                kernel(t, y[c * n : (c + 1) * n], int(data[layout, 1 + c]), data, out[c * n : (c + 1) * n])

        _STACKED[kernel] = stacked
    return _STACKED[kernel]


def compiled(model, engine) -> bool:
    """Whether the compiled engine runs the model (``engine`` "auto" or "compiled"); a ValueError where
    "compiled" is asked of a model it does not hold."""
    why = model.compiled_reason
    if engine == "compiled" and why is not None:
        raise ValueError(f"engine 'compiled' cannot run this model: {why}; use engine='scipy'")
    return engine != "scipy" and why is None


def flows(model, starts, V, dV, T, rtol, engine):
    """φ_T of each column of ``starts`` (n, k) at V (the last at V + dV, unless dV is None), as one system.

    The columns are integrated as one stacked state, so that they share one sequence of adaptive
    steps: the differences between neighbouring columns then carry the perturbation, not the noise
    of two step sequences (run apart at rtol 1e-10, the soft wheelset's multipliers on its flanges
    came out a tenth or more off; stacked, within 1e-4 of the DOP853 reference). Returns the ends
    (n, k) and the first column's lateral displacement at 401 points over the period. The compiled
    engine (RK45) runs it where it holds the model (see
    :func:`~raildyn.stability.nonlinear.simulate`'s ``engine``), the model's numpy ``rhs``
    (DOP853) otherwise.
    """
    from raildyn.integrators import runner

    n, k = starts.shape
    iy = model.lateral_index
    t = np.linspace(0.0, T, 401)
    last = V if dV is None else V + dV
    if compiled(model, engine):
        rows = [model.compiled_rhs(V), model.compiled_rhs(last)]
        width = max(max(r.row.size for r in rows), k + 1)
        data = np.zeros((3, width))
        for i, r in enumerate(rows):
            data[i, : r.row.size] = r.row
        data[2, : k + 1] = [n] + [0] * (k - 1) + [1]
        run = runner.dormand_prince(
            stacked(rows[0]), data, starts.T.ravel(), t, rtol=rtol, atol=_ATOL, rows=[iy],
            budget=_MAX_EVALUATIONS, label=_label(V),
        )  # fmt: skip
        return run.end.reshape(k, n).T, run.y[0]

    def rhs(time, z):
        Z = z.reshape(n, k)
        out = np.empty_like(Z)
        if k > 1:
            out[:, :-1] = model.rhs(time, Z[:, :-1], V)
        out[:, -1] = model.rhs(time, Z[:, -1], last)
        return out.ravel()

    sol = _integrate(rhs, T, starts.ravel(), "DOP853", rtol, _ATOL, V, t_eval=t)
    return sol.y[:, -1].reshape(n, k), sol.y[iy * k]
