"""Lateral vehicle models: a two-axle bogie and a full passenger car (book chapter 7).

* :class:`Bogie` — a bogie frame (lateral, yaw) on two wheelsets (lateral, yaw
  each), joined by the secondary suspension to a car body running straight:
  6 degrees of freedom;
* :class:`LateralCar` — a car body (lateral, yaw, roll) on two such bogies: 15 degrees
  of freedom.

Both are linear models of the one protocol (:class:`raildyn.linear_model.LinearModel`:
``linear_system()``, ``matrices(V)``, ``state_space(V)``, ``replace(...)``), driven
by the alignment and cross-level under each wheelset, for :mod:`raildyn.stability`
and :mod:`raildyn.vehicles.response`; ``nonlinear()`` gives the nonlinear counterpart.
The default parameters are those of the Manchester benchmark vehicle
(Iwnicki 1998), cited beside each value; the wheel–rail contact is the cone of
:class:`~raildyn.wheelset.Wheelset`. A second parameter set,
:data:`COOPERRIDER_CAR` (:func:`cooperrider_car`), is the car on two Cooperrider
bogies of DTU's DYTSI code. The bogie frame's roll and the heights of
the frame and wheelsets are left out: the car body rolls on the secondary
springs, which stand on frames that stay upright.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from raildyn import _checks, _deprecated, contact
from raildyn._checks import nonnegative, positive
from raildyn.constants import GRAVITY, STANDARD_RAIL_SPACING
from raildyn.linear_model import Assembler, LinearModelBase, LinearSystem
from raildyn.vehicles._shared import (
    _check_body_on_two_trucks,
    _check_truck_assembly,
    _nonlinear,
    _replace_through,
)
from raildyn.wheelset import NonlinearLateral, WheelRailContact, Wheelset, add_wheelset

__all__ = ["COOPERRIDER_CAR", "MANCHESTER_CAR", "Bogie", "LateralCar", "cooperrider_car"]

# The old names of issue 33 (raildyn._deprecated.RENAMED): each warns and gives the new object;
# they go after one issue.
__getattr__ = _deprecated.module_getattr(__name__, globals())

# Manchester benchmark vehicle 1 (Iwnicki 1998): lateral primary springs 1.0 m either side of the
# centre line (semi-spacing), secondary springs 1.0 m either side; semi-wheelbase 1.28 m; semi
# distance between bogie centres 9.5 m; body centre of gravity 1.8 m above rail, secondary spring
# seat 0.8275 m above rail as modelled here (the benchmark gives the body CG height and the bogie
# geometry; the seat height is taken from a public transcription of the data set).
_B1 = 1.0
_B2 = 1.0


class _OnTheRails(LinearModelBase):
    """A lateral vehicle whose wheelsets run on the rails: the linear protocol and its nonlinear twin."""

    def nonlinear(self, contact: WheelRailContact | None = None) -> NonlinearLateral:
        """The vehicle with nonlinear wheel–rail contact (its speed is given to each run).

        Parameters
        ----------
        contact : WheelRailContact, optional
            The nonlinear contact; default :class:`~raildyn.wheelset.WheelRailContact`.

        Returns
        -------
        NonlinearLateral
        """
        return _nonlinear(self, contact)


@dataclass(frozen=True)
class Bogie(_OnTheRails):
    """A two-axle bogie: frame and wheelsets, primary and secondary suspension (Manchester vehicle).

    The primary suspension of each wheelset is the one in its
    :class:`~raildyn.wheelset.Wheelset` (lateral and yaw stiffness and damping,
    totals per wheelset). The equations of motion, derived from the energies of the
    springs and the creep forces by virtual work, are
    :func:`raildyn.derivations.lateral.bogie` (notebook 07, section 7.1).

    Attributes
    ----------
    wheelset : Wheelset
    frame_mass : float
        m_f, kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass") (Iwnicki 1998: 2615 kg).
    frame_yaw_inertia : float
        I_f, kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia") (Iwnicki 1998: 3067
        kg·m²).
    semi_wheelbase : float
        b, half the wheelbase, m, in [0.01, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "vehicle_length") (Iwnicki 1998: 2.56 m wheelbase).
    secondary_lateral_stiffness, secondary_lateral_damping : float
        k_sy and c_sy, per bogie, N/m and N·s/m, ≥ 0 (Iwnicki 1998: 160 kN/m and 32 kN·s/m per
        side).
    secondary_yaw_stiffness, secondary_yaw_damping : float
        k_sψ and c_sψ, per bogie, N·m/rad and N·m·s/rad, ≥ 0 (Iwnicki 1998: longitudinal secondary
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
        _checks.instance("wheelset", self.wheelset, Wheelset)
        for name in ("frame_mass", "frame_yaw_inertia", "semi_wheelbase"):
            positive(name, getattr(self, name))
        _checks.plausible("frame_mass", self.frame_mass, "mass")
        _checks.plausible("frame_yaw_inertia", self.frame_yaw_inertia, "inertia")
        _checks.plausible("semi_wheelbase", self.semi_wheelbase, "vehicle_length")
        for name in (
            "secondary_lateral_stiffness",
            "secondary_lateral_damping",
            "secondary_yaw_stiffness",
            "secondary_yaw_damping",
        ):
            nonnegative(name, getattr(self, name))

    def replace(self, **changes) -> Bogie:
        """A copy with bogie or wheelset fields changed (``conicity=...`` reaches the wheelset).

        Parameters
        ----------
        **changes
            Fields of the bogie or of its :class:`~raildyn.wheelset.Wheelset`.

        Returns
        -------
        Bogie
        """
        return _replace_through(self, changes, "wheelset")

    def assemble(
        self, asm: Assembler, tag: str, body: dict[str, float], body_yaw: str | None, first_input: int
    ) -> None:
        """Add the frame and wheelsets of bogie ``tag`` to an assembly.

        Parameters
        ----------
        asm : Assembler
            Holding the bogie's labels for ``tag`` and two inputs (alignment, cross-level)
            per wheelset.
        tag : str
            Suffix of the bogie's labels ("frame{tag} y", "wheelset{tag}1 y", ...).
        body : dict of str to float
            The lateral displacement of the secondary seat as finite coefficients of the body
            coordinates (labels of ``asm``); empty for a body that does not move.
        body_yaw : str or None
            The body's yaw coordinate (a label of ``asm``), if the body moves.
        first_input : int
            Index of the leading wheelset's alignment input, in [0, ``asm.GK.shape[1] // 2`` − 2];
            the trailing one's is next, and their cross-level inputs follow the alignment
            inputs of every wheelset (``asm.GK.shape[1] // 2`` further on).
        """
        half = _check_truck_assembly(asm, tag, body, body_yaw, first_input, axles=2)
        ws, b = self.wheelset, self.semi_wheelbase
        fy, fpsi = f"frame{tag} y", f"frame{tag} ψ"
        asm.mass(fy, self.frame_mass)
        asm.mass(fpsi, self.frame_yaw_inertia)
        for k, x in ((1, b), (2, -b)):
            wy, wpsi = f"wheelset{tag}{k} y", f"wheelset{tag}{k} ψ"
            j = first_input + k - 1
            add_wheelset(asm, wy, wpsi, ws, alignment=j, cross_level=half + j)
            # Primary: lateral relative displacement at the axle, relative yaw.
            asm.element({wy: 1.0, fy: -1.0, fpsi: -x}, ws.lateral_stiffness, ws.lateral_damping)
            asm.element({wpsi: 1.0, fpsi: -1.0}, ws.yaw_stiffness, ws.yaw_damping)
        lateral = {fy: 1.0, **{k: -v for k, v in body.items()}}
        asm.element(lateral, self.secondary_lateral_stiffness, self.secondary_lateral_damping)
        yaw = {fpsi: 1.0} | ({body_yaw: -1.0} if body_yaw else {})
        asm.element(yaw, self.secondary_yaw_stiffness, self.secondary_yaw_damping)

    def linear_system(self) -> LinearSystem:
        """The bogie under a car body that runs straight (the body does not move): 6 coordinates.

        Four track inputs: the alignment at the leading and trailing wheelsets, then
        the cross-level there (m).

        Returns
        -------
        LinearSystem
        """
        labels = ["frame y", "frame ψ", "wheelset1 y", "wheelset1 ψ", "wheelset2 y", "wheelset2 ψ"]
        asm = Assembler(labels, n_inputs=4)
        self.assemble(asm, "", {}, None, 0)
        b = self.semi_wheelbase
        kinds = ("alignment",) * 2 + ("cross_level",) * 2
        return asm.system(input_positions=np.tile([0.0, 2 * b], 2), input_kinds=kinds)


@dataclass(frozen=True)
class LateralCar(_OnTheRails):
    """A passenger car: body (lateral, yaw, roll) on two bogies; the Manchester benchmark vehicle.

    The equations of motion, derived from the energies of the springs, the body's weight and the
    creep forces, are :func:`raildyn.derivations.lateral.lateral_car` (notebook 07, section 7.1).

    Attributes
    ----------
    bogie : Bogie
    body_mass : float
        m, kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass") (Iwnicki 1998: 32000 kg).
    body_yaw_inertia : float
        I_z, kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia") (Iwnicki 1998: 1.97
        × 10⁶ kg·m²).
    body_roll_inertia : float
        I_x, kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia") (Iwnicki 1998: 5.68
        × 10⁴ kg·m²).
    semi_bogie_spacing : float
        l, half the distance between bogie centres, m, in [0.01, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length"), greater than the bogie's
        semi-wheelbase (the bogies' wheelsets do not cross) (Iwnicki 1998: 19 m between centres).
    body_height : float
        h, height of the body's centre of gravity above the secondary lateral springs, m, in
        [0, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length") (1.8 m above rail, seat at
        0.8275 m: 0.9725 m).
    roll_stiffness : float
        k_ϕ, per bogie, N·m/rad: the vertical secondary springs, 430 kN/m per side at
        1.0 m (Iwnicki 1998), plus the anti-roll bar, 940 kN·m/rad. The two bogies'
        2 k_φ must exceed m g h, the roll moment of the body's weight h above the springs
        per radian; else the body topples.
    roll_damping : float
        c_ϕ, per bogie, N·m·s/rad, ≥ 0: vertical secondary dampers, 20 kN·s/m per side at 1.0 m.
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
        _checks.instance("bogie", self.bogie, Bogie)
        _check_body_on_two_trucks(self, "semi_bogie_spacing", "semi_wheelbase", self.bogie.semi_wheelbase)

    def replace(self, **changes) -> LateralCar:
        """A copy with car, bogie or wheelset fields changed.

        Parameters
        ----------
        **changes
            Fields of the car, of its :class:`Bogie` or of their :class:`~raildyn.wheelset.Wheelset`.

        Returns
        -------
        LateralCar
        """
        return _replace_through(self, changes, "bogie")

    @property
    def wheelset(self) -> Wheelset:
        """The wheelset of the car's bogies."""
        return self.bogie.wheelset

    @property
    def axle_positions(self) -> np.ndarray:
        """Distances of the four wheelsets behind the leading one, m: 0, 2b, 2s, 2s + 2b."""
        b, s = self.bogie.semi_wheelbase, self.semi_bogie_spacing
        return np.array([0.0, 2 * b, 2 * s, 2 * s + 2 * b])

    def linear_system(self) -> LinearSystem:
        """The 15-coordinate car (body y, ψ, φ; each frame y, ψ; each wheelset y, ψ) and its track inputs.

        Eight inputs: the alignment y_a (m) at each of the four wheelsets, then the
        cross-level Δz (m) there, coupled to each wheelset by
        :func:`~raildyn.wheelset.add_wheelset`. The bogie frames, which the model
        keeps upright on the track, tilt with the mean of their two wheelsets, so
        the secondary roll springs act on φ − Δz̄/(2a_r), Δz̄ the mean of the two and 2a_r the rail spacing.

        Returns
        -------
        LinearSystem
        """
        labels = ["body y", "body ψ", "body φ"]
        for tag in ("1", "2"):
            labels += [f"frame{tag} y", f"frame{tag} ψ"]
            labels += [f"wheelset{tag}{k} {q}" for k in (1, 2) for q in ("y", "ψ")]
        asm = Assembler(labels, n_inputs=8)
        asm.mass("body y", self.body_mass)
        asm.mass("body ψ", self.body_yaw_inertia)
        asm.mass("body φ", self.body_roll_inertia)
        h, s = self.body_height, self.semi_bogie_spacing
        tilt = 0.5 / STANDARD_RAIL_SPACING  # frame roll per metre of cross-level at each wheelset
        for first, (tag, x) in zip((0, 2), (("1", s), ("2", -s)), strict=True):
            # The secondary seat is h below the body's centre: it moves y + xψ + hφ.
            self.bogie.assemble(asm, tag, {"body y": 1.0, "body ψ": x, "body φ": h}, "body ψ", first)
            frame_tilt = {4 + first: tilt, 5 + first: tilt}
            asm.element({"body φ": 1.0}, self.roll_stiffness, self.roll_damping, inputs=frame_tilt)
        # The body's weight acting above the roll centre (the secondary seat) lowers its roll stiffness.
        asm.block(["body φ"], K=[[-self.body_mass * GRAVITY * h]])
        kinds = ("alignment",) * 4 + ("cross_level",) * 4
        return asm.system(input_positions=np.tile(self.axle_positions, 2), input_kinds=kinds)


MANCHESTER_CAR = LateralCar()
"""The Manchester benchmark vehicle with the default conical wheel–rail contact."""


# ---------------------------------------------------------------------------
# The Cooperrider car of DYTSI
#
# Source: D. Bigoni, DYTSI (DTU Compute), https://github.com/daniele-bigoni/dytsi:
# [xml] input/InputFiles/inputBifurcation-Cooperrider-straight.xml at commit
#       d66cf61a3a6a7669d82542f96c8d3e2a3889e3cb (the named parameters r0, a, u1, ..., k1, ..., D6);
# [ortho] src/Models/CooperriderOrthogonalModel.cpp at commit 303a11153a456b41fee68b4b58246c3b14685af6
#       (masses, inertias and the geometry of every spring and damper). The input file's model tag is
#       <CooperriderOrthogonalModel>, so DYTSI runs this class with it, not CooperriderModel.cpp.
# Lengths in m, stiffnesses per spring in N/m, dampings per damper in N·s/m; "per side" means one of
# the two elements, left and right, at ±y from the centre line.
_CR_WHEELSET_MASS = 1022.0  # kg [ortho: wheelset block, mass]
_CR_WHEELSET_YAW_INERTIA = 678.0  # kg·m² [ortho: wheelset block, Iz]
_CR_FRAME_MASS = 2918.9  # kg [ortho: bogie frame block, mass]
_CR_FRAME_YAW_INERTIA = 6780.0  # kg·m² [ortho: bogie frame block, Iz]
_CR_BODY_MASS = 44388.0  # kg [ortho: car body block, mass]
_CR_BODY_ROLL_INERTIA = 2.80e5  # kg·m² [ortho: car body block, Ix]
# [ortho: car body block, Iz, marked there "TODO: Retreive real measures"]. The non-orthogonal
# variant src/Models/CooperriderModel.cpp (same commit) has 5.6e6; the linear critical speed of
# this car moves by less than 0.05 m/s between the two.
_CR_BODY_YAW_INERTIA = 5.0e5  # kg·m²
_CR_R0 = 0.425  # centred rolling radius [xml: r0]
_CR_A = 0.75  # half the distance between the contact points [xml: a]
_CR_U1 = 7.5  # half the distance between the bogie centres [xml: u1]
_CR_U2 = 1.074  # half the wheelbase [xml: u2]
_CR_H2 = 1.5584  # height of the body's centre of gravity above the frame centre [xml: h2; ortho: r0+h1+h2]
_CR_S1 = 0.62  # lateral position of the primary longitudinal (and vertical) springs [xml: s1]
_CR_S2 = 0.6584  # height of the secondary lateral springs above the frame centre [xml: s2]
_CR_S3 = 0.68  # lateral position of the secondary vertical springs and dampers [xml: s3]
# Lateral position of the secondary yaw springs and dampers: a + l1 + l2 + l3/2 = 0.75 + 0.3 + 0.3
# + 0.15 = 1.5 m [xml: a, l1, l2, l3; ortho: "Left yaw spring and damper"]. They are longitudinal
# elements, so their arm about the bogie pivot is this lateral offset; s4 = 0.759 m [xml] is only
# how far ahead of the pivot they are fixed to the body and plays no part in the yaw moment.
_CR_YAW_ARM = 0.75 + 0.30 + 0.30 + 0.30 / 2
_CR_K1 = 1823000.0  # primary lateral spring, per side [xml: k1]
_CR_K2 = 3646000.0  # primary longitudinal spring, per side, at y = ±s1 [xml: k2]
_CR_K4 = 182300.0  # secondary lateral spring, per side [xml: k4]
_CR_K5 = 333300.0  # secondary vertical spring, per side, at y = ±s3 [xml: k5]
_CR_K6 = 903350.0  # secondary longitudinal (yaw) spring, per side, at y = ±1.5 m [xml: k6]
_CR_D1 = 20000.0  # secondary vertical damper, per side, at y = ±s3 [xml: D1]
_CR_D2 = 29200.0  # secondary lateral damper, per side [xml: D2]
_CR_D3 = 0.0  # primary longitudinal damper [xml: D3]
_CR_D5 = 0.0  # primary lateral damper [xml: D5]
_CR_D6 = 166669.0  # secondary longitudinal (yaw) damper, per side, at y = ±1.5 m [xml: D6]
# Steel: E = 210 GPa, ν = 0.27 [ortho: wheelset block]. The shear modulus is E/(2(1 + ν)) =
# 82.7 GPa; DYTSI's code writes E/(2(1 − ν)) = 144 GPa there, a sign slip that we do not copy.
_CR_YOUNG = 2.1e11
_CR_POISSON = 0.27
# Stand-in for the tabulated 1:40 wheel/rail geometry (RSGEO/1o40/RSGEO.dat [xml]): a cone with
# the 1:40 slope. The table's own rolling radius has a slope of about 0.030 at the centre.
_CR_CONICITY = 1.0 / 40.0


def cooperrider_car() -> LateralCar:
    """The car on two Cooperrider bogies of DTU's DYTSI code, as a :class:`LateralCar`.

    DYTSI (D. Bigoni, DTU Compute, 2011–2014) models a car body on two bogies
    of Cooperrider's design (Cooperrider 1972), as used by True and
    co-workers. The values come from the input file
    ``input/InputFiles/inputBifurcation-Cooperrider-straight.xml`` (commit
    d66cf61) and from the model class that file selects,
    ``src/Models/CooperriderOrthogonalModel.cpp`` (commit 303a111), of
    https://github.com/daniele-bigoni/dytsi; each one is cited beside its
    constant in this module.

    * Wheelset: 1022 kg, 678 kg·m²; r₀ = 0.425 m, a = 0.75 m. Primary: lateral
      2 k₁ = 2 × 1823 kN/m; yaw 2 k₂ s₁² with k₂ = 3646 kN/m per side at
      s₁ = 0.62 m; no dampers (D₃ = D₅ = 0).
    * Frame: 2918.9 kg, 6780 kg·m²; half wheelbase 1.074 m. Secondary, per
      bogie: lateral 2 k₄ = 2 × 182.3 kN/m and 2 D₂ = 2 × 29.2 kN·s/m; yaw
      2 k₆ y² and 2 D₆ y² from longitudinal springs (903.35 kN/m) and dampers
      (166.669 kN·s/m) at y = ±1.5 m.
    * Body: 44388 kg; roll 2.80 × 10⁵ kg·m², yaw 5.0 × 10⁵ kg·m² (marked
      provisional in DYTSI); bogie centres 2 × 7.5 m apart. Roll per bogie:
      2 k₅ s₃² and 2 D₁ s₃², vertical springs of 333.3 kN/m and dampers of
      20 kN·s/m per side at s₃ = 0.68 m. The body's centre of gravity is
      h₂ − s₂ = 1.5584 − 0.6584 = 0.9 m above the secondary lateral springs.
    * Contact: a cone of conicity 1/40 stands in for DYTSI's tabulated 1:40
      wheel/rail geometry, on knife-edge rails (contact angle and ε equal to
      the conicity), as for the Manchester default. Axle load: the whole
      vehicle's weight over four axles. The contact patch is Hertz's under
      half the axle load with curvature 1/r₀ along and across the track (a
      circle, as the Manchester default assumes), and Kalker's coefficients
      come from :func:`raildyn.contact.kalker.creep_coefficients` with
      G = E/(2(1 + ν)) = 82.7 GPa (E = 210 GPa, ν = 0.27).

    Left out, having no counterpart in the 15 coordinates of :class:`LateralCar`:

    * the vertical, roll and pitch motion of wheelsets, frames and body, with
      the primary vertical springs (k₃ = 3646 kN/m per side) and dampers
      (D₄ = 0), and the heights h₁, v₁–v₄ and x₁ of the attachment points;
    * the frames' roll, so the secondary lateral springs, s₂ = 0.6584 m above
      the frame centre, act on frames that stay upright;
    * the weight's roll moment: :class:`LateralCar` takes it at the secondary lateral
      springs (0.9 m below the centre of gravity), DYTSI through the vertical
      springs, 0.3096 m below it; the difference moves the linear critical
      speed by less than 0.01 m/s;
    * the tabulated profile itself (rolling radius, contact angle, contact
      patch at every lateral displacement), including the flange, and the
      friction coefficient 0.15, which only a nonlinear contact would use
      (``WheelRailContact(friction=0.15)``);
    * from the non-orthogonal variant ``src/Models/CooperriderModel.cpp``
      (same commit), which this input file does not select: the hard-coded
      shear springs of 150 kN/m under the vertical springs, the inclined yaw
      dampers and the body yaw inertia of 5.6 × 10⁶ kg·m².

    Returns
    -------
    LateralCar
    """
    wheel_load = 0.5 * (_CR_BODY_MASS + 2 * _CR_FRAME_MASS + 4 * _CR_WHEELSET_MASS) * GRAVITY / 4.0
    shear = _CR_YOUNG / (2.0 * (1.0 + _CR_POISSON))
    patch = contact.hertz_contact(wheel_load, _CR_R0, np.inf, _CR_R0, _CR_YOUNG, _CR_POISSON)
    f = contact.creep_coefficients(patch.a, patch.b, shear, _CR_POISSON)
    wheelset = Wheelset(
        mass=_CR_WHEELSET_MASS,
        yaw_inertia=_CR_WHEELSET_YAW_INERTIA,
        rolling_radius=_CR_R0,
        half_gauge=_CR_A,
        conicity=_CR_CONICITY,
        axle_load=2.0 * wheel_load,
        f11=float(f.f11),
        f22=float(f.f22),
        f23=float(f.f23),
        f33=float(f.f33),
        lateral_stiffness=2 * _CR_K1,
        yaw_stiffness=2 * _CR_K2 * _CR_S1**2,
        lateral_damping=2 * _CR_D5,
        yaw_damping=2 * _CR_D3 * _CR_S1**2,
    )
    bogie = Bogie(
        wheelset=wheelset,
        frame_mass=_CR_FRAME_MASS,
        frame_yaw_inertia=_CR_FRAME_YAW_INERTIA,
        semi_wheelbase=_CR_U2,
        secondary_lateral_stiffness=2 * _CR_K4,
        secondary_lateral_damping=2 * _CR_D2,
        secondary_yaw_stiffness=2 * _CR_K6 * _CR_YAW_ARM**2,
        secondary_yaw_damping=2 * _CR_D6 * _CR_YAW_ARM**2,
    )
    return LateralCar(
        bogie=bogie,
        body_mass=_CR_BODY_MASS,
        body_yaw_inertia=_CR_BODY_YAW_INERTIA,
        body_roll_inertia=_CR_BODY_ROLL_INERTIA,
        semi_bogie_spacing=_CR_U1,
        body_height=_CR_H2 - _CR_S2,
        roll_stiffness=2 * _CR_K5 * _CR_S3**2,
        roll_damping=2 * _CR_D1 * _CR_S3**2,
    )


COOPERRIDER_CAR = cooperrider_car()
"""The car on two Cooperrider bogies of DTU's DYTSI code (:func:`cooperrider_car`), on a 1:40 cone."""
