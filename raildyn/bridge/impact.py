"""Wheels rolling on a flexible track: the forces at a dipped joint, a wheel flat, rough rails (ch. 3, 10).

Everywhere else in raildyn a wheel follows the rail. Here it does not: each wheel rests on the rail
through the Hertz spring of chapter 4, F = C_H u_N^{3/2} while it presses on the rail (u_N > 0) and
F = 0 when it has lifted off, and the rail is the :class:`~raildyn.bridge.sleepers.DiscreteTrack`,
bending between sleepers on pads and ballast. Above the contacts stands a linear block
(:class:`~raildyn.bridge.wheels.WheelBlock`: one wheel's unsprung mass, with a share of the vehicle
on a primary spring, or a whole vertical vehicle on its wheels), with coordinates x up positive from
its static state, mass, damping and stiffness M_b, C_b, K_b. With w(x) the rail's deflection (down
positive), r_s(x) how far the running surface dips below its line (a dipped joint; a flat on the
wheel reads as a dip that comes round once a revolution), Q₀ᵢ each wheel's static load and wheel i at
xᵢ = x₀ + Vt − dᵢ:

    M_b ẍ + C_b ẋ + K_b x = Σᵢ eᵢ (Fᵢ − Q₀ᵢ),    M ü + C u̇ + K u = Σᵢ N(xᵢ)ᵀ Fᵢ,
    Fᵢ = C_H max(z₀ᵢ − x_{cᵢ} − N(xᵢ) u − r_s(xᵢ), 0)^{3/2},

N(x) the rail element's shape functions at a wheel, eᵢ the unit vector of wheel i's coordinate cᵢ and
z₀ᵢ where it stands at rest. A wheel running into a dip of total angle 2α = α₁ + α₂ meets a sudden
change 2αV of the rail's vertical velocity: first the wheel and the rail beneath it bounce against
each other on the stiff Hertz spring (the *P1* force, within a millisecond or two of the joint), then
wheel and track move together on the track's stiffness (the *P2* force, a few milliseconds later),
which loads sleepers and ballast (Jenkins, Stephenson, Clayton, Morland & Lyon 1974, *Railway
Engineering Journal* 3(1), 2–16). Their estimate of P2, :func:`jenkins_p2`, comes from that second
picture.

:func:`wheel_on_track` marches the equations (Newmark's average-acceleration rule, compiled; or, as
the reference for the march's answer and speed, scipy's RK45 on the same equations) and returns a
:class:`WheelOnTrack` with each wheel's contact force, P1 and P2, contact loss, the rail-seat (pad) and
ballast forces, and the energy balance. :func:`contact_force_spectrum` gives the linear answer for
small roughness from the receptances.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.bridge import _impact_reference
from raildyn.bridge.defects import MAX_DIP_ANGLE, DippedJoint, Roughness, WheelFlat
from raildyn.bridge.sleepers import DiscreteTrack, _shape
from raildyn.bridge.wheels import VehicleWheels, Wheel, WheelBlock
from raildyn.errors import SolverError

# Imported where used, to keep this module's import cheap (tests/test_imports.py): raildyn.bridge._band,
# raildyn.bridge._impact_kernel

__all__ = [
    "WheelOnTrack",
    "contact_compliance",
    "contact_force_spectrum",
    "jenkins_p2",
    "lumped_track",
    "wheel_on_track",
]


@dataclass(frozen=True, eq=False)
class WheelOnTrack(Tabular):
    """A run of wheels over a discrete track (:func:`wheel_on_track`): one row per record, one column
    per wheel (the leading wheel first).

    Attributes
    ----------
    t : ndarray, (k,)
        s, from 0.
    x : ndarray, (k,)
        The leading wheel's position on the track, m (for standing wheels, where the running surface
        under the leading one came from).
    offsets : ndarray, (w,)
        Each wheel's distance behind the leading one, m.
    contact_force : ndarray, (k, w)
        F, N (≥ 0; 0 where a wheel has lifted off).
    wheel : ndarray, (k, w)
        z_w, m (down positive, from where the wheel stands unloaded on an undeflected rail).
    rail : ndarray, (k, w)
        w, the rail's deflection under each wheel, m (down positive).
    irregularity : ndarray, (k, w)
        r_s met by each wheel, m (down positive).
    sleeper_positions : ndarray, (j,)
        x of each sleeper, m.
    pad_forces, ballast_forces : ndarray, (k, j)
        The rail-seat force on each sleeper through its pad, and the ballast's force under it, N
        (down positive: the load they carry).
    energy : ndarray, (k,)
        The whole system's energy, J (kinetic and strain energy, less the work the static loads could
        do), from which :attr:`balance` follows.
    work : ndarray, (k,)
        Work fed in by the rolling since t = 0, J: −Σ ∫ F V (∂w/∂x + dr_s/dx) dt.
    dissipated : ndarray, (k,)
        Work done on the dampers since t = 0, J.
    static_loads : ndarray, (w,)
        Q₀ of each wheel, N.
    speed : float
        V, m/s.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("t", "s"), ("x", "m"), ("contact_force", "N"), ("wheel", "m"), ("rail", "m"),
        ("irregularity", "m"), ("pad_forces", "N"), ("ballast_forces", "N"), ("energy", "J"), ("work", "J"),
        ("dissipated", "J"),
    )  # fmt: skip
    _scalars = (("speed", "m/s"),)

    t: np.ndarray
    x: np.ndarray
    offsets: np.ndarray
    contact_force: np.ndarray
    wheel: np.ndarray
    rail: np.ndarray
    irregularity: np.ndarray
    sleeper_positions: np.ndarray
    pad_forces: np.ndarray
    ballast_forces: np.ndarray
    energy: np.ndarray
    work: np.ndarray
    dissipated: np.ndarray
    static_loads: np.ndarray
    speed: float

    def __post_init__(self):
        k = _checks.array("t", self.t, ndim=1, allow_empty=False).size
        w = _checks.array("offsets", self.offsets, ndim=1, allow_empty=False, low=0.0).size
        j = _checks.array("sleeper_positions", self.sleeper_positions, ndim=1, allow_empty=False).size
        for name in ("x", "energy", "work", "dissipated"):
            _checks.array(name, getattr(self, name), shape=(k,))
        for name in ("wheel", "rail", "irregularity"):
            _checks.array(name, getattr(self, name), shape=(k, w))
        _checks.array("contact_force", self.contact_force, shape=(k, w), low=0.0)
        for name in ("pad_forces", "ballast_forces"):
            _checks.array(name, getattr(self, name), shape=(k, j))
        _checks.plausible_array("static_loads", self.static_loads, "wheel_load", shape=(w,))
        _checks.speed("speed", self.speed, high=150.0)

    @property
    def lost_contact(self) -> np.ndarray:
        """True where a wheel is off the rail (F = 0), (k, w)."""
        return self.contact_force <= 0.0

    @property
    def contact_loss_time(self) -> np.ndarray:
        """How long each wheel was off the rail in all, s, (w,)."""
        dt = self.t[1] - self.t[0] if self.t.size > 1 else 0.0
        return np.count_nonzero(self.lost_contact, axis=0) * dt

    @property
    def balance(self) -> np.ndarray:
        """E(t) − E(0) + dissipated − work, J: zero for an exact march (round-off and the rule's error)."""
        return self.energy - self.energy[0] + self.dissipated - self.work

    def _wheel(self, wheel) -> int:
        return _checks.integer("wheel", wheel, low=0, high=self.offsets.size - 1)

    def peaks(self, position: float, wheel: int = 0) -> tuple[float, float]:
        """(P1, P2), N: the impact forces of one wheel after it passes ``position`` (a joint's x, a flat's).

        The force is first smoothed over 0.5 ms, which keeps the two stages and removes the ripples of
        the rail's higher modes. P1 is the largest force up to the deepest trough of the smoothed force
        in the 5 ms after its first peak above Q₀ (the bounce on the Hertz spring, and its recoil); P2
        the largest from that trough until 20 ms after the wheel passed ``position`` (wheel and track
        moving down together).

        Parameters
        ----------
        position : float
            m, where that wheel passes during the run.
        wheel : int
            Which wheel, from 0 (the leading one). Default 0.

        Returns
        -------
        (float, float)
        """
        i = self._wheel(wheel)
        where = self.x - self.offsets[i]
        x = _checks.scalar("position", position, low=float(where.min()), high=float(where.max()))
        start = int(np.searchsorted(where, x)) if where[-1] > where[0] else 0
        dt = self.t[1] - self.t[0]
        f = self.contact_force[start : start + int(round(0.020 / dt)) + 1, i]
        width = max(1, int(round(0.5e-3 / dt)))
        smooth = np.convolve(f, np.ones(width) / width, mode="same")
        load = self.static_loads[i]
        rises = np.flatnonzero(
            (smooth[1:-1] >= smooth[:-2]) & (smooth[1:-1] > smooth[2:]) & (smooth[1:-1] > load)
        )
        if rises.size == 0:
            raise ValueError(f"the contact force rises to no peak above Q0 in the 20 ms after x = {x!r} m")
        first = int(rises[0]) + 1
        split = first + int(np.argmin(smooth[first : first + int(round(5e-3 / dt)) + 1]))
        return float(f[: split + 1].max()), float(f[split:].max())

    def plot(self, ax=None, *, position=None, wheel=0, artists=None) -> dict:
        """Draw one wheel's F (kN) against time, with P1 and P2 marked after ``position``; or move a drawing.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        position : float, optional
            Where the impact begins (a joint), m: time is then counted from the moment the wheel
            passes it, and P1 and P2 are marked.
        wheel : int
            Which wheel, from 0 (the leading one). Default 0.
        artists : dict, optional
            What a previous call returned: its lines take this run's values (any number of records).

        Returns
        -------
        dict
            ``{"force": line, "peaks": line}``.
        """
        i = self._wheel(wheel)
        force = self.contact_force[:, i]
        t0, px, py = 0.0, [], []
        if position is not None:
            p1, p2 = self.peaks(position, i)
            where = self.x - self.offsets[i]
            t0 = float(self.t[int(np.searchsorted(where, position))]) if where[-1] > where[0] else 0.0
            for p in (p1, p2):
                k = int(np.flatnonzero((force == p) & (self.t >= t0))[0])
                px.append(1e3 * (self.t[k] - t0))
                py.append(1e-3 * p)
        t, f = 1e3 * (self.t - t0), 1e-3 * force
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict returned by an earlier plot")
            artists["force"].set_data(t, f)
            artists["peaks"].set_data(px, py)
            return artists
        from raildyn import plots

        ax = plots.axes_or_new(ax)
        (line,) = ax.plot(t, f, color="C0", label="wheel–rail force F")
        (peaks,) = ax.plot(px, py, "v", color="C3", label="P1, P2")
        ax.axhline(1e-3 * self.static_loads[i], color="0.6", lw=0.8, ls="--")
        ax.set_xlabel("time after the joint (ms)" if position is not None else "time t (ms)")
        ax.set_ylabel("F (kN)")
        return {"force": line, "peaks": peaks}


