"""Fuzz registry: chapter 9's coupler chain derived (raildyn.derivations.train)."""

from __future__ import annotations

from fuzzing import call, fuzz

ENTRIES = [
    fuzz("raildyn.derivations.train.coupler_chain", lambda: call(3), limit=20.0),
]
