"""Vertical passenger car: body bounce and pitch on two bogies (bounce, pitch each) — chapter 6.

Six coordinates: body z, θ; bogie 1 (front) z, θ; bogie 2 z, θ. A point x m ahead
of a body's centre moves z + xθ (θ > 0 raises the front). The wheelsets follow
the track (rigid contact): their masses are unsprung and carry no dynamics here.
Primary springs and dampers join each wheelset to its bogie frame, secondary
ones each bogie to the body. The defaults are the Manchester benchmark vehicle
(Iwnicki 1998), the same car as :class:`raildyn.vehicles.LateralCar`, whose lateral
model reuses them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._checks import nonnegative, positive
from raildyn.constants import GRAVITY
from raildyn.linear_model import Assembler, LinearModelBase, LinearSystem
from raildyn.vehicles.lateral import Bogie, LateralCar

__all__ = ["LABELS", "MANCHESTER_VERTICAL", "BodyFrequencies", "VerticalCar", "body_on_two_trucks"]

_CAR, _BOGIE = LateralCar(), Bogie()

LABELS = ("body z", "body θ", "bogie1 z", "bogie1 θ", "bogie2 z", "bogie2 θ")


@dataclass(frozen=True)
class BodyFrequencies:
    """Undamped natural frequencies of a car body on its springs, Hz.

    Attributes
    ----------
    bounce_hz, pitch_hz : float
        ≥ 0.
    roll_hz : float or None
        ≥ 0, where the model has a roll coordinate.
    """

    bounce_hz: float
    pitch_hz: float
    roll_hz: float | None = None

    def __post_init__(self):
        for name in ("bounce_hz", "pitch_hz") + (() if self.roll_hz is None else ("roll_hz",)):
            object.__setattr__(self, name, _checks.nonnegative(name, getattr(self, name)))


def body_on_two_trucks(
    labels,
    body_mass,
    body_pitch_inertia,
    truck_mass,
    truck_pitch_inertia,
    semi_truck_spacing,
    axle_offsets,
    primary_stiffness,
    primary_damping,
    secondary_stiffness,
    secondary_damping,
    axle_positions,
) -> LinearSystem:
    """A body bouncing and pitching on two trucks, each on its axles: the vertical car and the locomotive.

    Coordinates (``labels``): body z, θ, then each truck's z, θ, front truck first. The
    secondary joins each truck's centre to the body at x = ±l; the primary joins each
    axle, ``axle_offsets`` ahead of its truck's centre, to the rail height under it
    (rigid wheel–rail contact), leading axle first: input j is axle j.

    Parameters
    ----------
    labels : sequence of 6 str
        Distinct, none empty.
    body_mass, truck_mass : float
        kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass").
    body_pitch_inertia, truck_pitch_inertia : float
        kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia").
    semi_truck_spacing : float
        l, m, in [0.01, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length").
    axle_offsets : sequence of float
        Axle positions ahead of the truck's centre, m, leading first: at least two,
        strictly decreasing (else the truck's pitch stands on nothing) and within
        (−l, l) (each truck's axles on its own side of the body's centre).
    primary_stiffness, primary_damping : float
        Per axle, N/m (> 0) and N·s/m (≥ 0).
    secondary_stiffness, secondary_damping : float
        Per truck, N/m (> 0) and N·s/m (≥ 0).
    axle_positions : ndarray
        Distance of each axle behind the leading one, m (the inputs' positions): the
        ones ``semi_truck_spacing`` and ``axle_offsets`` place, to within 1e-9 m per metre.

    Returns
    -------
    LinearSystem
    """
    labels = _checks.strings("labels", labels, 6, unique=True)
    for name, value in (
        ("body_mass", body_mass),
        ("body_pitch_inertia", body_pitch_inertia),
        ("truck_mass", truck_mass),
        ("truck_pitch_inertia", truck_pitch_inertia),
        ("primary_stiffness", primary_stiffness),
        ("secondary_stiffness", secondary_stiffness),
    ):
        _checks.positive(name, value)
    _checks.plausible("body_mass", body_mass, "mass")
    _checks.plausible("truck_mass", truck_mass, "mass")
    _checks.plausible("body_pitch_inertia", body_pitch_inertia, "inertia")
    _checks.plausible("truck_pitch_inertia", truck_pitch_inertia, "inertia")
    primary_damping = _checks.nonnegative("primary_damping", primary_damping)
    secondary_damping = _checks.nonnegative("secondary_damping", secondary_damping)
    s = _checks.plausible("semi_truck_spacing", semi_truck_spacing, "vehicle_length")
    offsets = _checks.array("axle_offsets", axle_offsets, ndim=1)
    if offsets.size < 2 or np.any(np.diff(offsets) >= 0):
        raise ValueError(f"axle_offsets must hold at least two offsets, strictly decreasing, got {offsets}")
    if np.abs(offsets).max() >= s:
        raise ValueError(
            f"axle_offsets must lie within (-s, s), s = semi_truck_spacing = {s!r} m (each truck's axles "
            f"on its own side of the body's centre), got {offsets}"
        )
    front = s + offsets  # axle positions ahead of the body's centre
    want = front[0] - np.concatenate([front, front - 2 * s])
    got = _checks.array("axle_positions", axle_positions, ndim=1)
    if got.shape != want.shape or np.abs(got - want).max() > 1e-9 * max(1.0, want.max()):
        raise ValueError(
            f"axle_positions must be the distances behind the leading axle that semi_truck_spacing and "
            f"axle_offsets place, {want}, got {got}"
        )
    asm = Assembler(labels, 2 * offsets.size)
    body_z, body_pitch = labels[0], labels[1]
    asm.mass(body_z, body_mass)
    asm.mass(body_pitch, body_pitch_inertia)
    j = 0
    for (z, th), x_truck in zip((labels[2:4], labels[4:6]), (s, -s), strict=True):
        asm.mass(z, truck_mass)
        asm.mass(th, truck_pitch_inertia)
        # secondary: the truck centre against the body at x = ±s
        asm.element({z: 1.0, body_z: -1.0, body_pitch: -x_truck}, secondary_stiffness, secondary_damping)
        for x_axle in offsets:
            asm.element({z: 1.0, th: x_axle}, primary_stiffness, primary_damping, inputs={j: 1.0})
            j += 1
    weight = -GRAVITY * np.diag(asm.M) * np.array([1, 0, 1, 0, 1, 0])
    return asm.system(input_positions=got, gravity_load=weight)


@dataclass(frozen=True)
class VerticalCar(LinearModelBase):
    """A passenger car in the vertical plane (Manchester benchmark vehicle, Iwnicki 1998).

    Every mass, inertia, length and stiffness is finite and > 0, every damping finite and ≥ 0,
    and the semi-wheelbase is less than the semi bogie spacing (the bogies' axles do not cross).
    The equations of motion are derived from the energies in
    :func:`raildyn.derivations.vertical.vertical_car` (notebook 06, section 6.1).

    Attributes
    ----------
    body_mass : float
        kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass") (Iwnicki 1998: 32 000 kg; as
        :class:`LateralCar`).
    body_pitch_inertia : float
        kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia") (Iwnicki 1998: 1.97 ×
        10⁶ kg·m²).
    bogie_mass : float
        Bogie frame, kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass") (Iwnicki 1998:
        2615 kg; as :class:`Bogie`).
    bogie_pitch_inertia : float
        kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia") (Iwnicki 1998: the
        frame's inertias are 1722 about x (roll), 1476 about
        y (pitch) and 3067 kg·m² about z (yaw); pitch turns about y. The 1476 is
        also what D. Cantero's TTB-2D takes for this vehicle's bogie in the
        vertical plane: ``TrainProp_Manchester_BenchMark.m``,
        https://github.com/DanielCanteroNTNU/TTB-2D, commit 2b414dd).
    semi_bogie_spacing : float
        l, m, in [0.01, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length") (Iwnicki 1998: 19
        m between bogie centres).
    semi_wheelbase : float
        b, m, in [0.01, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length") (Iwnicki 1998:
        2.56 m wheelbase).
    primary_stiffness, primary_damping : float
        Per wheelset (two axleboxes), N/m and N·s/m (Iwnicki 1998: 1220 kN/m and
        4 kN·s/m per axlebox).
    secondary_stiffness, secondary_damping : float
        Per bogie (two sides), N/m and N·s/m (Iwnicki 1998: 430 kN/m and
        20 kN·s/m per side; as the roll terms of :class:`LateralCar`).
    """

    body_mass: float = _CAR.body_mass
    body_pitch_inertia: float = 1.97e6
    bogie_mass: float = _BOGIE.frame_mass
    bogie_pitch_inertia: float = 1476.0
    semi_bogie_spacing: float = _CAR.semi_bogie_spacing
    semi_wheelbase: float = _BOGIE.semi_wheelbase
    primary_stiffness: float = 2 * 1220.0e3
    primary_damping: float = 2 * 4.0e3
    secondary_stiffness: float = 2 * 430.0e3
    secondary_damping: float = 2 * 20.0e3

    def __post_init__(self):
        for name in self.__dataclass_fields__:
            if name.endswith("damping"):
                nonnegative(name, getattr(self, name))
            else:
                positive(name, getattr(self, name))
        _checks.plausible_fields(self, "mass", ("body_mass", "bogie_mass"))
        _checks.plausible_fields(self, "inertia", ("body_pitch_inertia", "bogie_pitch_inertia"))
        _checks.plausible_fields(self, "vehicle_length", ("semi_bogie_spacing", "semi_wheelbase"))
        if self.semi_wheelbase >= self.semi_bogie_spacing:
            raise ValueError(
                f"semi_wheelbase must be less than semi_bogie_spacing ({self.semi_bogie_spacing!r} m), "
                f"got {self.semi_wheelbase!r}"
            )

    @property
    def axle_positions(self) -> np.ndarray:
        """Distances of the four axles behind the leading one, m: 0, 2b, 2l, 2l + 2b."""
        b, s = self.semi_wheelbase, self.semi_bogie_spacing
        return np.array([0.0, 2 * b, 2 * s, 2 * s + 2 * b])

    def linear_system(self) -> LinearSystem:
        """The 6-coordinate model with its four wheelset inputs (rail heights under each axle, both rails).

        Returns
        -------
        LinearSystem
        """
        b = self.semi_wheelbase
        return body_on_two_trucks(
            LABELS, self.body_mass, self.body_pitch_inertia, self.bogie_mass, self.bogie_pitch_inertia,
            self.semi_bogie_spacing, (b, -b), self.primary_stiffness, self.primary_damping,
            self.secondary_stiffness, self.secondary_damping, self.axle_positions,
        )  # fmt: skip

    def body_frequencies(self) -> BodyFrequencies:
        """Closed-form undamped body bounce and pitch frequencies on the secondary, bogies held.

        Returns
        -------
        BodyFrequencies
        """
        ks, s = self.secondary_stiffness, self.semi_bogie_spacing
        return BodyFrequencies(
            bounce_hz=float(np.sqrt(2 * ks / self.body_mass) / (2 * np.pi)),
            pitch_hz=float(np.sqrt(2 * ks * s**2 / self.body_pitch_inertia) / (2 * np.pi)),
        )


MANCHESTER_VERTICAL = VerticalCar()
"""The Manchester benchmark vehicle in the vertical plane."""
