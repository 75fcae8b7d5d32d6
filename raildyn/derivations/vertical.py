"""Chapter 6's vertical models derived: the passenger car, the freight car's rock and roll, the locomotive.

Each by Lagrange's equations (:func:`raildyn.derivations.lagrange`) from its kinetic energy T, the
potential energy U of its springs (and, for the freight car, of its weight), and Rayleigh's
dissipation function D of its dampers, every spring end's height written in the coordinates. The
coordinates are measured from the static equilibrium, where the springs' preload carries the weight;
a point x ahead of a body's centre rises by z + x sin θ (θ > 0 raises the front), a point y to the
left of the freight car's roll axis by y sin φ (φ > 0 raises the left side). Since sin θ = θ + O(θ³),
z + xθ holds to second order, which is all that linear equations of motion need, even with the
springs' preload (the preload works only through second-order terms of the deflections, and there
are none). The track input w_j is the rail height under wheelset j (rigid wheel–rail contact: the
wheelsets follow the rails and carry no dynamics of their own), met s_j/V after the leading
wheelset, s_j its distance behind it.

The tests hold the derived matrices to :class:`raildyn.vehicles.VerticalCar`,
:class:`raildyn.vehicles.freight.VerticalFreightCar` and
:class:`raildyn.vehicles.locomotive.VerticalLocomotive`.
"""

from __future__ import annotations

import functools

import sympy

from raildyn.constants import GRAVITY
from raildyn.derivations._core import Derivation, Step, coordinates, lagrange, time

__all__ = ["freight_rock_and_roll", "vertical_car", "vertical_locomotive"]


def _eq(name: str, value) -> sympy.Eq:
    return sympy.Eq(sympy.Symbol(name), value, evaluate=False)


def _delays(w, behind, rails=("z_v",)) -> Step:
    """The step w_j(t) = z_v(t − s_j/V): input j meets the track s_j behind the leading wheelset.

    ``rails`` names the profile of each input in turn (repeated): ("z_L", "z_R") for the left and
    right rail, z_v for a vertical profile that both rails share (chapter 3's names).
    """
    V = sympy.Symbol("V", positive=True)
    profiles = [sympy.Function(rails[j % len(rails)]) for j in range(len(w))]
    return Step(
        "track inputs: the rail heights met s_j behind the leading wheelset, s_j/V later",
        sympy.Eq(
            sympy.Matrix(w),
            sympy.Matrix([u(time - s / V) for u, s in zip(profiles, behind, strict=True)]),
            evaluate=False,
        ),
    )


