"""Freight car on three-piece trucks: body bounce, pitch and roll on friction-damped spring nests (chapter 6).

The body (with its lading) stands on four spring nests, one on each side frame of
each truck; each nest carries friction wedges that rub with a nearly constant
force F against the relative motion (Coulomb, :func:`raildyn.suspension.coulomb_friction`).
A side frame is rigid and rides on its two wheels, so its height is the mean of
the rail heights under them. The body rolls about the spring plane, its centre
of gravity h above it, so that its weight lowers the roll stiffness by m g h.

Three coordinates: body z, θ (pitch, front up) and φ (roll, left side up).
Eight inputs: the left and right rail under each of the four axles.

* :meth:`FreightCar.linear` — the linear model (wedges replaced by an
  equivalent viscous damper, optional) for FRFs and spectra;
* :func:`rock_and_roll` — the nonlinear run over staggered jointed rail at many
  speeds at once: the steady roll amplitude against speed.
* :func:`wedge_energy_per_cycle` — energy a wedge dissipates over one cycle of
  imposed harmonic motion (4 F X for the ideal law).

Default parameters: a loaded 100-ton hopper car (the AAR 286 000 lb gross rail
load, 129.7 t) on 11.9 m rails; the body values are derived in the docstring of
:class:`FreightCar` from that load and a nest deflection, and are representative
rather than taken from one published table.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from raildyn import _checks
from raildyn import track as _track
from raildyn.integrators import rk4
from raildyn.suspension import coulomb_friction
from raildyn.vehicles.response import GRAVITY, LinearVehicle, _Assembler

LABELS = ("body z", "body θ", "body φ")


@dataclass(frozen=True)
class FreightCar:
    """A loaded hopper car on two three-piece trucks.

    Attributes
    ----------
    body_mass : float
        Body and lading, kg: the AAR 286 000 lb (129.7 t) gross rail load (the "286K standard",
        railroad.net) less two trucks of about 4.35 t: 121 000 kg.
    body_pitch_inertia : float
        kg·m² (a uniform 15 m body: m L²/12 ≈ 2.3 × 10⁶ kg·m²).
    body_roll_inertia : float
        About the centre of gravity, kg·m² (3.2 m wide, 3.5 m tall box: m(w² + h²)/12).
    cg_height : float
        Centre of gravity above the spring plane, m (2.1 m above rail, nests 0.6 m).
    semi_truck_spacing : float
        Half the distance between truck centres, m (40 ft 8 in centres, the value
        :mod:`raildyn.train.vehicles` takes for the loaded hopper).
    semi_truck_wheelbase : float
        Half a truck's wheelbase, m (1.73 m wheelbase).
    semi_spring_spacing : float
        Half the lateral distance between the nests, m.
    nest_stiffness : float
        Per nest, N/m: a static deflection of 0.06 m under a quarter of the body.
    wedge_friction : float
        Friction force of the wedges of one nest, N.
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

    def __post_init__(self):
        for name in self.__dataclass_fields__:
            value = getattr(self, name)
            if name in ("wedge_friction", "cg_height"):
                _checks.nonnegative(name, value)
            else:
                _checks.positive(name, value)
        if self.roll_stiffness <= 0:
            raise ValueError(
                f"cg_height {self.cg_height!r} m leaves no roll stiffness: 4 k b² = "
                f"{4 * self.nest_stiffness * self.semi_spring_spacing**2:.4g} N·m/rad <= m g h"
            )

    def with_(self, **changes) -> FreightCar:
        return replace(self, **changes)

    @property
    def roll_stiffness(self) -> float:
        """4 k b² − m g h, N·m/rad."""
        return (
            4 * self.nest_stiffness * self.semi_spring_spacing**2 - self.body_mass * GRAVITY * self.cg_height
        )

    @property
    def roll_inertia_spring_plane(self) -> float:
        """Roll inertia about the spring plane, I + m h², kg·m²."""
        return self.body_roll_inertia + self.body_mass * self.cg_height**2

    def natural_frequencies(self) -> dict:
        """Undamped bounce, pitch and roll frequencies on the springs alone (wedges sliding freely), Hz."""
        k, s = self.nest_stiffness, self.semi_truck_spacing
        return {
            "bounce": np.sqrt(4 * k / self.body_mass) / (2 * np.pi),
            "pitch": np.sqrt(4 * k * s**2 / self.body_pitch_inertia) / (2 * np.pi),
            "roll": np.sqrt(self.roll_stiffness / self.roll_inertia_spring_plane) / (2 * np.pi),
        }

    def roll_resonance_speed(self, rail_length: float = _track.RAIL_LENGTH) -> float:
        """Speed (m/s) at which staggered joints, one cross-level cycle per rail length, meet the roll
        frequency: V = f_roll L."""
        return self.natural_frequencies()["roll"] * _checks.positive("rail_length", rail_length)

    @property
    def axle_positions(self) -> np.ndarray:
        a, s = self.semi_truck_wheelbase, self.semi_truck_spacing
        return np.array([0.0, 2 * a, 2 * s, 2 * s + 2 * a])

    def nests(self) -> list[tuple[np.ndarray, np.ndarray]]:
        """Per nest (g, h): its deflection is g·q − h·w (w: 8 rail heights, axle by axle, left first)."""
        s, b = self.semi_truck_spacing, self.semi_spring_spacing
        out = []
        for truck, x in enumerate((s, -s)):
            for side, y in enumerate((b, -b)):
                h = np.zeros(8)
                h[[4 * truck + side, 4 * truck + 2 + side]] = 0.5  # mean of the two wheels on that rail
                out.append((np.array([1.0, x, y]), h))
        return out

    def linear(self, equivalent_damping: float = 0.0) -> LinearVehicle:
        """The linear model, each nest's wedges replaced by a viscous damper (N·s/m, default none)."""
        c = _checks.nonnegative("equivalent_damping", equivalent_damping)
        asm = _Assembler(LABELS, 8)
        asm.mass("body z", self.body_mass)
        asm.mass("body θ", self.body_pitch_inertia)
        asm.mass("body φ", self.roll_inertia_spring_plane)
        for g, h in self.nests():
            asm.element(dict(zip(LABELS, g, strict=True)), self.nest_stiffness, c, dict(enumerate(h)))
        asm.K[2, 2] -= self.body_mass * GRAVITY * self.cg_height
        positions = np.repeat(self.axle_positions, 2)
        rails = np.tile([1.0, -1.0], 4)
        weight = np.array([-GRAVITY * self.body_mass, 0.0, 0.0])
        return LinearVehicle(asm.M, asm.C, asm.K, asm.GK, asm.GC, LABELS, positions, rails, weight)


