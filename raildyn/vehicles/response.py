"""Linear vehicles driven by the track: FRFs, response spectra and time histories (chapter 6).

Every vehicle here is a linear model of the one protocol
(:class:`raildyn.linear_model.LinearModel`), whose system is

    M q'' + C(V) q' + K q = G_K w(t) + G_C w'(t),

q the body coordinates, w the track inputs under its wheels (rail heights,
alignment or cross-level, :data:`raildyn.linear_model.INPUT_KINDS`). Input j is
the track met at distance d_j behind the leading axle: w_j(t) = u(t − τ_j) with
τ_j = d_j/V. The speed V is given once, to each function here, and reaches both
the delays and the creep damping of the lateral models.

* :func:`track_frf` — H(ω) = Σ_j a_j H_j(ω) e^{−iωτ_j}: from the track met by the
  leading axle to the output;
* :func:`response_spectrum` — response PSD and RMS for spatial track spectra at
  speed V, one per irregularity component, the components independent
  (:func:`raildyn.track.synthesis.excitation_csd` and
  :func:`raildyn.random_vibration.response_psd`);
* :func:`rms_over_speeds` — the RMS of :func:`response_spectrum` at many speeds;
* :func:`time_response` — the history over a track profile by ``scipy.signal.lsim``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import matplotlib
import numpy as np

from raildyn import _checks, plots
from raildyn import random_vibration as rv
from raildyn import track as _track
from raildyn.linear_model import INPUT_KINDS, LinearSystem, as_linear_system

__all__ = [
    "PeriodicProfile",
    "ResponseSpectrum",
    "TimeResponse",
    "periodic_profile",
    "response_spectrum",
    "rms_over_speeds",
    "time_response",
    "track_frf",
]


def _rail_weights(system: LinearSystem, component: str) -> np.ndarray:
    """a_j: how an irregularity of the given component reaches each input.

    An input of the same kind takes it whole; a rail-height input takes a vertical
    irregularity whole and a cross-level c as ±c/2 on the left/right rail.
    """
    if component not in INPUT_KINDS:
        raise ValueError(f"component must be one of {INPUT_KINDS}; got {component!r}")
    kinds = np.array(system.input_kinds)
    weights = (kinds == component).astype(float)
    if component == "cross_level":  # left − right = c: the left rail at +c/2, the right at −c/2
        weights += np.where(kinds == "vertical", 0.5 * system.input_rails, 0.0)
    return weights


def _steady_system(vehicle, speed) -> tuple[LinearSystem, float]:
    """The vehicle's system and V, refusing a speed at which the model is unstable (no steady response)."""
    system = as_linear_system(vehicle)
    V = _checks.positive("speed", speed)
    if np.any(system.C1):
        growth = np.linalg.eigvals(system.matrices(V).state_matrix()).real.max()
        if growth >= 0:
            raise ValueError(
                f"speed {V!r} m/s is at or above the critical speed of this vehicle (an eigenvalue has real "
                f"part {growth:.3g} 1/s >= 0): no steady response"
            )
    return system, V


def track_frf(vehicle, omega, speed, output="body z", derivative: int = 0, component: str = "vertical"):
    """H(ω) = Σ_j a_j H_j(ω) e^{−iωτ_j}: from the track under the leading axle to the output.

    a_j is 1 for an input of the component's kind, and ±1/2 on the left/right
    rail for a cross-level met by rail-height inputs.

    Parameters
    ----------
    vehicle : LinearModel or LinearSystem
    omega : array_like, (n_ω,)
        rad/s, ≥ 0.
    speed : float
        V, m/s (> 0, below the critical speed of a lateral model).
    output : str, (str, float) or array_like
        See :meth:`raildyn.linear_model.LinearSystem.output_vector`.
    derivative : {0, 1, 2}
        Output in m, m/s or m/s² per m of track.
    component : {"vertical", "alignment", "cross_level"}

    Returns
    -------
    ndarray, complex, (n_ω,)
    """
    system, V = _steady_system(vehicle, speed)
    Hj = system.axle_frf(omega, V, output, derivative)
    tau = _track.axle_delays(system.input_positions, V)
    return _delayed_sum(Hj, _rail_weights(system, component), np.asarray(omega, dtype=float), tau)


