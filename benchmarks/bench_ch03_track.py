"""Chapter 3: synthesizing a two-rail track sample, and the chapter's widget updates.

The track case synthesizes 10 km of two-rail track (vertical, alignment,
cross-level and gauge of FRA class 4, wavelengths 1–300 m) at 0.25 m spacing:
raildyn (one inverse FFT per component) against the straightforward sum of
cosines, one Python loop iteration per spectral line, each adding A_k cos(Ω_k x + φ_k)
over the 40 000 points. The loop would take tens of seconds per repeat, so it
is timed on every ``FRACTION``-th line and its time scaled by the number of
lines (the cost per line is constant: one cosine over the same points).
"""

from __future__ import annotations

import numpy as np

from benchmarks.common import Case, timed, widget_case
from raildyn import track
from raildyn.widgets import chapter03

LENGTH, DX, BAND = 10_000.0, 0.25, (1.0, 300.0)  # m
FRACTION = 20  # the loop runs over one line in FRACTION and is scaled up


def _raildyn(seed: int):
    return track.synthesize_track("fra", 4, LENGTH, DX, BAND, seed)


def _lines(component: str):
    n = int(round(LENGTH / DX))
    d_omega = 2 * np.pi / LENGTH
    omega = np.arange(1, (n - 1) // 2 + 1) * d_omega
    lo, hi = track.wavelength_band(BAND)
    omega = omega[(omega >= lo) & (omega <= hi)]
    amplitude = np.sqrt(2 * track.track_psd("fra", component, 4)(omega) * d_omega)
    return omega, amplitude


def _loop(seed: int, lines, x) -> float:
    """The cosine sum for every FRACTION-th line of each component; returns the scale to the full count."""
    rng = np.random.default_rng(seed)
    done = total = 0
    for omega, amplitude in lines:
        z = np.zeros_like(x)
        phases = rng.uniform(0, 2 * np.pi, omega.size)
        for k in range(0, omega.size, FRACTION):
            z += amplitude[k] * np.cos(omega[k] * x + phases[k])
            done += 1
        total += omega.size
    return total / done


def cases(repeats: int):
    x = np.arange(int(round(LENGTH / DX))) * DX
    lines = [_lines(c) for c in track.COMPONENTS]
    scale = _loop(0, lines, x)  # warm-up, and the factor from the timed lines to all of them
    fast = timed(_raildyn, repeats)
    slow = [scale * t for t in timed(lambda i: _loop(i, lines, x), repeats)]
    n_lines = sum(o.size for o, _ in lines)
    synth = Case(
        f"two-rail FRA track, 10 km at 0.25 m ({n_lines} lines)",
        fast,
        slow,
        "≥ 50× faster",
        f"Python loop of cosines (1 line in {FRACTION} timed, scaled)",
    )
    moves = [
        ("random_track seed", chapter03.RANDOM_TRACK, "seed", [2, 3, 4, 5, 6, 7]),
        ("random_track speed", chapter03.RANDOM_TRACK, "speed_kmh", [40.0, 80.0, 120.0, 160.0, 200.0, 250.0]),
        ("random_track track", chapter03.RANDOM_TRACK, "track", list(chapter03.TRACKS)[:6]),
        ("jointed_rail a", chapter03.JOINTED_RAIL, "half_width", [0.5, 1.0, 2.0, 3.0, 4.0, 5.0]),
        ("dipped_joint V", chapter03.DIPPED_JOINT, "speed_kmh", [60.0, 80.0, 120.0, 160.0, 200.0, 100.0]),
        ("dipped_joint 2α", chapter03.DIPPED_JOINT, "dip_mrad", [4.0, 6.0, 10.0, 14.0, 20.0, 8.0]),
    ]
    return [synth] + [widget_case(label, recipe, c, v, repeats) for label, recipe, c, v in moves]
