"""Sample tracks from a spectrum, and the track seen in time by a vehicle at speed V.

Samples are built on :func:`raildyn.random_vibration.synthesize` (random phases,
deterministic amplitudes, one inverse FFT; Shinozuka & Jan 1972), with one
change for the spatial case: each spectral line carries the integral of the
spectrum over its own cell [Ω_k − ΔΩ/2, Ω_k + ΔΩ/2] clipped to the requested
band, instead of S(Ω_k)ΔΩ. Track spectra fall as Ω⁻² to Ω⁻⁴ and the band
usually starts a few lines above zero, where S(Ω_k)ΔΩ misjudges the area by
several per cent; with cell integrals the mean square of every sample equals
∫_band S dΩ to the accuracy of an 8-point Gauss–Legendre rule per cell.

A vehicle running at speed V meets the wavenumber Ω at the circular frequency
ω = VΩ, and keeps the variance: S_t(ω) dω = S(Ω) dΩ, so S_t(ω) = S(ω/V)/V. An
axle a distance d behind the first meets the same track a time d/V later
(:func:`axle_delays`, :func:`excitation_csd`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from raildyn import _checks, plots
from raildyn import random_vibration as rv
from raildyn._tables import Tabular
from raildyn.track.deterministic import _vehicle_speed
from raildyn.track.spectra import COMPONENTS, _wavenumber_band, track_psd

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib

__all__ = [
    "ComponentVariances",
    "IrregularitySample",
    "TwoRailIrregularity",
    "axle_filter_wavelengths",
    "synthesize_irregularity",
    "synthesize_track",
    "temporal_psd",
    "spatial_to_temporal",
    "axle_delays",
    "excitation_csd",
]

# Gauss–Legendre nodes and weights on [−1/2, 1/2], for the integral of S over each line's cell.
_GL_NODES, _GL_WEIGHTS = np.polynomial.legendre.leggauss(8)
_GL_NODES, _GL_WEIGHTS = 0.5 * _GL_NODES, 0.5 * _GL_WEIGHTS

# At most this many points in one call of the synthesis (n × n_samples): 80 MB of samples, e.g. a
# 2500 km track at 0.25 m; beyond that the FFT's memory, not the spectrum, sets the limit.
_MAX_POINTS = 10_000_000
# Wavenumbers (rad/m) at which temporal_psd tries a spectrum when it is given: wavelengths 0.6–63 m.
_PROBE = np.array([0.1, 1.0, 10.0])


@dataclass(frozen=True)
class IrregularitySample(Tabular):
    """A sampled irregularity along the track.

    Attributes
    ----------
    x : ndarray
        Distance along the track, m (``arange(n) * dx``), strictly increasing, not empty.
    z : ndarray
        Irregularity, m: shape ``(n,)``, or ``(n_samples, n)``.
    band : (float, float)
        Wavenumber band kept, rad/m, 0 < low < high (the top is lowered to the cell
        edge of the highest line when the band reaches the Nyquist wavenumber π/dx).
    variance : float
        ∫_band S dΩ, m², >= 0; the mean square of every sample over its length.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("x", "m"), ("z", "m"))
    _scalars = (("variance", "m²"),)
    _by_row = ("z",)

    x: np.ndarray
    z: np.ndarray
    band: tuple[float, float]
    variance: float

    def __post_init__(self):
        x = _checks.time_grid("x", self.x)
        z = _checks.array("z", self.z, allow_empty=False)
        if z.ndim not in (1, 2) or z.shape[-1] != x.size:
            raise ValueError(
                f"z must have shape ({x.size},) or (n_samples, {x.size}) to match x, got {z.shape}"
            )
        object.__setattr__(self, "x", x)
        object.__setattr__(self, "z", z)
        object.__setattr__(self, "band", _checks.interval("band", self.band, unit="rad/m"))
        object.__setattr__(self, "variance", _checks.nonnegative("variance", self.variance))

    @property
    def rms(self) -> float:
        """√variance, m: the RMS the spectrum gives over the band."""
        return float(np.sqrt(self.variance))

    @property
    def measured_rms(self) -> float | np.ndarray:
        """RMS of the sample over its length, m (one per sample); equal to :attr:`rms` to rounding."""
        value = np.sqrt(np.mean(self.z**2, axis=-1))
        return float(value) if np.ndim(value) == 0 else value

    def plot(self, ax=None) -> dict:
        """Draw the (first) sample in mm against distance, with the ±RMS lines.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.

        Returns
        -------
        dict
            The artists ``line``, ``upper`` and ``lower``.
        """
        import matplotlib

        ax = plots.axes_or_new(ax)
        z = self.z if self.z.ndim == 1 else self.z[0]
        with matplotlib.rc_context(plots.STYLE):
            (line,) = ax.plot(self.x, 1e3 * z, color=plots.COLORS[0], lw=0.8)
            upper = ax.axhline(1e3 * self.rms, color="0.5", ls="--", lw=1)
            lower = ax.axhline(-1e3 * self.rms, color="0.5", ls="--", lw=1)
            ax.set_xlabel("distance $x$ (m)")
            ax.set_ylabel("irregularity (mm)")
        return {"line": line, "upper": upper, "lower": lower}


