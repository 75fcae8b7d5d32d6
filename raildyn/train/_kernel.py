"""The longitudinal right-hand side of one train state, compiled with numba.

``TrainModel.rhs_numpy`` is the readable reference and serves batches of
states; this module computes the same thing for a single state in one compiled
loop over the vehicles. A long train is a few hundred small operations per
evaluation, where numpy's per-call cost outweighs the arithmetic: the compiled
loop takes about 4 µs for 152 vehicles against 20 µs for numpy, which makes long
braking runs interactive. ``tests/test_train.py`` holds the two equal to round-off.

Everything the loop needs is packed into three float arrays (so a call unboxes
few arguments): ``table`` has one column per vehicle and the rows named by the
``ROW_*`` constants; ``scalars`` holds the coupler law, the brake, the driver's
settings and flags (``S_*``); ``route`` is ``[positions, grade, curvature]``.
For the compiled integrator (:func:`raildyn.integrators.runner.dormand_prince`), :func:`pack`
puts the three into one row of floats and :func:`rhs_dopri` unpacks them (views, no copies) and writes the
derivative in place, compiled to the integrator's one signature.
The dynamic brake's corner speeds come in ``scalars`` too, from
:data:`raildyn.train.forces.DYNAMIC_BRAKE_PEAK_SPEED` and ``..._FADE_SPEED`` (their one
definition), and the throttle as the fraction ``notch / NOTCHES``.

Nothing here checks its input: ``TrainModel.rhs`` checks the shape and finiteness of
the state before it calls :func:`rhs`, which trusts ``y`` to hold ``2 n`` numbers.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from raildyn.integrators.runner import RHS_SIGNATURE

__all__ = ["ROWS", "SCALARS", "all_finite", "coupler_force", "pack", "rhs", "rhs_dopri"]

# Rows of ``table`` (one column per vehicle).
(ROW_INV_MASS, ROW_A0, ROW_A1, ROW_A2, ROW_CURVE, ROW_WEIGHT, ROW_BRAKE, ROW_ARRIVAL,
 ROW_SPACING, ROW_POWER, ROW_EFFORT, ROW_DYNAMIC) = range(ROWS := 12)  # fmt: skip

# Entries of ``scalars``; the last four are flags (1.0 or 0.0). S_THROTTLE is notch / NOTCHES;
# S_DYNAMIC_PEAK and S_DYNAMIC_FADE are the dynamic brake's corner speeds (m/s).
(S_SLACK, S_K_LOAD, S_K_UNLOAD, S_TRAVEL, S_K_SOLID, S_SMOOTHING, S_TRANSITION, S_CREEP,
 S_BRAKE_START, S_BUILD_UP, S_THROTTLE, S_DYNAMIC, S_DYNAMIC_PEAK, S_DYNAMIC_FADE,
 S_RESISTANCE, S_BRAKE, S_TRACTION, S_ROUTE) = range(SCALARS := 18)  # fmt: skip


@numba.njit(cache=True, fastmath=False)
def coupler_force(delta, rate, s):
    """Force of one coupler (N, + tension) for extension ``delta`` and its rate: DraftGear.force."""
    sign = 1.0 if delta > 0.0 else (-1.0 if delta < 0.0 else 0.0)
    slack = s[S_SLACK]
    if slack == 0.0:
        u, slope = abs(delta), 1.0
    else:
        eps = s[S_SMOOTHING]
        a = abs(delta) - 0.5 * slack
        b = min(max(a + eps, 0.0), 2.0 * eps)
        u = a if a >= eps else b * b * (0.25 / eps)
        slope = b * (0.5 / eps)
    mean = 0.5 * (s[S_K_LOAD] + s[S_K_UNLOAD])
    half = 0.5 * (s[S_K_LOAD] - s[S_K_UNLOAD])
    k = mean + half * math.tanh(slope * sign * rate / s[S_TRANSITION])
    force = k * u
    if s[S_K_SOLID] > 0.0:
        force += s[S_K_SOLID] * max(u - s[S_TRAVEL], 0.0)
    return sign * force


@numba.njit(cache=True)
def all_finite(a):
    """True if every entry of the 1-D array ``a`` is finite (0.4 µs for 300 entries; numpy takes 2 µs)."""
    for x in a:
        if not math.isfinite(x):
            return False
    return True


@numba.njit(cache=True)
def _segment(xs, position):
    k = np.searchsorted(xs, position, side="right") - 1
    return min(max(k, 0), xs.size - 1)


@numba.njit(cache=True)
def rhs(t, y, table, scalars, route):
    """dy/dt of ``y = [x_0, Δx_0 … Δx_{n−2}, v_0 … v_{n−1}]`` (see TrainModel.initial_state)."""
    out = np.empty(2 * table.shape[1])
    _rhs_into(t, y, table, scalars, route, out)
    return out


@numba.njit(cache=True)
def _rhs_into(t, y, table, scalars, route, out):
    """:func:`rhs` written into ``out`` (2n), allocating nothing: the integrator calls it each stage."""
    n = table.shape[1]
    s = scalars
    creep = s[S_CREEP]
    brake_on = s[S_BRAKE] > 0.0 and t > s[S_BRAKE_START]
    x = y[0]  # route position of vehicle i, walked back along the train
    behind = 0.0  # the force of the coupler ahead of vehicle i (+ tension), pulling it forward
    for i in range(n):
        v = y[n + i]
        speed = abs(v)
        retard = 0.0
        if s[S_RESISTANCE] > 0.0:
            retard = table[ROW_A0, i] + speed * (table[ROW_A1, i] + table[ROW_A2, i] * speed)
        grade = 0.0
        if s[S_ROUTE] > 0.0:
            if i > 0:
                x -= table[ROW_SPACING, i - 1] + y[i]
            k = _segment(route[0], x)
            grade = route[1, k]
            if s[S_RESISTANCE] > 0.0:
                retard += table[ROW_CURVE, i] * abs(route[2, k])
        if brake_on:
            since = max(t - table[ROW_ARRIVAL, i], 0.0)
            retard -= table[ROW_BRAKE, i] * math.expm1(-since / s[S_BUILD_UP])
        total = math.tanh(-v / creep) * retard
        if grade != 0.0:
            total -= table[ROW_WEIGHT, i] * grade / math.sqrt(1.0 + grade * grade)
        if s[S_TRACTION] > 0.0:
            limit = table[ROW_POWER, i] / max(speed, 1e-6)
            traction = s[S_THROTTLE] * min(table[ROW_EFFORT, i], limit)
            shape = min(speed / s[S_DYNAMIC_PEAK], min(1.0, s[S_DYNAMIC_FADE] / max(speed, 1e-12)))
            dynamic = s[S_DYNAMIC] * table[ROW_DYNAMIC, i] * shape
            total += traction - math.tanh(v / creep) * dynamic
        force = behind + total
        if i < n - 1:
            rate = v - y[n + i + 1]
            behind = coupler_force(y[1 + i], rate, s)
            force -= behind
            out[1 + i] = rate
        out[n + i] = force * table[ROW_INV_MASS, i]
    out[0] = y[n]


# The layout of a model packed into one row of floats for the compiled integrator
# (raildyn.integrators.runner): a header, then ``table`` (ROWS x n), ``scalars`` and ``route`` (3 x m),
# each flattened in C order. The header holds n and m, and two entries that the right-hand side
# itself writes: how many of its evaluations gave a non-finite derivative, and the time of the last.
H_VEHICLES, H_SEGMENTS, H_NON_FINITE, H_LAST_NON_FINITE, HEADER = range(5)


def pack(table, scalars, route):
    """The model's three arrays as one row of ``data`` (shape (1, L)) for :func:`rhs_dopri`."""
    n, m = table.shape[1], route.shape[1]
    return np.concatenate([[n, m, 0.0, 0.0], table.ravel(), scalars, route.ravel()])[None, :].copy()


@numba.njit(RHS_SIGNATURE, cache=True)
def rhs_dopri(t, y, member, data, out):
    """:func:`rhs` for the compiled integrator, the model unpacked from row ``member`` of ``data``.

    A non-finite derivative is made all NaN, as :func:`raildyn.train.simulate` does for
    solve_ivp: its error norm is NaN, so the integrator rejects the step and retries a smaller
    one, and the first step is chosen as solve_ivp chooses it (from a NaN difference, where an
    infinite one would give a step of zero). Each such evaluation is counted in the row's
    header, for the message of a run that stops there.
    """
    row = data[member]
    n, m = int(row[H_VEHICLES]), int(row[H_SEGMENTS])
    start = HEADER + ROWS * n
    table = row[HEADER:start].reshape((ROWS, n))
    scalars = row[start : start + SCALARS]
    route = row[start + SCALARS : start + SCALARS + 3 * m].reshape((3, m))
    _rhs_into(t, y, table, scalars, route, out)
    if not all_finite(out):
        out[:] = np.nan
        row[H_NON_FINITE] += 1.0
        row[H_LAST_NON_FINITE] = t
