"""Banded symmetric solves, compiled: the discrete track's receptance and the wheel's time march.

A rail on sleepers, numbered node by node (each rail node's deflection and rotation, then the
sleeper under it, if any), gives mass, damping and stiffness matrices whose entries lie within a few
places of the diagonal. Stored by diagonals (``ab[k, j] = A[j + k, j]``, k = 0 … p), such a matrix
factors as L D Lᵀ in O(n p²) and solves in O(n p), where a dense solve costs O(n³): what makes 2,000
frequencies, or 100,000 time steps, of a 500-unknown track cheap. The same functions serve real
matrices (the march's effective stiffness) and complex symmetric ones (K − ω²M + iωC; symmetric, not
Hermitian, so no conjugates), numba compiling one version for each. No pivoting: both kinds are
dominated by their diagonals (a positive-definite stiffness and mass; damping only adds to it),
and :func:`raildyn.bridge.sleepers.DiscreteTrack.receptance` tests the factor's diagonal.
Nothing here checks its arguments; its callers do.
"""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["band_factor", "band_solve", "band_receptance"]


@numba.njit(cache=True)
def band_factor(ab):
    """Factor ``ab`` (by diagonals, p + 1 rows) in place into L D Lᵀ: D on row 0, L below."""
    p, n = ab.shape[0] - 1, ab.shape[1]
    v = np.empty(p + 1, dtype=ab.dtype)  # v[j - k] = L[j,k] d_k: each product made once a column
    for j in range(n):
        for k in range(max(0, j - p), j):  # d_j -= L[j,k]² d_k
            v[j - k] = ab[j - k, k] * ab[0, k]
            ab[0, j] -= ab[j - k, k] * v[j - k]
        inverse = 1.0 / ab[0, j]  # one division a column (complex division is dear)
        for i in range(j + 1, min(n, j + p + 1)):
            s = ab[i - j, j]
            for k in range(max(0, i - p), j):  # L[i,j] -= L[i,k] L[j,k] d_k
                s -= ab[i - k, k] * v[j - k]
            ab[i - j, j] = s * inverse


@numba.njit(cache=True)
def band_solve(ab, b):
    """Solve (L D Lᵀ) x = b with a factor of :func:`band_factor`; b is overwritten with x."""
    p, n = ab.shape[0] - 1, ab.shape[1]
    for i in range(n):  # L y = b
        for k in range(max(0, i - p), i):
            b[i] -= ab[i - k, k] * b[k]
    for i in range(n):
        b[i] /= ab[0, i]
    for i in range(n - 1, -1, -1):  # Lᵀ x = y / d
        for k in range(i + 1, min(n, i + p + 1)):
            b[i] -= ab[k - i, i] * b[k]


@numba.njit(cache=True, parallel=True)
def band_receptance(mass, damping, stiffness, omegas, dofs, weights):
    """w/F at one point for each ω: the point's deflection per unit harmonic force there.

    ``dofs`` and ``weights`` give the deflection at the point as Σ weights·u[dofs] (and, the load being
    consistent, the force's share on each). Returns the receptances and, for each ω, the smallest
    |D| of the factor (zero would mean a singular matrix). The frequencies are independent: they
    are shared among the machine's cores.
    """
    p1, n = stiffness.shape
    out = np.empty(omegas.size, dtype=np.complex128)
    smallest = np.empty(omegas.size)
    for m in numba.prange(omegas.size):
        w = omegas[m]
        ab = np.empty((p1, n), dtype=np.complex128)
        for k in range(p1):
            for j in range(n):
                ab[k, j] = stiffness[k, j] - w * w * mass[k, j] + 1j * w * damping[k, j]
        band_factor(ab)
        smallest[m] = np.min(np.abs(ab[0]))
        b = np.zeros(n, dtype=np.complex128)
        for i in range(dofs.size):
            b[dofs[i]] += weights[i]
        band_solve(ab, b)
        s = 0.0j
        for i in range(dofs.size):
            s += weights[i] * b[dofs[i]]
        out[m] = s
    return out, smallest
