"""The statistics of acceptance testing: percentiles, sliding RMS, maxima per section (chapter 11).

UIC 518 and EN 14363 judge a vehicle's running by statistics of measured or simulated records:
:func:`percentiles` (0.15 % and 99.85 % of each test section), :func:`sliding_rms` and
:func:`section_maxima`.

References
----------
* R. J. Hyndman and Y. Fan, "Sample quantiles in statistical packages", *The American
  Statistician* 50(4), 361–365, 1996 (definition 7: numpy's default percentile).
* UIC 518 (4th ed., 2009) and EN 14363:2016, *Railway applications — Testing and
  simulation for the acceptance of running characteristics of railway vehicles*:
  the 0.15 % and 99.85 % percentiles of each test section, sliding means and sliding
  r.m.s. values (as tabulated for UIC 518 / EN 14363 in the GENSYS course notes,
  gensys.se/course/UIC518_tests.html; the clause numbers of EN 14363:2016 are not
  checked here).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.plots import COLORS, STYLE, axes_or_new
from raildyn.validation import _records

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib

__all__ = ["SectionMaxima", "SlidingRMS", "percentiles", "section_maxima", "sliding_rms"]


def percentiles(record, percent=(0.15, 99.85)) -> np.ndarray:
    """Percentiles of a record, in its unit: by default the 0.15 % and 99.85 % of acceptance tests.

    UIC 518 and EN 14363 characterise the dynamic quantities of each test section (wheel
    forces, Y/Q, accelerations) by their 0.15 % and 99.85 % percentiles, and the
    quasi-static ones by the 50 % percentile (see the module's references). The
    percentile here is numpy's linear interpolation between order statistics
    (Hyndman & Fan 1996, definition 7); whether it matches the standards' own rule to the
    sample is not checked here.

    Parameters
    ----------
    record : array_like, shape (n,)
        The (filtered) record of one section, any unit, finite, n >= 1.
    percent : array_like, shape (k,)
        Percentages in [0, 100].

    Returns
    -------
    ndarray, shape (k,)
        The percentiles, in the unit of ``record``.

    Examples
    --------
    >>> percentiles(np.arange(10001.0), (0.15, 50.0, 99.85)).tolist()
    [15.0, 5000.0, 9985.0]
    """
    x = _records.record("record", record, min_size=1)
    q = _records.percent("percent", percent)
    return np.percentile(x, q)


@dataclass(frozen=True)
class SlidingRMS(Tabular):
    """A sliding RMS of a record (:func:`sliding_rms`).

    Attributes
    ----------
    position : ndarray, shape (k,)
        Centre of each window from the first sample, in the unit of the spacing (s or m).
    rms : ndarray, shape (k,)
        RMS over each window, >= 0, in the record's unit.
    window : float
        The window length, s or m, > 0.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("position", "s or m"), ("rms", "record's unit"))
    _scalars = (("window", "s or m"),)

    position: np.ndarray
    rms: np.ndarray
    window: float

    def __post_init__(self):
        pos = _checks.increasing("position", self.position, low=0.0)
        object.__setattr__(self, "position", pos)
        object.__setattr__(self, "rms", _checks.array("rms", self.rms, shape=pos.shape, low=0.0))
        object.__setattr__(self, "window", _checks.positive("window", self.window))

    def plot(self, ax=None, *, label: str | None = None, color=COLORS[0]) -> dict:
        """The sliding RMS against the window centre.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes if None.
        label : str, optional
            Legend label.
        color : color
            Line colour.

        Returns
        -------
        dict
            ``{"line": line}``.
        """
        import matplotlib

        ax = axes_or_new(ax)
        with matplotlib.rc_context(STYLE):
            (line,) = ax.plot(self.position, self.rms, color=color, label=label)
            ax.set_xlabel("window centre (s or m)")
            ax.set_ylabel(f"sliding RMS over {self.window:g}")
        return {"line": line}


def sliding_rms(record, spacing, window, *, step=None) -> SlidingRMS:
    """The RMS of a record over a window sliding along it.

    r_j = √((1/w) Σ_{i = jk}^{jk + w − 1} x_i²), w = window/spacing samples, k = step/spacing
    (both rounded to whole samples). UIC 518 and EN 14363 use sliding r.m.s. values
    of filtered bogie-frame accelerations and track forces to detect running instability
    (module references); the window and step the standard prescribes are inputs here.
    The record is in time (spacing and window in s) or along the track (in m): one unit
    for both.

    Parameters
    ----------
    record : array_like, shape (n,)
        The record, any unit, finite, n >= 1 (filter it to the band of interest first).
    spacing : float
        Sample spacing, s or m, > 0.
    window : float
        Window length in the unit of ``spacing``, spanning 1 to n samples.
    step : float, optional
        Advance from one window to the next, in the unit of ``spacing``, at least one
        sample; default one sample.

    Returns
    -------
    SlidingRMS
        Window centres and RMS values.

    Examples
    --------
    The RMS of a unit sine over whole periods is 1/√2 wherever the window sits:

    >>> s = np.arange(2000) * 0.5  # every 0.5 m
    >>> r = sliding_rms(np.sin(2 * np.pi * s / 20.0), 0.5, 100.0, step=10.0)
    >>> bool(np.allclose(r.rms, np.sqrt(0.5)))
    True
    """
    x = _records.record("record", record, min_size=1)
    spacing = _checks.positive("spacing", spacing)
    window = _checks.positive("window", window)
    w = _records.samples("window", window, spacing, x.size, "window length")
    k = (
        1
        if step is None
        else _records.samples("step", _checks.positive("step", step), spacing, x.size, "step")
    )
    u, s = _records.scaled(x)
    energy = np.concatenate(([0.0], np.cumsum(u * u)))
    starts = np.arange(0, x.size - w + 1, k)
    mean_square = np.maximum(energy[starts + w] - energy[starts], 0.0) / w
    return SlidingRMS((starts + 0.5 * (w - 1)) * spacing, s * np.sqrt(mean_square), w * spacing)


