"""Lateral stability (book chapter 7): eigenvalues against speed, mode tracking, critical speed, hunting.

The linear models of :mod:`raildyn.wheelset` and :mod:`raildyn.vehicles`
follow the one protocol (:class:`raildyn.linear_model.LinearModel`), and their
systems read M q̈ + (C₀ + C₁/V) q̇ + K q = 0 without the track,
so the state matrix at every speed of a sweep is built at once and all
eigenvalues come from one batched ``numpy.linalg`` call.

* :func:`eigenvalues_against_speed` — every eigenvalue at every speed;
* :func:`mode_sweep` — eigenvalues, frequencies and damping ratios with each
  mode followed across speed by its modal assurance criterion (MAC), so
  that crossing branches keep their labels;
* :func:`critical_speed` — the lowest speed at which the largest real part
  becomes positive, by a batched coarse scan and Brent's method;
* :func:`critical_speed_map` — the critical speed over a grid of two parameters;
* :func:`limit_cycle_amplitude`, :func:`bifurcation_diagram` — nonlinear hunting:
  the amplitude of the limit cycle against speed and the nonlinear critical speed.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import scipy.optimize

from raildyn._checks import array, integer, positive, scalar
from raildyn._progress import progress_bar
from raildyn.errors import SolverError
from raildyn.linear_model import as_linear_system

__all__ = [
    "BifurcationDiagram",
    "CriticalSpeed",
    "CriticalSpeedMap",
    "LimitCycle",
    "ModeSweep",
    "TrackedModes",
    "NonlinearRun",
    "PeriodicOrbit",
    "bifurcation_diagram",
    "critical_speed",
    "critical_speed_map",
    "eigenvalues_against_speed",
    "largest_real_part",
    "limit_cycle_amplitude",
    "mac",
    "mode_sweep",
    "simulate",
    "periodic_orbit",
    "track_modes",
]


def _speeds(speeds) -> np.ndarray:
    V = array("speeds", np.atleast_1d(speeds), ndim=1)
    if V.size == 0:
        raise ValueError("speeds must hold at least one speed, got an empty array")
    if np.any(V <= 0):
        raise ValueError(f"speeds must all be > 0 m/s (creep forces divide by V), got {V[V <= 0][0]!r}")
    return V


def eigenvalues_against_speed(model, speeds) -> np.ndarray:
    """All 2n eigenvalues at each speed, from one batched ``numpy.linalg.eigvals`` call.

    The state matrix A(V) = [[0, I], [−M⁻¹K, −M⁻¹(C₀ + C₁/V)]] of
    M q̈ + (C₀ + C₁/V) q̇ + K q = 0 (book chapter 7) at every speed.

    Parameters
    ----------
    model : LinearModel or LinearSystem
        A linear model of :mod:`raildyn.wheelset` or :mod:`raildyn.vehicles`, or its system.
    speeds : array_like, shape (n_speeds,)
        Speeds V, m/s (> 0: the creep damping divides by V).

    Returns
    -------
    ndarray of complex, shape (n_speeds, 2n)
        The eigenvalues λ, 1/s, in no particular order at each speed.
    """
    V = _speeds(speeds)
    return np.linalg.eigvals(as_linear_system(model).state_matrices(V))


def largest_real_part(model, speeds) -> np.ndarray:
    """The largest real part of the eigenvalues at each speed: positive where the model is unstable.

    Parameters
    ----------
    model : LinearModel or LinearSystem
        A linear model, or its system.
    speeds : array_like, shape (n_speeds,)
        Speeds V, m/s (> 0).

    Returns
    -------
    ndarray, shape (n_speeds,)
        max Re λ, 1/s.
    """
    return eigenvalues_against_speed(model, speeds).real.max(axis=1)


# ---------------------------------------------------------------------------
# Mode tracking


def mac(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Modal assurance criterion between the columns of two sets of (complex) vectors.

    MAC(aᵢ, bⱼ) = |aᵢᴴ bⱼ|² / (|aᵢ|² |bⱼ|²): 1 for vectors that differ by a complex factor,
    0 for orthogonal ones.

    Parameters
    ----------
    a : array_like, shape (p, ka)
        Vectors as columns (any unit; the criterion is dimensionless).
    b : array_like, shape (p, kb)
        Vectors as columns, of the same length p.

    Returns
    -------
    ndarray, shape (ka, kb)
        The criterion, between 0 and 1, of every column of ``a`` with every column of ``b``.
    """
    a = np.asarray(a, dtype=complex)
    b = np.asarray(b, dtype=complex)
    num = np.abs(a.conj().T @ b) ** 2
    den = np.outer(np.sum(np.abs(a) ** 2, axis=0), np.sum(np.abs(b) ** 2, axis=0))
    return num / np.maximum(den, np.finfo(float).tiny)


@dataclass(frozen=True)
class TrackedModes:
    """Eigenvalues and vectors with each column following one mode across the speeds.

    Attributes
    ----------
    eigenvalues : complex ndarray, shape (n_speeds, m)
        1/s.
    vectors : complex ndarray, shape (n_speeds, p, m)
        Column k of ``vectors[i]`` belongs to ``eigenvalues[i, k]``.
    """

    eigenvalues: np.ndarray
    vectors: np.ndarray