@dataclass(frozen=True)
class RockAndRoll:
    """Steady rocking of a freight car on staggered jointed rail.

    Attributes
    ----------
    speeds : ndarray
        m/s.
    roll_amplitude : ndarray
        Half the peak-to-peak roll over the last cycles, rad, one per speed.
    resonance_speed : float
        V = f_roll L of the car with free-sliding wedges (springs only), m/s.
    t : ndarray
        s.
    roll : ndarray, (n_speeds, n_t)
        Roll histories, rad.
    """

    speeds: np.ndarray
    roll_amplitude: np.ndarray
    resonance_speed: float
    t: np.ndarray
    roll: np.ndarray


def rock_and_roll(
    car: FreightCar,
    speeds,
    *,
    depth: float = 0.02,
    half_width: float = 1.0,
    rail_length: float = _track.RAIL_LENGTH,
    cycles: int = 40,
    dt: float = 0.005,
    velocity_scale: float = 0.002,
    progress: bool = False,
) -> RockAndRoll:
    """Roll of the car over staggered dipped joints at each speed, wedges in (nonlinear).

    All speeds are integrated together by :func:`raildyn.integrators.rk4` as one
    block-diagonal system; the friction is the smooth law F tanh(v/v_ε). The run
    lasts ``cycles`` rail lengths at the lowest speed; the amplitude is taken over
    its last quarter.
    """
    V = _checks.array("speeds", speeds, ndim=1, low=0.0, low_open=True)
    cycles = _checks.integer("cycles", cycles, low=4)
    dt = _checks.positive("dt", dt)
    eps = _checks.positive("velocity_scale", velocity_scale)
    L = _checks.positive("rail_length", rail_length)
    lin = car.linear()
    n, m = lin.n, V.size
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
    tail = t >= 0.75 * t[-1]
    amp = 0.5 * (roll[:, tail].max(axis=1) - roll[:, tail].min(axis=1))
    return RockAndRoll(V, amp, car.roll_resonance_speed(L), t, roll)


def wedge_energy_per_cycle(
    friction_force, amplitude, frequency, *, velocity_scale=None, n: int = 20_000
) -> float:
    """Energy (J) a wedge dissipates over one cycle of imposed motion X sin ωt: ∮ F(v) v dt.

    ``frequency`` in Hz; with the ideal law (no ``velocity_scale``) the result is 4 F X.
    """
    F = _checks.nonnegative("friction_force", friction_force)
    X = _checks.positive("amplitude", amplitude)
    w = 2 * np.pi * _checks.positive("frequency", frequency)
    n = _checks.integer("n", n, low=16)
    T = 2 * np.pi / w
    t = (np.arange(n) + 0.5) * T / n  # midpoints: the integrand is periodic
    v = X * w * np.cos(w * t)
    force = coulomb_friction(v, F, velocity_scale=velocity_scale)
    return float(np.sum(force * v) * T / n)
