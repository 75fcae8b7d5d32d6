"""Chapter 4: FASTSIM on a batch of contact states, and the chapter's widgets.

FASTSIM case (issue 6): 10⁴ contact states, each on a 20 × 20 grid. raildyn
marches all strips of all states together (numpy over states and strips, a
Python loop over the 20 cells of a strip); the baseline is the same algorithm
written cell by cell in plain Python (``fastsim_reference``), timed on a
subset of the states and scaled to 10⁴ (the per-state cost of the loop does
not depend on the batch). Goal: ≥ 30× faster.
"""

import numpy as np

from benchmarks.common import Case, timed, widget_case
from raildyn.contact import fastsim, fastsim_reference, flexibilities
from raildyn.widgets import chapter04

STATES = 10_000
SUBSET = 200  # states timed with the per-cell loop, scaled by STATES / SUBSET

MOVES = [
    ("hertz load", chapter04.HERTZ, "load_kn", [40.0, 80.0, 120.0, 160.0, 200.0, 60.0]),
    ("creep_laws spin", chapter04.CREEP_LAWS, "spin", [0.0, 0.4, 0.8, 1.2, 1.6, 2.0]),
    ("creep_laws a/b", chapter04.CREEP_LAWS, "a_over_b", [0.3, 0.6, 1.0, 2.0, 3.0, 5.0]),
    ("fastsim_patch ξ", chapter04.FASTSIM_PATCH, "xi_permille", [-3.0, -1.0, 0.0, 1.0, 2.0, 4.0]),
    ("profiles gauge", chapter04.PROFILES, "gauge_mm", [1432.0, 1435.0, 1437.0, 1440.0]),
]


def _states(seed=0):
    rng = np.random.default_rng(seed)
    return {
        "xi": rng.uniform(-5e-3, 5e-3, STATES),
        "eta": rng.uniform(-5e-3, 5e-3, STATES),
        "phi": rng.uniform(-1.0, 1.0, STATES),
        "load": rng.uniform(50e3, 150e3, STATES),
        "mu": rng.uniform(0.2, 0.4, STATES),
        "a": rng.uniform(4e-3, 8e-3, STATES),
        "b": rng.uniform(3e-3, 6e-3, STATES),
    }


def fastsim_case(repeats: int) -> Case:
    s = _states()  # steel of raildyn.constants: the defaults of fastsim and flexibilities
    flex = flexibilities(s["a"], s["b"])
    l1, l2, l3 = flex.l1, flex.l2, flex.l3

    def vectorized(_i):
        return fastsim(s["xi"], s["eta"], s["phi"], s["load"], s["mu"], s["a"], s["b"], fields=False)

    def loop(_i):
        for j in range(SUBSET):
            fastsim_reference(
                s["xi"][j], s["eta"][j], s["phi"][j], s["load"][j], s["mu"][j], s["a"][j], s["b"][j],
                l1[j], l2[j], l3[j],
            )  # fmt: skip

    fast = timed(vectorized, repeats)
    slow = [t * STATES / SUBSET for t in timed(loop, repeats)]
    per_contact_us = 1e6 * float(np.median(fast)) / STATES
    return Case(
        f"FASTSIM 10⁴ states × 20×20 cells ({per_contact_us:.1f} µs per contact)",
        fast,
        slow,
        "≥ 30× faster",
        f"per-cell Python loop ({SUBSET} states, scaled ×{STATES // SUBSET})",
    )


def cases(repeats: int):
    return [fastsim_case(repeats)] + [
        widget_case(label, recipe, control, values, repeats) for label, recipe, control, values in MOVES
    ]