def track_modes(eigenvalues: np.ndarray, vectors: np.ndarray) -> TrackedModes:
    """Reorder eigenvalues (and vectors) at each speed so that column j follows one mode.

    At each step the assignment that maximises the MAC of the state vectors
    with those of the previous speed is chosen (Hungarian algorithm), with the
    distance between eigenvalues, relative to their size, as a tie-breaker for
    conjugate partners, whose vectors are alike.

    Parameters
    ----------
    eigenvalues : complex ndarray, shape (n_speeds, m)
        Eigenvalues at each speed, 1/s.
    vectors : complex ndarray, shape (n_speeds, p, m)
        Eigenvectors (any unit): column k of ``vectors[i]`` belongs to ``eigenvalues[i, k]``.

    Returns
    -------
    TrackedModes
        The eigenvalues and vectors with the columns permuted at each speed.
    """
    lam = np.array(eigenvalues, dtype=complex, copy=True)
    vec = np.array(vectors, dtype=complex, copy=True)
    for i in range(1, lam.shape[0]):
        similarity = mac(vec[i - 1], vec[i])
        scale = np.maximum(np.abs(lam[i - 1])[:, None], 1.0)
        distance = np.abs(lam[i - 1][:, None] - lam[i][None, :]) / scale
        _, order = scipy.optimize.linear_sum_assignment((1.0 - similarity) + 0.5 * distance)
        lam[i] = lam[i, order]
        vec[i] = vec[i][:, order]
    return TrackedModes(lam, vec)


@dataclass(frozen=True)
class ModeSweep:
    """Modes of a lateral model across speed, each column one mode followed by MAC.

    Attributes
    ----------
    speeds : ndarray (n_speeds,)
        m/s.
    eigenvalues : complex ndarray (n_speeds, k)
        λ, 1/s; only the roots with Im λ ≥ 0 at the first speed are kept (one of each pair).
    frequencies_hz : ndarray (n_speeds, k)
        Damped frequency |Im λ|/2π, Hz.
    damping_ratios : ndarray (n_speeds, k)
        ξ = −Re λ/|λ| (negative when the mode is unstable).
    shapes : complex ndarray (n_speeds, n, k)
        Displacement part of each eigenvector, largest entry 1.
    labels : tuple of str
        For each mode, the coordinate that carries the largest share of its kinetic
        energy at the first speed (the shape weighted by the mass matrix).
    coordinates : tuple of str
        The model's coordinate names.
    """

    speeds: np.ndarray
    eigenvalues: np.ndarray
    frequencies_hz: np.ndarray
    damping_ratios: np.ndarray
    shapes: np.ndarray
    labels: tuple
    coordinates: tuple

    @property
    def hunting_mode(self) -> int:
        """Column of the mode least damped at the highest speed (the hunting mode of a vehicle)."""
        return int(np.argmin(self.damping_ratios[-1]))

    def plot(
        self,
        ax=None,
        *,
        critical: CriticalSpeed | None = None,
        artists: dict | None = None,
        real_limits: tuple[float, float] | None = (-25.0, 5.0),
        imag_limits: tuple[float, float] | None = (0.0, 70.0),
        damping_limits: tuple[float, float] | None = (-0.15, 0.5),
    ) -> dict:
        """Draw the roots against speed (left) and the damping factor of every mode (right).

        Left: every root λ of the sweep in the complex plane, coloured by speed (km/h). Right:
        the damping factor ξ of each mode against speed (km/h), grey, with the mode least
        damped at the highest speed (:attr:`hunting_mode`) in colour and the critical speed
        marked on ξ = 0 with its speed and frequency. The default windows show the roots
        that decide a railway vehicle's stability: near the imaginary axis and below about
        11 Hz (70 rad/s).

        Parameters
        ----------
        ax : sequence of two matplotlib Axes, optional
            The axes of the roots and of the damping factors; a new figure with two axes side
            by side if None. Ignored when ``artists`` is given.
        critical : CriticalSpeed, optional
            The critical speed to mark (from :func:`critical_speed` on the same model); nothing
            is marked if None or if it was not found.
        artists : dict, optional
            The artists an earlier call returned: they are moved to this sweep's data in place
            (``set_offsets``, ``set_data``, ``set_text``) and nothing is drawn anew; the sweep
            must have as many modes as the one drawn first.
        real_limits : (float, float) or None
            Range of Re λ shown, 1/s; None to fit the data.
        imag_limits : (float, float) or None
            Range of Im λ shown, rad/s; None to fit the data.
        damping_limits : (float, float) or None
            Range of ξ shown (dimensionless); None to fit the data.

        Returns
        -------
        dict
            The artists: ``roots`` (the ``PathCollection`` of the roots), ``colorbar`` (its
            speed scale), ``modes`` (one ``Line2D`` per mode), ``hunting`` (the ``Line2D`` of
            the hunting mode), ``critical`` (the marker, a ``Line2D``, empty when there is no
            crossing) and ``critical_text`` (its ``Annotation``: speed in km/h and frequency
            in Hz).

        Examples
        --------
        >>> from matplotlib.figure import Figure
        >>> from raildyn.wheelset import Wheelset
        >>> ws = Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)
        >>> sweep = mode_sweep(ws, np.linspace(2.0, 100.0, 50))
        >>> drawn = sweep.plot(Figure().subplots(1, 2), critical=critical_speed(ws, (2.0, 100.0)))
        >>> drawn["critical_text"].get_text()
        '197 km/h, 5.31 Hz'
        """
        kmh = 3.6 * self.speeds
        lam = self.eigenvalues
        offsets = np.column_stack([lam.real.ravel(), lam.imag.ravel()])
        colours = np.repeat(kmh, lam.shape[1])
        worst = self.hunting_mode
        if critical is not None and critical.found:
            mark = ([3.6 * critical.speed], [0.0])
            text = f"{3.6 * critical.speed:.0f} km/h, {critical.frequency_hz:.2f} Hz"
        else:
            mark, text = ([], []), ""
        if artists is not None:
            if len(artists["modes"]) != lam.shape[1]:
                raise ValueError(
                    f"artists were drawn for {len(artists['modes'])} modes; this sweep has {lam.shape[1]}"
                )
            artists["roots"].set_offsets(offsets)
            artists["roots"].set_array(colours)
            for line, xi in zip(artists["modes"], self.damping_ratios.T, strict=True):
                line.set_data(kmh, xi)
            artists["hunting"].set_data(kmh, self.damping_ratios[:, worst])
            artists["critical"].set_data(*mark)
            _place_critical_text(artists["critical_text"], mark, text)
            return artists
        import matplotlib

        from raildyn import plots

        if ax is None:
            import matplotlib.pyplot as plt

            with matplotlib.rc_context(plots.STYLE):
                _, ax = plt.subplots(1, 2, figsize=(10.0, 3.8), layout="constrained")
        ax_s, ax_d = ax
        with matplotlib.rc_context(plots.STYLE):
            roots = ax_s.scatter(
                offsets[:, 0], offsets[:, 1], s=2, c=colours, cmap="viridis", vmin=kmh[0], vmax=kmh[-1]
            )
            bar = ax_s.figure.colorbar(roots, ax=ax_s, label="speed (km/h)")
            ax_s.axvline(0.0, color="k", lw=0.8)
            ax_s.set_xlabel("Re λ (1/s)")
            ax_s.set_ylabel("Im λ (rad/s)")
            modes = [ax_d.plot(kmh, xi, color="0.75", lw=0.8)[0] for xi in self.damping_ratios.T]
            (hunting,) = ax_d.plot(
                kmh, self.damping_ratios[:, worst], color=plots.COLORS[1], lw=2, label="hunting mode"
            )
            (marker,) = ax_d.plot(*mark, "v", color="k", ms=8, label="critical speed")
            note = ax_d.annotate(
                "",
                (0.0, 0.0),
                xytext=(0.0, 8.0),
                textcoords="offset points",
                va="bottom",
                bbox={"fc": "white", "ec": "none", "alpha": 0.8, "pad": 1.0},
            )
            _place_critical_text(note, mark, text)
            ax_d.axhline(0.0, color="k", lw=0.8)
            ax_d.set_xlim(0.0, kmh[-1])
            ax_d.set_xlabel("speed (km/h)")
            ax_d.set_ylabel("damping factor ξ")
            ax_d.legend(loc="upper right")
        if real_limits is not None:
            ax_s.set_xlim(*real_limits)
        if imag_limits is not None:
            ax_s.set_ylim(*imag_limits)
        if damping_limits is not None:
            ax_d.set_ylim(*damping_limits)
        return {
            "roots": roots,
            "colorbar": bar,
            "modes": modes,
            "hunting": hunting,
            "critical": marker,
            "critical_text": note,
        }


