"""The linear critical speed (book chapter 7): of one model, and over a grid of two parameters.

:func:`~raildyn.stability.linear.critical_speed` finds the lowest speed where the largest real
part of a model's eigenvalues crosses zero and the mode that loses stability there;
:func:`~raildyn.stability.linear.critical_speed_map` does so over a grid of two parameters, up
to 64 models in one search. Both run the batched search of :mod:`raildyn.stability.search`.

Their names are documented, and imported, through :mod:`raildyn.stability.linear` too.
"""

from __future__ import annotations

import cmath
import numbers
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._checks import array, integer, positive
from raildyn._progress import progress_bar
from raildyn._tables import Tabular
from raildyn.linear_model import LinearSystem, as_linear_system
from raildyn.stability.search import (
    CRITICAL_SPEED_STATUSES,
    MAX_SCAN_SPEEDS,
    StateMatrices,
    _crossings,
    _range,
    critical_speeds,
)

__all__ = ["CriticalSpeed", "CriticalSpeedMap", "critical_speed", "critical_speed_map"]


@dataclass(frozen=True)
class CriticalSpeed:
    """The linear critical speed of a model within a range of speeds.

    Attributes
    ----------
    speed : float
        V_c, m/s (> 0): the lowest speed where max Re s_r crosses zero upwards.
        ``inf`` when stable over the whole range; the lower end of the range
        when unstable already there (see ``status``).
    frequency_hz : float
        Frequency of the mode that loses stability, |Im s_r|/2π, Hz (≥ 0; nan when none does).
    eigenvalue : complex
        That mode's eigenvalue at V_c, 1/s (a real number is a complex one with no imaginary part).
    status : str
        "crossing", "stable over the range" or "unstable at the lowest speed".
    mode_shape : complex ndarray (n,)
        The displacement part of that mode's eigenvector at V_c, largest entry of modulus 1
        (as ``ModeSweep.shapes``); NaN when no mode loses stability in the range.
    coordinates : tuple of str
        Name of each entry of ``mode_shape``.

    The inf and NaN stand only with the status "stable over the range": every other
    value is finite.
    """

    speed: float
    frequency_hz: float
    eigenvalue: complex
    status: str
    mode_shape: np.ndarray
    coordinates: tuple

    def __post_init__(self):
        _checks.choice("status", self.status, CRITICAL_SPEED_STATUSES)
        n = len(_checks.strings("coordinates", self.coordinates))
        if self.status == "stable over the range":  # no mode loses stability: nothing to give
            if self.speed != np.inf:
                raise ValueError(f"speed must be inf when the status is {self.status!r}, got {self.speed!r}")
            if np.shape(self.mode_shape) != (n,):
                raise ValueError(f"mode_shape must have shape ({n},), got {np.shape(self.mode_shape)}")
            return
        _checks.speed("speed", self.speed)
        _checks.nonnegative("frequency_hz", self.frequency_hz)
        if isinstance(self.eigenvalue, (str, bytes, bool)) or not isinstance(self.eigenvalue, numbers.Number):
            raise TypeError(f"eigenvalue must be a complex number, got {self.eigenvalue!r:.80}")
        if not cmath.isfinite(self.eigenvalue):
            raise ValueError(f"eigenvalue must be finite, got {self.eigenvalue!r}")
        shape = _checks.array("mode_shape", self.mode_shape, shape=(n,), dtype=complex)
        if abs(np.abs(shape).max() - 1.0) > 1e-6:
            raise ValueError(
                f"mode_shape must have its largest entry of modulus 1, got {np.abs(shape).max()!r}"
            )

    def amplitude(self, coordinate: str) -> float:
        """|entry| of the hunting mode's shape on one coordinate (largest entry of the shape 1).

        Parameters
        ----------
        coordinate : str
            One of ``coordinates``.

        Returns
        -------
        float
            In the coordinate's unit per unit of the largest entry (m or rad).
        """
        _checks.choice("coordinate", coordinate, self.coordinates)
        return float(abs(self.mode_shape[self.coordinates.index(coordinate)]))

    @property
    def found(self) -> bool:
        """True when the largest real part crosses zero inside the range (``status`` "crossing")."""
        return self.status == "crossing"


