"""The railway wheelset on tangent and curved track (book chapter 5): kinematics, linear and nonlinear
dynamics.

* Klingel's kinematic oscillation of a free coned wheelset and of a rigid
  two-axle bogie (:func:`kinematic_wavelength`, :func:`rigid_bogie_wavelength`);
* a :class:`Wheelset` parameter set and its linear lateral–yaw equations with
  Kalker's linear creep forces (f₁₁, f₂₂, f₂₃, f₃₃), gravitational stiffness
  and spin, on a primary suspension to a frame moving at the speed V: a
  linear model of the one protocol (:class:`raildyn.linear_model.LinearModel`:
  ``Wheelset().matrices(V)``, ``state_space(V)``), whose wheel–rail terms
  (:func:`creep_terms`, :func:`add_wheelset`) the bogie and car models of
  :mod:`raildyn.vehicles` assemble too;
* on a curve: the pure-rolling offset r₀a/(λR) of a free wheelset
  (:func:`pure_rolling_offset`) and the loads a curve of radius R puts on a
  wheelset through its creepages and gravitational stiffness (:func:`curve_loads`),
  from which :func:`raildyn.curving.steady.steady_curving` finds the steady state of any
  vehicle;
* the nonlinear wheelset (:class:`WheelRailContact`, :class:`NonlinearWheelset`):
  a rolling-radius difference Δr(y), saturating creep forces and a flange
  modelled as a stiff spring beyond the flangeway clearance, as ``rhs(t, y)``.

The contact geometry (Δr(y), contact-angle difference) enters as callables so
that the profiles of chapter 4 can be plugged in; the default is a cone of
conicity λ. Coordinates: x forward, y to the left, z up; ψ is the yaw angle
(positive turning to the left). SI units throughout.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from raildyn import _checks
from raildyn._checks import nonnegative, positive, scalar
from raildyn.constants import (
    GRAVITY,
    STANDARD_RAIL_SPACING,
    STEEL_POISSON_RATIO,
    STEEL_SHEAR_MODULUS,
    STEEL_YOUNGS_MODULUS,
)
from raildyn.contact.creep import creep_coefficients, saturation_factor, wheelset_creepages
from raildyn.contact.hertz import hertz_contact
from raildyn.linear_model import Assembler, LinearModelBase, LinearSystem

# ---------------------------------------------------------------------------
# Kinematics


__all__ = [
    "CreepTerms",
    "KinematicOscillation",
    "NonlinearLateral",
    "NonlinearWheelset",
    "SuspensionElement",
    "WheelForces",
    "WheelRailContact",
    "Wheelset",
    "add_wheelset",
    "contact_forces",
    "creep_terms",
    "curve_loads",
    "kinematic_oscillation",
    "kinematic_wavelength",
    "profile_contact",
    "pure_rolling_offset",
    "rigid_bogie_wavelength",
    "track_on_arc",
    "tread_contact_angles",
    "wheel_forces",
    "wickens_critical_speed",
]


def kinematic_wavelength(rolling_radius, half_gauge, conicity) -> float:
    """Klingel's wavelength of a free coned wheelset rolling without slip, m.

    L = 2π √(r₀ a / λ) (Klingel 1883; Garg & Dukkipati 1984, ch. 5).

    Parameters
    ----------
    rolling_radius : float
        Centred rolling radius r₀, m, in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "wheel_radius").
    half_gauge : float
        Half the lateral distance between the two contact points a, m, in [0.15, 1.1]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "half_gauge").
    conicity : float
        Equivalent conicity λ, dimensionless, in (0, 0.5] (real wheels run below about 0.5).

    Returns
    -------
    float
        L, m.

    Examples
    --------
    >>> round(kinematic_wavelength(0.46, 0.75, 0.05), 3)
    16.505
    """
    r0, a, lam = _coned_wheelset(rolling_radius, half_gauge, conicity)
    return float(2.0 * np.pi * np.sqrt(r0 * a / lam))


def _coned_wheelset(rolling_radius, half_gauge, conicity) -> tuple[float, float, float]:
    """The checked r₀, a and λ > 0 of the kinematic formulas, each in its plausible range."""
    r0 = _checks.plausible("rolling_radius", rolling_radius, "wheel_radius")
    a = _checks.plausible("half_gauge", half_gauge, "half_gauge")
    lam = scalar("conicity", conicity, low=0.0, low_open=True, high=_MAX_ANGLE)
    return r0, a, lam


def rigid_bogie_wavelength(rolling_radius, half_gauge, conicity, semi_wheelbase) -> float:
    """Kinematic wavelength of two wheelsets held rigidly parallel in a bogie, m.

    L = 2π √(r₀ a / λ · (1 + b²/a²)), with b the half wheelbase (Wickens 2003,
    ch. 2): the rigid frame forces each wheelset to slide laterally as it yaws,
    which lengthens the wave.

    Parameters
    ----------
    rolling_radius, half_gauge, conicity : float
        r₀ (m), a (m) and λ, as for :func:`kinematic_wavelength`.
    semi_wheelbase : float
        b, half the distance between the two axles, m, in [0.01, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length").

    Returns
    -------
    float
        L, m.

    Examples
    --------
    >>> round(rigid_bogie_wavelength(0.46, 0.75, 0.05, 1.28), 3)
    32.647
    """
    b = _checks.plausible("semi_wheelbase", semi_wheelbase, "vehicle_length")
    a = _checks.plausible("half_gauge", half_gauge, "half_gauge")
    # √(1 + (b/a)²) as a hypotenuse, which stays finite for any finite b/a
    return kinematic_wavelength(rolling_radius, half_gauge, conicity) * float(np.hypot(1.0, b / a))


@dataclass(frozen=True)
class KinematicOscillation:
    """Klingel's kinematic oscillation of a free wheelset and of two wheelsets held in a rigid bogie.

    Attributes
    ----------
    wavelength : float
        Of the free wheelset, 2π√(r₀a/λ), m (> 0).
    rigid_bogie_wavelength : float
        Of the rigid bogie, 2π√(r₀a/λ · (1 + b²/a²)), m (> 0).
    """

    wavelength: float
    rigid_bogie_wavelength: float

    def __post_init__(self):
        positive("wavelength", self.wavelength)
        positive("rigid_bogie_wavelength", self.rigid_bogie_wavelength)

    def plot(self, ax=None, *, artists: dict | None = None, distance=None, amplitude: float = 5.0) -> dict:
        """Draw both paths, y = A sin(2πx/L), against the distance along the track.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default. Ignored when ``artists`` is given.
        artists : dict, optional
            The artists an earlier call returned: they are moved to these wavelengths.
        distance : array_like, optional
            x, m (1-D, at least two, strictly increasing); 0 to 60 m by default (with ``artists``: the
            distances drawn first).
        amplitude : float
            A, mm (> 0).

        Returns
        -------
        dict
            The artists: ``free`` and ``bogie``.
        """
        import matplotlib

        from raildyn import plots

        amplitude = positive("amplitude", amplitude)
        if distance is not None:
            distance = _checks.increasing("distance", distance)
            if distance.size < 2:
                raise ValueError(f"distance must hold at least two distances, got {distance.size}")
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
            x = artists["free"].get_xdata()
        else:
            x = np.linspace(0.0, 60.0, 1200) if distance is None else distance
        paths = {
            "free": amplitude * np.sin(2 * np.pi * x / self.wavelength),
            "bogie": amplitude * np.sin(2 * np.pi * x / self.rigid_bogie_wavelength),
        }
        if artists is not None:
            for name, y in paths.items():
                artists[name].set_ydata(y)
            return artists
        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            (free,) = ax.plot(x, paths["free"], color=plots.COLORS[0], label="free wheelset (Klingel)")
            (bogie,) = ax.plot(x, paths["bogie"], "--", color=plots.COLORS[1], label="rigid bogie")
            ax.set_xlim(x[0], x[-1])
            ax.set_xlabel("distance along the track $x$ (m)")
            ax.set_ylabel("lateral displacement $y$ (mm)")
        return {"free": free, "bogie": bogie}


def kinematic_oscillation(rolling_radius, half_gauge, conicity, semi_wheelbase) -> KinematicOscillation:
    """Both kinematic wavelengths at once: :func:`kinematic_wavelength` and :func:`rigid_bogie_wavelength`.

    Parameters
    ----------
    rolling_radius, half_gauge, conicity : float
        r₀ (m), a (m) and λ.
    semi_wheelbase : float
        b, m.

    Returns
    -------
    KinematicOscillation

    Examples
    --------
    >>> k = kinematic_oscillation(0.46, 0.75, 0.15, 1.28)
    >>> round(k.wavelength, 2), round(k.rigid_bogie_wavelength, 2)
    (9.53, 18.85)
    """
    return KinematicOscillation(
        kinematic_wavelength(rolling_radius, half_gauge, conicity),
        rigid_bogie_wavelength(rolling_radius, half_gauge, conicity, semi_wheelbase),
    )


# ---------------------------------------------------------------------------
# Default contact


def _hertz_kalker(wheel_load, rolling_radius):
    """Kalker's coefficients of a wheel of radius r₀ on a rail crowned with the same radius, per wheel.

    The patch is Hertz's (:func:`raildyn.contact.hertz.hertz_contact`, curvature 1/r₀ along
    and across the track: a circle) and the coefficients are Kalker's
    (:func:`raildyn.contact.kalker.creep_coefficients`), both for the steel of
    :mod:`raildyn.constants`.
    """
    patch = hertz_contact(
        wheel_load, rolling_radius, np.inf, rolling_radius, STEEL_YOUNGS_MODULUS, STEEL_POISSON_RATIO
    )
    return creep_coefficients(patch.a, patch.b, STEEL_SHEAR_MODULUS, STEEL_POISSON_RATIO)


# Manchester benchmark vehicle (Iwnicki 1998, Table of vehicle 1 parameters): wheelset mass 1813 kg,
# yaw inertia 1120 kg·m², nominal rolling radius 0.46 m; primary stiffness per axlebox: lateral
# 3884 kN/m, longitudinal 31391 kN/m, at 1.0 m either side of the track centre line; primary damping
# per axlebox: lateral 2 kN·s/m, longitudinal 15 kN·s/m. Total vehicle mass 32000 + 2·2615 + 4·1813
# = 44482 kg, so the axle load is 44482·g/4.
_MANCHESTER_AXLE_LOAD = 44482.0 * GRAVITY / 4.0
_MANCHESTER_PRIMARY_YAW_SPACING = 1.0  # m, half the lateral distance between the primary springs
# Half the axle load on a 0.46 m wheel and a rail crowned with the same radius (our choice: the
# benchmark's real profiles are not modelled here).
_DEFAULT_CREEP = _hertz_kalker(_MANCHESTER_AXLE_LOAD / 2.0, 0.46)


_MAX_ANGLE = 0.5  # rad (29°), the largest conicity and centred contact angle: tread contact


@dataclass(frozen=True)
class Wheelset(LinearModelBase):
    """A wheelset, its contact with the rails and its primary suspension to a frame.

    The defaults are one wheelset of the Manchester benchmark vehicle (Iwnicki
    1998) on a cone; the conicity (0.15) and contact half-spacing (0.75 m, the
    usual value for standard gauge) are our choice, not the benchmark's, which
    specifies real profiles. Creep coefficients are per contact patch: Kalker's
    (:func:`raildyn.contact.kalker.creep_coefficients`) on Hertz's patch under half the
    axle load, wheel radius 0.46 m on a rail crowned with the same radius.

    Attributes
    ----------
    mass : float
        m, kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass").
    yaw_inertia : float
        I_z, kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia").
    rolling_radius : float
        r₀, m, in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_radius": from the smallest
        wheels of low-floor
        wagons to the largest steam drivers; 460 would be millimetres).
    half_gauge : float
        a, half the distance between the contact points, m, in [0.15, 1.1]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "half_gauge": from minimum gauge to the broadest; 750 would be millimetres).
    conicity : float
        λ, in [0, 0.5]: Δr = r_L − r_R = 2λy for small y. Real wheels run below about
        0.5, and the contact angle and ε, which follow λ by default, are small angles.
    axle_load : float
        W, total vertical load on the two wheels, N, in [1, 2e6]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "axle_load"; > 0: the
        creep forces saturate at μW/2).
    f11, f22, f23, f33 : float
        Kalker's longitudinal (N), lateral (N), lateral–spin (N·m) and spin
        (N·m²) creep coefficients of one wheel, each ≥ 0.
    contact_angle : float or None
        ϑ₀, contact angle of the centred wheelset, rad, in [0, 0.5] (tread contact, not
        the flange's; destabilising yaw gravitational stiffness −W a ϑ₀). None: λ, as for
        a cone on knife-edge rails.
    contact_angle_parameter : float or None
        ε ≥ 0 with ϑ_L − ϑ_R = 2εy/a; lateral gravitational stiffness W ε / a.
        None: λ, the value for a cone on knife-edge rails.
    lateral_stiffness, yaw_stiffness : float
        Primary suspension, N/m and N·m/rad (total for the wheelset), each ≥ 0.
    lateral_damping, yaw_damping : float
        Primary suspension, N·s/m and N·m·s/rad, each ≥ 0.
    """

    mass: float = 1813.0
    yaw_inertia: float = 1120.0
    rolling_radius: float = 0.46
    half_gauge: float = 0.75
    conicity: float = 0.15
    axle_load: float = _MANCHESTER_AXLE_LOAD
    f11: float = float(_DEFAULT_CREEP.f11)
    f22: float = float(_DEFAULT_CREEP.f22)
    f23: float = float(_DEFAULT_CREEP.f23)
    f33: float = float(_DEFAULT_CREEP.f33)
    contact_angle: float | None = None
    contact_angle_parameter: float | None = None
    lateral_stiffness: float = 2 * 3884.0e3
    yaw_stiffness: float = 2 * 31391.0e3 * _MANCHESTER_PRIMARY_YAW_SPACING**2
    lateral_damping: float = 2 * 2.0e3
    yaw_damping: float = 2 * 15.0e3 * _MANCHESTER_PRIMARY_YAW_SPACING**2

    def __post_init__(self):
        for name in ("mass", "yaw_inertia", "rolling_radius", "half_gauge", "axle_load"):
            positive(name, getattr(self, name))
        for name, quantity in (
            ("mass", "mass"),
            ("yaw_inertia", "inertia"),
            ("rolling_radius", "wheel_radius"),
            ("half_gauge", "half_gauge"),
            ("axle_load", "axle_load"),
        ):
            _checks.plausible(name, getattr(self, name), quantity)
        # Checked before the contact angle and ε that follow it, so that a message names it.
        scalar("conicity", self.conicity, low=0.0, high=_MAX_ANGLE)
        for name in (
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
        scalar("contact_angle", self.contact_angle, low=0.0, high=_MAX_ANGLE)
        nonnegative("contact_angle_parameter", self.contact_angle_parameter)

    def replace(self, **changes) -> Wheelset:
        """A copy with some fields changed (validated again).

        A contact angle or ε that followed the conicity keeps following it when
        only the conicity changes.

        Parameters
        ----------
        **changes
            Field names and their new values.

        Returns
        -------
        Wheelset
        """
        from dataclasses import replace

        if "conicity" in changes:
            for name in ("contact_angle", "contact_angle_parameter"):
                if name not in changes and getattr(self, name) == self.conicity:
                    changes[name] = None
        return replace(self, **changes)

    def free(self) -> Wheelset:
        """The same wheelset with no primary suspension.

        Returns
        -------
        Wheelset
        """
        return self.replace(lateral_stiffness=0.0, yaw_stiffness=0.0, lateral_damping=0.0, yaw_damping=0.0)

    def linear_system(self) -> LinearSystem:
        """The wheelset on its primary suspension to a frame running straight at V.

        Coordinates q = [y, ψ] (m, rad): m ÿ + c_y ẏ + k_y y = F_y and
        I_z ψ̈ + c_ψ ψ̇ + k_ψ ψ = M_z with the wheel–rail forces of
        :func:`creep_terms`. Two track inputs at the wheelset: the alignment and
        the cross-level (m), as :func:`add_wheelset` couples them.

        Returns
        -------
        LinearSystem

        Examples
        --------
        >>> mats = Wheelset().matrices(30.0)
        >>> mats.M
        array([[1813.,    0.],
               [   0., 1120.]])
        """
        asm = Assembler(["wheelset y", "wheelset ψ"], n_inputs=2)
        add_wheelset(asm, "wheelset y", "wheelset ψ", self, alignment=0, cross_level=1)
        asm.element({"wheelset y": 1.0}, self.lateral_stiffness, self.lateral_damping)
        asm.element({"wheelset ψ": 1.0}, self.yaw_stiffness, self.yaw_damping)
        return asm.system(input_kinds=("alignment", "cross_level"))


def _speed(speed) -> float:
    return _checks.speed("speed", speed)


@dataclass(frozen=True)
class CreepTerms:
    """The linear wheel–rail terms of one wheelset on its coordinates [y, ψ].

    The wheel–rail force on the wheelset is −(C₁/V) q̇ − (K_creep + K_gravity) q.

    Attributes
    ----------
    C1 : ndarray (2, 2)
        Creep damping times speed, N (divide by V for N·s/m).
    K_creep, K_gravity : ndarray (2, 2)
        Creep and gravitational stiffness, N/m and N·m/rad.

    Each is a finite 2 × 2 array, its entries of either sign.
    """

    C1: np.ndarray
    K_creep: np.ndarray
    K_gravity: np.ndarray

    def __post_init__(self):
        for name in ("C1", "K_creep", "K_gravity"):
            _checks.array(name, getattr(self, name), shape=(2, 2))


def creep_terms(ws: Wheelset) -> CreepTerms:
    """The linear wheel–rail terms of one wheelset on its coordinates [y, ψ].

    From Kalker's linear law summed over the two wheels (Garg & Dukkipati 1984,
    ch. 5; Wickens 2003, ch. 2), with the creepages of
    :func:`raildyn.contact.creepages.wheelset_creepages` to first order:

    * lateral:  F_y = −2f₂₂(ẏ/V − ψ) − 2f₂₃(ψ̇/V − εy/(a r₀)) − (Wε/a) y
    * yaw:      M_z = −2af₁₁(aψ̇/V + λy/r₀) + 2f₂₃(ẏ/V − ψ) − 2f₃₃(ψ̇/V − εy/(a r₀)) + W a ϑ₀ ψ

    The terms in εy/(a r₀) are the spin of the contact-angle difference: as the wheelset
    shifts by y the two contact angles part by 2εy/a, and each wheel turning at V/r₀ about
    its axle spins about its tilted contact normal by ∓ sin ϑ/r₀, which no longer cancel
    between the wheels. They give a lateral force 2f₂₃εy/(a r₀), which pulls the wheelset
    away from the centre and so cancels most of the gravitational stiffness Wε/a (for the
    default wheelset the net lateral stiffness is a fifth of Wε/a), and a yaw moment
    2f₃₃εy/(a r₀). :func:`raildyn.derivations.wheelset.tangent_wheelset` derives every term
    from the contact kinematics.

    Parameters
    ----------
    ws : Wheelset

    Returns
    -------
    CreepTerms

    Examples
    --------
    The net lateral stiffness of the default wheelset, Wε/a − 2f₂₃ε/(a r₀), against Wε/a:

    >>> ws = Wheelset()
    >>> terms = creep_terms(ws)
    >>> net = terms.K_creep[0, 0] + terms.K_gravity[0, 0]
    >>> round(float(terms.K_gravity[0, 0] / net), 2)
    4.71
    """
    _checks.instance("ws", ws, Wheelset)
    a, r0, lam, eps = ws.half_gauge, ws.rolling_radius, ws.conicity, ws.contact_angle_parameter
    f11, f22, f23, f33 = ws.f11, ws.f22, ws.f23, ws.f33
    # fmt: off
    C1 = np.array([[2 * f22,   2 * f23],
                   [-2 * f23,  2 * a**2 * f11 + 2 * f33]])
    K_creep = np.array([[-2 * f23 * eps / (a * r0),                            -2 * f22],
                        [2 * a * f11 * lam / r0 - 2 * f33 * eps / (a * r0),  2 * f23]])
    K_gravity = np.array([[ws.axle_load * eps / a, 0.0],
                          [0.0, -ws.axle_load * a * ws.contact_angle]])
    # fmt: on
    return CreepTerms(C1, K_creep, K_gravity)


def add_wheelset(asm: Assembler, y: str, psi: str, ws: Wheelset, *, alignment=None, cross_level=None) -> None:
    """Add a wheelset's mass, inertia and wheel–rail terms to an assembly, with its track inputs.

    Alignment y_a enters the terms that depend on the wheelset's displacement
    relative to the rails — the rolling-radius difference λ(y − y_a)/r₀ and the
    gravitational stiffness — while the creepages ẏ/V − ψ and aψ̇/V stay
    absolute. A cross-level Δz (left rail height less the right, measured over the rails as a
    cant is) rolls the plane of the rails by Δz/(2a_r), 2a_r the rail spacing
    (:data:`raildyn.constants.STANDARD_RAIL_SPACING`), and the rail reactions push the wheelset
    sideways by −W Δz/(2a_r).

    Parameters
    ----------
    asm : Assembler
    y, psi : str
        Labels of the wheelset's lateral (m) and yaw (rad) coordinates in ``asm``: two different
        coordinates, neither already a wheelset's.
    ws : Wheelset
    alignment, cross_level : int, optional
        Indices of the track inputs (in [0, q − 1]) that carry the alignment and the
        cross-level (m) at this wheelset, two different inputs; None where the input is
        not modelled.
    """
    _checks.instance("asm", asm, Assembler)
    iy = asm.labels.index(_checks.choice("y", y, asm.labels))
    ipsi = asm.labels.index(_checks.choice("psi", psi, asm.labels))
    if ipsi == iy:
        raise ValueError(
            f"psi must be another coordinate than y (the yaw, not the lateral motion), got {psi!r}"
        )
    for name, label, i in (("y", y, iy), ("psi", psi, ipsi)):
        if any(i in (jy, jpsi) for jy, jpsi, _ in asm.wheelsets):
            raise ValueError(f"{name} = {label!r} is already a wheelset's coordinate in asm (added twice?)")
    terms = creep_terms(_checks.instance("ws", ws, Wheelset))
    inputs = {}
    for name, j in (("alignment", alignment), ("cross_level", cross_level)):
        if j is not None:
            inputs[name] = asm._input(name, j)
    if len(inputs) == 2 and inputs["alignment"] == inputs["cross_level"]:
        raise ValueError(f"cross_level must be another input than alignment, got both {alignment!r}")
    stiffness = terms.K_creep + terms.K_gravity
    asm.block([y, psi], C1=terms.C1, K=stiffness)
    asm.mass(y, ws.mass)
    asm.mass(psi, ws.yaw_inertia)
    asm.wheelsets.append((iy, ipsi, ws))
    if "alignment" in inputs:
        asm.track_force(y, inputs["alignment"], stiffness[0, 0])
        asm.track_force(psi, inputs["alignment"], stiffness[1, 0])
    if "cross_level" in inputs:
        asm.track_force(y, inputs["cross_level"], -ws.axle_load / STANDARD_RAIL_SPACING)


def wickens_critical_speed(params: Wheelset) -> float:
    """Critical speed of the suspended wheelset in the limit of large creep coefficients, m/s.

    With f₁₁ = f₂₂ = f → ∞ (no spin, gravitational stiffness or suspension damping)
    the creep forces enforce rolling without slip, the motion tends to Klingel's
    at ω = V√(λ/(a r₀)), and its damping changes sign where

        V_c² = (a r₀ / λ) · (k_ψ + a² k_y) / (I_z + m a²)

    (Wickens 1965; Wickens 2003, ch. 3). Independent of the creep coefficients
    as long as they are equal; with f₁₁ ≠ f₂₂ the same expansion weights k_ψ
    and I by f₂₂ and a²k_y and m a² by f₁₁.

    Parameters
    ----------
    params : Wheelset
        Its conicity must be > 0.

    Returns
    -------
    float
        V_c, m/s (0 with no suspension stiffness).
    """
    _checks.instance("params", params, Wheelset)
    a, r0, lam = params.half_gauge, params.rolling_radius, positive("params.conicity", params.conicity)
    stiffness = params.yaw_stiffness + a**2 * params.lateral_stiffness
    if stiffness <= 0.0:
        return 0.0
    return float(np.sqrt(a * r0 / lam * stiffness / (params.yaw_inertia + params.mass * a**2)))


# ---------------------------------------------------------------------------
# Curved track


def pure_rolling_offset(rolling_radius, half_gauge, conicity, radius) -> float:
    """Lateral offset at which a free coned wheelset rolls round a curve without slip, m.

    y₀ = r₀ a / (λ R), towards the outer rail (Garg & Dukkipati 1984, ch. 5; Wickens 2003,
    ch. 7): the outer wheel then rolls on a radius larger by λ y₀, enough to cover the outer
    rail's extra length a/R per metre.

    Parameters
    ----------
    rolling_radius, half_gauge, conicity : float
        r₀ (m), a (m) and λ, as for :func:`kinematic_wavelength` (each in its range there).
    radius : float
        R, radius of the curve, m (> 0).

    Returns
    -------
    float
        y₀, m (≥ 0, towards the outer rail).

    Examples
    --------
    A wheelset of conicity 0.15 in a curve of 600 m runs 3.8 mm towards the outer rail:

    >>> round(1e3 * pure_rolling_offset(0.46, 0.75, 0.15, 600.0), 2)
    3.83
    """
    r0, a, lam = _coned_wheelset(rolling_radius, half_gauge, conicity)
    return float(r0 * a / (lam * positive("radius", radius)))


_MAX_POSITION = 100.0  # m: a wheelset's distance from the centre of its vehicle
_MIN_RADIUS = 50.0  # m: raildyn.curving.geometry.MINIMUM_RADIUS (that module imports this one)


def track_on_arc(position, curvature) -> tuple[np.ndarray, np.ndarray]:
    """Where an arc puts the track under a wheelset, in axes tangent to it at their origin.

    A wheelset x ahead of the origin of axes that follow the vehicle round an arc of curvature
    κ = 1/R meets the track's centre line displaced by y_t = ½x²κ and turned by ψ_t = xκ (the
    small-angle arc; Garg & Dukkipati 1984, ch. 8). The one place this geometry is written:
    :func:`curve_loads`, :meth:`NonlinearLateral.arc_forces` and the curving models use it.

    Parameters
    ----------
    position : float or array_like
        x, m, each within ±100 m (a wheelset's place along its vehicle); not empty.
    curvature : float or array_like
        κ, 1/m, each within ±1/50 m (the sharpest curve of :mod:`raildyn.curving.geometry`),
        broadcasting with ``position``; not empty.

    Returns
    -------
    y_t : ndarray
        m, to the left (towards the centre of a left-hand curve).
    psi_t : ndarray
        rad, anticlockwise.

    Examples
    --------
    >>> y_t, psi_t = track_on_arc(10.0, 1 / 500.0)
    >>> round(float(y_t), 3), round(float(psi_t), 3)
    (0.1, 0.02)
    """
    x = _checks.array("position", position, allow_empty=False)
    kappa = _checks.array("curvature", curvature, allow_empty=False)
    scalar("position", np.abs(x).max(), high=_MAX_POSITION)
    scalar("curvature", np.abs(kappa).max(), high=1.0 / _MIN_RADIUS)
    _checks.broadcast(position=x, curvature=kappa)
    return 0.5 * x * x * kappa, x * kappa


def curve_loads(ws: Wheelset, radius, position=0.0) -> np.ndarray:
    """The wheel–rail loads [F_y, M_z] that a curve puts on a wheelset, N and N·m.

    The vehicle is described in axes that follow it round a curve to the left of
    radius R (turning at V/R, their origin on the track's centre line, x along its
    tangent there). A wheelset x ahead of the origin meets the track displaced by
    y_t = x²/(2R) and turned by ψ_t = x/R, and its yaw rate is ψ̇ + V/R. So in the
    linear wheel–rail terms of :func:`creep_terms` the displacement becomes
    q − q_t and ψ̇/V becomes ψ̇/V + 1/R:

        f = (K_creep + K_gravity) q_t − C₁ [0, 1]ᵀ / R.

    The second term holds the longitudinal creepage a/R of the outer rail's extra
    length and the spin 1/R (Garg & Dukkipati 1984, ch. 5 and 8; Wickens 2003, ch. 7).
    These loads are independent of the speed; the cant deficiency's force acts on
    every mass and is added by :func:`raildyn.curving.steady.steady_curving`.

    Parameters
    ----------
    ws : Wheelset
    radius : float
        R, m, at least 50 (:data:`raildyn.curving.geometry.MINIMUM_RADIUS`; the curve turns to
        the left, +y).
    position : float
        x, the wheelset's distance ahead of the axes' origin, m, in [−100, 100] (negative
        behind): the axes follow one vehicle, and x/R must stay a small angle.

    Returns
    -------
    ndarray, (2,)
        [F_y (N), M_z (N·m)] on the wheelset held at q = 0 in the curve's axes.

    Examples
    --------
    A lone centred wheelset feels the yaw moment of its longitudinal creep, −2a²f₁₁/R:

    >>> ws = Wheelset(f23=0.0, f33=0.0)
    >>> F = curve_loads(ws, 600.0)
    >>> bool(np.isclose(F[1], -2 * ws.half_gauge**2 * ws.f11 / 600.0))
    True
    """
    terms = creep_terms(_checks.instance("ws", ws, Wheelset))
    R = scalar("radius", radius, low=_MIN_RADIUS)
    x = scalar("position", position, low=-_MAX_POSITION, high=_MAX_POSITION)
    track = np.array(track_on_arc(x, 1.0 / R))
    return (terms.K_creep + terms.K_gravity) @ track - terms.C1[:, 1] / R


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
        Coefficient of friction μ, in (0, 1] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "friction": dry
        rail steel reaches about
        0.6; 30 would be a percentage); the creep force of a wheel saturates at μ W/2.
    flange_clearance : float
        Flangeway clearance e, m, in (0, 0.05]: the flange touches the rail beyond
        |y| = e (5 to 15 mm on standard-gauge track).
    flange_stiffness : float
        Lateral stiffness of the rail under flange contact k_f, N/m (≥ 0). Defaults
        e = 9.1 mm and k_f = 14.6 MN/m as in Cooperrider's truck model
        (Cooperrider 1972, as used by Jensen & True 1997).
    rolling_radius_difference : callable or None
        Δr(y) = r_L − r_R, m, vectorised over y: an array of y's shape, within ±0.1 m
        (twice a flange height is about 60 mm). None: the cone 2λy of the wheelset.
    contact_angle_difference : callable or None
        ϑ_L(y) − ϑ_R(y), rad, vectorised over y, within ±π/2 (each contact angle lies in
        [0, π/2)). None: the linear 2εy/a of the wheelset.
    tread_angles : callable or None
        [ϑ_L(y), ϑ_R(y)], the two tread contacts' angles, rad, vectorised: an array of shape
        ``(2, *y.shape)``, each within ±π/2. Each wheel spins about its contact normal by
        sin ϑ/r₀ (:func:`contact_forces`), and its normal force, tilted by ϑ, enters its lateral
        force Y (:func:`raildyn.curving.quasi_static.quasi_static_curving`). None: ϑ₀ ± Δϑ(y)/2
        of the wheelset (:func:`tread_contact_angles`; ϑ₀ ± εy/a on a cone).

    Each callable is tried once, at y = −e, 0 and e, and what it returns checked.
    """

    friction: float = 0.3
    flange_clearance: float = 9.1e-3
    flange_stiffness: float = 14.6e6
    rolling_radius_difference: Callable | None = None
    contact_angle_difference: Callable | None = None
    tread_angles: Callable | None = None

    def __post_init__(self):
        _checks.friction("friction", self.friction)
        scalar("flange_clearance", self.flange_clearance, low=0.0, low_open=True, high=0.05)
        nonnegative("flange_stiffness", self.flange_stiffness)
        y = np.array([-1.0, 0.0, 1.0]) * self.flange_clearance
        for name, bound in (("rolling_radius_difference", 0.1), ("contact_angle_difference", np.pi / 2)):
            fn = getattr(self, name)
            if fn is not None:
                out = _checks.returned(name, _checks.function(name, fn)(y), shape=(3,), at=f"y = {y} m")
                if np.abs(out).max() > bound:
                    raise ValueError(
                        f"{name} must return values within ±{bound:.4g}, returned {out} at y = {y} m"
                    )
        if self.tread_angles is not None:
            fn = _checks.function("tread_angles", self.tread_angles)
            out = _checks.returned("tread_angles", fn(y), shape=(2, 3), at=f"y = {y} m")
            if np.abs(out).max() > np.pi / 2:
                raise ValueError(f"tread_angles must return angles within ±π/2, returned {out} at y = {y} m")


_FLANGE_CONTACT_ANGLE = 0.7  # rad (40°): a contact steeper than this is on the flange, not the tread
_PROFILE_STEP = 2.5e-4  # m, the lateral step of the contact tables


def profile_contact(
    wheel, rail, *, friction=0.3, flange_stiffness=14.6e6, gauge=1.435, tape_distance=1.5
) -> WheelRailContact:
    """The nonlinear contact of a wheel and rail profile pair: tread tables and the flange.

    The rigid contact of chapter 4 (:func:`raildyn.contact.geometry.contact_geometry`, with
    the wheelset's roll) is followed outwards from the centre in steps of 0.25 mm until a
    contact angle passes 40°: there the contact jumps from the tread to the flange, and that
    shift is the flangeway clearance e. Inside it, the rolling-radius and contact-angle
    differences Δr(y) and Δϑ(y) and the two tread angles ϑ_L(y), ϑ_R(y) are tabulated and
    interpolated linearly; beyond it the tread
    keeps its contact, its differences continued along their last slope, while the flange
    carries the rest as a spring of ``flange_stiffness``: a two-point contact, tread and
    flange at once (Garg & Dukkipati 1984, ch. 4 and 8).

    Parameters
    ----------
    wheel : raildyn.contact.profiles.WheelProfile
    rail : raildyn.contact.profiles.RailProfile
    friction : float
        μ, > 0.
    flange_stiffness : float
        k_f, the lateral stiffness of the rail under flange contact, N/m (≥ 0).
    gauge, tape_distance : float
        m, as for :func:`raildyn.contact.geometry.contact_geometry`.

    Returns
    -------
    WheelRailContact

    Raises
    ------
    ValueError
        If no flange contact is found within 20 mm of the centre (a profile pair with no
        flange, such as a cone).

    Examples
    --------
    The S1002 wheel on UIC 60 rail inclined at 1:40 flanges 6.5 to 6.75 mm off centre:

    >>> from raildyn.contact.profiles import s1002_wheel, uic60_rail
    >>> contact = profile_contact(s1002_wheel(), uic60_rail(1 / 40))
    >>> round(1e3 * contact.flange_clearance, 2)
    6.5
    """
    from raildyn.contact.profiles import contact_geometry

    y = np.arange(0.0, 0.02 + _PROFILE_STEP / 2, _PROFILE_STEP)
    left = contact_geometry(wheel, rail, y, gauge=gauge, tape_distance=tape_distance)
    right = contact_geometry(wheel, rail, -y, gauge=gauge, tape_distance=tape_distance)
    steep = (left.contact_angle[0] > _FLANGE_CONTACT_ANGLE) | (right.contact_angle[1] > _FLANGE_CONTACT_ANGLE)
    if not steep.any():
        raise ValueError(
            f"wheel and rail must meet on a flange within {1e3 * y[-1]:g} mm of the centre, got no contact "
            f"steeper than {np.degrees(_FLANGE_CONTACT_ANGLE):g}° ({wheel.name!r} on {rail.name!r})"
        )
    last = int(np.argmax(steep)) - 1  # the last shift on the treads
    if last < 2:
        raise ValueError("wheel and rail must run on their treads when centred, got flange contact at y = 0")
    shifts = np.concatenate([-y[last:0:-1], y[: last + 1]])
    angles = [
        np.concatenate([right.contact_angle[k, last:0:-1], left.contact_angle[k, : last + 1]]) for k in (0, 1)
    ]
    dr = np.concatenate(
        [right.rolling_radius_difference[last:0:-1], left.rolling_radius_difference[: last + 1]]
    )
    dd = np.concatenate(
        [right.contact_angle_difference[last:0:-1], left.contact_angle_difference[: last + 1]]
    )
    return WheelRailContact(
        friction=friction,
        flange_clearance=float(y[last]),
        flange_stiffness=flange_stiffness,
        rolling_radius_difference=_Table(shifts, dr),
        contact_angle_difference=_Table(shifts, dd),
        tread_angles=_Tables(_Table(shifts, angles[0]), _Table(shifts, angles[1])),
    )


class _Tables:
    """Two tables side by side: [f₀(y), f₁(y)], shape (2, *y.shape)."""

    def __init__(self, *tables: _Table):
        self.tables = tables

    def __call__(self, y):
        return np.stack([table(y) for table in self.tables])


class _Table:
    """f(y) by linear interpolation in a table, continued along the slope of its end intervals."""

    def __init__(self, x: np.ndarray, f: np.ndarray):
        self.x, self.f = x, f
        self.slopes = ((f[1] - f[0]) / (x[1] - x[0]), (f[-1] - f[-2]) / (x[-1] - x[-2]))

    def __call__(self, y):
        y = np.asarray(y, dtype=float)
        out = np.interp(y, self.x, self.f)
        out = np.where(y < self.x[0], self.f[0] + self.slopes[0] * (y - self.x[0]), out)
        return np.where(y > self.x[-1], self.f[-1] + self.slopes[1] * (y - self.x[-1]), out)


def contact_forces(ws: Wheelset, contact: WheelRailContact, y, psi, ydot, psidot, speed):
    """Lateral force (N) and yaw moment (N·m) of the rails on a wheelset, nonlinear; arrays broadcast.

    Each wheel has the creepages of :func:`raildyn.contact.creepages.wheelset_creepages` with
    r_L,R = r₀ ± Δr(y)/2 and its own tread contact angle ϑ_L(y), ϑ_R(y)
    (:func:`tread_contact_angles`): γ_x = ∓(aψ̇/V + Δr/(2r₀)), γ_y = ẏ/V − ψ and the spin
    φ = ψ̇ cos ϑ/V ∓ sin ϑ/r₀ on the left/right wheel. Kalker's linear forces of each wheel,
    F_x = −f₁₁γ_x, F_y = −f₂₂γ_y − f₂₃φ and M_z = f₂₃γ_y − f₃₃φ, are scaled together by the
    saturation of Shen, Hedrick and Elkins (:func:`raildyn.contact.saturation.saturation_factor`)
    of that wheel's resultant √(F_x² + F_y²) at μ W/2, as
    :func:`raildyn.contact.saturation.shen_hedrick_elkins` scales them. Gravity acts through the
    contact-angle difference, and the flange as a spring beyond the clearance.

    One simplification: the spins ∓ sin ϑ_c/r₀ of the centred wheelset (ϑ_c its tread angles at
    y = 0, ϑ₀ on a cone) are taken out of each wheel's spin. Their forces ±f₂₃ sin ϑ_c/r₀ are
    equal and opposite and leave the wheelset's equations, as in the linear model; kept in each
    wheel, they would take up part of its adhesion at rest (39 % of μW/2 on the default cone of
    0.15, under 8 % on a tread of 2°) and the saturation's slope there would soften every creep
    force about the centre. Left out, the nonlinear wheelset linearises about the centre to
    exactly the forces of :func:`creep_terms`, and its Hopf point is the linear critical speed.

    Parameters
    ----------
    ws : Wheelset
    contact : WheelRailContact
    y, psi, ydot, psidot : float or ndarray
        Lateral displacement (m), yaw (rad) and their rates (m/s, rad/s): finite, of
        either sign, shapes that broadcast together.
    speed : float or ndarray
        V, m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`] (the creepages divide by
        it), of a shape that broadcasts with the motion.

    Returns
    -------
    lateral : ndarray
        N.
    yaw : ndarray
        N·m.
    """
    return _contact_forces(ws, contact, *_motion(ws, contact, y, psi, ydot, psidot, speed))


def _motion(ws, contact, y, psi, ydot, psidot, speed) -> list:
    """The checked [y, ψ, ẏ, ψ̇, V] of :func:`contact_forces` and :func:`wheel_forces`, broadcast."""
    _checks.instance("ws", ws, Wheelset)
    _checks.instance("contact", contact, WheelRailContact)
    names = (*_MOTION, "speed")
    motion = [_checks.array(name, v) for name, v in zip(_MOTION, (y, psi, ydot, psidot), strict=True)]
    motion.append(_checks.plausible_array("speed", speed, "speed", low_open=True))
    _checks.broadcast(**dict(zip(names, motion, strict=True)))
    return list(np.broadcast_arrays(*motion))


_MOTION = ("y", "psi", "ydot", "psidot")


def tread_contact_angles(ws: Wheelset, contact: WheelRailContact, y) -> np.ndarray:
    """The contact angles ϑ_L(y), ϑ_R(y) of a wheelset's two treads, rad.

    The contact's ``tread_angles`` where it has them (a profile pair,
    :func:`profile_contact`); else ϑ₀ ± Δϑ(y)/2 with Δϑ(y) the contact's
    ``contact_angle_difference`` or, on a cone, the linear 2εy/a of the wheelset.

    Parameters
    ----------
    ws : Wheelset
    contact : WheelRailContact
    y : float or array_like
        Lateral displacement of the wheelset relative to the rails, m, finite.

    Returns
    -------
    ndarray, shape (2, *y.shape)
        [ϑ_L, ϑ_R], rad.

    Examples
    --------
    >>> ws = Wheelset(contact_angle=0.05, contact_angle_parameter=0.1)
    >>> np.round(tread_contact_angles(ws, WheelRailContact(), 3e-3), 4).tolist()
    [0.0504, 0.0496]
    """
    _checks.instance("ws", ws, Wheelset)
    _checks.instance("contact", contact, WheelRailContact)
    return np.stack(_angles(ws, contact, _checks.array("y", y))[:2])


def _angles(ws: Wheelset, contact: WheelRailContact, y):
    """ϑ_L(y), ϑ_R(y) and Δϑ(y) of :func:`tread_contact_angles`, unchecked."""
    if contact.contact_angle_difference is None:
        dd = 2.0 * ws.contact_angle_parameter * np.asarray(y, dtype=float) / ws.half_gauge
    else:
        dd = contact.contact_angle_difference(y)
    if contact.tread_angles is None:
        return ws.contact_angle + dd / 2.0, ws.contact_angle - dd / 2.0, dd
    left, right = contact.tread_angles(y)
    return left, right, dd


def _creep(ws: Wheelset, contact: WheelRailContact, y, psi, ydot, psidot, speed):
    """Each wheel's creepages, Kalker's linear forces and their saturation factor; Δϑ(y).

    Returns γ_x, γ_y, φ, F_x, F_y, M_z and the factor, each of shape (2, ...) (left, right),
    and Δϑ.
    """
    r0 = ws.rolling_radius
    dr = (contact.rolling_radius_difference or _cone(ws.conicity))(y)
    theta_l, theta_r, dd = _angles(ws, contact, y)
    creep = wheelset_creepages(
        speed,
        ydot,
        psi,
        psidot,
        r0 + dr / 2.0,
        r0 - dr / 2.0,
        r0,
        ws.half_gauge,
        theta_l,
        theta_r,
        check=False,
    )
    xi_x, xi_y = creep.longitudinal, creep.lateral
    # Less the centred wheelset's spins ∓ sin ϑ_c/r₀, whose forces cancel (contact_forces says why).
    centred_l, centred_r = _angles(ws, contact, 0.0)[:2]
    spin = (
        creep.spin
        + np.array([np.sin(centred_l), -np.sin(centred_r)]).reshape((2,) + (1,) * (creep.spin.ndim - 1)) / r0
    )
    fx = -ws.f11 * xi_x
    fy = -ws.f22 * xi_y - ws.f23 * spin
    mz = ws.f23 * xi_y - ws.f33 * spin
    scale = saturation_factor(np.hypot(fx, fy), contact.friction * ws.axle_load / 2.0, check=False)
    return xi_x, xi_y, spin, fx, fy, mz, scale, dd


def _flange(contact: WheelRailContact, y):
    """The flange's lateral force on the wheelset, N: a spring beyond the clearance, pushing back."""
    excess = np.abs(y) - contact.flange_clearance
    return -contact.flange_stiffness * np.sign(y) * np.maximum(excess, 0.0)


def _contact_forces(ws: Wheelset, contact: WheelRailContact, y, psi, ydot, psidot, speed):
    """:func:`contact_forces` without the checks, for the right-hand sides (called at every step)."""
    a, W = ws.half_gauge, ws.axle_load
    _, _, _, fx, fy, mz, scale, dd = _creep(ws, contact, y, psi, ydot, psidot, speed)
    lateral = scale[0] * fy[0] + scale[1] * fy[1] - W / 2.0 * dd + _flange(contact, y)
    yaw = a * (scale[1] * fx[1] - scale[0] * fx[0]) + scale[0] * mz[0] + scale[1] * mz[1]
    return lateral, yaw + W * a * ws.contact_angle * psi


@dataclass(frozen=True)
class WheelForces:
    """The rails' forces on the two wheels of a wheelset; index 0 is the left wheel, 1 the right.

    Attributes
    ----------
    longitudinal, lateral : ndarray, shape (2, ...)
        Saturated creep forces on each wheel, N (forwards, to the left).
    flange : ndarray, shape (2, ...)
        Lateral force of the flange contact on each wheel, N (to the left; 0 off the flange).
    wear_number : ndarray, shape (2, ...)
        Tγ = |T_x γ_x| + |T_y γ_y| of each wheel, N (J/m): the creep forces' work per metre
        rolled, the wear index of Pearce & Sherratt (1991).

    All finite, of one shape (2, ...); the wear number ≥ 0.
    """

    longitudinal: np.ndarray
    lateral: np.ndarray
    flange: np.ndarray
    wear_number: np.ndarray

    def __post_init__(self):
        shape = np.shape(self.longitudinal)
        for name in ("longitudinal", "lateral", "flange", "wear_number"):
            value = _checks.array(name, getattr(self, name), low=0.0 if name == "wear_number" else None)
            if value.ndim == 0 or value.shape[0] != 2 or value.shape != shape:
                raise ValueError(
                    f"{name} must have the shape (2, ...) of longitudinal, {shape}, got {value.shape}"
                )
            object.__setattr__(self, name, value)


def wheel_forces(ws: Wheelset, contact: WheelRailContact, y, psi, ydot, psidot, speed) -> WheelForces:
    """The rails' creep and flange forces on each wheel of a wheelset, nonlinear; arrays broadcast.

    The same forces as :func:`contact_forces`, wheel by wheel: each wheel's creep forces
    −f γ scaled by the saturation factor, and the flange spring on the wheel whose flange
    touches (the left one for y > e).

    Parameters
    ----------
    ws : Wheelset
    contact : WheelRailContact
    y, psi, ydot, psidot, speed : float or ndarray
        As for :func:`contact_forces`.

    Returns
    -------
    WheelForces

    Examples
    --------
    A wheelset 12 mm to the left, past the 9.1 mm flangeway clearance, leans on its left flange:

    >>> f = wheel_forces(Wheelset(), WheelRailContact(), 0.012, 0.0, 0.0, 0.0, 30.0)
    >>> round(float(f.flange[0]) / 1e3, 1), float(f.flange[1])
    (-42.3, 0.0)
    """
    y, psi, ydot, psidot, speed = _motion(ws, contact, y, psi, ydot, psidot, speed)
    xi_x, xi_y, _, fx, fy, _, scale, _ = _creep(ws, contact, y, psi, ydot, psidot, speed)
    tx, ty = scale * fx, scale * fy
    flange = _flange(contact, y)
    return WheelForces(
        tx,
        ty,
        np.stack([np.where(y > 0, flange, 0.0), np.where(y < 0, flange, 0.0)]),
        np.abs(tx * xi_x) + np.abs(ty * xi_y),
    )


def _state(state, n: int) -> np.ndarray:
    """A finite state of n rows, (n,) or (n, k): the cheap check of a right-hand side's argument."""
    x = state if type(state) is np.ndarray and state.dtype == np.float64 else _checks.array("state", state)
    if not 1 <= x.ndim <= 2 or x.shape[0] != n:
        raise ValueError(f"state must have shape ({n},) or ({n}, k), got shape {x.shape}")
    if not math.isfinite(x.sum()):  # one sum at every step; the full check only to word the message
        _checks.array("state", x)
    return x


@dataclass(frozen=True)
class NonlinearWheelset:
    """The suspended wheelset with nonlinear contact, as ``rhs(t, state)`` for solve_ivp.

    State [y, ψ, ẏ, ψ̇] (m, rad, m/s, rad/s); the frame runs straight at ``speed``.
    """

    wheelset: Wheelset = field(default_factory=Wheelset)
    contact: WheelRailContact = field(default_factory=WheelRailContact)
    speed: float = 30.0

    def __post_init__(self):
        _checks.instance("wheelset", self.wheelset, Wheelset)
        _checks.instance("contact", self.contact, WheelRailContact)
        _speed(self.speed)

    state_size = 4
    lateral_index = 0  # the state entry of the lateral displacement followed in hunting studies

    def at_speed(self, speed) -> NonlinearWheelset:
        """The same wheelset at another speed.

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].

        Returns
        -------
        NonlinearWheelset
        """
        return NonlinearWheelset(self.wheelset, self.contact, speed)

    def rhs(self, t, state):
        """Time derivative of the state (vectorised over trailing columns).

        Parameters
        ----------
        t : float
            s, finite (the model is autonomous: unused).
        state : ndarray, (4,) or (4, k)
            [y, ψ, ẏ, ψ̇], finite.

        Returns
        -------
        ndarray, like ``state``
            [ẏ, ψ̇, ÿ, ψ̈].
        """
        scalar("t", t)
        ws = self.wheelset
        y, psi, ydot, psidot = _state(state, 4)
        fy, mz = _contact_forces(ws, self.contact, y, psi, ydot, psidot, self.speed)
        yddot = (fy - ws.lateral_stiffness * y - ws.lateral_damping * ydot) / ws.mass
        psiddot = (mz - ws.yaw_stiffness * psi - ws.yaw_damping * psidot) / ws.yaw_inertia
        return np.array([ydot, psidot, yddot, psiddot])


_ELEMENT_PROBE = (np.array([-1.0e-3, 0.0, 1.0e-3]), np.array([-0.01, 0.0, 0.01]))  # m (rad), m/s (rad/s)


@dataclass(frozen=True)
class SuspensionElement:
    """A nonlinear suspension element of a :class:`NonlinearLateral`: a force law along one deflection.

    The element acts on the deflection d = Σ cᵢ qᵢ, a linear combination of the
    model's coordinates (a relative displacement such as y_frame − y_bolster, or a
    relative yaw), and pulls it back with the force F = f(d, ḋ) (N, or N·m on an
    angle): the generalized forces are −F cᵢ. The linear model may hold a linear
    spring k and damper c on the same deflection (an equivalent viscous damper
    standing for friction, a spring standing for a clearance); ``stiffness`` and
    ``damping`` name them, and the nonlinear model removes k c cᵀ from K and
    c c cᵀ from C₀ so that the law replaces them. Examples of laws, from
    :mod:`raildyn.suspension`:

    * friction wedges, F = F_f tanh(ḋ/v_ε):
      ``lambda d, v: coulomb_friction(v, F_f, velocity_scale=v_eps)``;
    * a spring k in parallel with friction: ``lambda d, v: k * d + coulomb_friction(v, ...)``;
    * a lateral play (clearance g, stop k_s beyond it):
      ``lambda d, v: clearance_force(d, g, k_s)``.

    Attributes
    ----------
    coordinates : dict of str to float
        Label of a coordinate of the model → its coefficient cᵢ (finite, at least one
        non-zero).
    force : callable
        f(d, ḋ) → F, vectorised: given two float arrays of one shape (m and m/s, or rad and
        rad/s), an array of that shape (N or N·m, finite). Tried once, at
        d = (−1, 0, 1) mm and ḋ = (−10, 0, 10) mm/s, and what it returns checked.
    stiffness, damping : float
        The linear spring (N/m) and damper (N·s/m) on d that the linear model holds in the
        element's place, each ≥ 0 (per radian for an angle); 0 where it holds none.
    """

    coordinates: dict
    force: Callable
    stiffness: float = 0.0
    damping: float = 0.0

    def __post_init__(self):
        _checks.instance("coordinates", self.coordinates, dict, "dict of coordinate label to coefficient")
        values = []
        for label, value in self.coordinates.items():
            _checks.instance("coordinates key", label, str, "str (a coordinate label)")
            values.append(scalar(f"coordinates[{label!r}]", value))
        if not any(values):
            raise ValueError(
                f"coordinates must give at least one non-zero coefficient, got {self.coordinates!r}"
            )
        law = _checks.function("force", self.force)
        d, v = _ELEMENT_PROBE
        _checks.returned("force", law(d.copy(), v.copy()), shape=d.shape, at=f"d = {d}, ḋ = {v}")
        nonnegative("stiffness", self.stiffness)
        nonnegative("damping", self.damping)


@dataclass(frozen=True)
class NonlinearLateral:
    """Any lateral :class:`~raildyn.linear_model.LinearSystem` with its linear wheel–rail terms replaced
    by :func:`contact_forces`, and optional nonlinear suspension elements.

    M q̈ = −C_s q̇ − K_s q + Σ F_contact − Σ_e F_e c_e, where K_s is K without the creep and
    gravitational terms of each wheelset and without each element's linear spring, C_s is C₀
    without each element's linear damper, and F_e = f_e(c_e·q, c_e·q̇) is the force of
    :class:`SuspensionElement` e on its deflection c_e·q. State [q; q̇]; ``rhs(t, state)``
    for solve_ivp.

    On a ``curve`` the coordinates are taken in axes that follow the vehicle: their origin
    runs along the track's centre line at V, at s_c = ``start`` + V t, turning with the
    track's tangent there at V κ(s_c) (the steady-curving axes of
    :func:`raildyn.curving.steady.steady_curving`, here with a curvature that varies). A wheelset
    x ahead of the origin meets the track displaced by y_t = ∫₀ˣ (x − u) κ(s_c + u) du,
    computed as ½x² κ(s_c + x/3), exact where κ is linear in s (a clothoid); its contact
    forces are those of :func:`contact_forces` at y − y_t, with the yaw ψ − x κ(s_c) that the
    axes' own turning gives its path, and the yaw rate ψ̇ + V κ(s_c). Every lateral
    coordinate (label ending in " y") carries −m a_q, a_q = V²κ(s_c) − g D(s_c)/G
    (:meth:`raildyn.curving.geometry.Curve.unbalanced_acceleration`). The
    Coriolis and Euler forces of the turning axes (of order m V κ ẏ) are left out.

    Attributes
    ----------
    system : LinearSystem
        With at least one wheelset on the rails.
    contact : WheelRailContact
    speed : float
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    elements : tuple of SuspensionElement
        Nonlinear suspension elements, each naming coordinates of ``system``; empty by default.
    curve : raildyn.curving.geometry.Curve or None
        The track's curve (turning left); None: tangent track.
    start : float
        s_c at t = 0, the distance of the vehicle's centre along ``curve``, m (finite).
    """

    system: LinearSystem
    contact: WheelRailContact = field(default_factory=WheelRailContact)
    speed: float = 30.0
    elements: tuple = ()
    curve: object = None
    start: float = 0.0
    # Derived once from the fields above (not arguments): the suspension stiffness and damping, M⁻¹,
    # the wheelsets grouped by their parameters, and the elements' deflection rows and laws.
    _K_suspension: np.ndarray = field(init=False, repr=False, compare=False)
    _C_suspension: np.ndarray = field(init=False, repr=False, compare=False)
    _M_inv: np.ndarray = field(init=False, repr=False, compare=False)
    _groups: list = field(init=False, repr=False, compare=False)
    _G: np.ndarray | None = field(init=False, repr=False, compare=False)
    _laws: tuple = field(init=False, repr=False, compare=False)
    _lateral_mass: np.ndarray = field(init=False, repr=False, compare=False)
    _positions: np.ndarray | None = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        _speed(self.speed)
        if self.curve is not None:
            from raildyn.curving.geometry import Curve  # here: raildyn.curving imports this module

            _checks.instance("curve", self.curve, Curve)
        scalar("start", self.start)
        _checks.instance("system", self.system, LinearSystem)
        _checks.instance("contact", self.contact, WheelRailContact)
        if not self.system.wheelsets:
            raise ValueError("system has no wheelsets in contact with the rails")
        if isinstance(self.elements, str) or not isinstance(self.elements, (tuple, list)):
            raise TypeError(f"elements must be a tuple of SuspensionElement, got {self.elements!r:.80}")
        labels = self.system.labels
        n = self.system.size
        G = np.zeros((len(self.elements), n))
        for i, element in enumerate(self.elements):
            _checks.instance(f"elements[{i}]", element, SuspensionElement)
            for label, value in element.coordinates.items():
                if label not in labels:
                    raise ValueError(
                        f"elements[{i}] coordinates must be labels of system {labels}, got {label!r}"
                    )
                G[i, labels.index(label)] += value
        object.__setattr__(self, "elements", tuple(self.elements))
        K_s = np.array(self.system.K, dtype=float, copy=True)
        C_s = np.array(self.system.C0, dtype=float, copy=True)
        for iy, ipsi, ws in self.system.wheelsets:
            terms = creep_terms(ws)
            idx = np.ix_([iy, ipsi], [iy, ipsi])
            K_s[idx] -= terms.K_creep + terms.K_gravity
        for g, element in zip(G, self.elements, strict=True):
            K_s -= element.stiffness * np.outer(g, g)
            C_s -= element.damping * np.outer(g, g)
        object.__setattr__(self, "_K_suspension", K_s)
        object.__setattr__(self, "_C_suspension", C_s)
        object.__setattr__(self, "_M_inv", np.linalg.inv(self.system.M))
        # Wheelsets with equal parameters are evaluated together in one vectorised call.
        # Each wheelset's place along the vehicle, for a curve; a system that does not give them (no
        # alignment inputs) runs on tangent track only.
        try:
            positions = self.system.wheelset_positions
        except ValueError as err:
            if self.curve is not None:
                raise ValueError(f"system cannot run on a curve: {err}") from None
            positions = None
        object.__setattr__(self, "_positions", positions)
        if positions is None:
            positions = np.zeros(len(self.system.wheelsets))
        groups: dict = {}
        for (iy, ipsi, ws), x in zip(self.system.wheelsets, positions, strict=True):
            groups.setdefault(ws, ([], [], []))
            for column, value in zip(groups[ws], (iy, ipsi, x), strict=True):
                column.append(value)
        object.__setattr__(
            self, "_groups", [(ws, np.array(a), np.array(b), np.array(x)) for ws, (a, b, x) in groups.items()]
        )
        lateral = np.array([label.endswith(" y") for label in self.system.labels], dtype=float)
        object.__setattr__(self, "_lateral_mass", self.system.M @ lateral)
        object.__setattr__(self, "_G", G if self.elements else None)  # None: no elements
        object.__setattr__(self, "_laws", tuple(e.force for e in self.elements))

    @property
    def state_size(self) -> int:
        return 2 * self.system.size

    @property
    def lateral_index(self) -> int:
        """State entry of the first wheelset's lateral displacement (followed in hunting studies)."""
        return self.system.wheelsets[0][0]

    def at_speed(self, speed) -> NonlinearLateral:
        """The same model at another speed.

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].

        Returns
        -------
        NonlinearLateral
        """
        return NonlinearLateral(self.system, self.contact, speed, self.elements, self.curve, self.start)

    def rhs(self, t, state):
        """Time derivative of [q; q̇].

        Parameters
        ----------
        t : float
            s, finite (the model is autonomous: unused).
        state : ndarray, (2n,) or (2n, k)
            [q; q̇], finite.

        Returns
        -------
        ndarray, like ``state``
            [q̇; q̈].
        """
        scalar("t", t)
        n = self.system.size
        state = _state(state, 2 * n)
        q, qdot = state[:n], state[n:]
        force = -self._C_suspension @ qdot - self._K_suspension @ q
        force = np.array(force, dtype=float, copy=True)
        if self.curve is None:
            for ws, iy, ipsi, _ in self._groups:
                fy, mz = _contact_forces(ws, self.contact, q[iy], q[ipsi], qdot[iy], qdot[ipsi], self.speed)
                force[iy] += fy
                force[ipsi] += mz
        else:
            self._curve_forces(t, q, qdot, force)
        if self._laws:
            d, v = self._G @ q, self._G @ qdot
            pull = np.array([law(d[i], v[i]) for i, law in enumerate(self._laws)], dtype=float)
            force -= self._G.T @ pull
        return np.concatenate([qdot, self._M_inv @ force])

    def relative_to_track(self, t, state) -> tuple[np.ndarray, np.ndarray]:
        """Each wheelset's lateral displacement and yaw relative to the track where it runs.

        On tangent track these are its coordinates; on a ``curve``, y − y_t and ψ − ψ_t with
        y_t = ½x²κ(s_c + x/3) and the track's tangent ψ_t = x κ(s_c + x/2) (both exact where κ
        is linear in s).

        Parameters
        ----------
        t : float
            s, finite.
        state : ndarray, (2n,) or (2n, k)
            [q; q̇], finite.

        Returns
        -------
        offset : ndarray, (w,) or (w, k)
            m, to the left, one row per wheelset in the order of ``system.wheelsets``.
        yaw : ndarray, like ``offset``
            rad, anticlockwise.
        """
        t = scalar("t", t)
        n = self.system.size
        q = _state(state, 2 * n)[:n]
        iy = np.array([w[0] for w in self.system.wheelsets])
        ipsi = np.array([w[1] for w in self.system.wheelsets])
        if self.curve is None:
            return q[iy].copy(), q[ipsi].copy()
        x = self.system.wheelset_positions
        s_c = self.start + self.speed * t
        column = (slice(None),) + (None,) * (q.ndim - 1)
        y_t = (0.5 * x * x * self.curve.curvature(s_c + x / 3.0))[column]
        psi_t = (x * self.curve.curvature(s_c + x / 2.0))[column]
        return q[iy] - y_t, q[ipsi] - psi_t

    def arc_forces(self, q, speed, curvature, unbalanced_acceleration) -> np.ndarray:
        """The generalized forces on the model at rest on circular arcs, for a batch of states at once.

        In the axes that follow the vehicle round an arc of curvature κ at the speed V (the
        class docstring, with κ the same under every wheelset: y_t = ½x²κ, the path's yaw x κ,
        the yaw rate V κ) and with q̇ = 0. Their zero is the quasi-static equilibrium of
        :func:`raildyn.curving.quasi_static.quasi_static_curving`. The model's own ``speed``, ``curve`` and
        ``start`` are not used.

        Parameters
        ----------
        q : ndarray, (n,) or (n, k)
            Coordinates, finite; one column per state of the batch.
        speed : float or array_like, (k,)
            V, m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
        curvature : float or array_like, (k,)
            κ = 1/R, 1/m, finite (positive: turning left).
        unbalanced_acceleration : float or array_like, (k,)
            a_q, m/s², finite (positive outwards).

        Returns
        -------
        ndarray, like ``q``
            N and N·m on each coordinate.
        """
        if self._positions is None:
            raise ValueError(
                "system cannot run on a curve: its wheelsets have no alignment inputs to place them"
            )
        n = self.system.size
        q = _checks.array("q", q)
        if not 1 <= q.ndim <= 2 or q.shape[0] != n:
            raise ValueError(f"q must have shape ({n},) or ({n}, k), got shape {q.shape}")
        batch = () if q.ndim == 1 else (q.shape[1],)
        V = _checks.plausible_array("speed", speed, "speed", low_open=True)
        kappa = _checks.array("curvature", curvature)
        a_q = _checks.array("unbalanced_acceleration", unbalanced_acceleration)
        for name, value in (("speed", V), ("curvature", kappa), ("unbalanced_acceleration", a_q)):
            if value.shape not in ((), batch):
                raise ValueError(
                    f"{name} must be a float or have the shape {batch} of q's batch, got {value.shape}"
                )
        column = (slice(None),) + (None,) * (q.ndim - 1)
        force = -self._K_suspension @ q
        self._add_curved_contact(
            q, np.zeros_like(q), V, kappa, lambda x: track_on_arc(x[column], kappa)[0], force
        )
        if self._laws:
            d = self._G @ q
            pull = np.array([law(d[i], np.zeros_like(d[i])) for i, law in enumerate(self._laws)], dtype=float)
            force -= self._G.T @ pull
        force -= self._lateral_mass[column] * a_q
        return force

    def arc_jacobian(self, q, speed, curvature, unbalanced_acceleration) -> np.ndarray:
        """∂F/∂q of :meth:`arc_forces`, for a batch of states at once.

        The suspension's part is −K_s exactly. Each wheelset's contact forces depend on its own
        y and ψ only, so their 2 × 2 blocks come from forward differences of every wheelset at
        once (two more evaluations of the contact, not n); each nonlinear element's from one more
        evaluation of the laws, through its deflection row. The step, 1e-7 m (rad), is well
        above rounding and below the scale of the flange's and the saturation's bends.

        Parameters
        ----------
        q, speed, curvature, unbalanced_acceleration
            As for :meth:`arc_forces`.

        Returns
        -------
        ndarray, (n, n) or (k, n, n)
            N/m, N, N·m/rad … : row i, column j is ∂F_i/∂q_j; one matrix per column of ``q``.
        """
        self.arc_forces(q, speed, curvature, unbalanced_acceleration)  # the checks, and a finite answer
        q = np.asarray(q, dtype=float)
        V, kappa = np.asarray(speed, dtype=float), np.asarray(curvature, dtype=float)
        column = (slice(None),) + (None,) * (q.ndim - 1)
        n, h = self.system.size, 1.0e-7
        J = np.broadcast_to(-self._K_suspension, (*q.shape[1:], n, n)).copy()
        for ws, iy, ipsi, x in self._groups:
            y_t, psi_t = track_on_arc(x[column], kappa)
            y, psi = q[iy] - y_t, q[ipsi] - psi_t
            rate = np.zeros_like(y) + V * kappa

            def forces(dy, dpsi, ws=ws, y=y, psi=psi, rate=rate):
                return _contact_forces(ws, self.contact, y + dy, psi + dpsi, 0.0 * y, rate, V)

            fy, mz = forces(0.0, 0.0)
            for j, shifted in ((iy, forces(h, 0.0)), (ipsi, forces(0.0, h))):
                for i, base, moved in ((iy, fy, shifted[0]), (ipsi, mz, shifted[1])):
                    # one entry per wheelset: its own rows and columns
                    slope = np.moveaxis(np.asarray((moved - base) / h), 0, -1)
                    J[..., i, j] += slope
        if self._laws:
            d = self._G @ q
            rest = np.zeros_like(d[0])
            slope = np.array(
                [(law(d[i] + h, rest) - law(d[i], rest)) / h for i, law in enumerate(self._laws)]
            )
            J -= np.einsum("ei,e...,ej->...ij", self._G, slope, self._G)
        return J

    def _add_curved_contact(self, q, qdot, V, kappa, track, force) -> None:
        """Add the wheel–rail forces in the axes that follow a curve to ``force``: each wheelset at y − y_t
        with y_t = ``track``(x), the yaw ψ − x κ of its path and the yaw rate ψ̇ + V κ."""
        column = (slice(None),) + (None,) * (q.ndim - 1)  # a wheelset's x against a batch of states
        for ws, iy, ipsi, x in self._groups:
            psi_path = x[column] * kappa  # the direction of the wheelset's path, not the track's tangent
            fy, mz = _contact_forces(
                ws, self.contact, q[iy] - track(x), q[ipsi] - psi_path, qdot[iy], qdot[ipsi] + V * kappa, V
            )
            force[iy] += fy
            force[ipsi] += mz

    def _curve_forces(self, t: float, q, qdot, force) -> None:
        """Add the contact forces on the curve and the unbalanced weight to ``force`` (see the class)."""
        V, curve = self.speed, self.curve
        s_c = self.start + V * t
        kappa = float(curve.curvature(s_c))
        a_q = float(curve.unbalanced_acceleration(s_c, V))
        column = (slice(None),) + (None,) * (q.ndim - 1)
        self._add_curved_contact(
            q, qdot, V, kappa, lambda x: (0.5 * x * x * curve.curvature(s_c + x / 3.0))[column], force
        )
        force -= self._lateral_mass[column] * a_q