def _place_critical_text(note, mark, text: str) -> None:
    """Move the critical speed's annotation to the marker, on the side of it with more room."""
    note.set_text(text)
    if not text:
        return
    x = mark[0][0]
    note.xy = (x, 0.0)
    low, high = note.axes.get_xlim()
    note.set_horizontalalignment("right" if x > 0.5 * (low + high) else "left")


def mode_sweep(model, speeds) -> ModeSweep:
    """Eigenvalues, frequencies and damping ratios of every mode against speed, modes tracked by MAC.

    All state matrices are solved in one batched ``numpy.linalg.eig`` call; the
    tracking then pairs each mode with its successor (:func:`track_modes`).

    Parameters
    ----------
    model : LinearModel or LinearSystem
        A linear model of :mod:`raildyn.wheelset` or :mod:`raildyn.vehicles`, or its system.
    speeds : array_like, shape (n_speeds,)
        Strictly increasing speeds, m/s (> 0).

    Returns
    -------
    ModeSweep
        Eigenvalues (1/s), damped frequencies (Hz), damping factors and shapes, one column per
        mode; draw them with :meth:`ModeSweep.plot`.

    Examples
    --------
    The suspended wheelset of chapter 5: its kinematic oscillation (the second mode) loses
    its damping as the speed rises and is unstable at 80 m/s.

    >>> from raildyn.wheelset import Wheelset
    >>> sweep = mode_sweep(Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6), [20.0, 50.0, 80.0])
    >>> sweep.labels
    ('wheelset ψ', 'wheelset y')
    >>> sweep.damping_ratios[:, 1].round(3)
    array([ 0.143,  0.024, -0.127])
    >>> sweep.frequencies_hz[-1].round(2)
    array([6.87, 6.98])
    """
    system = as_linear_system(model)
    V = _speeds(speeds)
    if np.any(np.diff(V) <= 0):
        raise ValueError("speeds must be strictly increasing for mode tracking")
    n = system.size
    lam, vec = np.linalg.eig(system.state_matrices(V))
    tracked = track_modes(lam, vec)
    lam, vec = tracked.eigenvalues, tracked.vectors
    # One root of each conjugate pair: the n roots highest in the upper half-plane at the first
    # speed (real roots fill in when some modes are overdamped), ordered by frequency.
    keep = np.argsort(-lam[0].imag, kind="stable")[:n]
    keep = keep[np.argsort(np.abs(lam[0, keep].imag), kind="stable")]
    lam, vec = lam[:, keep], vec[:, :n, keep]
    pivot = np.argmax(np.abs(vec), axis=1)
    scale = np.take_along_axis(vec, pivot[:, None, :], axis=1)
    shapes = vec / scale
    freq = np.abs(lam.imag) / (2 * np.pi)
    mag = np.abs(lam)
    ratio = np.divide(-lam.real, mag, out=np.zeros(mag.shape), where=mag > 0)
    names = system.labels or tuple(f"q{i}" for i in range(n))
    # Name each mode by the coordinate that carries most of its kinetic energy, Re(φ̄ᵢ (Mφ)ᵢ):
    # the largest entry of φ alone would weigh metres against radians.
    first = shapes[0]
    energy = np.real(np.conj(first) * (system.M @ first))
    labels = tuple(names[int(j)] for j in np.argmax(energy, axis=0))
    return ModeSweep(V, lam, freq, ratio, shapes, labels, tuple(names))


