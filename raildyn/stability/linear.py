"""Linear lateral stability (book chapter 7): eigenvalues against speed, mode tracking, critical speed.

The linear models of :mod:`raildyn.wheelset` and :mod:`raildyn.vehicles`
follow the one protocol (:class:`raildyn.linear_model.LinearModel`), and their
systems read M q̈ + (C₀ + C₁/V) q̇ + K q = 0 without the track,
so the state matrix at every speed of a sweep is built at once and all
eigenvalues come from one batched ``numpy.linalg`` call.
"""

from __future__ import annotations

import cmath
import numbers
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import scipy.optimize

from raildyn import _checks
from raildyn._checks import array, integer, positive
from raildyn._progress import progress_bar
from raildyn.linear_model import LinearSystem, as_linear_system

__all__ = [
    "CriticalSpeed",
    "CriticalSpeedMap",
    "ModeSweep",
    "TrackedModes",
    "critical_speed",
    "critical_speed_map",
    "eigenvalues_against_speed",
    "largest_real_part",
    "mac",
    "mode_sweep",
    "track_modes",
]


def eigenvalues_against_speed(model, speeds) -> np.ndarray:
    """All 2n eigenvalues at each speed, from one batched ``numpy.linalg.eigvals`` call.

    The state matrix A(V) = [[0, I], [−M⁻¹K, −M⁻¹(C₀ + C₁/V)]] of
    M q̈ + (C₀ + C₁/V) q̇ + K q = 0 (book chapter 7) at every speed.

    Parameters
    ----------
    model : LinearModel or LinearSystem
        A linear model of :mod:`raildyn.wheelset` or :mod:`raildyn.vehicles`, or its system.
    speeds : array_like, shape (n_speeds,)
        Speeds V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`] (the creep damping divides by V).

    Returns
    -------
    ndarray of complex, shape (n_speeds, 2n)
        The eigenvalues s_r (characteristic roots), 1/s, in no particular order at each speed.
    """
    V = _checks.speeds("speeds", speeds)
    return np.linalg.eigvals(as_linear_system(model).state_matrices(V))


def largest_real_part(model, speeds) -> np.ndarray:
    """The largest real part of the eigenvalues at each speed: positive where the model is unstable.

    Parameters
    ----------
    model : LinearModel or LinearSystem
        A linear model, or its system.
    speeds : array_like, shape (n_speeds,)
        Speeds V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].

    Returns
    -------
    ndarray, shape (n_speeds,)
        max Re s_r, 1/s.
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
        Vectors as columns (any unit; the criterion is dimensionless): finite, none of them zero.
    b : array_like, shape (p, kb)
        Vectors as columns, of the same length p; finite, none of them zero.

    Returns
    -------
    ndarray, shape (ka, kb)
        The criterion, between 0 and 1, of every column of ``a`` with every column of ``b``.
    """
    a = _vectors("a", a, 2)
    b = _vectors("b", b, 2)
    if a.shape[0] != b.shape[0]:
        raise ValueError(f"b must have columns of the length of a's, {a.shape[0]}, got shape {b.shape}")
    return _mac(a, b)


def _vectors(name: str, value, ndim: int) -> np.ndarray:
    """Finite (complex) vectors as the columns of the last two axes, none of them zero."""
    v = _checks.array(name, value, ndim=ndim, dtype=complex, allow_empty=False)
    zero = ~np.abs(v).any(axis=-2)
    if zero.any():
        raise ValueError(f"{name} must have no zero column (a mode has a direction), got one in {name}")
    return v