def _cell_psd(psd: Callable, lo: float, hi: float, d_omega: float) -> Callable:
    """A callable giving, at each line Ω_k, the mean of S over the part of its cell inside [lo, hi]."""

    def averaged(w):
        a = np.clip(w - 0.5 * d_omega, lo, hi)
        b = np.clip(w + 0.5 * d_omega, lo, hi)
        width = b - a
        inside = width > 0
        out = np.zeros_like(w)
        if np.any(inside):
            ai, wi = a[inside], width[inside]
            nodes = (ai + 0.5 * wi)[:, None] + wi[:, None] * _GL_NODES[None, :]
            values = _checks.returned("psd", psd(nodes.ravel()), shape=(nodes.size,), low=0.0)
            values = values.reshape(nodes.shape)
            out[inside] = (values @ _GL_WEIGHTS) * wi / d_omega
        return out

    return averaged


def synthesize_irregularity(
    psd: Callable,
    length: float,
    dx: float,
    wavelength_band: tuple[float, float],
    rng=None,
    *,
    n_samples: int = 1,
) -> IrregularitySample:
    """Seeded sample(s) of a stationary Gaussian irregularity with a given spatial spectrum.

    z(x) = Σ_k √(2 G_k ΔΩ) cos(Ω_k x + φ_k), Ω_k = kΔΩ, ΔΩ = 2π/length, φ_k
    uniform and independent, G_k the mean of S over line k's cell inside the band
    (module docstring); evaluated by one inverse FFT through
    :func:`raildyn.random_vibration.synthesize`.

    Parameters
    ----------
    psd : callable
        One-sided S(Ω) in m²/(rad/m), Ω in rad/m (e.g. ``lambda w: fra_psd("vertical", 4, w)``):
        given a 1-D array of wavenumbers it returns as many finite values >= 0 (checked).
    length : float
        Length of track, m, > 0; the sample has period ``length``.
    dx : float
        Spacing, m, > 0; ``length/dx`` is rounded to the number of points n >= 4.
    wavelength_band : (shortest, longest)
        Wavelengths kept, m: needs 2·dx <= shortest < longest <= length.
    rng : numpy.random.Generator, int or None
        Source of the phases; the same seed gives the same sample.
    n_samples : int
        Independent samples, >= 1. The points of all the samples, n × n_samples, are at
        most 10⁷ (80 MB): the memory of one FFT sets that limit.

    Returns
    -------
    IrregularitySample
        ``z`` has mean square ``variance`` = ∫_band S dΩ over its length.

    Examples
    --------
    >>> from raildyn.track import fra_psd
    >>> s = synthesize_irregularity(lambda w: fra_psd("vertical", 5, w), 1000.0, 0.25, (2.0, 200.0), rng=1)
    >>> bool(np.isclose(np.mean(s.z**2), s.variance, rtol=1e-12))
    True
    """
    psd = _checks.function("psd", psd)
    length = _checks.positive("length", length)
    dx = _checks.positive("dx", dx)
    n_samples = _checks.integer("n_samples", n_samples, low=1, high=_MAX_POINTS)
    if length / dx * n_samples > _MAX_POINTS:
        raise ValueError(
            f"n_samples × length/dx must be at most {_MAX_POINTS:.0e} points (the memory of the FFT), "
            f"got length={length!r}, dx={dx!r}, n_samples={n_samples!r}"
        )
    n = int(round(length / dx))
    if n < 4:
        raise ValueError(f"length/dx must give at least 4 points, got length={length!r}, dx={dx!r}")
    lo, hi = _wavelength_band_checked(wavelength_band, n * dx, dx)
    d_omega = 2.0 * np.pi / (n * dx)
    # The highest line is k = ⌈n/2⌉ − 1; its cell ends half a spacing above it, just under the Nyquist
    # wavenumber π/dx. The band kept (and reported) stops there.
    hi = min(hi, ((n - 1) // 2 + 0.5) * d_omega)
    averaged = _cell_psd(psd, lo, hi, d_omega)
    seen = {}

    def recorded(w):  # keep the line values that synthesize uses, to sum them without a second evaluation
        seen["values"] = averaged(w)
        return seen["values"]

    z = rv.synthesize(recorded, dx, n, rng, n_samples=n_samples)
    variance = float(np.sum(seen["values"]) * d_omega)
    return IrregularitySample(np.arange(n) * dx, z, (lo, hi), variance)


def _wavelength_band_checked(band, length: float, dx: float) -> tuple[float, float]:
    """Wavenumber band of a wavelength band, checked against the record: 2·dx <= L_min, L_max <= length."""
    lo, hi = _wavenumber_band(band, "wavelength_band")
    shortest, longest = 2 * np.pi / hi, 2 * np.pi / lo
    if shortest < 2.0 * dx * (1 - 1e-12):
        raise ValueError(
            f"wavelength_band shortest wavelength {shortest!r} m is below 2*dx = {2 * dx!r} m "
            "(the Nyquist limit of the spacing)"
        )
    if longest > length * (1 + 1e-12):
        raise ValueError(
            f"wavelength_band longest wavelength {longest!r} m exceeds the record length {length!r} m"
        )
    return lo, hi


@dataclass(frozen=True)
class ComponentVariances:
    """Variances ∫_band S dΩ of the four track irregularities, m².

    Attributes
    ----------
    vertical, alignment, cross_level, gauge : float
        One per component of ``raildyn.track.spectra.COMPONENTS``, m², >= 0.
    """

    vertical: float
    alignment: float
    cross_level: float
    gauge: float

    def __post_init__(self):
        for name in COMPONENTS:
            object.__setattr__(self, name, _checks.nonnegative(name, getattr(self, name)))


@dataclass(frozen=True)
class TwoRailIrregularity(Tabular):
    """A two-rail track sample: four irregularities along distance, consistent by construction.

    The vertical profile and alignment are those of the track centreline, the
    cross-level and gauge the differences between the rails, all in m:

        z_left = vertical + cross_level/2,   z_right = vertical − cross_level/2,
        y_left = alignment + gauge/2,        y_right = alignment − gauge/2

    (left minus right for the cross-level, and gauge growing as the rails part,
    with y positive to the left), so the cross-level and gauge computed from the
    rails are exactly the sampled ones.

    Attributes
    ----------
    x : ndarray
        Distance, m, strictly increasing, not empty.
    vertical, alignment, cross_level, gauge : ndarray
        Irregularities, m, each of the shape of ``x``.
    variances : ComponentVariances
        ∫_band S dΩ of each component, m².
    """

    _columns = (("x", "m"), ("vertical", "m"), ("alignment", "m"), ("cross_level", "m"), ("gauge", "m"))

    x: np.ndarray
    vertical: np.ndarray
    alignment: np.ndarray
    cross_level: np.ndarray
    gauge: np.ndarray
    variances: ComponentVariances

    def __post_init__(self):
        x = _checks.time_grid("x", self.x)
        object.__setattr__(self, "x", x)
        for name in COMPONENTS:
            object.__setattr__(self, name, _checks.array(name, getattr(self, name), shape=x.shape))
        _checks.instance("variances", self.variances, ComponentVariances)

    @property
    def left_vertical(self) -> np.ndarray:
        """Height of the left rail, vertical + cross_level/2, m."""
        return self.vertical + 0.5 * self.cross_level

    @property
    def right_vertical(self) -> np.ndarray:
        """Height of the right rail, vertical − cross_level/2, m."""
        return self.vertical - 0.5 * self.cross_level

    @property
    def left_lateral(self) -> np.ndarray:
        """Lateral position of the left rail, alignment + gauge/2, m."""
        return self.alignment + 0.5 * self.gauge

    @property
    def right_lateral(self) -> np.ndarray:
        """Lateral position of the right rail, alignment − gauge/2, m."""
        return self.alignment - 0.5 * self.gauge

    def _component(self, component: str) -> str:
        return _checks.choice("component", component, COMPONENTS)

    def rms(self, component: str) -> float:
        """RMS the spectrum gives a component over the band, √(∫_band S dΩ), m.

        Parameters
        ----------
        component : {"vertical", "alignment", "cross_level", "gauge"}
            Which irregularity.

        Returns
        -------
        float
            m.
        """
        return float(np.sqrt(getattr(self.variances, self._component(component))))

    def measured_rms(self, component: str) -> float:
        """RMS of a component of this sample over its length, m; equal to :meth:`rms` to rounding.

        Parameters
        ----------
        component : {"vertical", "alignment", "cross_level", "gauge"}
            Which irregularity.

        Returns
        -------
        float
            m.
        """
        return float(np.sqrt(np.mean(getattr(self, self._component(component)) ** 2)))

    def plot(self, axes=None) -> dict:
        """Draw both rails, vertical and lateral, in mm on two axes.

        Parameters
        ----------
        axes : sequence of two matplotlib.axes.Axes, optional
            Vertical above lateral; new ones on a new pyplot figure if None.

        Returns
        -------
        dict
            The lines ``left_vertical``, ``right_vertical``, ``left_lateral`` and ``right_lateral``.
        """
        import matplotlib

        if axes is not None:
            from matplotlib.axes import Axes

            if isinstance(axes, (str, bytes)) or not (
                hasattr(axes, "__len__") and len(axes) == 2 and all(isinstance(a, Axes) for a in axes)
            ):
                raise TypeError(
                    f"axes must be a sequence of two matplotlib.axes.Axes or None, got {axes!r:.80}"
                )
        else:
            import matplotlib.pyplot as plt

            with matplotlib.rc_context(plots.STYLE):
                _, axes = plt.subplots(2, 1, sharex=True, figsize=(8.0, 4.0), layout="constrained")
        lines = {}
        with matplotlib.rc_context(plots.STYLE):
            for ax, kind in zip(axes, ("vertical", "lateral"), strict=True):
                for i, side in enumerate(("left", "right")):
                    values = getattr(self, f"{side}_{kind}")
                    (lines[f"{side}_{kind}"],) = ax.plot(
                        self.x, 1e3 * values, color=plots.COLORS[i], lw=0.8, label=f"{side} rail"
                    )
                ax.set_ylabel(f"{kind} (mm)")
            axes[0].legend(loc="upper right", ncols=2)
            axes[-1].set_xlabel("distance $x$ (m)")
        return lines


def synthesize_track(
    spectrum: str,
    grade,
    length: float,
    dx: float,
    wavelength_band: tuple[float, float],
    rng=None,
) -> TwoRailIrregularity:
    """A two-rail sample: vertical, alignment, cross-level and gauge drawn independently.

    The sources give no cross-spectra between the four components, so they are
    sampled as independent processes (from one generator, in the order of
    ``raildyn.track.spectra.COMPONENTS``).

    Parameters
    ----------
    spectrum : {"fra", "german"}
        The family of spectra.
    grade : int or str
        FRA class 1–6 or German level "low"/"high".
    length : float
        Length of track, m.
    dx : float
        Spacing, m, > 0.
    wavelength_band : (shortest, longest)
        Wavelengths kept, m, as for :func:`synthesize_irregularity`.
    rng : numpy.random.Generator, int or None
        Source of the phases of all four components.

    Returns
    -------
    TwoRailIrregularity
        The four irregularities, their rails and their band variances.

    Examples
    --------
    >>> t = synthesize_track("fra", 4, 1000.0, 0.25, (1.524, 304.8), rng=2026)
    >>> round(1e3 * t.rms("vertical"), 1), bool(np.isclose(t.measured_rms("gauge"), t.rms("gauge")))
    (25.0, True)
    """
    generator = _checks.generator(rng)
    parts, variances = {}, {}
    for component in COMPONENTS:
        sample = synthesize_irregularity(
            track_psd(spectrum, component, grade), length, dx, wavelength_band, generator
        )
        parts[component], variances[component] = sample.z, sample.variance
    return TwoRailIrregularity(sample.x, variances=ComponentVariances(**variances), **parts)


def temporal_psd(psd: Callable, speed: float) -> Callable:
    """S_t(ω) = S(ω/V)/V: the spectrum in time, per rad/s, of a track spectrum met at speed V.

    Parameters
    ----------
    psd : callable
        Spatial one-sided S(Ω), m²/(rad/m), Ω in rad/m: given an array of wavenumbers
        it returns as many finite values >= 0. It is tried once now, at Ω = 0.1, 1
        and 10 rad/m, and what it returns is checked at every later call too.
    speed : float
        V, m/s, 0 < V <= 1000 (six times the rail speed record; the spectrum in time
        divides S(ω/V), which grows without bound as ω/V → 0, by V).

    Returns
    -------
    callable
        S_t(ω), m²/(rad/s), ω in rad/s (an array, or a number, of wavenumbers).

    Examples
    --------
    >>> round(float(temporal_psd(lambda w: 1.0 / w**2, 10.0)(20.0)), 6)  # S(2)/10
    0.025
    """
    V = _vehicle_speed(speed)
    psd = _checks.function("psd", psd)
    _checks.returned("psd", psd(_PROBE), shape=_PROBE.shape, low=0.0, at=f"Ω = {_PROBE.tolist()} rad/m")

    def in_time(omega):
        w = np.asarray(omega, dtype=float)
        return _checks.returned("psd", psd(w / V), shape=w.shape, low=0.0) / V

    return in_time


def spatial_to_temporal(psd_values, wavenumber, speed) -> rv.Spectrum:
    """Convert a spatial spectrum on a grid to time: ω = VΩ and S_t = S/V.

    Parameters
    ----------
    psd_values : array_like
        One-sided S(Ω) >= 0, m²/(rad/m), one per wavenumber.
    wavenumber : array_like, shape (n,)
        Ω >= 0, rad/m: a grid, strictly increasing, not empty.
    speed : float
        V > 0, m/s.

    Returns
    -------
    raildyn.random_vibration.Spectrum
        ``omega`` (rad/s) and the one-sided ``psd`` S_t(ω), m²/(rad/s);
        ∫ S_t dω = ∫ S dΩ over matching bands.

    Examples
    --------
    >>> s = spatial_to_temporal([2.0, 2.0], [0.0, 1.0], 10.0)
    >>> s.omega.tolist(), s.psd.tolist()
    ([0.0, 10.0], [0.2, 0.2])
    """
    V = _checks.speed("speed", speed)
    W = _checks.time_grid("wavenumber", wavenumber)
    if W[0] < 0:
        raise ValueError(f"wavenumber must be >= 0 rad/m, got {W[0]!r}")
    S = _checks.array("psd_values", psd_values, shape=W.shape, low=0.0)
    return rv.Spectrum(omega=V * W, psd=S / V)


def axle_delays(axle_positions, speed) -> np.ndarray:
    """Time delays τ_j = d_j/V of axles at distances d_j behind the first, at speed V.

    Parameters
    ----------
    axle_positions : array_like, shape (q,)
        Distances d_j, m, behind a common origin, not empty; the first is the
        reference. Positions may repeat (two inputs under one axle) or lie ahead of
        the first (a negative delay).
    speed : float
        V > 0, m/s.

    Returns
    -------
    ndarray, shape (q,)
        τ_j, s (τ_0 = 0).

    Examples
    --------
    >>> axle_delays([0.0, 2.5, 17.5], 25.0).tolist()
    [0.0, 0.1, 0.7]
    """
    V = _checks.speed("speed", speed)
    d = _checks.array("axle_positions", axle_positions, ndim=1)
    if d.size == 0:
        raise ValueError("axle_positions must hold at least one axle, got an empty array")
    return (d - d[0]) / V


def excitation_csd(psd: Callable, omega, axle_positions, speed) -> np.ndarray:
    """Cross-spectral matrix in time of the track met by several axles (m²/(rad/s)).

    S_jk(ω) = S_t(ω) exp(−iω(τ_j − τ_k)), S_t(ω) = S(ω/V)/V and τ_j = d_j/V, built by
    :func:`raildyn.random_vibration.delayed_input_csd`; ready for
    :func:`raildyn.random_vibration.response_psd`.

    Parameters
    ----------
    psd : callable
        Spatial one-sided S(Ω), m²/(rad/m).
    omega : array_like, shape (n,)
        Circular frequencies > 0, rad/s, not empty.
    axle_positions : array_like, shape (q,)
        Distances of the axles, m, as for :func:`axle_delays`.
    speed : float
        V, m/s, 0 < V <= 1000, as for :func:`temporal_psd`.

    Returns
    -------
    ndarray, complex, shape (n, q, q)
        The Hermitian cross-spectral matrix.
    """
    w = _checks.array("omega", omega, ndim=1, low=0.0, low_open=True, allow_empty=False)
    delays = axle_delays(axle_positions, speed)
    return rv.delayed_input_csd(temporal_psd(psd, speed)(w), w, delays)


def axle_filter_wavelengths(axle_spacing: float, count: int) -> np.ndarray:
    """Wavelengths L_j = 2d/(2j + 1) that the mean of two axles a distance d apart does not feel.

    Each axle meets the same track d apart; where d is an odd number of half
    wavelengths the two see opposite irregularities and their mean (the bounce
    of a bogie or a car) is zero, whatever the speed. At speed V these are the
    frequencies V/L_j (:func:`~raildyn.track.deterministic.passing_frequency`), i.e. the
    :func:`raildyn.random_vibration.cancellation_frequencies` for τ = d/V.

    Parameters
    ----------
    axle_spacing : float
        d, m, > 0.
    count : int
        Number of wavelengths, 1 <= count <= 10⁶ (a table, held in memory).

    Returns
    -------
    ndarray, shape (count,)
        L_j, m, j = 0 … count − 1, longest first.

    Examples
    --------
    >>> axle_filter_wavelengths(2.5, 3).round(4).tolist()
    [5.0, 1.6667, 1.0]
    """
    d = _checks.positive("axle_spacing", axle_spacing)
    n = _checks.integer("count", count, low=1, high=1_000_000)
    return 2.0 * d / (2 * np.arange(n) + 1)
