"""The free-decay results the single-degree-of-freedom oscillator returns, with their plot.

:class:`DecayPeaks` (the maxima of a free decay, with their logarithmic decrement) and
:class:`FreeVibration` (a free response with its envelope and peaks, ``.plot``). SI units.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._checks import array, time_grid
from raildyn._tables import Tabular
from raildyn.vibration.sdof_curves import decrement_from_peaks

__all__ = [
    "DecayPeaks",
    "FreeVibration",
]


@dataclass(frozen=True)
class DecayPeaks(Tabular):
    """Successive maxima of an underdamped free response (book Fig. 1.5).

    Attributes
    ----------
    times : ndarray, shape (count,)
        Times of the maxima, s, one damped period T_d apart.
    values : ndarray, shape (count,)
        Displacements there, m (or the unit of x0).
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("times", "s"), ("values", "m"))

    times: np.ndarray
    values: np.ndarray

    def __post_init__(self):
        times = array("times", self.times, ndim=1, low=0.0)
        values = array("values", self.values)
        if values.shape != times.shape:
            raise ValueError(
                f"times and values must have the same shape, got {times.shape} and {values.shape}"
            )
        object.__setattr__(self, "times", times)
        object.__setattr__(self, "values", values)

    @property
    def log_decrement(self) -> float:
        """δ = ln(x₁/x_{j+1})/j measured over the j periods between the first and the last peak (eq. 1.17).

        Needs at least two peaks; equal to :attr:`~raildyn.vibration.SDOF.log_decrement` to rounding.
        """
        return decrement_from_peaks(self.values[0], self.values[-1], cycles=self.values.size - 1)


@dataclass(frozen=True)
class FreeVibration(Tabular):
    """The free response of an SDOF system on a time grid, with its envelope and its maxima.

    Built by :meth:`SDOF.free_vibration`; :meth:`plot` draws it as book Fig. 1.5.

    Attributes
    ----------
    time : ndarray, shape (n,)
        t, s.
    displacement : ndarray, shape (n,)
        x(t), in the unit of x0 (m).
    envelope : ndarray, shape (n,)
        A e^(−ξω_n t) when the system oscillates, else |x(t)|; same unit.
    peaks : DecayPeaks
        The first maxima (empty arrays when ξ >= 1: no oscillation, no peaks).
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("time", "s"), ("displacement", "m"), ("envelope", "m"))

    time: np.ndarray
    displacement: np.ndarray
    envelope: np.ndarray
    peaks: DecayPeaks

    def __post_init__(self):
        time = array("time", time_grid("time", self.time), low=0.0)
        object.__setattr__(self, "time", time)
        object.__setattr__(self, "displacement", array("displacement", self.displacement, shape=time.shape))
        object.__setattr__(self, "envelope", array("envelope", self.envelope, shape=time.shape, low=0.0))
        _checks.instance("peaks", self.peaks, DecayPeaks)

    def plot(self, ax=None, *, artists=None) -> dict:
        """Draw x(t), the envelope ±A e^(−ξω_n t) and the maxima; or move artists drawn before.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        artists : dict, optional
            The dict a previous call returned: its lines are moved to this
            response (``set_data``) instead of drawing new ones, as a widget does.

        Returns
        -------
        dict
            The artists: ``line``, ``upper``, ``lower`` (the envelope) and ``peaks``.
        """
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict returned by an earlier plot")
            missing = {"line", "upper", "lower", "peaks"} - set(artists)
            if missing:
                raise ValueError(
                    f"artists must be the dict an earlier plot returned; it lacks {sorted(missing)}"
                )
            artists["line"].set_data(self.time, self.displacement)
            artists["upper"].set_data(self.time, self.envelope)
            artists["lower"].set_data(self.time, -self.envelope)
            artists["peaks"].set_data(self.peaks.times, self.peaks.values)
            return artists
        import matplotlib

        from raildyn import plots

        drawn = plots.time_history(self.time, self.displacement, ax=ax, envelope=self.envelope)
        ax = drawn["line"].axes
        with matplotlib.rc_context(plots.STYLE):
            (drawn["peaks"],) = ax.plot(
                self.peaks.times, self.peaks.values, "s", color=plots.COLORS[1], ms=6, label="maxima"
            )
        return drawn
