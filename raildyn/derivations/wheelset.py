"""Chapter 5's wheelset derived: on tangent track, and on a curve.

Both from the kinematics of the two contact points (rolling radii, contact angles, slip
velocities, hence the creepages), Kalker's linear creep law per wheel, the lateral components
of the two normal forces, and the wheelset's energies, through Lagrange's equations
(:func:`raildyn.derivations.lagrange`) with the contact forces as generalized forces by
virtual work (:func:`raildyn.derivations.generalized_forces`). The tests hold
:func:`tangent_wheelset` to ``Wheelset.matrices`` and
:func:`curved_wheelset` to :func:`raildyn.wheelset.curve_loads`.

Axes: x forward, y to the left, z up; ψ the yaw, positive turning to the left. The left wheel's
contact is at +a along the axle, the right wheel's at −a. Sources: Garg & Dukkipati (1984),
ch. 5; Wickens (1965; 2003, ch. 2 and 7); Kalker (1967) for the creep coefficients.
"""

from __future__ import annotations

import functools

import sympy

from raildyn.constants import GRAVITY, STANDARD_RAIL_SPACING
from raildyn.derivations._core import Derivation, Step, coordinates, generalized_forces, lagrange, time
from raildyn.derivations._wheel_rail import RAIL_HALF_SPACING, RAIL_PAIR

__all__ = ["critical_speed_limit", "curved_wheelset", "tangent_wheelset"]


def _symbols() -> dict:
    """The wheelset's parameters as symbols, each with the Wheelset field that holds its value."""
    positive = {
        "m": "mass",
        "I_z": "yaw_inertia",
        "r_0": "rolling_radius",
        "a": "half_gauge",
        "W": "axle_load",
    }
    nonnegative = {
        "lambda": "conicity",
        "f_11": "f11",
        "f_22": "f22",
        "f_23": "f23",
        "f_33": "f33",
        "vartheta_0": "contact_angle",
        "varepsilon": "contact_angle_parameter",
        "k_y": "lateral_stiffness",
        "k_psi": "yaw_stiffness",
        "c_y": "lateral_damping",
        "c_psi": "yaw_damping",
    }
    out = {name: (sympy.Symbol(name, positive=True), field) for name, field in positive.items()}
    out.update({name: (sympy.Symbol(name, nonnegative=True), field) for name, field in nonnegative.items()})
    return out


def _eq(name: str, value) -> sympy.Eq:
    return sympy.Eq(sympy.Symbol(name), value, evaluate=False)


