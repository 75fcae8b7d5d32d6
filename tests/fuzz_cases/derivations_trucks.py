"""Fuzz registry: chapter 7's freight truck and locomotive derivations (raildyn.derivations.trucks)."""

from __future__ import annotations

from fuzzing import call, fuzz

# No arguments: only the unknown keyword applies, which Python refuses before the body runs.
ENTRIES = [
    fuzz("raildyn.derivations.trucks.three_piece_truck", lambda: call()),
    fuzz("raildyn.derivations.trucks.lateral_freight_car", lambda: call()),
    fuzz("raildyn.derivations.trucks.three_axle_truck", lambda: call()),
    fuzz("raildyn.derivations.trucks.lateral_locomotive", lambda: call()),
]
