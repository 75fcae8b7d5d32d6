"""Chapter 1 widgets: one update against drawing the same frame on a new figure."""

from benchmarks.common import widget_case
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


def cases(repeats: int):
    return [widget_case(label, recipe, control, values, repeats) for label, recipe, control, values in MOVES]
