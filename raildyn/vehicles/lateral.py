"""Lateral vehicle models: a two-axle bogie and a full passenger car (book chapter 7).

* :class:`Bogie` — a bogie frame (lateral, yaw) on two wheelsets (lateral, yaw
  each), joined by the secondary suspension to a car body running straight:
  6 degrees of freedom;
* :class:`Car` — a car body (lateral, yaw, roll) on two such bogies: 15 degrees
  of freedom.

Both give a :class:`~raildyn.wheelset.LateralSystem` (``linear_system()``) for
:mod:`raildyn.stability`, and a nonlinear counterpart (``nonlinear(speed)``).
The default parameters are those of the Manchester benchmark vehicle
(Iwnicki 1998), cited beside each value; the wheel–rail contact is the cone of
:class:`~raildyn.wheelset.Wheelset`. The bogie frame's roll and the heights of
the frame and wheelsets are left out: the car body rolls on the secondary
springs, which stand on frames that stay upright.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from raildyn._checks import nonnegative, positive
from raildyn.wheelset import (
    GRAVITY,
    LateralSystem,
    NonlinearLateral,
    WheelRailContact,
    Wheelset,
    creep_terms,
)

# Manchester benchmark vehicle 1 (Iwnicki 1998): lateral primary springs 1.0 m either side of the
# centre line (semi-spacing), secondary springs 1.0 m either side; semi-wheelbase 1.28 m; semi
# distance between bogie centres 9.5 m; body centre of gravity 1.8 m above rail, secondary spring
# seat 0.8275 m above rail as modelled here (the benchmark gives the body CG height and the bogie
# geometry; the seat height is taken from a public transcription of the data set).
_B1 = 1.0
_B2 = 1.0


class _Assembly:
    """M, C₀, C₁, K of a lateral model, built element by element."""

    def __init__(self, labels: list[str]):
        self.labels = list(labels)
        n = len(labels)
        self.M = np.zeros((n, n))
        self.C0 = np.zeros((n, n))
        self.C1 = np.zeros((n, n))
        self.K = np.zeros((n, n))
        self.wheelsets: list = []

    def index(self, label: str) -> int:
        return self.labels.index(label)

    def mass(self, label: str, value: float) -> None:
        i = self.index(label)
        self.M[i, i] += value

    def element(self, terms: dict[str, float], stiffness: float, damping: float = 0.0) -> None:
        """A spring and damper acting on the relative displacement d = Σ coefficient · coordinate."""
        g = np.zeros(len(self.labels))
        for label, coefficient in terms.items():
            g[self.index(label)] += coefficient
        self.K += stiffness * np.outer(g, g)
        self.C0 += damping * np.outer(g, g)

    def wheelset(self, y: str, psi: str, ws: Wheelset) -> None:
        """The wheel–rail terms of one wheelset on its two coordinates."""
        C1, K_creep, K_gravity = creep_terms(ws)
        idx = np.ix_([self.index(y), self.index(psi)], [self.index(y), self.index(psi)])
        self.C1[idx] += C1
        self.K[idx] += K_creep + K_gravity
        self.mass(y, ws.mass)
        self.mass(psi, ws.yaw_inertia)
        self.wheelsets.append((self.index(y), self.index(psi), ws))

    def system(self) -> LateralSystem:
        return LateralSystem(self.M, self.C0, self.C1, self.K, tuple(self.labels), tuple(self.wheelsets))


@dataclass(frozen=True)
class Bogie:
    """A two-axle bogie: frame and wheelsets, primary and secondary suspension (Manchester vehicle).

    The primary suspension of each wheelset is the one in its
    :class:`~raildyn.wheelset.Wheelset` (lateral and yaw stiffness and damping,
    totals per wheelset).

    Attributes
    ----------
    wheelset : Wheelset
    frame_mass : float
        kg (Iwnicki 1998: 2615 kg).
    frame_yaw_inertia : float
        kg·m² (Iwnicki 1998: 3067 kg·m²).
    semi_wheelbase : float
        b, m (Iwnicki 1998: 2.56 m wheelbase).
    secondary_lateral_stiffness, secondary_lateral_damping : float
        Per bogie, N/m and N·s/m (Iwnicki 1998: 160 kN/m and 32 kN·s/m per side).
    secondary_yaw_stiffness, secondary_yaw_damping : float
        Per bogie, N·m/rad and N·m·s/rad (Iwnicki 1998: longitudinal secondary
        stiffness 160 kN/m per side at 1.0 m from the centre line; no yaw damper).
    """

    wheelset: Wheelset = field(default_factory=Wheelset)
    frame_mass: float = 2615.0
    frame_yaw_inertia: float = 3067.0
    semi_wheelbase: float = 1.28
    secondary_lateral_stiffness: float = 2 * 160.0e3
    secondary_lateral_damping: float = 2 * 32.0e3
    secondary_yaw_stiffness: float = 2 * 160.0e3 * _B2**2
    secondary_yaw_damping: float = 0.0

    def __post_init__(self):
        if not isinstance(self.wheelset, Wheelset):
            raise TypeError(f"wheelset must be a Wheelset, got {type(self.wheelset).__name__}")
        for name in ("frame_mass", "frame_yaw_inertia", "semi_wheelbase"):
            positive(name, getattr(self, name))
        for name in (
            "secondary_lateral_stiffness",
            "secondary_lateral_damping",
            "secondary_yaw_stiffness",
            "secondary_yaw_damping",
        ):
            nonnegative(name, getattr(self, name))

    def with_(self, **changes) -> Bogie:
        """A copy with bogie or wheelset fields changed (``conicity=...`` reaches the wheelset)."""
        ws_fields = set(Wheelset.__dataclass_fields__)
        ws_changes = {k: v for k, v in changes.items() if k in ws_fields}
        own = {k: v for k, v in changes.items() if k not in ws_fields}
        if ws_changes:
            own["wheelset"] = self.wheelset.replace(**ws_changes)
        return replace(self, **own)

    def _add(self, asm: _Assembly, tag: str, body: dict[str, float], body_yaw: str | None) -> None:
        """Frame and wheelsets of bogie ``tag``; ``body`` gives the lateral displacement of its
        secondary seat as coefficients of the body coordinates, ``body_yaw`` the body's yaw coordinate."""
        ws, b = self.wheelset, self.semi_wheelbase
        fy, fpsi = f"frame{tag} y", f"frame{tag} ψ"
        asm.mass(fy, self.frame_mass)
        asm.mass(fpsi, self.frame_yaw_inertia)
        for k, x in ((1, b), (2, -b)):
            wy, wpsi = f"wheelset{tag}{k} y", f"wheelset{tag}{k} ψ"
            asm.wheelset(wy, wpsi, ws)
            # Primary: lateral relative displacement at the axle, relative yaw.
            asm.element({wy: 1.0, fy: -1.0, fpsi: -x}, ws.lateral_stiffness, ws.lateral_damping)
            asm.element({wpsi: 1.0, fpsi: -1.0}, ws.yaw_stiffness, ws.yaw_damping)
        lateral = {fy: 1.0, **{k: -v for k, v in body.items()}}
        asm.element(lateral, self.secondary_lateral_stiffness, self.secondary_lateral_damping)
        yaw = {fpsi: 1.0} | ({body_yaw: -1.0} if body_yaw else {})
        asm.element(yaw, self.secondary_yaw_stiffness, self.secondary_yaw_damping)

    def linear_system(self) -> LateralSystem:
        """The bogie under a car body that runs straight (the body does not move): 6 coordinates."""
        labels = ["frame y", "frame ψ", "wheelset1 y", "wheelset1 ψ", "wheelset2 y", "wheelset2 ψ"]
        asm = _Assembly(labels)
        self._add(asm, "", {}, None)
        return asm.system()

    def nonlinear(self, speed: float = 30.0, contact: WheelRailContact | None = None) -> NonlinearLateral:
        """The bogie with nonlinear wheel–rail contact at ``speed`` (m/s)."""
        return NonlinearLateral(self.linear_system(), contact or WheelRailContact(), speed)