# ---------------------------------------------------------------------------
# Critical speed


@dataclass(frozen=True)
class CriticalSpeed:
    """The linear critical speed of a model within a range of speeds.

    Attributes
    ----------
    speed : float
        V_c, m/s: the lowest speed where max Re λ crosses zero upwards.
        ``inf`` when stable over the whole range; the lower end of the range
        when unstable already there (see ``status``).
    frequency_hz : float
        Frequency of the mode that loses stability, |Im λ|/2π, Hz (nan when none does).
    eigenvalue : complex
        That mode's eigenvalue at V_c, 1/s.
    status : str
        "crossing", "stable over the range" or "unstable at the lowest speed".
    mode_shape : complex ndarray (n,)
        The displacement part of that mode's eigenvector at V_c, largest entry 1 (as
        :attr:`ModeSweep.shapes`); NaN when no mode loses stability in the range.
    coordinates : tuple of str
        Name of each entry of ``mode_shape``.
    """

    speed: float
    frequency_hz: float
    eigenvalue: complex
    status: str
    mode_shape: np.ndarray
    coordinates: tuple

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
        if coordinate not in self.coordinates:
            raise ValueError(f"coordinate must be one of {self.coordinates}, got {coordinate!r}")
        return float(abs(self.mode_shape[self.coordinates.index(coordinate)]))

    @property
    def found(self) -> bool:
        """True when the largest real part crosses zero inside the range (``status`` "crossing")."""
        return self.status == "crossing"


def _range(speed_range) -> tuple[float, float]:
    r = np.asarray(speed_range, dtype=float).ravel()
    if r.size != 2:
        raise ValueError(f"speed_range must be (low, high) in m/s, got {speed_range!r}")
    low = scalar("speed_range[0]", float(r[0]), low=0.0, low_open=True)
    high = scalar("speed_range[1]", float(r[1]), low=low, low_open=True)
    return low, high


def critical_speed(model, speed_range=(1.0, 150.0), *, tol: float = 0.01, scan: int = 64) -> CriticalSpeed:
    """The linear critical speed: where the largest real part of the eigenvalues first becomes positive.

    A coarse batched scan of ``scan`` speeds brackets the first upward zero of
    g(V) = max Re λ(V), which Brent's method then refines to ``tol`` m/s.

    Parameters
    ----------
    model : LinearModel or LinearSystem
        A linear model of :mod:`raildyn.wheelset` or :mod:`raildyn.vehicles`, or its system.
    speed_range : (float, float)
        Lowest and highest speed, m/s (0 < low < high).
    tol : float
        Absolute tolerance on V_c, m/s (default 0.01, well inside 0.1 m/s).
    scan : int
        Number of speeds in the coarse scan (≥ 8).

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
    ('crossing', 54.6, 5.31)
    """
    system = as_linear_system(model)
    low, high = _range(speed_range)
    positive("tol", tol)
    integer("scan", scan, low=8)
    V = np.linspace(low, high, scan)
    g = largest_real_part(system, V)

    n = system.size

    def at(speed):
        lam = eigenvalues_against_speed(system, [speed])[0]
        j = int(np.argmax(lam.real))
        return lam[j]

    def result(speed, status):
        lam, vec = np.linalg.eig(system.state_matrices([speed])[0])
        j = int(np.argmax(lam.real))
        shape = vec[:n, j] / vec[:n, j][np.argmax(np.abs(vec[:n, j]))]
        frequency = float(abs(lam[j].imag) / (2 * np.pi))
        return CriticalSpeed(float(speed), frequency, complex(lam[j]), status, shape, system.labels)

    if g[0] >= 0.0:
        return result(low, "unstable at the lowest speed")
    up = np.flatnonzero((g[:-1] < 0.0) & (g[1:] >= 0.0))
    if up.size == 0:
        return CriticalSpeed(
            np.inf,
            np.nan,
            complex(np.nan, np.nan),
            "stable over the range",
            np.full(n, np.nan + 0j),
            system.labels,
        )
    i = int(up[0])
    speed = scipy.optimize.brentq(lambda v: at(v).real, V[i], V[i + 1], xtol=tol)
    return result(speed, "crossing")


