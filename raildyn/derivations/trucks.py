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

The parts every truck and vehicle here is built from (wheelsets on the rails, elements, a body on two
trucks, the assembly by Lagrange's equations) are in ``raildyn.derivations._truck_parts``.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
import sympy

from raildyn.derivations._core import Derivation, Step, coordinates, time
from raildyn.derivations._truck_parts import (
    _attribute,
    _body_symbols,
    _derive,
    _element,
    _energy_steps,
    _Parameters,
    _Part,
    _speed,
    _Truck,
    _vehicle,
    _wheelset,
    _wheelset_steps,
    _wheelset_symbols,
)
from raildyn.derivations._wheel_rail import (
    WheelsetSymbols,
)

__all__ = ["lateral_freight_car", "lateral_locomotive", "three_axle_truck", "three_piece_truck"]


# ---------------------------------------------------------------------------------------------------------
# Friction as an equivalent damper (the three-piece truck's wedges and centre plate).


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
# The freight car: a car body (lateral, yaw, roll) on two three-piece trucks.


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
