"""Chapter 9's coupler chain derived: n vehicles joined by draft gears, linearised beyond the slack.

The train of :mod:`raildyn.train.longitudinal` is nonlinear: each coupler has a free gap (the slack
e) and a friction draft gear whose loading and unloading branches differ. Once the slack of every
coupler has closed and each gear is being loaded further, the coupler is a linear spring of the
loading stiffness k_l, and the train moves as a chain of masses and springs, damped by the part of
its running resistance that grows with speed. :func:`coupler_chain` derives that chain by
Lagrange's equations (:func:`raildyn.derivations.lagrange`); the tests hold it to the Jacobian of
:meth:`raildyn.train.TrainModel.rhs` at a state where every coupler is loaded beyond its slack.
"""

from __future__ import annotations

import functools

import sympy

from raildyn import _checks
from raildyn.derivations._core import Derivation, Step, coordinates, generalized_forces, lagrange, time

__all__ = ["coupler_chain"]


def coupler_chain(count: int = 3) -> Derivation:
    """n vehicles in a line, joined by couplers loaded beyond their slack, resisted by Davis's law.

    Vehicle i (0 at the front) of mass m_i runs at the speed V + ẋ_i, where x_i is its
    displacement from a reference motion at the train's speed V. Coupler i, behind vehicle i, has
    the extension Δx_i = Δx_i⁰ + x_i − x_{i+1} (Δx_i⁰ its value in the reference motion); beyond
    the slack e its draft gear deflects by u_i = Δx_i − e/2 in draft (−Δx_i − e/2 in buff) and,
    while it is being loaded further, pushes back with the loading stiffness k_i (Cole 2006;
    :class:`raildyn.train.DraftGear`), storing U_i = ½ k_i u_i². Each vehicle is held back by
    the Davis resistance R_i = A_i + B_i v + C_i v² at its speed v (Davis 1926; book ch. 9),
    which works through x_i. Lagrange's equations about the reference motion give

        m_i ẍ_i + (B_i + 2 C_i V) ẋ_i + k_{i−1}(x_i − x_{i−1}) + k_i(x_i − x_{i+1}) = 0,

    the constant forces (the couplers' preload, A_i + B_i V + C_i V²) setting the reference motion
    and dropping out of the equations for x.

    Parameters
    ----------
    count : int
        n, the number of vehicles, in [2, 8] (the symbolic algebra grows as n²: 4 s at 8).

    Returns
    -------
    Derivation
        Coordinates x_0 … x_{n−1} (m); speed V (m/s); parameters read from a
        :class:`raildyn.train.TrainModel`: m_i from ``consist.mass``, k_i from
        ``gear.loading_stiffness``, B_i and C_i from ``davis_coefficients`` (rows 1 and 2).

    Examples
    --------
    >>> d = coupler_chain(2)
    >>> d.K
    Matrix([
    [ k_0, -k_0],
    [-k_0,  k_0]])
    """
    n = _checks.integer("count", count, low=2, high=8)
    return _coupler_chain(n)


@functools.cache  # the checked count only
def _coupler_chain(n: int) -> Derivation:
    x = coordinates(" ".join(f"x_{i}" for i in range(n)))
    xd = [xi.diff(time) for xi in x]
    V = sympy.Symbol("V", positive=True)
    e = sympy.Symbol("e", nonnegative=True)
    ms = sympy.symbols(f"m_0:{n}", positive=True)
    ks = sympy.symbols(f"k_0:{n - 1}", positive=True)
    A = sympy.symbols(f"A_0:{n}", nonnegative=True)
    B = sympy.symbols(f"B_0:{n}", nonnegative=True)
    C = sympy.symbols(f"C_0:{n}", nonnegative=True)
    reference = sympy.symbols(f"Δx_0:{n - 1}__0", positive=True)  # Δx_i⁰, beyond the slack in draft
    extension = [reference[i] + x[i] - x[i + 1] for i in range(n - 1)]
    deflection = [dx - e / 2 for dx in extension]  # in draft; in buff u = −Δx − e/2, the same k
    speed = [V + v for v in xd]
    resistance = [A[i] + B[i] * speed[i] + C[i] * speed[i] ** 2 for i in range(n)]

    T = sum(m * v**2 for m, v in zip(ms, speed, strict=True)) / 2
    U = sum(k * u**2 for k, u in zip(ks, deflection, strict=True)) / 2
    Q = generalized_forces([(-R, xi) for R, xi in zip(resistance, x, strict=True)], x)
    M, Cm, K, GK, GC = lagrange(T, U, 0, x, forces=Q)

    def davis(row, i):
        return lambda model: model.davis_coefficients[row, i]

    def mass(i):
        return lambda model: model.consist.mass[i]

    parameters = (
        tuple((s, mass(i)) for i, s in enumerate(ms))
        + tuple((s, "gear.loading_stiffness") for s in ks)
        + tuple((s, davis(1, i)) for i, s in enumerate(B))
        + tuple((s, davis(2, i)) for i, s in enumerate(C))
    )
    v = sympy.Symbol("v")
    return Derivation(
        title=f"coupler chain of {n} vehicles (draft gears loaded beyond the slack)",
        coordinates=x,
        M=M,
        C=Cm,
        K=K,
        GK=GK,
        GC=GC,
        parameters=parameters,
        speed=V,
        steps=(
            Step("coupler extension", sympy.Eq(sympy.Symbol("Δx_0"), extension[0])),
            Step(
                "draft-gear deflection beyond the slack (draft)", sympy.Eq(sympy.Symbol("u_0"), deflection[0])
            ),
            Step("Davis resistance", sympy.Eq(sympy.Function("R_0")(v), A[0] + B[0] * v + C[0] * v**2)),
            Step("kinetic energy", sympy.Eq(sympy.Symbol("T"), T)),
            Step("potential energy of the draft gears", sympy.Eq(sympy.Symbol("U"), U)),
            Step(
                "generalized forces of the resistance (virtual work)",
                sympy.Eq(sympy.Matrix(sympy.symbols(f"Q_0:{n}")), Q, evaluate=False),
            ),
        ),
    )
