"""What an analysis of a train returns: quasi-static forces, simulated runs and their peaks.

Each result is a frozen dataclass with SI fields; those worth a picture draw it
with a ``plot``/``plot_*`` method that takes ``ax=None`` and returns its artists,
so that the figures and the widgets of chapter 9 draw them the same way and a
widget can move the artists in place. A :class:`TrainRun` that exists is a
success: ``raildyn.train.simulate`` raises ``raildyn.errors.SolverError`` when it
cannot finish.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks, plots
from raildyn._tables import Tabular

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib

__all__ = ["CouplerPeak", "QuasiStatic", "TrainRun"]


@dataclass(frozen=True)
class QuasiStatic(Tabular):
    """Quasi-static state of a train.

    Attributes
    ----------
    coupler_force : ndarray (n−1,)
        Coupler forces, N (+ tension), front coupler first.
    acceleration : float
        Common acceleration, m/s².
    external_force : ndarray (n,)
        Net external force on each vehicle, N.
    position : ndarray (n,)
        Route positions of the vehicle centres, m.
    coupler_offsets : ndarray (n−1,)
        Distance of each coupler behind the front of the train, m
        (``Consist.coupler_offsets``).
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units;
    # a row per coupler, front first; the per-vehicle forces and positions (one more) are no columns.
    _columns = (("coupler_offsets", "m"), ("coupler_force", "N"))
    _scalars = (("acceleration", "m/s²"),)

    coupler_force: np.ndarray
    acceleration: float
    external_force: np.ndarray
    position: np.ndarray
    coupler_offsets: np.ndarray

    def __post_init__(self):
        external = _checks.array("external_force", self.external_force, ndim=1, allow_empty=False)
        n = external.size
        object.__setattr__(self, "external_force", external)
        object.__setattr__(self, "position", _checks.array("position", self.position, shape=(n,)))
        for name in ("coupler_force", "coupler_offsets"):
            object.__setattr__(self, name, _checks.array(name, getattr(self, name), shape=(n - 1,)))
        object.__setattr__(self, "acceleration", _checks.scalar("acceleration", self.acceleration))

    def plot(self, ax=None, *, label: str | None = None, color=None) -> dict:
        """Draw the coupler forces (kN) along the train (m behind the front).

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default.
        label : str, optional
            Legend label of the line.
        color : matplotlib colour, optional
            Colour of the line; the first house colour by default.

        Returns
        -------
        dict
            The artists: ``line``.
        """
        import matplotlib

        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            (line,) = ax.plot(
                self.coupler_offsets,
                self.coupler_force / 1e3,
                color=plots.COLORS[0] if color is None else color,
                label=label,
            )
            ax.set_xlabel("coupler position behind the front (m)")
            ax.set_ylabel("coupler force (kN, + draft)")
        return {"line": line}


@dataclass(frozen=True)
class CouplerPeak:
    """The coupler force of largest magnitude in a run.

    Attributes
    ----------
    force : float
        The force, N (+ draft/tension, − buff/compression).
    coupler : int
        Index of the coupler, 0 behind the front vehicle.
    offset : float
        Distance of that coupler behind the front of the train, m.
    time : float
        Time at which it occurs, s.
    """

    force: float
    coupler: int
    offset: float
    time: float

    def __post_init__(self):
        object.__setattr__(self, "coupler", _checks.integer("coupler", self.coupler, low=0))
        for name in ("force", "offset", "time"):
            object.__setattr__(self, name, _checks.scalar(name, getattr(self, name)))

    @property
    def kind(self) -> str:
        """``"draft"`` for a tension, ``"buff"`` for a compression."""
        return "buff" if self.force < 0 else "draft"


