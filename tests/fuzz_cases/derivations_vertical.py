"""Fuzz registry: chapter 6's vertical models derived (raildyn.derivations.vertical)."""

from __future__ import annotations

from fuzzing import call, fuzz

ENTRIES = [
    fuzz("raildyn.derivations.vertical.vertical_car", lambda: call(), limit=20.0),
    fuzz("raildyn.derivations.vertical.vertical_locomotive", lambda: call(), limit=20.0),
    fuzz("raildyn.derivations.vertical.freight_rock_and_roll", lambda: call(), limit=20.0),
]
