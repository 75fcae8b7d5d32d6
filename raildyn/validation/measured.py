"""A real measured case: strain on the Lerelva railway bridge (Trondheim) under an NSB class 92 unit.

The record is a decimated extract (``raildyn/validation/data/``, with its provenance and terms
in the README there) of the strain measured by Slettebak (2016) for his master's thesis on
bridge weigh-in-motion: three gauges 1 m apart about the middle of the first stringer panel
at the Trondheim end of Lerelva bridge, a 25 m riveted steel truss of 1921 whose stringers
span the 4.17 m between its cross-girders (25 m in six panels). The train is a two-car NSB
class 92 diesel multiple unit running towards Heimdal (train 3 of the thesis).

:func:`lerelva_strain` loads the record; :func:`lerelva_case` runs the case study end to end:
bridge weigh-in-motion (:func:`raildyn.validation.bridge_wim.weigh_in_motion`) for the
speed, the axle pattern and the axle loads; two independent speed estimates; the chapter-10
prediction (:func:`raildyn.bridge.beam.moving_force_response` of the NSB 92's axles on the stringer as a
simply supported span); and its agreement with the measurement
(:func:`raildyn.validation.metrics.compare`).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.bridge import AxleSequence, SimplySupportedBeam, moving_force_response
from raildyn.constants import GRAVITY
from raildyn.validation.bridge_wim import WeighInMotionFit, weigh_in_motion
from raildyn.validation.metrics import Agreement, compare

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.signal

__all__ = [
    "LERELVA_PANEL",
    "NSB92_LOADS",
    "NSB92_SPACINGS",
    "LerelvaCase",
    "StrainRecord",
    "lerelva_case",
    "lerelva_strain",
]

_DATA = Path(__file__).resolve().parent / "data"
_RUNS = ("1603161045",)

#: Length of the stringer panel the gauges are on, m: the 25 m truss in six panels (Slettebak 2016, §3.2).
LERELVA_PANEL = 25.0 / 6.0

#: NSB class 92 axle spacings, m, leading axle first, read off the unit's drawing (``nsb92.png`` in the
#: source folder: bogie wheelbases 2.5 m and 2.55 m, 16.5 m between bogie centres, 3.575 m from the
#: inner bogie centres to the car ends and 0.5 m between the cars); the same values as the thesis's
#: ``readStrain.m`` (Slettebak 2016).
NSB92_SPACINGS = (2.5, 14.0, 2.5, 5.125, 2.55, 13.975, 2.5)

#: NSB class 92 nominal axle loads, N: the empty weights shared among the axles, 9 500 kg per axle of
#: the trailer and 14 575 kg of the motor car (Slettebak 2016, table "axle weights", from the NSB rolling
#: stock handbook), times g. Passengers are not included.
NSB92_LOADS = tuple([9500.0 * GRAVITY] * 4 + [14575.0 * GRAVITY] * 4)

#: First-to-last bogie-centre distance of the NSB 92, m: 16.5 + 7.65 + 16.5 from the drawing.
_BOGIE_SPAN = 16.5 + (3.575 + 0.5 + 3.575) + 16.5


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class StrainRecord(Tabular):
    """A strain record: gauges' time histories with their names, positions, units and provenance.

    Attributes
    ----------
    time : ndarray, (n,)
        t, s, uniformly spaced (from the start of the source record).
    strain : ndarray, (s, n)
        Strain at each gauge as recorded (dimensionless; the gauges' zero offsets remain).
    channels : tuple of str
        The gauges' names, one per row of ``strain``.
    positions : ndarray, (s,)
        Each gauge's distance from the panel's Trondheim end, m.
    units : tuple of str
        The unit of each row of ``strain``.
    rate_hz : float
        Sampling rate, Hz: 1/Δt of ``time`` (to 1e-6 relative).
    provenance : str
        Where the record comes from and what was done to it.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("time", "s"), ("strain", "-"))
    _scalars = (("rate_hz", "Hz"),)
    _labels = (("strain", "channels"),)
    _by_row = ("strain",)

    time: np.ndarray
    strain: np.ndarray
    channels: tuple
    positions: np.ndarray
    units: tuple
    rate_hz: float
    provenance: str

    def __post_init__(self):
        _checks.fields(self)
        t = _checks.time_grid("time", self.time, uniform=True)
        eps = _checks.array("strain", self.strain, ndim=2)
        if eps.shape[1] != t.size:
            raise ValueError(f"strain must have shape (s, {t.size}), got {eps.shape}")
        _checks.strings("channels", self.channels, eps.shape[0])
        _checks.strings("units", self.units, eps.shape[0])
        _checks.array("positions", self.positions, shape=(eps.shape[0],))
        rate = _checks.positive("rate_hz", self.rate_hz)
        if t.size > 1:
            step = (t[-1] - t[0]) / (t.size - 1)
            if abs(rate * step - 1.0) > 1e-6:  # the time vector's own rate, to the rounding of its times
                raise ValueError(
                    f"rate_hz must be the sampling rate of time, 1/Δt = {1.0 / step:.9g} Hz, "
                    f"got {self.rate_hz!r}"
                )
        _checks.instance("provenance", self.provenance, str)

    def zeroed(self, before: float | None = None) -> np.ndarray:
        """The strain less each gauge's zero offset (its median before the train), (s, n).

        Parameters
        ----------
        before : float, optional
            The time before which the bridge carries no train, s, with at least one sample
            before it; None: the first quarter of the record.

        Returns
        -------
        ndarray, (s, n)
        """
        if before is None:
            quiet = np.arange(self.time.size) < max(self.time.size // 4, 1)
        else:
            at = _checks.scalar("before", before, low=float(self.time[0]), low_open=True)
            quiet = self.time < at
        return self.strain - np.median(self.strain[:, quiet], axis=1, keepdims=True)

    def plot(self, ax=None) -> dict:
        """Draw each gauge's strain (its zero offset removed) in microstrain against time.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.

        Returns
        -------
        dict
            ``lines``: one line per gauge.
        """
        import matplotlib

        from raildyn import plots

        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            lines = [
                ax.plot(self.time, 1e6 * row, lw=0.8, color=plots.COLORS[i % 5], label=name)[0]
                for i, (row, name) in enumerate(zip(self.zeroed(), self.channels, strict=True))
            ]
            ax.set_xlabel("time (s)")
            ax.set_ylabel("strain (µε)")
            ax.legend()
        return {"lines": lines}


def lerelva_strain(run: str = "1603161045") -> StrainRecord:
    """The strain measured on Lerelva bridge as an NSB class 92 unit crossed (a decimated extract).

    Three gauges on the bottom of the first stringer panel at the Trondheim end (span
    :data:`LERELVA_PANEL`), at its middle and 1 m either side (Slettebak 2016, §3.3). The source
    recorded at 1024 Hz; the extract keeps the 10 s around the passage, low-pass filtered and
    decimated to 256 Hz (``scripts/extract_lerelva.py``; terms and provenance in
    ``raildyn/validation/data/README.md``).

    Parameters
    ----------
    run : str
        The record's name in the source (its start, yymmddHHMM): "1603161045", the only
        record of a train kept.

    Returns
    -------
    StrainRecord
        Rows in the order midspan, 1 m towards Trondheim, 1 m towards Heimdal.

    Examples
    --------
    >>> rec = lerelva_strain()
    >>> rec.strain.shape, rec.rate_hz
    ((3, 2560), 256.0)
    """
    _checks.choice("run", run, _RUNS)
    with np.load(_DATA / f"lerelva_{run}.npz") as data:
        rate = float(data["rate"])
        strain = data["strain"].astype(float)
        start = float(data["start"])
        channels = tuple(str(c) for c in data["channels"])
        source = str(data["source"])
    time = start + np.arange(strain.shape[1]) / rate
    half = LERELVA_PANEL / 2
    provenance = (
        f"Slettebak, T. H. (2016), master's thesis data, {source}; no licence granted, kept as a small "
        f"decimated extract for teaching and research with attribution. Decimated 1024 Hz -> {rate:g} Hz "
        f"(scipy.signal.decimate, zero phase), window {time[0]:g}-{time[-1] + 1 / rate:g} s of the record, "
        "values as recorded (strain, zero offsets kept), stored as float32."
    )
    return StrainRecord(
        time, strain, channels, np.array([half, half - 1.0, half + 1.0]), ("strain",) * 3, rate, provenance
    )


@dataclass(frozen=True, eq=False)
class LerelvaCase(Tabular):
    """The Lerelva case study: identification, prediction and agreement (see :func:`lerelva_case`).

    Attributes
    ----------
    record : StrainRecord
        The measurement.
    fit : WeighInMotionFit
        Weigh-in-motion with the NSB 92's spacings given: speed, arrival, axle loads in units of
        EI/c (the section is unknown), offsets.
    pattern : WeighInMotionFit
        Weigh-in-motion with the spacings free too (started from the drawing's).
    peak_speed : float
        Independent speed, m/s: the drawing's first-to-last bogie-centre distance (40.65 m)
        over the time between the first and the last strain maxima at midspan (one per bogie).
    lag_speed : float
        Speed from the cross-correlation lag of the two gauges 2 m apart, m/s.
    model_lag_speed : float
        The same estimator applied to the fitted model's strains at those gauges, m/s: what the
        lag reads for this influence line at the identified speed.
    time : ndarray, (n,)
        t, s.
    measured : ndarray, (3, n)
        The strain less its zero offsets.
    predicted : ndarray, (3, n)
        The chapter-10 prediction: ``scale`` × the deflection of
        :func:`raildyn.bridge.beam.moving_force_response`.
    scale : float
        The one factor fitted from deflection (m) to strain at the gauges, 1/m.
    agreement : tuple of Agreement
        :func:`raildyn.validation.metrics.compare` of measured and predicted, one per gauge.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("time", "s"), ("measured", "-"), ("predicted", "-"))
    _scalars = (("peak_speed", "m/s"), ("lag_speed", "m/s"), ("model_lag_speed", "m/s"), ("scale", "1/m"))
    _by_row = ("measured", "predicted")

    record: StrainRecord
    fit: WeighInMotionFit
    pattern: WeighInMotionFit
    peak_speed: float
    lag_speed: float
    model_lag_speed: float
    time: np.ndarray
    measured: np.ndarray
    predicted: np.ndarray
    scale: float
    agreement: tuple

    def __post_init__(self):
        _checks.fields(self)
        _checks.instance("record", self.record, StrainRecord)
        _checks.instance("fit", self.fit, WeighInMotionFit)
        _checks.instance("pattern", self.pattern, WeighInMotionFit)
        for name in ("peak_speed", "lag_speed", "model_lag_speed"):
            _checks.speed(name, getattr(self, name))
        t = _checks.array("time", self.time, ndim=1, allow_empty=False)
        m = _checks.array("measured", self.measured, ndim=2)
        if m.shape[1] != t.size:
            raise ValueError(f"measured must have shape (s, {t.size}), got {m.shape}")
        _checks.array("predicted", self.predicted, shape=m.shape)
        if not isinstance(self.agreement, tuple) or not all(isinstance(a, Agreement) for a in self.agreement):
            raise TypeError(f"agreement must be a tuple of Agreement, got {self.agreement!r:.80}")

    @property
    def pattern_spacings(self) -> np.ndarray:
        """The free fit's axle spacings rescaled to ``peak_speed``, m.

        The record fixes the times between axles, d_k/v, far better than v itself (the only
        length in the model is the span); these are those times at the independent speed.
        """
        return self.pattern.spacings * self.peak_speed / self.pattern.speed

    def plot(self, ax=None) -> dict:
        """Draw the measured and the predicted strain at each gauge, in microstrain.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.

        Returns
        -------
        dict
            ``measured`` and ``predicted``: lists of lines, one per gauge.
        """
        import matplotlib

        from raildyn import plots

        ax = plots.axes_or_new(ax)
        drawn = {"measured": [], "predicted": []}
        with matplotlib.rc_context(plots.STYLE):
            for i, name in enumerate(self.record.channels):
                color = plots.COLORS[i % 5]
                drawn["measured"].append(
                    ax.plot(self.time, 1e6 * self.measured[i], color=color, lw=0.6, alpha=0.6, label=name)[0]
                )
                drawn["predicted"].append(
                    ax.plot(self.time, 1e6 * self.predicted[i], color=color, lw=1.6, ls="--")[0]
                )
            ax.set_xlabel("time (s)")
            ax.set_ylabel("strain (µε); dashed: chapter-10 prediction")
            ax.legend()
        return drawn


def _lag_speed(t, first, second, distance):
    """Speed from the lag of the cross-correlation's peak of two records ``distance`` apart (m)."""
    from scipy import signal

    dt = t[1] - t[0]
    a, b = first - first.mean(), second - second.mean()
    corr = signal.correlate(b, a, mode="full")
    lags = signal.correlation_lags(b.size, a.size, mode="full")
    k = int(np.argmax(corr))
    shift = float(lags[k])
    if 0 < k < corr.size - 1:  # parabolic interpolation of the peak: a fraction of a sample
        y0, y1, y2 = corr[k - 1], corr[k], corr[k + 1]
        den = y0 - 2 * y1 + y2
        if den != 0.0:
            shift += 0.5 * (y0 - y2) / den
    if shift <= 0.0:
        raise ValueError(
            "the sensors' cross-correlation puts the second before the first: give positions in the "
            "direction of travel, or speed"
        )
    return distance / (shift * dt)


def _peak_speed(t, midspan, rate):
    """First-to-last bogie-centre distance over the time between the first and last bogie maxima."""
    from scipy import signal

    b, a = signal.butter(4, 8.0 / (rate / 2))  # keep the bogies' humps (~1-2 Hz), drop the ringing
    smooth = signal.filtfilt(b, a, midspan)
    peaks, _ = signal.find_peaks(smooth, height=0.3 * smooth.max(), distance=int(0.25 * rate))
    if peaks.size < 2:
        raise ValueError("the record shows fewer than two bogie maxima")
    return _BOGIE_SPAN / (t[peaks[-1]] - t[peaks[0]])


def lerelva_case(
    run: str = "1603161045",
    *,
    flexural_rigidity: float = 1.0e8,
    mass_per_length: float = 1.0e3,
    damping_ratio: float = 0.02,
) -> LerelvaCase:
    """The Lerelva case study end to end: identify the train, predict the strain, compare.

    1. Bridge weigh-in-motion (:func:`raildyn.validation.bridge_wim.weigh_in_motion`) on the
       three gauges over the passage, the stringer panel taken as a simply supported span of
       :data:`LERELVA_PANEL`: once with the NSB 92's spacings given (speed, arrival, axle loads),
       once with the spacings free too (the axle pattern).
    2. Two independent speeds: the drawing's bogie-centre distances over the times of the
       bogies' strain maxima, and the cross-correlation lag of the gauges 2 m apart.
    3. The chapter-10 prediction: :func:`raildyn.bridge.beam.moving_force_response` of the NSB 92 as an
       :class:`raildyn.bridge.AxleSequence` (the thesis's nominal loads) at the identified speed
       and arrival, at each gauge. The thesis gives no section for the stringer, so EI, m and c
       are not known: the deflection is turned into strain by one factor fitted by least squares
       over the three gauges, and ``flexural_rigidity``, ``mass_per_length`` set only the
       dynamics (assumed values for a riveted stringer of the period: f₁ ≈ 28 Hz with the
       defaults, α = v/(2f₁L) ≈ 0.09, so the response is nearly quasi-static).
    4. The agreement, gauge by gauge (:func:`raildyn.validation.metrics.compare`).

    The simple span leaves out what the real stringer has: continuity over the cross-girders
    (the measured strain turns negative as the axles load the neighbouring panels, which a
    simply supported span cannot do), the rails and sleepers spreading each axle over more
    than a point, and the truss's own deflection. The prediction's humps are therefore
    narrower than the measured ones and lack their negative lobes.

    Parameters
    ----------
    run : str
        The record, as for :func:`lerelva_strain`.
    flexural_rigidity : float
        EI of the stringer, N·m², in (0, 1e13]: assumed (sets only the dynamics).
    mass_per_length : float
        m of stringer and track, kg/m, in (0, 1e6]: assumed (sets only the dynamics).
    damping_ratio : float
        ζ of every mode, in [0, 1).

    Returns
    -------
    LerelvaCase

    Examples
    --------
    >>> case = lerelva_case()
    >>> round(case.fit.speed, 1)
    21.0
    """
    rec = lerelva_strain(run)
    ei = _checks.scalar("flexural_rigidity", flexural_rigidity, low=0.0, high=1.0e13, low_open=True)
    mass = _checks.scalar("mass_per_length", mass_per_length, low=0.0, high=1.0e6, low_open=True)
    beam = SimplySupportedBeam(LERELVA_PANEL, ei, mass, damping_ratio=damping_ratio, modes=20)
    unit = SimplySupportedBeam(LERELVA_PANEL, 1.0, 1.0)  # for weigh-in-motion: loads in units of EI/c
    eps = rec.zeroed(before=14.0)
    # the passage: 14.5-18.0 s of the source record (the strain is at its noise floor outside it)
    w = (rec.time > 14.5) & (rec.time < 18.0)
    t = rec.time[w]
    order = [1, 0, 2]  # in the direction of travel (towards Heimdal): Trondheim gauge, midspan, Heimdal
    spacings = np.array(NSB92_SPACINGS)
    fit = weigh_in_motion(unit, t, eps[order][:, w], rec.positions[order], spacings, fit_spacings=False)
    pattern = weigh_in_motion(
        unit, t, eps[order][:, w], rec.positions[order], spacings, fit_spacings=True, speed=fit.speed
    )
    peak = _peak_speed(t, eps[0, w], rec.rate_hz)
    lag = _lag_speed(t, eps[1, w], eps[2, w], 2.0)
    model_lag = _lag_speed(t, fit.fitted[0], fit.fitted[2], 2.0)
    # the chapter-10 prediction at each gauge, on the record's time base
    axles = AxleSequence(np.concatenate([[0.0], np.cumsum(spacings)]), np.array(NSB92_LOADS), "NSB 92")
    samples = int(np.ceil((2 * beam.span + axles.length) / fit.speed * rec.rate_hz * 4))
    arrival = fit.value("arrival")
    deflection = []
    for x in rec.positions:
        r = moving_force_response(beam, fit.speed, axles, position=float(x), samples=samples)
        deflection.append(np.interp(t - arrival, r.time[0], r.deflection[0], left=0.0, right=0.0))
    deflection = np.array(deflection)
    measured = eps[:, w]
    scale = float(np.sum(deflection * measured) / np.sum(deflection**2))
    predicted = scale * deflection
    agreement = tuple(compare(m, p, t) for m, p in zip(measured, predicted, strict=True))
    return LerelvaCase(rec, fit, pattern, peak, lag, model_lag, t, measured, predicted, scale, agreement)
