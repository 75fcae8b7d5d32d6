"""FASTSIM's march over the cells of every contact state, compiled with numba.

:func:`raildyn.contact.fastsim.fastsim` checks its input, computes the flexibilities,
the pressure normalisation and the scaling of huge creepages with numpy (a few
operations per state), then calls :func:`march` (or :func:`march_parallel` for a large
batch) for the cells, the part that grows as S × n_y × n_x. ``_fastsim_numpy`` in that
module is the numpy march this replaces; ``tests/test_fastsim_kernel.py`` holds the two
equal to 1e-12 of the largest force.

The loops run over states, then cells along x, then strips across: the strips of one
state are independent, so the innermost loop carries no dependency and the compiler
puts four strips through each vector instruction (AVX2), square root and division
included. Marching one strip to its end instead chains each cell on the one before, and
a sliding cell's chain (square, square root, division, product) would set the pace: such
a chain measured 15 ns per cell, eight times the kernel. Every division but the cap's
and the strip geometry are taken out of the cell loop, and the forces are summed per
strip and multiplied by the cell area once per strip. The step and its products with the
three traction rates and with ½ stay in the cell loop (five multiplications): moved into
per-strip arrays they made LLVM give up vectorizing the loop (more arrays than its
run-time overlap checks allow), three times slower. ``error_model="numpy"`` makes a
division plain IEEE arithmetic, without numba's zero test, which also stops vectorizing;
``fastmath`` stays off, as it would reorder the sums and approximate the division and
square root, and the tests ask for 1e-12.

The slide test takes min(1, μp/√(t_x² + t_y²)) for every cell, without a branch: the
numpy test |t| > μp but for the last bit of |t|, where the cap is 1 to rounding either way.
It needs the squares to stay within floating-point range, which the scaling of huge
creepages (``_within_sliding``) ensures for any bound μp₀ between 1e-100 and 1e100 Pa; a
state outside that range (an absurd μ or load) is marched with ``math.hypot`` as in numpy.

Operations per cell (the inner loop of :func:`_march_state`, forces only): 13
multiplications, 9 additions or subtractions, 1 square root, 1 division and 1 comparison,
25 in all. Measured on this machine (AMD EPYC, Zen 3, 2 cores shared with other sessions;
the clock, from a chain of dependent additions of 3 cycles each, ~3.2 GHz), best of
repeated runs on one thread, 10⁴ random states on 20 × 20 cells (57 % of them sliding):
1.86 ns per cell, 0.75 µs per contact, 5.4 × 10⁸ cells/s, 6 cycles per cell or 4.2
operations per cycle. One operation per cycle, the pace of dependent scalar code, would
allow 1.3 × 10⁸ cells/s: the kernel runs 4.2 times faster by its four-wide vectors. The
same 25 operations on independent cells in a compiled loop (no carried traction, data in
the L1 cache) take 1.44 ns per cell, 7 × 10⁸ cells/s: the kernel reaches 0.77 of that
limit, of which the vector square root and division alone take 1.03 ns per cell (0.95 ns
for the other 23 operations). The rest of :func:`fastsim`, the numpy preparation of the
states (mostly the interpolation of Kalker's coefficients), adds about 0.8 µs per contact.
"""

from __future__ import annotations

import math

import numba
import numpy as np

__all__ = ["march"]

# Bounds μp₀ (Pa) between which the squares of the tractions cannot overflow or underflow
# (the tractions stay within ~1e12 μp₀, see _within_sliding): the fast slide test holds.
_SAFE_LOW, _SAFE_HIGH = 1e-100, 1e100


