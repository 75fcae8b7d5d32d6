"""The ride of a vehicle on random track, two ways: from the track's spectrum and along one sample of it.

:func:`ride_run` gives the output's response spectrum at speed V and its ride measures
(:func:`raildyn.ride.ride_quality`) beside a time run along a periodic sample of the same track
(:func:`raildyn.vehicles.time_domain.time_response`) and the measures of that history
(:func:`raildyn.ride.ride_quality_history`), so that a reader sees the two agree (book
chapter 6). The run starts from rest and drops its first ``settle`` seconds.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks, ride
from raildyn._tables import Tabular
from raildyn.vehicles.response import ResponseSpectrum, response_spectrum
from raildyn.vehicles.time_domain import PeriodicProfile, time_response

__all__ = ["RideRun", "ride_run"]

_MAX_STEPS = 1_000_000  # time steps of one run: 10⁶ steps of a 30-state car take about a second


@dataclass(frozen=True)
class RideRun(Tabular):
    """The ride of a vehicle at one speed on one track, two ways.

    Attributes
    ----------
    spectrum : raildyn.vehicles.ResponseSpectrum
        The output's acceleration spectrum, one-sided per rad/s.
    frequency_domain : raildyn.ride.RideQuality
        RMS, Sperling's Wz and the ISO 2631 weighted RMS of ``spectrum``.
    t : ndarray, shape (n,)
        Time of the run, s, from 0 (the settling time dropped); strictly increasing, not empty.
    acceleration : ndarray, shape (n,)
        The output's acceleration along the run, m/s².
    time_domain : raildyn.ride.RideQuality
        The same measures of ``acceleration``.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("t", "s"), ("acceleration", "m/s²"))

    spectrum: ResponseSpectrum
    frequency_domain: ride.RideQuality
    t: np.ndarray
    acceleration: np.ndarray
    time_domain: ride.RideQuality

    def __post_init__(self):
        _checks.instance("spectrum", self.spectrum, ResponseSpectrum)
        _checks.instance("frequency_domain", self.frequency_domain, ride.RideQuality)
        _checks.instance("time_domain", self.time_domain, ride.RideQuality)
        t = _checks.time_grid("t", self.t)
        object.__setattr__(self, "t", t)
        object.__setattr__(
            self, "acceleration", _checks.array("acceleration", self.acceleration, shape=t.shape)
        )


def ride_run(
    vehicle,
    psd,
    speed,
    profile: PeriodicProfile,
    frequencies_hz,
    *,
    output="body z",
    dt: float = 0.01,
    settle: float = 10.0,
) -> RideRun:
    """The output's acceleration spectrum and ride measures beside a time run along one track sample.

    The spectrum is :func:`~raildyn.vehicles.response.response_spectrum` (acceleration) on the
    grid ω = 2π ``frequencies_hz``, measured by :func:`raildyn.ride.ride_quality`; the run is
    :func:`~raildyn.vehicles.time_domain.time_response` along ``profile`` (one period repeated)
    from rest for ``settle`` s plus one period's time, with the first ``settle`` s dropped,
    measured by :func:`raildyn.ride.ride_quality_history`. When ``profile`` is a sample of
    the track ``psd`` describes, the two sets of measures agree within the sample's scatter.

    Parameters
    ----------
    vehicle : LinearModel or LinearSystem
        A vehicle of :mod:`raildyn.vehicles` with vertical rail inputs (such as
        ``raildyn.vehicles.MANCHESTER_VERTICAL``).
    psd : TrackSpectrum
        The track's vertical spectrum (:func:`raildyn.track.spectra.track_psd`), one-sided per rad/m.
    speed : float
        V, m/s, in [0.001, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    profile : PeriodicProfile
        The track sample the run follows (:func:`~raildyn.vehicles.time_domain.periodic_profile`).
    frequencies_hz : array_like, (k,)
        The spectrum's grid, Hz: strictly increasing, > 0, at least two.
    output : str, (str, float) or array_like
        The output, as :meth:`raildyn.linear_model.LinearSystem.output_vector` (the body centre's
        bounce by default).
    dt : float
        The run's time step, s (> 0); the run takes at most 10⁶ steps.
    settle : float
        Time dropped from the start of the run, s (≥ 0): the car starts at rest.

    Returns
    -------
    RideRun
        The spectrum and its measures, and the run and its measures.

    Examples
    --------
    >>> from raildyn import track
    >>> from raildyn.vehicles import MANCHESTER_VERTICAL, periodic_profile
    >>> psd = track.track_psd("fra", "vertical", 4)
    >>> z = track.synthesize_irregularity(psd, 500.0, 0.25, (1.0, 300.0), 1).z.reshape(-1)
    >>> f = np.linspace(0.05, 30.0, 600)
    >>> run = ride_run(MANCHESTER_VERTICAL, psd, 120.0 / 3.6, periodic_profile(z, 0.25), f)
    >>> bool(abs(run.time_domain.rms / run.frequency_domain.rms - 1.0) < 0.3)
    True
    """
    _checks.instance(
        "profile", profile, PeriodicProfile, "PeriodicProfile (raildyn.vehicles.periodic_profile)"
    )
    f = _checks.increasing("frequencies_hz", frequencies_hz, low=0.0, low_open=True)
    if f.size < 2:
        raise ValueError(f"frequencies_hz must hold two frequencies at least, got {f.size}")
    dt = _checks.positive("dt", dt)
    settle = _checks.nonnegative("settle", settle)
    V = _checks.speed("speed", speed, low=1.0e-3, low_open=False)
    steps = (settle + profile.period / V) / dt
    if steps > _MAX_STEPS:
        raise ValueError(
            f"dt and settle must give at most {_MAX_STEPS} steps over the run ({settle:g} s and one period, "
            f"{profile.period:g} m, at {V:g} m/s), got {dt!r}: {steps:.3g} steps"
        )
    w = 2 * np.pi * f
    spectrum = response_spectrum(vehicle, psd, V, w, output, derivative=2)
    frequency_domain = ride.ride_quality(spectrum.psd, w)
    t = np.arange(0.0, settle + profile.period / V, dt)
    run = time_response(vehicle, profile.height, V, t, output, derivative=2, profile_rate=profile.slope)
    keep = t >= settle
    if np.count_nonzero(keep) < 2:
        raise ValueError(
            f"dt and settle must leave two steps of the run at least, got dt {dt!r} s, settle {settle!r} s"
        )
    time_domain = ride.ride_quality_history(run.y[keep], dt)
    return RideRun(spectrum, frequency_domain, t[keep] - settle, run.y[keep], time_domain)
