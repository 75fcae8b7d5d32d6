"""Why a run blew up: the failure of a diverging scheme, naming its stability limit on the system.

The runs of :mod:`raildyn.integrators.linear` and :mod:`raildyn.integrators.nonlinear` call
:func:`diverged` when a state outgrows the scale of its problem; the reason it gives compares the
step with the scheme's limit from :mod:`raildyn.integrators.amplification` (on the undamped periods
for the schemes on (x, v, a), on the eigenvalues of the first-order system for the first-order
schemes), and the completed part of the run becomes the :class:`raildyn.errors.SolverError`'s
``partial``. It sits between the amplification analysis and the runs, so neither imports the other.
"""

from __future__ import annotations

import numpy as np

from raildyn.errors import SolverError
from raildyn.integrators._common import Problem, highest_frequency, partial_result
from raildyn.integrators.amplification import first_order_step_limit, stability_limit
from raildyn.vibration import first_order_matrix


def diverged(
    name: str, p: Problem, step: int, x, v, a, params, *, iterations=0, analysed_as=None
) -> SolverError:
    """The failure of a run that blew up at ``step``: the reason names the stability limit of the scheme.

    ``x``, ``v``, ``a`` hold the rows (m, n) computed before ``step``; the completed part
    becomes the error's ``partial`` result.
    """
    done = min(len(x), len(v), len(a), step)
    partial = partial_result(name, p.t[:done], x, v, a, iterations)
    time = float(p.t[0] + step * p.h)
    return SolverError(divergence_reason(name, p, params, analysed_as), step=step, time=time, partial=partial)


def divergence_reason(method: str, p: Problem, params, analysed_as: str | None = None) -> str:
    """Why a run of ``method`` blew up, naming its stability limit on this system."""
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
    lam = np.linalg.eigvals(first_order_matrix(p.M, p.C, p.K))
    decaying = lam[(lam.real <= 1e-12 * np.abs(lam).max()) & (lam != 0)]
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
