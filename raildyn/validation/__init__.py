"""Validating models (book chapter 11): comparing predictions with measurements, identifying
parameters from records, and spreading uncertain parameters into the answer.

* :mod:`raildyn.validation.metrics` — a prediction against a measurement in time: NRMSE, correlation,
  Theil's U, Sprague–Geers.
* :mod:`raildyn.validation.spectra` — in frequency: one-third-octave RMS, H1 and the coherence.
* :mod:`raildyn.validation.acceptance` — the statistics of acceptance tests: percentiles, sliding RMS,
  maxima per section.
* :mod:`raildyn.validation.identification` — parameters from records by least squares, with confidence
  intervals: a free decay, a bridge's free vibration, a coast-down; :mod:`raildyn.validation.bridge_wim`
  — bridge weigh-in-motion; :mod:`raildyn.validation.fits` — the fit result they all return.
* :mod:`raildyn.validation.measured` — a measured case: strain at midspan of a railway bridge near
  Trondheim under an NSB class 92 train, and the chapter-10 prediction beside it.
* :mod:`raildyn.validation.uncertainty` — Monte Carlo prediction bands and Sobol' indices from
  pseudo-random or quasi-random (scrambled Sobol', Halton) samples, run on dask.distributed (a local
  cluster of one process per core by default, any scheduler on request) or any ``concurrent.futures``
  executor, reproducible from a seed.
"""

from raildyn.validation.acceptance import SectionMaxima, SlidingRMS, percentiles, section_maxima, sliding_rms
from raildyn.validation.bridge_wim import WeighInMotionFit, weigh_in_motion
from raildyn.validation.fits import ParameterFit
from raildyn.validation.identification import (
    CoastDownFit,
    FreeDecayFit,
    bridge_free_vibration,
    coast_down,
    free_decay,
)
from raildyn.validation.measured import (
    LERELVA_PANEL,
    NSB92_LOADS,
    NSB92_SPACINGS,
    LerelvaCase,
    StrainRecord,
    lerelva_case,
    lerelva_strain,
)
from raildyn.validation.metrics import (
    NORMALISATIONS,
    Agreement,
    SpragueGeers,
    compare,
    correlation,
    nrmse,
    sprague_geers,
    theil_u,
)
from raildyn.validation.spectra import (
    BandRMS,
    FrequencyResponseEstimate,
    frequency_response_h1,
    third_octave_rms,
)
from raildyn.validation.uncertainty import MonteCarloResult, SobolResult, monte_carlo, sobol_indices

__all__ = [
    "MonteCarloResult",
    "SobolResult",
    "monte_carlo",
    "sobol_indices",
    "LERELVA_PANEL",
    "NSB92_LOADS",
    "NSB92_SPACINGS",
    "CoastDownFit",
    "FreeDecayFit",
    "LerelvaCase",
    "ParameterFit",
    "StrainRecord",
    "WeighInMotionFit",
    "bridge_free_vibration",
    "coast_down",
    "free_decay",
    "lerelva_case",
    "lerelva_strain",
    "weigh_in_motion",
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
