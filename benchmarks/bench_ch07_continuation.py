"""Chapter 7: the whole bifurcation diagram, the branch of limit cycles by continuation.

One case: the branch of the Manchester benchmark car (the default ``LateralCar``), from its
hunting cycle at 65 m/s down through the fold and up the unstable branch to the Hopf point, by
``stability.limit_cycle_branch`` on the compiled engine; against the same continuation on the
numpy right-hand side (``engine="scipy"``: DOP853, the path the engine replaces), whose fold must
agree before the timing counts. The goal is the issue's: the unstable branch of one car in ≤ 10 s.
The ramp-down diagram of the same car (11 speeds × 8 s and four bisections) is timed beside it, for
scale: what the unstable half of the picture costs against the stable half.
"""

from __future__ import annotations

import numpy as np

from benchmarks.common import Case, timed
from raildyn import stability
from raildyn.vehicles import LateralCar


def _branch_case(repeats: int) -> list[Case]:
    car = LateralCar().nonlinear()
    start = stability.limit_cycle_amplitude(car, 65.0)  # the ramp's kind of cycle, 8 s from 12 mm

    def branch(engine):
        return stability.limit_cycle_branch(car, start, engine=engine)

    results = {"compiled": branch("compiled")}  # compiles the stacked kernel: not timed
    # The numpy path takes about a minute and a half: one repeat.
    slow_times = timed(lambda i: results.setdefault("scipy", branch("scipy")), 1)
    fast_times = timed(lambda i: branch("compiled"), max(1, repeats // 5))
    fast, slow = results["compiled"], results["scipy"]
    # Both fold to Newton's tolerance (1e-5 of the scaled unknowns): the same fold to 0.01 m/s.
    assert abs(fast.fold_speed - slow.fold_speed) < 0.01, (fast.fold_speed, slow.fold_speed)
    unstable = int((~fast.stable).sum())
    speeds = np.linspace(50.0, 100.0, 11)
    ramp_times = timed(lambda i: stability.bifurcation_diagram(car, speeds, progress=False), repeats)
    name = (
        f"branch of the car, 65 m/s → fold {fast.fold_speed:.2f} m/s → Hopf end "
        f"{fast.speeds[-1]:.1f} m/s ({fast.speeds.size} cycles, {unstable} unstable)"
    )
    return [
        Case(
            name, fast_times, slow_times, "≤ 10 s and ≥ 5× faster", "the same continuation on numpy (DOP853)"
        ),
        Case(
            name, fast_times, ramp_times, "report", "the ramp-down diagram (11 speeds × 8 s + 4 bisections)"
        ),
    ]


def cases(repeats: int):
    return _branch_case(repeats)
