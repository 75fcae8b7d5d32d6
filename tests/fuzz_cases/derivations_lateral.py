"""Fuzz registry: chapter 7's bogie and lateral car derivations (raildyn.derivations.lateral)."""

from __future__ import annotations

from fuzzing import call, fuzz

ENTRIES = [
    fuzz("raildyn.derivations.lateral.bogie", lambda: call(), limit=30.0),
    fuzz("raildyn.derivations.lateral.lateral_car", lambda: call(), limit=30.0),
]
