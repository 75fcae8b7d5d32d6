"""Chapter 1's models derived: the oscillator on a moving base, and a chain of masses and springs.

Both by Lagrange's equations (:func:`raildyn.derivations.lagrange`) from their energies; the tests
hold them to :class:`raildyn.vibration.SDOF` and :func:`raildyn.vibration.chain_matrices`.
"""

from __future__ import annotations

import functools

import sympy

from raildyn import _checks
from raildyn.derivations._core import Derivation, Step, coordinates, lagrange, time

__all__ = ["chain", "sdof"]


@functools.cache
def sdof() -> Derivation:
    """The oscillator of book eq. 1.3 on a base that moves by y(t) (chapter 1's base excitation).

    T = ½ m ẋ², U = ½ k (x − y)², D = ½ c (ẋ − ẏ)² give m ẍ + c ẋ + k x = k y + c ẏ.

    Returns
    -------
    Derivation
        Parameters read from a :class:`raildyn.vibration.SDOF` (``mass``, ``damping``, ``stiffness``).

    Examples
    --------
    >>> from raildyn.vibration import SDOF
    >>> d = sdof()
    >>> d.difference(([[1000.0]], [[2000.0]], [[4e5]], [[4e5]], [[2000.0]]), SDOF(1000.0, 2000.0, 4e5))
    0.0
    """
    m, c, k = sympy.symbols("m c k", positive=True)
    (x,) = coordinates("x")
    (y,) = coordinates("y")
    xd, yd = x.diff(time), y.diff(time)
    T = m * xd**2 / 2
    U = k * (x - y) ** 2 / 2
    D = c * (xd - yd) ** 2 / 2
    M, C, K, GK, GC = lagrange(T, U, D, [x], inputs=[y])
    return Derivation(
        title="single-degree-of-freedom oscillator on a moving base",
        coordinates=(x,),
        inputs=(y,),
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=((m, "mass"), (c, "damping"), (k, "stiffness")),
        steps=(
            Step("kinetic energy", sympy.Eq(sympy.Symbol("T"), T)),
            Step("potential energy of the spring", sympy.Eq(sympy.Symbol("U"), U)),
            Step("Rayleigh's dissipation function", sympy.Eq(sympy.Symbol("D"), D)),
        ),
    )


def chain(count: int = 3, grounded: bool = True) -> Derivation:
    """n masses in a line joined by springs and dampers (book §1's multi-degree-of-freedom system).

    Spring j (damper j beside it) joins mass j − 1 to mass j; with ``grounded`` spring 0 ties
    mass 0 to the ground, as :func:`raildyn.vibration.chain_matrices` numbers them.

    Parameters
    ----------
    count : int
        n, the number of masses, in [1, 12] (the symbolic matrices grow as n²).
    grounded : bool
        Whether spring 0 ties mass 0 to the ground (fixed–free) or the chain floats (free–free).

    Returns
    -------
    Derivation
        Parameters read from a dict with arrays ``masses``, ``stiffnesses`` and ``dampings``.
    """
    n = _checks.integer("count", count, low=1, high=12)
    grounded = _checks.flag("grounded", grounded)
    if not grounded and n < 2:
        raise ValueError(f"count must be at least 2 for a free-free chain (one spring), got {count!r}")
    return _chain(n, grounded)


@functools.cache  # the checked arguments only: a cache cannot hash a list a caller passes by mistake
def _chain(n: int, grounded: bool) -> Derivation:
    x = coordinates(" ".join(f"x{i + 1}" for i in range(n)))
    ms = sympy.symbols(f"m1:{n + 1}", positive=True)
    springs = n if grounded else n - 1
    ks = sympy.symbols(f"k1:{springs + 1}", positive=True)
    cs = sympy.symbols(f"c1:{springs + 1}", nonnegative=True)
    xd = [xi.diff(time) for xi in x]
    # Spring j stretches by x_j − x_{j−1} (grounded: spring 0 by x_0 alone).
    stretch = (
        [x[0]] + [x[i] - x[i - 1] for i in range(1, n)]
        if grounded
        else [x[i] - x[i - 1] for i in range(1, n)]
    )
    rate = [s.diff(time) for s in stretch]
    T = sum(mi * v**2 for mi, v in zip(ms, xd, strict=True)) / 2
    U = sum(kj * s**2 for kj, s in zip(ks, stretch, strict=True)) / 2
    D = sum(cj * r**2 for cj, r in zip(cs, rate, strict=True)) / 2
    M, C, K, GK, GC = lagrange(T, U, D, x)

    def item(field, i):
        return lambda p: p[field][i]

    parameters = (
        tuple((s, item("masses", i)) for i, s in enumerate(ms))
        + tuple((s, item("stiffnesses", i)) for i, s in enumerate(ks))
        + tuple((s, item("dampings", i)) for i, s in enumerate(cs))
    )
    return Derivation(
        title=f"chain of {n} masses ({'fixed–free' if grounded else 'free–free'})",
        coordinates=x,
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=parameters,
        steps=(
            Step("kinetic energy", sympy.Eq(sympy.Symbol("T"), T)),
            Step("potential energy of the springs", sympy.Eq(sympy.Symbol("U"), U)),
            Step("Rayleigh's dissipation function", sympy.Eq(sympy.Symbol("D"), D)),
        ),
    )
