"""Linear lateral stability (book chapter 7): eigenvalues against speed, mode tracking, critical speed.

The critical speed itself lives in :mod:`raildyn.stability.critical` and its batched search in
:mod:`raildyn.stability.search`; their names are re-exported here, where they used to live.

The linear models of :mod:`raildyn.wheelset` and :mod:`raildyn.vehicles`
follow the one protocol (:class:`raildyn.linear_model.LinearModel`), and their
systems read M q̈ + (C₀ + C₁/V) q̇ + K q = 0 without the track,
so the state matrix at every speed of a sweep is built at once and all
eigenvalues come from one batched ``numpy.linalg`` call.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.linear_model import as_linear_system

# Moved to raildyn.stability.critical; re-exported so that the old import path keeps working for one
# issue (then the names go from here).
from raildyn.stability.critical import CriticalSpeed, CriticalSpeedMap, critical_speed, critical_speed_map

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.optimize

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
    import scipy.optimize

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
class ModeSweep(Tabular):
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

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("speeds", "m/s"), ("eigenvalues", "1/s"), ("frequencies_hz", "Hz"), ("damping_ratios", "-"),
        ("shapes", "-"),
    )  # fmt: skip
    _labels = (("eigenvalues", "labels"), ("frequencies_hz", "labels"), ("damping_ratios", "labels"))

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
