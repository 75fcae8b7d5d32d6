"""Couplers with slack and friction draft gear: the force between two adjacent vehicles.

Each coupler has a free gap (the slack) in which it carries no force; past the
gap the draft gear deflects with a stiff loading branch and a soft unloading
branch (the friction wedges of a friction draft gear absorb the difference), and
at the end of its travel it goes solid. The model follows the loading/unloading
description of Cole {cole2006}; every function works on arrays of all the
couplers of a train at once.

Chatter-free slack: the corner where the gap closes is replaced by a quadratic
blend over ``±smoothing`` around the gap edge, so the force is continuous with a
continuous slope (no event handling needed), is exactly zero while a gap is open
and differs from the sharp-cornered law by at most ``k · smoothing / 4``.
Branch switching is blended by ``tanh(rate / transition_rate)``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks, plots
from raildyn._tables import Tabular

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib

__all__ = ["DraftGear", "DraftGearLoop"]

# Largest coupler extension or gear deflection the law takes, m, in either direction. A real
# coupler has a few centimetres of slack and under 10 cm of gear travel; a metre means the
# vehicles have parted or overrun each other, where the law does not apply (and the solid
# branch would overflow for absurd extensions).
_MAX_EXTENSION = 1.0


def _extension(name: str, value) -> np.ndarray:
    """``value`` as a non-empty finite array of extensions within ±``_MAX_EXTENSION`` (m)."""
    arr = _checks.array(name, value, allow_empty=False)
    if np.abs(arr).max() > _MAX_EXTENSION:
        raise ValueError(
            f"{name} must be within ±{_MAX_EXTENSION} m (beyond it the vehicles have parted or overrun "
            f"each other, where the coupler law does not apply), got {arr.flat[np.argmax(np.abs(arr))]!r}"
        )
    return arr


@dataclass(frozen=True)
class DraftGear:
    """A coupler with slack and a friction draft gear (the same in draft and buff).

    Parameters
    ----------
    slack : float
        Total free play of the coupling, m, in [0, 0.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "coupler_travel"); half on each
        side of centre.
    loading_stiffness : float
        Stiffness while the gear is being compressed further, N/m (> 0).
    unloading_stiffness : float
        Stiffness while it recovers, N/m; 0 < value <= ``loading_stiffness``.
    travel : float
        Draft-gear travel before it goes solid, m, in (0, 0.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "coupler_travel").
    solid_stiffness : float
        Extra stiffness once the travel is used up, N/m (>= 0).
    smoothing : float
        Half-width of the blend at the gap edge, m (> 0, < slack/2 when slack > 0).
    transition_rate : float
        Deflection rate over which the branch switches, m/s (> 0).

    Notes
    -----
    Default values are assumed typical of a North American AAR coupler with a
    friction draft gear: 25 mm slack per coupling, about 83 mm of gear travel
    and a 25 MN/m loading branch (≈ 2 MN at full travel), with the unloading
    branch at 30 % of it so that about 70 % of the stored energy is absorbed.
    """

    slack: float = 0.025
    loading_stiffness: float = 25e6
    unloading_stiffness: float = 7.5e6
    travel: float = 0.083
    solid_stiffness: float = 250e6
    smoothing: float = 0.001
    transition_rate: float = 0.02

    def __post_init__(self):
        _checks.plausible("slack", self.slack, "coupler_travel")
        k = _checks.positive("loading_stiffness", self.loading_stiffness)
        _checks.positive("unloading_stiffness", self.unloading_stiffness)
        if self.unloading_stiffness > k:
            raise ValueError(
                f"unloading_stiffness must be at most loading_stiffness = {k!r} N/m (the gear recovers on "
                f"a softer branch), got {self.unloading_stiffness!r}"
            )
        _checks.plausible("travel", self.travel, "coupler_travel", low_open=True)
        _checks.nonnegative("solid_stiffness", self.solid_stiffness)
        _checks.positive("smoothing", self.smoothing)
        if self.slack > 0 and self.smoothing >= self.slack / 2:
            raise ValueError(f"smoothing must be < slack/2 = {self.slack / 2!r} m, got {self.smoothing!r}")
        _checks.positive("transition_rate", self.transition_rate)

    def deflection(self, extension):
        """Draft-gear deflection for a coupler extension, with the gap corner rounded.

        Parameters
        ----------
        extension : float or array
            Coupler extension Δx, m (see ``force``), within ±1 m.

        Returns
        -------
        ndarray
            Deflection u >= 0, m, the shape of ``extension``: 0 inside the gap,
            ``|Δx| − slack/2`` beyond the blend, ``(|Δx| − slack/2 + ε)²/(4ε)`` within it.
        """
        u, _ = self._deflection_and_slope(_extension("extension", extension))
        return u

    def _deflection_and_slope(self, extension):
        """Deflection u >= 0 (m) and du/d|Δx| for a coupler extension Δx (m)."""
        if self.slack == 0:
            # No gap, no corner to smooth: the gear deflects from Δx = 0.
            return np.abs(extension), np.ones(np.shape(extension))
        eps = self.smoothing
        a = np.abs(extension) - 0.5 * self.slack
        b = np.minimum(np.maximum(a + eps, 0.0), 2 * eps)  # position inside the blend, 0 … 2ε
        u = np.where(a >= eps, a, b * b * (0.25 / eps))  # (a + ε)²/(4ε) inside the blend
        return u, b * (0.5 / eps)

    def force(self, extension, rate):
        """Coupler force, vectorised over couplers and times.

        Parameters
        ----------
        extension : float or array
            Δx = (separation of the two vehicle centres) − (its value with the slack
            centred), m; > 0 pulls the vehicles apart; within ±1 m (beyond it the
            vehicles have parted or overrun each other).
        rate : float or array
            dΔx/dt, m/s; broadcasts against ``extension``.

        Returns
        -------
        ndarray
            Force, N (+ draft/tension, − buff/compression).

        Examples
        --------
        >>> gear = DraftGear(slack=0.02)
        >>> gear.force([0.005, 0.03], [0.0, 1.0]) / 1e3  # inside the gap; loading, 20 mm past it
        array([  0., 500.])
        """
        extension = _extension("extension", extension)
        rate = _checks.array("rate", rate, allow_empty=False)
        _checks.broadcast(extension=extension, rate=rate)
        return self._force(extension, rate)

    def _force(self, extension, rate):
        """:meth:`force` of checked arrays."""
        s = np.sign(extension)
        u, slope = self._deflection_and_slope(extension)
        # k_u + (k_l − k_u)(1 + tanh)/2, written as mean ± half difference
        mean = 0.5 * (self.loading_stiffness + self.unloading_stiffness)
        half = 0.5 * (self.loading_stiffness - self.unloading_stiffness)
        k = mean + half * np.tanh(slope * s * rate * (1.0 / self.transition_rate))
        force = k * u
        if self.solid_stiffness > 0:
            force = force + self.solid_stiffness * np.maximum(u - self.travel, 0.0)
        return s * force

    def loop_energy(self, amplitude: float) -> float:
        """Energy absorbed by one slow load–unload cycle from 0 to deflection ``amplitude``.

        The area between the loading and unloading branches, ``(k_l − k_u) U²/2``
        while ``U`` is within the travel (the solid part is elastic).

        Parameters
        ----------
        amplitude : float
            Largest deflection U of the cycle, m (0 to 1).

        Returns
        -------
        float
            Energy, J.
        """
        amplitude = _checks.scalar("amplitude", amplitude, low=0.0, high=_MAX_EXTENSION)
        u = min(amplitude, self.travel)
        return 0.5 * (self.loading_stiffness - self.unloading_stiffness) * u**2

    def static_loop(self, amplitude: float, points: int = 200) -> DraftGearLoop:
        """The slow load–unload loop of the gear to a deflection ``amplitude``.

        Parameters
        ----------
        amplitude : float
            Largest deflection, m (0 < amplitude <= 1).
        points : int
            Points on each branch (2 to 100000, more than a drawing needs).

        Returns
        -------
        DraftGearLoop
            The closed loop (loading branch up, unloading branch down) and its energy.
        """
        amplitude = _checks.scalar("amplitude", amplitude, low=0.0, high=_MAX_EXTENSION, low_open=True)
        points = _checks.integer("points", points, low=2, high=100_000)
        up = np.linspace(0.0, amplitude, points)
        down = up[::-1]
        solid = self.solid_stiffness * np.maximum(up - self.travel, 0.0)
        f_up = self.loading_stiffness * up + solid
        f_down = self.unloading_stiffness * down + solid[::-1]
        return DraftGearLoop(
            deflection=np.r_[up, down, 0.0],
            force=np.r_[f_up, f_down, 0.0],
            energy=self.loop_energy(amplitude),
        )


@dataclass(frozen=True)
class DraftGearLoop(Tabular):
    """A slow load–unload loop of a draft gear.

    Attributes
    ----------
    deflection : ndarray (2 points + 1,)
        Deflection around the closed loop, m.
    force : ndarray, shape of ``deflection``
        Force around the loop, N.
    energy : float
        Energy absorbed per cycle (the area of the loop), J.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("deflection", "m"), ("force", "N"))
    _scalars = (("energy", "J"),)

    deflection: np.ndarray
    force: np.ndarray
    energy: float

    def __post_init__(self):
        deflection = _checks.array("deflection", self.deflection, ndim=1, allow_empty=False)
        object.__setattr__(self, "deflection", deflection)
        object.__setattr__(self, "force", _checks.array("force", self.force, shape=deflection.shape))
        object.__setattr__(self, "energy", _checks.scalar("energy", self.energy))

    def plot(self, ax=None) -> dict:
        """Draw the loop (kN against mm) with its area shaded.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default.

        Returns
        -------
        dict
            The artists: ``line`` (the loop) and ``area`` (the shaded energy).
        """
        import matplotlib

        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            (area,) = ax.fill(1e3 * self.deflection, self.force / 1e3, color=plots.COLORS[0], alpha=0.2)
            (line,) = ax.plot(1e3 * self.deflection, self.force / 1e3, color=plots.COLORS[0])
            ax.set_xlabel("draft-gear deflection (mm)")
            ax.set_ylabel("force (kN)")
        return {"line": line, "area": area}