def _contact(s: dict, y, psi, yd, psid, V, offset, path_yaw, turning, tilt):
    """The kinematics and forces of the two contacts, for both derivations.

    ``offset`` is the wheelset's displacement relative to the rails, y − y_t; ``path_yaw`` the
    direction of its path (0 on tangent track); ``turning`` the yaw rate of the axes (0 on
    tangent track); ``tilt`` the roll of the rails' plane by the cross-level. Returns the
    force pairs and the steps.
    """
    r0, a, lam, eps, th0 = (s[k][0] for k in ("r_0", "a", "lambda", "varepsilon", "vartheta_0"))
    f11, f22, f23, f33, W = (s[k][0] for k in ("f_11", "f_22", "f_23", "f_33", "W"))
    # Contact geometry of a cone on the rails: radii and angles follow the offset.
    r_L, r_R = r0 + lam * offset, r0 - lam * offset
    th_L, th_R = th0 + eps * offset / a, th0 - eps * offset / a
    # The axle turns at ω_y = V/r₀: the two longitudinal creep forces come out equal and opposite,
    # so they put no torque about the axle and leave its speed unchanged to first order.
    Omega = V / r0
    yaw_rate = psid + turning
    # Slip velocity of the wheel's material at each contact, relative to the rail, in the wheelset's
    # axes: forward V, less the yaw rate times the lever ±a, less the rolling ω_y r.
    v_xL = V - a * yaw_rate - Omega * r_L
    v_xR = V + a * yaw_rate - Omega * r_R
    v_y = yd - V * (psi - path_yaw)
    # Spin: the angular velocity about each contact normal, tilted by ϑ towards the track's centre,
    # ψ̇ cos ϑ ∓ ω_y sin ϑ (raildyn.derivations.contact.creepages), to first order in the small
    # contact angle as the normal forces' lateral components N sin ϑ ≈ N ϑ below.
    w_L = yaw_rate - Omega * th_L
    w_R = yaw_rate + Omega * th_R
    g_xL, g_xR = sympy.expand(v_xL / V), sympy.expand(v_xR / V)
    g_y = sympy.expand(v_y / V)
    p_L, p_R = sympy.expand(w_L / V), sympy.expand(w_R / V)
    # Kalker's linear law, per wheel (force on the wheel).
    Fx_L, Fx_R = -f11 * g_xL, -f11 * g_xR
    Fy_L, Fy_R = -f22 * g_y - f23 * p_L, -f22 * g_y - f23 * p_R
    Mz = (f23 * g_y - f33 * p_L) + (f23 * g_y - f33 * p_R)
    # Normal forces, W/2 each: their lateral components, across the rails (tilted by the cross-level).
    N = W / 2
    Fn_L = -N * (th_L + tilt)
    Fn_R = N * (th_R - tilt)
    return {
        "pairs": (Fx_L, Fx_R, Fy_L, Fy_R, Mz, Fn_L, Fn_R),
        "steps": (
            Step("rolling radius of the left wheel", _eq("r_L", r_L)),
            Step("rolling radius of the right wheel", _eq("r_R", r_R)),
            Step("contact angle of the left wheel", _eq("vartheta_L", th_L)),
            Step("contact angle of the right wheel", _eq("vartheta_R", th_R)),
            Step("longitudinal creepage, left wheel: (V − a ψ̇ − ω_y r_L)/V", _eq("gamma_xL", g_xL)),
            Step("longitudinal creepage, right wheel: (V + a ψ̇ − ω_y r_R)/V", _eq("gamma_xR", g_xR)),
            Step("lateral creepage, both wheels", _eq("gamma_y", g_y)),
            Step("spin creepage, left wheel: (ψ̇ cos ϑ_L − ω_y sin ϑ_L)/V, small ϑ_L", _eq("varphi_L", p_L)),
            Step("spin creepage, right wheel: (ψ̇ cos ϑ_R + ω_y sin ϑ_R)/V, small ϑ_R", _eq("varphi_R", p_R)),
            Step("Kalker: longitudinal creep force, left wheel", _eq("F_xL", Fx_L)),
            Step("Kalker: lateral creep force, left wheel", _eq("F_yL", Fy_L)),
            Step("Kalker: spin moments of both wheels", _eq("M_z", Mz)),
            Step("lateral component of the left normal force", _eq("N_yL", Fn_L)),
            Step("lateral component of the right normal force", _eq("N_yR", Fn_R)),
        ),
    }


def _forces(contact: dict, y, psi, a, rail_yaw) -> tuple:
    """Generalized forces of the contact forces by virtual work: the creep forces at the contact
    points (±a along the axle; the lateral ones along the axle itself), the spin moments about z,
    the normal forces across the rails (turned by ``rail_yaw``) at the contact points.

    Returns Q, and the part of it that the spin of the contact-angle difference gives (the terms
    in f₂₃ and f₃₃ that the offset y − y_t moves), for a step to show.
    """
    Fx_L, Fx_R, Fy_L, Fy_R, Mz, Fn_L, Fn_R = contact["pairs"]
    q = [y, psi]

    # sin and cos to second order in the angles: enough for a force that does not vanish at rest
    # (the normal forces' W ϑ₀/2) to give its first-order generalized force.
    def sin(angle):
        return angle

    def cos(angle):
        return 1 - sympy.Rational(1, 2) * angle**2

    def across_rails(side):
        # Displacement across the rails of the contact point at ±a along the axle.
        px, py = -side * a * sin(psi), y + side * a * cos(psi)
        return sympy.expand(-px * sin(rail_yaw) + py * cos(rail_yaw))

    pairs = [
        (Fx_L, -a * sin(psi)),
        (Fx_R, a * sin(psi)),
        # along the axle: they work through δy (cos ψ δy, to first order)
        (Fy_L, y),
        (Fy_R, y),
        (Mz, psi),
        (Fn_L, across_rails(1)),
        (Fn_R, across_rails(-1)),
    ]
    return generalized_forces([(sympy.expand(f), u) for f, u in pairs], q).applyfunc(sympy.expand)


def _parameters(s: dict, source) -> tuple:
    return tuple((symbol, source(field)) for symbol, field in s.values())


