"""The rocking freight car run over staggered jointed rail: wheel loads, wheel lift, plate and bearer
contact, at one speed (:func:`~raildyn.vehicles.rocking_runs.rocking_run`) and over many
(:func:`~raildyn.vehicles.rocking_runs.rocking_sweep`).

The car is :class:`raildyn.vehicles.rocking.RockingFreightCar`; the track is
:func:`~raildyn.track.deterministic.jointed_track` with the right rail's joints half a rail length along
the left's,
tabulated over one rail length (1 mm apart) and read by each wheelset at its own delay. The march is
RK4 at a fixed step, compiled with numba (``_rocking_kernel``), one speed after another.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks, plots
from raildyn import track as _track
from raildyn._tables import Tabular
from raildyn.errors import SolverError
from raildyn.integrators import stable_step
from raildyn.vehicles._shared import _earlier_artists
from raildyn.vehicles.rocking import RockingFreightCar

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib,
# raildyn.vehicles._rocking_kernel

__all__ = ["RockingRun", "RockingSweep", "rocking_run", "rocking_sweep"]

_TABLE_SPACING = 0.001  # m: the rail profile's table, far finer than a dip's 1 m half-width
_MAX_STEPS = 2_000_000  # per speed: some 10 s of compiled work


@dataclass(frozen=True, eq=False)
class RockingRun(Tabular):
    """The rocking car at one speed over staggered jointed rail
    (:func:`~raildyn.vehicles.rocking_runs.rocking_run`).

    The measures (``peak_unloading`` … ``roll_amplitude``) are taken over the steady window, the
    run's second half, at every step of the march; the histories are sampled more coarsely.

    Attributes
    ----------
    speed : float
        V, m/s, > 0.
    rail_length : float
        L, m, > 0.
    t : ndarray, (n_t,)
        s, strictly increasing.
    wheel_loads : ndarray, (n_t, 4, 2)
        Each wheel's load, N, ≥ 0: wheelsets leading first, left then right.
    plate_loads, bearer_loads : ndarray, (n_t, 2, 2)
        Each truck's centre-plate edge and side-bearer loads, left and right, N, ≥ 0.
    roll : ndarray, (n_t,)
        The body's roll, rad (left side up).
    static_wheel_load : float
        Q₀, each wheel's load at rest, N, in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "wheel_load").
    peak_unloading : float
        The largest ΔQ/Q = 1 − Q/Q₀ of any wheel in the steady window, in [0, 1] (1: a wheel lifted).
    lift_fraction, plate_lift_fraction, bearer_contact_fraction : float
        The shares of the steady window, in [0, 1], in which some wheel is off its rail, some centre
        plate stands on one edge (the other lifted), and some side bearer is closed.
    roll_amplitude : float
        Half the body's peak-to-peak roll in the steady window, rad, in [0, π/2].
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("t", "s"), ("wheel_loads", "N"), ("plate_loads", "N"), ("bearer_loads", "N"), ("roll", "rad"),
    )  # fmt: skip
    _scalars = (
        ("speed", "m/s"), ("rail_length", "m"), ("static_wheel_load", "N"), ("peak_unloading", "-"),
        ("lift_fraction", "-"), ("plate_lift_fraction", "-"), ("bearer_contact_fraction", "-"),
        ("roll_amplitude", "rad"),
    )  # fmt: skip

    speed: float
    rail_length: float
    t: np.ndarray
    wheel_loads: np.ndarray
    plate_loads: np.ndarray
    bearer_loads: np.ndarray
    roll: np.ndarray
    static_wheel_load: float
    peak_unloading: float
    lift_fraction: float
    plate_lift_fraction: float
    bearer_contact_fraction: float
    roll_amplitude: float

    def __post_init__(self):
        object.__setattr__(self, "speed", _checks.speed("speed", self.speed))
        object.__setattr__(self, "rail_length", _checks.positive("rail_length", self.rail_length))
        t = _checks.time_grid("t", self.t)
        object.__setattr__(self, "t", t)
        object.__setattr__(
            self, "wheel_loads", _checks.array("wheel_loads", self.wheel_loads, shape=(t.size, 4, 2), low=0.0)
        )
        for name in ("plate_loads", "bearer_loads"):
            object.__setattr__(
                self, name, _checks.array(name, getattr(self, name), shape=(t.size, 2, 2), low=0.0)
            )
        object.__setattr__(self, "roll", _checks.array("roll", self.roll, shape=(t.size,)))
        object.__setattr__(
            self,
            "static_wheel_load",
            _checks.plausible("static_wheel_load", self.static_wheel_load, "wheel_load"),
        )
        for name in ("peak_unloading", "lift_fraction", "plate_lift_fraction", "bearer_contact_fraction"):
            object.__setattr__(self, name, _checks.scalar(name, getattr(self, name), low=0.0, high=1.0))
        object.__setattr__(
            self,
            "roll_amplitude",
            _checks.scalar("roll_amplitude", self.roll_amplitude, low=0.0, high=np.pi / 2),
        )

    @property
    def side_loads(self) -> np.ndarray:
        """Q_L and Q_R of each truck, the loads of its two wheels on each rail, N: (n_t, 2, 2)."""
        return self.wheel_loads.reshape(-1, 2, 2, 2).sum(axis=2)

    @property
    def truck_loads(self) -> np.ndarray:
        """N = Q_L + Q_R, each truck's vertical load on the rails, N: (n_t, 2)."""
        return self.side_loads.sum(axis=2)

    @property
    def unloading(self) -> np.ndarray:
        """ΔQ/Q = 1 − Q/Q₀ of each wheel, (n_t, 4, 2): 1 where it has lifted, < 0 where loaded above Q₀."""
        return 1.0 - self.wheel_loads / self.static_wheel_load

    @property
    def wheel_lifted(self) -> np.ndarray:
        """Whether each wheel is off its rail, (n_t, 4, 2) of bool."""
        return self.wheel_loads <= 0.0

    @property
    def plate_lifted(self) -> np.ndarray:
        """Whether each truck's centre plate stands on one edge, (n_t, 2) of bool."""
        return (self.plate_loads <= 0.0).any(axis=2)

    @property
    def bearer_contact(self) -> np.ndarray:
        """Whether each truck's side bearers are closed, left and right, (n_t, 2, 2) of bool."""
        return self.bearer_loads > 0.0

    @property
    def lift_distance(self) -> float:
        """The distance run with some wheel lifted, per rail length, m: ``lift_fraction`` × L."""
        return self.lift_fraction * self.rail_length

    def plot(self, ax=None, *, truck: int = 0, artists: dict | None = None) -> dict:
        """Draw one truck's side loads Q_L and Q_R (kN) against time, the wheel lifts marked on the axis.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default. Ignored when ``artists`` is given.
        truck : {0, 1}
            The leading (0) or trailing (1) truck.
        artists : dict, optional
            The artists an earlier call returned: they are moved to this run.

        Returns
        -------
        dict
            The artists: ``left``, ``right`` (lines) and ``lift`` (the times some wheel of the truck is
            off its rail, as points on the zero line).
        """
        import matplotlib

        truck = _checks.integer("truck", truck, low=0, high=1)
        q = self.side_loads[:, truck] / 1e3
        lifted = self.wheel_lifted[:, 2 * truck : 2 * truck + 2].any(axis=(1, 2))
        lift_y = np.where(lifted, 0.0, np.nan)
        if artists is not None:
            got = _earlier_artists(artists, ("left", "right", "lift"))
            got["left"].set_data(self.t, q[:, 0])
            got["right"].set_data(self.t, q[:, 1])
            got["lift"].set_data(self.t, lift_y)
            return artists
        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            (left,) = ax.plot(self.t, q[:, 0], color=plots.COLORS[0], lw=0.9, label="$Q_L$ (left rail)")
            (right,) = ax.plot(self.t, q[:, 1], color=plots.COLORS[1], lw=0.9, label="$Q_R$ (right rail)")
            (lift,) = ax.plot(self.t, lift_y, color="k", lw=4, solid_capstyle="butt", label="a wheel lifted")
            ax.axhline(2 * self.static_wheel_load / 1e3, color="0.6", ls=":", lw=0.8)
            ax.set_xlabel("time (s)")
            ax.set_ylabel(f"truck {truck + 1} side load (kN)")
        return {"left": left, "right": right, "lift": lift}


