"""Chapter 10's beam derived: its modes by Lagrange, and the modal equations under a moving force or mass.

The simply supported Euler–Bernoulli beam of span L, flexural rigidity EI and mass m per unit
length deflects as w(x, t) = Σ_j φ_j(x) b_j(t) in the assumed modes φ_j = sin(jπx/L), which meet
both supports' conditions (w = w″ = 0). Its kinetic and strain energies,

    T = ½ ∫₀ᴸ m ẇ² dx,        U = ½ ∫₀ᴸ EI w″² dx,

integrated symbolically, give Lagrange's equations for the modal coordinates b_j; each mode is
damped by the ratio ξ through Rayleigh's D = Σ_j ξ ω_j μ_j ḃ_j². A force P at x = s does the
virtual work P δw(s, t), so mode j takes P φ_j(s); a mass M riding on the beam at x = Vt adds
its kinetic energy ½ M (d/dt w(Vt, t))², whose Lagrange terms are the convective ones
M φ_jφ_k, 2MV φ_jφ_k′ and MV² φ_jφ_k″ (Frýba 1972, ch. 1 and 8; Garg & Dukkipati 1984, ch. 10).

The tests hold :func:`beam_modes` to :class:`raildyn.bridge.SimplySupportedBeam` (its
``modal_masses`` and ``frequencies_hz``) and the moving loads to the matrices that the time march
of :func:`raildyn.bridge.coupled.crossing` assembles with the load at a given place.
"""

from __future__ import annotations

import functools

import sympy
from sympy.simplify.fu import TR8

from raildyn import _checks
from raildyn.derivations._core import Derivation, Step, coordinates, generalized_forces, lagrange, time

__all__ = ["beam_modes", "beam_under_moving_force", "beam_under_moving_mass"]

_MAX_MODES = 6  # the symbolic integrals take about 0.1 s a pair of modes

_x = sympy.Symbol("x", real=True)
_L = sympy.Symbol("L", positive=True)
_m = sympy.Symbol("m", positive=True)
_EI = sympy.Symbol("EI", positive=True)
_xi = sympy.Symbol("xi", nonnegative=True)
_s = sympy.Symbol("s", real=True)  # the load's position on the span
_v = sympy.Symbol("V", positive=True)  # its speed
_BEAM = (
    (_m, "beam.mass_per_length"),
    (_EI, "beam.flexural_rigidity"),
    (_L, "beam.span"),
    (_xi, "beam.damping_ratio"),
)


def _count(count) -> int:
    return _checks.integer("count", count, low=1, high=_MAX_MODES)


def _integral(f):
    """∫₀ᴸ f dx of a product of sines and cosines in x: turned into a sum of single harmonics
    (product-to-sum), each integrated once, its coefficient kept outside (fast)."""
    total = sympy.Integer(0)
    for term in sympy.Add.make_args(TR8(sympy.expand(f))):
        coefficient, harmonic = term.as_independent(_x, as_Add=False)
        total += coefficient * _harmonic_integral(harmonic)
    return sympy.simplify(total)


@functools.cache
def _harmonic_integral(harmonic):
    return sympy.integrate(harmonic, (_x, 0, _L))