def _profile(irregularity, x):
    if irregularity is None:
        return np.zeros_like(x), np.zeros_like(x)
    if not isinstance(irregularity, DippedJoint | WheelFlat | Roughness):
        raise TypeError(
            "irregularity must be a DippedJoint, a WheelFlat, a Roughness or None, "
            f"got {type(irregularity).__name__}"
        )
    return irregularity.profile(x)


def _surface(irregularity, seen):
    """(r_s, dr_s/dx) each wheel meets, (k, w): a flat turns with the leading wheel only."""
    r, slope = _profile(irregularity, seen)
    if isinstance(irregularity, WheelFlat):
        r[:, 1:], slope[:, 1:] = 0.0, 0.0
    return r, slope


def wheel_on_track(
    wheels,
    speed: float,
    irregularity=None,
    *,
    track: DiscreteTrack | None = None,
    start: float | None = None,
    distance: float | None = None,
    time_step: float = 1.0e-5,
    standing: bool = False,
    record_every: int = 1,
    method: str = "newmark",
) -> WheelOnTrack:
    """Run wheels over a discrete track at a steady speed (the module docstring's equations).

    The run starts from the static equilibrium of vehicle, wheels and track under the static loads.

    Parameters
    ----------
    wheels : Wheel, VehicleWheels or WheelBlock
        One wheel (with any share of the vehicle on a primary spring), a whole vertical vehicle on its
        wheels, or any block of wheels and what they carry.
    speed : float
        V, m/s, in (0, 150].
    irregularity : DippedJoint, WheelFlat, Roughness or None
        What the wheels meet; None: a smooth rail (the sleepers' passing alone). A joint or roughness
        lies on the rail, under every wheel in turn; a flat is on the leading wheel.
    track : DiscreteTrack, optional
        Default ``DiscreteTrack()``.
    start : float, optional
        x where the leading wheel starts, m; default where the last wheel stands in the first sleeper
        bay past the quiet layer.
    distance : float, optional
        How far the wheels run, m (> 0); default until the leading wheel reaches the bay before the far
        quiet layer. The whole run stays outside the quiet layers.
    time_step : float
        Δt, s, in [1e-7, 1e-4]. Default 10 µs (some 50 steps in the bounce on the Hertz spring).
    standing : bool
        If True the wheels stand where they start and the irregularity passes under them at V (the
        moving-irregularity model, for comparison with :func:`contact_force_spectrum`).
    record_every : int
        Keep every this-many steps, in [1, 1000].
    method : {"newmark", "scipy"}
        The compiled march, or scipy's RK45 on the same equations (rtol 1e-8; the reference for the
        march's speed and answer: slow).

    Returns
    -------
    WheelOnTrack

    Raises
    ------
    SolverError
        If a contact force goes non-finite, or the contact forces will not settle in a step.
    """
    from raildyn.bridge import _band, _impact_kernel

    if not isinstance(wheels, Wheel | VehicleWheels | WheelBlock):
        raise TypeError(f"wheels must be a Wheel, VehicleWheels or a WheelBlock, got {type(wheels).__name__}")
    block = wheels if isinstance(wheels, WheelBlock) else wheels.block()
    track = DiscreteTrack() if track is None else track
    if not isinstance(track, DiscreteTrack):
        raise TypeError(f"track must be a DiscreteTrack, got {type(track).__name__}")
    V = _checks.speed("speed", speed, high=150.0)
    dt = _checks.scalar("time_step", time_step, low=1e-7, high=1e-4)
    standing = _checks.flag("standing", standing)
    every = _checks.integer("record_every", record_every, low=1, high=1000)
    if method not in ("newmark", "scipy"):
        raise ValueError(f"method must be 'newmark' or 'scipy', got {method!r}")
    d = track.sleeper_spacing
    lo, hi = (track.quiet_bays + 1) * d, track.length - (track.quiet_bays + 1) * d
    lo_lead = lo + block.offsets.max()
    if hi <= lo_lead:
        raise ValueError(
            f"track must leave room for the wheels ({block.offsets.max():g} m apart) between its quiet "
            f"layers, got {track.bays} bays"
        )
    x0 = lo_lead if start is None else _checks.scalar("start", start, low=lo_lead, high=hi)
    span = hi - x0 if distance is None else _checks.scalar("distance", distance, low=0.0, low_open=True)
    if not standing and x0 + span > hi + 1e-9:
        raise ValueError(f"distance must keep the wheels before x = {hi!r} m (the quiet layer), got {span!r}")
    steps = int(math.ceil(span / V / dt))
    if steps * block.offsets.size > 5_000_000:
        raise ValueError(
            f"the run must take at most 5e6 wheel-steps, got {steps} steps (distance/speed/time_step)"
        )
    t = np.arange(steps + 1) * dt
    lead = x0 + V * t
    seen = lead[:, None] - block.offsets[None, :]
    where = np.broadcast_to(x0 - block.offsets, seen.shape) if standing else seen
    r, slope_r = _surface(irregularity, seen)
    mats = track.matrices
    h = d / track.elements_per_bay
    element = np.minimum((where / h).astype(int), track.elements_per_bay * track.bays - 1)
    phi = 12.0 * track.rail_flexural_rigidity / (track.rail_shear_stiffness * h * h)
    nw, dnw = (np.moveaxis(a, 0, -1).copy() for a in _shape(where / h - element, h, phi)[:2])
    if standing:
        dnw[:] = 0.0
    a, b = mats.deflection[element], mats.deflection[element + 1]
    dofs = np.stack([a, a + 1, b, b + 1], axis=-1)
    # The static state: the rail under the static loads, each Hertz spring pressed by (Q₀/C_H)^{2/3}.
    u = np.zeros(mats.size)
    for i, load in enumerate(block.static_loads):
        np.add.at(u, dofs[0, i], nw[0, i] * load)
    stiff = mats.stiffness.copy()
    _band.band_factor(stiff)
    _band.band_solve(stiff, u)
    rail0 = np.einsum("wk,wk->w", nw[0], u[dofs[0]])
    origin = rail0 + (block.static_loads / block.hertz_constants) ** (2 / 3) + r[0]
    records = steps // every + 1
    w = block.offsets.size
    out = {name: np.zeros(records) for name in ("energy", "work", "dissipated")}
    out |= {name: np.zeros((records, w)) for name in ("force", "wheel", "rail")}
    out["pad"], out["ballast"] = np.zeros((records, track.bays)), np.zeros((records, track.bays))
    if method == "scipy":
        surface = lambda s: _surface(irregularity, s)  # noqa: E731
        _impact_reference.march(track, block, surface, x0, V, standing, t[::every], u, origin, out)
    else:
        effective = mats.stiffness + 4.0 / dt**2 * mats.mass + 2.0 / dt * mats.damping
        rail_dofs = np.unique(dofs)
        column_of = np.full(mats.size, -1)
        column_of[rail_dofs] = np.arange(rail_dofs.size)
        columns = _impact_kernel.influence(effective, rail_dofs)
        nb = block.mass.shape[0]
        done, status = _impact_kernel.march(
            mats.mass,
            mats.damping,
            mats.stiffness,
            effective,
            columns,
            column_of,
            dofs,
            nw,
            dnw,
            r,
            slope_r,
            V,
            block.mass,
            block.damping,
            block.stiffness,
            block.contact_dofs,
            block.static_loads,
            origin,
            block.hertz_constants,
            dt,
            u,
            np.zeros_like(u),
            np.zeros_like(u),
            np.zeros(nb),
            np.zeros(nb),
            np.zeros(nb),
            block.static_loads.copy(),
            every,
            mats.deflection[mats.sleeper_nodes],
            mats.sleepers,
            track.pad_stiffness,
            track.pad_damping,
            track.ballast_stiffness,
            track.ballast_damping,
            out["force"],
            out["wheel"],
            out["rail"],
            out["pad"],
            out["ballast"],
            out["energy"],
            out["work"],
            out["dissipated"],
        )
        if status:
            reason = "became non-finite: the run diverged" if status == 1 else "would not settle in a step"
            raise SolverError(f"the contact forces {reason}", step=int(done), time=float(done * dt))
    keep = slice(None, None, every)
    return WheelOnTrack(
        t[keep],
        lead[keep],
        block.offsets,
        out["force"],
        out["wheel"],
        out["rail"],
        r[keep],
        track.sleeper_positions,
        out["pad"],
        out["ballast"],
        out["energy"],
        out["work"],
        out["dissipated"],
        block.static_loads,
        V,
    )


