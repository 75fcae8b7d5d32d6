"""Fuzz registry: chapter 9's coupler chain derived (raildyn.derivations.train)."""

from __future__ import annotations

from functools import cache

from fuzzing import call, fuzz

from raildyn.train import TrainModel, make_consist


@cache
def _model():
    """The consist, made when its entry first asks (not when the registry is collected)."""
    return TrainModel(make_consist("1 SD40-2 + 2 loaded hopper"))


ENTRIES = [
    fuzz("raildyn.derivations.train.coupler_chain", lambda: call(3), limit=20.0),
    fuzz(
        "raildyn.derivations.train.loaded_train_matrices",
        lambda: call(_model(), 20.0, deflection=0.01, signs=1.0),
        limit=20.0,
        # two couplers: a list of two is one value each; −1 is buff
        accepts={"deflection": "list", "signs": "negative list"},
    ),
]