def _body_on_two_trucks(title: str, truck: str, axles: int, spacing: str, paths: dict) -> Derivation:
    """A body bouncing and pitching on two trucks, each on ``axles`` equally spaced wheelsets.

    The axles of a truck stand at x = b, …, −b from its centre (``axles`` = 2: ±b; 3: b, 0, −b);
    the trucks' centres at x = ±l from the body's. ``paths`` maps each parameter name to where the
    model holds it.
    """
    z_c, th_c, z_1, th_1, z_2, th_2 = coordinates(
        f"z_c theta_c z_{truck}1 theta_{truck}1 z_{truck}2 theta_{truck}2"
    )
    n_in = 2 * axles
    w = coordinates(" ".join(f"w_{j + 1}" for j in range(n_in)))
    m_c, I_c = sympy.symbols("m_c I_c", positive=True)
    m_t, I_t = sympy.symbols(f"m_{truck} I_{truck}", positive=True)
    l, b, k_p, k_s = sympy.symbols("l b k_p k_s", positive=True)
    c_p, c_s = sympy.symbols("c_p c_s", nonnegative=True)
    q = (z_c, th_c, z_1, th_1, z_2, th_2)

    def rate(e):
        return e.diff(time)

    def height(z, theta, x):  # a point x ahead of a body's centre: z + x sin θ, to first order
        return z + x * theta

    # Axle positions ahead of their truck's centre: b, ..., −b (equally spaced).
    offsets = [b - 2 * b * i / (axles - 1) for i in range(axles)]
    secondary, primary, ahead = [], [], []
    for z, th, x_t in ((z_1, th_1, l), (z_2, th_2, -l)):
        # secondary spring: the truck's centre against the point of the body above it
        secondary.append(z - height(z_c, th_c, x_t))
        for x in offsets:
            # primary spring: the axlebox on the truck against the rail height under the wheelset
            primary.append(height(z, th, x) - w[len(primary)])
            ahead.append(x_t + x)
    T = (m_c * rate(z_c) ** 2 + I_c * rate(th_c) ** 2) / 2 + sum(
        (m_t * rate(z) ** 2 + I_t * rate(th) ** 2) / 2 for z, th in ((z_1, th_1), (z_2, th_2))
    )
    U = (k_s * sum(u**2 for u in secondary) + k_p * sum(u**2 for u in primary)) / 2
    D = (c_s * sum(rate(u) ** 2 for u in secondary) + c_p * sum(rate(u) ** 2 for u in primary)) / 2
    M, C, K, GK, GC = lagrange(T, U, D, q, inputs=w)
    s = [sympy.expand(ahead[0] - x) for x in ahead]
    symbols = {"m_c": m_c, "I_c": I_c, "m_t": m_t, "I_t": I_t, "l": l, "b": b}
    symbols |= {"k_p": k_p, "c_p": c_p, "k_s": k_s, "c_s": c_s}
    return Derivation(
        title=title,
        coordinates=q,
        inputs=w,
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=tuple((symbols[name], path) for name, path in paths.items()),
        steps=(
            Step(
                "secondary deflections (truck centre below the body at x = ±l)",
                sympy.Eq(sympy.Matrix(sympy.symbols("u_s1 u_s2")), sympy.Matrix(secondary), evaluate=False),
            ),
            Step(
                f"primary deflections (axle over the rail, {spacing})",
                sympy.Eq(
                    sympy.Matrix(sympy.symbols(f"u_p1:{n_in + 1}")), sympy.Matrix(primary), evaluate=False
                ),
            ),
            Step("kinetic energy", _eq("T", T)),
            Step("potential energy of the springs", _eq("U", U)),
            Step("Rayleigh's dissipation function", _eq("D", D)),
            _delays(w, s),
        ),
    )


@functools.cache
def vertical_car() -> Derivation:
    """The passenger car in the vertical plane: body and two bogies, each bouncing and pitching.

    Coordinates q = (z_c, θ_c, z_b1, θ_b1, z_b2, θ_b2), m and rad, front bogie first; inputs w₁…w₄ the
    rail heights under the four wheelsets, leading first. The secondary suspension (k_s, c_s per bogie)
    joins each bogie's centre to the body at x = ±l; the primary (k_p, c_p per wheelset) joins each
    axle, at x = ±b from its bogie's centre, to the rail under it. With the deflections
    u_s = z_b − (z_c ± l θ_c) and u_p = z_b ± b θ_b − w_j,

        T = ½ m_c ż_c² + ½ I_c θ̇_c² + Σ (½ m_b ż_b² + ½ I_b θ̇_b²),
        U = ½ k_s Σ u_s² + ½ k_p Σ u_p²,   D = ½ c_s Σ u̇_s² + ½ c_p Σ u̇_p²,

    and Lagrange's equations give M q̈ + C q̇ + K q = G_K w + G_C ẇ (chapter 6's vertical car; the
    Manchester benchmark vehicle's layout, Iwnicki 1998). Wheelset j lies s_j = 0, 2b, 2l, 2l + 2b
    behind the leading one, so w_j(t) = z_v(t − s_j/V) for a vertical track profile z_v.

    Returns
    -------
    Derivation
        Parameters read from a :class:`raildyn.vehicles.VerticalCar`.

    Examples
    --------
    >>> from raildyn.vehicles import VerticalCar
    >>> m = VerticalCar().matrices(30.0)
    >>> vertical_car().difference((m.M, m.C, m.K, m.GK, m.GC), VerticalCar()) < 1e-14
    True
    """
    return _body_on_two_trucks(
        "passenger car in the vertical plane",
        "b",
        2,
        "at ±b from the bogie's centre",
        {
            "m_c": "body_mass",
            "I_c": "body_pitch_inertia",
            "m_t": "bogie_mass",
            "I_t": "bogie_pitch_inertia",
            "l": "semi_bogie_spacing",
            "b": "semi_wheelbase",
            "k_p": "primary_stiffness",
            "c_p": "primary_damping",
            "k_s": "secondary_stiffness",
            "c_s": "secondary_damping",
        },
    )