def contact_force_spectrum(wheel: Wheel, speed: float, psd, frequencies, *, track=None, position=None):
    """The wheel–rail force's spectrum from a roughness's, linearised: S_F = S_r(f) / |α_w + α_H + α_r|².

    For small roughness the Hertz spring acts as its tangent k_H = 1/α_H at the static load, and the
    force that the roughness r drives between wheel (receptance α_w,
    :meth:`raildyn.bridge.wheels.Wheel.receptance`) and rail (α_r, the track's point receptance) is
    F = −r/(α_w + α_H + α_r): the three compliances in series.

    Parameters
    ----------
    wheel : Wheel
    speed : float
        V, m/s, in (0, 150].
    psd : callable
        The roughness's one-sided spatial spectrum S(Ω), m²/(rad/m), Ω in rad/m (as
        :func:`raildyn.track.synthesis.synthesize_irregularity` takes it).
    frequencies : array_like
        f, Hz, each in (0, 10 000].
    track : DiscreteTrack or LayeredTrack, optional
        Default ``DiscreteTrack()``.
    position : float, optional
        For a DiscreteTrack, where the wheel stands (its receptance is taken there), m; default its
        :meth:`~raildyn.bridge.sleepers.DiscreteTrack.receptance` default.

    Returns
    -------
    ndarray
        S_F, N²/Hz, one-sided, one per frequency.
    """
    from raildyn.track import temporal_psd

    V = _checks.speed("speed", speed, high=150.0)
    f = _checks.array("frequencies", frequencies, ndim=1, low=0.0, low_open=True, allow_empty=False)
    compliance = contact_compliance(wheel, f, track=track, position=position)
    roughness = 2 * np.pi * temporal_psd(psd, V)(2 * np.pi * f)  # per Hz
    return roughness / np.abs(compliance) ** 2


