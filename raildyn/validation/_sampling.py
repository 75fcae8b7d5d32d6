"""Drawing the samples of :mod:`raildyn.validation.uncertainty`: pseudo-random, or quasi-random.

``"random"`` draws each parameter by its distribution's ``rvs`` from the seed; ``"sobol"`` and
``"halton"`` take the points of a scrambled Sobol' or Halton sequence (``scipy.stats.qmc``,
scrambled from the same seed) in the unit cube and send each coordinate through its
distribution's inverse CDF (``ppf``), so that any frozen scipy distribution serves. The module
is private: :mod:`raildyn.validation.uncertainty` imports its names.

Scrambled Sobol' points are balanced (each dyadic box of the cube holds its share of points)
over 2^m points only; a study of another number of points loses the property, and with it most
of the gain in accuracy that is the reason to choose them. A student who asks for 1000 points
gets a message naming 512 and 1024 (and Halton, which takes any number) rather than a study
of a size other than the one asked for.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks

__all__ = ["SAMPLINGS", "check", "draw"]

#: The ways of drawing the samples.
SAMPLINGS = ("random", "sobol", "halton")


def check(sampling, distributions, names, n) -> str:
    """``sampling`` checked against the distributions and the number of points n; returned."""
    _checks.choice("sampling", sampling, SAMPLINGS)
    if sampling == "random":
        return sampling
    for name in names:
        if not callable(getattr(distributions[name], "ppf", None)):
            raise TypeError(
                f"distributions[{name!r}] must have a ppf (inverse CDF) for sampling={sampling!r}, got "
                f"{distributions[name]!r:.80}; give a frozen scipy.stats distribution or sampling='random'"
            )
    if sampling == "sobol" and n & (n - 1):
        below = 1 << (n.bit_length() - 1)
        raise ValueError(
            f"samples must be a power of two for sampling='sobol' (scrambled Sobol' points are balanced "
            f"over 2^m points only), got {n}; use {below} or {2 * below}, or sampling='halton' for any number"
        )
    return sampling


def draw(distributions, names, n, gen, sampling, blocks: int = 1) -> np.ndarray:
    """n points in ``blocks`` independent blocks of one column per name: shape (n, blocks · d).

    Column j holds parameter ``names[j % d]``. Pseudo-random draws come block by block, column
    by column, from ``gen``; quasi-random ones are one sequence of dimension blocks · d (its
    columns are independent, which is how Saltelli et al. 2010, section 5, make the two base
    samples of the Sobol' indices from one Sobol' sequence), scrambled from ``gen``.
    """
    d = len(names)
    if sampling == "random":
        return np.column_stack([_rvs(distributions, name, n, gen) for _ in range(blocks) for name in names])
    from scipy.stats import qmc

    if sampling == "sobol":
        # 64 bits: the points are multiples of 2^-64, so none is exactly 0 (where an unbounded
        # distribution's ppf is −inf) but with a chance of n 2^-64 per column.
        engine = qmc.Sobol(blocks * d, scramble=True, bits=64, rng=gen)
    else:
        engine = qmc.Halton(blocks * d, scramble=True, rng=gen)
    U = engine.random(n)
    X = np.empty_like(U)
    for j in range(blocks * d):
        name = names[j % d]
        try:
            X[:, j] = distributions[name].ppf(U[:, j])
        except (TypeError, ValueError) as err:
            raise ValueError(f"distributions[{name!r}] could not be sampled through its ppf: {err}") from err
        _finite(name, X[:, j])
    return X


def _rvs(distributions, name, n, gen) -> np.ndarray:
    """n pseudo-random draws of one parameter."""
    try:
        values = np.asarray(distributions[name].rvs(size=n, random_state=gen), dtype=float)
    except (TypeError, ValueError) as err:
        raise ValueError(f"distributions[{name!r}] could not be sampled: {err}") from err
    if values.shape != (n,):
        raise ValueError(
            f"distributions[{name!r}] must be a scalar distribution; rvs(size={n}) gave shape {values.shape}"
        )
    _finite(name, values)
    return values


def _finite(name, values) -> None:
    if not np.isfinite(values).all():
        k = int(np.flatnonzero(~np.isfinite(values))[0])
        raise ValueError(f"distributions[{name!r}] drew a non-finite value {values[k]!r} (draw {k})")
