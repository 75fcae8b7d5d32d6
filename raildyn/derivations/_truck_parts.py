"""The parts the lateral truck derivations of :mod:`raildyn.derivations.trucks` are built from.

A parameter registry that remembers where each model holds its value, a wheelset on the rails (its
inertia and the wheel–rail forces by virtual work), an element (spring and damper across a
deflection), a truck as a set of parts, a car body (lateral, yaw, roll) on two trucks, and the
assembly of the parts' energies and forces into a :class:`~raildyn.derivations.Derivation` by
Lagrange's equations. The trucks themselves (three-piece, three-axle) and the vehicles on them are
in :mod:`raildyn.derivations.trucks`.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import sympy
from sympy.core.function import AppliedUndef

from raildyn.constants import GRAVITY
from raildyn.derivations._core import Derivation, Step, coordinates, lagrange, time
from raildyn.derivations._wheel_rail import (
    RAIL_HALF_SPACING,
    RAIL_PAIR,
    WheelsetSymbols,
    linear,
    wheel_rail,
    wheelset_symbols,
)


class _Parameters:
    """The parameter symbols of one derivation, each with where its model holds the value."""

    def __init__(self):
        self.pairs = []

    def __call__(self, name: str, source) -> sympy.Symbol:
        # No assumptions (positive, ...): sympy would query them at every derivative, and they change
        # nothing in equations that are polynomials of the parameters.
        symbol = sympy.Symbol(name)
        self.pairs.append((symbol, source))
        return symbol


def _attribute(path: str, scale: float = 1.0):
    """A getter of a dotted attribute of the model, times ``scale`` (ω = 2π f)."""
    names = path.split(".")
    return lambda model: scale * functools.reduce(getattr, names, model)


def _wheelset_symbols(p: _Parameters, prefix: str) -> WheelsetSymbols:
    """The wheelset's symbols, read from ``prefix + field`` and registered with ``p``."""
    w, pairs = wheelset_symbols(prefix.rstrip("."))
    p.pairs.extend(pairs)
    return w


def _wheelset_steps(y, psi, ya, c, w, V) -> tuple:
    """Steps showing the left wheel's creepages and the wheelset's generalized forces."""
    Q, kin = wheel_rail(y, psi, ya, c, w, V)
    variables = [y, psi, ya, c]
    gx, gy, phi = sympy.symbols(r"\gamma_{xL} \gamma_y \varphi")
    return (
        Step("longitudinal creepage of the left wheel", sympy.Eq(gx, linear(kin["gx"], variables))),
        Step("lateral creepage (both wheels)", sympy.Eq(gy, linear(kin["gy"], variables))),
        Step("spin creepage (both wheels)", sympy.Eq(phi, kin["spin"])),
        Step("contact angle of the left wheel", sympy.Eq(sympy.Symbol(r"\vartheta_L"), kin["angle"])),
        Step(
            "Kalker's linear law on the left wheel",
            sympy.Eq(
                sympy.Matrix(sympy.symbols("F_xL F_yL M_zL")),
                sympy.Matrix([-w.f11 * gx, -w.f22 * gy - w.f23 * phi, w.f23 * gy - w.f33 * phi]),
            ),
        ),
        Step(
            "wheel–rail lateral force on the leading wheelset (virtual work, linearised)",
            sympy.Eq(sympy.Symbol("Q_{y1}"), Q[y]),
        ),
        Step(
            "wheel–rail yaw moment on the leading wheelset (virtual work, linearised)",
            sympy.Eq(sympy.Symbol(r"Q_{\psi1}"), Q[psi]),
        ),
    )


@dataclass(frozen=True)
class _Part:
    """One part's contribution to the equations: its T, U, D and generalized forces ((coordinate, Q), ...)."""

    T: object = 0
    U: object = 0
    D: object = 0
    forces: tuple = ()


def _element(k, c, deflection) -> _Part:
    """A spring k and a damper c across ``deflection``: U = k u²/2, D = c u̇²/2."""
    return _Part(U=k * deflection**2 / 2, D=c * deflection.diff(time) ** 2 / 2)