@functools.cache
def vertical_locomotive() -> Derivation:
    """The six-axle locomotive in the vertical plane: body and two three-axle trucks, bouncing and pitching.

    As :func:`vertical_car`, with trucks (m_t, I_t) in place of bogies and three axles per truck at
    x = b, 0, −b from its centre (b the axle spacing, which is the truck's semi-wheelbase). Wheelset j
    lies s_j = 0, b, 2b, 2l, 2l + b, 2l + 2b behind the leading one.

    Returns
    -------
    Derivation
        Parameters read from a :class:`raildyn.vehicles.locomotive.VerticalLocomotive`.

    Examples
    --------
    >>> from raildyn.vehicles.locomotive import VerticalLocomotive
    >>> m = VerticalLocomotive().matrices(30.0)
    >>> vertical_locomotive().difference((m.M, m.C, m.K, m.GK, m.GC), VerticalLocomotive()) < 1e-14
    True
    """
    return _body_on_two_trucks(
        "six-axle locomotive in the vertical plane",
        "t",
        3,
        "at b, 0, −b from the truck's centre",
        {
            "m_c": "body_mass",
            "I_c": "body_pitch_inertia",
            "m_t": "truck_mass",
            "I_t": "truck_pitch_inertia",
            "l": "semi_truck_spacing",
            "b": "axle_spacing",
            "k_p": "primary_stiffness",
            "c_p": "primary_damping",
            "k_s": "secondary_stiffness",
            "c_s": "secondary_damping",
        },
    )