def contact_compliance(wheel: Wheel, frequencies, *, track=None, position=None) -> np.ndarray:
    """α_w + 1/k_H + α_r: the wheel's, the contact's and the rail's compliances in series, m/N (complex).

    The roughness r_s drives the force F = −r_s/(α_w + 1/k_H + α_r) between wheel and rail
    (:func:`contact_force_spectrum`); |1/compliance| is that force per metre of roughness.

    Parameters
    ----------
    wheel : Wheel
    frequencies : array_like
        f, Hz, a non-empty 1-D array, each in (0, 10 000].
    track : DiscreteTrack or LayeredTrack, optional
        Default ``DiscreteTrack()``.
    position : float, optional
        For a DiscreteTrack, where the wheel stands, m; as for
        :meth:`~raildyn.bridge.sleepers.DiscreteTrack.receptance`.

    Returns
    -------
    ndarray of complex
        One per frequency.
    """
    from raildyn.bridge.track import LayeredTrack

    if not isinstance(wheel, Wheel):
        raise TypeError(f"wheel must be a Wheel, got {type(wheel).__name__}")
    f = _checks.array("frequencies", frequencies, ndim=1, low=0.0, low_open=True, allow_empty=False)
    track = DiscreteTrack() if track is None else track
    if isinstance(track, DiscreteTrack):
        rail = track.receptance(f, position)
    elif isinstance(track, LayeredTrack):
        rail = track.receptance(f)
    else:
        raise TypeError(f"track must be a DiscreteTrack or a LayeredTrack, got {type(track).__name__}")
    return wheel.receptance(f) + 1.0 / wheel.contact_stiffness + rail


