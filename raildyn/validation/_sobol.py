"""The sums of :func:`raildyn.validation.uncertainty.sobol_indices`: the indices and their bootstrap.

Given the model's outputs on A, B and the d matrices A_B⁽ⁱ⁾, the first-order index is
Saltelli's estimator and the total index Jansen's, both centred on the outputs' mean
(Saltelli et al. 2010, Table 2). ``scipy.stats.sobol_indices`` computes exactly these
(its ``saltelli_2010`` method, centred the same way) from outputs handed to it, and is used
whenever it can be; raildyn's own lines of numpy remain where it cannot (see each function).
The module is private: :mod:`raildyn.validation.uncertainty` imports its names.
"""

from __future__ import annotations

import numpy as np

__all__ = ["bootstrap_intervals", "estimators", "indices"]

#: Bootstrap values held at once (about 32 MB of float64), whatever N and d.
_BOOTSTRAP_VALUES = 4_000_000


def indices(fA, fB, fAB) -> tuple:
    """S_i and S_Ti, each of shape (d,), from ``fA`` and ``fB`` of shape (N,) and ``fAB`` of shape (d, N).

    scipy's ``sobol_indices`` for a power-of-two N; for another N raildyn's :func:`estimators`
    (the same sums), because scipy refuses such an N even when given the outputs (it checks
    the balance of its own Sobol' points whether or not it drew them).
    """
    N = fA.size
    if N & (N - 1):
        first, total, _ = estimators(fA, fB, fAB)
        return first, total
    from scipy.stats import sobol_indices

    res = sobol_indices(func={"f_A": fA[None], "f_B": fB[None], "f_AB": fAB[:, None]}, n=N)
    return np.atleast_1d(res.first_order), np.atleast_1d(res.total_order)


def estimators(fA, fB, fAB):
    """S_i by Saltelli's estimator and S_Ti by Jansen's (Saltelli et al. 2010, Table 2), centred, and σ_Y².

    ``fA`` and ``fB`` have shape (..., N); ``fAB`` has shape (d, ..., N). Returns arrays of
    shape (d, ...) and the variance of shape (...). The bootstrap needs them over many
    resamples at once, which scipy's ``sobol_indices`` does not take (one sample per call).
    """
    both = np.concatenate([fA, fB], axis=-1)
    variance = np.var(both, axis=-1)
    # Centred first: f(B) multiplies a difference whose mean is S_i V, so an output's mean f0
    # adds f0 (f(A_B) − f(A)), zero on average but with f0² times its variance to the estimate
    # (a critical speed of 78 ± 1 m/s would drown its indices in noise).
    mean = both.mean(axis=-1, keepdims=True)
    first = np.mean((fB - mean) * (fAB - fA), axis=-1) / variance
    total = 0.5 * np.mean((fA - fAB) ** 2, axis=-1) / variance
    return first, total, variance


def bootstrap_intervals(fA, fB, fAB, gen, resamples: int, level: float) -> tuple:
    """Bootstrap percentile intervals (Efron & Tibshirani 1993, ch. 13) of S_i and S_Ti, each (d, 2).

    The N rows are resampled ``resamples`` times (the same rows for A, B and every A_B⁽ⁱ⁾)
    with draws from ``gen``. Not scipy's ``SobolResult.bootstrap``: it passes no seed to
    ``scipy.stats.bootstrap``, so its intervals would change from run to run, and its BCa
    intervals add a jackknife of N evaluations of the estimators.
    """
    d, N = fAB.shape
    rows_per_chunk = max(1, _BOOTSTRAP_VALUES // (N * (d + 2)))  # resamples at once: bounded memory
    boot_first, boot_total = [], []
    for start in range(0, resamples, rows_per_chunk):
        idx = gen.integers(0, N, size=(min(rows_per_chunk, resamples - start), N))
        with np.errstate(divide="ignore", invalid="ignore"):  # a resample of equal rows: NaN, left out
            s, t, _ = estimators(fA[idx], fB[idx], fAB[:, idx])
        boot_first.append(s)
        boot_total.append(t)
    tail = 50.0 * (1.0 - level)
    q = (tail, 100.0 - tail)
    boot_first, boot_total = np.concatenate(boot_first, axis=-1), np.concatenate(boot_total, axis=-1)
    kept = np.isfinite(boot_first).all(axis=0) & np.isfinite(boot_total).all(axis=0)
    if kept.sum() < 10:
        raise ValueError(
            f"samples = {N} is too few for a bootstrap: the output varies in fewer than 10 of "
            f"{resamples} resamples"
        )
    return np.percentile(boot_first[:, kept], q, axis=-1).T, np.percentile(boot_total[:, kept], q, axis=-1).T