@functools.cache
def tangent_wheelset() -> Derivation:
    """The wheelset on its primary suspension to a frame running straight at V (book ch. 5).

    Coordinates q = [y, ψ] (m, rad), inputs w = [y_t, Δz]: the alignment (lateral position of the
    track's centre line, m) and the cross-level (left rail height less the right, m) at the
    wheelset, as :meth:`raildyn.wheelset.Wheelset.linear_system` takes them. The rolling radii
    r₀ ± λ(y − y_t) and contact angles ϑ₀ ± ε(y − y_t)/a give the slip velocity of each contact
    point, hence the creepages γ_x = ∓(aψ̇/V + λ(y − y_t)/r₀), γ_y = ẏ/V − ψ and the spin
    φ = ψ̇ cos ϑ/V ∓ sin ϑ/r₀ ≈ ψ̇/V ∓ ϑ/r₀ (small contact angles, as in the normal forces);
    Kalker's linear law gives each wheel F_x = −f₁₁γ_x, F_y = −f₂₂γ_y − f₂₃φ, M_z = f₂₃γ_y − f₃₃φ
    (Kalker 1967); the normal forces W/2, tilted by ϑ and
    by the cross-level's roll Δz/(2a_r) (2a_r the rail spacing), give the lateral gravitational
    stiffness Wε/a, the yaw one −Waϑ₀ and the load −W Δz/(2a_r) (Wickens 1965; Garg & Dukkipati 1984,
    ch. 5). The spin of the
    contact-angle difference, ∓ε(y − y_t)/(a r₀) on the two wheels, adds the lateral force
    2f₂₃ε(y − y_t)/(a r₀) and the yaw moment 2f₃₃ε(y − y_t)/(a r₀) (shown in a step). Lagrange's
    equations with T = ½mẏ² + ½I_zψ̇², the suspension's U and D, and the contact forces by virtual
    work give M q̈ + (C₀ + C₁/V) q̇ + K q = G_K w.

    Left out, as the package leaves them out: the gyroscopic couple of the spinning axle and the
    change of the normal loads.

    Returns
    -------
    Derivation
        Parameters read from a :class:`raildyn.wheelset.Wheelset`; ``speed`` V (m/s).

    Examples
    --------
    >>> from raildyn.wheelset import Wheelset
    >>> ws = Wheelset()
    >>> m = ws.matrices(30.0)
    >>> tangent_wheelset().difference((m.M, m.C, m.K, m.GK, m.GC), ws, 30.0) < 1e-14
    True
    """
    s = _symbols()
    m, I_z, a = s["m"][0], s["I_z"][0], s["a"][0]
    k_y, k_psi, c_y, c_psi = (s[k][0] for k in ("k_y", "k_psi", "c_y", "c_psi"))
    V = sympy.Symbol("V", positive=True)
    y, psi = coordinates("y psi")
    y_t, z_c = coordinates(r"y_t \Delta{}z")  # the cross-level Δz
    yd, psid = y.diff(time), psi.diff(time)
    contact = _contact(s, y, psi, yd, psid, V, y - y_t, 0, 0, z_c / (2 * RAIL_HALF_SPACING))
    Q = _forces(contact, y, psi, a, 0)
    T = m * yd**2 / 2 + I_z * psid**2 / 2
    U = k_y * y**2 / 2 + k_psi * psi**2 / 2
    D = c_y * yd**2 / 2 + c_psi * psid**2 / 2
    M, C, K, GK, GC = lagrange(T, U, D, [y, psi], forces=Q, inputs=[y_t, z_c])
    q = sympy.Matrix([y, psi])
    linear_Q = (-(C - sympy.diag(c_y, c_psi)) * q.diff(time) - (K - sympy.diag(k_y, k_psi)) * q).applyfunc(
        sympy.expand
    )
    eps, f23, f33 = (s[k][0] for k in ("varepsilon", "f_23", "f_33"))

    def contact_angle_spin(entry):
        return sum(t for t in sympy.Add.make_args(entry) if t.has(eps) and (t.has(f23) or t.has(f33)))

    return Derivation(
        title="wheelset on its primary suspension, tangent track",
        coordinates=(y, psi),
        inputs=(y_t, z_c),
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=(*_parameters(s, lambda field: field), RAIL_PAIR),
        speed=V,
        steps=(
            *contact["steps"],
            Step("generalized forces of the contact (y_t = Δz = 0), lateral and yaw", _eq("Q", linear_Q)),
            Step(
                "of which the spin of the contact-angle difference (y_t = Δz = 0)",
                _eq("Q_spin", linear_Q.applyfunc(contact_angle_spin)),
            ),
            Step("kinetic energy", _eq("T", T)),
            Step("potential energy of the primary springs", _eq("U", U)),
            Step("Rayleigh's dissipation function of the primary dampers", _eq("D", D)),
        ),
    )


def _wheelset_field(field: str):
    """A getter of a Wheelset's field from a Wheelset (at x = 0) or a pair (Wheelset, x)."""

    def get(model):
        return getattr(model[0] if isinstance(model, tuple) else model, field)

    return get


