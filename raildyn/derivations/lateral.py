"""Chapter 7's lateral models derived: the two-axle bogie and the 15-coordinate passenger car.

Both by Lagrange's equations (:func:`raildyn.derivations.lagrange`): the kinetic energy of the
rigid bodies, the potential energy and Rayleigh's dissipation function of the primary and
secondary springs and dampers, written from the lateral displacement of each spring's two ends
in the coordinates, and the wheel–rail forces of every wheelset as generalized forces by
virtual work: Kalker's linear creep law on the creepages of each wheel (Kalker 1967; Garg &
Dukkipati 1984, ch. 5) and the lateral and yaw components of the normal loads (the
gravitational stiffness, Wickens 2003, ch. 2). The tests hold them to
:class:`raildyn.vehicles.lateral.Bogie` and :class:`raildyn.vehicles.lateral.LateralCar`.

Sign convention: x forward, y to the left, z up; ψ (yaw) turns x towards y, the roll ϕ turns y
towards z. The track inputs are the alignment y_a (lateral position of the track centre line)
and the cross-level Δz (left rail height minus right rail height) under each wheelset, m.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import sympy

from raildyn.constants import GRAVITY
from raildyn.derivations._core import Derivation, Step, coordinates, lagrange, time
from raildyn.derivations._wheel_rail import (
    RAIL_HALF_SPACING,
    RAIL_PAIR,
    WheelsetSymbols,
    linear,
    symbol_table,
    wheel_rail,
    wheelset_symbols,
)

__all__ = ["bogie", "lateral_car"]

_BOGIE_ROWS = (
    "frame lateral",
    "frame yaw",
    "leading wheelset lateral",
    "leading wheelset yaw",
    "trailing wheelset lateral",
    "trailing wheelset yaw",
)
_CAR_ROWS = (
    "body lateral",
    "body yaw",
    "body roll",
    "front frame lateral",
    "front frame yaw",
    "leading wheelset lateral",
    "leading wheelset yaw",
)


def _rate(expr):
    return sympy.diff(expr, time)


def _wheelset_terms(y, psi, ya, c, p: WheelsetSymbols, V) -> tuple:
    """One wheelset's kinetic energy, the generalized forces of its wheel–rail forces and its creepages.

    The wheel–rail forces are the one derivation every lateral vehicle shares
    (``_wheel_rail.wheel_rail``: creepages, Kalker's linear law and the tilted normal loads by
    virtual work, linearised).

    Returns
    -------
    (T, forces, creepages)
        T the kinetic energy; forces {y: Q_y, ψ: Q_ψ}; creepages the left wheel's γ_x and the
        wheelset's γ_y and φ, linearised, for the steps.
    """
    T = p.m * _rate(y) ** 2 / 2 + p.I * _rate(psi) ** 2 / 2
    forces, kinematics = wheel_rail(y, psi, ya, c, p, V)
    variables = [y, psi, ya, c]
    creepages = {key: linear(kinematics[key], variables) for key in ("gx", "gy", "spin")}
    return T, forces, creepages


def _creepage_steps(subscript: str, creepages: dict) -> tuple:
    """Steps that show the creepages of one wheelset (left wheel; the right one's γ_x is −γ_x,L)."""
    return (
        Step(
            f"longitudinal creepage of the left wheel of wheelset {subscript}",
            sympy.Eq(sympy.Symbol(f"gamma_xL{subscript}"), creepages["gx"]),
        ),
        Step(
            f"lateral creepage of wheelset {subscript}",
            sympy.Eq(sympy.Symbol(f"gamma_y{subscript}"), creepages["gy"]),
        ),
        Step(
            f"spin creepage of wheelset {subscript}",
            sympy.Eq(sympy.Symbol(f"varphi{subscript}"), creepages["spin"]),
        ),
    )


@dataclass(frozen=True)
class _BogieSymbols:
    mf: sympy.Symbol
    If: sympy.Symbol
    b: sympy.Symbol
    ksy: sympy.Symbol
    csy: sympy.Symbol
    kspsi: sympy.Symbol
    cspsi: sympy.Symbol


def _bogie_symbols(path: str) -> tuple:
    """The frame's and the secondary suspension's symbols and their pairs, the bogie at ``path``."""
    fields = {
        "mf": ("m_f", "frame_mass"),
        "If": ("I_f", "frame_yaw_inertia"),
        "b": ("b", "semi_wheelbase"),
        "ksy": ("k_sy", "secondary_lateral_stiffness"),
        "csy": ("c_sy", "secondary_lateral_damping"),
        "kspsi": ("k_{s\\psi}", "secondary_yaw_stiffness"),
        "cspsi": ("c_{s\\psi}", "secondary_yaw_damping"),
    }
    made, pairs = symbol_table(fields, path)
    return _BogieSymbols(**made), pairs


def _bogie_pieces(tag, frame, wheelsets, inputs, seat_y, seat_psi, w: WheelsetSymbols, s: _BogieSymbols, V):
    """T, U, D and the wheel–rail generalized forces of one bogie: frame, two wheelsets, suspension.

    ``seat_y`` and ``seat_psi`` are the lateral displacement and yaw of the body at the secondary
    suspension (0 for a body that runs straight).
    """
    yf, psif = frame
    T = s.mf * _rate(yf) ** 2 / 2 + s.If * _rate(psif) ** 2 / 2
    U = sympy.Integer(0)
    D = sympy.Integer(0)
    forces = {}
    creepages = []
    for (y, psi), (ya, c), x in zip(wheelsets, inputs, (s.b, -s.b), strict=True):
        Tw, pw, cw = _wheelset_terms(y, psi, ya, c, w, V)
        T += Tw
        forces |= pw
        creepages.append(cw)
        # Primary: the axlebox at x = ±b moves with the wheelset by y; the frame's end of the
        # spring, x ahead of the frame's centre, by y_f + x ψ_f. Yaw: relative yaw ψ − ψ_f.
        u_lat = y - yf - x * psif
        u_yaw = psi - psif
        U += w.ky * u_lat**2 / 2 + w.kpsi * u_yaw**2 / 2
        D += w.cy * _rate(u_lat) ** 2 / 2 + w.cpsi * _rate(u_yaw) ** 2 / 2
    # Secondary: between the frame's centre and the body's seat above it.
    u_sec = yf - seat_y
    u_sec_yaw = psif - seat_psi
    U += s.ksy * u_sec**2 / 2 + s.kspsi * u_sec_yaw**2 / 2
    D += s.csy * _rate(u_sec) ** 2 / 2 + s.cspsi * _rate(u_sec_yaw) ** 2 / 2
    return T, U, D, forces, creepages


def _equation_steps(M, C, K, GK, GC, q, w, rows, names) -> tuple:
    """Steps that write out the equations of motion of some coordinates, row by row of the matrices.

    Row i reads Σ_j (M_ij q̈_j + C_ij q̇_j + K_ij q_j) = Σ_k (G_K,ik w_k + G_C,ik ẇ_k); nothing is
    simplified, so that a notebook shows each row at once.
    """
    rates = [c.diff(time) for c in q]
    accelerations = [c.diff(time, 2) for c in q]
    input_rates = [v.diff(time) for v in w]
    steps = []
    for i, name in zip(rows, names, strict=True):
        left = [M[i, j] * accelerations[j] for j in range(len(q)) if M[i, j] != 0]
        left += [C[i, j] * rates[j] for j in range(len(q)) if C[i, j] != 0]
        left += [K[i, j] * q[j] for j in range(len(q)) if K[i, j] != 0]
        right = [GK[i, k] * w[k] for k in range(len(w)) if GK[i, k] != 0]
        right += [GC[i, k] * input_rates[k] for k in range(len(w)) if GC[i, k] != 0]
        # Not evaluated: sympy would otherwise try to decide whether the two sides are equal.
        equation = sympy.Eq(sympy.Add(*left), sympy.Add(*right), evaluate=False)
        steps.append(Step(f"equation of motion: {name}", equation))
    return tuple(steps)


@functools.cache
def bogie() -> Derivation:
    """The bogie of :class:`raildyn.vehicles.lateral.Bogie` under a body that runs straight.

    Coordinates q = [y_f, ψ_f, y₁, ψ₁, y₂, ψ₂]: the frame's and each wheelset's lateral displacement
    (m) and yaw (rad), wheelset 1 leading at x = +b. Inputs w = [y_a1, y_a2, c₁, c₂], the alignment
    and the cross-level under each wheelset (m). Lagrange's equations (book ch. 7) with

    * T = ½ m_f ẏ_f² + ½ I_f ψ̇_f² + Σ_j (½ m_w ẏ_j² + ½ I_w ψ̇_j²);
    * U = Σ_j [½ k_y (y_j − y_f ∓ bψ_f)² + ½ k_ψ (ψ_j − ψ_f)²] + ½ k_sy y_f² + ½ k_sψ ψ_f², and D
      alike with the dampers;
    * Q: Kalker's linear creep forces on each wheel and the normal loads' lateral and yaw
      components, by virtual work (Garg & Dukkipati 1984, ch. 5; Wickens 2003, ch. 2).

    Returns
    -------
    Derivation
        Parameters read from a :class:`~raildyn.vehicles.lateral.Bogie`; the damping holds the
        speed V (m/s).

    Examples
    --------
    >>> from raildyn.vehicles.lateral import Bogie
    >>> d = bogie()
    >>> d.K[0, 2]  # the frame's lateral row, wheelset 1's column: the primary spring pulls back
    -k_y
    >>> m = Bogie().matrices(30.0)
    >>> d.difference((m.M, m.C, m.K, m.GK, m.GC), Bogie(), 30.0) < 1e-14
    True
    """
    V = sympy.Symbol("V")
    w, wheelset_pairs = wheelset_symbols("wheelset")
    s, bogie_pairs = _bogie_symbols("")
    q = coordinates("y_f psi_f y_1 psi_1 y_2 psi_2")
    inputs = coordinates(r"y_a1 y_a2 \Delta{}z_1 \Delta{}z_2")  # alignment, cross-level Δz
    wheelsets = ((q[2], q[3]), (q[4], q[5]))
    track = ((inputs[0], inputs[2]), (inputs[1], inputs[3]))
    T, U, D, forces, creepages = _bogie_pieces(
        "", (q[0], q[1]), wheelsets, track, sympy.Integer(0), sympy.Integer(0), w, s, V
    )
    Q = sympy.Matrix([forces.get(c, 0) for c in q])
    M, C, K, GK, GC = lagrange(T, U, D, q, forces=Q, inputs=inputs)
    return Derivation(
        title="two-axle bogie under a body that runs straight",
        coordinates=q,
        inputs=inputs,
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=wheelset_pairs + bogie_pairs + (RAIL_PAIR,),
        speed=V,
        steps=(
            Step("kinetic energy", sympy.Eq(sympy.Symbol("T"), T)),
            Step("potential energy of the primary and secondary springs", sympy.Eq(sympy.Symbol("U"), U)),
            Step("Rayleigh's dissipation function of the dampers", sympy.Eq(sympy.Symbol("D"), D)),
            *_creepage_steps("1", creepages[0]),
            Step(
                "generalized forces of the wheel–rail contact (virtual work)",
                sympy.Eq(sympy.Symbol("Q"), Q.applyfunc(sympy.expand), evaluate=False),
            ),
            *_equation_steps(M, C, K, GK, GC, q, inputs, range(6), _BOGIE_ROWS),
        ),
    )


@functools.cache
def lateral_car() -> Derivation:
    """The 15-coordinate passenger car of :class:`raildyn.vehicles.lateral.LateralCar`.

    Coordinates q = [y, ψ, ϕ; y_f1, ψ_f1, y₁₁, ψ₁₁, y₁₂, ψ₁₂; y_f2, ψ_f2, y₂₁, ψ₂₁, y₂₂, ψ₂₂]:
    the body's lateral displacement (m), yaw and roll (rad); each bogie frame's lateral
    displacement and yaw; each wheelset's (bogie 1 leading, at x = +l; wheelset j1 leading in its
    bogie). Inputs w: the alignment y_a under the four wheelsets, then the cross-level Δz there (m).
    Lagrange's equations (book ch. 7) with the bogie's T, U, D and Q (:func:`bogie`) for each bogie,
    the secondary seat at x = ±l, h below the body's centre of gravity, moving by
    y ± lψ + hϕ, and for the body

    * T = ½ m ẏ² + ½ I_z ψ̇² + ½ I_x ϕ̇²;
    * U = Σ_bogies ½ k_ϕ (ϕ − (c_k1 + c_k2)/(4a))² + m g h (cos ϕ − 1): the roll springs
      stand on frames that tilt with the mean cross-level under their wheelsets, and the body's
      weight, h above the seat about which it rolls, lowers the roll stiffness by m g h.

    Returns
    -------
    Derivation
        Parameters read from a :class:`~raildyn.vehicles.lateral.LateralCar`; the damping holds the speed
        V (m/s).

    Examples
    --------
    >>> from raildyn.vehicles.lateral import LateralCar
    >>> d = lateral_car()
    >>> d.K[2, 2]  # roll: two bogies' roll springs, the lateral springs' arm h, less the weight's moment
    -g*h*m + 2*h**2*k_sy + 2*k_phi
    >>> m = LateralCar().matrices(40.0)
    >>> d.difference((m.M, m.C, m.K, m.GK, m.GC), LateralCar(), 40.0) < 1e-14
    True
    """
    V = sympy.Symbol("V")
    w, wheelset_pairs = wheelset_symbols("bogie.wheelset")
    s, bogie_pairs = _bogie_symbols("bogie.")
    mc, Icz, Icx, l, h, kphi, cphi, g = sympy.symbols("m I_z I_x l h k_phi c_phi g")
    body_pairs = (
        (mc, "body_mass"),
        (Icz, "body_yaw_inertia"),
        (Icx, "body_roll_inertia"),
        (l, "semi_bogie_spacing"),
        (h, "body_height"),
        (kphi, "roll_stiffness"),
        (cphi, "roll_damping"),
        (g, lambda model: GRAVITY),
    )
    q = coordinates("y psi phi y_f1 psi_f1 y_11 psi_11 y_12 psi_12 y_f2 psi_f2 y_21 psi_21 y_22 psi_22")
    inputs = coordinates(r"y_a11 y_a12 y_a21 y_a22 \Delta{}z_11 \Delta{}z_12 \Delta{}z_21 \Delta{}z_22")
    yc, psic, phic = q[:3]
    T = mc * _rate(yc) ** 2 / 2 + Icz * _rate(psic) ** 2 / 2 + Icx * _rate(phic) ** 2 / 2
    # The body rests on the secondary springs at the seat, h below its centre of gravity: rolling by
    # ϕ about the seat lowers the centre of gravity by h(1 − cos ϕ).
    U = mc * g * h * (sympy.cos(phic) - 1)
    D = sympy.Integer(0)
    forces = {}
    pieces = {}
    for k, x in ((0, l), (1, -l)):
        base = 3 + 6 * k
        frame = (q[base], q[base + 1])
        wheelsets = ((q[base + 2], q[base + 3]), (q[base + 4], q[base + 5]))
        track = ((inputs[2 * k], inputs[4 + 2 * k]), (inputs[2 * k + 1], inputs[4 + 2 * k + 1]))
        seat = yc + x * psic + h * phic  # the seat, x along and h below the centre, moves by this
        Tb, Ub, Db, pb, _ = _bogie_pieces(str(k + 1), frame, wheelsets, track, seat, psic, w, s, V)
        # Roll: the secondary vertical springs (and anti-roll bar) between the body and a frame that
        # tilts by the mean cross-level of its two wheelsets over the rail spacing 2a_r.
        u_roll = phic - (track[0][1] + track[1][1]) / (4 * RAIL_HALF_SPACING)
        Ub += kphi * u_roll**2 / 2
        Db += cphi * _rate(u_roll) ** 2 / 2
        T += Tb
        U += Ub
        D += Db
        forces |= pb
        if k == 0:
            pieces = {"U": Ub, "D": Db}
    Q = sympy.Matrix([forces.get(c, 0) for c in q])
    M, C, K, GK, GC = lagrange(T, U, D, q, forces=Q, inputs=inputs)
    return Derivation(
        title="passenger car on two bogies (15 coordinates)",
        coordinates=q,
        inputs=inputs,
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=wheelset_pairs + bogie_pairs + body_pairs + (RAIL_PAIR,),
        speed=V,
        steps=(
            Step("kinetic energy", sympy.Eq(sympy.Symbol("T"), T)),
            Step(
                "potential energy of the body's weight",
                sympy.Eq(sympy.Symbol("U_g"), mc * g * h * (sympy.cos(phic) - 1)),
            ),
            Step(
                "potential energy of bogie 1's springs (bogie 2 alike, at x = −l)",
                sympy.Eq(sympy.Symbol("U_1"), pieces["U"]),
            ),
            Step("dissipation of bogie 1's dampers", sympy.Eq(sympy.Symbol("D_1"), pieces["D"])),
            *_equation_steps(M, C, K, GK, GC, q, inputs, range(7), _CAR_ROWS),
        ),
    )
