"""Chapter 8's steady curving derived: a suspended wheelset, a two-axle bogie, and the bogie's two
wheelsets joined by a bending and a shear stiffness.

A vehicle that runs steadily round a curve of radius R is at rest in axes that follow it (origin on the
track's centre line, x along the tangent there, y to the left, turning at V/R). In those axes the
equations of motion lose their time derivatives and become K q = G_K w, with the two inputs

    w = (κ, a_q):  κ = 1/R the curvature (1/m), a_q the unbalanced lateral acceleration (m/s²).

Each derivation builds the primary and secondary springs' strain energy U from where each spring's ends
are, the creep forces from the creepages written out wheel by wheel (Kalker's linear law), the
gravitational forces of the contact geometry and the outward force −m a_q on every mass, and calls
Lagrange's equations (:func:`raildyn.derivations.lagrange`) with T = D = 0, that is ∂U/∂q = Q
(M and C are zero matrices). The tests hold
K and G_K to the package's :func:`raildyn.curving.steady.steady_curving` (its stiffness matrix and
its loads, :func:`raildyn.wheelset.curve_loads` and −M r a_q) and to
:func:`raildyn.curving.stiffness.bending_shear_stiffness`.

Sources: Garg & Dukkipati (1984), ch. 5 and 8; Wickens (2003), ch. 7; Boocock (1969).
"""

from __future__ import annotations

import functools

import sympy

from raildyn.derivations._core import Derivation, Step, coordinates, generalized_forces, lagrange

__all__ = ["bending_shear", "bogie_curving", "wheelset_curving"]

# The contact's symbols, shared by the three derivations: per wheel f₁₁, f₂₂, f₂₃, f₃₃ (N, N·m, N·m²),
# a, r₀, λ, W, ε, ϑ₀ (m, m, -, N, -, rad).
_f11, _f22, _f23, _f33 = sympy.symbols("f_11 f_22 f_23 f_33", nonnegative=True)
_a, _r0 = sympy.symbols("a r_0", positive=True)
_lam, _W, _eps, _theta0 = sympy.symbols("lambda W varepsilon vartheta_0", nonnegative=True)
_k_y, _k_psi = sympy.symbols("k_y k_psi", nonnegative=True)  # primary, per wheelset
_b = sympy.Symbol("b", positive=True)  # semi-wheelbase
_CONTACT = ("f11", "f22", "f23", "f33", "half_gauge", "rolling_radius", "conicity", "axle_load")


def _contact_parameters(prefix: str) -> tuple:
    """(symbol, path) for the contact of a Wheelset reached through ``prefix`` ("" or "wheelset.")."""
    symbols = (_f11, _f22, _f23, _f33, _a, _r0, _lam, _W)
    pairs = tuple((s, prefix + n) for s, n in zip(symbols, _CONTACT, strict=True))
    return pairs + ((_eps, prefix + "contact_angle_parameter"), (_theta0, prefix + "contact_angle"))


