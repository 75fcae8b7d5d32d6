"""The first call of each compiled path the notebooks meet, then the whole warm-up, in a fresh process;
prints numba's counts as one line ``first calls: {json}`` (run by tests/binder_env.py in the Binder
environment, read by tests/test_warm.py)."""

import json

import numpy as np

from raildyn import bridge, stability, train
from raildyn.__main__ import cache_counts, kernels, warm
from raildyn.contact import fastsim
from raildyn.vehicles import LateralCar


def main() -> None:
    stability.bifurcation_diagram(
        LateralCar().nonlinear(), np.linspace(50.0, 100.0, 3), duration=0.5, refine=1, progress=False
    )
    fastsim(np.linspace(-2e-3, 2e-3, 1000), 0.0, 0.0, 100e3, 0.3, 6e-3, 4e-3, fields=False)
    train.simulate(train.braking_model(10, 1), 5.0, 20.0)
    beam = bridge.SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=5)
    bridge.crossing(beam, bridge.AxleSequence([0.0], [1.0e5]), 40.0)
    first = {
        name: [sum(k.stats.cache_hits.values()), sum(k.stats.cache_misses.values())]
        for name, k in kernels().items()
    }
    warm(progress=False)
    print("first calls:", json.dumps({"first": first, "all": cache_counts()}))


if __name__ == "__main__":
    main()
