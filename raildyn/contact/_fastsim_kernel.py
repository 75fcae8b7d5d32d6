"""FASTSIM's march over the cells of every contact state, compiled with numba.

:func:`raildyn.contact.fastsim.fastsim` checks its input, computes the flexibilities,
the pressure normalisation and the scaling of huge creepages with numpy (a few
operations per state), then calls :func:`march` here for the cells, the part that
grows as S × n_y × n_x. ``_fastsim_numpy`` in that module is the numpy march this
replaces; ``tests/test_fastsim_kernel.py`` holds the two equal to 1e-12 of the largest force.

The loops run over states, then cells along x, then strips across: the strips of one
state are independent, so the innermost loop has no carried dependency and the
compiler issues the strips' square roots and divisions side by side (vectorized four
wide with AVX2). Marching one strip to its end instead chains each cell on the previous
one, and a sliding cell's chain (multiply, square root, divide, multiply: some 45
cycles) would then set the pace. Every division and every per-strip constant is taken
out of the cell loop; the forces are summed per strip and multiplied by the cell area
once per strip. ``fastmath`` is off: it would let the compiler reorder the sums and
replace the division and square root by approximations, and the tests ask for 1e-12.

The slide test compares squares, t_x² + t_y² > (μp)², and takes a square root and a
division only where the cell slides. That is the numpy test |t| > μp but for the last
bit of |t|, where the cap is 1 to rounding either way. It needs the squares to stay
within floating-point range, which the scaling of huge creepages (``_within_sliding``)
ensures for any bound μp₀ between 1e-100 and 1e100 Pa; a state outside that range (an
absurd μ or load) is marched with ``math.hypot`` as in numpy.

Operations per cell, counted in the inner loop of :func:`_march_state` (forces only):
x = h − (k + ½)Δx (1 multiply-add), the two traction increments (t_x: 1 multiply, 1
subtract; t_y: 4 multiplies or adds, 2 subtracts), the bound μp (1 multiply), the slide
test (3 multiplies, 1 add, 1 compare), the cap where it slides (1 square root, 1
division, 2 multiplies), and the sums of p_x, p_y and x p_y (3 adds, 1 multiply): about
20 floating-point operations in adhesion, 24 in slip, with one square root and one
division. Measured on this machine (AMD EPYC, Zen 3, 2 cores at 2.45 GHz, 10⁴ random
states on 20 × 20 cells, mostly sliding cells): about 0.5 µs per contact on one thread
(8 × 10⁸ cells/s, about 3 cycles per cell; the numpy march took 10 to 13 µs). Dependent scalar code
issues about one floating-point operation per cycle, which would allow ~1.2 × 10⁸
cells/s at 20 operations per cell; independent strips let the core's two or four
floating-point pipes and its four-wide vectors work at once, so the kernel runs
several times faster than that scalar bound. Its real ceiling is the vector square
root and division of sliding cells (one four-wide square root per ~9 cycles and one
division per ~5 on Zen 3, i.e. ~3.5 cycles per sliding cell), which it is close to.
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


@numba.njit(cache=True, parallel=True)
def march(xi, eta, phi, a, b, l1, l2, l3, limit, eta_y, root, shape, forces, out, stick, threads):
    """FASTSIM's march for S states (1-D arrays of length S), in parallel over blocks of states.

    ``shape`` is (n_x, n_y), cell-major; ``forces`` (3, S) receives F_x, F_y (N) and M_z (N m);
    ``out`` and ``stick`` the fields, or None (see :func:`_march_state`). ``threads`` is
    ``numba.get_num_threads()`` of the caller (called here, it would keep numba from caching).
    Each thread's block allocates its scratch once, so the cost per state is the cells' arithmetic.
    """
    n_states = xi.size
    n_y = shape.shape[1]
    blocks = min(threads, max(n_states, 1))
    for block in numba.prange(blocks):
        work = np.empty((11, n_y))
        for s in range(block * n_states // blocks, (block + 1) * n_states // blocks):
            _march_state(
                s, xi, eta, phi, a, b, l1, l2, l3, limit, eta_y, root, shape, work, forces, out, stick
            )