def _delayed_sum(Hj, weights, omega, delays) -> np.ndarray:
    """Σ_j a_j H_j(ω) e^{−iωτ_j}: each input met τ_j after the leading axle; ``delays`` (q,) or (n_V, q)."""
    phase = np.exp(-1j * omega[:, None] * delays[..., None, :])  # (..., n_ω, q)
    return np.einsum("kj,j,...kj->...k", Hj, weights, phase)


@dataclass(frozen=True)
class ResponseSpectrum:
    """A response spectrum at one speed.

    Attributes
    ----------
    omega : ndarray
        rad/s.
    psd : ndarray
        One-sided PSD of the output, (unit)²/(rad/s).
    rms : float
        √∫S dω over the grid, in the output unit.
    speed : float
        m/s.
    """

    omega: np.ndarray
    psd: np.ndarray
    rms: float
    speed: float

    @property
    def frequency_hz(self) -> np.ndarray:
        """The grid in Hz."""
        return self.omega / (2 * np.pi)

    @property
    def psd_per_hz(self) -> np.ndarray:
        """The one-sided PSD per Hz, (unit)²/Hz, the form ride standards plot."""
        return rv.convert_psd(self.psd, from_sided="one", from_unit="rad/s", to_unit="Hz")

    def plot(self, ax=None, *, artists: dict | None = None, label: str | None = None, color=None) -> dict:
        """Draw the PSD per Hz against frequency in Hz, on a logarithmic axis.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default. Ignored when ``artists`` is given.
        artists : dict, optional
            The artists an earlier call returned: they are moved to this spectrum.
        label : str, optional
            Legend entry.
        color : optional
            Line colour; the house palette's first by default.

        Returns
        -------
        dict
            The artists: ``line``.
        """
        floor = 1e-12  # (unit)²/Hz: a logarithmic axis cannot show a zero
        y = np.maximum(self.psd_per_hz, floor)
        if artists is not None:
            artists["line"].set_data(self.frequency_hz, y)
            return artists
        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            (line,) = ax.semilogy(self.frequency_hz, y, color=plots.COLORS[0] if color is None else color,
                                  label=label)  # fmt: skip
            ax.set_xlabel("frequency (Hz)")
            ax.set_ylabel(r"PSD ((m/s$^2$)$^2$/Hz)")
        return {"line": line}


def _spectra(psd, component) -> dict:
    """{component: S(Ω)} from one spectrum and its component, or from a mapping of independent components."""
    if isinstance(psd, Mapping):
        if component is not None:
            raise ValueError(f"component must be None when psd is a mapping of components, got {component!r}")
        spectra = dict(psd)
    else:
        spectra = {"vertical" if component is None else component: psd}
    if not spectra:
        raise ValueError("psd must hold at least one spectrum")
    for name, S in spectra.items():
        if name not in INPUT_KINDS:
            raise ValueError(f"psd component must be one of {INPUT_KINDS}; got {name!r}")
        if not callable(S):
            raise TypeError(f"psd[{name!r}] must be a callable S(Ω) in m²/(rad/m), got {S!r}")
    return spectra


def response_spectrum(
    vehicle,
    psd,
    speed,
    omega,
    output="body z",
    derivative: int = 2,
    component: str | None = None,
) -> ResponseSpectrum:
    """Response PSD and RMS of an output for spatial track spectra S(Ω) (m²/(rad/m)) at speed V.

    For each irregularity component the inputs' cross-spectral matrix comes from
    :func:`raildyn.track.synthesis.excitation_csd` and the response from
    :func:`raildyn.random_vibration.response_psd`; the components (vertical
    profile, alignment, cross-level) are taken as independent processes, so
    their response PSDs add.

    Parameters
    ----------
    vehicle : LinearModel or LinearSystem
    psd : callable or mapping
        S(Ω), one-sided, m²/(rad/m), of the irregularity named by ``component``
        (default "vertical"); or a mapping {component: S} of independent components.
    speed : float
        V, m/s.
    omega : array_like
        rad/s, > 0.
    output : str, (str, float) or array_like
        See :meth:`raildyn.linear_model.LinearSystem.output_vector`.
    derivative : {0, 1, 2}
        Displacement, velocity or acceleration of the output.
    component : {"vertical", "alignment", "cross_level"}, optional
        With a single ``psd``: the component it describes.

    Returns
    -------
    ResponseSpectrum
    """
    system, V = _steady_system(vehicle, speed)
    w = _checks.array("omega", omega, ndim=1, low=0.0, low_open=True)
    Hj = system.axle_frf(w, V, output, derivative)
    S = np.zeros(w.size)
    for name, spectrum in _spectra(psd, component).items():
        H = Hj * _rail_weights(system, name)[None, :]
        S_in = _track.excitation_csd(spectrum, w, system.input_positions, V)
        S = S + rv.response_psd(H, S_in)
    return ResponseSpectrum(w, S, float(np.sqrt(rv.mean_square(S, w))), V)