def _wheelset_in_curve(y, psi, x, kappa):
    """The wheel–rail forces on a wheelset x ahead of the origin, at rest in the curve's axes.

    Returns the (force, displacement) pairs of its lateral force and yaw moment and the steps:
    the track under it, the creepages of its left (inner) and right (outer) wheel, the forces.
    """
    # The track's centre line x ahead of the origin (a small-angle arc): displaced by x²κ/2 and
    # turned by xκ; the wheelset's displacement and yaw relative to it.
    y_t, psi_t = x**2 * kappa / 2, x * kappa
    y_r, psi_r = y - y_t, psi - psi_t
    # At rest in axes turning at Vκ: ẏ = 0, and the wheelset's yaw rate is Ω = Vκ. Rolling radii
    # r₀ ± λ y_r (left, right). Left wheel at +a moves forwards at V − aΩ, the right at V + aΩ,
    # while rolling at ω = V/r₀; so, dividing by V (every creepage is speed-free here):
    gx_L = -_a * kappa - _lam * y_r / _r0  # (V − aΩ − ω r_L)/V
    gx_R = _a * kappa + _lam * y_r / _r0  # (V + aΩ − ω r_R)/V
    gy = -psi_r  # (ẏ − V ψ_r)/V on both wheels
    # Spin Ω/V ∓ ϑ/r₀ at the contact angles ϑ₀ ± εy_r/a (first order): the ϑ₀ parts cancel over the
    # two wheels, the difference 2εy_r/a does not.
    spin_L = kappa - (_theta0 + _eps * y_r / _a) / _r0
    spin_R = kappa + (_theta0 - _eps * y_r / _a) / _r0
    # Kalker's linear law on each wheel, forces on the wheel: F_x = −f₁₁γ_x, F_y = −f₂₂γ_y − f₂₃φ,
    # M_z = f₂₃γ_y − f₃₃φ; the longitudinal forces at ±a turn the wheelset by −a F_xL + a F_xR.
    Fx_L, Fx_R = -_f11 * gx_L, -_f11 * gx_R
    F_creep = 2 * (-_f22 * gy) - _f23 * (spin_L + spin_R)
    M_creep = -_a * Fx_L + _a * Fx_R + 2 * _f23 * gy - _f33 * (spin_L + spin_R)
    # Gravitational forces of the contact geometry (chapter 5): the rails' normal forces, tilted by
    # the contact angles ϑ₀ ± εy/a, push the displaced wheelset back (W ε/a) and their longitudinal
    # components yaw it further (W a ϑ₀).
    F_grav = -_W * _eps / _a * y_r
    M_grav = _W * _a * _theta0 * psi_r
    Fy, Mz = sympy.expand(F_creep + F_grav), sympy.expand(M_creep + M_grav)
    gamma_y = sympy.Symbol("gamma_y")
    steps = (
        Step("the track under the wheelset: displaced and turned",
             sympy.Eq(sympy.Matrix(sympy.symbols("y_t psi_t")), sympy.Matrix([y_t, psi_t]))),
        Step("longitudinal creepage, left (inner) and right (outer) wheel",
             sympy.Eq(sympy.Matrix([sympy.Symbol("gamma_xL"), sympy.Symbol("gamma_xR")]),
                      sympy.Matrix([gx_L, gx_R]))),
        Step("lateral creepage, each wheel", sympy.Eq(gamma_y, gy)),
        Step("spin, left (inner) and right (outer) wheel",
             sympy.Eq(sympy.Matrix([sympy.Symbol("varphi_L"), sympy.Symbol("varphi_R")]),
                      sympy.Matrix([spin_L, spin_R]))),
        Step("lateral force on the wheelset (creep and gravitational)", sympy.Eq(sympy.Symbol("F_y"), Fy)),
        Step("yaw moment on the wheelset (creep and gravitational)", sympy.Eq(sympy.Symbol("M_z"), Mz)),
    )  # fmt: skip
    return [(Fy, y), (Mz, psi)], steps


def _matrix_step(name: str, matrix) -> sympy.Eq:
    """name = matrix, as an equation that prints (an Eq of a plain Symbol and a Matrix is False)."""
    return sympy.Eq(sympy.MatrixSymbol(name, *matrix.shape), matrix)


def _inputs():
    kappa, a_q = coordinates("kappa a_q")
    return kappa, a_q


@functools.cache
def wheelset_curving() -> Derivation:
    """A wheelset on its primary springs, steady in a curve (chapter 8; chapter 5's suspended wheelset).

    The springs (k_y lateral, k_ψ yaw, totals per wheelset) tie the wheelset to a frame that runs
    square to the track in the curve's axes (the origin at the wheelset). K q = G_K (κ, a_q) with
    q = (y, ψ) in those axes; G_K's first column is the curve's creep loads
    (:func:`raildyn.wheelset.curve_loads` per unit κ), its second −m (the outward force per unit a_q).

    Returns
    -------
    Derivation
        M and C zero; parameters read from a :class:`raildyn.wheelset.Wheelset`.

    Examples
    --------
    >>> d = wheelset_curving()
    >>> d.labels
    ('y', 'psi')
    >>> d.K[0, 1]  # the lateral creep force of the yaw: −2f₂₂
    -2*f_22
    """
    y, psi = coordinates("y psi")
    kappa, a_q = _inputs()
    m = sympy.Symbol("m", positive=True)
    U = _k_y * y**2 / 2 + _k_psi * psi**2 / 2
    pairs, steps = _wheelset_in_curve(y, psi, 0, kappa)
    Q = generalized_forces(pairs + [(-m * a_q, y)], [y, psi])
    M, C, K, GK, GC = lagrange(0, U, 0, (y, psi), forces=Q, inputs=(kappa, a_q))
    return Derivation(
        title="suspended wheelset, steady in a curve",
        coordinates=(y, psi),
        inputs=(kappa, a_q),
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=_contact_parameters("")
        + ((_k_y, "lateral_stiffness"), (_k_psi, "yaw_stiffness"), (m, "mass")),
        steps=(Step("strain energy of the primary springs", sympy.Eq(sympy.Symbol("U"), U)),)
        + steps
        + (Step("generalized forces (virtual work), outward force −m a_q included",
                _matrix_step("Q", Q)),),
    )  # fmt: skip


