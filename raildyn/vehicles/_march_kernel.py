"""The compiled recurrence of :func:`raildyn.vehicles.time_response`: x[i] = x[i − 1] A_d + F[i − 1].

Apart from :mod:`raildyn.vehicles.time_domain`, which imports it where it runs, so that importing the
vehicles does not load numba (tests/test_imports.py).
"""

from __future__ import annotations

import numba

__all__ = ["march"]


@numba.njit(cache=True)
def march(Ad, F, x):
    """x[i] = x[i − 1] A_d + F[i − 1] for i = 1 … n_steps − 1, in place (states as rows)."""
    n = x.shape[1]
    for i in range(1, x.shape[0]):
        for k in range(n):
            total = F[i - 1, k]
            for j in range(n):
                total += x[i - 1, j] * Ad[j, k]
            x[i, k] = total