def rms_over_speeds(
    vehicle, psd, speeds, omega, output="body z", derivative: int = 2, component: str | None = None
) -> np.ndarray:
    """The RMS of :func:`response_spectrum` at each speed, from one batched FRF solve where it can.

    A vehicle without creep damping (the vertical cars) has axle FRFs that do not
    depend on speed: only the delays and the temporal spectrum S(ω/V)/V do, so a
    speed costs one weighted sum over the grid. A lateral model's FRFs are solved
    again at each speed.

    Parameters
    ----------
    vehicle, psd, omega, output, derivative, component
        As for :func:`response_spectrum`.
    speeds : array_like, (n_V,)
        m/s, > 0.

    Returns
    -------
    ndarray, (n_V,)
        RMS of the output at each speed, in its unit.
    """
    system = as_linear_system(vehicle)
    V = _checks.array("speeds", speeds, ndim=1, low=0.0, low_open=True)
    w = _checks.array("omega", omega, ndim=1, low=0.0, low_open=True)
    spectra = _spectra(psd, component)
    if np.any(system.C1):
        return np.array([response_spectrum(system, spectra, v, w, output, derivative).rms for v in V])
    Hj = system.axle_frf(w, V[0], output, derivative)  # (n_ω, q), the same at every speed
    tau = _track.axle_delays(system.input_positions, 1.0)[None, :] / V[:, None]  # (n_V, q), s
    S = np.zeros((V.size, w.size))
    for name, spectrum in spectra.items():
        H = _delayed_sum(Hj, _rail_weights(system, name), w, tau)  # (n_V, n_ω)
        S = S + np.abs(H) ** 2 * np.asarray(spectrum(w[None, :] / V[:, None])) / V[:, None]
    return np.sqrt(np.trapezoid(S, w, axis=1))


@dataclass(frozen=True)
class TimeResponse:
    """A time history.

    Attributes
    ----------
    t : ndarray
        s.
    y : ndarray
        Output (m, m/s or m/s²).
    inputs : ndarray, (n_t, q)
        Track heights at the inputs, m.
    """

    t: np.ndarray
    y: np.ndarray
    inputs: np.ndarray


@dataclass(frozen=True)
class PeriodicProfile:
    """A track profile sampled over one period, with its exact slope.

    Attributes
    ----------
    heights : ndarray, (n,)
        The samples, m, every ``dx`` from x = 0.
    slopes : ndarray, (n,)
        dz/dx at the samples, the derivative of the sample's Fourier series.
    dx : float
        m.
    """

    heights: np.ndarray
    slopes: np.ndarray
    dx: float

    @property
    def period(self) -> float:
        """n·dx, m."""
        return self.heights.size * self.dx

    def _along(self, values, x) -> np.ndarray:
        grid = np.arange(values.size) * self.dx
        return np.interp(np.mod(x, self.period), grid, values, period=self.period)

    def height(self, x, rails=None) -> np.ndarray:
        """The profile at distances x (m), the signature :func:`time_response` takes.

        Parameters
        ----------
        x : array_like
            m; beyond one period the profile repeats.
        rails : array_like, optional
            Ignored: both rails alike.

        Returns
        -------
        ndarray
            m, shaped like ``x``.
        """
        return self._along(self.heights, x)

    def slope(self, x, rails=None) -> np.ndarray:
        """dz/dx at distances x (m), for ``profile_rate`` of :func:`time_response`.

        Parameters
        ----------
        x : array_like
            m.
        rails : array_like, optional
            Ignored.

        Returns
        -------
        ndarray
            Shaped like ``x``.
        """
        return self._along(self.slopes, x)


