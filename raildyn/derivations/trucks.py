"""Chapter 7's freight truck and locomotive, lateral, derived: the three-piece truck, the freight car on two
of them, the three-axle locomotive truck and the locomotive on two of those.

Each model's equations come from Lagrange's equations (:func:`raildyn.derivations.lagrange`): the kinetic
energy T of every part written from the velocities of its points, the potential energy U of every spring
from the deflection across it written in the coordinates, Rayleigh's dissipation function D of every damper,
and the wheel–rail forces as generalized forces by virtual work
(:func:`raildyn.derivations.generalized_forces`). The wheel–rail forces are built here from the kinematics
of each wheel: its creepages (Garg & Dukkipati 1984, ch. 5), Kalker's linear law per wheel
(Kalker 1967), and the lateral components of the rails' normal forces on the two coned wheels, which give
the gravitational stiffness W ε/a and the destabilising yaw term −W a ϑ₀.

The friction of the three-piece truck's wedges and centre plate enters as the viscous damper that
dissipates the same energy per cycle of the reference motion X sin ωt: π c ω X² = 4 F X, derived as a
step. The tests hold each derivation to its model in :mod:`raildyn.vehicles.three_piece` and
:mod:`raildyn.vehicles.locomotive_lateral` over random parameter sets.

Sign convention: x forward, y to the left, z up; ψ (yaw) turns x towards y, the body's roll ϕ turns y
towards z; small angles. Coordinates (names as in the derived equations; the models' labels in brackets):
side frames y_f, ψ_f (``frame y``, ``frame ψ``), bolster ψ_b (``bolster ψ``), locomotive truck frame y_T,
ψ_T (``frame y``, ``frame ψ``), wheelset k y_k, ψ_k (``wheelsetk y``, ``wheelsetk ψ``); on a vehicle the
truck's number comes first (y_f1; y_12: truck 1, wheelset 2), and the body has y, ψ, ϕ (``body y``,
``body ψ``, ``body φ``: lateral, yaw, roll). Track inputs: the alignment y_a (lateral position of the
track centre line) and the cross-level Δz (left rail height minus right rail height) at each wheelset, m,
numbered as the wheelsets (y_a12, Δz_12), in the models' order (every alignment, then every cross-level).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
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

__all__ = ["lateral_freight_car", "lateral_locomotive", "three_axle_truck", "three_piece_truck"]


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


# ---------------------------------------------------------------------------------------------------------
# One wheelset on the rails: its inertia, and the wheel-rail forces by virtual work.


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


def _equivalent_damper(F, omega, X):
    """c = 4F/(π ω X): the damper that dissipates, per cycle of X sin ωt, the energy 4 F X of friction F."""
    return 4 * F / (sympy.pi * omega * X)


def _equivalent_damper_step() -> Step:
    """The energy balance that gives the equivalent damper, integrated symbolically."""
    c, F, omega, X, t = sympy.symbols(r"c_{eq} F \omega X t", positive=True)
    period = 2 * sympy.pi / omega
    velocity = X * omega * sympy.cos(omega * t)
    damper = sympy.integrate(c * velocity**2, (t, 0, period))  # ∮ c ẋ ẋ dt
    # ∮ F |ẋ| dt: four quarter periods, each F X
    friction = 4 * sympy.integrate(F * velocity, (t, 0, period / 4))
    solved = sympy.solve(sympy.Eq(damper, friction), c)[0]
    return Step(
        "equivalent damper of a friction F: π c ω X² = 4 F X per cycle of X sin ωt",
        sympy.Eq(sympy.Symbol(r"c_{eq}"), solved),
    )


# ---------------------------------------------------------------------------------------------------------
# The three-piece truck (raildyn.vehicles.three_piece).


@dataclass(frozen=True)
class _ThreePieceSymbols:
    w: WheelsetSymbols
    mf: sympy.Symbol
    If: sympy.Symbol
    Ib: sympy.Symbol
    b: sympy.Symbol
    d: sympy.Symbol
    kw: sympy.Symbol
    ks: sympy.Symbol
    Fl: sympy.Symbol
    Mw: sympy.Symbol
    Mc: sympy.Symbol
    omega: sympy.Symbol
    X: sympy.Symbol
    Theta: sympy.Symbol


def _three_piece_symbols(p: _Parameters, prefix: str) -> _ThreePieceSymbols:
    w = _wheelset_symbols(p, prefix + "wheelset.")
    return _ThreePieceSymbols(
        w=w,
        mf=p("m_f", prefix + "side_frame_mass"),
        If=p("I_f", prefix + "side_frame_yaw_inertia"),
        Ib=p("I_b", prefix + "bolster_yaw_inertia"),
        b=p("b", prefix + "semi_wheelbase"),
        d=p("d", prefix + "side_frame_spacing"),
        kw=p("k_w", prefix + "warp_stiffness"),
        ks=p("k_n", prefix + "nest_shear_stiffness"),
        Fl=p("F_l", prefix + "lateral_friction"),
        Mw=p("M_w", prefix + "warp_friction"),
        Mc=p("M_c", prefix + "centre_plate_friction"),
        omega=p("omega", _attribute(prefix + "reference_frequency", 2 * np.pi)),
        X=p("X", prefix + "reference_amplitude"),
        Theta=p("Theta", prefix + "reference_angle"),
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


def _three_piece(s: _ThreePieceSymbols, tag: str, plate, plate_yaw, V) -> _Truck:
    """Three-piece truck ``tag`` under a body whose centre plate moves laterally by ``plate`` and yaws by
    ``plate_yaw``. Small angles throughout."""
    w = s.w
    yf, psif, psib, y1, psi1, y2, psi2 = coordinates(
        f"y_f{tag} psi_f{tag} psi_b{tag} y_{tag}1 psi_{tag}1 y_{tag}2 psi_{tag}2"
    )
    ya = coordinates(f"y_a{tag}1 y_a{tag}2")
    c = coordinates(" ".join(rf"\Delta{{}}z_{tag}{k}" for k in (1, 2)))  # cross-levels Δz
    # Each side frame (half of m_f and I_f) sits at ±d: it moves laterally with y_f, yaws with ψ_f, and
    # slides longitudinally by ∓d ψ_b when the bolster, whose ends it holds, yaws.
    parts = [
        _Part(T=(s.mf / 2) * ((-side * s.d * psib).diff(time) ** 2 + yf.diff(time) ** 2) / 2
              + (s.If / 2) * psif.diff(time) ** 2 / 2)
        for side in (1, -1)
    ]  # fmt: skip
    parts.append(_Part(T=s.Ib * psib.diff(time) ** 2 / 2))
    for (y, psi), x, yak, ck in zip(((y1, psi1), (y2, psi2)), (s.b, -s.b), ya, c, strict=True):
        parts.append(_wheelset(y, psi, yak, ck, w, V))
        # The side frames swing as pendulums on the adapters, at y_f + x ψ_f on the side frames; the
        # adapters hold the axle square to the bolster's transverse line.
        parts.append(_element(w.ky, w.cy, y - (yf + x * psif)))
        parts.append(_element(w.kpsi, w.cpsi, psi - psib))
    # The nests' shear and the lateral wedges between the centre plate and the side frames; the warp
    # spring and wedges between the bolster and the side frames; the centre plate's friction.
    parts.append(_element(s.ks, _equivalent_damper(s.Fl, s.omega, s.X), plate - yf))
    parts.append(_element(s.kw, _equivalent_damper(s.Mw, s.omega, s.Theta), psib - psif))
    parts.append(_element(0, _equivalent_damper(s.Mc, s.omega, s.Theta), psib - plate_yaw))
    return _Truck((yf, psif, psib, y1, psi1, y2, psi2), ya, c, tuple(parts))


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


@functools.cache
def three_piece_truck() -> Derivation:
    """The three-piece freight truck under a body that runs straight: 7 coordinates, 4 track inputs.

    Side frames (y_f, ψ_f), bolster yaw ψ_b and two wheelsets (y_k, ψ_k at x = ±b), as
    :class:`raildyn.vehicles.three_piece.ThreePieceTruck` (its module docstring describes the truck):

    * T: the wheelsets; each side frame (m_f/2, I_f/2) moves with y_f and ψ_f and slides ∓d ψ_b
      longitudinally as the bolster yaws (so m_f d² adds to the bolster's I_b); the bolster;
    * U: the side frames' pendulum k_y (y_k − y_f − x_k ψ_f)²/2 and the adapters k_ψ (ψ_k − ψ_b)²/2 per
      wheelset, the nests' shear k_n y_f²/2 and the warp k_w (ψ_b − ψ_f)²/2;
    * D: the wheelset's c_y, c_ψ on the same deflections, and the wedges' and centre plate's friction
      F_l, M_w, M_c as equivalent dampers 4F/(π ω X) (4M/(π ω Θ) for the angles);
    * Q: the wheel–rail forces (creep by Kalker's linear law, gravitational stiffness) by virtual work.

    Returns
    -------
    Derivation
        Coordinates (y_f, ψ_f, ψ_b, y₁, ψ₁, y₂, ψ₂) in m and rad; inputs (y_a1, y_a2, c₁, c₂), m; the
        parameters read from a ``ThreePieceTruck``.

    Examples
    --------
    >>> from raildyn.vehicles.three_piece import ThreePieceTruck
    >>> d = three_piece_truck()
    >>> truck = ThreePieceTruck().replace(lateral_friction=0.0, warp_friction=0.0, centre_plate_friction=0.0)
    >>> m = truck.matrices(20.0)
    >>> d.difference((m.M, m.C, m.K, m.GK, m.GC), truck, 20.0) < 1e-14
    True
    """
    p = _Parameters()
    s = _three_piece_symbols(p, "")
    V = _speed()
    truck = _three_piece(s, "", sympy.Integer(0), sympy.Integer(0), V)
    steps = (
        *_energy_steps(truck.parts),
        _equivalent_damper_step(),
        *_wheelset_steps(*truck.coords[3:5], truck.alignment[0], truck.cross_level[0], s.w, V),
    )
    return _derive(
        "three-piece freight truck",
        truck.coords,
        truck.alignment + truck.cross_level,
        truck.parts,
        p,
        V,
        steps,
    )


# ---------------------------------------------------------------------------------------------------------
# A car body (lateral, yaw, roll) on two trucks.


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


@functools.cache
def lateral_freight_car() -> Derivation:
    """The freight car: a body (y, ψ, φ) on two three-piece trucks, 17 coordinates, 8 track inputs.

    As :class:`raildyn.vehicles.three_piece.LateralFreightCar`: each truck as in
    :func:`three_piece_truck`, its centre plate at x = ±l moving with the body's point h below its centre
    of gravity, y_c = y ± l ψ + h φ, and turning with ψ; the body's weight h above the nests, U = m g h cos φ
    (so −m g h in the roll stiffness); the nests' roll stiffness k_φ and the wedges' vertical friction c_φ
    per truck on φ − Δz̄/(2a_r), Δz̄ the mean cross-level under the truck.

    Returns
    -------
    Derivation
        Coordinates (y, ψ, φ, then per truck y_f, ψ_f, ψ_b, y_k1, ψ_k1, y_k2, ψ_k2); inputs (y_a1 … y_a4,
        c₁ … c₄); the parameters read from a ``LateralFreightCar``.
    """
    p = _Parameters()
    B = _body_symbols(p)
    s = _three_piece_symbols(p, "truck.")
    return _vehicle("freight car on three-piece trucks", s, _three_piece, B, p, _speed())


# ---------------------------------------------------------------------------------------------------------
# The three-axle locomotive truck (raildyn.vehicles.locomotive_lateral).


@dataclass(frozen=True)
class _ThreeAxleSymbols:
    w: WheelsetSymbols
    mt: sympy.Symbol
    It: sympy.Symbol
    mm: sympy.Symbol
    kappa: sympy.Symbol
    b: sympy.Symbol
    km: sympy.Symbol
    cm: sympy.Symbol
    ksy: sympy.Symbol
    csy: sympy.Symbol
    kspsi: sympy.Symbol
    cspsi: sympy.Symbol


def _three_axle_symbols(p: _Parameters, prefix: str) -> _ThreeAxleSymbols:
    return _ThreeAxleSymbols(
        w=_wheelset_symbols(p, prefix + "wheelset."),
        mt=p("m_t", prefix + "frame_mass"),
        It=p("I_t", prefix + "frame_yaw_inertia"),
        mm=p("m_m", prefix + "motor_mass"),
        kappa=p("rho_m", prefix + "motor_axle_share"),
        b=p("b", prefix + "axle_spacing"),
        km=p("k_m", prefix + "middle_lateral_stiffness"),
        cm=p("c_m", prefix + "middle_lateral_damping"),
        ksy=p("k_sy", prefix + "secondary_lateral_stiffness"),
        csy=p("c_sy", prefix + "secondary_lateral_damping"),
        kspsi=p(r"k_s\psi", prefix + "secondary_yaw_stiffness"),
        cspsi=p(r"c_s\psi", prefix + "secondary_yaw_damping"),
    )


def _three_axle(s: _ThreeAxleSymbols, tag: str, seat, seat_yaw, V) -> _Truck:
    """Three-axle truck ``tag`` under a body whose secondary seat moves laterally by ``seat`` and yaws by
    ``seat_yaw``. Small angles throughout."""
    w = s.w
    yt, psit = coordinates(f"y_T{tag} psi_T{tag}")
    wheelsets = [coordinates(f"y_{tag}{k} psi_{tag}{k}") for k in (1, 2, 3)]
    ya = coordinates(f"y_a{tag}1 y_a{tag}2 y_a{tag}3")
    c = coordinates(" ".join(rf"\Delta{{}}z_{tag}{k}" for k in (1, 2, 3)))  # cross-levels Δz
    parts = [_Part(T=s.mt * yt.diff(time) ** 2 / 2 + s.It * psit.diff(time) ** 2 / 2)]
    for k, ((y, psi), x, yak, ck) in enumerate(zip(wheelsets, (s.b, 0, -s.b), ya, c, strict=True), start=1):
        # The traction motor: a share ρ_m moves laterally with the axle, the rest with the frame at x.
        parts.append(_Part(T=s.kappa * s.mm * y.diff(time) ** 2 / 2))
        parts.append(_Part(T=(1 - s.kappa) * s.mm * (yt + x * psit).diff(time) ** 2 / 2))
        parts.append(_wheelset(y, psi, yak, ck, w, V))
        # Primary: lateral at the axle (the middle axle only on its centring springs), yaw.
        ky, cy = (s.km, s.cm) if k == 2 else (w.ky, w.cy)
        parts.append(_element(ky, cy, y - (yt + x * psit)))
        parts.append(_element(w.kpsi, w.cpsi, psi - psit))
    # Secondary: the flexicoil springs and the lateral dampers, between the frame and the body's seat.
    parts.append(_element(s.ksy, s.csy, yt - seat))
    parts.append(_element(s.kspsi, s.cspsi, psit - seat_yaw))
    coords = (yt, psit) + sum(wheelsets, ())
    return _Truck(coords, ya, c, tuple(parts))


@functools.cache
def three_axle_truck() -> Derivation:
    """The three-axle locomotive truck under a body that runs straight: 8 coordinates, 6 track inputs.

    As :class:`raildyn.vehicles.locomotive_lateral.ThreeAxleTruck`: a frame (y_T, ψ_T) on three wheelsets at
    x = +b, 0, −b (b the model's ``axle_spacing``, half the truck's wheelbase):

    * T: the frame (m_t, I_t); the wheelsets (m_w, I_w); each traction motor m_m, a share ρ_m moving laterally
      with its axle and 1 − ρ_m with the frame at x_k, ½(1 − ρ_m) m_m (ẏ_t + x_k ψ̇_t)² (the cross terms cancel
      as Σ x_k = 0, and (1 − ρ_m) m_m Σ x_k² adds to I_t);
    * U, D: the primary lateral k_y, c_y of the end axles and k_m, c_m of the middle one on
      y_k − y_T − x_k ψ_T, the primary yaw k_ψ, c_ψ on ψ_k − ψ_T, the secondary k_sy, c_sy on y_T and
      k_sψ, c_sψ on ψ_T;
    * Q: the wheel–rail forces (creep by Kalker's linear law, gravitational stiffness) by virtual work.

    Returns
    -------
    Derivation
        Coordinates (y_T, ψ_T, y₁, ψ₁, y₂, ψ₂, y₃, ψ₃); inputs (y_a1, y_a2, y_a3, c₁, c₂, c₃); the parameters
        read from a ``ThreeAxleTruck``.

    Examples
    --------
    >>> from raildyn.vehicles.locomotive_lateral import ThreeAxleTruck
    >>> truck = ThreeAxleTruck()
    >>> m = truck.matrices(30.0)
    >>> three_axle_truck().difference((m.M, m.C, m.K, m.GK, m.GC), truck, 30.0) < 1e-14
    True
    """
    p = _Parameters()
    s = _three_axle_symbols(p, "")
    V = _speed()
    truck = _three_axle(s, "", sympy.Integer(0), sympy.Integer(0), V)
    steps = (
        *_energy_steps(truck.parts),
        *_wheelset_steps(*truck.coords[2:4], truck.alignment[0], truck.cross_level[0], s.w, V),
    )
    return _derive(
        "three-axle locomotive truck",
        truck.coords,
        truck.alignment + truck.cross_level,
        truck.parts,
        p,
        V,
        steps,
    )


@functools.cache
def lateral_locomotive() -> Derivation:
    """The six-axle locomotive: a body (y, ψ, φ) on two three-axle trucks, 19 coordinates, 12 track inputs.

    As :class:`raildyn.vehicles.locomotive_lateral.LateralLocomotive`: each truck as in
    :func:`three_axle_truck`, its secondary seat at x = ±l moving with the body's point h below its centre
    of gravity, y ± l ψ + h φ, and its yaw spring on ψ_T − ψ; the body's weight h above the seats,
    U = m g h cos φ; the secondary roll stiffness k_φ and damping c_φ per truck on φ − Δz̄/(2a_r), Δz̄ the mean
    cross-level under the truck's three wheelsets.

    Returns
    -------
    Derivation
        Coordinates (y, ψ, φ, then per truck y_T, ψ_T, y_k1, ψ_k1, y_k2, ψ_k2, y_k3, ψ_k3); inputs
        (y_a1 … y_a6, c₁ … c₆); the parameters read from a ``LateralLocomotive``.
    """
    p = _Parameters()
    B = _body_symbols(p)
    s = _three_axle_symbols(p, "truck.")
    return _vehicle("six-axle locomotive on three-axle trucks", s, _three_axle, B, p, _speed())
