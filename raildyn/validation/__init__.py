"""Validating models (book chapter 11): comparing predictions with measurements, identifying
parameters from records, and spreading uncertain parameters into the answer.

* :mod:`raildyn.validation.metrics` — a prediction against a measurement: in time (NRMSE, correlation,
  Theil's U, Sprague–Geers), in frequency (one-third-octave RMS, H1 and coherence), and the statistics of
  acceptance tests (percentiles, sliding RMS, maxima per section).
"""

from raildyn.validation.metrics import (
    NORMALISATIONS,
    Agreement,
    BandRMS,
    FrequencyResponseEstimate,
    SectionMaxima,
    SlidingRMS,
    SpragueGeers,
    compare,
    correlation,
    frequency_response_h1,
    nrmse,
    percentiles,
    section_maxima,
    sliding_rms,
    sprague_geers,
    theil_u,
    third_octave_rms,
)

__all__ = [
    "NORMALISATIONS",
    "Agreement",
    "BandRMS",
    "FrequencyResponseEstimate",
    "SectionMaxima",
    "SlidingRMS",
    "SpragueGeers",
    "compare",
    "correlation",
    "frequency_response_h1",
    "nrmse",
    "percentiles",
    "section_maxima",
    "sliding_rms",
    "sprague_geers",
    "theil_u",
    "third_octave_rms",
]
