"""Six-axle locomotive in the vertical plane: body bounce and pitch on two three-axle trucks (chapter 6).

Six coordinates: body z, θ; truck 1 (front) z, θ; truck 2 z, θ (a point x ahead of
a centre moves z + xθ). Each truck has three equally spaced axles (centre axle
under the truck centre); the wheelsets, with their traction motors, follow the
track and are unsprung. Primary springs join each axle to its truck frame,
secondary springs each truck to the body.

The default values are representative of an EMD SD40-2: 368 000 lb (167 t) and
truck centres 43 ft 6 in (13.26 m), as published (Wikipedia, "EMD SD40-2"); 2.07 m
between axles; the split of the mass between body, frames and unsprung wheelsets and
the spring rates are chosen, not taken from a published table (body bounce
near 1.4 Hz).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks, _deprecated
from raildyn.linear_model import LinearModelBase, LinearSystem
from raildyn.vehicles.vertical import body_on_two_trucks

__all__ = ["DEFAULT_LOCOMOTIVE", "LABELS", "VerticalLocomotive"]

# The old names of issue 33 (raildyn._deprecated.RENAMED): each warns and gives the new object;
# they go after one issue.
__getattr__ = _deprecated.module_getattr(__name__, globals())

LABELS = ("body z", "body θ", "truck1 z", "truck1 θ", "truck2 z", "truck2 θ")


@dataclass(frozen=True)
class VerticalLocomotive(LinearModelBase):
    """A six-axle locomotive, vertical.

    Every mass, inertia, length and stiffness is finite and > 0, every damping finite and ≥ 0,
    and the axle spacing is less than the semi truck spacing (each truck's axles on its own
    side of the body's centre). The equations of motion are derived from the energies in
    :func:`raildyn.derivations.vertical.vertical_locomotive` (notebook 06, section 6.5).

    Attributes
    ----------
    body_mass : float
        kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass") (167 t less 6 × 3.5 t
        unsprung and 2 × 6.5 t frames).
    body_pitch_inertia : float
        kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia") (m L²/12 for a 20 m body).
    truck_mass, truck_pitch_inertia : float
        One truck frame, kg in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass") and kg·m² in
        [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia").
    semi_truck_spacing : float
        l, half the distance between truck centres, m, in [0.01, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length").
    axle_spacing : float
        Between neighbouring axles of a truck, m, in [0.01, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "vehicle_length"): b, the truck's semi-wheelbase (the middle axle
        stands under the truck's centre).
    primary_stiffness, primary_damping : float
        Per axle, N/m and N·s/m.
    secondary_stiffness, secondary_damping : float
        Per truck, N/m and N·s/m.
    """

    body_mass: float = 133_000.0
    body_pitch_inertia: float = 133_000.0 * 20.0**2 / 12
    truck_mass: float = 6_500.0
    truck_pitch_inertia: float = 6_500.0 * 4.5**2 / 12
    semi_truck_spacing: float = (43 + 6 / 12) * 0.3048 / 2
    axle_spacing: float = 2.07
    primary_stiffness: float = 3.0e6
    primary_damping: float = 3.0e4
    secondary_stiffness: float = 5.15e6
    secondary_damping: float = 6.0e4

    def __post_init__(self):
        for name in self.__dataclass_fields__:
            if name.endswith("damping"):
                _checks.nonnegative(name, getattr(self, name))
            else:
                _checks.positive(name, getattr(self, name))
        _checks.plausible_fields(self, "mass", ("body_mass", "truck_mass"))
        _checks.plausible_fields(self, "inertia", ("body_pitch_inertia", "truck_pitch_inertia"))
        _checks.plausible_fields(self, "vehicle_length", ("semi_truck_spacing", "axle_spacing"))
        if self.axle_spacing >= self.semi_truck_spacing:
            raise ValueError(
                f"axle_spacing must be less than semi_truck_spacing ({self.semi_truck_spacing!r} m), "
                f"got {self.axle_spacing!r}"
            )

    @property
    def axle_positions(self) -> np.ndarray:
        """Distances of the six axles behind the leading one, m."""
        a, s = self.axle_spacing, self.semi_truck_spacing
        front = np.array([0.0, a, 2 * a])
        return np.concatenate([front, front + 2 * s])

    def linear_system(self) -> LinearSystem:
        """The 6-coordinate model with its six axle inputs (rail heights, both rails).

        Returns
        -------
        LinearSystem
        """
        a = self.axle_spacing
        return body_on_two_trucks(
            LABELS, self.body_mass, self.body_pitch_inertia, self.truck_mass, self.truck_pitch_inertia,
            self.semi_truck_spacing, (a, 0.0, -a), self.primary_stiffness, self.primary_damping,
            self.secondary_stiffness, self.secondary_damping, self.axle_positions,
        )  # fmt: skip


DEFAULT_LOCOMOTIVE = VerticalLocomotive()
"""The representative six-axle locomotive."""