def _mac(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """:func:`mac` of checked vectors: each column scaled by its largest entry first, so that the
    squares stay finite for any finite entries."""
    a = a / np.abs(a).max(axis=0, initial=0.0)
    b = b / np.abs(b).max(axis=0, initial=0.0)
    num = np.abs(a.conj().T @ b) ** 2
    den = np.outer(np.sum(np.abs(a) ** 2, axis=0), np.sum(np.abs(b) ** 2, axis=0))
    return num / den


def _modes(eigenvalues, vectors) -> tuple[np.ndarray, np.ndarray]:
    """Eigenvalues (n_speeds, m) and their vectors (n_speeds, p, m), checked."""
    lam = _checks.array("eigenvalues", eigenvalues, ndim=2, dtype=complex, allow_empty=False)
    vec = _vectors("vectors", vectors, 3)
    if vec.shape[0] != lam.shape[0] or vec.shape[2] != lam.shape[1]:
        raise ValueError(
            f"vectors must have shape ({lam.shape[0]}, p, {lam.shape[1]}) to match the eigenvalues, "
            f"got {vec.shape}"
        )
    return lam, vec


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

    def __post_init__(self):
        _modes(self.eigenvalues, self.vectors)


def track_modes(eigenvalues: np.ndarray, vectors: np.ndarray) -> TrackedModes:
    """Reorder eigenvalues (and vectors) at each speed so that column j follows one mode.

    At each step the assignment that maximises the MAC of the state vectors
    with those of the previous speed is chosen (Hungarian algorithm), with the
    distance between eigenvalues, relative to their size, as a tie-breaker for
    conjugate partners, whose vectors are alike.

    Parameters
    ----------
    eigenvalues : complex ndarray, shape (n_speeds, m)
        Eigenvalues at each speed, 1/s (finite).
    vectors : complex ndarray, shape (n_speeds, p, m)
        Eigenvectors (any unit, finite, none zero): column k of ``vectors[i]`` belongs to
        ``eigenvalues[i, k]``.

    Returns
    -------
    TrackedModes
        The eigenvalues and vectors with the columns permuted at each speed.
    """
    lam, vec = (arr.copy() for arr in _modes(eigenvalues, vectors))
    # The cost of pairing each mode at one speed with each at the next, for all speeds at once: the
    # MAC in one batched product (as _mac: each column scaled by its largest entry first) and the
    # distances. The loop then only puts the rows in the previous speed's tracked order and solves
    # the assignment; a MAC per step took more than half the time of a long sweep of a small model.
    scaled = vec / np.abs(vec).max(axis=1, keepdims=True)
    squares = np.sum(np.abs(scaled) ** 2, axis=1)
    similarity = np.abs(np.swapaxes(scaled[:-1].conj(), 1, 2) @ scaled[1:]) ** 2
    similarity /= squares[:-1, :, None] * squares[1:, None, :]
    scale = np.maximum(np.abs(lam[:-1])[:, :, None], 1.0)
    distance = np.abs(lam[:-1, :, None] - lam[1:, None, :]) / scale
    cost = (1.0 - similarity) + 0.5 * distance
    # Where each mode's cheapest partner is a different mode of the next speed, and strictly the
    # cheapest, pairing each with it is the one optimal assignment (no other reaches the sum of the
    # row minima), which the Hungarian algorithm would return too: it runs only where that fails.
    m = lam.shape[1]
    best = cost.argmin(axis=2)
    if m > 1:
        lowest = np.partition(cost, 1, axis=2)
        strict = (lowest[:, :, 1] > lowest[:, :, 0]).all(axis=1)
    else:
        strict = np.ones(cost.shape[0], dtype=bool)
    clear = strict & (np.sort(best, axis=1) == np.arange(m)).all(axis=1)
    previous = np.arange(m)  # the previous speed's columns, in their tracked order
    for i in range(1, lam.shape[0]):
        if clear[i - 1]:
            order = best[i - 1][previous]
        else:
            _, order = scipy.optimize.linear_sum_assignment(cost[i - 1][previous])
        lam[i] = lam[i, order]
        vec[i] = vec[i][:, order]
        previous = order
    return TrackedModes(lam, vec)


@dataclass(frozen=True)
class ModeSweep:
    """Modes of a lateral model across speed, each column one mode followed by MAC.

    Attributes
    ----------
    speeds : ndarray (n_speeds,)
        m/s, > 0 and strictly increasing.
    eigenvalues : complex ndarray (n_speeds, k)
        s_r, 1/s; only the roots with Im s_r ≥ 0 at the first speed are kept (one of each pair).
    frequencies_hz : ndarray (n_speeds, k)
        Damped frequency |Im s_r|/2π, Hz (≥ 0).
    damping_ratios : ndarray (n_speeds, k)
        ξ = −Re s_r/|s_r| (negative when the mode is unstable).
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

    def __post_init__(self):
        s = _checks.speeds("speeds", _checks.increasing("speeds", self.speeds, low=0.0, low_open=True)).size
        k = _checks.array("eigenvalues", self.eigenvalues, shape=(s, None), dtype=complex).shape[1]
        _checks.array("frequencies_hz", self.frequencies_hz, shape=(s, k), low=0.0)
        _checks.array("damping_ratios", self.damping_ratios, shape=(s, k))
        shapes = _checks.array("shapes", self.shapes, shape=(s, None, k), dtype=complex)
        if np.any(np.abs(np.abs(shapes).max(axis=1, initial=0.0) - 1.0) > 1e-6):
            raise ValueError("shapes must have the largest entry of each mode of modulus 1")
        n = shapes.shape[1]
        _checks.strings("labels", self.labels, k)
        _checks.strings("coordinates", self.coordinates, n)

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

        Left: every root s_r of the sweep in the complex plane, coloured by speed (km/h). Right:
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
            Range of Re s_r shown, 1/s (finite, low < high); None to fit the data.
        imag_limits : (float, float) or None
            Range of Im s_r shown, rad/s (finite, low < high); None to fit the data.
        damping_limits : (float, float) or None
            Range of ξ shown (dimensionless; finite, low < high); None to fit the data.

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
        '196 km/h, 5.30 Hz'
        """
        if ax is not None:
            from matplotlib.axes import Axes

            if not (isinstance(ax, (tuple, list, np.ndarray)) and len(ax) == 2):
                raise TypeError(f"ax must be a sequence of two matplotlib Axes or None, got {ax!r:.80}")
            for i, one in enumerate(ax):
                _checks.instance(f"ax[{i}]", one, Axes, "matplotlib.axes.Axes")
        if critical is not None:
            _checks.instance("critical", critical, CriticalSpeed, "CriticalSpeed or None")
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
        limits = {
            name: None if value is None else _checks.interval(name, value, low=-np.inf)
            for name, value in (
                ("real_limits", real_limits), ("imag_limits", imag_limits), ("damping_limits", damping_limits)
            )
        }  # fmt: skip
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
            ax_s.set_xlabel("Re $s_r$ (1/s)")
            ax_s.set_ylabel("Im $s_r$ (rad/s)")
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
        if limits["real_limits"] is not None:
            ax_s.set_xlim(*limits["real_limits"])
        if limits["imag_limits"] is not None:
            ax_s.set_ylim(*limits["imag_limits"])
        if limits["damping_limits"] is not None:
            ax_d.set_ylim(*limits["damping_limits"])
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
    array([ 0.142,  0.023, -0.127])
    >>> sweep.frequencies_hz[-1].round(2)
    array([6.87, 6.97])
    """
    system = as_linear_system(model)
    V = _checks.speeds("speeds", _checks.increasing("speeds", np.atleast_1d(speeds), low=0.0, low_open=True))
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


_STATUSES = ("crossing", "stable over the range", "unstable at the lowest speed")


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
        _checks.choice("status", self.status, _STATUSES)
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


def _range(speed_range) -> tuple[float, float]:
    return _checks.speed_range("speed_range", speed_range)


class _StateMatrices:
    """A(V) = [[0, I], [−M⁻¹K, −M⁻¹C₀ − M⁻¹C₁/V]] of one system or of a stack of systems of one size.

    :func:`critical_speed` asks for A at a dozen or more single speeds (the scan, then each step
    of the refinement); :meth:`LinearSystem.state_matrices` checks the speeds and M and solves
    with M at every call, which took about as long as the eigenvalues of a 30-state car. Here the
    three blocks are solved once; A(V) differs from that method's by round-off only. Each of M, K,
    C₀ and C₁ is (n, n) or a stack (m, n, n): a matrix shared by the whole stack is solved once.
    """

    _CHUNK = 1024  # state matrices per eigenvalue call: a long scan of many systems stays within memory

    def __init__(self, M, K, C0, C1):
        self.n = n = M.shape[-1]
        self.count = max([1] + [x.shape[0] for x in (M, K, C0, C1) if x.ndim == 3])
        if M.ndim == 2 and C0.ndim == 2 and C1.ndim == 2:  # only K varies (or nothing): M⁻¹C once
            self.stiffness = -np.linalg.solve(M, K)
            damping = -np.linalg.solve(M, np.concatenate([C0, C1], axis=1))
            self.damping, self.creep = damping[:, :n], damping[:, n:]
        else:
            # The system has checked M (symmetric positive definite) and the other matrices (finite).
            stack = np.concatenate(np.broadcast_arrays(K, C0, C1), axis=-1)
            blocks = -np.linalg.solve(M, stack)
            self.stiffness, self.damping, self.creep = (
                blocks[..., :n],
                blocks[..., n : 2 * n],
                blocks[..., 2 * n :],
            )

    @classmethod
    def of(cls, system: LinearSystem) -> _StateMatrices:
        return cls(system.M, system.K, system.C0, system.C1)

    def __call__(self, speeds: np.ndarray, which: np.ndarray | None = None) -> np.ndarray:
        """A of system ``which[k]`` (default 0) at ``speeds[k]`` (m/s, > 0, checked): (m, 2n, 2n)."""
        n = self.n
        which = np.zeros(speeds.size, dtype=int) if which is None else which

        def pick(block):
            return block[which] if block.ndim == 3 else block

        A = np.zeros((speeds.size, 2 * n, 2 * n))
        A[:, :n, n:] = np.eye(n)
        A[:, n:, :n] = pick(self.stiffness)
        A[:, n:, n:] = pick(self.damping) + pick(self.creep) / speeds[:, None, None]
        return A

    def largest(self, which: np.ndarray, speeds: np.ndarray) -> np.ndarray:
        """max Re s_r of A for each pair (system ``which[k]``, ``speeds[k]``), 1/s."""
        out = np.empty(speeds.size)
        for start in range(0, speeds.size, self._CHUNK):
            part = slice(start, start + self._CHUNK)
            out[part] = np.linalg.eigvals(self(speeds[part], which[part])).real.max(axis=-1)
        return out


_MAX_SCAN = 10_000  # speeds in a coarse scan: the refinement narrows the bracket, so more only cost time
_MAX_STEPS = 400  # of the refinement: every three steps at least halve a bracket, so far more than needed


def _crossings(state: _StateMatrices, low: float, high: float, tol: float, scan: int):
    """The status and critical speed of every system of ``state`` (arguments checked by the caller).

    The definition of :func:`critical_speed`, for a stack of systems at once: a coarse scan of
    ``scan`` speeds brackets each system's first upward zero of g(V) = max Re s_r(V), then a
    bracketed refinement narrows every bracket below 2 tol; the midpoint is returned. The scan
    goes up in batches of 4 speeds, then of half the speeds done so far, and leaves a system at
    its first upward crossing: a crossing low in the range costs a few eigenvalue problems, a
    system stable over the range a few batched calls. The refinement is the Illinois variant of
    regula falsi, each point kept at least tol/2 inside its bracket; where two steps have not
    halved a bracket, a bisection follows, so that a kink of g (two modes trading places) cannot
    stall it.

    Returns (status, speed): an object array of :data:`_STATUSES` and V_c in m/s (inf where
    stable over the range, ``low`` where unstable at the lowest speed), each of shape (m,).
    """
    m = state.count
    V = np.linspace(low, high, scan)
    speed = np.full(m, np.inf)
    status = np.full(m, _STATUSES[1], dtype=object)
    every = np.arange(m)
    g_low = state.largest(every, np.full(m, low))
    unstable = g_low >= 0.0
    speed[unstable], status[unstable] = low, _STATUSES[2]
    open_, g_last = every[~unstable], g_low[~unstable]
    todo, a, b, ga, gb = [], [], [], [], []
    done = 1  # speeds of the scan behind every open system, all with g < 0
    while open_.size and done < scan:
        batch = V[done : done + max(4, done // 2)]
        g = state.largest(np.repeat(open_, batch.size), np.tile(batch, open_.size)).reshape(open_.size, -1)
        up = g >= 0.0
        crossed = np.flatnonzero(up.any(axis=1))
        k = up[crossed].argmax(axis=1)  # the first speed of the batch where g ≥ 0
        before = np.where(k == 0, g_last[crossed], g[crossed, k - 1])
        todo.append(open_[crossed])
        a.append(V[done - 1 + k])
        b.append(V[done + k])
        ga.append(before)
        gb.append(g[crossed, k])
        stay = ~up.any(axis=1)
        open_, g_last = open_[stay], g[stay, -1]
        done += batch.size
    if not todo or not sum(t.size for t in todo):
        return status, speed
    todo, a, b, ga, gb = (np.concatenate(x) for x in (todo, a, b, ga, gb))
    side = np.zeros(todo.size, dtype=int)  # which end the last step kept: −1 a, +1 b
    bisect = np.zeros(todo.size, dtype=bool)
    before = np.full(todo.size, np.inf)  # each bracket's width when the previous step began
    for _ in range(_MAX_STEPS):
        # a bracket as narrow as the speeds' round-off is done too, whatever tol asked for
        active = (b - a > 2.0 * tol) & (b - a > 8.0 * np.spacing(b))
        if not active.any():
            break
        i = np.flatnonzero(active)
        width = b[i] - a[i]
        falsi = (a[i] * gb[i] - b[i] * ga[i]) / (gb[i] - ga[i])
        c = np.where(bisect[i], 0.5 * (a[i] + b[i]), np.clip(falsi, a[i] + 0.5 * tol, b[i] - 0.5 * tol))
        gc = state.largest(todo[i], c)
        right = gc >= 0.0  # the zero lies in [a, c]: c becomes b
        for mask, keep in ((right, -1), (~right, 1)):
            j = i[mask]
            if keep == -1:
                b[j], gb[j] = c[mask], gc[mask]
                ga[j] = np.where(side[j] == -1, 0.5 * ga[j], ga[j])  # Illinois: a kept twice
            else:
                a[j], ga[j] = c[mask], gc[mask]
                gb[j] = np.where(side[j] == 1, 0.5 * gb[j], gb[j])
            side[j] = keep
        # two steps that have not halved the bracket are followed by a bisection
        bisect[i] = b[i] - a[i] > 0.5 * before[i]
        before[i] = width
    else:  # pragma: no cover - every three steps at least halve each bracket
        raise RuntimeError("the critical-speed refinement did not converge")
    speed[todo], status[todo] = 0.5 * (a + b), _STATUSES[0]
    return status, speed


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
    integer("scan", scan, low=8, high=_MAX_SCAN)
    state = _StateMatrices.of(system)
    (status,), (speed,) = _crossings(state, low, high, tol, scan)
    n = system.size
    if status == "stable over the range":
        return CriticalSpeed(
            np.inf, np.nan, complex(np.nan, np.nan), status, np.full(n, np.nan + 0j), system.labels
        )
    lam, vec = np.linalg.eig(state(np.array([speed]))[0])
    j = int(np.argmax(lam.real))
    shape = vec[:n, j] / vec[:n, j][np.argmax(np.abs(vec[:n, j]))]
    frequency = float(abs(lam[j].imag) / (2 * np.pi))
    return CriticalSpeed(float(speed), frequency, complex(lam[j]), status, shape, system.labels)


@dataclass(frozen=True)
class CriticalSpeedMap:
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
    for n in {system.size for _, _, system in built}:
        group = [(j, i, system) for j, i, system in built if system.size == n]
        state = _StateMatrices(
            *(np.stack([getattr(s, name) for *_, s in group]) for name in ("M", "K", "C0", "C1"))
        )
        _, speeds = _crossings(state, low, high, tol, scan)
        for (j, i, _), v in zip(group, speeds, strict=True):
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
    integer("scan", scan, low=8, high=_MAX_SCAN)
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