def _wheelset(y, psi, ya, c, w: WheelsetSymbols, V) -> _Part:
    """A wheelset on the rails: its inertia and the wheel–rail forces (``_wheel_rail.wheel_rail``)."""
    Q, _ = wheel_rail(y, psi, ya, c, w, V)
    return _Part(T=w.m * y.diff(time) ** 2 / 2 + w.I * psi.diff(time) ** 2 / 2, forces=tuple(Q.items()))


@dataclass(frozen=True)
class _Truck:
    """One truck: its coordinates, its inputs (alignment, cross-level per wheelset) and its parts."""

    coords: tuple
    alignment: tuple
    cross_level: tuple
    parts: tuple


def _derive(title, coords, inputs, parts, p: _Parameters, V, steps) -> Derivation:
    """Lagrange's equations of the parts, added up, as a Derivation.

    Lagrange's equations are linear in T, U, D and Q, so each part's terms are derived on the coordinates
    and inputs it holds, and added into the matrices of the whole: the same matrices as one call on the
    sums, at a fraction of the algebra.
    """
    n, r = len(coords), len(inputs)
    M, C, K = (sympy.zeros(n, n) for _ in range(3))
    GK, GC = sympy.zeros(n, r), sympy.zeros(n, r)
    for part in parts:
        exprs = [part.T, part.U, part.D, *(f for _, f in part.forces)]
        found = set().union(*(sympy.sympify(e).atoms(AppliedUndef) for e in exprs))
        local = [q for q in coords if q in found]
        local_inputs = [u for u in inputs if u in found]
        if not local:
            continue
        # The part in coordinates q0, q1, ... and inputs w0, w1, ...: parts alike but for their
        # coordinates (every wheelset, every yaw spring) are then derived once.
        generic = coordinates(" ".join(f"q{i}" for i in range(len(local))))
        generic_inputs = (
            coordinates(" ".join(f"w{j}" for j in range(len(local_inputs)))) if local_inputs else ()
        )
        rename = dict(zip(local + local_inputs, generic + generic_inputs, strict=True))
        forces = dict(part.forces)
        key = tuple(sympy.sympify(e).xreplace(rename) for e in (part.T, part.U, part.D))
        Q = tuple(sympy.sympify(forces.get(q, 0)).xreplace(rename) for q in local)
        m, c, k, gk, gc = _lagrange(key, Q, generic, generic_inputs)
        i = [coords.index(q) for q in local]
        j = [inputs.index(u) for u in local_inputs]
        for a, ia in enumerate(i):
            for b, ib in enumerate(i):
                M[ia, ib] += m[a, b]
                C[ia, ib] += c[a, b]
                K[ia, ib] += k[a, b]
            for b, jb in enumerate(j):
                GK[ia, jb] += gk[a, b]
                GC[ia, jb] += gc[a, b]
    # Parts' terms that cancel (a cross term of two motors' shares, say) cancel on collection.
    M, C, K, GK, GC = (m.applyfunc(_collect) for m in (M, C, K, GK, GC))
    return Derivation(
        title=title,
        coordinates=tuple(coords),
        inputs=tuple(inputs),
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=(*p.pairs, RAIL_PAIR),
        speed=V,
        steps=tuple(steps),
    )


def _collect(entry):
    """One entry of the assembled matrices, its like terms gathered (a sum that cancels becomes 0)."""
    if not isinstance(entry, sympy.Add):
        return entry
    expanded = sympy.expand(entry)
    return expanded if sympy.count_ops(expanded) < sympy.count_ops(entry) else entry


@functools.cache
def _lagrange(energies: tuple, forces: tuple, coords: tuple, inputs: tuple) -> tuple:
    """:func:`~raildyn.derivations.lagrange` of one part, cached on its energies, forces and coordinates."""
    T, U, D = energies
    return lagrange(T, U, D, coords, forces=sympy.Matrix(forces), inputs=inputs)


