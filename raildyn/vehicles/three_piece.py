"""The three-piece freight truck and the freight car on two of them, in the lateral plane (chapters 6 and 7).

A three-piece truck is two cast side frames and a bolster. Each wheelset's
bearing adapters sit in the pedestal jaws of the two side frames; the bolster
rests on a spring nest in each side frame, held there by friction wedges;
the car body rests on the bolster's centre plate. Seen from above, the side
frames and the transverse members (the two axles and the bolster) form a
parallelogram that can shear: the truck *warps*, resisted only by the wedges'
squaring stiffness and friction. Its coordinates here (per truck, m and rad):

* ``frame y`` — the lateral displacement of the side frames (they move together:
  the bolster ties them laterally);
* ``frame ψ`` — the yaw of the side frames, which stay parallel to each other;
* ``bolster ψ`` — the yaw of the transverse members: the bolster, and the line
  the adapters hold the axles square to. Warp is ``bolster ψ − frame ψ``. In this
  motion the side frames slide longitudinally, ±d ψ at ±d from the centre, so
  their mass times d² adds to the bolster's yaw inertia;
* ``wheelset1 y``, ``wheelset1 ψ``, ``wheelset2 y``, ``wheelset2 ψ`` — the leading and
  trailing wheelsets on the rails (:func:`raildyn.wheelset.add_wheelset`).

The elements, each an :meth:`raildyn.linear_model.Assembler.element`:

* the side frames hang on the bearing adapters and swing laterally as pendulums:
  wheelset k to side frames, on ``wheelset y − frame y − x_k frame ψ`` (x_k = ±b),
  the :class:`~raildyn.wheelset.Wheelset`'s ``lateral_stiffness``;
* the adapters hold each wheelset square in the pedestals: on ``wheelset ψ − bolster ψ``,
  the wheelset's ``yaw_stiffness``;
* warp: the wedges' squaring stiffness and friction, on ``bolster ψ − frame ψ``;
* the spring nests in lateral shear and the wedges' lateral friction, between the
  bolster, which moves laterally with the body's centre plate, and the side frames;
* the centre plate: friction only, on ``bolster ψ − body ψ``.

Friction enters the linear model (:meth:`ThreePieceTruck.assemble`, eigenvalues and
critical speeds) as the equivalent viscous damper that dissipates the same energy
per cycle of a reference harmonic motion, c = 4F/(π ω X) (energy 4FX of
:func:`raildyn.vehicles.wedges.wedge_energy_per_cycle`), and the nonlinear
model (:meth:`LateralFreightCar.nonlinear`) as the friction itself, through
:class:`raildyn.wheelset.SuspensionElement`: the smooth law F tanh(v/v_ε) with
v_ε = (π/4) ω X, whose slope F/v_ε at v = 0 is that equivalent damper, so that the
nonlinear model linearises to the linear one and departs from it only as the friction
slides.

Left out: the bolster's own lateral motion on the body's centre plate (it moves with
the body: its mass is in the body's), the side frames' roll and the wedges'
vertical motion, the side bearings, the clearances of the adapters in the pedestal
jaws and of the bolster gibs, and the body's bending.

* :class:`ThreePieceTruck` — one truck under a body that runs straight;
* :class:`LateralFreightCar` — the car body (lateral, yaw, roll) on two trucks, 17
  coordinates, driven by the alignment and cross-level at its four wheelsets like
  :class:`~raildyn.vehicles.lateral.LateralCar`;
* :data:`EMPTY_FREIGHT_CAR`, :data:`LOADED_FREIGHT_CAR` (:func:`freight_car`): a
  100-ton hopper on three-piece trucks, empty and loaded.

Their parameters, each with its source, are in ``raildyn.vehicles._three_piece_parameters``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from raildyn import _checks
from raildyn._checks import nonnegative, positive
from raildyn.constants import (
    GRAVITY,
    STANDARD_RAIL_SPACING,
)
from raildyn.linear_model import Assembler, LinearModelBase, LinearSystem
from raildyn.vehicles._shared import (
    _check_body_on_two_trucks,
    _check_truck_assembly,
    _nonlinear,
    _replace_through,
)
from raildyn.vehicles._three_piece_parameters import (
    _BODY_HEIGHT,
    _BODY_LENGTH,
    _BODY_WIDTH,
    _BOLSTER_YAW_INERTIA,
    _EMPTY_HEIGHT,
    _GROSS_MASS,
    _LIGHT_MASS,
    _LOADED_HEIGHT,
    _NEST_LATERAL,
    _NEST_STIFFNESS,
    _REFERENCE_AMPLITUDE,
    _REFERENCE_ANGLE,
    _REFERENCE_FREQUENCY,
    _SEMI_TRUCK_SPACING,
    _SEMI_WHEELBASE,
    _SIDE_FRAME_MASS,
    _SIDE_FRAME_SPACING,
    _SIDE_FRAME_YAW_INERTIA,
    _WARP_STIFFNESS,
    _WEDGE_FRICTION,
    _WEDGE_OFFSET,
    _body_mass,
    _centre_plate_friction,
    _wedge_normal_force,
    _wheelset,
)
from raildyn.vehicles.wedges import wedge_energy_per_cycle
from raildyn.wheelset import NonlinearLateral, SuspensionElement, WheelRailContact, Wheelset, add_wheelset

__all__ = ["EMPTY_FREIGHT_CAR", "LOADED_FREIGHT_CAR", "LateralFreightCar", "ThreePieceTruck", "freight_car"]


def _equivalent_damping(friction: float, amplitude: float, frequency: float) -> float:
    """The viscous damper (N·s/m, or N·m·s/rad) dissipating the friction's energy per cycle of X sin ωt.

    π c ω X² = 4 F X (:func:`~raildyn.vehicles.wedges.wedge_energy_per_cycle`, ideal law).
    """
    energy = wedge_energy_per_cycle(friction, amplitude, frequency) if friction > 0 else 0.0
    return energy / (np.pi * 2 * np.pi * frequency * amplitude**2)


@dataclass(frozen=True)
class ThreePieceTruck(LinearModelBase):
    """A three-piece freight truck: side frames, bolster, two wheelsets, warp and friction wedges.

    Coordinates and elements are described in :mod:`raildyn.vehicles.three_piece`. The
    wheelset's primary suspension (its ``lateral_stiffness``, ``yaw_stiffness`` and dampings)
    is the side frames' pendulum and the adapters. Friction is linearised at the reference
    motion (``reference_frequency``, ``reference_amplitude``, ``reference_angle``) for the
    linear model, and kept as friction in the nonlinear one (its smooth law's velocity scale
    from the same reference motion). The defaults are the loaded
    car's truck (:func:`freight_car`).

    Attributes
    ----------
    wheelset : Wheelset
    side_frame_mass : float
        Both side frames, kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass")
        (Baruffaldi's Ride Control truck: 2 × 290 kg).
    side_frame_yaw_inertia : float
        Both side frames about their own centres, kg·m², in [1, 5e8]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia") (2 × 91 kg·m²).
    bolster_yaw_inertia : float
        The bolster, kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia") (99 kg·m²);
        the side frames' 2 m d² is added to it.
    semi_wheelbase : float
        b, m, in [0.01, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length") (0.865 m).
    side_frame_spacing : float
        d, half the distance between the side frames (and their nests), m, in [0.01, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length") (1.0 m).
    warp_stiffness : float
        Between bolster and side frames, N·m/rad, ≥ 0 (representative: 2 MN·m/rad).
    nest_shear_stiffness : float
        The two nests in lateral shear, N/m, ≥ 0 (half their vertical rate).
    lateral_friction : float
        The wedges' friction against lateral sliding of the bolster in the side frames, N, ≥ 0:
        four wedges, each pressed on its column with the mean force of
        :func:`~raildyn.vehicles.wedges.wedge_friction_force`, times μ.
    warp_friction : float
        The wedges' friction moment against warp, N·m, ≥ 0: the same four friction forces at
        their offset of 0.221 m ahead of and behind the bolster's centre line.
    centre_plate_friction : float
        Friction moment of the centre plate against yaw of the bolster under the body, N·m, ≥ 0:
        μ W (2/3) R with W the body's weight on the truck.
    reference_frequency : float
        f of the reference motion, Hz, > 0 (2 Hz).
    reference_amplitude : float
        X of the reference lateral sliding, m, > 0 (0.5 mm).
    reference_angle : float
        Θ of the reference warp and centre-plate rotation, rad, > 0 (0.5 mrad).
    """

    wheelset: Wheelset = field(default_factory=lambda: _wheelset(_GROSS_MASS))
    side_frame_mass: float = 2 * _SIDE_FRAME_MASS
    side_frame_yaw_inertia: float = 2 * _SIDE_FRAME_YAW_INERTIA
    bolster_yaw_inertia: float = _BOLSTER_YAW_INERTIA
    semi_wheelbase: float = _SEMI_WHEELBASE
    side_frame_spacing: float = _SIDE_FRAME_SPACING
    warp_stiffness: float = _WARP_STIFFNESS
    nest_shear_stiffness: float = 2 * _NEST_LATERAL
    lateral_friction: float = 4 * _WEDGE_FRICTION * _wedge_normal_force()
    warp_friction: float = 4 * _WEDGE_FRICTION * _wedge_normal_force() * _WEDGE_OFFSET
    centre_plate_friction: float = _centre_plate_friction(_GROSS_MASS)
    reference_frequency: float = _REFERENCE_FREQUENCY
    reference_amplitude: float = _REFERENCE_AMPLITUDE
    reference_angle: float = _REFERENCE_ANGLE

    def __post_init__(self):
        _checks.instance("wheelset", self.wheelset, Wheelset)
        for name in (
            "side_frame_mass",
            "side_frame_yaw_inertia",
            "bolster_yaw_inertia",
            "semi_wheelbase",
            "side_frame_spacing",
            "reference_frequency",
            "reference_amplitude",
            "reference_angle",
        ):
            positive(name, getattr(self, name))
        _checks.plausible("side_frame_mass", self.side_frame_mass, "mass")
        _checks.plausible_fields(self, "inertia", ("side_frame_yaw_inertia", "bolster_yaw_inertia"))
        _checks.plausible_fields(self, "vehicle_length", ("semi_wheelbase", "side_frame_spacing"))
        for name in (
            "warp_stiffness",
            "nest_shear_stiffness",
            "lateral_friction",
            "warp_friction",
            "centre_plate_friction",
        ):
            nonnegative(name, getattr(self, name))

    def replace(self, **changes) -> ThreePieceTruck:
        """A copy with truck or wheelset fields changed (``conicity=...`` reaches the wheelset).

        Parameters
        ----------
        **changes
            Fields of the truck or of its :class:`~raildyn.wheelset.Wheelset`.

        Returns
        -------
        ThreePieceTruck
        """
        return _replace_through(self, changes, "wheelset")

    def _frictions(self, tag: str, body: dict, body_yaw: str | None) -> list:
        """(deflection, friction, equivalent damper c, v_ε) of the lateral, warp and centre-plate friction.

        v_ε = F/c, so that the smooth law F tanh(v/v_ε) starts with the slope of the equivalent
        damper: (π/4) ω X, and (π/4) ω Θ for the angles.
        """
        f, X, T = self.reference_frequency, self.reference_amplitude, self.reference_angle
        w = 2 * np.pi * f
        fy, fpsi, bpsi = f"frame{tag} y", f"frame{tag} ψ", f"bolster{tag} ψ"
        lateral = {**body}
        lateral[fy] = lateral.get(fy, 0.0) - 1.0  # the bolster's lateral displacement less the side frames'
        plate = {bpsi: 1.0} | ({body_yaw: -1.0} if body_yaw else {})
        c = _equivalent_damping
        return [
            (lateral, self.lateral_friction, c(self.lateral_friction, X, f), np.pi / 4 * w * X),
            ({bpsi: 1.0, fpsi: -1.0}, self.warp_friction, c(self.warp_friction, T, f), np.pi / 4 * w * T),
            (plate, self.centre_plate_friction, c(self.centre_plate_friction, T, f), np.pi / 4 * w * T),
        ]

    def _friction_elements(self, tag: str, body: dict, body_yaw: str | None) -> tuple:
        """The truck's friction as nonlinear elements, each replacing its equivalent damper.

        Parameters
        ----------
        tag : str
            Suffix of the truck's labels, as for :meth:`assemble`.
        body : dict of str to float
            The lateral displacement of the centre plate as coefficients of the body
            coordinates, as for :meth:`assemble`.
        body_yaw : str or None
            The body's yaw coordinate, as for :meth:`assemble`.

        Returns
        -------
        tuple of SuspensionElement
            Lateral wedge friction, warp friction, centre-plate friction (those with a
            friction force > 0).
        """
        _checks.instance("tag", tag, str, "str")
        _checks.instance("body", body, dict, "dict of body label to coefficient")
        if body_yaw is not None:
            _checks.instance("body_yaw", body_yaw, str, "str or None")
        out = []
        for deflection, friction, damping, scale in self._frictions(tag, body, body_yaw):
            if friction > 0:
                law = _friction_law(friction, scale)
                out.append(SuspensionElement(deflection, law, stiffness=0.0, damping=damping))
        return tuple(out)

    def assemble(
        self, asm: Assembler, tag: str, body: dict[str, float], body_yaw: str | None, first_input: int
    ) -> None:
        """Add truck ``tag`` (side frames, bolster yaw, two wheelsets) to an assembly.

        Parameters
        ----------
        asm : Assembler
            Holding the truck's labels for ``tag`` and two inputs (alignment, cross-level)
            per wheelset.
        tag : str
            Suffix of the truck's labels ("frame{tag} y", "frame{tag} ψ", "bolster{tag} ψ",
            "wheelset{tag}1 y", ...).
        body : dict of str to float
            The lateral displacement of the centre plate (and bolster) at the nests' height as
            finite coefficients of the body coordinates (labels of ``asm``); empty for a body
            that does not move.
        body_yaw : str or None
            The body's yaw coordinate (a label of ``asm``), if the body moves.
        first_input : int
            Index of the leading wheelset's alignment input, in [0, ``asm.GK.shape[1] // 2`` − 2];
            the trailing one's is next, and their cross-level inputs follow the alignment
            inputs of every wheelset (``asm.GK.shape[1] // 2`` further on).
        """
        own = [f"frame{tag} y", f"frame{tag} ψ", f"bolster{tag} ψ"]
        half = _check_truck_assembly(asm, tag, body, body_yaw, first_input, parts=("frame", "bolster"))
        ws, b, d = self.wheelset, self.semi_wheelbase, self.side_frame_spacing
        fy, fpsi, bpsi = own[:3]
        asm.mass(fy, self.side_frame_mass)
        asm.mass(fpsi, self.side_frame_yaw_inertia)
        asm.mass(bpsi, self.bolster_yaw_inertia + self.side_frame_mass * d * d)
        for k, x in ((1, b), (2, -b)):
            wy, wpsi = f"wheelset{tag}{k} y", f"wheelset{tag}{k} ψ"
            j = first_input + k - 1
            add_wheelset(asm, wy, wpsi, ws, alignment=j, cross_level=half + j)
            # The side frames swing on the adapters (pendulum); the adapters keep the axle square.
            asm.element({wy: 1.0, fy: -1.0, fpsi: -x}, ws.lateral_stiffness, ws.lateral_damping)
            asm.element({wpsi: 1.0, bpsi: -1.0}, ws.yaw_stiffness, ws.yaw_damping)
        stiffness = (self.nest_shear_stiffness, self.warp_stiffness, 0.0)
        for (deflection, _, damping, _), k in zip(
            self._frictions(tag, body, body_yaw), stiffness, strict=True
        ):
            asm.element(deflection, k, damping)

    def linear_system(self) -> LinearSystem:
        """The truck under a car body that runs straight (the body does not move): 7 coordinates.

        Four track inputs: the alignment at the leading and trailing wheelsets, then
        the cross-level there (m).

        Returns
        -------
        LinearSystem
        """
        labels = ["frame y", "frame ψ", "bolster ψ"] + [f"wheelset{k} {q}" for k in (1, 2) for q in "yψ"]
        asm = Assembler(labels, n_inputs=4)
        self.assemble(asm, "", {}, None, 0)
        kinds = ("alignment",) * 2 + ("cross_level",) * 2
        return asm.system(input_positions=np.tile([0.0, 2 * self.semi_wheelbase], 2), input_kinds=kinds)

    def nonlinear(self, contact: WheelRailContact | None = None) -> NonlinearLateral:
        """The truck with nonlinear wheel–rail contact and its friction as friction (its speed is given to
        each run).

        Parameters
        ----------
        contact : WheelRailContact, optional
            The nonlinear contact; default :class:`~raildyn.wheelset.WheelRailContact`.

        Returns
        -------
        NonlinearLateral
        """
        return _nonlinear(self, contact, self._friction_elements("", {}, None))


def _friction_law(friction: float, velocity_scale: float):
    """F tanh(v/v_ε), the smooth law of :func:`raildyn.suspension.coulomb_friction`, as a law f(d, ḋ).

    F and v_ε were checked with the truck; the law skips coulomb_friction's checks of its
    arguments, which would cost more than the rest of a right-hand side (tests hold the two equal).
    """

    def law(d, v):
        return friction * np.tanh(v / velocity_scale)

    return law


def _roll_damping() -> float:
    """The wedges' vertical friction as a roll damper per truck, N·m·s/rad.

    Two wedges per nest, each with its mean column friction, linearised at the reference
    motion, at ±d.
    """
    vertical = 2 * _WEDGE_FRICTION * _wedge_normal_force()
    c = _equivalent_damping(vertical, _REFERENCE_AMPLITUDE, _REFERENCE_FREQUENCY)
    return 2 * c * _SIDE_FRAME_SPACING**2


_ROLL_DAMPING = _roll_damping()


@dataclass(frozen=True)
class LateralFreightCar(LinearModelBase):
    """A freight car body (lateral, yaw, roll) on two three-piece trucks: 17 coordinates.

    The body rolls on the spring nests, ``body_height`` below its centre of gravity, and
    the nests' lateral shear acts there too. Eight track inputs, as for
    :class:`~raildyn.vehicles.lateral.LateralCar`: the alignment at each of the four wheelsets,
    then the cross-level there; the side frames ride on the wheelsets, so the nests tilt
    with the mean cross-level of their truck. The defaults are the loaded car of
    :func:`freight_car`.

    Attributes
    ----------
    truck : ThreePieceTruck
    body_mass : float
        Body (with lading and the bolsters), kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "mass").
    body_yaw_inertia, body_roll_inertia : float
        About the centre of gravity, kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "inertia").
    semi_truck_spacing : float
        Half the distance between truck centres, m, in [0.01, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length"), greater than the truck's
        semi-wheelbase.
    body_height : float
        Centre of gravity above the nests, m, in [0, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "vehicle_length").
    roll_stiffness : float
        Per truck, N·m/rad: the two nests' vertical rate at ±d, 2 k d². The two trucks'
        2 k_φ must exceed m g h (else the body topples).
    roll_damping : float
        Per truck, N·m·s/rad, ≥ 0: the wedges' vertical friction, linearised at the truck's
        reference motion.
    """

    truck: ThreePieceTruck = field(default_factory=ThreePieceTruck)
    body_mass: float = _body_mass(_GROSS_MASS)
    body_yaw_inertia: float = _body_mass(_GROSS_MASS) * (_BODY_LENGTH**2 + _BODY_WIDTH**2) / 12
    body_roll_inertia: float = _body_mass(_GROSS_MASS) * (_BODY_WIDTH**2 + _BODY_HEIGHT**2) / 12
    semi_truck_spacing: float = _SEMI_TRUCK_SPACING
    body_height: float = _LOADED_HEIGHT
    roll_stiffness: float = 2 * _NEST_STIFFNESS * _SIDE_FRAME_SPACING**2
    roll_damping: float = _ROLL_DAMPING

    def __post_init__(self):
        _checks.instance("truck", self.truck, ThreePieceTruck)
        _check_body_on_two_trucks(self, "semi_truck_spacing", "semi_wheelbase", self.truck.semi_wheelbase)

    def replace(self, **changes) -> LateralFreightCar:
        """A copy with car, truck or wheelset fields changed.

        Parameters
        ----------
        **changes
            Fields of the car, of its :class:`ThreePieceTruck` or of their
            :class:`~raildyn.wheelset.Wheelset`.

        Returns
        -------
        LateralFreightCar
        """
        return _replace_through(self, changes, "truck")

    @property
    def wheelset(self) -> Wheelset:
        """The wheelset of the car's trucks."""
        return self.truck.wheelset

    @property
    def axle_positions(self) -> np.ndarray:
        """Distances of the four wheelsets behind the leading one, m: 0, 2b, 2s, 2s + 2b."""
        b, s = self.truck.semi_wheelbase, self.semi_truck_spacing
        return np.array([0.0, 2 * b, 2 * s, 2 * s + 2 * b])

    def _trucks(self):
        """(tag, body coefficients of the centre plate's lateral displacement, first input) per truck."""
        h, s = self.body_height, self.semi_truck_spacing
        return [
            (tag, {"body y": 1.0, "body ψ": x, "body φ": h}, first)
            for tag, x, first in (("1", s, 0), ("2", -s, 2))
        ]

    def linear_system(self) -> LinearSystem:
        """The 17-coordinate car (body y, ψ, φ; per truck frame y, ψ, bolster ψ, wheelsets y, ψ).

        Returns
        -------
        LinearSystem
        """
        labels = ["body y", "body ψ", "body φ"]
        for tag in ("1", "2"):
            labels += [f"frame{tag} y", f"frame{tag} ψ", f"bolster{tag} ψ"]
            labels += [f"wheelset{tag}{k} {q}" for k in (1, 2) for q in "yψ"]
        asm = Assembler(labels, n_inputs=8)
        asm.mass("body y", self.body_mass)
        asm.mass("body ψ", self.body_yaw_inertia)
        asm.mass("body φ", self.body_roll_inertia)
        tilt = 0.5 / STANDARD_RAIL_SPACING  # nest roll per metre of cross-level at each wheelset
        for tag, body, first in self._trucks():
            self.truck.assemble(asm, tag, body, "body ψ", first)
            inputs = {4 + first: tilt, 5 + first: tilt}
            asm.element({"body φ": 1.0}, self.roll_stiffness, self.roll_damping, inputs=inputs)
        # The body's weight acting above the roll centre (the nests) lowers its roll stiffness.
        asm.block(["body φ"], K=[[-self.body_mass * GRAVITY * self.body_height]])
        kinds = ("alignment",) * 4 + ("cross_level",) * 4
        return asm.system(input_positions=np.tile(self.axle_positions, 2), input_kinds=kinds)

    def nonlinear(self, contact: WheelRailContact | None = None) -> NonlinearLateral:
        """The car with nonlinear wheel–rail contact and the trucks' friction as friction (its speed is
        given to each run).

        The lateral wedges, the warp wedges and the centre plates become nonlinear elements
        (:class:`~raildyn.wheelset.SuspensionElement`) with the smooth Coulomb law
        F tanh(v/v_ε); their equivalent dampers leave the model.

        Parameters
        ----------
        contact : WheelRailContact, optional
            The nonlinear contact; default :class:`~raildyn.wheelset.WheelRailContact`.

        Returns
        -------
        NonlinearLateral
        """
        elements = sum(
            (self.truck._friction_elements(tag, body, "body ψ") for tag, body, _ in self._trucks()), ()
        )
        return _nonlinear(self, contact, elements)


def freight_car(loaded: bool = True) -> LateralFreightCar:
    """A 100-ton hopper car on three-piece trucks, empty or loaded.

    Each value is cited beside its constant in :mod:`raildyn.vehicles.three_piece`.

    * Weights: loaded, the AAR gross rail load of 286 000 lb (129.7 t); empty, the
      63 000 lb (28.6 t) light weight of ``raildyn.train.vehicles``. Each truck's wheelsets,
      side frames and wedges (4.63 t) stay with the truck; the rest, bolsters included,
      moves laterally with the body: 120.5 t loaded, 19.3 t empty.
    * Body: centre of gravity 1.5 m above the nests loaded (as for
      :class:`~raildyn.vehicles.freight.VerticalFreightCar`), 0.9 m empty (representative); yaw and
      roll inertias of a uniform body 15 m long, 3.2 m wide and 3.5 m tall (as for
      ``VerticalFreightCar``), empty scaled by its mass (the same radii of gyration: representative).
    * Trucks: side frames, bolster and wedges of Baruffaldi's Ride Control truck model;
      36 in wheels on a 1:20 taper; Kalker's coefficients on Hertz's patch under the wheel
      load on a rail crowned with the wheel's radius, so that they grow with the load as
      W^(2/3). The side frames' pendulum stiffness is the weight on the adapters over the
      pendulum length (0.219 m), so it grows with the load too, as does the centre plate's
      friction; the wedges' friction is the same empty and loaded (constant-damping wedges,
      pressed by their own springs).

    Linear critical speeds (:func:`~raildyn.stability.linear.critical_speed`, measured): empty
    14.5 m/s (52 km/h; 0.77 Hz, the body swaying on the side frames' pendulums), unstable
    from there up, strongly (the trucks hunt) above about 40 m/s; loaded 34.7 m/s
    (125 km/h; 1.27 Hz, trucks and body laterally), a weak instability (growth rate at most
    0.25 1/s) that ends at 67.5 m/s. The load-proportional centre-plate friction and
    pendulum stiffness make the difference (``tests/test_freight_lateral.py``). With its
    friction sliding, the empty car hunts from 12.5 m/s (a cycle of about 9 mm at 0.7 Hz,
    :func:`~raildyn.stability.bifurcation.bifurcation_diagram` with ``method="BDF"``), below
    its linear critical speed; the loaded car's large motions grow without bound from
    about 20 m/s, with nothing (no gib stop) to limit them.

    Parameters
    ----------
    loaded : bool
        The loaded car (True) or the empty one.

    Returns
    -------
    LateralFreightCar
    """
    total, height = (
        (_GROSS_MASS, _LOADED_HEIGHT) if _checks.flag("loaded", loaded) else (_LIGHT_MASS, _EMPTY_HEIGHT)
    )
    body = _body_mass(total)
    truck = ThreePieceTruck(wheelset=_wheelset(total), centre_plate_friction=_centre_plate_friction(total))
    return LateralFreightCar(
        truck=truck,
        body_mass=body,
        body_yaw_inertia=body * (_BODY_LENGTH**2 + _BODY_WIDTH**2) / 12,
        body_roll_inertia=body * (_BODY_WIDTH**2 + _BODY_HEIGHT**2) / 12,
        semi_truck_spacing=_SEMI_TRUCK_SPACING,
        body_height=height,
        roll_stiffness=2 * _NEST_STIFFNESS * _SIDE_FRAME_SPACING**2,
        roll_damping=_ROLL_DAMPING,
    )


LOADED_FREIGHT_CAR = freight_car(loaded=True)
"""The loaded 100-ton hopper on three-piece trucks (:func:`freight_car`)."""

EMPTY_FREIGHT_CAR = freight_car(loaded=False)
"""The empty 100-ton hopper on three-piece trucks (:func:`freight_car`)."""
