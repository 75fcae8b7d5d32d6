"""The loaded freight car rocking on its trucks, with wheels that can lift (chapter 6): the parameters,
the linearisation and the quasi-static roll.

:class:`VerticalFreightCar` holds the body on its four spring nests with every wheel following its
rail; here the roll plane is opened up, one joint at a time, from the body to the rail:

* the **body** (bounce z, pitch θ, roll φ, sway y; its reference point its centre of gravity) rests on
  each truck's bolster through the **centre plate**, a disc of radius r_p that carries the load while
  the roll moment on it stays below r_p times the load, and lifts on one edge beyond (two one-sided
  contacts at ±r_p), held laterally by the bowl's rim; and on two **side bearers** at ±y_b, open by a
  gap g that closes into a stiff contact;
* each **bolster** (bounce, roll, sway) stands on two **spring nests** at ±d, with their vertical rate
  k, their lateral (shear) rate k_y and the **wedges'** friction F (as :class:`VerticalFreightCar`:
  F tanh(v/v_ε), :func:`raildyn.suspension.coulomb_friction`);
* each nest stands on a rigid side frame that rides on the bearings of the truck's two **wheelsets**
  (bounce, roll; the side frames' mass shared between them); each wheel stands on its rail through a
  one-sided contact with the track's stiffness and damping beneath it: a wheel whose load falls to
  zero lifts.

Eighteen coordinates, measured from the static equilibrium. The force law of every joint and the
compiled march live in ``_rocking_kernel``; the runs over jointed rail in
:mod:`raildyn.vehicles.rocking_runs`.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np

from raildyn import _checks
from raildyn import track as _track
from raildyn.constants import GRAVITY, STANDARD_RAIL_SPACING
from raildyn.linear_model import SystemMatrices
from raildyn.vehicles import _rocking_coordinates
from raildyn.vehicles.freight import VerticalFreightCar

# Imported where used, to keep this module's import cheap (tests/test_imports.py):
# raildyn.vehicles._rocking_kernel

if TYPE_CHECKING:
    from raildyn.vehicles.rocking_analysis import StaticRoll

__all__ = ["LABELS", "RockingFreightCar", "TRACK_STIFFNESS"]

LABELS = _rocking_coordinates.LABELS
"""The names of the 18 coordinates: the body's height, pitch, roll and sway, each bolster's height, roll
and sway, each wheelset's height and roll (wheelsets leading first), m and rad."""

INCH = 0.0254
# Track under one wheel: a rail on a Winkler foundation of modulus u takes a point load with the
# stiffness 2u/β, β = (u/4EI)^¼ (Hetényi's beam on an elastic foundation, as raildyn.bridge.WinklerBeam).
# Representative of older jointed track: u = 2000 lb/in per in of rail (13.8 MPa; wood-tie track lies
# at some 1500-3000) under 115 RE rail (I = 65.6 in⁴ = 2.73e-5 m⁴, E = 207 GPa): 3.1e7 N/m.
_TRACK_MODULUS = 2000 * 4.4482216 / INCH**2
_RAIL_EI = 207e9 * 65.6 * INCH**4
_BETA = (_TRACK_MODULUS / (4 * _RAIL_EI)) ** 0.25
TRACK_STIFFNESS = 2 * _TRACK_MODULUS / _BETA
"""The track's stiffness under one wheel, N/m: 2u/β of a 115 RE rail on a foundation of 13.8 MPa."""


