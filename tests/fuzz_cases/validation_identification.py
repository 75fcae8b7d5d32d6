"""Fuzz registry: parameter identification and the measured Lerelva case (raildyn.validation.identification,
raildyn.validation.measured)."""

from __future__ import annotations

from functools import cache

import numpy as np
from fuzzing import call, fuzz, on

from raildyn.bridge import SimplySupportedBeam
from raildyn.validation.identification import coast_down, free_decay
from raildyn.validation.measured import LerelvaCase, lerelva_case, lerelva_strain

T = np.arange(0.0, 3.0, 0.01)
X = np.exp(-0.03 * 2 * np.pi * 2.0 * T) * np.cos(2 * np.pi * 2.0 * T) + 0.01 * np.sin(37.0 * T)
V = 30.0 - 0.02 * T - 0.001 * T**2
BEAM = SimplySupportedBeam(10.0, 1.0e9, 1.0e4)
TW = np.arange(0.0, 1.5, 1.0 / 128)
POS = np.array([4.0, 6.0])


def _strain():
    a = 20.0 * (TW - 0.2)
    out = np.zeros((2, TW.size))
    for d in (0.0, 3.0):
        b = a - d
        m = np.where(b <= POS[:, None], b * (10.0 - POS[:, None]), POS[:, None] * (10.0 - b)) / 10.0
        out += 1e-5 * np.where((b >= 0) & (b <= 10.0), m, 0.0)
    return out + 1e-8 * np.sin(50.0 * TW)


EPS = _strain()


# The fits are made when an entry first asks for them, not when the registry is collected.
@cache
def _fit():
    return free_decay(T, X)


@cache
def _coast():
    return coast_down(T, V, 1.0e5)


FIELDS = dict(
    names=("a", "b"),
    estimate=np.array([1.0, 2.0]),
    standard_error=np.array([0.1, 0.2]),
    interval=np.array([[0.8, 1.2], [1.6, 2.4]]),
    confidence=0.95,
    residual_rms=0.01,
    time=T[:4],
    measured=np.ones(4),
    fitted=np.ones(4),
)
# result fields hold what a fit computes: any finite number is valid, but not NaN/inf/empty/strings
RESULT = "zero negative huge list fraction mm big"

ENTRIES = [
    fuzz(
        "raildyn.validation.identification.free_decay",
        lambda: call(T, X, confidence=0.95),
        accepts={
            "confidence": "tiny",
            "response": "negative list",
        },  # a decay of either sign or any size is a decay
    ),
    fuzz(
        "raildyn.validation.identification.bridge_free_vibration",
        lambda: call(T, X, 0.5, confidence=0.9),
        accepts={
            "confidence": "tiny",
            "response": "negative list",
            "leaves": "zero",
        },  # leaves = 0: the whole record
    ),
    fuzz(
        "raildyn.validation.identification.weigh_in_motion",
        lambda: call(BEAM, TW, EPS, POS, [2.8], fibre_distance=0.1, speed=None, fit_spacings=True),
        # a scaled record gives scaled loads (negative: upward); lists are arrays
        accepts={
            "fibre_distance": "mm",
            "confidence": "tiny",
            "strain": "list",
            "positions": "list",
            "spacings": "list empty",
        },  # empty: one axle
        limit=10.0,
    ),
    fuzz(
        "raildyn.validation.identification.coast_down",
        lambda: call(T, V, 1.0e5, confidence=0.95),
        accepts={"mass": "big mm", "confidence": "tiny", "speed": "list"},
    ),
    fuzz(
        "raildyn.validation.identification.ParameterFit",
        lambda: call(**FIELDS),
        accepts={"residual_rms": "big mm", "*": RESULT},
    ),
    fuzz("raildyn.validation.identification.ParameterFit.value", lambda: on(_fit(), "damping_ratio")),
    fuzz("raildyn.validation.identification.ParameterFit.bounds", lambda: on(_fit(), "frequency_hz")),
    fuzz("raildyn.validation.identification.ParameterFit.plot", lambda: on(_fit(), None)),
    fuzz(
        "raildyn.validation.identification.FreeDecayFit",
        lambda: call(**FIELDS, log_decrement=0.2, decrement_damping_ratio=0.03),
        accepts={
            "residual_rms": "big mm",
            "*": RESULT,
            "log_decrement": RESULT + " none",
            "decrement_damping_ratio": RESULT + " none",
        },
    ),
    fuzz(
        "raildyn.validation.identification.WeighInMotionFit",
        lambda: call(**FIELDS, given_spacings=np.array([2.5])),
        accepts={"residual_rms": "big mm", "*": RESULT, "given_spacings": RESULT + " none"},
    ),
    fuzz(
        "raildyn.validation.identification.CoastDownFit",
        lambda: call(**FIELDS),
        accepts={"residual_rms": "big mm", "*": RESULT},
    ),
    fuzz(
        "raildyn.validation.identification.CoastDownFit.resistance",
        lambda: on(_coast(), [5.0, 20.0]),
        accepts={"speed": "zero negative list shape"},  # R(v) is a polynomial: any v, any shape, evaluates
    ),
]

# -- raildyn.validation.measured -----------------------------------------------------------------------------

RECORD = lerelva_strain()
_CASE = []


def case() -> LerelvaCase:
    if not _CASE:
        _CASE.append(lerelva_case())
    return _CASE[0]


ENTRIES += [
    fuzz("raildyn.validation.measured.lerelva_strain", lambda: call("1603161045")),
    fuzz(
        "raildyn.validation.measured.StrainRecord",
        lambda: call(
            T[:4], np.ones((3, 4)), ("a", "b", "c"), np.array([1.0, 2.0, 3.0]), ("strain",) * 3, 100.0, "x"
        ),
        accepts={"strain": RESULT, "positions": RESULT, "time": "zero", "provenance": "unknown"},
    ),
    fuzz(
        "raildyn.validation.measured.StrainRecord.zeroed",
        lambda: on(RECORD, 14.0),
        accepts={"before": "huge none big mm"},  # None: the first quarter; beyond the end: the whole record
    ),
    fuzz("raildyn.validation.measured.StrainRecord.plot", lambda: on(RECORD, None)),
    fuzz(
        "raildyn.validation.measured.lerelva_case",
        lambda: call("1603161045", flexural_rigidity=1.0e8, mass_per_length=1.0e3, damping_ratio=0.02),
        accepts={"flexural_rigidity": "big mm", "mass_per_length": "mm", "damping_ratio": "zero"},
        limit=20.0,
    ),
    fuzz(
        "raildyn.validation.measured.LerelvaCase",
        lambda: call(
            RECORD,
            case().fit,
            case().pattern,
            20.0,
            30.0,
            30.0,
            T[:4],
            np.ones((3, 4)),
            np.ones((3, 4)),
            0.05,
            case().agreement,
        ),  # fmt: skip
        accepts={
            "peak_speed": "tiny",
            "lag_speed": "tiny",
            "model_lag_speed": "tiny",
            "time": RESULT,
            "measured": RESULT,
            "predicted": RESULT,
            "scale": RESULT,
        },
        limit=20.0,
    ),
    fuzz("raildyn.validation.measured.LerelvaCase.plot", lambda: on(case(), None), limit=20.0),
]