@dataclass(frozen=True)
class Car:
    """A passenger car: body (lateral, yaw, roll) on two bogies; the Manchester benchmark vehicle.

    Attributes
    ----------
    bogie : Bogie
    body_mass : float
        kg (Iwnicki 1998: 32000 kg).
    body_yaw_inertia : float
        kg·m² (Iwnicki 1998: 1.97 × 10⁶ kg·m²).
    body_roll_inertia : float
        kg·m² (Iwnicki 1998: 5.68 × 10⁴ kg·m²).
    semi_bogie_spacing : float
        Half the distance between bogie centres, m (Iwnicki 1998: 19 m between centres).
    body_height : float
        Height of the body's centre of gravity above the secondary lateral springs, m
        (1.8 m above rail, seat at 0.8275 m: 0.9725 m).
    roll_stiffness : float
        Per bogie, N·m/rad: the vertical secondary springs, 430 kN/m per side at
        1.0 m (Iwnicki 1998), plus the anti-roll bar, 940 kN·m/rad.
    roll_damping : float
        Per bogie, N·m·s/rad: vertical secondary dampers, 20 kN·s/m per side at 1.0 m.
    """

    bogie: Bogie = field(default_factory=Bogie)
    body_mass: float = 32000.0
    body_yaw_inertia: float = 1.97e6
    body_roll_inertia: float = 5.68e4
    semi_bogie_spacing: float = 9.5
    body_height: float = 1.8 - 0.8275
    roll_stiffness: float = 2 * 430.0e3 * _B2**2 + 940.0e3
    roll_damping: float = 2 * 20.0e3 * _B2**2

    def __post_init__(self):
        if not isinstance(self.bogie, Bogie):
            raise TypeError(f"bogie must be a Bogie, got {type(self.bogie).__name__}")
        for name in ("body_mass", "body_yaw_inertia", "body_roll_inertia", "semi_bogie_spacing"):
            positive(name, getattr(self, name))
        for name in ("body_height", "roll_stiffness", "roll_damping"):
            nonnegative(name, getattr(self, name))

    def with_(self, **changes) -> Car:
        """A copy with car, bogie or wheelset fields changed."""
        own_fields = set(Car.__dataclass_fields__)
        own = {k: v for k, v in changes.items() if k in own_fields}
        rest = {k: v for k, v in changes.items() if k not in own_fields}
        if rest:
            own["bogie"] = (own.get("bogie") or self.bogie).with_(**rest)
        return replace(self, **own)

    @property
    def wheelset(self) -> Wheelset:
        return self.bogie.wheelset

    def linear_system(self) -> LateralSystem:
        """The 15-coordinate car: body y, ψ, φ; each frame y, ψ; each wheelset y, ψ."""
        labels = ["body y", "body ψ", "body φ"]
        for tag in ("1", "2"):
            labels += [f"frame{tag} y", f"frame{tag} ψ"]
            labels += [f"wheelset{tag}{k} {q}" for k in (1, 2) for q in ("y", "ψ")]
        asm = _Assembly(labels)
        asm.mass("body y", self.body_mass)
        asm.mass("body ψ", self.body_yaw_inertia)
        asm.mass("body φ", self.body_roll_inertia)
        h, s = self.body_height, self.semi_bogie_spacing
        for tag, x in (("1", s), ("2", -s)):
            # The secondary seat is h below the body's centre: it moves y + xψ + hφ.
            self.bogie._add(asm, tag, {"body y": 1.0, "body ψ": x, "body φ": h}, "body ψ")
            asm.element({"body φ": 1.0}, self.roll_stiffness, self.roll_damping)
        # The body's weight acting above the roll centre (the secondary seat) lowers its roll stiffness.
        i = asm.index("body φ")
        asm.K[i, i] -= self.body_mass * GRAVITY * h
        return asm.system()

    def nonlinear(self, speed: float = 30.0, contact: WheelRailContact | None = None) -> NonlinearLateral:
        """The car with nonlinear wheel–rail contact at ``speed`` (m/s)."""
        return NonlinearLateral(self.linear_system(), contact or WheelRailContact(), speed)


MANCHESTER_CAR = Car()
"""The Manchester benchmark vehicle with the default conical wheel–rail contact."""