def _position(model):
    return model[1] if isinstance(model, tuple) else 0.0


@functools.cache
def curved_wheelset() -> Derivation:
    """The wheelset on a curve of curvature κ = 1/R with cant h_t, in axes that follow the vehicle.

    The axes' origin runs along the track's centre line at V, x along its tangent, and the axes
    turn at Vκ. The wheelset sits x ahead of the origin (0 for a lone wheelset, ±b in a bogie),
    where the centre line is displaced by y_t = x²κ/2 and turned by ψ_t = xκ, and the path of a
    point fixed in the axes is turned by xκ. Its kinetic energy in these axes,
    T = ½m[(V − Vκy)² + (ẏ + Vκx)²] + ½I_z(ψ̇ + Vκ)², and the potential energy of its weight in
    the plane of the track rolled by h_t/(2a_r) (2a_r the rail spacing on which the cant is
    stated), −m g h_t y/(2a_r), give the inertia force −mV²κ and the weight's share
    m g h_t/(2a_r): together −m a_q, a_q = V²κ − g h_t/(2a_r) (the unbalanced lateral
    acceleration). The contact is that of :func:`tangent_wheelset` with y − y_t in the rolling
    radii and contact angles, ψ − xκ in the lateral creepage, the yaw rate ψ̇ + Vκ in the
    longitudinal and spin creepages, and the normal forces across the rails turned by ψ_t
    (Garg & Dukkipati 1984, ch. 5 and 8; Wickens 2003, ch. 7).

    Inputs w = [κ, h_t] (1/m, m). G_K's first column, less the inertia force −mV² on y, is
    R·:func:`raildyn.wheelset.curve_loads`; its second is m g/(2a_r) on y. G_C holds the Euler
    force and moment of a changing curvature, −m x V and −I_z V per unit κ̇, which the steady
    state does not see and :func:`raildyn.curving.steady.steady_curving` leaves out. The steps
    end with the free wheelset's steady offset, −r₀a κ/λ: the pure-rolling offset r₀a/(λR)
    towards the outer rail (:func:`raildyn.wheelset.pure_rolling_offset`).

    Returns
    -------
    Derivation
        Parameters read from a :class:`raildyn.wheelset.Wheelset` (the wheelset at x = 0) or a
        pair (Wheelset, x); g and 2a_r from :mod:`raildyn.constants` and
        :data:`raildyn.constants.STANDARD_RAIL_SPACING`; ``speed`` V (m/s).

    Examples
    --------
    >>> import numpy as np
    >>> from raildyn.wheelset import Wheelset, curve_loads
    >>> ws = Wheelset()
    >>> GK = curved_wheelset().numeric(ws, 30.0)[3]
    >>> bool(np.allclose(GK[:, 0] / 600.0 + [ws.mass * 30.0**2 / 600.0, 0.0], curve_loads(ws, 600.0)))
    True
    """
    s = _symbols()
    m, I_z, a, r0, lam = (s[k][0] for k in ("m", "I_z", "a", "r_0", "lambda"))
    k_y, k_psi, c_y, c_psi = (s[k][0] for k in ("k_y", "k_psi", "c_y", "c_psi"))
    V = sympy.Symbol("V", positive=True)
    x = sympy.Symbol("x", real=True)
    g, a_r = sympy.symbols("g a_r", positive=True)
    y, psi = coordinates("y psi")
    kappa, h_t = coordinates("kappa h_t")
    yd, psid = y.diff(time), psi.diff(time)
    y_t, psi_t = x**2 * kappa / 2, x * kappa
    contact = _contact(s, y, psi, yd, psid, V, y - y_t, x * kappa, V * kappa, 0)
    Q = _forces(contact, y, psi, a, psi_t)
    Omega = V * kappa
    T = m * ((V - Omega * y) ** 2 + (yd + Omega * x) ** 2) / 2 + I_z * (psid + Omega) ** 2 / 2
    U = k_y * y**2 / 2 + k_psi * psi**2 / 2 - m * g * h_t / (2 * a_r) * y
    Dr = c_y * yd**2 / 2 + c_psi * psid**2 / 2
    M, C, K, GK, GC = lagrange(sympy.expand(T), U, Dr, [y, psi], forces=Q, inputs=[kappa, h_t])
    # The steady state of the free, spin-free wheelset with no gravitational stiffness, at the
    # balance speed: K q = G_K w with the suspension, f₂₃, f₃₃, ε, ϑ₀ zero and h_t = 2a_r V²κ/g.
    ideal = {s[k][0]: 0 for k in ("k_y", "k_psi", "f_23", "f_33", "varepsilon", "vartheta_0")}
    balance = {h_t: 2 * a_r * V**2 * kappa / g, x: 0}
    w = sympy.Matrix([kappa, h_t])
    rest = sympy.Matrix(K.subs(ideal)).LUsolve(sympy.Matrix(GK.subs(ideal) * w).subs(balance))
    rest = rest.applyfunc(sympy.simplify)
    T_shown = sympy.expand(T)

    def field(name):
        return _wheelset_field(name)

    parameters = _parameters(s, field) + (
        (x, _position),
        (g, lambda model: GRAVITY),
        (a_r, lambda model: STANDARD_RAIL_SPACING / 2),
    )
    return Derivation(
        title="wheelset on its primary suspension, on a curve",
        coordinates=(y, psi),
        inputs=(kappa, h_t),
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=parameters,
        speed=V,
        steps=(
            Step("the track under the wheelset: offset", _eq("y_t", y_t)),
            Step("the track under the wheelset: turn", _eq("psi_t", psi_t)),
            *contact["steps"],
            Step("kinetic energy in the turning axes", _eq("T", T_shown)),
            Step("potential energy: springs and the weight on the canted track", _eq("U", U)),
            Step(
                "steady state of the free wheelset, no spin or gravity terms, at the balance speed",
                sympy.Eq(sympy.Matrix([sympy.Symbol("y"), sympy.Symbol("psi")]), rest),
            ),
        ),
    )