@functools.cache
def _beam(n: int) -> tuple:
    """The beam's modes, coordinates, T, U, D and the steps that show them."""
    b = coordinates(" ".join(f"b_{j}" for j in range(1, n + 1)))
    bd = [bj.diff(time) for bj in b]
    phi = [sympy.sin(j * sympy.pi * _x / _L) for j in range(1, n + 1)]
    curvature = [p.diff(_x, 2) for p in phi]
    # The energies from the integrals of each product of two modes (the integrals are symmetric).
    mass = sympy.zeros(n, n)
    stiffness = sympy.zeros(n, n)
    for j in range(n):
        for k in range(j, n):
            mass[j, k] = mass[k, j] = _m * _integral(phi[j] * phi[k])
            stiffness[j, k] = stiffness[k, j] = _EI * _integral(curvature[j] * curvature[k])
    T = sum(mass[j, k] * bd[j] * bd[k] for j in range(n) for k in range(n)) / 2
    U = sum(stiffness[j, k] * b[j] * b[k] for j in range(n) for k in range(n)) / 2
    # Modal damping: each mode's ratio ξ of its own critical damping 2 √(k_j μ_j).
    D = sum(_xi * sympy.sqrt(stiffness[j, j] * mass[j, j]) * bd[j] ** 2 for j in range(n))
    w = sympy.Function("w")(_x, time)
    steps = (
        Step(
            "deflection in the assumed modes", sympy.Eq(w, sum(p * bj for p, bj in zip(phi, b, strict=True)))
        ),
        Step(
            "kinetic energy",
            sympy.Eq(sympy.Symbol("T"), sympy.Integral(_m * w.diff(time) ** 2 / 2, (_x, 0, _L))),
        ),
        Step("kinetic energy, integrated", sympy.Eq(sympy.Symbol("T"), T)),
        Step(
            "strain energy",
            sympy.Eq(sympy.Symbol("U"), sympy.Integral(_EI * w.diff(_x, 2) ** 2 / 2, (_x, 0, _L))),
        ),
        Step("strain energy, integrated", sympy.Eq(sympy.Symbol("U"), U)),
        Step("Rayleigh's dissipation function (modal damping ratio ξ)", sympy.Eq(sympy.Symbol("D"), D)),
        Step(
            "natural frequencies, ω_j = √(k_j/μ_j)",
            sympy.Eq(
                sympy.Matrix(sympy.symbols(f"omega_1:{n + 1}")),
                sympy.Matrix([sympy.sqrt(stiffness[j, j] / mass[j, j]) for j in range(n)]),
                evaluate=False,
            ),
        ),
    )
    return b, phi, T, U, D, w, steps


def beam_modes(count: int = 3) -> Derivation:
    """The simply supported beam in its first ``count`` modes, by Lagrange's equations.

    The integrals of the module docstring give the modal masses μ_j = mL/2, the modal stiffnesses
    EI (jπ/L)⁴ L/2 and so ω_j = (jπ/L)² √(EI/m) (book ch. 10; Frýba 1972, eq. 1.10); the modes
    do not couple (their integrals vanish for j ≠ k).

    Parameters
    ----------
    count : int
        n, the number of modes, in [1, 6].

    Returns
    -------
    Derivation
        Coordinates b_1 … b_n (m: the amplitude of each mode); parameters m (kg/m), EI (N·m²),
        L (m) and ξ read from an object whose ``beam`` is a
        :class:`raildyn.bridge.SimplySupportedBeam`.

    Examples
    --------
    >>> beam_modes(2).M
    Matrix([
    [L*m/2,     0],
    [    0, L*m/2]])
    """
    return _beam_modes(_count(count))


@functools.cache
def _beam_modes(n: int) -> Derivation:
    b, phi, T, U, D, w, steps = _beam(n)
    M, C, K, GK, GC = lagrange(T, U, D, b)
    return Derivation(
        title=f"simply supported beam in {n} modes",
        coordinates=b,
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=_BEAM,
        steps=steps,
    )


def beam_under_moving_force(count: int = 3) -> Derivation:
    """The beam's modal equations under a force P(t) at the place x = s on the span.

    The force P δ_D(x − s) (downwards, as w) does the virtual work P δw(s, t) = Σ_j P φ_j(s) δb_j,
    so mode j is driven by the generalized force P φ_j(s) (book ch. 10; Frýba 1972, eq. 1.12):
    with s = Vt, μ_j(b̈_j + 2ξω_j ḃ_j + ω_j² b_j) = P sin(jπVt/L).

    Parameters
    ----------
    count : int
        n, the number of modes, in [1, 6].

    Returns
    -------
    Derivation
        As :func:`beam_modes`, with the input P (N) and the force's place s (m) read from the
        object's ``position``.
    """
    return _beam_under_moving_force(_count(count))