@dataclass(frozen=True)
class CriticalSpeedMap:
    """Critical speed over a grid of two parameters.

    Attributes
    ----------
    x, y : ndarray
        The two parameter grids (units of the parameters).
    speeds : ndarray (len(y), len(x))
        V_c, m/s (inf where stable over the range).
    x_name, y_name : str
        Names of the two parameters (with their units), used as axis labels.
    """

    x: np.ndarray
    y: np.ndarray
    speeds: np.ndarray
    x_name: str
    y_name: str

    def plot(self, ax=None, *, levels=None, cmap: str = "viridis") -> dict:
        """Draw the critical speed (km/h) as filled contours over the two parameters.

        Critical speeds above the highest level (and ``inf``, no crossing in the range) are
        shown in the colour of the highest level.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default.
        levels : array_like, optional
            Contour levels, km/h; by default 50 km/h apart up to the largest finite critical speed.
        cmap : str
            Colour map.

        Returns
        -------
        dict
            The artists: ``contours`` (the ``QuadContourSet``) and ``colorbar``.
        """
        import matplotlib

        from raildyn import plots

        kmh = 3.6 * self.speeds
        finite = kmh[np.isfinite(kmh)]
        if levels is None:
            top = finite.max() if finite.size else 50.0
            levels = np.arange(0.0, 50.0 * np.ceil(top / 50.0) + 50.0, 50.0)
        levels = array("levels", np.atleast_1d(levels), ndim=1)
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
        array([244., 169.])
        """
        kmh = 3.6 * self.speeds
        rows = np.where(np.isfinite(kmh), kmh, np.nan)
        if artists is not None:
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
    Each model goes through :func:`critical_speed`.

    Parameters
    ----------
    factory : callable
        ``factory(x_value, y_value)`` returns a linear model (or system).
    x : array_like, shape (nx,)
        Values of the first parameter (its own unit).
    y : array_like, shape (ny,)
        Values of the second parameter (its own unit).
    speed_range : (float, float)
        Lowest and highest speed searched, m/s (0 < low < high).
    x_name : str
        Name (and unit) of the first parameter, for the plots.
    y_name : str
        Name (and unit) of the second parameter.
    tol : float
        Absolute tolerance on each critical speed, m/s.
    scan : int
        Number of speeds in each coarse scan (≥ 8).
    progress : bool
        Show a progress bar.

    Returns
    -------
    CriticalSpeedMap
        The critical speeds, m/s, shape (ny, nx) (``inf`` where stable over the range).
    """
    xs = array("x", np.atleast_1d(x), ndim=1)
    ys = array("y", np.atleast_1d(y), ndim=1)
    if xs.size == 0 or ys.size == 0:
        raise ValueError("x and y must each hold at least one value")
    out = np.empty((ys.size, xs.size))
    pairs = [(j, i) for j in range(ys.size) for i in range(xs.size)]
    if progress:
        pairs = progress_bar(pairs, desc="critical speed map")
    for j, i in pairs:
        out[j, i] = critical_speed(factory(xs[i], ys[j]), speed_range, tol=tol, scan=scan).speed
    return CriticalSpeedMap(xs, ys, out, x_name, y_name)


# ---------------------------------------------------------------------------
# Nonlinear hunting


@dataclass(frozen=True)
class NonlinearRun:
    """A time history of a nonlinear lateral model.

    Attributes
    ----------
    speed : float
        m/s.
    t : ndarray, (n_t,)
        s.
    states : ndarray, (state_size, n_t)
        The model's state at each time, in its units (m, rad, m/s, rad/s).
    lateral_index : int
        Row of the first wheelset's lateral displacement.
    """

    speed: float
    t: np.ndarray
    states: np.ndarray
    lateral_index: int

    @property
    def lateral(self) -> np.ndarray:
        """The first wheelset's lateral displacement, m."""
        return self.states[self.lateral_index]

    def plot(self, ax=None, *, flange_clearance: float | None = None) -> dict:
        """Draw the first wheelset's lateral displacement (mm) against time, with the flangeway clearance.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default.
        flange_clearance : float, optional
            m; marked at ±δ_f when given.

        Returns
        -------
        dict
            The artists: ``line`` and, with a clearance, ``flange`` (two lines).
        """
        import matplotlib

        from raildyn import plots

        ax = plots.axes_or_new(ax)
        out = {}
        with matplotlib.rc_context(plots.STYLE):
            (out["line"],) = ax.plot(self.t, 1e3 * self.lateral, color=plots.COLORS[0])
            if flange_clearance is not None:
                d = 1e3 * flange_clearance
                out["flange"] = [
                    ax.axhline(sign * d, color=plots.COLORS[1], ls="--", lw=1) for sign in (1, -1)
                ]
                ax.text(0.05, d + 0.5, "flange contact", color=plots.COLORS[1])
            ax.set_xlabel("time $t$ (s)")
            ax.set_ylabel("lateral displacement $y$ (mm)")
            ax.set_xlim(0, self.t[-1])
        return out


def simulate(model, speed, initial_state, duration, *, max_step: float = 2.0e-3, rtol: float = 1.0e-6):
    """Integrate a nonlinear lateral model at speed V from a state, by RK45 (scipy).

    Parameters
    ----------
    model : NonlinearWheelset, NonlinearLateral or any object with ``at_speed(V)``
        ``at_speed(V)`` gives one with ``rhs``, ``state_size`` and ``lateral_index``.
    speed : float
        V, m/s (> 0).
    initial_state : array_like, (state_size,)
        In the units of the model's state.
    duration : float
        s (> 0).
    max_step : float
        Largest step, s (> 0).
    rtol : float
        Relative tolerance of the integration, in (0, 1).

    Returns
    -------
    NonlinearRun

    Raises
    ------
    SolverError
        If the integration fails.

    Examples
    --------
    >>> from raildyn.wheelset import NonlinearWheelset, Wheelset
    >>> run = simulate(NonlinearWheelset(Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)), 60.0,
    ...                [1e-3, 0.0, 0.0, 0.0], 0.5)
    >>> run.states.shape[0], float(run.t[-1])
    (4, 0.5)
    """
    import scipy.integrate

    V = scalar("speed", speed, low=0.0, low_open=True)
    T = positive("duration", duration)
    h = positive("max_step", max_step)
    r = scalar("rtol", rtol, low=0.0, high=1.0, low_open=True, high_open=True)
    m = model.at_speed(V)
    y0 = array("initial_state", initial_state, shape=(m.state_size,))
    sol = scipy.integrate.solve_ivp(m.rhs, (0.0, T), y0, method="RK45", rtol=r, atol=1e-9, max_step=h)
    if not sol.success:
        raise SolverError(f"integration failed at V = {V:.2f} m/s: {sol.message}", time=float(sol.t[-1]))
    return NonlinearRun(V, sol.t, sol.y, m.lateral_index)