@dataclass(frozen=True, eq=False)
class RockingSweep(Tabular):
    """The rocking car over staggered jointed rail at many speeds
    (:func:`~raildyn.vehicles.rocking_runs.rocking_sweep`).

    Attributes
    ----------
    speeds : ndarray, (n,)
        m/s, each > 0.
    peak_unloading, lift_fraction, plate_lift_fraction, bearer_contact_fraction : ndarray, (n,)
        Each run's measures (:class:`RockingRun`), in [0, 1].
    roll_amplitude : ndarray, (n,)
        rad, ≥ 0.
    resonance_speed : float
        V = f L of the car's linear rocking mode
        (:meth:`~raildyn.vehicles.rocking.RockingFreightCar.roll_resonance_speed`), m/s.
    runs : tuple of RockingRun
        One per speed, with its histories.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("speeds", "m/s"), ("peak_unloading", "-"), ("lift_fraction", "-"), ("plate_lift_fraction", "-"),
        ("bearer_contact_fraction", "-"), ("roll_amplitude", "rad"),
    )  # fmt: skip
    _scalars = (("resonance_speed", "m/s"),)

    speeds: np.ndarray
    peak_unloading: np.ndarray
    lift_fraction: np.ndarray
    plate_lift_fraction: np.ndarray
    bearer_contact_fraction: np.ndarray
    roll_amplitude: np.ndarray
    resonance_speed: float
    runs: tuple

    def __post_init__(self):
        V = _checks.speeds("speeds", self.speeds)
        object.__setattr__(self, "speeds", V)
        for name in ("peak_unloading", "lift_fraction", "plate_lift_fraction", "bearer_contact_fraction"):
            arr = _checks.array(name, getattr(self, name), shape=V.shape, low=0.0)
            if (arr > 1.0).any():
                raise ValueError(f"{name} must lie in [0, 1], got {arr.max()!r}")
            object.__setattr__(self, name, arr)
        object.__setattr__(
            self,
            "roll_amplitude",
            _checks.array("roll_amplitude", self.roll_amplitude, shape=V.shape, low=0.0),
        )
        object.__setattr__(self, "resonance_speed", _checks.speed("resonance_speed", self.resonance_speed))
        if not (
            isinstance(self.runs, tuple)
            and len(self.runs) == V.size
            and all(isinstance(r, RockingRun) for r in self.runs)
        ):
            raise TypeError(f"runs must be a tuple of {V.size} RockingRun, got {self.runs!r:.80}")

    @property
    def peak_speed(self) -> float:
        """The speed of the largest ΔQ/Q (the first, where it reaches 1 at several), m/s."""
        return float(self.speeds[int(np.argmax(self.peak_unloading))])

    def plot(self, ax=None, *, artists: dict | None = None, resonance: bool = True) -> dict:
        """Draw the peak ΔQ/Q and the share of time with a wheel lifted against speed (km/h).

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default. Ignored when ``artists`` is given.
        artists : dict, optional
            The artists an earlier call returned: they are moved to this sweep.
        resonance : bool
            Mark the linear rocking mode's speed V = f L with a dotted line.

        Returns
        -------
        dict
            The artists: ``unloading``, ``lift`` and, with ``resonance``, ``resonance``.
        """
        import matplotlib

        resonance = _checks.flag("resonance", resonance)
        kmh = 3.6 * self.speeds
        if artists is not None:
            got = _earlier_artists(artists, ("unloading", "lift"))
            got["unloading"].set_data(kmh, self.peak_unloading)
            got["lift"].set_data(kmh, self.lift_fraction)
            if "resonance" in artists:
                artists["resonance"].set_xdata([3.6 * self.resonance_speed] * 2)
            return artists
        ax = plots.axes_or_new(ax)
        out = {}
        with matplotlib.rc_context(plots.STYLE):
            (out["unloading"],) = ax.plot(
                kmh, self.peak_unloading, "o-", ms=3, color=plots.COLORS[0], label="peak ΔQ/Q"
            )
            (out["lift"],) = ax.plot(
                kmh,
                self.lift_fraction,
                "s--",
                ms=3,
                color=plots.COLORS[1],
                label="share of time with a wheel lifted",
            )
            if resonance:
                out["resonance"] = ax.axvline(
                    3.6 * self.resonance_speed, color="k", ls=":", lw=1, label="rocking mode $f L$"
                )
            ax.set_xlabel("speed (km/h)")
            ax.set_ylabel("ΔQ/Q, share of time")
            ax.set_ylim(0, 1.05)
        return out


def _settings(car, depth, half_width, rail_length, cycles, dt, output_step):
    """Checked run settings: (L, cycles, dt, output step, rail table)."""
    _checks.instance("car", car, RockingFreightCar)
    L = _checks.plausible("rail_length", rail_length, "rail_length")
    _checks.plausible("depth", depth, "irregularity")
    _checks.plausible("half_width", half_width, "track_length", high=L / 2)
    cycles = _checks.integer("cycles", cycles, low=4, high=1000)
    lin = car.linearized(engaged=True)
    limit = stable_step("rk4", lin.M, lin.C, lin.K)
    if dt is None:
        dt = min(0.001, 0.9 * limit)
    else:
        dt = _checks.positive("dt", dt)
        if dt > limit:
            raise ValueError(
                f"dt must be at most {limit:.4g} s for RK4 to stay stable on this car with its contacts "
                f"closed and its wedges sticking (slope F/v_ε), got {dt!r}"
            )
    output_step = _checks.scalar("output_step", output_step, low=0.0, low_open=True, high=1.0)
    if output_step < dt:
        raise ValueError(f"output_step must be at least the time step dt = {dt:.4g} s, got {output_step!r}")
    x = np.linspace(0.0, L, int(np.ceil(L / _TABLE_SPACING)) + 1)
    rails = _track.jointed_track(x, depth, half_width, rail_length=L, arrangement="staggered")
    slopes = _track.jointed_track(x, depth, half_width, rail_length=L, arrangement="staggered", derivative=1)
    table = np.ascontiguousarray(np.stack([rails.left, rails.right, slopes.left, slopes.right]))
    return L, cycles, dt, output_step, table


def _run(car, speed, L, cycles, dt, output_step, table) -> RockingRun:
    from raildyn.vehicles import _rocking_kernel as kernel

    mass, dofs, ei, ef, _ = car._tables()
    c = car.car
    a, s = c.semi_truck_wheelbase, c.semi_truck_spacing
    behind = np.array([0.0, 2 * a, 2 * s, 2 * s + 2 * a])
    steps = int(np.ceil(cycles * L / speed / dt))
    if steps > _MAX_STEPS:
        raise ValueError(
            f"the run of cycles = {cycles} rail lengths at speed {speed!r} m/s in steps of dt = {dt:.4g} s "
            f"would take {steps} steps; at most {_MAX_STEPS}: take fewer cycles or a higher speed"
        )
    stride = max(1, int(round(output_step / dt)))
    n_out = steps // stride + 1
    watched = np.arange(16, dtype=np.int64)
    hist = np.zeros((n_out, 16))
    roll = np.zeros(n_out)
    extremes = np.zeros((2, 17))
    counts = np.zeros(19, dtype=np.int64)
    tail = steps // 2
    status = kernel.march(
        mass,
        dofs,
        ei,
        ef,
        car.velocity_scale,
        float(speed),
        behind,
        L,
        L / (table.shape[1] - 1),
        table,
        dt,
        steps,
        stride,
        tail,
        np.zeros(18),
        np.zeros(18),
        watched,
        2,
        hist,
        roll,
        np.zeros((0, 36)),
        extremes,
        counts,
    )
    if status >= 0:
        raise SolverError(
            f"the state became non-finite at {speed:.4g} m/s: RK4 went unstable",
            step=int(status),
            time=float(status * dt),
        )
    window = steps - tail + 1
    Q0 = car.static_wheel_load
    return RockingRun(
        speed=float(speed),
        rail_length=L,
        t=np.arange(n_out) * (stride * dt),
        wheel_loads=hist[:, :8].reshape(-1, 4, 2),
        plate_loads=hist[:, 8:12].reshape(-1, 2, 2),
        bearer_loads=hist[:, 12:16].reshape(-1, 2, 2),
        roll=roll,
        static_wheel_load=Q0,
        peak_unloading=float(np.clip(1.0 - extremes[0, :8].min() / Q0, 0.0, 1.0)),
        lift_fraction=counts[16] / window,
        plate_lift_fraction=counts[17] / window,
        bearer_contact_fraction=counts[18] / window,
        roll_amplitude=0.5 * (extremes[1, 16] - extremes[0, 16]),
    )


def rocking_run(
    car: RockingFreightCar,
    speed: float,
    *,
    depth: float = 0.02,
    half_width: float = 1.0,
    rail_length: float = _track.RAIL_LENGTH,
    cycles: int = 16,
    dt: float | None = None,
    output_step: float = 0.005,
) -> RockingRun:
    """The rocking car at one speed over staggered dipped joints, its wheels free to lift.

    The car starts at rest in its static equilibrium with its leading wheelset on a left joint and
    runs ``cycles`` rail lengths; the measures come from the second half. Each joint is the cusp of
    :func:`~raildyn.track.deterministic.dipped_joints`, the right rail's joints half a rail length along.

    Parameters
    ----------
    car : RockingFreightCar
    speed : float
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    depth, half_width : float
        Each joint's dip, m, in [0, 0.1] ("irregularity"), and the half-length of track it spans, m, in
        [0.001, L/2] ("track_length").
    rail_length : float
        L, m, in [1, 150] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "rail_length").
    cycles : int
        Rail lengths run, in [4, 1000].
    dt : float, optional
        RK4's step, s, > 0 and at most the stability limit of the car with every contact closed and its
        wedges sticking (:func:`raildyn.integrators.stable_step`): a longer step is refused with the
        limit in the message. Default: 1 ms or 0.9 of that limit, the shorter.
    output_step : float
        s between the histories' samples, in [``dt``, 1] (rounded to a whole number of steps).

    Returns
    -------
    RockingRun

    Raises
    ------
    SolverError
        If the state becomes non-finite.
    """
    L, cycles, dt, output_step, table = _settings(
        car, depth, half_width, rail_length, cycles, dt, output_step
    )
    V = _checks.speed("speed", speed)
    return _run(car, V, L, cycles, dt, output_step, table)


def rocking_sweep(
    car: RockingFreightCar,
    speeds,
    *,
    depth: float = 0.02,
    half_width: float = 1.0,
    rail_length: float = _track.RAIL_LENGTH,
    cycles: int = 16,
    dt: float | None = None,
    output_step: float = 0.005,
    progress: bool = False,
) -> RockingSweep:
    """:func:`~raildyn.vehicles.rocking_runs.rocking_run` at each of ``speeds``: the peak ΔQ/Q, the wheel
    lift, and the plate and bearer
    contact against speed.

    Parameters
    ----------
    car : RockingFreightCar
    speeds : array_like
        m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`], not empty.
    depth, half_width, rail_length, cycles, dt, output_step
        As :func:`~raildyn.vehicles.rocking_runs.rocking_run`, the same for every speed.
    progress : bool
        Show a progress bar.

    Returns
    -------
    RockingSweep
    """
    L, cycles, dt, output_step, table = _settings(
        car, depth, half_width, rail_length, cycles, dt, output_step
    )
    V = _checks.speeds("speeds", speeds)
    progress = _checks.flag("progress", progress)
    for v in V:  # refuse a too-long run before any work
        if cycles * L / v / dt > _MAX_STEPS:
            raise ValueError(
                f"the run of cycles = {cycles} rail lengths at the speed {v!r} m/s in steps of dt = {dt:.4g} "
                "s "
                f"would take more than {_MAX_STEPS} steps: take fewer cycles or higher speeds"
            )
    items = V
    if progress:
        from tqdm.auto import tqdm

        items = tqdm(V, desc="rocking car", leave=False)
    runs = tuple(_run(car, float(v), L, cycles, dt, output_step, table) for v in items)
    return RockingSweep(
        speeds=V,
        peak_unloading=np.array([r.peak_unloading for r in runs]),
        lift_fraction=np.array([r.lift_fraction for r in runs]),
        plate_lift_fraction=np.array([r.plate_lift_fraction for r in runs]),
        bearer_contact_fraction=np.array([r.bearer_contact_fraction for r in runs]),
        roll_amplitude=np.array([r.roll_amplitude for r in runs]),
        resonance_speed=car.roll_resonance_speed(L),
        runs=runs,
    )