@functools.cache
def _beam_under_moving_force(n: int) -> Derivation:
    b, phi, T, U, D, w, steps = _beam(n)
    (P,) = coordinates("P")
    deflection = sum(p * bj for p, bj in zip(phi, b, strict=True)).subs(_x, _s)
    Q = generalized_forces([(P, deflection)], b)
    M, C, K, GK, GC = lagrange(T, U, D, b, forces=Q, inputs=[P])
    return Derivation(
        title=f"simply supported beam in {n} modes under a force at x = s",
        coordinates=b,
        inputs=(P,),
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=(*_BEAM, (_s, "position")),
        steps=(
            *steps,
            Step("deflection under the force", sympy.Eq(w.subs(_x, _s), deflection)),
            Step(
                "generalized forces of the force (virtual work)",
                sympy.Eq(sympy.Matrix(sympy.symbols(f"Q_1:{n + 1}")), Q, evaluate=False),
            ),
        ),
    )


def beam_under_moving_mass(count: int = 3) -> Derivation:
    """The beam's modal equations with a mass M riding on it at the speed V, where it stands at x = s.

    The mass stays on the beam, so it moves with w(Vt, t) = Σ_j φ_j(Vt) b_j(t), at the rate
    Σ_j (φ_j ḃ_j + V φ_j′ b_j): its kinetic energy ½ M (Σ_j φ_j ḃ_j + V φ_j′ b_j)² joins the
    beam's. Lagrange's equations, written with the mass at s = Vt, give the convective terms
    M φ_jφ_k in the mass matrix, 2MV φ_jφ_k′ in the damping and MV² φ_jφ_k″ in the stiffness
    (Frýba 1972, ch. 8; book ch. 10); its weight W does the virtual work of a moving force, so
    mode j takes W φ_j(s).

    Parameters
    ----------
    count : int
        n, the number of modes, in [1, 6].

    Returns
    -------
    Derivation
        As :func:`beam_under_moving_force`, with the speed V (m/s), the input W (N, the weight)
        and M (kg) read from the object's ``load`` (a :class:`raildyn.bridge.MovingLoad` of one
        axle, its ``unsprung_masses[0]``).
    """
    return _beam_under_moving_mass(_count(count))


@functools.cache
def _beam_under_moving_mass(n: int) -> Derivation:
    b, phi, T, U, D, w, steps = _beam(n)
    (W,) = coordinates("W")
    Mc = sympy.Symbol("M", positive=True)
    # The shapes where the mass stands, φ_j(Vt), as functions of time g_j(t): by the chain rule
    # ġ_j = V φ_j′(Vt) and g̈_j = V² φ_j″(Vt). (Functions rather than sin(jπVt/L) keep the algebra
    # of Lagrange's equations light; the shapes go in once the equations are formed.)
    g = coordinates(" ".join(f"phi_{j}" for j in range(1, n + 1)))
    height = sum(gj * bj for gj, bj in zip(g, b, strict=True))
    T_mass = Mc * height.diff(time) ** 2 / 2
    Q = generalized_forces([(W, height)], b)
    matrices = lagrange(T + T_mass, U, D, b, forces=Q, inputs=[W])
    at_mass = [(gj.diff(time, 2), _v**2 * p.diff(_x, 2)) for gj, p in zip(g, phi, strict=True)]
    at_mass += [(gj.diff(time), _v * p.diff(_x)) for gj, p in zip(g, phi, strict=True)]
    at_mass += list(zip(g, phi, strict=True))
    M, C, K, GK, GC = (m.subs(at_mass).subs(_x, _s) for m in matrices)
    return Derivation(
        title=f"simply supported beam in {n} modes with a mass riding on it",
        coordinates=b,
        inputs=(W,),
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=(*_BEAM, (Mc, lambda model: model.load.unsprung_masses[0]), (_s, "position")),
        speed=_v,
        steps=(
            *steps,
            Step("height of the mass, φ_j standing for φ_j(Vt)", sympy.Eq(w.subs(_x, _v * time), height)),
            Step("kinetic energy of the mass", sympy.Eq(sympy.Symbol("T_M"), T_mass)),
            Step(
                "the shapes' rates along the path (chain rule)",
                sympy.Eq(g[0].diff(time), _v * phi[0].diff(_x).subs(_x, _v * time)),
            ),
        ),
    )
