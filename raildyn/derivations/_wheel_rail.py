"""One wheelset on the rails, derived once for every vehicle: its parameter symbols, and the
generalized forces of its wheel–rail forces by virtual work, linearised.

:mod:`raildyn.derivations.lateral` (bogie, car) and :mod:`raildyn.derivations.trucks` (freight truck,
locomotive) build their wheelsets from here, so that the wheel–rail forces of every lateral vehicle
are one derivation. The single wheelset of chapter 5 (:mod:`raildyn.derivations.wheelset`) is
derived in full in its own module, step by step, as the notebook shows.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import sympy

from raildyn.constants import STANDARD_RAIL_SPACING
from raildyn.derivations._core import coordinates, generalized_forces, time


@dataclass(frozen=True)
class WheelsetSymbols:
    """The symbols of a :class:`raildyn.wheelset.Wheelset`'s parameters (shared by all its wheelsets)."""

    m: sympy.Symbol  # mass, kg (on a locomotive the motor's axle share is added)
    I: sympy.Symbol  # noqa: E741 - yaw inertia I_w, kg·m²
    r0: sympy.Symbol
    a: sympy.Symbol
    lam: sympy.Symbol
    W: sympy.Symbol
    f11: sympy.Symbol
    f22: sympy.Symbol
    f23: sympy.Symbol
    f33: sympy.Symbol
    theta0: sympy.Symbol
    eps: sympy.Symbol
    ky: sympy.Symbol
    kpsi: sympy.Symbol
    cy: sympy.Symbol
    cpsi: sympy.Symbol


# field → (symbol name, the Wheelset's attribute)
_FIELDS = {
    "m": ("m_w", "mass"),
    "I": ("I_w", "yaw_inertia"),
    "r0": ("r_0", "rolling_radius"),
    "a": ("a", "half_gauge"),
    "lam": ("lambda", "conicity"),
    "W": ("W", "axle_load"),
    "f11": ("f_11", "f11"),
    "f22": ("f_22", "f22"),
    "f23": ("f_23", "f23"),
    "f33": ("f_33", "f33"),
    "theta0": ("vartheta_0", "contact_angle"),
    "eps": ("epsilon", "contact_angle_parameter"),
    "ky": ("k_y", "lateral_stiffness"),
    "kpsi": ("k_psi", "yaw_stiffness"),
    "cy": ("c_y", "lateral_damping"),
    "cpsi": ("c_psi", "yaw_damping"),
}


RAIL_HALF_SPACING = sympy.Symbol("a_r")
"""a_r, half the rail spacing (m): a cross-level Δz rolls the plane of the rails by Δz/(2a_r)."""


def _rail_half_spacing(model) -> float:
    return STANDARD_RAIL_SPACING / 2


RAIL_PAIR = (RAIL_HALF_SPACING, _rail_half_spacing)
"""The parameter pair of :data:`RAIL_HALF_SPACING`, for a derivation's ``parameters``: the value is
half :data:`raildyn.constants.STANDARD_RAIL_SPACING`, whatever the model."""


def symbol_table(fields: dict, path: str) -> tuple:
    """Symbols for a table ``{key: (symbol name, attribute)}`` and their (symbol, ``path + attribute``) pairs.

    No assumptions (positive, ...) on any symbol: nothing here simplifies, and sympy's assumption
    queries would take most of the time of building a car's matrices.
    """
    made = {key: sympy.Symbol(name) for key, (name, _) in fields.items()}
    pairs = tuple((made[key], f"{path}{attribute}") for key, (_, attribute) in fields.items())
    return made, pairs


def wheelset_symbols(path: str) -> tuple:
    """The wheelset's symbols and their (symbol, dotted attribute path) pairs, the wheelset at ``path``."""
    made, pairs = symbol_table(_FIELDS, f"{path}.")
    return WheelsetSymbols(**made), pairs


def linear(expr, variables):
    """The first-order Taylor polynomial of ``expr`` about rest (every variable and its rate 0)."""
    rates = [v.diff(time) for v in variables]
    everything = rates + list(variables)  # rates first: substituting a function must not touch its rate
    rest = [(v, 0) for v in everything]
    out = expr.subs(rest)
    for v in everything:
        out += expr.diff(v).subs(rest) * v
    return sympy.expand(out)