def critical_speed(model, speed_range=(1.0, 150.0), *, tol: float = 0.01, scan: int = 64) -> CriticalSpeed:
    """The linear critical speed: where the largest real part of the eigenvalues first becomes positive.

    A coarse batched scan of ``scan`` speeds brackets the first upward zero of
    g(V) = max Re s_r(V), which a bracketed refinement (regula falsi, Illinois variant, with
    bisection where it stalls) narrows to ``tol`` m/s. The scan ends at that bracket (the speeds
    above it are not needed).

    Parameters
    ----------
    model : LinearModel or LinearSystem
        A linear model of :mod:`raildyn.wheelset` or :mod:`raildyn.vehicles`, or its system.
    speed_range : (float, float)
        Lowest and highest speed, m/s (0 < low < high).
    tol : float
        Absolute tolerance on V_c, m/s (> 0; default 0.01, well inside 0.1 m/s).
    scan : int
        Number of speeds in the coarse scan, in [8, 10 000] (the refinement narrows the
        bracket, so more speeds only cost time).

    Returns
    -------
    CriticalSpeed
        V_c (m/s), the frequency (Hz) and eigenvalue (1/s) of the mode that loses stability
        there, and whether a crossing was found in the range.

    Examples
    --------
    >>> from raildyn.wheelset import Wheelset
    >>> cs = critical_speed(Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6), (1.0, 200.0))
    >>> cs.status, round(cs.speed, 1), round(cs.frequency_hz, 2)
    ('crossing', 54.5, 5.3)
    """
    system = as_linear_system(model)
    low, high = _range(speed_range)
    positive("tol", tol)
    integer("scan", scan, low=8, high=MAX_SCAN_SPEEDS)
    state = StateMatrices.of(system)
    (status,), (speed,) = _crossings(state, low, high, tol, scan)
    n = system.size
    if status == "stable over the range":
        return CriticalSpeed(
            np.inf, np.nan, complex(np.nan, np.nan), status, np.full(n, np.nan + 0j), system.labels
        )
    lam, vec = np.linalg.eig(state.state_matrices([speed])[0])
    j = int(np.argmax(lam.real))
    shape = vec[:n, j] / vec[:n, j][np.argmax(np.abs(vec[:n, j]))]
    frequency = float(abs(lam[j].imag) / (2 * np.pi))
    return CriticalSpeed(float(speed), frequency, complex(lam[j]), status, shape, system.labels)