def _energy_steps(parts) -> tuple:
    """T, U and D of the whole, the sums of its parts'."""
    T, U, D = (sum((getattr(part, name) for part in parts), sympy.Integer(0)) for name in "TUD")
    return (
        Step("kinetic energy", sympy.Eq(sympy.Symbol("T"), T)),
        Step("potential energy", sympy.Eq(sympy.Symbol("U"), U)),
        Step("Rayleigh's dissipation function", sympy.Eq(sympy.Symbol("D"), D)),
    )


def _speed() -> sympy.Symbol:
    return sympy.Symbol("V")


def _leading_wheelset_steps(truck: _Truck, w: WheelsetSymbols, V) -> tuple:
    y, psi = truck.coords[-4:-2] if len(truck.coords) == 7 else truck.coords[2:4]
    return _wheelset_steps(y, psi, truck.alignment[0], truck.cross_level[0], w, V)


@dataclass(frozen=True)
class _BodySymbols:
    m: sympy.Symbol
    Ipsi: sympy.Symbol
    Iphi: sympy.Symbol
    l: sympy.Symbol
    h: sympy.Symbol
    kphi: sympy.Symbol
    cphi: sympy.Symbol
    g: sympy.Symbol


def _body_symbols(p: _Parameters) -> _BodySymbols:
    return _BodySymbols(
        m=p("m", "body_mass"),
        Ipsi=p("I_z", "body_yaw_inertia"),
        Iphi=p("I_x", "body_roll_inertia"),
        l=p("l", "semi_truck_spacing"),
        h=p("h", "body_height"),
        kphi=p("k_phi", "roll_stiffness"),
        cphi=p("c_phi", "roll_damping"),
        g=p("g", lambda model: GRAVITY),
    )


def _body(B: _BodySymbols, trucks, a) -> tuple:
    """The body's coordinates and parts: its inertia, its weight h above the seats, the roll springs.

    Each truck's seats tilt with the mean cross-level Δz̄ of its wheelsets, by Δz̄/(2a_r) (2a_r the rail
    spacing), so the roll spring and damper of a truck act on φ − Δz̄/(2a_r).
    """
    y, psi, phi = coordinates("y psi phi")
    parts = [
        _Part(
            T=B.m * y.diff(time) ** 2 / 2
            + B.Ipsi * psi.diff(time) ** 2 / 2
            + B.Iphi * phi.diff(time) ** 2 / 2,
            # The centre of gravity h above the seats, about which the body rolls.
            U=B.m * B.g * B.h * sympy.cos(phi),
        )
    ]
    for truck in trucks:
        mean = sum(truck.cross_level) / len(truck.cross_level)
        parts.append(_element(B.kphi, B.cphi, phi - mean / (2 * RAIL_HALF_SPACING)))
    return (y, psi, phi), parts


def _seat(body_coords, x, B: _BodySymbols):
    """The lateral displacement of the body's point x ahead of its centre, h below its centre of gravity."""
    y, psi, phi = body_coords
    return y + x * psi + B.h * phi


def _vehicle(title, truck_symbols, build, B, p, V) -> Derivation:
    """A body on two trucks built by ``build(symbols, tag, seat, body yaw, V)``, derived."""
    body = coordinates("y psi phi")
    trucks = []
    for tag, x in (("1", B.l), ("2", -B.l)):
        truck = build(truck_symbols, tag, _seat(body, x, B), body[1], V)
        trucks.append(truck)
    body, body_parts = _body(B, trucks, truck_symbols.w.a)
    coords = body + sum((t.coords for t in trucks), ())
    inputs = sum((t.alignment for t in trucks), ()) + sum((t.cross_level for t in trucks), ())
    parts = tuple(body_parts) + sum((t.parts for t in trucks), ())
    steps = (
        Step(
            "lateral displacement of the leading truck's seat on the body",
            sympy.Eq(sympy.Symbol("y_{c1}"), _seat(body, B.l, B)),
        ),
        *_energy_steps(parts),
    )
    return _derive(title, coords, inputs, parts, p, V, steps)
