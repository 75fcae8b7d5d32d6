"""Six-axle locomotive in the lateral plane: a body on two three-axle trucks (book chapters 6 and 7).

* :class:`~raildyn.vehicles.locomotive_lateral.ThreeAxleTruck` — a truck frame (lateral,
  yaw) on three wheelsets at +d, 0 and −d (lateral, yaw each), joined by the secondary
  suspension (flexicoil springs, dampers) to a body running straight: 8 degrees of freedom;
* :class:`~raildyn.vehicles.locomotive_lateral.LateralLocomotive` — a body (lateral, yaw,
  roll) on two such trucks: 19 degrees of freedom, driven by the alignment and the cross-level under each of
  its six wheelsets (12 inputs, ordered as :class:`~raildyn.vehicles.lateral.LateralCar`'s).

Both follow the one linear protocol (:class:`raildyn.linear_model.LinearModel`), so
:mod:`raildyn.stability` and :mod:`raildyn.vehicles.response` take them unchanged,
and ``nonlinear()`` gives the nonlinear counterpart
(:class:`~raildyn.wheelset.NonlinearLateral`: nonlinear wheel–rail contact, and the
middle axles' play as a clearance).

Traction motors. Each axle drives through a nose-suspended motor: the motor hangs
on the axle through its suspension bearings and rests its nose on the frame, so a
share of its mass (``motor_axle_share``, a half by default: the motor is carried
about half by the axle and half by the nose) moves with the wheelset and the rest
with the frame. The axle's share adds to the wheelset's lateral mass; the frame's
share adds to the frame's mass and, at each axle's position x, m x² to its yaw
inertia. The motors' own yaw inertia and their offset ahead of or behind the axle
are left out.

The middle axle's lateral play. The middle axle of a three-axle locomotive truck is
given a free lateral clearance in the frame (so that the truck can curve), beyond
which a stop engages. The linear model represents small motions within the play:
the middle axle is held laterally only by its soft centring springs
(``middle_lateral_stiffness``), while the end axles have the full primary lateral
stiffness of the :class:`~raildyn.wheelset.Wheelset`. The nonlinear models
(:meth:`~raildyn.vehicles.locomotive_lateral.ThreeAxleTruck.nonlinear`,
:meth:`~raildyn.vehicles.locomotive_lateral.LateralLocomotive.nonlinear`) replace that
spring by the clearance law of
:meth:`~raildyn.vehicles.locomotive_lateral.ThreeAxleTruck.play_element`: the soft centring
inside the play (``middle_lateral_play``) and, beyond it, a stop as stiff as the end
axles' primary spring.

The default values (:data:`~raildyn.vehicles.locomotive_lateral.LATERAL_LOCOMOTIVE`) are
representative of an EMD SD40-2, as the vertical :class:`~raildyn.vehicles.locomotive.VerticalLocomotive` is,
and use its masses and spacings so that the two models describe one locomotive; no
published lateral parameter set of a six-axle locomotive was found. Each value is
given with its source or its reasoning beside the constant below.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from raildyn import _checks, contact
from raildyn._checks import nonnegative, positive
from raildyn.constants import GRAVITY, STANDARD_RAIL_SPACING
from raildyn.linear_model import Assembler, LinearModelBase, LinearSystem
from raildyn.suspension import clearance_force
from raildyn.vehicles._shared import (
    _check_body_on_two_trucks,
    _check_truck_assembly,
    _nonlinear,
    _replace_through,
)
from raildyn.vehicles.locomotive import DEFAULT_LOCOMOTIVE
from raildyn.wheelset import (
    NonlinearLateral,
    SuspensionElement,
    WheelRailContact,
    Wheelset,
    add_wheelset,
    rigid_bogie_wavelength,
)

__all__ = ["LATERAL_LOCOMOTIVE", "LateralLocomotive", "ThreeAxleTruck", "rigid_truck_wavelength"]

# ---------------------------------------------------------------------------
# Representative values of an EMD SD40-2 (no published lateral parameter set was found).
#
# From the vertical model raildyn.vehicles.locomotive.VerticalLocomotive (one locomotive, two models):
# total mass 167 t (368 000 lb, Wikipedia "EMD SD40-2"), body 133 t, truck 6.5 t, unsprung 3.5 t per
# axle; truck centres 13.26 m apart (43 ft 6 in, Wikipedia); 2.07 m between neighbouring axles;
# secondary vertical stiffness 5.15 MN/m and damping 60 kN·s/m per truck.
_BODY_MASS = DEFAULT_LOCOMOTIVE.body_mass  # kg
_SEMI_TRUCK_SPACING = DEFAULT_LOCOMOTIVE.semi_truck_spacing  # m
_AXLE_SPACING = DEFAULT_LOCOMOTIVE.axle_spacing  # m
# Body yaw inertia: m L²/12 for a 20 m body, as the vertical model's pitch inertia.
_BODY_YAW_INERTIA = _BODY_MASS * 20.0**2 / 12
# Body roll inertia: m (w² + h²)/12 for a box 3.12 m wide (10 ft 3 in, Wikipedia "EMD SD40-2") with its
# mass spread over 2.5 m of height (representative: frame, engine and hood).
_BODY_ROLL_INERTIA = _BODY_MASS * (3.12**2 + 2.5**2) / 12
# Centre of gravity 1.9 m above rail, flexicoil lateral seat 1.0 m above rail (representative of a
# diesel-electric locomotive), so 0.9 m above the secondary lateral springs.
_BODY_HEIGHT = 0.9
# Traction motor: about 3 t for a nose-suspended DC motor of a six-axle diesel (representative). Half
# rides on the axle: a nose-suspended motor rests on its axle through the suspension bearings and on the
# frame through its nose, a part of its weight unsprung (Wikipedia "Traction motor", nose-suspended
# motors; the half split is the usual approximation, e.g. Italian Wikipedia "Sospensione per il naso").
_MOTOR_MASS = 3000.0  # kg
_MOTOR_AXLE_SHARE = 0.5
# Wheelset: the vertical model's 3.5 t unsprung per axle less the motor's axle share, 1.5 t: 2.0 t.
_WHEELSET_MASS = 3500.0 - _MOTOR_AXLE_SHARE * _MOTOR_MASS
# Wheelset yaw inertia: the Manchester wheelset's 1120 kg·m² for 1813 kg (Iwnicki 1998) scaled by mass
# (a heavier axle and bull gear on the same gauge).
_WHEELSET_YAW_INERTIA = 1120.0 * _WHEELSET_MASS / 1813.0
# Frame: the vertical model's 6.5 t truck less the frame's share of three motors (3 × 1.5 t): 2.0 t;
# its own yaw inertia m L²/12 for a 4.5 m frame, as the vertical model's pitch inertia.
_FRAME_MASS = 6500.0 - 3 * (1.0 - _MOTOR_AXLE_SHARE) * _MOTOR_MASS
_FRAME_YAW_INERTIA = _FRAME_MASS * 4.5**2 / 12
# Wheels 40 in (1.016 m) in diameter (Wikipedia "EMD SD40-2"), new AAR 1:20 tapered treads (conicity
# 0.05), contact points 1.5 m apart on standard gauge.
_ROLLING_RADIUS = 40 * 0.0254 / 2
_HALF_GAUGE = 0.75
_CONICITY = 1.0 / 20.0
_AXLE_LOAD = 167_000.0 * GRAVITY / 6  # N, the whole locomotive's weight over six axles
# Primary, per axle (representative of pedestal liners and rubber thrust pads): end axles lateral
# 10 MN/m; longitudinal 5 MN/m per axlebox at ±1.0 m, so 2 × 5 MN/m × 1 m² in yaw; light damping.
_PRIMARY_LATERAL = 10.0e6
_PRIMARY_YAW = 2 * 5.0e6 * 1.0**2
_PRIMARY_LATERAL_DAMPING = 10.0e3
_PRIMARY_YAW_DAMPING = 10.0e3
# Middle axle: a free lateral play of ±19 mm (3/4 in) in the frame, centred by soft springs of
# 0.3 MN/m, its stop 10 MN/m (as the end axles) beyond the play (representative).
_MIDDLE_LATERAL = 0.3e6
_MIDDLE_PLAY = 0.019
# Secondary, per truck (representative): four flexicoil springs, 1.0 MN/m laterally together (body
# lateral mode near 0.6 Hz), each a quarter of it in shear at (±1.0 m, ±1.0 m) from the truck centre, so
# Σ k_i r_i² = 1.0 MN/m × 2 m² = 2 MN·m/rad in yaw; lateral dampers 40 kN·s/m; no yaw dampers (a
# freight locomotive of the period; yaw dampers of 2 × 200 kN·s/m at ±1.2 m would raise the critical
# speed by some 15 %).
_SECONDARY_LATERAL = 1.0e6
_SECONDARY_LATERAL_DAMPING = 40.0e3
_SECONDARY_YAW = _SECONDARY_LATERAL * (1.0**2 + 1.0**2)
_SECONDARY_YAW_DAMPING = 0.0
# Body roll per truck: the vertical model's secondary stiffness and damping split between springs at
# ±1.0 m from the centre line (k y² per truck).
_ROLL_STIFFNESS = DEFAULT_LOCOMOTIVE.secondary_stiffness * 1.0**2
_ROLL_DAMPING = DEFAULT_LOCOMOTIVE.secondary_damping * 1.0**2


def _locomotive_wheelset() -> Wheelset:
    """The SD40-2 wheelset on a 1:20 cone: Kalker's coefficients on Hertz's patch under half the axle load.

    The patch is that of a 0.508 m wheel on a rail crowned with the same radius (a circle), as the
    Manchester default of :class:`~raildyn.wheelset.Wheelset` assumes, for the steel of
    :mod:`raildyn.constants`.
    """
    patch = contact.hertz_contact(_AXLE_LOAD / 2, _ROLLING_RADIUS, np.inf, _ROLLING_RADIUS)
    f = contact.creep_coefficients(patch.a, patch.b)
    return Wheelset(
        mass=_WHEELSET_MASS,
        yaw_inertia=_WHEELSET_YAW_INERTIA,
        rolling_radius=_ROLLING_RADIUS,
        half_gauge=_HALF_GAUGE,
        conicity=_CONICITY,
        axle_load=_AXLE_LOAD,
        f11=float(f.f11),
        f22=float(f.f22),
        f23=float(f.f23),
        f33=float(f.f33),
        lateral_stiffness=_PRIMARY_LATERAL,
        yaw_stiffness=_PRIMARY_YAW,
        lateral_damping=_PRIMARY_LATERAL_DAMPING,
        yaw_damping=_PRIMARY_YAW_DAMPING,
    )


def rigid_truck_wavelength(rolling_radius, half_gauge, conicity, axle_spacing) -> float:
    """Kinematic wavelength of three wheelsets held rigidly parallel in a truck, at +d, 0 and −d, m.

    L = 2π √(r₀ a / λ · (1 + 2d²/(3a²))).

    Derivation (Wickens 2003, ch. 2, for two axles; the same steps for n): with
    f₁₁ = f₂₂ and no inertia, a rigid truck (lateral y, yaw ψ) whose wheelsets sit at
    x_i moves each of them by y + x_i ψ. The lateral creep forces sum to
    −2f₂₂ n (ẏ/V − ψ) (Σ x_i = 0), so y′ = ψ along the track. The yaw moments of the
    longitudinal creep forces, −2af₁₁(aψ̇/V + λ(y + x_iψ)/r₀), and of the lateral ones
    about the centre, −2f₂₂ x_i(ẏ + x_iψ̇)/V + 2f₂₂x_iψ, sum to
    −2f (n a² + Σx_i²) ψ′ − 2f n a λ y/r₀ = 0. Hence
    y″ = −λ/(a r₀) · y / (1 + Σx_i²/(n a²)): the free wheelset's wavenumber
    √(λ/(a r₀)) divided by √(1 + Σx_i²/(n a²)). Two axles at ±b give Klingel's
    rigid-bogie factor 1 + b²/a² (:func:`raildyn.wheelset.rigid_bogie_wavelength`);
    three at ±d and 0 give 1 + 2d²/(3a²): the middle axle adds creep forces that
    steer without adding a moment arm, so the truck's wave is shorter than that of a
    two-axle bogie of the same length.

    Parameters
    ----------
    rolling_radius, half_gauge, conicity : float
        r₀ (m, > 0), a (m, > 0) and λ (> 0), as for :func:`raildyn.wheelset.kinematic_wavelength`.
    axle_spacing : float
        d, between neighbouring axles, m, in [0.0123, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "vehicle_length"; the lower end gives the least semi-wheelbase √(2/3) d that
        :func:`~raildyn.wheelset.rigid_bogie_wavelength` takes).

    Returns
    -------
    float
        L, m.

    Examples
    --------
    >>> round(rigid_truck_wavelength(0.508, 0.75, 0.05, 2.07), 2)
    42.76
    """
    # the rigid bogie's semi-wheelbase b = 0.01 m, the least plausible, at d = b √(3/2)
    d = _checks.plausible("axle_spacing", axle_spacing, "vehicle_length", low=_LEAST_AXLE_SPACING)
    # Three axles at −d, 0, +d steer as two at ±b with b² = Σx_i²/n = 2d²/3 (the derivation above):
    # the rigid bogie's formula, written once in raildyn.wheelset, at that b.
    return rigid_bogie_wavelength(rolling_radius, half_gauge, conicity, np.sqrt(2.0 / 3.0) * d)


_LEAST_AXLE_SPACING = 0.01 * np.sqrt(1.5)  # m


@dataclass(frozen=True)
class ThreeAxleTruck(LinearModelBase):
    """A three-axle locomotive truck: frame, three motored wheelsets, primary and secondary suspension.

    The primary suspension of the end axles is the one in the
    :class:`~raildyn.wheelset.Wheelset` (lateral and yaw stiffness and damping, per
    axle); the middle axle has the same yaw restraint and, within its lateral play,
    only ``middle_lateral_stiffness`` laterally (see the module docstring).

    Attributes
    ----------
    wheelset : Wheelset
        Its ``mass`` is the wheelset's own, without the motor.
    frame_mass, frame_yaw_inertia : float
        The frame alone, kg in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass") and
        kg·m² in [1, 5e8] ("inertia") (representative: 2.0 t, the vertical model's 6.5 t truck
        less the frame's share of three motors; m L²/12 for 4.5 m).
    motor_mass : float
        One traction motor, kg, 0 or in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass")
        (representative: 3 t).
    motor_axle_share : float
        Fraction of each motor's mass that moves with its axle, in [0, 1]; the rest moves with
        the frame (nose suspension: a half).
    axle_spacing : float
        d, between neighbouring axles, m, in [0.01, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "vehicle_length") (2.07 m, as the vertical model).
    middle_lateral_stiffness, middle_lateral_damping : float
        The middle axle's lateral restraint within its play, N/m and N·s/m, ≥ 0
        (representative: soft centring springs, 0.3 MN/m; the end axles' damping).
    middle_lateral_play : float
        The middle axle's free lateral clearance either side, m, ≥ 0 (representative: 19 mm);
        used by the nonlinear model
        (:meth:`~raildyn.vehicles.locomotive_lateral.ThreeAxleTruck.play_element`), not by the linear one.
    secondary_lateral_stiffness, secondary_lateral_damping : float
        Per truck, N/m and N·s/m, ≥ 0 (flexicoil springs and lateral dampers: 1.0 MN/m and
        40 kN·s/m, representative).
    secondary_yaw_stiffness, secondary_yaw_damping : float
        Per truck, N·m/rad and N·m·s/rad, ≥ 0 (the flexicoil springs' longitudinal shear at
        ±1.0 m, 2 MN·m/rad; no yaw dampers, representative).
    """

    wheelset: Wheelset = field(default_factory=_locomotive_wheelset)
    frame_mass: float = _FRAME_MASS
    frame_yaw_inertia: float = _FRAME_YAW_INERTIA
    motor_mass: float = _MOTOR_MASS
    motor_axle_share: float = _MOTOR_AXLE_SHARE
    axle_spacing: float = _AXLE_SPACING
    middle_lateral_stiffness: float = _MIDDLE_LATERAL
    middle_lateral_damping: float = _PRIMARY_LATERAL_DAMPING
    middle_lateral_play: float = _MIDDLE_PLAY
    secondary_lateral_stiffness: float = _SECONDARY_LATERAL
    secondary_lateral_damping: float = _SECONDARY_LATERAL_DAMPING
    secondary_yaw_stiffness: float = _SECONDARY_YAW
    secondary_yaw_damping: float = _SECONDARY_YAW_DAMPING

    def __post_init__(self):
        _checks.instance("wheelset", self.wheelset, Wheelset)
        for name in ("frame_mass", "frame_yaw_inertia", "axle_spacing"):
            positive(name, getattr(self, name))
        _checks.plausible("frame_mass", self.frame_mass, "mass")
        _checks.plausible("frame_yaw_inertia", self.frame_yaw_inertia, "inertia")
        _checks.plausible("axle_spacing", self.axle_spacing, "vehicle_length")
        if self.motor_mass != 0:
            _checks.plausible("motor_mass", self.motor_mass, "mass")
        _checks.scalar("motor_axle_share", self.motor_axle_share, low=0.0, high=1.0)
        for name in (
            "motor_mass",
            "middle_lateral_stiffness",
            "middle_lateral_damping",
            "middle_lateral_play",
            "secondary_lateral_stiffness",
            "secondary_lateral_damping",
            "secondary_yaw_stiffness",
            "secondary_yaw_damping",
        ):
            nonnegative(name, getattr(self, name))

    def replace(self, **changes) -> ThreeAxleTruck:
        """A copy with truck or wheelset fields changed (``conicity=...`` reaches the wheelset).

        Parameters
        ----------
        **changes
            Fields of the truck or of its :class:`~raildyn.wheelset.Wheelset`.

        Returns
        -------
        ThreeAxleTruck
        """
        return _replace_through(self, changes, "wheelset")

    @property
    def axle_offsets(self) -> np.ndarray:
        """Positions of the leading, middle and trailing axles ahead of the truck centre, m: d, 0, −d."""
        return np.array([self.axle_spacing, 0.0, -self.axle_spacing])

    @property
    def mass(self) -> float:
        """The whole truck: frame, three wheelsets and three motors, kg."""
        return self.frame_mass + 3 * (self.wheelset.mass + self.motor_mass)

    def without_play(self) -> ThreeAxleTruck:
        """The same truck with its middle axle held laterally as the end axles (no play).

        Returns
        -------
        ThreeAxleTruck
        """
        ws = self.wheelset
        return replace(
            self,
            middle_lateral_stiffness=ws.lateral_stiffness,
            middle_lateral_damping=ws.lateral_damping,
            middle_lateral_play=0.0,
        )

    def play_element(self, tag: str = "") -> SuspensionElement | None:
        """The middle axle's lateral play as a nonlinear suspension element of truck ``tag``.

        On the deflection u = y_w − y_f of the middle wheelset in the frame (it sits under
        the frame's centre, so the frame's yaw does not move it), the force
        ``F = k_c u + k_y (|u| − g)₊ sgn u`` (:func:`raildyn.suspension.clearance_force`):
        the soft centring k_c within the play g, and beyond it a stop as stiff as the end
        axles' primary spring k_y. It replaces the spring k_c of the linear model, its
        slope within the play; the damper stays.

        Parameters
        ----------
        tag : {"", "1", "2"}
            Suffix of the truck's labels: "" for the truck alone, "1" or "2" on a locomotive.

        Returns
        -------
        SuspensionElement or None
            None when the play is 0 (the linear spring holds the axle).
        """
        _checks.choice("tag", tag, ("", "1", "2"))
        if self.middle_lateral_play == 0.0:
            return None
        gap, stop, centring = (
            self.middle_lateral_play,
            self.wheelset.lateral_stiffness,
            self.middle_lateral_stiffness,
        )
        return SuspensionElement(
            {f"wheelset{tag}2 y": 1.0, f"frame{tag} y": -1.0},
            lambda u, _: clearance_force(u, gap, stop, centring),
            stiffness=centring,
        )

    def nonlinear(self, contact: WheelRailContact | None = None) -> NonlinearLateral:
        """The truck with nonlinear wheel–rail contact and its middle axle's play (its speed is given to
        each run).

        Parameters
        ----------
        contact : WheelRailContact, optional
            The nonlinear contact; default :class:`~raildyn.wheelset.WheelRailContact`.

        Returns
        -------
        NonlinearLateral
        """
        play = self.play_element()
        return _nonlinear(self, contact, () if play is None else (play,))

    def assemble(
        self, asm: Assembler, tag: str, body: dict[str, float], body_yaw: str | None, first_input: int
    ) -> None:
        """Add the frame, wheelsets and motors of truck ``tag`` to an assembly.

        Parameters
        ----------
        asm : Assembler
            Holding the truck's labels for ``tag`` and two inputs (alignment, cross-level)
            per wheelset.
        tag : str
            Suffix of the truck's labels ("frame{tag} y", "wheelset{tag}1 y", ... "wheelset{tag}3 ψ").
        body : dict of str to float
            The lateral displacement of the secondary seat as finite coefficients of the body
            coordinates (labels of ``asm``); empty for a body that does not move.
        body_yaw : str or None
            The body's yaw coordinate (a label of ``asm``), if the body moves.
        first_input : int
            Index of the leading wheelset's alignment input, in [0, ``asm.GK.shape[1] // 2`` − 3];
            the middle and trailing ones' follow, and their cross-level inputs follow the
            alignment inputs of every wheelset (``asm.GK.shape[1] // 2`` further on).
        """
        half = _check_truck_assembly(asm, tag, body, body_yaw, first_input, axles=3)
        ws = self.wheelset
        on_axle = self.motor_axle_share * self.motor_mass
        on_frame = self.motor_mass - on_axle
        fy, fpsi = f"frame{tag} y", f"frame{tag} ψ"
        offsets = self.axle_offsets
        asm.mass(fy, self.frame_mass + 3 * on_frame)
        asm.mass(fpsi, self.frame_yaw_inertia + on_frame * float(np.sum(offsets**2)))
        for k, x in enumerate(offsets, start=1):
            wy, wpsi = f"wheelset{tag}{k} y", f"wheelset{tag}{k} ψ"
            j = first_input + k - 1
            add_wheelset(asm, wy, wpsi, ws, alignment=j, cross_level=half + j)
            if on_axle > 0.0:
                asm.mass(wy, on_axle)
            # Primary: lateral relative displacement at the axle (the middle axle within its play), yaw.
            ky, cy = (
                (self.middle_lateral_stiffness, self.middle_lateral_damping)
                if k == 2
                else (ws.lateral_stiffness, ws.lateral_damping)
            )
            asm.element({wy: 1.0, fy: -1.0, fpsi: -x}, ky, cy)
            asm.element({wpsi: 1.0, fpsi: -1.0}, ws.yaw_stiffness, ws.yaw_damping)
        lateral = {fy: 1.0, **{k: -v for k, v in body.items()}}
        asm.element(lateral, self.secondary_lateral_stiffness, self.secondary_lateral_damping)
        yaw = {fpsi: 1.0} | ({body_yaw: -1.0} if body_yaw else {})
        asm.element(yaw, self.secondary_yaw_stiffness, self.secondary_yaw_damping)

    def linear_system(self) -> LinearSystem:
        """The truck under a body that runs straight (the body does not move): 8 coordinates.

        Six track inputs: the alignment at the leading, middle and trailing wheelsets,
        then the cross-level there (m).

        Returns
        -------
        LinearSystem
        """
        labels = ["frame y", "frame ψ"] + [f"wheelset{k} {q}" for k in (1, 2, 3) for q in "yψ"]
        asm = Assembler(labels, n_inputs=6)
        self.assemble(asm, "", {}, None, 0)
        d = self.axle_spacing
        kinds = ("alignment",) * 3 + ("cross_level",) * 3
        return asm.system(input_positions=np.tile([0.0, d, 2 * d], 2), input_kinds=kinds)


@dataclass(frozen=True)
class LateralLocomotive(LinearModelBase):
    """A six-axle locomotive: body (lateral, yaw, roll) on two three-axle trucks.

    Attributes
    ----------
    truck : ThreeAxleTruck
    body_mass : float
        kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass") (133 t, as the vertical
        :class:`~raildyn.vehicles.locomotive.VerticalLocomotive`).
    body_yaw_inertia : float
        kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia") (m L²/12 for a 20 m body).
    body_roll_inertia : float
        kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia") (m (w² + h²)/12, 3.12 m
        wide, mass over 2.5 m of height).
    semi_truck_spacing : float
        Half the distance between truck centres, m, in [0.01, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length"), greater than the truck's axle
        spacing (each truck's axles on its own side of the body's centre) (13.26 m between centres).
    body_height : float
        Height of the body's centre of gravity above the secondary lateral springs, m, in [0, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length")
        (0.9 m).
    roll_stiffness, roll_damping : float
        Per truck, N·m/rad and N·m·s/rad, ≥ 0: the vertical model's secondary springs and dampers
        split between the two sides at ±1.0 m. The two trucks' 2 k_φ must exceed m g h, or the body
        topples.
    """

    truck: ThreeAxleTruck = field(default_factory=ThreeAxleTruck)
    body_mass: float = _BODY_MASS
    body_yaw_inertia: float = _BODY_YAW_INERTIA
    body_roll_inertia: float = _BODY_ROLL_INERTIA
    semi_truck_spacing: float = _SEMI_TRUCK_SPACING
    body_height: float = _BODY_HEIGHT
    roll_stiffness: float = _ROLL_STIFFNESS
    roll_damping: float = _ROLL_DAMPING

    def __post_init__(self):
        _checks.instance("truck", self.truck, ThreeAxleTruck)
        _check_body_on_two_trucks(self, "semi_truck_spacing", "axle_spacing", self.truck.axle_spacing)

    def replace(self, **changes) -> LateralLocomotive:
        """A copy with locomotive, truck or wheelset fields changed.

        Parameters
        ----------
        **changes
            Fields of the locomotive, of its
            :class:`~raildyn.vehicles.locomotive_lateral.ThreeAxleTruck` or of their
            :class:`~raildyn.wheelset.Wheelset`.

        Returns
        -------
        LateralLocomotive
        """
        return _replace_through(self, changes, "truck")

    def without_play(self) -> LateralLocomotive:
        """The same locomotive with the middle axles held laterally as the end axles.

        Returns
        -------
        LateralLocomotive
        """
        return replace(self, truck=self.truck.without_play())

    def nonlinear(self, contact: WheelRailContact | None = None) -> NonlinearLateral:
        """The locomotive with nonlinear wheel–rail contact and its middle axles' play (its speed is given to
        each run).

        Parameters
        ----------
        contact : WheelRailContact, optional
            The nonlinear contact; default :class:`~raildyn.wheelset.WheelRailContact`.

        Returns
        -------
        NonlinearLateral
        """
        plays = [self.truck.play_element(tag) for tag in ("1", "2")]
        return _nonlinear(self, contact, tuple(p for p in plays if p is not None))

    @property
    def wheelset(self) -> Wheelset:
        """The wheelset of the locomotive's trucks."""
        return self.truck.wheelset

    @property
    def mass(self) -> float:
        """The whole locomotive, kg."""
        return self.body_mass + 2 * self.truck.mass

    @property
    def axle_positions(self) -> np.ndarray:
        """Distances of the six wheelsets behind the leading one, m: 0, d, 2d, 2s, 2s + d, 2s + 2d."""
        d, s = self.truck.axle_spacing, self.semi_truck_spacing
        front = np.array([0.0, d, 2 * d])
        return np.concatenate([front, front + 2 * s])

    def linear_system(self) -> LinearSystem:
        """The 19-coordinate locomotive (body y, ψ, φ; each frame y, ψ; each wheelset y, ψ) and its inputs.

        Twelve inputs: the alignment y_a (m) at each of the six wheelsets, then the
        cross-level Δz (m) there, coupled to each wheelset by
        :func:`~raildyn.wheelset.add_wheelset`. The truck frames, kept upright on the
        track, tilt with the mean of their three wheelsets' cross-level, so the
        secondary roll springs act on φ − Δz̄/(2a_r), Δz̄ that mean and 2a_r the rail spacing.

        Returns
        -------
        LinearSystem
        """
        labels = ["body y", "body ψ", "body φ"]
        for tag in ("1", "2"):
            labels += [f"frame{tag} y", f"frame{tag} ψ"]
            labels += [f"wheelset{tag}{k} {q}" for k in (1, 2, 3) for q in "yψ"]
        asm = Assembler(labels, n_inputs=12)
        asm.mass("body y", self.body_mass)
        asm.mass("body ψ", self.body_yaw_inertia)
        asm.mass("body φ", self.body_roll_inertia)
        h, s = self.body_height, self.semi_truck_spacing
        tilt = (1.0 / 3.0) / STANDARD_RAIL_SPACING  # frame roll per metre of cross-level at a wheelset
        for first, (tag, x) in zip((0, 3), (("1", s), ("2", -s)), strict=True):
            # The secondary seat is h below the body's centre: it moves y + xψ + hφ.
            self.truck.assemble(asm, tag, {"body y": 1.0, "body ψ": x, "body φ": h}, "body ψ", first)
            frame_tilt = {6 + first + k: tilt for k in range(3)}
            asm.element({"body φ": 1.0}, self.roll_stiffness, self.roll_damping, inputs=frame_tilt)
        # The body's weight acting above the roll centre (the secondary seat) lowers its roll stiffness.
        asm.block(["body φ"], K=[[-self.body_mass * GRAVITY * h]])
        kinds = ("alignment",) * 6 + ("cross_level",) * 6
        return asm.system(input_positions=np.tile(self.axle_positions, 2), input_kinds=kinds)


LATERAL_LOCOMOTIVE = LateralLocomotive()
"""The representative six-axle locomotive (EMD SD40-2) on new 1:20 wheels, middle axles with lateral play.

Its linear critical speed is 101.5 m/s (4.6 Hz, truck hunting), 45.4 m/s on worn treads of
conicity 0.2; its nonlinear critical speed (flange contact at 9.1 mm) is 96.1 m/s."""