@functools.cache
def bogie_curving() -> Derivation:
    """A two-axle bogie under a body that runs round the curve without moving, steady in the curve.

    Coordinates in the order of :meth:`raildyn.vehicles.lateral.Bogie.linear_system`: the frame's y_f, ψ_f,
    then y₁, ψ₁ of the leading wheelset (x = +b) and y₂, ψ₂ of the trailing one (x = −b), all in the
    curve's axes with their origin at the bogie's centre. The primary springs stretch by the
    wheelset's displacement less the frame's at the axle, y_i − y_f − x_i ψ_f, and by ψ_i − ψ_f; the
    secondary springs tie the frame to the body (k_sy, k_sψ). K q = G_K (κ, a_q).

    Returns
    -------
    Derivation
        M and C zero; parameters read from a :class:`raildyn.vehicles.Bogie`.

    Examples
    --------
    >>> d = bogie_curving()
    >>> d.K[0, 0]  # frame lateral: two primary springs and the secondary
    k_sy + 2*k_y
    """
    y_f, psi_f, y1, psi1, y2, psi2 = q = coordinates("y_f psi_f y_1 psi_1 y_2 psi_2")
    kappa, a_q = _inputs()
    m_w, m_f = sympy.symbols("m_w m_f", positive=True)
    k_sy, k_spsi = sympy.symbols("k_sy k_spsi", nonnegative=True)
    U = (
        _k_y * ((y1 - y_f - _b * psi_f) ** 2 + (y2 - y_f + _b * psi_f) ** 2) / 2
        + _k_psi * ((psi1 - psi_f) ** 2 + (psi2 - psi_f) ** 2) / 2
        + k_sy * y_f**2 / 2
        + k_spsi * psi_f**2 / 2
    )
    lead, lead_steps = _wheelset_in_curve(y1, psi1, _b, kappa)
    trail, _ = _wheelset_in_curve(y2, psi2, -_b, kappa)
    outward = [(-m_f * a_q, y_f), (-m_w * a_q, y1), (-m_w * a_q, y2)]
    Q = generalized_forces(lead + trail + outward, list(q))
    M, C, K, GK, GC = lagrange(0, U, 0, q, forces=Q, inputs=(kappa, a_q))
    return Derivation(
        title="two-axle bogie, steady in a curve",
        coordinates=q,
        inputs=(kappa, a_q),
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=_contact_parameters("wheelset.")
        + (
            (_k_y, "wheelset.lateral_stiffness"),
            (_k_psi, "wheelset.yaw_stiffness"),
            (k_sy, "secondary_lateral_stiffness"),
            (k_spsi, "secondary_yaw_stiffness"),
            (_b, "semi_wheelbase"),
            (m_w, "wheelset.mass"),
            (m_f, "frame_mass"),
        ),
        steps=(
            Step("strain energy of the primary and secondary springs", sympy.Eq(sympy.Symbol("U"), U)),
            *(Step(f"leading wheelset (x = +b): {s.caption}", s.equation) for s in lead_steps),
        ),
    )


