"""Fuzz registry: raildyn.validation.metrics (chapter 11, comparing a prediction with a measurement).

A record is any finite array: a zero, negated or spiked (1e300) record is a valid record, so
those changes are accepted wherever the metric stays defined (every metric is scaled before it
squares); a zero record is refused where the definition divides by it.
"""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn.validation import (
    BandRMS,
    compare,
    frequency_response_h1,
    section_maxima,
    sliding_rms,
)

T = np.arange(200) * 0.01
MEASURED = np.sin(2 * np.pi * T) + 0.1 * np.cos(7 * T)
PREDICTED = 1.1 * np.sin(2 * np.pi * (T - 0.02))
NOISE = np.random.default_rng(19).standard_normal(2048)
RECORD = np.sin(2 * np.pi * 12.0 * np.arange(4000) * 1e-3) + 0.3 * NOISE[:2000].repeat(2)

VALID_RECORD = "zero negative huge"  # a zero, negated or spiked record is still a record

ENTRIES = [
    fuzz(
        "raildyn.validation.metrics.nrmse",
        lambda: call(MEASURED, PREDICTED, normalisation="rms"),
        accepts={"measured": "negative huge", "predicted": VALID_RECORD},
    ),
    fuzz(
        "raildyn.validation.metrics.correlation",
        lambda: call(MEASURED, PREDICTED),
        accepts={"measured": "negative huge", "predicted": "negative huge"},
    ),
    fuzz(
        "raildyn.validation.metrics.theil_u",
        lambda: call(MEASURED, PREDICTED),
        accepts={"measured": VALID_RECORD, "predicted": VALID_RECORD},
    ),
    fuzz(
        "raildyn.validation.metrics.sprague_geers",
        lambda: call(MEASURED, PREDICTED, 0.01),
        accepts={"measured": "negative huge", "predicted": "negative huge", "time": "huge none big tiny mm"},
    ),
    fuzz(
        "raildyn.validation.metrics.SpragueGeers",
        lambda: call(0.1, 0.2, 0.22),
        accepts={"magnitude": "zero negative huge big mm", "phase": "zero", "combined": "zero huge big mm"},
    ),
    fuzz(
        "raildyn.validation.metrics.compare",
        lambda: call(MEASURED, PREDICTED, T, normalisation="std"),
        accepts={"measured": "negative huge", "predicted": "negative huge", "time": "none"},
    ),
    fuzz(
        "raildyn.validation.metrics.Agreement",
        lambda: call(T, MEASURED, PREDICTED, "range", 0.2, 0.9, 0.1, 0.1, 0.05, 0.11),
        accepts={
            "time": "none",  # records without a time base
            "measured": VALID_RECORD,
            "predicted": VALID_RECORD,
            "nrmse": "zero huge big mm",
            "correlation": "zero negative",
            "theil_u": "zero",
            "magnitude": "zero negative huge big mm",
            "phase": "zero",
            "combined": "zero huge big mm",
        },
    ),
    fuzz("raildyn.validation.metrics.Agreement.plot", lambda: on(compare(MEASURED, PREDICTED, 0.01))),
    fuzz(
        "raildyn.validation.spectra.third_octave_rms",
        lambda: call(RECORD, 1e-3, nperseg=2000, f_min=5.0, f_max=100.0),
        accepts={
            "record": VALID_RECORD,
            "dt": "huge",  # a slow sampling only moves the bands down
            "nperseg": "none",
            "f_min": "none tiny",
            "f_max": "huge none big mm",  # no upper limit: every band below the Nyquist frequency
        },
    ),
    fuzz(
        "raildyn.validation.spectra.BandRMS",
        lambda: call([10.0, 12.5], [8.9, 11.2], [11.2, 14.1], [0.5, 0.2]),
        accepts={"rms": "zero huge", "upper_hz": "huge"},
    ),
    fuzz(
        "raildyn.validation.spectra.BandRMS.plot",
        lambda: on(BandRMS(np.array([10.0, 12.5]), [8.9, 11.2], [11.2, 14.1], [0.5, 0.2])),
    ),
    fuzz(
        "raildyn.validation.spectra.frequency_response_h1",
        lambda: call(NOISE, np.convolve(NOISE, [0.5, 0.3, 0.2])[:2048], 1e-3, nperseg=256),
        accepts={
            "excitation": "negative huge",
            "response": VALID_RECORD,
            "dt": "huge big tiny mm",
            "nperseg": "none",
        },
    ),
    fuzz(
        "raildyn.validation.spectra.FrequencyResponseEstimate",
        lambda: call([0.0, 1.0, 2.0], np.array([1.0, 0.5 - 0.5j, 0.1j]), [0.9, 0.8, 0.2]),
        accepts={"h1": "zero negative huge", "coherence": "zero", "omega": "huge"},
    ),
    fuzz(
        "raildyn.validation.spectra.FrequencyResponseEstimate.plot",
        lambda: on(frequency_response_h1(NOISE, 2.0 * NOISE, 1e-3)),
    ),
    fuzz(
        "raildyn.validation.acceptance.percentiles",
        lambda: call(RECORD, (0.15, 50.0, 99.85)),
        accepts={"record": VALID_RECORD, "percent": "zero"},
    ),
    fuzz(
        "raildyn.validation.acceptance.sliding_rms",
        lambda: call(RECORD, 0.5, 100.0, step=10.0),
        accepts={"record": VALID_RECORD, "step": "none"},
    ),
    fuzz(
        "raildyn.validation.acceptance.SlidingRMS",
        lambda: call([0.5, 1.5, 2.5], [0.1, 0.2, 0.0], 1.0),
        accepts={"rms": "zero huge", "window": "huge big tiny mm", "position": "zero"},
    ),
    fuzz("raildyn.validation.acceptance.SlidingRMS.plot", lambda: on(sliding_rms(RECORD, 0.5, 100.0))),
    fuzz(
        "raildyn.validation.acceptance.section_maxima",
        lambda: call(RECORD, 0.5, 250.0, percent=(0.15, 99.85)),
        accepts={"record": VALID_RECORD, "percent": "zero"},
    ),
    fuzz(
        "raildyn.validation.acceptance.SectionMaxima",
        lambda: call([0.0, 10.0], [-1.0, -2.0], [1.0, 3.0], 10.0, (0.15, 99.85)),
        accepts={
            "start": "zero",
            "lower": "zero negative",
            "upper": "zero",
            "length": "huge big tiny mm",
            "percent": "zero",
        },
    ),
    fuzz("raildyn.validation.acceptance.SectionMaxima.plot", lambda: on(section_maxima(RECORD, 0.5, 250.0))),
]