@dataclass(frozen=True)
class CriticalSpeedMap(Tabular):
    """Critical speed over a grid of two parameters.

    Attributes
    ----------
    x, y : ndarray
        The two parameter grids (units of the parameters; finite, at least one value each).
    speeds : ndarray (len(y), len(x))
        V_c, m/s (> 0; inf where stable over the range).
    x_name, y_name : str
        Names of the two parameters (with their units), used as axis labels.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units; the
    # map as laid out, a row for each y, a column of speeds for each x ("speeds[x=0.5] (m/s)").
    _columns = (("y", "units of the parameters"), ("speeds", "m/s"))
    _scalars = (("x_name", "-"), ("y_name", "-"))  # what x and y are, with their units
    _labels = (("speeds", "x"),)

    x: np.ndarray
    y: np.ndarray
    speeds: np.ndarray
    x_name: str
    y_name: str

    def __post_init__(self):
        nx = _checks.array("x", self.x, ndim=1, allow_empty=False).size
        ny = _checks.array("y", self.y, ndim=1, allow_empty=False).size
        # inf where stable over the range: the one non-finite value a critical speed may take
        speeds = _checks._numbers("speeds", self.speeds)
        speeds = _checks.array("speeds", np.where(np.isposinf(speeds), 1.0, speeds), shape=(ny, nx))
        _checks.plausible_array("speeds", speeds, "speed", low_open=True)  # or inf, taken as 1 above
        for name in ("x_name", "y_name"):
            _checks.instance(name, getattr(self, name), str, "string")

    def plot(self, ax=None, *, levels=None, cmap: str = "viridis") -> dict:
        """Draw the critical speed (km/h) as filled contours over the two parameters.

        Critical speeds above the highest level (and ``inf``, no crossing in the range) are
        shown in the colour of the highest level.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default.
        levels : array_like, optional
            Contour levels, km/h (at least two, strictly increasing); by default 50 km/h apart
            up to the largest finite critical speed.
        cmap : str
            Name of a matplotlib colour map.

        Returns
        -------
        dict
            The artists: ``contours`` (the ``QuadContourSet``) and ``colorbar``.
        """
        import matplotlib

        from raildyn import plots

        if isinstance(cmap, str) and cmap not in matplotlib.colormaps:
            raise ValueError(f"cmap must name a matplotlib colour map (matplotlib.colormaps), got {cmap!r}")
        _checks.instance("cmap", cmap, str, "string, the name of a colour map")
        kmh = 3.6 * self.speeds
        finite = kmh[np.isfinite(kmh)]
        if levels is None:
            top = finite.max() if finite.size else 50.0
            levels = np.arange(0.0, 50.0 * np.ceil(top / 50.0) + 50.0, 50.0)
        levels = _checks.increasing("levels", levels)
        if levels.size < 2:
            raise ValueError(f"levels must hold at least two levels, got {levels}")
        if self.x.size < 2 or self.y.size < 2:
            raise ValueError(
                f"a contour plot needs two values of x and of y at least, got {self.speeds.shape}"
            )
        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            contours = ax.contourf(self.x, self.y, np.minimum(kmh, levels[-1]), levels=levels, cmap=cmap)
            bar = ax.figure.colorbar(contours, ax=ax, label="critical speed (km/h)")
            ax.set_xlabel(self.x_name)
            ax.set_ylabel(self.y_name)
        return {"contours": contours, "colorbar": bar}

    def plot_curves(self, ax=None, *, artists: dict | None = None, **style) -> dict:
        """Draw the critical speed (km/h) against the first parameter, one line per value of the second.

        Where there is no crossing in the range (``inf``) the line is left blank.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default. Ignored when ``artists`` is given.
        artists : dict, optional
            The artists an earlier call returned: their data are replaced in place
            (``set_data``) and nothing is drawn anew.
        **style
            Passed to ``Axes.plot`` (``label``, ``color``, ``marker``, ``ls``...). Without a
            ``label``, each line is labelled with its value of the second parameter.

        Returns
        -------
        dict
            ``{"lines": [Line2D, ...]}``, one line per value of ``y``.

        Examples
        --------
        >>> from matplotlib.figure import Figure
        >>> from raildyn.wheelset import Wheelset
        >>> grid = critical_speed_map(
        ...     lambda lam, k: Wheelset(conicity=lam, yaw_stiffness=k, lateral_stiffness=1.0e6),
        ...     [0.1, 0.2],
        ...     [2.0e6],
        ...     (1.0, 200.0),
        ...     x_name="conicity λ",
        ...     y_name="k_ψ (N·m/rad)",
        ...     progress=False,
        ... )
        >>> line = grid.plot_curves(Figure().subplots(), label="wheelset")["lines"][0]
        >>> line.get_ydata().round(0)
        array([244., 168.])
        """
        import matplotlib.lines

        try:  # a keyword that is no line property is refused before anything is drawn
            matplotlib.lines.Line2D([], [], **style)
        except AttributeError as err:
            raise TypeError(f"style: {err} (keywords must be properties of matplotlib's Line2D)") from None
        kmh = 3.6 * self.speeds
        rows = np.where(np.isfinite(kmh), kmh, np.nan)
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
            if len(artists["lines"]) != rows.shape[0]:
                raise ValueError(
                    f"artists were drawn for {len(artists['lines'])} lines; this map has {rows.shape[0]}"
                )
            for line, row in zip(artists["lines"], rows, strict=True):
                line.set_data(self.x, row)
            return artists
        import matplotlib

        from raildyn import plots

        ax = plots.axes_or_new(ax)
        lines = []
        with matplotlib.rc_context(plots.STYLE):
            for y, row in zip(self.y, rows, strict=True):
                kwargs = {"label": f"{self.y_name} = {y:g}"} | style
                lines.append(ax.plot(self.x, row, **kwargs)[0])
            ax.set_xlabel(self.x_name)
            ax.set_ylabel("critical speed (km/h)")
        return {"lines": lines}


_MAP_CHUNK = 64  # grid points searched together: one eigenvalue call a step for all of them


def _search_together(built: list, out: np.ndarray, low: float, high: float, tol: float, scan: int) -> None:
    """out[j, i] = the critical speed of each (j, i, system) of ``built``, systems of one size at once."""
    found = critical_speeds([system for *_, system in built], (low, high), tol=tol, scan=scan)
    for (j, i, _), v in zip(built, found.speeds, strict=True):
        out[j, i] = v


def critical_speed_map(
    factory: Callable[[float, float], object],
    x,
    y,
    speed_range=(1.0, 150.0),
    *,
    x_name: str = "x",
    y_name: str = "y",
    tol: float = 0.05,
    scan: int = 64,
    progress: bool = True,
) -> CriticalSpeedMap:
    """Critical speed for every pair of parameters: ``factory(x_i, y_j)`` gives the model.

    Example: critical speed against conicity and primary yaw stiffness,
    ``factory = lambda lam, k: car.replace(conicity=lam, yaw_stiffness=k)``.
    Each model has the critical speed of :func:`critical_speed` (the same search, the same
    numbers); up to 64 models are searched together, one batched eigenvalue call a step.

    Parameters
    ----------
    factory : callable
        ``factory(x_value, y_value)`` returns a linear model (or system). A ValueError or
        TypeError it raises is raised again with the values of x and y that caused it.
    x : array_like, shape (nx,)
        Values of the first parameter (its own unit; finite, at least one).
    y : array_like, shape (ny,)
        Values of the second parameter (its own unit; finite, at least one).
    speed_range : (float, float)
        Lowest and highest speed searched, m/s (0 < low < high).
    x_name : str
        Name (and unit) of the first parameter, for the plots.
    y_name : str
        Name (and unit) of the second parameter.
    tol : float
        Absolute tolerance on each critical speed, m/s (> 0).
    scan : int
        Number of speeds in each coarse scan, in [8, 10 000].
    progress : bool
        Show a progress bar.

    Returns
    -------
    CriticalSpeedMap
        The critical speeds, m/s, shape (ny, nx) (``inf`` where stable over the range).
    """
    _checks.function("factory", factory)
    xs = array("x", np.atleast_1d(x), ndim=1, allow_empty=False)
    ys = array("y", np.atleast_1d(y), ndim=1, allow_empty=False)
    low, high = _range(speed_range)
    for name, value in (("x_name", x_name), ("y_name", y_name)):
        _checks.instance(name, value, str, "string")
    positive("tol", tol)
    integer("scan", scan, low=8, high=MAX_SCAN_SPEEDS)
    out = np.empty((ys.size, xs.size))
    pairs = [(j, i) for j in range(ys.size) for i in range(xs.size)]
    if _checks.flag("progress", progress):
        pairs = progress_bar(pairs, desc="critical speed map")
    built: list = []  # (j, i, system) not yet searched: up to a chunk, searched together
    for count, (j, i) in enumerate(pairs, start=1):
        xi, yj = float(xs[i]), float(ys[j])
        where = f"x[{i}] = {xi!r}, y[{j}] = {yj!r}"
        try:
            model = factory(xi, yj)
        except (ValueError, TypeError) as err:
            kind = ValueError if isinstance(err, ValueError) else TypeError
            raise kind(f"factory failed at {where}: {err}") from err
        if not isinstance(model, LinearSystem) and not callable(getattr(model, "linear_system", None)):
            raise TypeError(f"factory must return a linear model, returned {model!r:.80} at {where}")
        built.append((j, i, as_linear_system(model)))
        if len(built) == _MAP_CHUNK or count == xs.size * ys.size:
            _search_together(built, out, low, high, tol, scan)
            built = []
    return CriticalSpeedMap(xs, ys, out, x_name, y_name)