@functools.cache
def critical_speed_limit() -> tuple:
    """Wickens' critical speed of the suspended wheelset, derived from :func:`tangent_wheelset`.

    The characteristic equation det(s²M + sC + K) = 0 of the wheelset is a quartic in s. With
    the spin, gravitational and damping terms removed and f₁₁ = f₂₂ = f, its Hurwitz condition
    a₃a₂a₁ − a₄a₁² − a₀a₃² > 0 (all roots in the left half-plane, the coefficients being positive)
    is, to leading order as f → ∞ (order f⁴), a bound on the speed:

        V² < V_c² = (a r₀ / λ) · (k_ψ + a² k_y) / (I_z + m a²)

    (Wickens 1965; Wickens 2003, ch. 3), as :func:`raildyn.wheelset.wickens_critical_speed`
    evaluates it.

    Returns
    -------
    tuple of Step
        The characteristic polynomial, its coefficients in the reduced case, the Hurwitz
        expression, its leading term in f, and V_c² (the last step's right-hand side, in the
        symbols of :func:`tangent_wheelset`'s parameters).

    Examples
    --------
    >>> critical_speed_limit()[-1].equation.lhs
    V_c**2
    """
    d = tangent_wheelset()
    s_ = sympy.Symbol("s")
    f = sympy.Symbol("f", positive=True)
    V = d.speed
    names = {symbol.name: symbol for symbol, _ in d.parameters}
    reduced = {names[k]: 0 for k in ("f_23", "f_33", "vartheta_0", "varepsilon", "c_y", "c_psi")}
    reduced.update({names["f_11"]: f, names["f_22"]: f})
    A = s_**2 * d.M + s_ * d.C + d.K
    P = sympy.expand(A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0])
    coefficients = sympy.Poly(sympy.expand(P.subs(reduced)), s_).all_coeffs()
    a4, a3, a2, a1, a0 = coefficients
    H = sympy.expand(a3 * a2 * a1 - a4 * a1**2 - a0 * a3**2)
    lead = sympy.factor(sympy.Poly(H, f).LC())
    # The one factor that changes sign with the speed.
    (bracket,) = [m for m in sympy.Mul.make_args(lead) if m.has(V) and m.has(names["lambda"])]
    (V_c2,) = sympy.solve(bracket, V**2)
    a_symbols = sympy.symbols("a_4 a_3 a_2 a_1 a_0")
    return (
        Step("characteristic equation det(s²M + sC + K) = 0", sympy.Eq(sympy.collect(P, s_), 0)),
        *(
            Step(f"coefficient of s^{4 - i}: no spin, gravity or damping, f_11 = f_22 = f", sympy.Eq(ai, c))
            for i, (ai, c) in enumerate(zip(a_symbols, coefficients, strict=True))
        ),
        Step("Hurwitz condition for the quartic: > 0 when stable", _eq("H", H)),
        Step("its leading term as f grows (order f^4)", _eq("H_4", lead)),
        Step("the leading term changes sign at the critical speed", sympy.Eq(sympy.Symbol("V_c") ** 2, V_c2)),
    )
