"""Chapter 7: the Manchester car on real profiles (S1002 wheels on UIC 60 rails at 1:40, the flange a
second contact), its limit cycles through the compiled engine against scipy's RK45 on the numpy
right-hand side (engine="scipy"). Both runs take the same steps until a rounding difference tips one step
choice at a kink of the flange; from there they differ by the integration error of rtol 1e-6 (measured
1e-4 of the amplitude), so the cycles must agree to 1e-3 of their amplitude before the timing counts.
"""

from __future__ import annotations

import numpy as np

from benchmarks.common import Case, timed
from raildyn import stability
from raildyn.contact.profiles import s1002_wheel, uic60_rail
from raildyn.vehicles import LateralCar
from raildyn.wheelset import NonlinearLateral, profile_contact

SPEEDS = (70.0, 80.0, 90.0, 100.0)  # m/s: below and beyond the car's flange contact


def _real_profiles_case(repeats: int) -> Case:
    pair = profile_contact(s1002_wheel(), uic60_rail(1 / 40))
    model = NonlinearLateral(LateralCar().nonlinear().system, pair)

    def cycles(engine):
        return [stability.limit_cycle_amplitude(model, V, duration=8.0, engine=engine) for V in SPEEDS]

    stability.limit_cycle_amplitude(model, 80.0, duration=0.1)  # loads the compiled engine: not timed
    results = {}
    slow = timed(lambda i: results.setdefault("scipy", cycles("scipy")), 1)
    fast = timed(lambda i: results.setdefault("compiled", cycles("compiled")), repeats)
    a = np.array([c.amplitude for c in results["compiled"]])
    b = np.array([c.amplitude for c in results["scipy"]])
    assert np.abs(a - b).max() < 1e-3 * b.max()
    assert a.max() > model.contact.flange_clearance  # the fastest runs are on their flanges
    return Case(
        f"car on S1002 / UIC 60 with two-point contact, {len(SPEEDS)} limit cycles × 8 s",
        fast,
        slow,
        "≥ 50× faster, same cycles",
        "scipy RK45 on the numpy right-hand side",
    )


def cases(repeats: int):
    return [_real_profiles_case(repeats)]