@dataclass(frozen=True)
class TrainRun(Tabular):
    """A simulated run: a returned run is always a success (failures raise ``SolverError``).

    Attributes
    ----------
    t : ndarray (m,)
        Times, s.
    position : ndarray (n, m)
        Route positions of the vehicle centres, m.
    speed : ndarray (n, m)
        Vehicle speeds, m/s.
    coupler_force : ndarray (n−1, m)
        Coupler forces, N (+ tension).
    coupler_offsets : ndarray (n−1,)
        Distance of each coupler behind the front of the train, m
        (``Consist.coupler_offsets``).
    evaluations : int
        Right-hand-side calls made by the integrator.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("t", "s"), ("position", "m"), ("speed", "m/s"), ("coupler_force", "N"))
    _scalars = (("evaluations", "-"),)
    _by_row = ("position", "speed", "coupler_force")

    t: np.ndarray
    position: np.ndarray
    speed: np.ndarray
    coupler_force: np.ndarray
    coupler_offsets: np.ndarray
    evaluations: int

    def __post_init__(self):
        t = _checks.array("t", self.t, ndim=1, allow_empty=False)
        speed = _checks.plausible_array("speed", self.speed, "speed", signed=True, ndim=2, allow_empty=False)
        n, m = speed.shape
        if m != t.size:
            raise ValueError(f"speed must have one column per time, shape ({n}, {t.size}), got {speed.shape}")
        object.__setattr__(self, "t", t)
        object.__setattr__(self, "speed", speed)
        object.__setattr__(self, "position", _checks.array("position", self.position, shape=(n, m)))
        force = _checks.array("coupler_force", self.coupler_force, shape=(n - 1, m))
        object.__setattr__(self, "coupler_force", force)
        offsets = _checks.array("coupler_offsets", self.coupler_offsets, shape=(n - 1,))
        object.__setattr__(self, "coupler_offsets", offsets)
        object.__setattr__(self, "evaluations", _checks.integer("evaluations", self.evaluations, low=0))

    @property
    def max_tension(self) -> np.ndarray:
        """Largest draft force of each coupler over the run, N (shape (n−1,))."""
        return self.coupler_force.max(axis=1)

    @property
    def max_compression(self) -> np.ndarray:
        """Largest buff force of each coupler over the run, N, as a positive number (shape (n−1,))."""
        return -self.coupler_force.min(axis=1)

    @property
    def peak(self) -> CouplerPeak:
        """The coupler force of largest magnitude: its value, coupler, place and time."""
        j, k = np.unravel_index(np.argmax(np.abs(self.coupler_force)), self.coupler_force.shape)
        return CouplerPeak(
            force=float(self.coupler_force[j, k]),
            coupler=int(j),
            offset=float(self.coupler_offsets[j]),
            time=float(self.t[k]),
        )

    def stop_time(self, vehicle: int = 0, threshold: float = 0.01) -> float | None:
        """First time a vehicle's speed falls below ``threshold``.

        Parameters
        ----------
        vehicle : int
            Index of the vehicle, 0 at the front; negative counts from the rear.
        threshold : float
            Speed taken as stopped, m/s (> 0).

        Returns
        -------
        float or None
            Time, s; None if the vehicle is still moving at the end of the run.
        """
        n = self.speed.shape[0]
        vehicle = _checks.integer("vehicle", vehicle, low=-n, high=n - 1)
        threshold = _checks.positive("threshold", threshold)
        below = np.abs(self.speed[vehicle]) < threshold
        return float(self.t[np.argmax(below)]) if below.any() else None

    def plot_envelope(self, ax=None, *, artists: dict | None = None) -> dict:
        """Draw the coupler-force envelope along the train (kN against m behind the front), with the peak.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default. Ignored when ``artists`` is given.
        artists : dict, optional
            The artists an earlier call returned (keys ``draft``, ``buff`` and ``peak``):
            they are moved to this run's data in place (``set_data``), nothing is drawn anew.

        Returns
        -------
        dict
            The artists: ``draft`` (largest tension), ``buff`` (largest compression, drawn
            negative) and ``peak`` (a marker on the force of largest magnitude).
        """
        import matplotlib

        x = self.coupler_offsets
        peak = self.peak
        data = {
            "draft": (x, self.max_tension / 1e3),
            "buff": (x, -self.max_compression / 1e3),
            "peak": ([peak.offset], [peak.force / 1e3]),
        }
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
            missing = [name for name in data if not hasattr(artists.get(name), "set_data")]
            if missing:
                raise ValueError(f"artists must hold line artists under {sorted(data)}; missing {missing}")
            for name, (u, w) in data.items():
                artists[name].set_data(u, w)
            return artists
        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            (draft,) = ax.plot(*data["draft"], color=plots.COLORS[0], label="largest draft (tension)")
            (buff,) = ax.plot(*data["buff"], color=plots.COLORS[1], label="largest buff (compression)")
            (mark,) = ax.plot(*data["peak"], "o", color="k", mfc="w", mew=2, ms=7, label="peak")
            ax.axhline(0, color="0.4", lw=0.8)
            ax.set_xlabel("coupler position behind the front (m)")
            ax.set_ylabel("coupler force envelope (kN)")
            ax.legend(loc="lower right")
        return {"draft": draft, "buff": buff, "peak": mark}

    def plot_wave(self, ax=None, *, limit: float | None = None) -> dict:
        """Draw the coupler force (kN) over time and position along the train as a colour map.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default.
        limit : float, optional
            Force at the ends of the colour scale, kN (> 0); the largest magnitude by default.

        Returns
        -------
        dict
            The artists: ``mesh`` (the colour map) and ``colorbar``.
        """
        import matplotlib

        peak = abs(self.peak.force) / 1e3
        limit = (peak if peak > 0 else 1.0) if limit is None else _checks.positive("limit", limit)
        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            mesh = ax.pcolormesh(
                self.t, self.coupler_offsets, self.coupler_force / 1e3, cmap="RdBu_r", vmin=-limit, vmax=limit
            )
            bar = ax.figure.colorbar(mesh, ax=ax, label="coupler force (kN, + draft)")
            ax.set_xlabel("time (s)")
            ax.set_ylabel("coupler position behind the front (m)")
        return {"mesh": mesh, "colorbar": bar}