def lumped_track(track: DiscreteTrack, position=None, band=(5.0, 60.0)) -> tuple[float, float, float]:
    """The track seen as one mass on a spring and damper: (K_t, M_t, C_t) for :func:`jenkins_p2`.

    Least squares of 1/α(f) = K_t − M_t ω² + iω C_t over ``band`` (the real part for K_t and M_t, the
    imaginary for C_t), α the track's receptance at ``position``: the picture Jenkins et al. (1974)
    draw of the track under P2. The band should hold the P2 resonance (some 30–60 Hz); the fit moves
    with the band, for no real track is one mass.

    Parameters
    ----------
    track : DiscreteTrack
    position : float, optional
        m, as for :meth:`~raildyn.bridge.sleepers.DiscreteTrack.receptance`.
    band : (float, float)
        f, Hz, 0 < low < high ≤ 1000.

    Returns
    -------
    (float, float, float)
        K_t (N/m), M_t (kg), C_t (N·s/m).
    """
    if not isinstance(track, DiscreteTrack):
        raise TypeError(f"track must be a DiscreteTrack, got {type(track).__name__}")
    lo, hi = _checks.array("band", band, shape=(2,), low=0.0, low_open=True)
    if not lo < hi <= 1000.0:
        raise ValueError(f"band must be (low, high) with 0 < low < high <= 1000 Hz, got {band!r}")
    f = np.linspace(lo, hi, 64)
    w = 2 * np.pi * f
    stiffness = 1.0 / track.receptance(f, position)
    (k, m), *_ = np.linalg.lstsq(np.stack([np.ones_like(w), -(w**2)], 1), stiffness.real, rcond=None)
    c = float(np.linalg.lstsq(w[:, None], stiffness.imag, rcond=None)[0][0])
    return float(k), float(m), c


