"""Freight car on three-piece trucks: body bounce, pitch and roll on friction-damped spring nests (chapter 6).

The body (with its lading) stands on four spring nests, one on each side frame of
each truck; each nest carries friction wedges that rub with a nearly constant
force F against the relative motion (Coulomb, :func:`raildyn.suspension.coulomb_friction`).
A side frame is rigid and rides on its two wheels, so its height is the mean of
the rail heights under them. The body rolls about the spring plane, its centre
of gravity h above it, so that its weight lowers the roll stiffness by m g h.

Three coordinates: body z, θ (pitch, front up) and φ (roll, left side up).
Eight inputs: the left and right rail under each of the four axles.

* :meth:`VerticalFreightCar.linear_system` — the linear model (wedges replaced by an
  equivalent viscous damper, optional) for FRFs and spectra;
* :func:`rock_and_roll` — the nonlinear run over staggered jointed rail at many
  speeds at once: the steady roll amplitude against speed.
* the wedges' own force and energy per cycle are in :mod:`raildyn.vehicles.wedges`.

Two parameter sets:

* ``VerticalFreightCar()``: a loaded 100-ton hopper car (the AAR 286 000 lb gross rail
  load, 129.7 t); its body values are derived in the docstring of
  :class:`VerticalFreightCar` from that load and a nest deflection, representative
  rather than taken from one published table;
* :data:`GDU_ORE_CAR` (:func:`gdu_ore_car`): a loaded iron-ore gondola on
  AmstedMaxion Ride Control trucks, every value taken from the public model of
  L. Baruffaldi's doctoral thesis (UNICAMP), cited beside its constant.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks, _deprecated, plots
from raildyn import track as _track
from raildyn._tables import Tabular
from raildyn.constants import GRAVITY
from raildyn.errors import SolverError
from raildyn.integrators import rk4, stable_step
from raildyn.linear_model import Assembler, LinearModelBase, LinearSystem
from raildyn.suspension import coulomb_friction
from raildyn.vehicles._shared import _earlier_artists
from raildyn.vehicles.vertical import BodyFrequencies

# Moved to raildyn.vehicles.wedges (issue 33): imported here so that the old paths
# (raildyn.vehicles.freight.X) keep working for one issue; then this goes.
from raildyn.vehicles.wedges import WedgeFriction, wedge_energy_per_cycle, wedge_friction_force  # noqa: F401

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib

__all__ = [
    "GDU_ORE_CAR",
    "LABELS",
    "VerticalFreightCar",
    "RockAndRoll",
    "gdu_ore_car",
    "rock_and_roll",
]

# The old names of issue 33 (raildyn._deprecated.RENAMED): each warns and gives the new object;
# they go after one issue.
__getattr__ = _deprecated.module_getattr(__name__, globals())

LABELS = ("body z", "body θ", "body φ")

#: The longest run of :func:`rock_and_roll`: steps × speeds (each costs about 1.1 kB of tabulated track).
_MAX_STEP_SPEEDS = 5e5


@dataclass(frozen=True)
class VerticalFreightCar(LinearModelBase):
    """A loaded hopper car on two three-piece trucks.

    Every field is finite; masses, inertias, lengths and the nest stiffness are > 0,
    ``cg_height``, ``wedge_friction`` and ``equivalent_damping`` ≥ 0. The truck's
    semi-wheelbase is less than the semi truck spacing, and the roll stiffness
    4 k d² − m g h is > 0, d the semi spring spacing (else the body topples). The linear
    model's equations are derived from the energies in
    :func:`raildyn.derivations.vertical.freight_rock_and_roll` (notebook 06, section 6.4).

    The body pitches about a transverse axis in the spring plane, as it rolls about a longitudinal
    one there: the trucks hold the body at its centre plates, along the track as across it, so
    that it turns about that plane and not about its centre of gravity, h above it. Both motions
    therefore lift the centre of gravity over the axis, and the weight lowers both stiffnesses by
    m g h: pitch 4 k l² − m g h (l the semi truck spacing), roll 4 k d² − m g h; both inertias are
    taken about the spring plane, I + m h².

    Attributes
    ----------
    body_mass : float
        Body and lading, kg: the AAR 286 000 lb (129.7 t) gross rail load (the "286K standard",
        railroad.net) less two trucks of about 4.35 t: 121 000 kg; in [10, 1e6]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass").
    body_pitch_inertia : float
        kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "inertia") (a uniform 15 m body: m
        L²/12 ≈ 2.3 × 10⁶ kg·m²).
    body_roll_inertia : float
        About the centre of gravity, kg·m², in [1, 5e8] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "inertia") (3.2 m wide, 3.5 m tall box: m(w² + h²)/12).
    cg_height : float
        Centre of gravity above the spring plane, m, in [0, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length") (2.1 m above rail, nests 0.6 m).
    semi_truck_spacing : float
        l, half the distance between truck centres, m, in [0.01, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length") (40 ft 8 in centres, the value
        :mod:`raildyn.train.vehicles` takes for the loaded hopper).
    semi_truck_wheelbase : float
        b, half a truck's wheelbase, m, in [0.01, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "vehicle_length") (1.73 m wheelbase).
    semi_spring_spacing : float
        d, half the lateral distance between the nests (the side-frame spacing), m, in [0.01, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length").
    nest_stiffness : float
        Per nest, N/m: a static deflection of 0.06 m under a quarter of the body.
    wedge_friction : float
        Friction force of the wedges of one nest, N.
    equivalent_damping : float
        The viscous damper (N·s/m) that stands for each nest's wedges in the linear
        model (:meth:`linear_system`); default none, the wedges sliding freely.
    """

    body_mass: float = 121_000.0
    body_pitch_inertia: float = 121_000.0 * 15.0**2 / 12
    body_roll_inertia: float = 121_000.0 * (3.2**2 + 3.5**2) / 12
    cg_height: float = 1.5
    semi_truck_spacing: float = (40 + 8 / 12) * 0.3048 / 2
    semi_truck_wheelbase: float = 0.865
    semi_spring_spacing: float = 1.0
    nest_stiffness: float = 121_000.0 * GRAVITY / 4 / 0.06
    wedge_friction: float = 6.0e3
    equivalent_damping: float = 0.0

    def __post_init__(self):
        for name in self.__dataclass_fields__:
            value = getattr(self, name)
            if name in ("wedge_friction", "cg_height", "equivalent_damping"):
                _checks.nonnegative(name, value)
            else:
                _checks.positive(name, value)
        _checks.plausible("body_mass", self.body_mass, "mass")
        _checks.plausible_fields(self, "inertia", ("body_pitch_inertia", "body_roll_inertia"))
        _checks.plausible("cg_height", self.cg_height, "vehicle_length", low=0.0)
        lengths = ("semi_truck_spacing", "semi_truck_wheelbase", "semi_spring_spacing")
        _checks.plausible_fields(self, "vehicle_length", lengths)
        if self.semi_truck_wheelbase >= self.semi_truck_spacing:
            raise ValueError(
                f"semi_truck_wheelbase must be less than semi_truck_spacing ({self.semi_truck_spacing!r} m) "
                f"so that the trucks' axles do not cross, got {self.semi_truck_wheelbase!r}"
            )
        if not 0 < self.roll_stiffness < np.inf:
            raise ValueError(
                f"nest_stiffness {self.nest_stiffness!r} N/m at semi_spring_spacing "
                f"{self.semi_spring_spacing!r} m against body_mass {self.body_mass!r} kg at cg_height "
                f"{self.cg_height!r} m give a roll stiffness 4 k b² − m g h = {self.roll_stiffness:.4g} "
                "N·m/rad; it must be finite and > 0 (else the body topples)"
            )

    @property
    def roll_stiffness(self) -> float:
        """4 k d² − m g h, N·m/rad (d the semi spring spacing, h the centre of gravity's height)."""
        b = self.semi_spring_spacing
        return 4 * self.nest_stiffness * b * b - self.body_mass * GRAVITY * self.cg_height

    @property
    def roll_inertia_spring_plane(self) -> float:
        """Roll inertia about the spring plane, I + m h², kg·m²."""
        return self.body_roll_inertia + self.body_mass * self.cg_height * self.cg_height

    @property
    def pitch_stiffness(self) -> float:
        """4 k l² − m g h, N·m/rad (l the semi truck spacing, h the centre of gravity's height)."""
        s = self.semi_truck_spacing
        return 4 * self.nest_stiffness * s * s - self.body_mass * GRAVITY * self.cg_height

    @property
    def pitch_inertia_spring_plane(self) -> float:
        """Pitch inertia about the transverse axis in the spring plane, I + m h², kg·m²."""
        return self.body_pitch_inertia + self.body_mass * self.cg_height * self.cg_height

    def natural_frequencies(self) -> BodyFrequencies:
        """Undamped bounce, pitch and roll frequencies on the springs alone (wedges sliding freely).

        Returns
        -------
        BodyFrequencies
        """
        k = self.nest_stiffness
        return BodyFrequencies(
            bounce_hz=float(np.sqrt(4 * k / self.body_mass) / (2 * np.pi)),
            pitch_hz=float(np.sqrt(self.pitch_stiffness / self.pitch_inertia_spring_plane) / (2 * np.pi)),
            roll_hz=float(np.sqrt(self.roll_stiffness / self.roll_inertia_spring_plane) / (2 * np.pi)),
        )

    def roll_resonance_speed(self, rail_length: float = _track.RAIL_LENGTH) -> float:
        """Speed at which staggered joints, one cross-level cycle per rail length, meet the roll
        frequency: V = f_roll L.

        Parameters
        ----------
        rail_length : float
            L, m, in [1, 150] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "rail_length").

        Returns
        -------
        float
            V, m/s.
        """
        L = _checks.plausible("rail_length", rail_length, "rail_length")
        return self.natural_frequencies().roll_hz * L

    def roll_input_factor(self, rail_length: float = _track.RAIL_LENGTH) -> float:
        """|cos(2π l/L)|: the share of a cross-level wave of length L that the two trucks, 2l apart,
        pass on to the body's roll (their inputs cancel when 2s = L/2).

        Parameters
        ----------
        rail_length : float
            L, m, in [1, 150] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "rail_length").

        Returns
        -------
        float
            In [0, 1].
        """
        L = _checks.plausible("rail_length", rail_length, "rail_length")
        return float(abs(np.cos(2 * np.pi * self.semi_truck_spacing / L)))

    @property
    def axle_positions(self) -> np.ndarray:
        a, s = self.semi_truck_wheelbase, self.semi_truck_spacing
        return np.array([0.0, 2 * a, 2 * s, 2 * s + 2 * a])

    def nests(self) -> list[tuple[np.ndarray, np.ndarray]]:
        """The geometry of each spring nest.

        Returns
        -------
        list of (ndarray (3,), ndarray (8,))
            Per nest (g, h): its deflection is g·q − h·w (w: 8 rail heights, axle by
            axle, left first), front truck first, left side first.
        """
        s, b = self.semi_truck_spacing, self.semi_spring_spacing
        out = []
        for truck, x in enumerate((s, -s)):
            for side, y in enumerate((b, -b)):
                h = np.zeros(8)
                h[[4 * truck + side, 4 * truck + 2 + side]] = 0.5  # mean of the two wheels on that rail
                out.append((np.array([1.0, x, y]), h))
        return out

    def linear_system(self) -> LinearSystem:
        """The linear model, each nest's wedges replaced by the viscous ``equivalent_damping``.

        Eight inputs: the left and right rail heights under each of the four axles.

        Returns
        -------
        LinearSystem
        """
        c = self.equivalent_damping
        asm = Assembler(LABELS, 8)
        asm.mass("body z", self.body_mass)
        asm.mass("body θ", self.pitch_inertia_spring_plane)
        asm.mass("body φ", self.roll_inertia_spring_plane)
        for g, h in self.nests():
            asm.element(dict(zip(LABELS, g, strict=True)), self.nest_stiffness, c, dict(enumerate(h)))
        # The weight h above the spring plane, about which the body pitches and rolls (class docstring).
        asm.block(["body θ", "body φ"], K=-self.body_mass * GRAVITY * self.cg_height * np.eye(2))
        positions = np.repeat(self.axle_positions, 2)
        rails = np.tile([1.0, -1.0], 4)
        weight = np.array([-GRAVITY * self.body_mass, 0.0, 0.0])
        return asm.system(input_positions=positions, input_rails=rails, gravity_load=weight)


@dataclass(frozen=True)
class RockAndRoll(Tabular):
    """Steady rocking of a freight car on staggered jointed rail.

    Attributes
    ----------
    speeds : ndarray, (n_speeds,)
        m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`], not empty.
    roll_amplitude : ndarray, (n_speeds,)
        Half the peak-to-peak roll over the last cycles, rad, ≥ 0, one per speed.
    resonance_speed : float
        V = f_roll L of the car with free-sliding wedges (springs only), m/s, > 0.
    t : ndarray, (n_t,)
        s, strictly increasing.
    roll : ndarray, (n_speeds, n_t)
        Roll histories, rad, of either sign.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units;
    # the roll histories (a row per speed along ``t``) are no columns.
    _columns = (("speeds", "m/s"), ("roll_amplitude", "rad"))
    _scalars = (("resonance_speed", "m/s"),)

    speeds: np.ndarray
    roll_amplitude: np.ndarray
    resonance_speed: float
    t: np.ndarray
    roll: np.ndarray

    def __post_init__(self):
        V = _checks.speeds("speeds", self.speeds)
        t = _checks.time_grid("t", self.t)
        object.__setattr__(self, "speeds", V)
        object.__setattr__(self, "roll_amplitude", _checks.array("roll_amplitude", self.roll_amplitude,
                                                                 shape=V.shape, low=0.0))  # fmt: skip
        object.__setattr__(self, "resonance_speed", _checks.speed("resonance_speed", self.resonance_speed))
        object.__setattr__(self, "t", t)
        object.__setattr__(self, "roll", _checks.array("roll", self.roll, shape=(V.size, t.size)))

    def plot(
        self, ax=None, *, artists: dict | None = None, label: str | None = None, color=None, resonance=True
    ) -> dict:
        """Draw the roll amplitude (deg) against speed (km/h), with the springs' roll resonance.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default. Ignored when ``artists`` is given.
        artists : dict, optional
            The artists an earlier call returned: they are moved to this result.
        label : str, optional
            Legend entry of the curve.
        color : optional
            Curve colour; the house palette's first by default.
        resonance : bool
            Mark the resonance speed V = f_φ L with a dotted line (ignored when ``artists`` is given:
            the line is moved if it was drawn).

        Returns
        -------
        dict
            The artists: ``curve`` and, with ``resonance``, ``resonance``.
        """
        import matplotlib

        resonance = _checks.flag("resonance", resonance)
        kmh = 3.6 * self.speeds
        amplitude = np.degrees(self.roll_amplitude)
        if artists is not None:
            _earlier_artists(artists, ("curve",))["curve"].set_data(kmh, amplitude)
            if "resonance" in artists:
                artists["resonance"].set_xdata([3.6 * self.resonance_speed] * 2)
            return artists
        ax = plots.axes_or_new(ax)
        out = {}
        with matplotlib.rc_context(plots.STYLE):
            (out["curve"],) = ax.plot(kmh, amplitude, "o-", ms=3, label=label,
                                      color=plots.COLORS[0] if color is None else color)  # fmt: skip
            if resonance:
                out["resonance"] = ax.axvline(3.6 * self.resonance_speed, color="k", ls=":", lw=1,
                                              label="roll resonance $f_\\phi L$")  # fmt: skip
            ax.set_xlabel("speed (km/h)")
            ax.set_ylabel("roll amplitude (deg)")
        return out


def rock_and_roll(
    car: VerticalFreightCar,
    speeds,
    *,
    depth: float = 0.02,
    half_width: float = 1.0,
    rail_length: float = _track.RAIL_LENGTH,
    cycles: int = 40,
    dt: float | None = None,
    velocity_scale: float = 0.002,
    progress: bool = False,
) -> RockAndRoll:
    """Roll of the car over staggered dipped joints at each speed, wedges in (nonlinear).

    All speeds are integrated together by :func:`raildyn.integrators.rk4` as one
    block-diagonal system; the friction is the smooth law F tanh(v/v_ε). The run
    lasts ``cycles`` rail lengths at the lowest speed; the amplitude is taken over
    its last quarter.

    RK4 is explicit: it is stable only while every eigenvalue s_r of the car with its
    stiffest wedge law — sticking, the tanh's slope F/v_ε as a viscous damper —
    keeps |1 + z + z²/2 + z³/6 + z⁴/24| ≤ 1 at z = s_r Δt. A larger ``dt`` is
    refused before the run with the largest stable step in the message; a run
    whose roll still becomes non-finite raises :class:`raildyn.errors.SolverError`.

    The run is bounded: its steps times its speeds may not exceed 5 × 10⁵ (the track is
    tabulated for every speed at every half step, about 1.1 kB per step and speed, so the
    bound keeps a run within about 0.6 GB and a minute or so); a longer run is refused
    before it starts.

    Parameters
    ----------
    car : VerticalFreightCar
    speeds : array_like
        m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`], not empty.
    depth, half_width : float
        Dip of each joint (m, in [0, 0.1], :data:`~raildyn.constants.PLAUSIBLE_RANGES` "irregularity") and
        its half-length along
        the rail (m, in [0.001, L/2], "track_length").
    rail_length : float
        L, m, in [1, 150] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "rail_length").
    cycles : int
        Rail lengths run at the lowest speed (≥ 4).
    dt : float, optional
        Time step, s (> 0, at most the stability limit below). Default: 8 ms, or 0.9 of the
        stability limit (:func:`raildyn.integrators.stable_step`) where that is smaller (stiff wedges).
    velocity_scale : float
        v_ε of the smooth friction law, m/s, in [1e-6, 1] (a smoothing of the sign of the sliding
        velocity, far below it).
    progress : bool
        Show a progress bar.

    Returns
    -------
    RockAndRoll
    """
    _checks.instance("car", car, VerticalFreightCar)
    V = _checks.speeds("speeds", speeds)
    cycles = _checks.integer("cycles", cycles, low=4)
    eps = float(_checks.smoothing_speed("velocity_scale", velocity_scale).max())
    _checks.scalar("velocity_scale", velocity_scale)  # one number
    L = _checks.plausible("rail_length", rail_length, "rail_length")
    _checks.plausible("depth", depth, "irregularity")
    _checks.plausible("half_width", half_width, "track_length", high=L / 2)
    progress = _checks.flag("progress", progress)
    sticking = car.replace(equivalent_damping=car.wedge_friction / eps).matrices(1.0)
    limit = stable_step("rk4", sticking.M, sticking.C, sticking.K)
    dt = min(0.008, 0.9 * limit) if dt is None else _checks.positive("dt", dt)
    if dt > limit:
        raise ValueError(
            f"dt must be at most {limit:.4g} s for RK4 to stay stable on this car with sticking wedges "
            f"(slope F/v_ε = {car.wedge_friction / eps:.4g} N·s/m per nest), got {dt!r}"
        )
    steps = cycles * L / V.min() / dt
    if steps * V.size > _MAX_STEP_SPEEDS:
        raise ValueError(
            f"the run of cycles = {cycles} rail lengths (rail_length = {L!r} m) at the lowest of the "
            f"speeds, {V.min()!r} m/s, in steps of dt = {dt:.4g} s, for {V.size} speeds, would take "
            f"{steps:.3g} steps × speeds; at most {_MAX_STEP_SPEEDS:.0e} (about 0.6 GB of tabulated track)"
        )
    lin = car.linear_system()
    n, m = lin.size, V.size
    M = np.kron(np.eye(m), lin.M)
    K = np.kron(np.eye(m), lin.K)
    C = np.zeros_like(M)
    G = np.array([g for g, _ in car.nests()])  # (4, 3)
    t = np.arange(0.0, cycles * L / V.min() + dt / 2, dt)
    x_axle = lin.input_positions

    # Every time RK4 asks for lies on the half-step grid: tabulate the rail heights and rates there once.
    half = np.arange(2 * t.size + 1) * (dt / 2)
    pos = V[None, :, None] * half[:, None, None] - x_axle[None, None, :]  # (n_half, m, 8)
    left_rail = lin.input_rails > 0
    profile = _track.jointed_track(pos, depth, half_width, rail_length=L, arrangement="staggered")
    slope = _track.jointed_track(pos, depth, half_width, rail_length=L, arrangement="staggered", derivative=1)
    w_tab = np.where(left_rail, profile.left, profile.right)
    wdot_tab = V[None, :, None] * np.where(left_rail, slope.left, slope.right)
    H = np.array([h for _, h in car.nests()])  # (4, 8)
    track_force = w_tab @ lin.GK.T  # (n_half, m, 3)
    frame_rate = wdot_tab @ H.T  # (n_half, m, 4): side-frame velocity at each nest

    def force(tk, x, v):
        k = int(round(tk / (dt / 2)))
        rel = v.reshape(m, n) @ G.T - frame_rate[k]  # the wedges rub at the nests' relative velocity
        friction = coulomb_friction(rel, car.wedge_friction, velocity_scale=eps)
        return (track_force[k] - friction @ G).reshape(-1)

    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=1, desc="rock and roll", leave=False)
    run = rk4(M, C, K, t, np.zeros(n * m), np.zeros(n * m), force)
    if progress:
        bar.update(1)
        bar.close()
    roll = run.x[2::n]
    if not np.all(np.isfinite(roll)):
        step = int(np.argmin(np.all(np.isfinite(roll), axis=0)))
        raise SolverError("the roll became non-finite: RK4 went unstable", step=step, time=float(t[step]))
    tail = t >= 0.75 * t[-1]
    amp = 0.5 * (roll[:, tail].max(axis=1) - roll[:, tail].min(axis=1))
    return RockAndRoll(V, amp, car.roll_resonance_speed(L), t, roll)


# The loaded Vale GDU iron-ore gondola (1.6 m gauge) on AmstedMaxion Ride Control trucks, from the
# MBSim model of L. Baruffaldi's doctoral thesis (UNICAMP): https://github.com/leo-bart/doutorado-repo,
# commit 247ba5c, files input.in ("SYSTEM_NAME=GDU_Vale_Freq_Bounce") [in], src/system.cpp [sys] and
# src/ridecontroltruck.cpp [truck]; the truck is "based on AmstedMaxion SS Ride Control 7 in x 12 in,
# Part no. 3013-40754-00-1" [include/ridecontroltruck.h, commit 94aaff0].
_GDU_BODY_MASS = 116200.0  # [in: BOX_MASS]
# [in] gives BOX_Ixx = BOX_Iyy = 640 000 and BOX_Izz = 130 000 kg·m² in a frame with x along the car,
# y up and z across [sys, truck], and its planar model turns the body about z. Read literally, that
# is a pitch inertia of 1.3e5 and a roll inertia of 6.4e5 kg·m²: radii of gyration of 1.06 m along
# an 8.75 m body and 2.35 m across a 3.11 m one. A uniform box of the body's size [sys: setLength
# 8.747, setWidth 3.113, setHeight 1.908] has a roll inertia m(w² + h²)/12 = 1.29e5 kg·m², so we take
# 130 000 as the roll and 640 000 as the pitch inertia (tests/test_freight.py checks this reading
# against the same author's explicitly labelled set in leo-bart/mbsim-wagons, input2.in).
_GDU_ROLL_INERTIA = 130000.0
_GDU_PITCH_INERTIA = 640000.0
_GDU_TRUCK_CENTRES = 5.410  # [in: CAR_WHEEL_BASE]
_GDU_WHEELBASE = 1.828  # [in: TRUCK_WHEEL_BASE]
_GDU_CG_ABOVE_RAIL = 2.152  # height of the body's reference frame above the rail [sys]
_GDU_SPRING_RATE = 527833.0  # one coil of a nest, N/m [truck: bolsterSpringStiffness]
_GDU_SPRINGS_PER_NEST = 9  # a 3 × 3 grid at 0.143 m pitch [truck: LBS11 … LBS91]
_GDU_NEST_SPACING = 2.278  # lateral distance between the side frames, m [truck: sideFrameLateralDistance]
_GDU_SPRING_SEAT = 0.238  # spring seat above the rail, m [truck: sideFrameSpringBedBottomHeight]
_GDU_SPRING_FREE = 0.327  # m [truck: bolsterSpringFreeLength]
_GDU_SPRING_DESIGN = 0.267  # loaded, m [truck: bolsterSpringDesignLength]
_GDU_WEDGE_SPRING = 344000.0  # N/m [truck: wedgeSpringStiffness]
_GDU_WEDGE_FREE = 0.1857  # m [truck: wedgeSpringFreeLength]
_GDU_WEDGE_DESIGN = 0.1381  # m [truck: wedgeSpringDesignLength]
_GDU_WEDGE_ANGLE = np.radians(37.5)  # bolster slope from the vertical; column face vertical [truck]
_GDU_WEDGE_FRICTION = 0.10  # [in: FRICTION_COEFF]
_GDU_WEDGES_PER_NEST = 2  # one ahead of and one behind the bolster on each side frame [truck: WRL, WFL]


def gdu_ore_car() -> VerticalFreightCar:
    """A loaded iron-ore gondola on Ride Control trucks, from a public thesis model, as a
    :class:`VerticalFreightCar`.

    The Vale GDU ore car (1.6 m gauge) on AmstedMaxion Ride Control
    (constant-damping) trucks, as L. Baruffaldi modelled it in MBSim for his
    doctoral thesis at UNICAMP (https://github.com/leo-bart/doutorado-repo,
    commit 247ba5c; each value is cited beside its constant in this module).

    * Body with lading 116.2 t; roll 1.3 × 10⁵ and pitch 6.4 × 10⁵ kg·m² (the
      source's axis labels are read as explained beside the constants); centre
      of gravity 2.152 m above the rail.
    * Truck centres 5.410 m apart, wheelbase 1.828 m.
    * Each nest: nine coils of 527.8 kN/m (4.75 MN/m), the nests 2.278 m apart;
      the springs stand on a seat 0.238 m above the rail and are 0.267 m long
      under load, so the spring plane is 0.505 m above the rail and the centre
      of gravity 1.647 m above it.
    * Two wedges per nest on a 37.5° slope, spring 344 kN/m compressed from
      0.1857 to 0.1381 m (16.4 kN), μ = 0.10: by :func:`~raildyn.vehicles.wedges.wedge_friction_force`,
      4.91 kN per nest with the bolster going down and 3.78 kN going up;
      raildyn's symmetric law takes their mean, 4.34 kN.

    Left out: the bolsters and wedges (0.4 t a truck) that ride on the springs
    with the body, and the 1 % of roll stiffness the width of each 3 × 3 nest
    adds about its own centre.

    Returns
    -------
    VerticalFreightCar
    """
    nest = _GDU_SPRINGS_PER_NEST * _GDU_SPRING_RATE
    preload = _GDU_WEDGE_SPRING * (_GDU_WEDGE_FREE - _GDU_WEDGE_DESIGN)
    wedges = wedge_friction_force(preload, _GDU_WEDGE_ANGLE, _GDU_WEDGE_FRICTION, wedges=_GDU_WEDGES_PER_NEST)
    return VerticalFreightCar(
        body_mass=_GDU_BODY_MASS,
        body_pitch_inertia=_GDU_PITCH_INERTIA,
        body_roll_inertia=_GDU_ROLL_INERTIA,
        cg_height=_GDU_CG_ABOVE_RAIL - (_GDU_SPRING_SEAT + _GDU_SPRING_DESIGN),
        semi_truck_spacing=_GDU_TRUCK_CENTRES / 2,
        semi_truck_wheelbase=_GDU_WHEELBASE / 2,
        semi_spring_spacing=_GDU_NEST_SPACING / 2,
        nest_stiffness=nest,
        wedge_friction=wedges.mean,
    )


GDU_ORE_CAR = gdu_ore_car()
"""The loaded Vale GDU ore gondola on Ride Control trucks (:func:`gdu_ore_car`)."""
