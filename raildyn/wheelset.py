"""The railway wheelset on tangent track (book chapter 5): kinematics, linear and nonlinear dynamics.

* Klingel's kinematic oscillation of a free coned wheelset and of a rigid
  two-axle bogie (:func:`kinematic_wavelength`, :func:`rigid_bogie_wavelength`);
* a :class:`Wheelset` parameter set and its linear lateral–yaw equations with
  Kalker's linear creep forces (f₁₁, f₂₂, f₂₃, f₃₃), gravitational stiffness
  and spin, on a primary suspension to a frame moving at the speed V
  (:func:`wheelset_matrices`, :func:`suspended_wheelset`);
* the speed-dependent second-order system :class:`LateralSystem` that the
  bogie and car models of :mod:`raildyn.vehicles` also produce, and that
  :mod:`raildyn.stability` sweeps over speed;
* the nonlinear wheelset (:class:`WheelRailContact`, :class:`NonlinearWheelset`):
  a rolling-radius difference Δr(y), saturating creep forces and a flange
  modelled as a stiff spring beyond the flangeway clearance, as ``rhs(t, y)``.

The contact geometry (Δr(y), contact-angle difference) enters as callables so
that the profiles of chapter 4 can be plugged in; the default is a cone of
conicity λ. Coordinates: x forward, y to the left, z up; ψ is the yaw angle
(positive turning to the left). SI units throughout.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from raildyn._checks import nonnegative, positive, scalar

GRAVITY = 9.81  # m/s²


# ---------------------------------------------------------------------------
# Kinematics


def kinematic_wavelength(rolling_radius, half_gauge, conicity) -> float:
    """Klingel's wavelength of a free coned wheelset rolling without slip, m.

    L = 2π √(r₀ a / λ) (Klingel 1883; Garg & Dukkipati 1984, ch. 5).

    Parameters
    ----------
    rolling_radius : float
        Centred rolling radius r₀, m (> 0).
    half_gauge : float
        Half the lateral distance between the two contact points a, m (> 0).
    conicity : float
        Equivalent conicity λ (> 0), dimensionless.

    Examples
    --------
    >>> round(kinematic_wavelength(0.46, 0.75, 0.05), 3)
    16.505
    """
    r0 = positive("rolling_radius", rolling_radius)
    a = positive("half_gauge", half_gauge)
    lam = positive("conicity", conicity)
    return float(2.0 * np.pi * np.sqrt(r0 * a / lam))


def rigid_bogie_wavelength(rolling_radius, half_gauge, conicity, semi_wheelbase) -> float:
    """Kinematic wavelength of two wheelsets held rigidly parallel in a bogie, m.

    L = 2π √(r₀ a / λ · (1 + b²/a²)), with b the half wheelbase (Wickens 2003,
    ch. 2): the rigid frame forces each wheelset to slide laterally as it yaws,
    which lengthens the wave.

    Examples
    --------
    >>> round(rigid_bogie_wavelength(0.46, 0.75, 0.05, 1.28), 3)
    32.647
    """
    b = positive("semi_wheelbase", semi_wheelbase)
    a = positive("half_gauge", half_gauge)
    return kinematic_wavelength(rolling_radius, half_gauge, conicity) * float(np.sqrt(1.0 + (b / a) ** 2))


# ---------------------------------------------------------------------------
# Creep coefficients


def kalker_creep_coefficients(shear_modulus, semi_axis_a, semi_axis_b, c11, c22, c23, c33):
    """Kalker's linear creep coefficients of one contact patch, (f₁₁, f₂₂, f₂₃, f₃₃).

    f₁₁ = G c² C₁₁, f₂₂ = G c² C₂₂, f₂₃ = G c³ C₂₃, f₃₃ = G c⁴ C₃₃ with c = √(ab)
    (Kalker 1967). Units: N, N, N·m, N·m².
    """
    G = positive("shear_modulus", shear_modulus)
    c = np.sqrt(positive("semi_axis_a", semi_axis_a) * positive("semi_axis_b", semi_axis_b))
    names = ("c11", "c22", "c23", "c33")
    coefficients = [nonnegative(name, v) for name, v in zip(names, (c11, c22, c23, c33), strict=True)]
    return (
        float(G * c**2 * coefficients[0]),
        float(G * c**2 * coefficients[1]),
        float(G * c**3 * coefficients[2]),
        float(G * c**4 * coefficients[3]),
    )


# Kalker's coefficients for a circular patch (a/b = 1) and Poisson's ratio 0.25, as tabulated by
# Kalker (1967, 1990): C11 = 4.12, C22 = 3.67, C23 = 1.47, C33 = 1.19. The patch radius of 6 mm
# is our choice, the order of a new wheel on a new rail under about 55 kN; G = 80 GPa for steel.
_DEFAULT_CREEP = kalker_creep_coefficients(8.0e10, 6.0e-3, 6.0e-3, 4.12, 3.67, 1.47, 1.19)

# Manchester benchmark vehicle (Iwnicki 1998, Table of vehicle 1 parameters): wheelset mass 1813 kg,
# yaw inertia 1120 kg·m², nominal rolling radius 0.46 m; primary stiffness per axlebox: lateral
# 3884 kN/m, longitudinal 31391 kN/m, at 1.0 m either side of the track centre line; primary damping
# per axlebox: lateral 2 kN·s/m, longitudinal 15 kN·s/m. Total vehicle mass 32000 + 2·2615 + 4·1813
# = 44482 kg, so the axle load is 44482·g/4.
_MANCHESTER_AXLE_LOAD = 44482.0 * GRAVITY / 4.0
_MANCHESTER_PRIMARY_YAW_SPACING = 1.0  # m, half the lateral distance between the primary springs


@dataclass(frozen=True)
class Wheelset:
    """A wheelset, its contact with the rails and its primary suspension to a frame.

    The defaults are one wheelset of the Manchester benchmark vehicle (Iwnicki
    1998) on a cone; the conicity (0.15) and contact half-spacing (0.75 m, the
    usual value for standard gauge) are our choice, not the benchmark's, which
    specifies real profiles. Creep coefficients are per contact patch (see
    ``_DEFAULT_CREEP`` for how they are evaluated).

    Attributes
    ----------
    mass : float
        m, kg.
    yaw_inertia : float
        I_z, kg·m².
    rolling_radius : float
        r₀, m.
    half_gauge : float
        a, half the distance between the contact points, m.
    conicity : float
        λ (≥ 0): Δr = r_L − r_R = 2λy for small y.
    axle_load : float
        W, total vertical load on the two wheels, N.
    f11, f22, f23, f33 : float
        Kalker's longitudinal (N), lateral (N), lateral–spin (N·m) and spin
        (N·m²) creep coefficients of one wheel.
    contact_angle : float or None
        δ₀, contact angle of the centred wheelset, rad (destabilising yaw
        gravitational stiffness −W a δ₀). None: λ, as for a cone on knife-edge rails.
    contact_angle_parameter : float or None
        ε with δ_L − δ_R = 2εy/a; lateral gravitational stiffness W ε / a.
        None: λ, the value for a cone on knife-edge rails.
    lateral_stiffness, yaw_stiffness : float
        Primary suspension, N/m and N·m/rad (total for the wheelset).
    lateral_damping, yaw_damping : float
        Primary suspension, N·s/m and N·m·s/rad.
    """

    mass: float = 1813.0
    yaw_inertia: float = 1120.0
    rolling_radius: float = 0.46
    half_gauge: float = 0.75
    conicity: float = 0.15
    axle_load: float = _MANCHESTER_AXLE_LOAD
    f11: float = _DEFAULT_CREEP[0]
    f22: float = _DEFAULT_CREEP[1]
    f23: float = _DEFAULT_CREEP[2]
    f33: float = _DEFAULT_CREEP[3]
    contact_angle: float | None = None
    contact_angle_parameter: float | None = None
    lateral_stiffness: float = 2 * 3884.0e3
    yaw_stiffness: float = 2 * 31391.0e3 * _MANCHESTER_PRIMARY_YAW_SPACING**2
    lateral_damping: float = 2 * 2.0e3
    yaw_damping: float = 2 * 15.0e3 * _MANCHESTER_PRIMARY_YAW_SPACING**2

    def __post_init__(self):
        for name in ("mass", "yaw_inertia", "rolling_radius", "half_gauge"):
            positive(name, getattr(self, name))
        for name in (
            "conicity",
            "axle_load",
            "f11",
            "f22",
            "f23",
            "f33",
            "lateral_stiffness",
            "yaw_stiffness",
            "lateral_damping",
            "yaw_damping",
        ):
            nonnegative(name, getattr(self, name))
        # A cone on knife-edge rails: the contact angle and ε both equal the cone's slope λ.
        for name in ("contact_angle", "contact_angle_parameter"):
            if getattr(self, name) is None:
                object.__setattr__(self, name, self.conicity)
        scalar("contact_angle", self.contact_angle, low=-0.5, high=0.5)
        scalar("contact_angle_parameter", self.contact_angle_parameter)

    def replace(self, **changes) -> Wheelset:
        """A copy with some fields changed (validated again).

        A contact angle or ε that followed the conicity keeps following it when
        only the conicity changes.
        """
        from dataclasses import replace

        if "conicity" in changes:
            for name in ("contact_angle", "contact_angle_parameter"):
                if name not in changes and getattr(self, name) == self.conicity:
                    changes[name] = None
        return replace(self, **changes)

    def free(self) -> Wheelset:
        """The same wheelset with no primary suspension."""
        return self.replace(lateral_stiffness=0.0, yaw_stiffness=0.0, lateral_damping=0.0, yaw_damping=0.0)


def _speed(speed) -> float:
    return scalar("speed", speed, low=0.0, low_open=True)


def creep_terms(ws: Wheelset) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The wheel–rail terms of one wheelset on its coordinates [y, ψ]: (C₁, K_creep, K_gravity).

    The wheel–rail force on the wheelset is −(C₁/V) q̇ − (K_creep + K_gravity) q with
    q = [y, ψ], from Kalker's linear law summed over the two wheels
    (Garg & Dukkipati 1984, ch. 5; Wickens 2003, ch. 2):

    * lateral:  F_y = −2f₂₂(ẏ/V − ψ) − 2f₂₃ψ̇/V − (Wε/a) y
    * yaw:      M_z = −2af₁₁(aψ̇/V + λy/r₀) + 2f₂₃(ẏ/V − ψ) − 2f₃₃ψ̇/V + W a δ₀ ψ

    The small lateral spin force due to the contact-angle difference,
    proportional to f₂₃ε/(a r₀), is left out.

    Returns
    -------
    C1 : ndarray (2, 2)
        Creep damping times speed, N·s/m · m/s (divide by V for C).
    K_creep, K_gravity : ndarray (2, 2)
        Creep and gravitational stiffness, N/m and N·m/rad.
    """
    a, r0, lam = ws.half_gauge, ws.rolling_radius, ws.conicity
    f11, f22, f23, f33 = ws.f11, ws.f22, ws.f23, ws.f33
    # fmt: off
    C1 = np.array([[2 * f22,   2 * f23],
                   [-2 * f23,  2 * a**2 * f11 + 2 * f33]])
    K_creep = np.array([[0.0,                   -2 * f22],
                        [2 * a * f11 * lam / r0,  2 * f23]])
    K_gravity = np.array([[ws.axle_load * ws.contact_angle_parameter / a, 0.0],
                          [0.0, -ws.axle_load * a * ws.contact_angle]])
    # fmt: on
    return C1, K_creep, K_gravity