def periodic_profile(height, dx) -> PeriodicProfile:
    """A track profile sampled over one period, and its slope.

    ``height`` (m) is sampled every ``dx`` (m) over exactly one period of length
    n·dx (a synthesized sample is periodic); beyond it the profile repeats. The
    slope is the exact derivative of the sample's Fourier series, so the damper
    inputs of :func:`time_response` carry no finite-difference error.

    Parameters
    ----------
    height : array_like, (n,)
        m.
    dx : float
        Sample spacing, m (> 0).

    Returns
    -------
    PeriodicProfile

    Examples
    --------
    >>> z = 0.01 * np.sin(2 * np.pi * np.arange(100) * 0.5 / 25.0)
    >>> track = periodic_profile(z, 0.5)
    >>> round(float(track.slope(np.array([0.0]))[0]), 6)  # 0.01 · 2π/25
    0.002513
    """
    z = _checks.array("height", height, ndim=1)
    dx = _checks.positive("dx", dx)
    n = z.size
    rate = np.fft.irfft(2j * np.pi * np.fft.rfftfreq(n, dx) * np.fft.rfft(z), n=n)
    return PeriodicProfile(z, rate, dx)


def time_response(
    vehicle,
    profile: Callable,
    speed,
    t,
    output="body z",
    derivative: int = 0,
    profile_rate: Callable | None = None,
) -> TimeResponse:
    """History of an output as the vehicle runs over a profile, by ``scipy.signal.lsim``.

    Parameters
    ----------
    vehicle : LinearModel or LinearSystem
    profile : callable
        ``profile(x, rails)`` → track input (m) at each input at distances x
        (m, array (n_t, q)); ``rails`` is ``input_rails`` of the vehicle's system
        broadcast like x. The leading axle is at x = V t.
    profile_rate : callable, optional
        The slope dz/dx with the same signature; without it the damper inputs
        use a finite-difference slope.
    speed : float
        m/s.
    t : array_like
        Uniform times, s, starting from rest at static equilibrium.
    output : str, (str, float) or array_like
        See :meth:`raildyn.linear_model.LinearSystem.output_vector`.
    derivative : {0, 1, 2}
        Displacement, velocity or acceleration of the output.

    Returns
    -------
    TimeResponse
    """
    from scipy import signal

    vehicle, V = _steady_system(vehicle, speed)
    tt = _checks.time_grid("t", t, uniform=True)
    d = _checks.integer("derivative", derivative, low=0, high=2)
    o = vehicle.output_vector(output)
    x = V * tt[:, None] - vehicle.input_positions[None, :]
    rails = np.broadcast_to(vehicle.input_rails, x.shape)
    w = np.asarray(profile(x, rails), dtype=float)
    if profile_rate is not None:
        wdot = V * np.asarray(profile_rate(x, rails), dtype=float)
    else:
        wdot = np.gradient(w, tt, axis=0)
    n, q = vehicle.size, w.shape[1]
    mats = vehicle.matrices(V)
    A = mats.state_matrix()
    B = np.vstack([np.zeros((n, 2 * q)), np.linalg.solve(mats.M, np.hstack([mats.GK, mats.GC]))])
    if d == 0:
        Cs, D = np.concatenate([o, np.zeros(n)])[None, :], np.zeros((1, 2 * q))
    elif d == 1:
        Cs, D = np.concatenate([np.zeros(n), o])[None, :], np.zeros((1, 2 * q))
    else:
        Cs, D = (o @ A[n:])[None, :], (o @ B[n:])[None, :]
    _, y, _ = signal.lsim((A, B, Cs, D), np.hstack([w, wdot]), tt)
    return TimeResponse(tt, np.asarray(y, dtype=float).reshape(-1), w)