def wheel_rail(y, psi, ya, c, w: WheelsetSymbols, V) -> tuple:
    """The wheel–rail forces on wheelset (y, ψ) over its track inputs (y_a, Δz): see :func:`_wheel_rail_of`.

    Derived once in generic coordinates and renamed for each wheelset.

    Returns
    -------
    (forces, kinematics)
        forces {y: Q_y, ψ: Q_ψ}, linearised; kinematics the left wheel's creepages γ_x, γ_y, φ and
        contact angle ϑ_L (keys "gx", "gy", "spin", "angle"), exact, for the steps to show.
    """
    generic = coordinates(r"y psi y_a \Delta{}z")
    rename = dict(zip(generic, (y, psi, ya, c), strict=True))
    Q, kinematics = _wheel_rail_of(w, V)
    return (
        {rename[q]: f.xreplace(rename) for q, f in Q.items()},
        {name: f.xreplace(rename) for name, f in kinematics.items()},
    )


@functools.cache
def _wheel_rail_of(w: WheelsetSymbols, V) -> tuple:
    """The wheel–rail forces on one wheelset by virtual work, linearised: ({y: Q_y, ψ: Q_ψ}, kinematics).

    Left wheel s = +1 at y = +a, right wheel s = −1 (y to the left, ψ turning left):

    * rolling radius r = r₀ + s λ (y − y_a) (the alignment y_a moves the rails under the wheelset);
    * longitudinal creepage γ_x = (V − s a ψ̇ − Ω r)/V with Ω = V/r₀: the contact point of the wheel moves
      forward at V − s a ψ̇ and its rim backward at Ω r;
    * lateral creepage γ_y = (ẏ − V sin ψ)/V: the wheel rolls along its own plane, yawed by ψ;
    * the contact angle ϑ = ϑ₀ + s ε (y − y_a)/a;
    * spin φ = ψ̇ cos ϑ/V − s sin ϑ/r₀, the angular velocity about the contact normal over V
      (:func:`raildyn.derivations.contact.creepages`), for a small angle ψ̇/V − s ϑ/r₀ (as the normal
      force's lateral component below): its constant parts ∓ϑ₀/r₀ cancel between the wheels, its
      difference 2ε(y − y_a)/(a r₀) does not;
    * Kalker's linear law per wheel: F_x = −f₁₁γ_x, F_y = −f₂₂γ_y − f₂₃φ, M_z = f₂₃γ_y − f₃₃φ;
    * the rail's normal force, W/2 on each wheel, tilted by the contact angle, pushes the wheel
      laterally by −s (W/2) ϑ;
    * on a cross-level Δz the track rolls by Δz/(2a_r) (2a_r the rail spacing, over which a cross-level is
      measured as a cant is), and the weight's component in its plane pushes the wheelset toward the low
      rail by −W Δz/(2a_r).

    The forces work through the displacements of the contact point, the point (0, s a) of the wheelset:
    x = −s a sin ψ and y + s a (cos ψ − 1) in the track's axes, where the normal force acts; the creep
    force F_y lies along the axle, along which the point moves by cos ψ δy; the spin moment works
    through ψ. (The two wheels' spin forces ±f₂₃ϑ₀/r₀ at rest lie on the axle's line: a yaw turns
    them together and they make no couple.) The generalized forces are
    linearised about rest before they join the equations (first-order Taylor polynomials).
    """
    y, psi, ya, c = coordinates(r"y psi y_a \Delta{}z")  # c: the cross-level Δz
    yd, psid = y.diff(time), psi.diff(time)
    pairs = []
    kinematics = {}
    for s in (1, -1):
        radius = w.r0 + s * w.lam * (y - ya)
        gx = (V - s * w.a * psid - V / w.r0 * radius) / V
        gy = (yd - V * sympy.sin(psi)) / V
        angle = w.theta0 + s * w.eps * (y - ya) / w.a
        spin = psid / V - s * angle / w.r0  # ψ̇ cos ϑ/V − s sin ϑ/r₀ for a small angle, as in the normal force
        Fx = -w.f11 * gx
        Fy = -w.f22 * gy - w.f23 * spin
        Mz = w.f23 * gy - w.f33 * spin
        normal = -s * w.W / 2 * angle
        pairs += [
            (Fx, -s * w.a * sympy.sin(psi)),
            (Fy, y),  # along the axle: the contact point moves along it by cos ψ δy (first order: δy)
            (normal, y + s * w.a * (sympy.cos(psi) - 1)),  # across the rails, in the track's axes
            (Mz, psi),
        ]
        if s == 1:
            kinematics = {"gx": gx, "gy": gy, "spin": spin, "angle": angle}
    pairs.append((-w.W * c / (2 * RAIL_HALF_SPACING), y))
    Q = generalized_forces(pairs, [y, psi])
    variables = [y, psi, ya, c]
    return {y: linear(Q[0], variables), psi: linear(Q[1], variables)}, kinematics
