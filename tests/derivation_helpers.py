"""What the derivation tests share: hold a derivation's matrices to a model's, and draw parameter sets.

The comparison is to round-off: the derived and the coded matrices are the same formulas evaluated in
a different order, so each entry agrees to a few ulps of the largest entry of its matrix (tolerance
1e-12 of that entry, about 5000 ulps: sums of a dozen terms of either sign lose a few digits, never
twelve).
"""

from __future__ import annotations

import numpy as np
from hypothesis import strategies as st

RELATIVE = 1e-12  # see the module docstring


def assert_derived(derivation, matrices, model, speed=None, scales=None) -> None:
    """Every derived matrix equals the model's to round-off (relative to the model's largest entry).

    ``matrices`` is the model's (M, C, K) or (M, C, K, GK, GC), e.g. ``model.matrices(V)`` unpacked.
    ``scales`` gives, by matrix name, the size of the terms that make it up where those terms can
    cancel to round-off (a mass at a node of a mode's slope): the tolerance is then relative to that.
    """
    derived = derivation.numeric(model, speed)
    for name, mine, theirs in zip(("M", "C", "K", "GK", "GC"), derived, matrices, strict=False):
        theirs = np.asarray(theirs, dtype=float)
        assert mine.shape == theirs.shape, f"{derivation.title}: {name} shape {mine.shape} != {theirs.shape}"
        scale = max(np.abs(theirs).max(initial=0.0), (scales or {}).get(name, 0.0), 1e-300)
        np.testing.assert_allclose(
            mine, theirs, rtol=0.0, atol=RELATIVE * scale, err_msg=f"{derivation.title}: {name} differs"
        )


def system_matrices(model, speed) -> tuple:
    """A linear model's (M, C, K, GK, GC) at ``speed`` from its ``matrices(speed)``."""
    m = model.matrices(speed)
    return m.M, m.C, m.K, m.GK, m.GC


# Factors narrower than [0.3, 3] where the default times 3 would leave the parameter's plausible range
# (raildyn.constants.PLAUSIBLE_RANGES): the half gauge, 0.75 m by default, stays within [0.15, 1.1] m.
FACTOR_RANGES = {"half_gauge": (0.3, 1.4)}


def factors(names) -> st.SearchStrategy:
    """A dict of a factor in [0.3, 3] for each name: a random parameter set around the defaults.

    Scaling by up to 3 either way moves every default well away from itself while keeping each
    parameter physical (positive where it was positive, inside any range the model allows; the
    half gauge's factor stops at 1.4, see ``FACTOR_RANGES``).
    """
    return st.fixed_dictionaries({n: st.floats(*FACTOR_RANGES.get(n, (0.3, 3.0))) for n in names})


def scaled(model, changes: dict):
    """The model with each named parameter multiplied by its factor (``model.replace``)."""
    return model.replace(**{n: getattr(model, n) * f for n, f in changes.items()})