@dataclass(frozen=True)
class RockingFreightCar:
    """A loaded freight car on two three-piece trucks in the roll plane, its wheels free to lift.

    Every field is finite; masses, inertias, stiffnesses, lengths and ``velocity_scale`` are > 0, the
    dampers and the side-bearer gap ≥ 0. The heights rise from the rail: spring plane < centre plate <
    the body's centre of gravity, the bolster's between the spring plane and the plate; the plate's
    radius is less than the side bearers' half-spacing, which is less than the nests'.

    Attributes
    ----------
    car : VerticalFreightCar
        The body on its nests (:class:`VerticalFreightCar`, default the loaded 286K hopper): its mass and
        inertias, the centre of gravity ``cg_height`` above the spring plane, the truck spacing and
        wheelbase, the nests' half-spacing d, their vertical rate k and the wedges' friction F per nest.
    bolster_mass : float
        kg, in [10, 1e6]: 342, the Ride Control truck's bolster in L. Baruffaldi's MBSim model
        (doctoral thesis, UNICAMP; https://github.com/leo-bart/doutorado-repo, src/ridecontroltruck.cpp,
        commit 247ba5c: ``bolsterMass``).
    bolster_roll_inertia : float
        About its centre of gravity, kg·m², in [1, 5e8]: a 2.6 m bar of 342 kg, m L²/12 = 193
        (representative: the casting's shape is not published).
    wheelset_mass : float
        A wheelset with its bearings and half of each side frame, kg, in [10, 1e6]: the truck's 4350 kg
        (``car``'s docstring) less the bolster, over two: 2004.
    wheelset_roll_inertia : float
        About its axle, with the side frames' share, kg·m², in [1, 5e8]: 1500 (representative: a
        wheelset of 1120 kg·m² at 1813 kg [Iwnicki 1998], scaled to 2000 kg, and two side-frame halves
        of 145 kg at ±1 m).
    wheel_radius : float
        r₀, m, in [0.1, 1.5]: 36 in wheels (AAR, for cars of 286 000 lb).
    half_rail_spacing : float
        a_r, half the distance between the rails' centres, m, in [0.15, 1.1]
        (:data:`~raildyn.constants.STANDARD_RAIL_SPACING` / 2).
    spring_plane_height : float
        Top of the nests above the rail, m: 0.6 (``car``'s docstring: centre of gravity 2.1 m above the
        rail, 1.5 m above the nests).
    bolster_height, centre_plate_height : float
        The bolster's centre of gravity and the centre plate's bearing face above the rail, m: 0.65 and
        0.70 (representative: a bolster some 0.1 m deep between the nests and the bowl).
    centre_plate_radius : float
        r_p, m: 8 in (a 16 in plate; the U.S. Army's rail car maintenance rules, TM 55-203 / DoD P-301,
        name bowls of 12, 14 and 16 in; the largest is taken for the 100-ton truck, representative).
    side_bearer_spacing : float
        y_b, half the distance between the side bearers, m: 25 in (50 in centres; representative).
    side_bearer_gap : float
        g, the clearance of each side bearer at rest, m, in [0, 0.05]: 1/4 in, the middle of the 3/16 to
        5/16 in the same maintenance rules allow (DoD P-301, "Defective rail car truck").
    centre_plate_stiffness, side_bearer_stiffness : float
        N/m, per plate edge and per bearer: 5e8 (representative: steel castings in contact; the
        answer changes little above 1e8, and a stiffer value only shortens the time step).
    contact_damping : float
        N·s/m, per plate edge and per bearer: 1e5 (representative: a damping ratio of about 0.1 of a
        bolster on its plate).
    plate_lateral_stiffness : float
        The bowl's rim holding the body on the bolster laterally, N/m, per plate: 1e8 (representative).
    nest_lateral_stiffness : float
        k_y, the lateral (shear) rate of a nest, N/m: 0.5 k, the value :mod:`raildyn.vehicles.three_piece`
        takes (representative: a loaded coil's lateral rate is a fraction of its vertical rate).
    track_stiffness : float
        Under each wheel, N/m: 3.1e7, ``TRACK_STIFFNESS`` (representative of older jointed track).
    track_damping : float
        Under each wheel, N·s/m: 1e5 (representative: a damping ratio of about 0.2 of a wheelset on
        the track).
    velocity_scale : float
        v_ε of the wedges' smooth friction law, m/s, in [1e-6, 1]: 0.02, a tenth or less of the nests'
        relative speeds when the car rocks. The runs barely feel it (at 28, 30 and 34 km/h the peak
        ΔQ/Q moves by under 2 % from 0.02 to 0.005 m/s), while the explicit march's step shrinks with
        it (0.94 ms at 0.02, 0.21 ms at 0.005; :func:`raildyn.vehicles.freight.rock_and_roll` takes 0.002).
    """

    car: VerticalFreightCar = field(default_factory=VerticalFreightCar)
    bolster_mass: float = 342.0
    bolster_roll_inertia: float = 342.0 * 2.6**2 / 12
    wheelset_mass: float = (4350.0 - 342.0) / 2
    wheelset_roll_inertia: float = 1500.0
    wheel_radius: float = 36 * INCH / 2
    half_rail_spacing: float = STANDARD_RAIL_SPACING / 2
    spring_plane_height: float = 0.6
    bolster_height: float = 0.65
    centre_plate_height: float = 0.70
    centre_plate_radius: float = 8 * INCH
    side_bearer_spacing: float = 25 * INCH
    side_bearer_gap: float = 0.25 * INCH
    centre_plate_stiffness: float = 5e8
    side_bearer_stiffness: float = 5e8
    contact_damping: float = 1e5
    plate_lateral_stiffness: float = 1e8
    nest_lateral_stiffness: float = 0.5 * VerticalFreightCar().nest_stiffness
    track_stiffness: float = TRACK_STIFFNESS
    track_damping: float = 1e5
    velocity_scale: float = 0.02

    def __post_init__(self):
        _checks.instance("car", self.car, VerticalFreightCar)
        for name in ("bolster_mass", "wheelset_mass"):
            _checks.plausible(name, getattr(self, name), "mass")
        for name in ("bolster_roll_inertia", "wheelset_roll_inertia"):
            _checks.plausible(name, getattr(self, name), "inertia")
        _checks.plausible("wheel_radius", self.wheel_radius, "wheel_radius")
        _checks.plausible("half_rail_spacing", self.half_rail_spacing, "half_gauge")
        for name in (
            "spring_plane_height",
            "bolster_height",
            "centre_plate_height",
            "centre_plate_radius",
            "side_bearer_spacing",
        ):
            _checks.plausible(name, getattr(self, name), "vehicle_length")
        _checks.scalar("side_bearer_gap", self.side_bearer_gap, low=0.0, high=0.05)
        for name in (
            "centre_plate_stiffness",
            "side_bearer_stiffness",
            "plate_lateral_stiffness",
            "nest_lateral_stiffness",
            "track_stiffness",
        ):
            _checks.positive(name, getattr(self, name))
        for name in ("contact_damping", "track_damping"):
            _checks.nonnegative(name, getattr(self, name))
        _checks.smoothing_speed("velocity_scale", _checks.scalar("velocity_scale", self.velocity_scale))
        order = ("spring_plane_height", "bolster_height", "centre_plate_height")
        heights = [getattr(self, n) for n in order] + [self.cg_height_above_rail]
        if not heights[0] < heights[1] < heights[2] < heights[3]:
            raise ValueError(
                f"the heights must rise from the rail: spring_plane_height < bolster_height < "
                f"centre_plate_height < the body's centre of gravity (spring plane + car.cg_height), got "
                f"{', '.join(f'{n} = {getattr(self, n)!r}' for n in order)} m and the centre of gravity at "
                f"{heights[3]!r} m"
            )
        d = self.car.semi_spring_spacing
        if not self.centre_plate_radius < self.side_bearer_spacing < d:
            raise ValueError(
                f"centre_plate_radius ({self.centre_plate_radius!r} m) must be less than side_bearer_spacing "
                f"({self.side_bearer_spacing!r} m), and that less than the nests' half-spacing "
                f"car.semi_spring_spacing ({d!r} m)"
            )

    def replace(self, **changes) -> RockingFreightCar:
        """A copy with some fields changed (checked as a new car).

        Parameters
        ----------
        **changes
            Field names and their new values.

        Returns
        -------
        RockingFreightCar
        """
        return replace(self, **changes)

    @property
    def cg_height_above_rail(self) -> float:
        """The body's centre of gravity above the rail, m: the spring plane plus ``car.cg_height``."""
        return self.spring_plane_height + self.car.cg_height

    @property
    def weight(self) -> float:
        """The whole car's weight, N: body, two bolsters and four wheelsets."""
        return GRAVITY * (self.car.body_mass + 2 * self.bolster_mass + 4 * self.wheelset_mass)

    @property
    def static_wheel_load(self) -> float:
        """The load on each wheel at rest on level track, N: an eighth of :attr:`weight`."""
        return self.weight / 8

    # ------------------------------------------------------------------------------------------ assembly

    def _tables(self):
        """Masses, coordinate map and element tables for the kernel; the watched elements' indices."""
        c = self.car
        g = GRAVITY
        hG, hp, hb, hs = (
            self.cg_height_above_rail,
            self.centre_plate_height,
            self.bolster_height,
            self.spring_plane_height,
        )
        l, d = c.semi_truck_spacing, c.semi_spring_spacing
        r, rp, yb, ar = (
            self.wheel_radius,
            self.centre_plate_radius,
            self.side_bearer_spacing,
            self.half_rail_spacing,
        )
        # bodies: 0 body (z θ φ y), 1-2 bolsters (z . φ y), 3-6 wheelsets (z . φ .) whose reference
        # point is the middle of the wheels' contact line, at the rail; 7 the ground. A coordinate a
        # body lacks is the kernel's extra entry 18, held at 0.
        dofs = np.full((8, 4), 18, dtype=np.int64)
        dofs[0] = [0, 1, 2, 3]
        for i in range(2):
            dofs[1 + i] = [4 + 3 * i, 18, 5 + 3 * i, 6 + 3 * i]
        for j in range(4):
            dofs[3 + j] = [10 + 2 * j, 18, 11 + 2 * j, 18]
        mb, mw = self.bolster_mass, self.wheelset_mass
        # The bowls hold the body along the track at the plates' height, so it pitches about that
        # level, its centre of gravity hG − hp above: I_θ + m (hG − hp)² (the plates' forces, acting at
        # that depth below the centre of gravity, give the weight's m g (hG − hp) against the pitch).
        mass = np.array(
            [
                c.body_mass,
                c.body_pitch_inertia + c.body_mass * (hG - hp) ** 2,
                c.body_roll_inertia,
                c.body_mass,
            ]
            + [mb, self.bolster_roll_inertia, mb] * 2
            # a wheelset rolls about its contact line, its centre r₀ above: I + m r₀²
            + [mw, self.wheelset_roll_inertia + mw * r * r] * 4
        )
        plate = c.body_mass * g / 2  # each plate's load
        nest = (plate + mb * g) / 2  # each nest's
        wheel = nest / 2 + mw * g / 2  # each wheel's
        rows_i, rows_f, names = [], [], []

        def add(name, kind, direction, A, pa, B, pb, k=0.0, cd=0.0, P0=0.0, F=0.0, B2=7, w=1.0, rail=8):
            names.append(name)
            rows_i.append([kind, direction, A, 7 if B < 0 else B, B2, rail])
            rows_f.append([*pa, *pb, w, k, cd, P0, F])

        # the wheels (watched 0-7): wheelset j, left then right, on its rails (inputs 2j, 2j + 1)
        for j in range(4):
            for s, y in enumerate((ar, -ar)):
                add(
                    f"wheel {j + 1}{'LR'[s]}",
                    1,
                    0,
                    3 + j,
                    (0.0, y, 0.0),
                    -1,
                    (0.0, 0.0, 0.0),
                    self.track_stiffness,
                    self.track_damping,
                    wheel,
                    rail=2 * j + s,
                )
        # the centre plates' edges (watched 8-11) and the side bearers (watched 12-15), truck by truck
        for i, x in enumerate((l, -l)):
            for s, y in enumerate((rp, -rp)):
                add(
                    f"plate {i + 1}{'LR'[s]}",
                    1,
                    0,
                    0,
                    (x, y, hp - hG),
                    1 + i,
                    (0.0, y, hp - hb),
                    self.centre_plate_stiffness,
                    self.contact_damping,
                    plate / 2,
                )
        for i, x in enumerate((l, -l)):
            for s, y in enumerate((yb, -yb)):
                k = self.side_bearer_stiffness
                add(
                    f"bearer {i + 1}{'LR'[s]}",
                    1,
                    0,
                    0,
                    (x, y, hp - hG),
                    1 + i,
                    (0.0, y, hp - hb),
                    k,
                    self.contact_damping,
                    -k * self.side_bearer_gap,
                )
        for i, x in enumerate((l, -l)):
            add(
                f"plate {i + 1} rim",
                0,
                1,
                0,
                (x, 0.0, hp - hG),
                1 + i,
                (0.0, 0.0, hp - hb),
                self.plate_lateral_stiffness,
            )
            for s, y in enumerate((d, -d)):
                # the nest: bolster end on the side frame, which stands on the truck's two wheelsets
                ends = dict(B=3 + 2 * i, B2=4 + 2 * i, w=0.5)
                add(
                    f"nest {i + 1}{'LR'[s]}",
                    1,
                    0,
                    1 + i,
                    (0.0, y, hs - hb),
                    ends["B"],
                    (0.0, y, hs),
                    c.nest_stiffness,
                    0.0,
                    nest,
                    F=c.wedge_friction,
                    **{k: ends[k] for k in ("B2", "w")},
                )
                add(
                    f"nest {i + 1}{'LR'[s]} lateral",
                    0,
                    1,
                    1 + i,
                    (0.0, y, hs - hb),
                    ends["B"],
                    (0.0, y, hs),
                    self.nest_lateral_stiffness,
                    **{k: ends[k] for k in ("B2", "w")},
                )
        # the weights, at each body's centre of gravity (a wheelset's r₀ above its reference point)
        add("weight body", 0, 0, 0, (0.0, 0.0, 0.0), -1, (0.0, 0.0, 0.0), P0=-c.body_mass * g)
        for i in range(2):
            add(f"weight bolster {i + 1}", 0, 0, 1 + i, (0.0, 0.0, 0.0), -1, (0.0, 0.0, 0.0), P0=-mb * g)
        for j in range(4):
            add(f"weight wheelset {j + 1}", 0, 0, 3 + j, (0.0, 0.0, r), -1, (0.0, 0.0, 0.0), P0=-mw * g)
        ei = np.array(rows_i, dtype=np.int64)
        ef = np.array(rows_f, dtype=float)
        return mass, dofs, ei, ef, tuple(names)

    def element_names(self) -> tuple:
        """The name of each force element, in the kernel's order: 8 wheels, 4 plate edges, 4 side
        bearers, then the rims, nests and weights.

        Returns
        -------
        tuple of str
        """
        return self._tables()[4]

    def forces(self, q, v, rail_heights=None, rail_rates=None):
        """The generalized forces (N, N·m) on the 18 coordinates and each element's force (N).

        Parameters
        ----------
        q, v : array_like, (18,)
            Coordinates from the static equilibrium (m, rad; ``LABELS``) and their rates.
        rail_heights, rail_rates : array_like, (8,), optional
            The left and right rail under each wheelset, leading first (m, m/s); level track by default.

        Returns
        -------
        generalized : ndarray, (18,)
        element : ndarray, (n_elements,)
            In the order of :meth:`~raildyn.vehicles.rocking.RockingFreightCar.element_names`; ≥ 0 for the
            contacts.
        """
        from raildyn.vehicles import _rocking_kernel as kernel

        q = _checks.array("q", q, shape=(18,))
        v = _checks.array("v", v, shape=(18,))
        z = np.zeros(8) if rail_heights is None else _checks.array("rail_heights", rail_heights, shape=(8,))
        zd = np.zeros(8) if rail_rates is None else _checks.array("rail_rates", rail_rates, shape=(8,))
        return kernel.evaluate(self, q, v, z, zd)[:2]

    # ------------------------------------------------------------------------------------- linearisation

    def linearized(self, *, engaged: bool = False) -> SystemMatrices:
        """M, C and K about the static equilibrium, every contact closed that is closed at rest.

        K = Σ k g gᵀ + Σ P₀ ∇²δ over the elements (g = ∇δ at rest; the preloads' second term is the
        geometric stiffness, the weight above a roll axis among it), C = Σ (c + F/v_ε) g gᵀ (the wedges
        sticking, the steepest slope of their smooth law); the inputs are the 8 rail heights. With
        ``engaged`` the side bearers count as closed too (the stiffest state, for the time step).

        Parameters
        ----------
        engaged : bool
            Count the open side bearers as closed.

        Returns
        -------
        SystemMatrices
            At a nominal 1 m/s (nothing in it depends on speed).
        """
        from raildyn.vehicles import rocking_analysis

        return rocking_analysis.linearize(self, _checks.flag("engaged", engaged))

    def natural_frequencies(self) -> np.ndarray:
        """The undamped natural frequencies of
        :meth:`~raildyn.vehicles.rocking.RockingFreightCar.linearized`, Hz, ascending.

        Returns
        -------
        ndarray, (18,)
        """
        lin = self.linearized()
        w2 = np.linalg.eigvals(np.linalg.solve(lin.M, lin.K)).real
        return np.sort(np.sqrt(np.maximum(w2, 0.0))) / (2 * np.pi)

    def roll_frequency(self) -> float:
        """The frequency of the car's rocking mode, Hz.

        Of the undamped modes of :meth:`~raildyn.vehicles.rocking.RockingFreightCar.linearized`, the one
        that a cross-level (left rails up, right
        rails down, by the same amount under every wheelset) rolls the body most through, quasi-statically:
        the largest |φ_r,body φ_rᵀ G_K w_x| / ω_r² over the mass-normalised modes φ_r. On a car whose
        nests are laterally flexible this is the lower of the two modes that couple the body's roll with
        its sway, a roll about a centre below the body.

        Returns
        -------
        float
            Hz, > 0.

        Raises
        ------
        ValueError
            If that mode is unstable (the car would topple).
        """
        lin = self.linearized()
        s = 1 / np.sqrt(np.diag(lin.M))
        A = s[:, None] * lin.K * s[None, :]
        w2, vec = np.linalg.eigh(0.5 * (A + A.T))
        modes = s[:, None] * vec  # mass-normalised
        cross = np.tile([0.5, -0.5], 4)
        with np.errstate(divide="ignore"):
            share = np.abs(modes[2] * (modes.T @ lin.GK @ cross) / np.abs(w2))
        k = int(np.argmax(share))
        if w2[k] <= 0:
            raise ValueError(f"the car's rocking mode is unstable (ω² = {w2[k]:.4g} 1/s²): it would topple")
        return float(np.sqrt(w2[k]) / (2 * np.pi))

    def roll_resonance_speed(self, rail_length: float = _track.RAIL_LENGTH) -> float:
        """V = f_roll L, the speed at which staggered joints drive the roll mode once per rail, m/s.

        Parameters
        ----------
        rail_length : float
            L, m, in [1, 150] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "rail_length").

        Returns
        -------
        float
            m/s.
        """
        L = _checks.plausible("rail_length", rail_length, "rail_length")
        return self.roll_frequency() * L

    # ----------------------------------------------------------------------------------- quasi-static roll

    def static_roll(self, roll_moment: float = 0.0, lateral_acceleration: float = 0.0) -> StaticRoll:
        """The car at rest on level track under a roll moment on its body (a steady wind), or a lateral
        acceleration of every part of it (a cant deficiency: the centrifugal force less the cant's share
        of the weight), or both.

        ``scipy.optimize.root`` on the force balance of
        :meth:`~raildyn.vehicles.rocking.RockingFreightCar.forces` (its Jacobian by central
        differences; wedges left out: they only hold whatever state the car reaches), the moment stepped
        up from zero in eighths (halved where a step fails, down to 1/1024) by Powell's method, each from
        the last balance or, where the body snaps
        over from its plate's edge onto a side bearer (no balance lies between), from the body turned
        through the bearers' gap; the balance is met to 1e-8 of the weight.

        Parameters
        ----------
        roll_moment : float
            N·m, left side up positive, within ± :attr:`weight` × a_r (beyond, the car overturns).
        lateral_acceleration : float
            a_y, m/s², towards the right positive (it leans the car onto the right rail, as a positive
            ``roll_moment`` does), within ± g.

        Returns
        -------
        StaticRoll

        Raises
        ------
        SolverError
            If the balance is not found (the car is about to overturn).
        """
        from raildyn.vehicles import rocking_analysis

        return rocking_analysis.static_roll(self, roll_moment, lateral_acceleration)

    def wheel_lift_acceleration(self) -> float:
        """The lateral acceleration of the whole car at which its first wheel unloads fully,
        quasi-statically, m/s².

        The least a_y beyond which no balance holds every wheel on its rail (bisection to 1e-7 g). On
        rigid trucks and track it is g a_r / h̄, h̄ the height of the car's centre of gravity; the
        flexible car leans over the loaded rail and lifts sooner. (A roll moment on the body alone
        cannot lift a wheel: the body tips off its plates over its side bearers first, at about
        m g y_b.)

        Returns
        -------
        float
            m/s², > 0 (towards the right: the left wheels lift).
        """
        from raildyn.vehicles import rocking_analysis

        return rocking_analysis.threshold(self, "wheel_lift")

    def plate_lift_moment(self) -> float:
        """The roll moment on the body at which a centre plate's edge unloads, quasi-statically, N·m.

        Returns
        -------
        float
            N·m, > 0.
        """
        from raildyn.vehicles import rocking_analysis

        return rocking_analysis.threshold(self, "plate_lift")
