"""The one compiled integrator with error control: Dormand–Prince 5(4), as scipy's RK45, in numba.

scipy's ``solve_ivp`` spends some 7 µs of Python on each evaluation of a right-hand side, which
is most of a run when the right-hand side itself is compiled (a 150-wagon train: 4 µs; a car
with four wheelsets: 1 µs). This module runs the same method with the same step control in
compiled code: the Dormand–Prince pair (Dormand & Prince 1980) with scipy's RK45 error norm
(the RMS of the error over ``atol + rtol·max(|y|, |y_new|)``), its step factors (safety 0.9,
between 0.2 and 10, no growth right after a rejection), its first step (Hairer, Nørsett &
Wanner 1993, sec. II.4) and its quartic dense output (Shampine 1986). A run therefore takes
the steps ``solve_ivp(method="RK45")`` takes, and the tests hold the two to each other.

The right-hand side is a numba function compiled to :data:`RHS_SIGNATURE`, ``rhs(t, y, member,
data, out)``: ``member`` picks the parameter set of a batch, a row of ``data`` (each model packs its
parameters into one row of floats), and the derivative is written into ``out``. The integrator takes
it as a first-class function, so that it is compiled once and cached, whatever the model.
:func:`advance` runs one member; :func:`advance_batch` runs many members at once, in parallel
threads, each with its own steps. Nothing is checked here: callers check their input before any
compiled code runs, and read the status codes below to raise :class:`raildyn.errors.SolverError`.
"""

from __future__ import annotations

import concurrent.futures
import os

import numba
import numpy as np
from numba import types

# The one signature of a right-hand side, rhs(t, y, member, data, out): a first-class function type,
# so that the integrator is compiled once, cached on disk, and calls any right-hand side compiled to it.
RHS_SIGNATURE = types.void(
    types.float64, types.float64[::1], types.int64, types.float64[:, ::1], types.float64[::1]
)
_RHS = types.FunctionType(RHS_SIGNATURE)
_F, _I = types.float64, types.int64
_VEC, _IVEC, _MAT = types.float64[::1], types.int64[::1], types.float64[:, ::1]

# Status of a run.
DONE = 0  # reached the end time
PAUSED = 1  # took the number of steps asked for (call again to go on)
TOO_SMALL_STEP = 2  # the step fell below 10 spacings of floating-point numbers at t
OVER_BUDGET = 3  # more evaluations of the right-hand side than allowed

STATUS_TEXT = {
    TOO_SMALL_STEP: "the step size fell below the spacing of floating-point numbers",
    OVER_BUDGET: "the run needed more evaluations of the right-hand side than allowed",
}

# The Dormand–Prince tableau, as in scipy.integrate.RK45 (Dormand & Prince 1980, table 2).
_C = np.array([0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0])
_A = np.array(
    [
        [0.0, 0.0, 0.0, 0.0, 0.0],
        [1 / 5, 0.0, 0.0, 0.0, 0.0],
        [3 / 40, 9 / 40, 0.0, 0.0, 0.0],
        [44 / 45, -56 / 15, 32 / 9, 0.0, 0.0],
        [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729, 0.0],
        [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656],
    ]
)
_B = np.array([35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84])
_E = np.array([-71 / 57600, 0.0, 71 / 16695, -71 / 1920, 17253 / 339200, -22 / 525, 1 / 40])
# The quartic interpolant of each step, y(t_old + x h) = y_old + h K·P·[x, x², x³, x⁴] (Shampine 1986).
_P = np.array(
    [
        [1.0, -8048581381 / 2820520608, 8663915743 / 2820520608, -12715105075 / 11282082432],
        [0.0, 0.0, 0.0, 0.0],
        [0.0, 131558114200 / 32700410799, -68118460800 / 10900136933, 87487479700 / 32700410799],
        [0.0, -1754552775 / 470086768, 14199869525 / 1410260304, -10690763975 / 1880347072],
        [0.0, 127303824393 / 49829197408, -318862633887 / 49829197408, 701980252875 / 199316789632],
        [0.0, -282668133 / 205662961, 2019193451 / 616988883, -1453857185 / 822651844],
        [0.0, 40617522 / 29380423, -110615467 / 29380423, 69997945 / 29380423],
    ]
)
_SAFETY, _MIN_FACTOR, _MAX_FACTOR = 0.9, 0.2, 10.0
_EXPONENT = -1.0 / 5.0  # of the error norm: the error of the 4th-order estimate goes as h⁵


@numba.njit(_F(_VEC, _VEC), cache=True, error_model="numpy")
def _rms(x, scale):
    total = 0.0
    for i in range(x.size):
        r = x[i] / scale[i]
        total += r * r
    return np.sqrt(total / x.size)


@numba.njit(_F(_RHS, _MAT, _I, _F, _VEC, _VEC, _F, _F, _F, _VEC), cache=True, error_model="numpy")
def first_step(rhs, data, member, t0, y0, f0, t1, max_step, rtol, atol):
    """scipy's ``select_initial_step`` for a method of order 4 (one evaluation of ``rhs``)."""
    n = y0.size
    scale = atol + np.abs(y0) * rtol
    d0, d1 = _rms(y0, scale), _rms(f0, scale)
    h0 = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
    h0 = min(h0, t1 - t0)
    f1 = np.empty(n)
    rhs(t0 + h0, y0 + h0 * f0, member, data, f1)
    d2 = _rms(f1 - f0, scale) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / 5.0)
    return min(100.0 * h0, h1, t1 - t0, max_step)


