"""Fuzz registry: chapter 3, track irregularities, and the ride measures of chapter 6 (raildyn.ride)."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn import track

X = np.linspace(0.0, 12.0, 7)  # m: a few points along one rail length
W = np.array([0.1, 1.0, 3.0])  # rad/m
BAND = (2.0, 50.0)  # m: wavelengths kept by the samples
AXLES = np.array([0.0, 2.5, 17.5, 20.0])  # m


def _psd(w):
    return track.fra_psd("vertical", 4, w)


def _sample():
    return track.synthesize_irregularity(_psd, 100.0, 1.0, BAND, rng=1, n_samples=2)


def _two_rail():
    return track.synthesize_track("fra", 4, 100.0, 1.0, BAND, rng=1)


def _jointed():
    return track.jointed_track(X, 0.01, 2.0)


_VARIANCES = {"vertical": 1e-4, "alignment": 2e-4, "cross_level": 3e-5, "gauge": 1e-5}
_T = np.arange(64) * 0.01
_ACC = np.sin(2 * np.pi * 2.0 * _T)
_OMEGA = np.linspace(1.0, 200.0, 50)


ENTRIES = [
    # ----------------------------------------------------------------- deterministic irregularities
    fuzz(
        "raildyn.track.dipped_joints",
        lambda: call(X, 0.01, 2.0, derivative=1, speed=10.0),
        # x: any distances, any shape (elementwise); depth >= 0; the offset is any position.
        accepts={
            "x": "zero negative shape",
            "depth": "zero",
            "offset": "zero negative big",
            "derivative": "zero",
            "speed": "none tiny",  # None: the derivative along x
        },
    ),
    fuzz(
        "raildyn.track.jointed_track",
        lambda: call(X, 0.01, 2.0, derivative=2, speed=10.0),
        accepts={"x": "zero negative shape", "depth": "zero", "derivative": "zero", "speed": "none tiny"},
    ),
    fuzz(
        "raildyn.track.JointedTrack",
        lambda: call(X, -0.01 * np.ones(7), 0.005 * np.ones(7), "staggered"),
        # a result: distances and profiles of any sign, of the shape of x
        accepts={"x": "zero negative", "left": "zero negative", "right": "zero negative"},
    ),
    fuzz("raildyn.track.JointedTrack.plot", lambda: on(_jointed())),
    fuzz(
        "raildyn.track.bump",
        lambda: call(X, 0.02, 1.0, position=0.5, derivative=2, speed=10.0),
        accepts={
            "length": "mm",
            "x": "zero negative shape",
            "height": "zero negative",
            "position": "zero negative big mm",
            "derivative": "zero",
            "speed": "none tiny",  # None: the derivative along x
        },
    ),
    fuzz(
        "raildyn.track.sinusoid",
        lambda: call(X, 0.005, 20.0, phase=0.3, derivative=2, speed=10.0),
        accepts={
            "x": "zero negative shape",
            "amplitude": "zero negative",
            "phase": "zero negative big mm",
            "derivative": "zero",
            "speed": "none tiny",  # None: the derivative along x
        },
    ),
    fuzz("raildyn.track.passing_frequency", lambda: call(30.0, 11.9), accepts={"speed": "tiny"}),
    fuzz("raildyn.track.passing_speed", lambda: call(0.9, 11.9, harmonic=3), accepts={"frequency": "tiny"}),
    fuzz(
        "raildyn.track.harmonic_amplitudes",
        lambda: call(np.cos(2 * np.pi * np.arange(16) / 16), 3),
        accepts={"one_period": "zero negative"},  # any profile, a flat one included
    ),
    # ----------------------------------------------------------------- spectra
    fuzz(
        "raildyn.track.fra_psd",
        lambda: call("vertical", 4, W, k=0.25),
        accepts={"k": "tiny", "wavenumber": "shape"},
    ),
    fuzz("raildyn.track.german_psd", lambda: call("cross_level", "low", W), accepts={"wavenumber": "shape"}),
    fuzz("raildyn.track.track_psd", lambda: call("fra", "vertical", 4)),
    fuzz("raildyn.track.TrackSpectrum", lambda: call("german", "alignment", "high")),
    fuzz("raildyn.track.fra_speed_limit", lambda: call(4, "freight")),
    fuzz("raildyn.track.wavelength_band", lambda: call((1.524, 304.8))),
    fuzz(
        "raildyn.track.band_variance",
        lambda: call("fra", "cross_level", 4, (0.02, 4.0), k=0.25),
        accepts={"k": "tiny"},
    ),
    # ----------------------------------------------------------------- samples and the view in time
    fuzz(
        "raildyn.track.synthesize_irregularity",
        lambda: call(_psd, 100.0, 1.0, BAND, rng=1, n_samples=2),
        # rng: a seed >= 0 (0 and 10**12 included) or None
        accepts={"length": "mm", "rng": "zero huge none"},
    ),
    fuzz(
        "raildyn.track.synthesize_track",
        lambda: call("german", "low", 100.0, 1.0, BAND, rng=1),
        accepts={"length": "mm", "rng": "zero huge none"},
    ),
    fuzz(
        "raildyn.track.IrregularitySample",
        lambda: call(np.arange(8.0), np.ones((2, 8)), (0.1, 1.0), 1e-4),
        # a result: the irregularity has any sign; a variance may be 0
        accepts={"z": "zero negative", "variance": "zero big mm"},
    ),
    fuzz("raildyn.track.IrregularitySample.plot", lambda: on(_sample())),
    fuzz(
        "raildyn.track.ComponentVariances",
        lambda: call(**_VARIANCES),
        accepts={
            "vertical": "big mm",
            "alignment": "big mm",
            "cross_level": "big mm",
            "gauge": "big mm",
            "*": "zero",
        },  # a result: variances >= 0
    ),
    fuzz(
        "raildyn.track.TwoRailIrregularity",
        lambda: call(
            np.arange(8.0),
            *(np.full(8, 1e-3 * (i + 1)) for i in range(4)),
            track.ComponentVariances(**_VARIANCES),
        ),
        # a result: every irregularity has any sign
        accepts={c: "zero negative" for c in ("vertical", "alignment", "cross_level", "gauge")},
    ),
    fuzz("raildyn.track.TwoRailIrregularity.rms", lambda: on(_two_rail(), "vertical")),
    fuzz("raildyn.track.TwoRailIrregularity.measured_rms", lambda: on(_two_rail(), "gauge")),
    fuzz("raildyn.track.TwoRailIrregularity.plot", lambda: on(_two_rail())),
    fuzz("raildyn.track.temporal_psd", lambda: call(_psd, 30.0), accepts={"speed": "tiny"}),
    fuzz(
        "raildyn.track.spatial_to_temporal",
        lambda: call([2.0, 1.0, 0.5], [0.0, 1.0, 2.0], 10.0),
        accepts={"speed": "tiny", "psd_values": "zero"},  # a spectrum >= 0
    ),
    fuzz(
        "raildyn.track.axle_delays",
        lambda: call(AXLES, 25.0),
        # the positions may coincide (the two rails under one axle) or lie ahead of the first
        accepts={"speed": "tiny", "axle_positions": "zero negative"},
    ),
    fuzz(
        "raildyn.track.excitation_csd",
        lambda: call(_psd, np.array([1.0, 5.0, 20.0]), AXLES, 25.0),
        accepts={"speed": "tiny", "axle_positions": "zero negative"},
    ),
    fuzz(
        "raildyn.track.axle_filter_wavelengths", lambda: call(2.5, 3), accepts={"axle_spacing": "big tiny mm"}
    ),
    # ----------------------------------------------------------------- ride measures
    fuzz(
        "raildyn.ride.sperling_correction",
        lambda: call([1.0, 10.0, 30.0], "vertical"),
        accepts={"frequency": "shape"},  # elementwise, any shape
    ),
    fuzz(
        "raildyn.ride.sperling_weighting",
        lambda: call([0.5, 5.0, 50.0], "lateral"),
        accepts={"frequency": "zero shape"},
    ),
    fuzz(
        "raildyn.ride.sperling_harmonic",
        lambda: call(0.3, 4.0, "vertical"),
        # array_like, broadcast together: a list of values is valid; a zero acceleration too
        accepts={"amplitude": "zero list big mm", "frequency": "list big mm"},
    ),
    fuzz("raildyn.ride.sperling_index", lambda: call(0.05), accepts={"weighted_rms": "zero big mm"}),
    fuzz(
        "raildyn.ride.iso2631_weighting",
        lambda: call([0.5, 6.3, 80.0], "Wk"),
        accepts={"frequency": "zero shape"},
    ),
    fuzz(
        "raildyn.ride.ride_quality",
        lambda: call(np.full(50, 1e-4), _OMEGA, "vertical"),
        accepts={"psd": "zero"},  # a spectrum >= 0
    ),
    fuzz(
        "raildyn.ride.ride_quality_history",
        lambda: call(_ACC, 0.01, "lateral"),
        accepts={"dt": "big tiny mm", "acceleration": "zero negative"},  # any acceleration history
    ),
    fuzz(
        "raildyn.ride.RideQuality",
        lambda: call(0.1, 0.05, 1.5, 0.08),
        accepts={
            "rms": "big mm",
            "sperling_rms": "big mm",
            "wz": "big mm",
            "iso_rms": "big mm",
            "*": "zero",
        },  # a result: RMS values and an index, all >= 0
    ),
]
