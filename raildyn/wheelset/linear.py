"""The linear wheelset of chapter 5 on tangent track: its parameters and Kalker's linear wheel–rail terms.

* :class:`~raildyn.wheelset.Wheelset`, a parameter set and a linear model of the one protocol
  (:class:`raildyn.linear_model.LinearModel`: ``Wheelset().matrices(V)``, ``state_space(V)``):
  lateral displacement and yaw on a primary suspension to a frame running straight at V;
* its wheel–rail terms, creep damping, creep stiffness and gravitational stiffness
  (:func:`~raildyn.wheelset.creep_terms`), which :func:`~raildyn.wheelset.add_wheelset` adds
  to any assembled model (the bogies and cars of :mod:`raildyn.vehicles` too);
* Wickens' critical speed of a wheelset on a yaw spring
  (:func:`~raildyn.wheelset.wickens_critical_speed`).

Coordinates: y to the left, ψ turning to the left. SI units throughout.
"""

from __future__ import annotations

from dataclasses import dataclass

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
from raildyn.contact.hertz import hertz_contact
from raildyn.contact.kalker import creep_coefficients
from raildyn.linear_model import Assembler, LinearModelBase, LinearSystem
from raildyn.wheelset.kinematics import _MAX_ANGLE

__all__ = ["CreepTerms", "Wheelset", "add_wheelset", "creep_terms", "wickens_critical_speed"]


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

    def on_profiles(self, wheel, rail, amplitude=3.0e-3, *, gauge=1.435, tape_distance=1.5) -> Wheelset:
        """The same wheelset linearised on a real wheel and rail profile pair at a lateral amplitude ŷ.

        The cone's three contact parameters come from the pair's contact geometry
        (:func:`raildyn.contact.geometry.contact_geometry`, with the wheelset's roll):

        * the conicity is EN 15302's equivalent conicity λ_e(ŷ)
          (:func:`raildyn.contact.geometry.equivalent_conicity`);
        * the contact angle ϑ₀ is the mean of the two treads' contact angles when centred, and the
          rolling radius r₀ the mean of their rolling radii;
        * ε is read, like λ_e, over a motion of amplitude ŷ: the model's contact-angle difference is
          Δϑ = 2εy/a, so ε = a k_ϑ(ŷ), with k_ϑ the first-harmonic slope of Δϑ(y)/2 over
          y = ŷ sin θ (:func:`raildyn.contact.conicity.harmonic_conicity` of the Δϑ table).

        The creep coefficients, the axle load, the half-spacing a and the suspension stay.

        Parameters
        ----------
        wheel : raildyn.contact.geometry.WheelProfile
        rail : raildyn.contact.geometry.RailProfile
        amplitude : float
            ŷ, m, in [0.001, 0.01]: EN 15302 quotes λ_e at 3 mm; the treads carry the wheelset to
            about 6 mm, where a new S1002 wheel reaches its flange. Below 1 mm a new profile pair's
            λ_e runs past the linear model's bound of 0.5.
        gauge, tape_distance : float
            m, as for :func:`~raildyn.contact.geometry.contact_geometry`.

        Returns
        -------
        Wheelset

        Examples
        --------
        A conical wheel of slope 1:20 linearises to its cone: λ_e, ϑ₀ and ε all about 0.05, the
        values a :class:`Wheelset` takes for a cone (its roll on the rails adds 2 % to λ_e):

        >>> from raildyn.contact.profiles import conical_wheel, uic60_rail
        >>> ws = Wheelset().on_profiles(conical_wheel(1 / 20), uic60_rail(1 / 40))
        >>> round(ws.conicity, 3), round(ws.contact_angle, 3), round(ws.contact_angle_parameter, 3)
        (0.051, 0.05, 0.05)
        """
        from raildyn.contact.conicity import harmonic_conicity
        from raildyn.contact.geometry import contact_geometry, equivalent_conicity

        A = scalar("amplitude", amplitude, low=1.0e-3, high=0.01)
        options = {"gauge": gauge, "tape_distance": tape_distance}
        conicity = float(equivalent_conicity(wheel, rail, A, **options)[0])
        if conicity > _MAX_ANGLE:
            raise ValueError(
                f"amplitude {A!r} m gives this profile pair an equivalent conicity of {conicity:.3g}, beyond "
                f"the linear model's {_MAX_ANGLE}: take a larger amplitude (EN 15302 quotes 3 mm)"
            )
        y = np.linspace(-A, A, 801)
        geometry = contact_geometry(wheel, rail, y, **options)
        # Δϑ is odd in y (the wheels are mirror images): its odd part removes the contact search's rounding.
        dd = 0.5 * (geometry.contact_angle_difference - geometry.contact_angle_difference[::-1])
        centred = contact_geometry(wheel, rail, 0.0, **options)
        return self.replace(
            conicity=conicity,
            contact_angle=float(centred.contact_angle.mean()),
            contact_angle_parameter=self.half_gauge * float(harmonic_conicity(y, dd, A)[0]),
            rolling_radius=float(centred.rolling_radius.mean()),
        )

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