@dataclass(frozen=True)
class LimitCycle:
    """Steady lateral oscillation of a nonlinear model at one speed.

    Attributes
    ----------
    speed : float
        m/s.
    amplitude : float
        Half the peak-to-peak lateral displacement of the first wheelset over
        the last quarter of the run, m.
    frequency_hz : float
        Frequency of the oscillation, Hz, from the upward crossings of the mean (nan when there
        is no oscillation).
    growth : float
        Amplitude over the last quarter divided by that over the quarter before:
        below 1 while the motion is still dying away.
    state : ndarray
        The state at the end of the run (to start the next speed of a ramp from).
    """

    speed: float
    amplitude: float
    frequency_hz: float
    growth: float
    state: np.ndarray

    def hunting(self, threshold: float = 2.0e-4) -> bool:
        """Whether the motion is a sustained oscillation: above ``threshold`` and no longer decaying.

        Parameters
        ----------
        threshold : float
            Amplitude below which the motion counts as decayed, m (default 0.2 mm).

        Returns
        -------
        bool
            True when ``amplitude > threshold`` and ``growth > 0.95``.
        """
        return self.amplitude > threshold and self.growth > 0.95


def limit_cycle_amplitude(
    model,
    speed,
    *,
    initial_displacement: float = 12.0e-3,
    initial_state=None,
    duration: float = 8.0,
    max_step: float = 2.0e-3,
    rtol: float = 1e-6,
) -> LimitCycle:
    """Amplitude of the steady hunting of a nonlinear model at one speed, by direct integration.

    Starts from a lateral displacement of the first wheelset (or from
    ``initial_state``) and integrates ``duration`` seconds with RK45; the
    amplitude is taken over the last quarter of the run.

    Parameters
    ----------
    model : NonlinearWheelset, NonlinearLateral or any object with ``at_speed(V)``
        The nonlinear model; ``at_speed(V)`` gives one with ``rhs``, ``state_size`` and
        ``lateral_index``.
    speed : float
        Speed V, m/s (> 0).
    initial_displacement : float
        Starting lateral displacement of the first wheelset, m (default 12 mm:
        beyond the flangeway clearance, so that a large limit cycle is found
        where one exists).
    initial_state : array_like, optional
        Full starting state, instead of ``initial_displacement``.
    duration : float
        Simulated time, s.
    max_step : float
        Largest solver step, s.
    rtol : float
        Relative tolerance of the solver.

    Returns
    -------
    LimitCycle
        Amplitude (m), frequency (Hz), growth over the last two quarters and final state.

    Raises
    ------
    SolverError
        If the integration fails.

    Examples
    --------
    The suspended wheelset of chapter 5 at 60 m/s, above its linear critical speed of
    54.6 m/s: from 12 mm it settles on a limit cycle of about 10 mm at 5.7 Hz.

    >>> from raildyn.wheelset import NonlinearWheelset, Wheelset
    >>> model = NonlinearWheelset(Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6))
    >>> cycle = limit_cycle_amplitude(model, 60.0, duration=2.0)
    >>> cycle.hunting(), round(1e3 * cycle.amplitude, 1), round(cycle.frequency_hz, 1)
    (True, 10.3, 5.7)
    """
    V = scalar("speed", speed, low=0.0, low_open=True)
    positive("duration", duration)
    positive("max_step", max_step)
    m = model.at_speed(V)
    if initial_state is None:
        y0 = np.zeros(m.state_size)
        y0[m.lateral_index] = scalar("initial_displacement", initial_displacement)
    else:
        y0 = array("initial_state", initial_state, shape=(m.state_size,))
    run = simulate(m, V, y0, duration, max_step=max_step, rtol=rtol)
    t, y, x = run.t, run.states, run.lateral
    last = t >= 0.75 * duration
    before = (t >= 0.5 * duration) & ~last
    amplitude = 0.5 * (x[last].max() - x[last].min())
    previous = 0.5 * (x[before].max() - x[before].min())
    growth = amplitude / previous if previous > 0 else 1.0
    tail, tt = x[last], t[last]
    crossings = np.flatnonzero(np.diff(np.sign(tail - tail.mean())) > 0)
    frequency_hz = np.nan
    if amplitude > 1e-6 and crossings.size >= 2:
        frequency_hz = (crossings.size - 1) / (tt[crossings[-1]] - tt[crossings[0]])
    return LimitCycle(V, float(amplitude), float(frequency_hz), float(growth), y[:, -1].copy())