@numba.njit(cache=True, error_model="numpy")
def _march_state(s, xi, eta, phi, a, b, l1, l2, l3, limit, eta_y, root, shape, work, forces, out, stick):
    """March state ``s`` over its n_y strips and n_x cells; forces into ``forces[:, s]``, fields if asked.

    ``eta_y`` and ``root`` hold each strip's y/b and √(1 − (y/b)²); ``shape`` (n_x, n_y) the
    pressure shape of each cell, cell-major (times μp₀ it bounds the traction). ``work`` (11, n_y)
    is scratch space; ``out`` (5, S, n_y, n_x) receives x, p_x, p_y, slip_x and slip_y and
    ``stick`` (S, n_y, n_x) the adhesion flags (the caller fills y and p_z). Both None for the
    forces alone: numba then compiles a version without the stores, whose cell loop
    vectorizes (a run-time flag keeps them in the loop and halves the speed).
    ``error_model="numpy"`` lets a division be IEEE (no zero test), which the vectorizer needs.
    """
    n_x, n_y = shape.shape
    rate_y = eta[s] / l2[s]  # ∂p_y/∂x = γ_y/L₂ + φx/L₃ and ∂p_x/∂x = γ_x/L₁ − φy/L₃
    spin_y = phi[s] / l3[s]
    rate_0 = xi[s] / l1[s]
    bound_scale = limit[s]
    dy = 2.0 * b[s] / n_y
    fast = _SAFE_LOW <= bound_scale <= _SAFE_HIGH
    y, half, dx, rate_x, px, py = work[0], work[1], work[2], work[3], work[4], work[5]
    sum_x, sum_y, sum_m, slip_x, slip_y = work[6], work[7], work[8], work[9], work[10]
    for j in range(n_y):
        y[j] = b[s] * eta_y[j]
        half[j] = a[s] * root[j]
        dx[j] = 2.0 * half[j] / n_x
        rate_x[j] = rate_0 - spin_y * y[j]
        px[j] = 0.0
        py[j] = 0.0
        sum_x[j] = 0.0
        sum_y[j] = 0.0
        sum_m[j] = 0.0
    for k in range(n_x):
        # The first cell's centre lies half a cell from the leading edge, the others one cell on.
        first = 0.5 if k == 0 else 1.0
        centre = k + 0.5
        if out is not None and k < 2:  # L/step, which turns a traction deficit into slip
            for j in range(n_y):
                slip_x[j] = l1[s] / (first * dx[j])
                slip_y[j] = l2[s] / (first * dx[j])
        for j in range(n_y):  # strips are independent: this loop vectorizes
            step = first * dx[j]
            x = half[j] - centre * dx[j]
            # Exact increment of the adhesion traction from x + step to x (marching against x):
            # ∫ φx/L₃ dx over the step is φ/L₃ · step · (x + step/2).
            tx = px[j] - rate_x[j] * step
            ty = py[j] - rate_y * step - spin_y * step * (x + 0.5 * step)
            bound = bound_scale * shape[k, j]
            # The cap μp/|t| where the cell slides, 1 where it sticks (|t| = 0 gives inf, hence 1):
            # without a branch, so that four strips go through one vector square root and division.
            if fast:
                factor = min(1.0, bound / math.sqrt(tx * tx + ty * ty))
            else:
                factor = min(1.0, bound / math.hypot(tx, ty))
            p_x = tx * factor
            p_y = ty * factor
            px[j] = p_x
            py[j] = p_y
            sum_x[j] += p_x
            sum_y[j] += p_y
            sum_m[j] += x * p_y
            if out is not None:
                out[0, s, j, k] = x
                out[1, s, j, k] = p_x
                out[2, s, j, k] = p_y
                # Slip: the part of the rigid-slip rate the springs could not take up, in creepage units.
                out[3, s, j, k] = (tx - p_x) * slip_x[j]
                out[4, s, j, k] = (ty - p_y) * slip_y[j]
                stick[s, j, k] = factor >= 1.0
    fx = fy = mz = 0.0
    for j in range(n_y):
        cell = dx[j] * dy
        fx += sum_x[j] * cell
        fy += sum_y[j] * cell
        mz += (sum_m[j] - y[j] * sum_x[j]) * cell  # Σ (x p_y − y p_x) with y fixed along the strip
    forces[0, s] = fx
    forces[1, s] = fy
    forces[2, s] = mz


@numba.njit(cache=True)
def march(xi, eta, phi, a, b, l1, l2, l3, limit, eta_y, root, shape, forces, out, stick):
    """FASTSIM's march for S states (1-D arrays of length S), one after the other.

    ``shape`` is (n_x, n_y), cell-major; ``forces`` (3, S) receives F_x, F_y (N) and M_z (N m);
    ``out`` and ``stick`` the fields, or None (see :func:`_march_state`).
    """
    work = np.empty((11, shape.shape[1]))
    for s in range(xi.size):
        _march_state(s, xi, eta, phi, a, b, l1, l2, l3, limit, eta_y, root, shape, work, forces, out, stick)


@numba.njit(cache=True, parallel=True)
def march_parallel(xi, eta, phi, a, b, l1, l2, l3, limit, eta_y, root, shape, forces, out, stick, threads):
    """:func:`march` with the states shared among ``threads`` blocks run in parallel.

    ``threads`` is ``numba.get_num_threads()`` of the caller (called here, it would keep numba
    from caching). Each block allocates its scratch once, so the cost per state is the cells'
    arithmetic; each state is marched by one thread, so the result does not depend on ``threads``.
    """
    n_states = xi.size
    n_y = shape.shape[1]
    for block in numba.prange(threads):
        work = np.empty((11, n_y))
        for s in range(block * n_states // threads, (block + 1) * n_states // threads):
            _march_state(
                s, xi, eta, phi, a, b, l1, l2, l3, limit, eta_y, root, shape, work, forces, out, stick
            )
