"""Fuzz registry: the ride of a vehicle two ways (:func:`raildyn.vehicles.ride_run`, chapter 6)."""

from __future__ import annotations

import functools

import numpy as np
from fuzzing import call, fuzz

from raildyn import track
from raildyn.vehicles import MANCHESTER_VERTICAL, periodic_profile


@functools.lru_cache(maxsize=1)
def _profile():
    psd = track.track_psd("fra", "vertical", 4)
    return periodic_profile(
        track.synthesize_irregularity(psd, 300.0, 0.25, (1.0, 100.0), 1).z.reshape(-1), 0.25
    )


ENTRIES = [
    fuzz(
        "raildyn.vehicles.ride_run",
        lambda: call(
            MANCHESTER_VERTICAL,
            track.track_psd("fra", "vertical", 4),
            120.0 / 3.6,  # at 30 m/s response_spectrum refuses its own round-off (a PSD of -2e-22)
            _profile(),
            np.linspace(0.05, 30.0, 600),
            dt=0.02,
            settle=2.0,
        ),
        # no settling is a run from rest, measured whole
        accepts={"settle": "zero tiny mm"},  # 2000 s of settling is a long run, no error
        limit=10.0,
    ),
]