@dataclass(frozen=True)
class BifurcationDiagram:
    """Limit-cycle amplitude against speed and the nonlinear critical speed.

    Attributes
    ----------
    speeds : ndarray
        m/s, decreasing (the order of the ramp).
    amplitudes : ndarray
        Lateral amplitude of the first wheelset, m.
    frequencies_hz : ndarray
        Frequency of the motion at each speed, Hz (nan where there is no oscillation).
    hunting : ndarray of bool
        Whether the motion at each speed is a sustained oscillation.
    nonlinear_critical_speed : float
        Lowest speed at which a limit cycle persists, m/s, refined by bisection
        between the grid speeds (inf if there is none on the grid).
    threshold : float
        Amplitude below which the motion counts as decayed, m.
    """

    speeds: np.ndarray
    amplitudes: np.ndarray
    frequencies_hz: np.ndarray
    hunting: np.ndarray
    nonlinear_critical_speed: float
    threshold: float

    def plot(self, ax=None, *, linear_critical_speed: float | None = None) -> dict:
        """Draw the amplitude (mm) against speed (km/h), with the nonlinear and linear critical speeds.

        Filled markers joined by a line: sustained hunting; open markers: motion that dies away.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default.
        linear_critical_speed : float, optional
            The linear critical speed of the same vehicle, m/s (finite, > 0; from
            :func:`critical_speed`), drawn as a dashed line; left out if None.

        Returns
        -------
        dict
            The artists: ``cycles`` and ``decaying`` (``Line2D``), and the vertical lines
            ``nonlinear`` (when the nonlinear critical speed is finite) and ``linear`` (when
            ``linear_critical_speed`` is given).
        """
        import matplotlib

        from raildyn import plots

        V, amp, hunt = 3.6 * self.speeds, 1e3 * self.amplitudes, self.hunting
        ax = plots.axes_or_new(ax)
        out = {}
        with matplotlib.rc_context(plots.STYLE):
            (out["cycles"],) = ax.plot(V[hunt], amp[hunt], "o-", color=plots.COLORS[0], label="limit cycle")
            (out["decaying"],) = ax.plot(
                V[~hunt], amp[~hunt], "o", mfc="none", color=plots.COLORS[0], label="motion dies away"
            )
            if linear_critical_speed is not None:
                vc = 3.6 * scalar("linear_critical_speed", linear_critical_speed, low=0.0, low_open=True)
                out["linear"] = ax.axvline(
                    vc, color=plots.COLORS[1], ls="--", label=f"linear V_c {vc:.0f} km/h"
                )
            vnl = 3.6 * self.nonlinear_critical_speed
            if np.isfinite(vnl):
                out["nonlinear"] = ax.axvline(
                    vnl, color=plots.COLORS[2], ls=":", label=f"nonlinear V_c {vnl:.0f} km/h"
                )
            ax.set_xlabel("speed (km/h)")
            ax.set_ylabel("amplitude of $y$ (mm)")
            ax.legend(loc="center right")
        return out


def bifurcation_diagram(
    model,
    speeds,
    *,
    initial_displacement: float = 12.0e-3,
    duration: float = 8.0,
    max_step: float = 2.0e-3,
    threshold: float = 2.0e-4,
    refine: int = 4,
    progress: bool = True,
) -> BifurcationDiagram:
    """Limit-cycle amplitude along a speed ramp-down, and the nonlinear critical speed.

    The highest speed starts from a large lateral displacement of the first
    wheelset; each lower speed starts from the final state of the one above
    (a slow ramp-down in steps), so the branch of large limit cycles is
    followed below the linear critical speed as far as it exists (a
    subcritical Hopf bifurcation). Where the branch ends, ``refine`` bisection
    steps between the last hunting and the first decaying speed locate the
    nonlinear critical speed.

    Parameters
    ----------
    model : NonlinearWheelset, NonlinearLateral or any object with ``at_speed(V)``
        The nonlinear model, as for :func:`limit_cycle_amplitude`.
    speeds : array_like, shape (n_speeds,)
        Speeds of the ramp, m/s (> 0), in any order: they are run from the highest down.
    initial_displacement : float
        Starting lateral displacement of the first wheelset at the highest speed (and after
        a speed where the motion died away), m.
    duration : float
        Simulated time at each speed, s.
    max_step : float
        Largest solver step, s.
    threshold : float
        Amplitude below which the motion counts as decayed, m.
    refine : int
        Number of bisection steps on the nonlinear critical speed (≥ 0).
    progress : bool
        Show a progress bar.

    Returns
    -------
    BifurcationDiagram
        Amplitudes (m), frequencies (Hz) and hunting flags along the ramp, and the nonlinear
        critical speed (m/s); draw it with :meth:`BifurcationDiagram.plot`.

    Raises
    ------
    SolverError
        If an integration fails.
    """
    V = np.sort(_speeds(speeds))[::-1]
    positive("threshold", threshold)
    integer("refine", refine, low=0)
    items = V
    if progress:
        items = progress_bar(V, desc="bifurcation diagram (ramp-down)")
    cycles, state = [], None
    for v in items:
        cycle = limit_cycle_amplitude(
            model,
            v,
            initial_displacement=initial_displacement,
            initial_state=state,
            duration=duration,
            max_step=max_step,
        )
        cycles.append(cycle)
        state = cycle.state if cycle.hunting(threshold) else None
    hunting = np.array([c.hunting(threshold) for c in cycles])
    vnl = np.inf
    if hunting.any():
        k = int(np.flatnonzero(hunting).max())
        vnl = float(V[k])
        if k + 1 < V.size and not hunting[k + 1]:
            high, low, start = V[k], V[k + 1], cycles[k].state
            for _ in range(refine):
                mid = 0.5 * (high + low)
                trial = limit_cycle_amplitude(
                    model, mid, initial_state=start, duration=duration, max_step=max_step
                )
                if trial.hunting(threshold):
                    high, start = mid, trial.state
                else:
                    low = mid
            vnl = float(high)
    amp = np.array([c.amplitude for c in cycles])
    freq = np.array([c.frequency_hz for c in cycles])
    return BifurcationDiagram(V, amp, freq, hunting, vnl, threshold)


@dataclass(frozen=True)
class PeriodicOrbit:
    """A periodic solution of a nonlinear model found by shooting.

    Attributes
    ----------
    speed : float
        m/s.
    period : float
        T, s.
    state : ndarray
        A point of the orbit, where the first wheelset's lateral velocity is zero.
    amplitude : float
        Half the peak-to-peak lateral displacement of the first wheelset over one period, m.
    multipliers : complex ndarray
        Floquet multipliers (eigenvalues of the monodromy matrix); the orbit is
        stable when all but the trivial one (≈ 1) lie inside the unit circle.
    residual : float
        Norm of φ_T(x₀) − x₀ at the solution, in units of the state.
    """

    speed: float
    period: float
    state: np.ndarray
    amplitude: float
    multipliers: np.ndarray
    residual: float

    @property
    def stable(self) -> bool:
        """All multipliers but the trivial one (the one closest to 1) inside the unit circle."""
        trivial = int(np.argmin(np.abs(self.multipliers - 1.0)))
        others = np.delete(self.multipliers, trivial)
        return bool(np.all(np.abs(others) < 1.0))