def jenkins_p2(wheel: Wheel, speed: float, total_angle: float, track_mass: float, track_stiffness: float,
               track_damping: float) -> float:  # fmt: skip
    """P2 by the closed-form estimate of Jenkins et al. (1974), N.

    P2 = Q₀ + 2αV √(m_w/(m_w + M_t)) [1 − π C_t / (4√(K_t(m_w + M_t)))] √(K_t m_w).

    After the P1 bounce the wheel and an effective track mass M_t share the wheel's momentum 2αV m_w
    and ride down together on the track's stiffness K_t and damping C_t; the bracket is the first-order
    effect of damping on that oscillator's first peak. It holds while the two stages stay apart (P1
    over well before P2: a Hertz spring much stiffer than the track), the damping ratio is small, the
    wheel keeps contact, and the dip is sharp against the P2 period (its legs longer than the distance
    run in half a P2 period, so that the wheel meets no third slope change before P2).

    Parameters
    ----------
    wheel : Wheel
        Its unsprung mass and static load (a sprung mass is taken as not moving).
    speed : float
        V, m/s, in (0, 150].
    total_angle : float
        2α, rad, in (0, 0.1].
    track_mass, track_stiffness, track_damping : float
        M_t (kg, > 0), K_t (N/m, > 0), C_t (N·s/m, ≥ 0): the track as one mass on a spring and damper.

    Returns
    -------
    float
    """
    if not isinstance(wheel, Wheel):
        raise TypeError(f"wheel must be a Wheel, got {type(wheel).__name__}")
    V = _checks.speed("speed", speed, high=150.0)
    angle = _checks.scalar("total_angle", total_angle, low=0.0, low_open=True, high=2 * MAX_DIP_ANGLE)
    mt, kt = _checks.positive("track_mass", track_mass), _checks.positive("track_stiffness", track_stiffness)
    ct = _checks.nonnegative("track_damping", track_damping)
    mu = wheel.unsprung_mass
    damping = 1.0 - math.pi * ct / (4.0 * math.sqrt(kt * (mu + mt)))
    return wheel.static_load + angle * V * math.sqrt(mu / (mu + mt)) * damping * math.sqrt(kt * mu)