@functools.cache
def bending_shear() -> Derivation:
    """The bogie's two wheelsets joined by a bending and a shear stiffness, steady in a curve.

    The frame, with no secondary springs and no load of its own, settles where the primary springs'
    strain energy U is least: ∂U/∂y_f = ∂U/∂ψ_f = 0, solved here. What is left is
    U_min = ½k_b(ψ₁ − ψ₂)² + ½k_sh(y₁ − y₂ − b(ψ₁ + ψ₂))² with k_b = k_ψ/2 and
    k_sh = k_y k_ψ/(2(k_ψ + b²k_y)) (Wickens 2003, ch. 7; Boocock 1969), shown as steps. With the
    creep and gravitational forces of each wheelset, K q = G_K κ for q = (y₁, ψ₁, y₂, ψ₂) at the
    balance speed (a_q = 0).

    Returns
    -------
    Derivation
        M and C zero; parameters read from a :class:`raildyn.vehicles.Bogie` (its secondary springs
        play no part). Its K is the bogie's stiffness matrix with the frame condensed out (the
        Schur complement), when the bogie's secondary springs are zero.

    Examples
    --------
    >>> d = bending_shear()
    >>> d.K[0, 2]  # the shear spring between the lateral displacements: −k_sh
    -k_psi*k_y/(2*b**2*k_y + 2*k_psi)
    """
    y1, psi1, y2, psi2 = q = coordinates("y_1 psi_1 y_2 psi_2")
    (kappa,) = coordinates("kappa")
    y_f, psi_f = sympy.symbols("y_f psi_f")
    U = (
        _k_y * ((y1 - y_f - _b * psi_f) ** 2 + (y2 - y_f + _b * psi_f) ** 2) / 2
        + _k_psi * ((psi1 - psi_f) ** 2 + (psi2 - psi_f) ** 2) / 2
    )
    # U is quadratic in (y_f, ψ_f): its stationary point is one linear solve.
    A, rhs = sympy.linear_eq_to_matrix([sympy.diff(U, y_f), sympy.diff(U, psi_f)], [y_f, psi_f])
    frame = dict(zip((y_f, psi_f), (sympy.factor(v) for v in A.LUsolve(rhs)), strict=True))
    U_min = U.subs(frame)
    k_b, k_s = sympy.symbols("k_b k_sh", nonnegative=True)
    derived = {k_b: _k_psi / 2, k_s: _k_y * _k_psi / (2 * (_k_psi + _b**2 * _k_y))}
    reduced = k_b * (psi1 - psi2) ** 2 / 2 + k_s * (y1 - y2 - _b * (psi1 + psi2)) ** 2 / 2
    # The minimum is the bending–shear form: checked here, symbolically, every time it is built.
    if sympy.cancel(sympy.together(U_min - reduced.subs(derived))) != 0:  # pragma: no cover
        raise AssertionError("the frame's least-energy position does not give the bending-shear form")
    lead, _ = _wheelset_in_curve(y1, psi1, _b, kappa)
    trail, _ = _wheelset_in_curve(y2, psi2, -_b, kappa)
    Q = generalized_forces(lead + trail, list(q))
    # The equations with k_b and k_sh as symbols (for the step below), then k_b and k_sh replaced.
    M, C, K_bs, GK, GC = lagrange(0, reduced, 0, q, forces=Q, inputs=(kappa,))
    K = K_bs.subs(derived)
    return Derivation(
        title="two wheelsets joined by a bending and a shear stiffness, steady in a curve",
        coordinates=q,
        inputs=(kappa,),
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=_contact_parameters("wheelset.")
        + ((_k_y, "wheelset.lateral_stiffness"), (_k_psi, "wheelset.yaw_stiffness"), (_b, "semi_wheelbase")),
        steps=(
            Step("strain energy of the primary springs, frame at (y_f, ψ_f)", sympy.Eq(sympy.Symbol("U"), U)),
            Step("the frame where U is least (∂U/∂y_f = ∂U/∂ψ_f = 0)",
                 sympy.Eq(sympy.Matrix([y_f, psi_f]), sympy.Matrix([frame[y_f], frame[psi_f]]))),
            Step("what is left: a bending and a shear spring", sympy.Eq(sympy.Symbol("U_min"), reduced)),
            Step("bending stiffness", sympy.Eq(k_b, derived[k_b])),
            Step("shear stiffness", sympy.Eq(k_s, derived[k_s])),
            Step("stiffness matrix in k_b and k_sh", _matrix_step("K", K_bs)),
        ),
    )  # fmt: skip