def periodic_orbit(
    model,
    speed,
    state,
    period,
    *,
    tol: float = 1e-7,
    max_iter: int = 12,
    rtol: float = 1e-10,
) -> PeriodicOrbit:
    """Periodic orbit through Newton shooting, from a guess of one of its points and of its period.

    Unknowns: the state x₀ with the first wheelset's lateral velocity held at
    zero (the phase condition) and the period T; equations φ_T(x₀) − x₀ = 0,
    with the Jacobian by finite differences (one integration per unknown). The
    monodromy matrix of the converged orbit gives its Floquet multipliers, so
    unstable orbits — the other branch of a subcritical bifurcation — are found
    as well as stable ones.

    Parameters
    ----------
    model : NonlinearWheelset, NonlinearLateral or any object with ``at_speed(V)``
        The nonlinear model; ``at_speed(V)`` gives one with ``rhs``, ``state_size`` and
        ``lateral_index``.
    speed : float
        Speed V, m/s (> 0).
    state : array_like, shape (state_size,)
        Guess of a point on the orbit (for instance the ``state`` at the end of a
        :func:`limit_cycle_amplitude` run), in the units of the model's state.
    period : float
        Guess of T, s (1 / ``frequency_hz`` of the settled motion).
    tol : float
        Convergence on the relative size of the Newton step (dimensionless).
    max_iter : int
        Largest number of Newton steps (≥ 1).
    rtol : float
        Relative tolerance of the DOP853 integrations.

    Returns
    -------
    PeriodicOrbit
        The period (s), a point of the orbit, its amplitude (m), Floquet multipliers and the
        residual of the periodicity condition.

    Raises
    ------
    SolverError
        If an integration fails or Newton's method does not converge in ``max_iter`` steps.

    Notes
    -----
    The centred state is a trivial solution of the same equations: a guess
    far from any cycle may converge to it (amplitude 0).
    """
    import scipy.integrate

    V = scalar("speed", speed, low=0.0, low_open=True)
    T = positive("period", period)
    m = model.at_speed(V)
    n = m.state_size
    x = array("state", state, shape=(n,)).copy()
    iy = m.lateral_index
    iv = iy + n // 2  # the lateral velocity of the same wheelset
    free = [i for i in range(n) if i != iv]

    def section(t, z):
        return z[iv]

    section.direction = -1.0  # a maximum of the lateral displacement
    # Move the guess along its own trajectory to the section ẏ = 0, so that it meets the phase condition.
    sol = scipy.integrate.solve_ivp(
        m.rhs, (0.0, 2.0 * T), x, method="DOP853", rtol=rtol, atol=1e-12, events=section
    )
    if sol.t_events[0].size:
        x = sol.y_events[0][0].copy()
    x[iv] = 0.0

    def flow(starts, t_end):
        """φ_t(x₀) for each column of ``starts``, integrated as one system.

        The columns share one sequence of adaptive steps, so the differences between
        neighbouring trajectories that the finite differences below take carry the
        truncation error of the perturbation, not the noise of two step sequences.
        """
        k = starts.shape[1]

        def rhs(t, z):
            return m.rhs(t, z.reshape(n, k)).reshape(-1)

        sol = scipy.integrate.solve_ivp(
            rhs, (0.0, t_end), starts.reshape(-1), method="DOP853", rtol=rtol, atol=1e-12
        )
        if not sol.success:
            raise SolverError(
                f"shooting integration failed at V = {V:.2f} m/s: {sol.message}", time=float(sol.t[-1])
            )
        return sol.y[:, -1].reshape(n, k)

    # Finite-difference steps relative to each entry, with a floor so that an entry near 0 (such
    # as the lateral velocity on the section) is not perturbed below the integration noise.
    scale = np.maximum(np.abs(x), 1e-2 * np.abs(x).max())
    h = 1e-5 * scale
    for _ in range(integer("max_iter", max_iter, low=1)):
        starts = np.column_stack([x] + [x + h[i] * np.eye(n)[i] for i in free])
        ends = flow(starts, T)
        end, residual = ends[:, 0], ends[:, 0] - x
        J = np.empty((n, n))
        J[:, :-1] = (ends[:, 1:] - starts[:, 1:] - residual[:, None]) / h[free]
        J[:, -1] = m.rhs(T, end)  # d/dT of φ_T(x₀)
        step = np.linalg.solve(J, -residual)
        x[free] += step[:-1]
        T += step[-1]
        if np.linalg.norm(step[:-1] / scale[free]) < tol and abs(step[-1]) < tol * T:
            break
    else:
        raise SolverError(f"shooting did not converge in {max_iter} iterations at V = {V:.2f} m/s")
    # Monodromy matrix (central differences, all trajectories on one step sequence) and one period of
    # the orbit, for the multipliers and the amplitude.
    shifts = np.diag(h)
    ends = flow(np.column_stack([x[:, None] + shifts, x[:, None] - shifts, x]), T)
    monodromy = (ends[:, :n] - ends[:, n : 2 * n]) / (2 * h)
    end = ends[:, -1]
    sol = scipy.integrate.solve_ivp(
        m.rhs, (0.0, T), x, method="DOP853", rtol=rtol, atol=1e-12, max_step=T / 200
    )
    lateral = sol.y[iy]
    return PeriodicOrbit(
        V,
        float(T),
        x,
        float(0.5 * (lateral.max() - lateral.min())),
        np.linalg.eigvals(monodromy),
        float(np.linalg.norm(end - x)),
    )