@functools.cache
def freight_rock_and_roll() -> Derivation:
    """The freight car's body bouncing, pitching and rolling on its four spring nests (linear model).

    Coordinates q = (z, θ, φ): the height of the body's pitch and roll axes, which lie in the spring
    plane (m), the pitch (rad, front up) and the roll (rad, left side up). The nests stand at x = ±l (the
    truck centres) and y = ±d (the side frames, left positive); each carries k and, in the linear
    model, the viscous c that stands for its wedges. A side frame rides on its two wheels, so the
    nest on it is pushed up by the mean of the two rail heights under them: with w₁…w₈ the rail
    heights axle by axle, left rail first, the nest deflects by

        u = z + x θ + y φ − ½ (w on that rail under the leading axle + under the trailing axle).

    The body turns about axes in the spring plane, where the trucks hold it at its centre plates,
    and its centre of gravity lies h above them; pitching by θ and rolling by φ move it to
    (−h sin θ, −h sin φ, z + h cos θ cos φ), so the body's weight adds U_g = m g z_G, whose
    ½ (−m g h)(θ² + φ²) lowers the pitch stiffness to 4 k l² − m g h and the roll stiffness to
    4 k d² − m g h (chapter 6's rock and roll).

        T = ½ m (ẋ_G² + ẏ_G² + ż_G²) + ½ I_θ θ̇² + ½ I_φ φ̇²,
        U = ½ k Σ u² + m g z_G,   D = ½ c Σ u̇²,

    with I_θ and I_φ the inertias about the centre of gravity; Lagrange's equations then give the
    inertias about the axes in the spring plane, I + m h², by the parallel-axis theorem.

    Returns
    -------
    Derivation
        Parameters read from a :class:`raildyn.vehicles.freight.VerticalFreightCar` (d is its
        ``semi_spring_spacing``, l its ``semi_truck_spacing``, c its ``equivalent_damping``).

    Examples
    --------
    >>> from raildyn.vehicles.freight import VerticalFreightCar
    >>> car = VerticalFreightCar(equivalent_damping=2e4)
    >>> m = car.matrices(20.0)
    >>> freight_rock_and_roll().difference((m.M, m.C, m.K, m.GK, m.GC), car) < 1e-14
    True
    """
    z, th, ph = q = coordinates("z theta phi")
    w = coordinates(" ".join(f"w_{j + 1}" for j in range(8)))
    m, I_th, I_ph, l, b, d, k = sympy.symbols("m I_theta I_phi l b d k", positive=True)
    h, c = sympy.symbols("h c", nonnegative=True)
    g = sympy.Symbol("g", positive=True)
    zd, thd, phd = (v.diff(time) for v in q)
    # The centre of gravity h above the axes in the spring plane, those at height z: (−h sin θ, −h sin φ,
    # z + h cos θ cos φ), the cosines to second order, which the weight's potential needs.
    x_g, y_g, z_g = -h * th, -h * ph, z + h * (1 - th**2 / 2 - ph**2 / 2)
    T = m * (x_g.diff(time) ** 2 + y_g.diff(time) ** 2 + z_g.diff(time) ** 2) / 2
    T += I_ph * phd**2 / 2 + I_th * thd**2 / 2
    nests = []
    for truck, x in enumerate((l, -l)):
        for side, y in enumerate((d, -d)):
            leading, trailing = w[4 * truck + side], w[4 * truck + 2 + side]
            nests.append(z + x * th + y * ph - (leading + trailing) / 2)
    U_springs = k * sum(u**2 for u in nests) / 2
    U_weight = m * g * z_g
    D = c * sum(u.diff(time) ** 2 for u in nests) / 2
    M, C, K, GK, GC = lagrange(T, U_springs + U_weight, D, q, inputs=w)
    return Derivation(
        title="freight car: body bounce, pitch and roll on four spring nests",
        coordinates=q,
        inputs=w,
        M=M,
        C=C,
        K=K,
        GK=GK,
        GC=GC,
        parameters=(
            (m, "body_mass"),
            (I_th, "body_pitch_inertia"),
            (I_ph, "body_roll_inertia"),
            (h, "cg_height"),
            (l, "semi_truck_spacing"),
            (b, "semi_truck_wheelbase"),
            (d, "semi_spring_spacing"),
            (k, "nest_stiffness"),
            (c, "equivalent_damping"),
            (g, lambda model: GRAVITY),
        ),
        steps=(
            Step(
                "nest deflections (front truck first, left nest first)",
                sympy.Eq(sympy.Matrix(sympy.symbols("u_1:5")), sympy.Matrix(nests), evaluate=False),
            ),
            Step(
                "centre of gravity (longitudinal, lateral, vertical)",
                sympy.Eq(
                    sympy.Matrix(sympy.symbols("x_G y_G z_G")), sympy.Matrix([x_g, y_g, z_g]), evaluate=False
                ),
            ),
            Step("kinetic energy", _eq("T", T)),
            Step("potential energy of the nests and of the weight", _eq("U", U_springs + U_weight)),
            Step("Rayleigh's dissipation function", _eq("D", D)),
            # the left and right rail under axles 0, 2b, 2l, 2l + 2b behind the leading one
            _delays(w, [s for s in (0, 2 * b, 2 * l, 2 * l + 2 * b) for _ in range(2)], ("z_L", "z_R")),
        ),
    )
