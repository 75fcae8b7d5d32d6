"""Fuzz registry: chapter 5's wheelset derivations (raildyn.derivations.wheelset)."""

from __future__ import annotations

from fuzzing import call, fuzz

ENTRIES = [
    fuzz("raildyn.derivations.wheelset.tangent_wheelset", lambda: call(), limit=30.0),
    fuzz("raildyn.derivations.wheelset.curved_wheelset", lambda: call(), limit=30.0),
]
ENTRIES.append(fuzz("raildyn.derivations.wheelset.critical_speed_limit", lambda: call(), limit=30.0))
