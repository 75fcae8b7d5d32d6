"""Chapter 4: FASTSIM on a batch of contact states, and the chapter's widgets.

FASTSIM cases (issues 6 and 22): 10⁴ contact states, each on a 20 × 20 grid.
raildyn marches the cells in a numba-compiled loop (``raildyn/contact/_fastsim_kernel.py``),
in parallel over states on all of numba's threads and again on one thread. Baselines:

* today's numpy march before the kernel (``_fastsim_numpy``: numpy over states and
  strips, a Python loop over the 20 cells of a strip), on all 10⁴ states. Goal
  (issue 22): ≥ 4× faster and ≤ 3 µs per contact, on one thread too.
* the same algorithm written cell by cell in plain Python (``fastsim_reference``),
  timed on a subset of the states and scaled to 10⁴ (the per-state cost of the loop
  does not depend on the batch). Goal (issue 6): ≥ 30× faster.

The kernel is compiled (or loaded from numba's cache) before any timing.
"""

import importlib

import numba
import numpy as np

from benchmarks.common import Case, timed, widget_case
from raildyn.contact import fastsim, fastsim_reference, flexibilities
from raildyn.widgets import chapter04

_fastsim_numpy = importlib.import_module("raildyn.contact.fastsim_python")._fastsim_numpy

STATES = 10_000
SUBSET = 200  # states timed with the per-cell loop, scaled by STATES / SUBSET

MOVES = [
    ("hertz load", chapter04.HERTZ, "load_kn", [40.0, 80.0, 120.0, 160.0, 200.0, 60.0]),
    ("creep_laws spin", chapter04.CREEP_LAWS, "spin", [0.0, 0.4, 0.8, 1.2, 1.6, 2.0]),
    ("creep_laws a/b", chapter04.CREEP_LAWS, "a_over_b", [0.3, 0.6, 1.0, 2.0, 3.0, 5.0]),
    ("fastsim_patch ξ", chapter04.FASTSIM_PATCH, "xi_permille", [-3.0, -1.0, 0.0, 1.0, 2.0, 4.0]),
    ("profiles gauge", chapter04.PROFILES, "gauge_mm", [1432.0, 1435.0, 1437.0, 1440.0]),
    ("wheel_on_rail y", chapter04.WHEEL_ON_RAIL, "shift_mm", [-7.5, -3.0, 0.5, 4.0, 6.25, 7.0]),
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


def fastsim_cases(repeats: int) -> list[Case]:
    s = _states()  # steel of raildyn.constants: the defaults of fastsim and flexibilities
    flex = flexibilities(s["a"], s["b"])
    l1, l2, l3 = flex.l1, flex.l2, flex.l3
    args = (s["xi"], s["eta"], s["phi"], s["load"], s["mu"], s["a"], s["b"])

    def compiled(_i):
        return fastsim(*args, fields=False)

    def numpy_march(_i):
        return _fastsim_numpy(*args, fields=False)

    def loop(_i):
        for j in range(SUBSET):
            fastsim_reference(
                s["xi"][j], s["eta"][j], s["phi"][j], s["load"][j], s["mu"][j], s["a"][j], s["b"][j],
                l1[j], l2[j], l3[j],
            )  # fmt: skip

    threads = numba.get_num_threads()
    compiled(0)  # compile, or load numba's cache, outside the timings: the parallel march...
    try:
        numba.set_num_threads(1)
        compiled(0)  # ... and the one on the calling thread
        one = timed(compiled, repeats)
    finally:
        numba.set_num_threads(threads)
    fast = timed(compiled, repeats)
    reference = timed(numpy_march, repeats)
    slow = [t * STATES / SUBSET for t in timed(loop, repeats)]

    def per_contact(times):
        return 1e6 * float(np.median(times)) / STATES

    goal = "≥ 4× and ≤ 3 µs per contact"
    grid = "FASTSIM 10⁴ states × 20×20 cells"
    numpy_name = f"numpy march ({per_contact(reference):.1f} µs per contact)"
    loop_name = f"per-cell Python loop ({SUBSET} states, scaled ×{STATES // SUBSET})"
    return [
        Case(
            f"{grid} ({per_contact(fast):.2f} µs per contact, {threads} threads)",
            fast,
            reference,
            goal,
            numpy_name,
        ),
        Case(f"{grid}, one thread ({per_contact(one):.2f} µs per contact)", one, reference, goal, numpy_name),
        Case(f"{grid} against the per-cell loop ({threads} threads)", fast, slow, "≥ 30× faster", loop_name),
    ]


def _contact_table_case(repeats: int) -> Case:
    # The contact tables of one profile pair (S1002 on UIC 60 at 1:40, 81 shifts each way to 20 mm, with the
    # wheelset's roll), as the nonlinear models take them: profile_contact's two vectorised searches against
    # one contact_geometry call per shift. Both give the same tables before the timing counts.
    from raildyn.contact.geometry import contact_geometry
    from raildyn.contact.profiles import s1002_wheel, uic60_rail
    from raildyn.wheelset import profile_contact

    wheel, rail = s1002_wheel(), uic60_rail(1 / 40)
    shifts = np.arange(0.0, 0.02 + 1.25e-4, 2.5e-4)

    def one_by_one(i):
        return [contact_geometry(wheel, rail, [sign * y]) for sign in (1.0, -1.0) for y in shifts]

    table = profile_contact(wheel, rail).rolling_radius_difference
    inside = table.x[(table.x >= 0) & (table.x <= 0.0065 + 1e-9)]
    single = [float(contact_geometry(wheel, rail, [y]).rolling_radius_difference[0]) for y in inside]
    np.testing.assert_allclose(table(inside), single, rtol=0, atol=1e-12)
    # profile_contact keeps the tables of the pairs it has made: each repeat asks for a gauge a micrometre
    # wider, a pair it has not seen, so that every timing tabulates afresh.
    return Case(
        "contact tables of one profile pair (S1002 / UIC 60 1:40, 162 shifts with roll)",
        timed(lambda i: profile_contact(wheel, rail, gauge=1.435 + 1e-6 * (i + 1)), repeats),
        timed(one_by_one, repeats),
        "≤ 0.5 s",
        "contact_geometry one shift at a time",
    )


def cases(repeats: int):
    return (
        fastsim_cases(repeats)
        + [_contact_table_case(repeats)]
        + [widget_case(label, recipe, control, values, repeats) for label, recipe, control, values in MOVES]
    )
