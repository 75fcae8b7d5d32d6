"""Chapter 1: the widgets (one update against drawing the same frame on a new figure) and a long forced
response."""

import numpy as np

from benchmarks.common import Case, timed, widget_case
from raildyn.vibration import SDOF
from raildyn.widgets import chapter01

# A cycle of control values that a student might drag through.
MOVES = [
    ("free_vibration ξ", chapter01.FREE_VIBRATION, "damping_ratio", [0.05, 0.1, 0.3, 0.7, 1.0, 1.5]),
    ("free_vibration ω_n", chapter01.FREE_VIBRATION, "natural_frequency", [3.0, 5.0, 8.0, 12.0, 16.0, 19.0]),
    ("forced_response ξ", chapter01.FORCED_RESPONSE, "damping_ratio", [0.05, 0.1, 0.2, 0.4, 0.7, 1.0]),
    ("chain_modes k_i/k₁", chapter01.CHAIN_MODES, "stiffness_ratio", [0.5, 0.8, 1.0, 1.5, 2.0, 2.5]),
    ("chain_modes number of masses", chapter01.CHAIN_MODES, "dof", [2, 3]),
    ("random_response f_n", chapter01.RANDOM_RESPONSE, "frequency_hz", [0.8, 1.2, 1.6, 2.0, 2.6, 3.2]),
    ("random_response seed", chapter01.RANDOM_RESPONSE, "seed", [2, 3, 4, 5, 6, 7]),
]


def _forced_response_case(repeats: int) -> Case:
    """An SDOF's response to 10⁵ force samples: the FFT convolution against scipy's ``lsim``.

    Both hold the force linear between samples (a first-order hold), so they give the same answer,
    which is checked before the timing counts.
    """
    import scipy.signal

    s = SDOF.from_modal(2 * np.pi, 0.02, mass=3.0)
    t = np.arange(100_000) * 1e-3
    force = np.sin(3.0 * t)
    system = scipy.signal.lti([1.0 / s.mass], [1.0, s.damping / s.mass, s.stiffness / s.mass])
    ours = s.forced_response(t, force)
    theirs = scipy.signal.lsim(system, force, t)[1]
    gap = np.abs(ours - theirs).max() / np.abs(theirs).max()
    if gap > 1e-9:
        raise AssertionError(f"forced_response and lsim disagree by {gap:.3g} of the peak")
    fast = timed(lambda i: s.forced_response(t, force), repeats)
    slow = timed(lambda i: scipy.signal.lsim(system, force, t), max(1, repeats // 5))
    return Case(
        f"SDOF forced response, 10⁵ samples (agree to {gap:.0e} of the peak)",
        fast,
        slow,
        "≤ 1 s (milliseconds), ≥ 10× faster",
        "scipy.signal.lsim, first-order hold",
    )


def cases(repeats: int):
    widgets = [widget_case(name, recipe, control, values, repeats) for name, recipe, control, values in MOVES]
    return [*widgets, _forced_response_case(repeats)]