@dataclass(frozen=True)
class SectionMaxima(Tabular):
    """Extremes (or percentiles) of a record section by section (:func:`section_maxima`).

    Attributes
    ----------
    start : ndarray, shape (k,)
        Where each section begins, from the first sample, in the unit of the spacing (s or m).
    lower, upper : ndarray, shape (k,)
        The lower and upper statistic of each section (minimum and maximum, or the
        percentiles asked for), in the record's unit; lower <= upper.
    length : float
        Section length, s or m, > 0.
    percent : ndarray, shape (2,)
        The percentiles taken, in [0, 100] ((0, 100): the extremes).
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("start", "s or m"), ("lower", "record's unit"), ("upper", "record's unit"))
    _scalars = (("length", "s or m"),)

    start: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    length: float
    percent: np.ndarray

    def __post_init__(self):
        start = _checks.increasing("start", self.start, low=0.0)
        object.__setattr__(self, "start", start)
        for name in ("lower", "upper"):
            object.__setattr__(self, name, _checks.array(name, getattr(self, name), shape=start.shape))
        if np.any(self.lower > self.upper):
            raise ValueError("lower must not exceed upper in any section")
        object.__setattr__(self, "length", _checks.positive("length", self.length))
        object.__setattr__(self, "percent", _records.percent("percent", self.percent, pair=True))

    def plot(self, ax=None, *, color=COLORS[0]) -> dict:
        """The lower and upper statistic of each section as steps along the record.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes if None.
        color : color
            Colour of both steps.

        Returns
        -------
        dict
            The step artists ``lower`` and ``upper``.
        """
        import matplotlib

        ax = axes_or_new(ax)
        edges = np.append(self.start, self.start[-1] + self.length)
        lo, hi = (f"{q:g} %" for q in self.percent)
        with matplotlib.rc_context(STYLE):
            upper = ax.stairs(self.upper, edges, color=color, label=f"section {hi}")
            lower = ax.stairs(self.lower, edges, color=color, ls="--", label=f"section {lo}")
            ax.set_xlabel("position along the record (s or m)")
            ax.legend()
        return {"lower": lower, "upper": upper}


def section_maxima(record, spacing, length, *, percent=(0.0, 100.0)) -> SectionMaxima:
    """The extremes, or two percentiles, of a record in consecutive sections of a given length.

    The record is cut into ⌊n/m⌋ sections of m = length/spacing samples (rounded); a
    shorter tail is left out. Each section gives its ``percent`` percentiles (numpy's
    linear rule, as in :func:`percentiles`): (0, 100), the default, is the minimum and
    maximum; (0.15, 99.85) are the per-section values of UIC 518 and EN 14363, whose
    test zones are evaluated section by section (module references).

    Parameters
    ----------
    record : array_like, shape (n,)
        The record, any unit, finite, n >= 1.
    spacing : float
        Sample spacing, s or m, > 0.
    length : float
        Section length in the unit of ``spacing``, spanning 1 to n samples.
    percent : array_like, shape (2,)
        The lower and upper percentiles, in [0, 100], lower <= upper.

    Returns
    -------
    SectionMaxima
        Section starts and the lower and upper statistic of each.

    Examples
    --------
    >>> sm = section_maxima([0.0, 3.0, -1.0, 2.0, 5.0, -4.0, 9.0], 1.0, 3.0)
    >>> sm.upper.tolist(), sm.lower.tolist()
    ([3.0, 5.0], [-1.0, -4.0])
    """
    x = _records.record("record", record, min_size=1)
    spacing = _checks.positive("spacing", spacing)
    length = _checks.positive("length", length)
    q = _records.percent("percent", percent, pair=True)
    m = _records.samples("length", length, spacing, x.size, "section length")
    k = x.size // m
    sections = x[: k * m].reshape(k, m)
    lower, upper = np.percentile(sections, q, axis=1)
    return SectionMaxima(np.arange(k) * m * spacing, lower, upper, m * spacing, q)