@dataclass(frozen=True)
class LateralSystem:
    """A linear lateral model whose damping varies as 1/V: M q̈ + (C₀ + C₁/V) q̇ + K q = 0.

    Every model of chapters 5 and 7 has this form, because linear creep forces
    are proportional to creepages, which are velocities divided by V.

    Attributes
    ----------
    M, C0, C1, K : ndarray (n, n)
        Mass (kg), speed-independent damping (N·s/m), creep damping times speed
        (N), stiffness (N/m); rotational rows in the matching units.
    labels : tuple of str
        Name of each coordinate.
    wheelsets : tuple of (int, int, Wheelset)
        Indices of the [y, ψ] coordinates of each wheelset and its parameters,
        so that :class:`NonlinearLateral` can replace the linear wheel–rail terms.
    """

    M: np.ndarray
    C0: np.ndarray
    C1: np.ndarray
    K: np.ndarray
    labels: tuple = ()
    wheelsets: tuple = field(default=())

    @property
    def size(self) -> int:
        return self.M.shape[0]

    def matrices(self, speed) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(M, C(V), K) at the speed V (m/s, > 0)."""
        V = _speed(speed)
        return self.M, self.C0 + self.C1 / V, self.K

    def state_matrices(self, speeds) -> np.ndarray:
        """A(V) = [[0, I], [−M⁻¹K, −M⁻¹C(V)]] for every speed, shape (n_speeds, 2n, 2n), in one pass."""
        from raildyn._checks import array

        V = array("speeds", np.atleast_1d(speeds), ndim=1, low=0.0, low_open=True)
        n = self.size
        Minv = np.linalg.inv(self.M)
        MK, MC0, MC1 = Minv @ self.K, Minv @ self.C0, Minv @ self.C1
        A = np.zeros((V.size, 2 * n, 2 * n))
        A[:, :n, n:] = np.eye(n)
        A[:, n:, :n] = -MK
        A[:, n:, n:] = -MC0 - MC1 / V[:, None, None]
        return A


def wheelset_matrices(params: Wheelset, speed) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """M, C(V), K(V) of a wheelset on its primary suspension to a frame moving at V along the track.

    Coordinates q = [y, ψ] (m, rad). The equations are
    m ÿ + c_y ẏ + k_y y = F_y and I_z ψ̈ + c_ψ ψ̇ + k_ψ ψ = M_z with the
    wheel–rail forces of :func:`creep_terms`.

    Parameters
    ----------
    params : Wheelset
    speed : float
        V, m/s (> 0: the creep forces divide by it).

    Returns
    -------
    M, C, K : ndarray (2, 2)
        kg and kg·m²; N·s/m and N·m·s/rad; N/m and N·m/rad. C and K are not symmetric.

    Examples
    --------
    >>> M, C, K = wheelset_matrices(Wheelset(), 30.0)
    >>> M
    array([[1813.,    0.],
           [   0., 1120.]])
    """
    return suspended_wheelset(params).matrices(speed)


def suspended_wheelset(params: Wheelset) -> LateralSystem:
    """The wheelset on its primary suspension to a frame running straight at V: a :class:`LateralSystem`."""
    if not isinstance(params, Wheelset):
        raise TypeError(f"params must be a Wheelset, got {type(params).__name__}")
    C1, K_creep, K_gravity = creep_terms(params)
    M = np.diag([params.mass, params.yaw_inertia])
    C0 = np.diag([params.lateral_damping, params.yaw_damping])
    K = np.diag([params.lateral_stiffness, params.yaw_stiffness]) + K_creep + K_gravity
    return LateralSystem(M, C0, C1, K, labels=("wheelset y", "wheelset ψ"), wheelsets=((0, 1, params),))


def wickens_critical_speed(params: Wheelset) -> float:
    """Critical speed of the suspended wheelset in the limit of large creep coefficients, m/s.

    With f₁₁ = f₂₂ = f → ∞ (no spin, gravitational stiffness or suspension damping)
    the creep forces enforce rolling without slip, the motion tends to Klingel's
    at ω = V√(λ/(a r₀)), and its damping changes sign where

        V_c² = (a r₀ / λ) · (k_ψ + a² k_y) / (I_z + m a²)

    (Wickens 1965; Wickens 2003, ch. 3). Independent of the creep coefficients
    as long as they are equal; with f₁₁ ≠ f₂₂ the same expansion weights k_ψ
    and I by f₂₂ and a²k_y and m a² by f₁₁.
    """
    a, r0, lam = params.half_gauge, params.rolling_radius, positive("conicity", params.conicity)
    stiffness = params.yaw_stiffness + a**2 * params.lateral_stiffness
    if stiffness <= 0.0:
        return 0.0
    return float(np.sqrt(a * r0 / lam * stiffness / (params.yaw_inertia + params.mass * a**2)))


# ---------------------------------------------------------------------------
# Nonlinear wheelset


def _cone(conicity: float) -> Callable[[np.ndarray], np.ndarray]:
    def rolling_radius_difference(y):
        return 2.0 * conicity * np.asarray(y, dtype=float)

    return rolling_radius_difference


@dataclass(frozen=True)
class WheelRailContact:
    """Nonlinear wheel–rail contact of one wheelset: geometry, saturation and flange.

    Attributes
    ----------
    friction : float
        Coefficient of friction μ; the creep force of a wheel saturates at μ W/2.
    flange_clearance : float
        Flangeway clearance δ_f, m: the flange touches the rail beyond |y| = δ_f.
    flange_stiffness : float
        Lateral stiffness of the rail under flange contact k_f, N/m. Defaults
        δ_f = 9.1 mm and k_f = 14.6 MN/m as in Cooperrider's truck model
        (Cooperrider 1972, as used by Jensen & True 1997).
    rolling_radius_difference : callable or None
        Δr(y) = r_L − r_R, m, vectorised over y. None: the cone 2λy of the wheelset.
    contact_angle_difference : callable or None
        δ_L(y) − δ_R(y), rad. None: the linear 2εy/a of the wheelset.
    """

    friction: float = 0.3
    flange_clearance: float = 9.1e-3
    flange_stiffness: float = 14.6e6
    rolling_radius_difference: Callable | None = None
    contact_angle_difference: Callable | None = None

    def __post_init__(self):
        positive("friction", self.friction)
        positive("flange_clearance", self.flange_clearance)
        nonnegative("flange_stiffness", self.flange_stiffness)
        for name in ("rolling_radius_difference", "contact_angle_difference"):
            value = getattr(self, name)
            if value is not None and not callable(value):
                raise TypeError(f"{name} must be a callable of y or None, got {value!r}")


def saturation_factor(force, limit) -> np.ndarray:
    """Shen–Hedrick–Elkins reduction of a linear creep force magnitude F to μN (Shen et al. 1983).

    Returns F_sat/F with F_sat = μN(u − u²/3 + u³/27) for u = F/(μN) < 3 and μN beyond.
    """
    force = np.abs(np.asarray(force, dtype=float))
    u = force / limit
    sat = np.where(u < 3.0, u - u**2 / 3.0 + u**3 / 27.0, 1.0)
    return np.divide(sat, u, out=np.ones_like(u), where=u > 0)


def contact_forces(ws: Wheelset, contact: WheelRailContact, y, psi, ydot, psidot, speed):
    """Lateral force (N) and yaw moment (N·m) of the rails on a wheelset, nonlinear; arrays broadcast.

    Creepages of the left/right wheel: ξx = ∓(aψ̇/V + Δr(y)/(2r₀)), ξy = ẏ/V − ψ,
    spin ψ̇/V. Each wheel's longitudinal and lateral linear force is reduced
    by :func:`saturation_factor` at μ W/2; gravity acts through the
    contact-angle difference, and the flange as a spring beyond the clearance.
    For small motion the result equals the linear forces of :func:`creep_terms`.
    """
    a, r0, W = ws.half_gauge, ws.rolling_radius, ws.axle_load
    dr = (contact.rolling_radius_difference or _cone(ws.conicity))(y)
    if contact.contact_angle_difference is None:
        dd = 2.0 * ws.contact_angle_parameter * np.asarray(y, dtype=float) / a
    else:
        dd = contact.contact_angle_difference(y)
    xi_x = -(a * psidot / speed + dr / (2.0 * r0))  # left wheel; the right one has the opposite sign
    xi_y = ydot / speed - psi
    spin = psidot / speed
    fx = -ws.f11 * xi_x
    fy = -ws.f22 * xi_y - ws.f23 * spin
    limit = contact.friction * W / 2.0
    # The two wheels have the same lateral and opposite longitudinal force, so the same magnitude.
    scale = saturation_factor(np.hypot(fx, fy), limit)
    lateral = 2.0 * scale * fy - W / 2.0 * dd
    yaw = -2.0 * a * scale * fx + 2.0 * (ws.f23 * xi_y - ws.f33 * spin) + W * a * ws.contact_angle * psi
    excess = np.abs(y) - contact.flange_clearance
    lateral = lateral - contact.flange_stiffness * np.sign(y) * np.maximum(excess, 0.0)
    return lateral, yaw


@dataclass(frozen=True)
class NonlinearWheelset:
    """The suspended wheelset with nonlinear contact, as ``rhs(t, state)`` for solve_ivp.

    State [y, ψ, ẏ, ψ̇] (m, rad, m/s, rad/s); the frame runs straight at ``speed``.
    """

    wheelset: Wheelset = field(default_factory=Wheelset)
    contact: WheelRailContact = field(default_factory=WheelRailContact)
    speed: float = 30.0

    def __post_init__(self):
        _speed(self.speed)

    state_size = 4
    lateral_index = 0  # the state entry of the lateral displacement followed in hunting studies

    def at_speed(self, speed) -> NonlinearWheelset:
        """The same wheelset at another speed (m/s)."""
        return NonlinearWheelset(self.wheelset, self.contact, speed)

    def rhs(self, t, state):
        """Time derivative of the state (vectorised over trailing columns)."""
        ws = self.wheelset
        y, psi, ydot, psidot = state
        fy, mz = contact_forces(ws, self.contact, y, psi, ydot, psidot, self.speed)
        yddot = (fy - ws.lateral_stiffness * y - ws.lateral_damping * ydot) / ws.mass
        psiddot = (mz - ws.yaw_stiffness * psi - ws.yaw_damping * psidot) / ws.yaw_inertia
        return np.array([ydot, psidot, yddot, psiddot])


@dataclass(frozen=True)
class NonlinearLateral:
    """Any :class:`LateralSystem` with its linear wheel–rail terms replaced by :func:`contact_forces`.

    M q̈ = −C₀q̇ − K_s q + Σ F_contact, where K_s is K without the creep and
    gravitational terms of each wheelset. State [q; q̇]; ``rhs(t, state)`` for solve_ivp.
    """

    system: LateralSystem
    contact: WheelRailContact = field(default_factory=WheelRailContact)
    speed: float = 30.0

    def __post_init__(self):
        _speed(self.speed)
        if not self.system.wheelsets:
            raise ValueError("system has no wheelsets in contact with the rails")
        K_s = np.array(self.system.K, dtype=float, copy=True)
        for iy, ipsi, ws in self.system.wheelsets:
            _, K_creep, K_gravity = creep_terms(ws)
            idx = np.ix_([iy, ipsi], [iy, ipsi])
            K_s[idx] -= K_creep + K_gravity
        object.__setattr__(self, "_K_suspension", K_s)
        object.__setattr__(self, "_M_inv", np.linalg.inv(self.system.M))
        # Wheelsets with equal parameters are evaluated together in one vectorised call.
        groups: dict = {}
        for iy, ipsi, ws in self.system.wheelsets:
            groups.setdefault(ws, ([], []))
            groups[ws][0].append(iy)
            groups[ws][1].append(ipsi)
        object.__setattr__(self, "_groups", [(ws, np.array(a), np.array(b)) for ws, (a, b) in groups.items()])

    @property
    def state_size(self) -> int:
        return 2 * self.system.size

    @property
    def lateral_index(self) -> int:
        """State entry of the first wheelset's lateral displacement (followed in hunting studies)."""
        return self.system.wheelsets[0][0]

    def at_speed(self, speed) -> NonlinearLateral:
        """The same model at another speed (m/s)."""
        return NonlinearLateral(self.system, self.contact, speed)

    def rhs(self, t, state):
        """Time derivative of [q; q̇]."""
        n = self.system.size
        q, qdot = state[:n], state[n:]
        force = -self.system.C0 @ qdot - self._K_suspension @ q
        force = np.array(force, dtype=float, copy=True)
        for ws, iy, ipsi in self._groups:
            fy, mz = contact_forces(ws, self.contact, q[iy], q[ipsi], qdot[iy], qdot[ipsi], self.speed)
            force[iy] += fy
            force[ipsi] += mz
        return np.concatenate([qdot, self._M_inv @ force])