@numba.njit(
    types.Tuple((_I, _F, _F))(
        _RHS, _MAT, _I, _F, _VEC, _VEC, _F, _F, _F, _VEC, _F, _VEC, _IVEC, _MAT, _IVEC, _I
    ),
    cache=True,
    error_model="numpy",
    nogil=True,
)
def advance(
    rhs, data, member, t, y, f, h_abs, t1, rtol, atol, max_step, t_out, rows, y_out, counts, max_steps
):
    """Advance one member from (t, y) with derivative f and step h_abs towards t1; in place.

    ``y`` and ``f`` are overwritten with the state and derivative reached. The states at the times
    ``t_out`` (increasing) that the run passes are interpolated into ``y_out[:, k]``, rows ``rows``
    of the state. ``counts`` holds [evaluations, evaluation budget, next output index, accepted
    steps, rejected steps] and is updated. At most ``max_steps`` steps are taken.

    Returns
    -------
    status : int
        :data:`DONE`, :data:`PAUSED`, :data:`TOO_SMALL_STEP` or :data:`OVER_BUDGET`.
    t : float
        The time reached.
    h_abs : float
        The step to try next (to resume with).
    """
    n = y.size
    K = np.empty((7, n))
    y_new = np.empty(n)
    stage = np.empty(n)
    steps = 0
    while t < t1:
        if steps >= max_steps:
            return PAUSED, t, h_abs
        min_step = 10.0 * (np.nextafter(t, np.inf) - t)
        h_abs = min(max(h_abs, min_step), max_step)
        rejected = False
        while True:
            if h_abs < min_step:
                return TOO_SMALL_STEP, t, h_abs
            if counts[0] + 6 > counts[1]:
                return OVER_BUDGET, t, h_abs
            t_new = min(t + h_abs, t1)
            h = t_new - t
            h_abs = h
            for i in range(n):  # element by element: ARCHITECTURE.md, compiled kernels
                K[0, i] = f[i]
            for s in range(1, 6):
                for i in range(n):
                    acc = 0.0
                    for j in range(s):
                        acc += K[j, i] * _A[s, j]
                    stage[i] = y[i] + h * acc
                rhs(t + _C[s] * h, stage, member, data, K[s])
            for i in range(n):
                acc = 0.0
                for j in range(6):
                    acc += K[j, i] * _B[j]
                y_new[i] = y[i] + h * acc
            rhs(t_new, y_new, member, data, K[6])
            counts[0] += 6
            total = 0.0
            for i in range(n):
                err = 0.0
                for j in range(7):
                    err += K[j, i] * _E[j]
                scale = atol[i] + max(abs(y[i]), abs(y_new[i])) * rtol
                r = err * h / scale
                total += r * r
            norm = np.sqrt(total / n)
            if norm < 1.0:
                factor = _MAX_FACTOR if norm == 0.0 else min(_MAX_FACTOR, _SAFETY * norm**_EXPONENT)
                if rejected:
                    factor = min(1.0, factor)
                h_abs *= factor
                break
            # Rejected; a non-finite stage (a NaN norm) shrinks the step by the least factor.
            factor = _SAFETY * norm**_EXPONENT
            h_abs *= factor if factor > _MIN_FACTOR else _MIN_FACTOR
            rejected = True
            counts[4] += 1
        # The output times this step passes, from its quartic interpolant.
        k = counts[2]
        while k < t_out.size and t_out[k] <= t_new:
            x = (t_out[k] - t) / h
            for r in range(rows.size):
                i = rows[r]
                q = 0.0
                for j in range(7):
                    q += K[j, i] * (x * (_P[j, 0] + x * (_P[j, 1] + x * (_P[j, 2] + x * _P[j, 3]))))
                y_out[r, k] = y[i] + h * q
            k += 1
        counts[2] = k
        counts[3] += 1
        steps += 1
        t = t_new
        for i in range(n):
            y[i] = y_new[i]
            f[i] = K[6, i]
    return DONE, t, h_abs


@numba.njit(_F(_RHS, _MAT, _I, _F, _VEC, _F, _F, _VEC, _F, _VEC), cache=True, error_model="numpy", nogil=True)
def start(rhs, data, member, t0, y, t1, rtol, atol, max_step, f):
    """The derivative at the start (into ``f``) and the first step; two evaluations of ``rhs``."""
    rhs(t0, y, member, data, f)
    return first_step(rhs, data, member, t0, y, f, t1, max_step, rtol, atol)


def advance_batch(rhs, data, t1, states, rtol, atol, max_step, t_out, rows, y_out, counts, status, reached):
    """Run every member of a batch from t = 0 to t1, each with its own steps, on all cores.

    ``states`` (k, n) holds each member's start and is overwritten with its end; ``y_out`` (k,
    len(rows), len(t_out)) receives the sampled rows; ``counts`` (k, 5) as for :func:`advance`
    (set its budget column before the call); ``status`` and ``reached`` (k,) the outcome.

    The members are shared among threads: :func:`advance` releases the GIL, so they run on every
    core at once. (A numba ``prange`` would do the same but doubled the compile time to 10 s.)
    """

    def run(m):
        y, f = states[m].copy(), np.empty(states.shape[1])
        h = start(rhs, data, m, 0.0, y, t1, rtol, atol, max_step, f)
        counts[m, 0] += 2
        status[m], reached[m], _ = advance(
            rhs, data, m, 0.0, y, f, h, t1, rtol, atol, max_step, t_out, rows, y_out[m], counts[m], 1 << 62
        )
        states[m] = y

    k = states.shape[0]
    workers = min(k, os.cpu_count() or 1)
    if workers <= 1:
        for m in range(k):
            run(m)
        return
    with concurrent.futures.ThreadPoolExecutor(workers) as pool:
        list(pool.map(run, range(k)))  # list: re-raises a worker's exception here
