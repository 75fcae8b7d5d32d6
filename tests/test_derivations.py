"""The symbolic derivations' shape (raildyn.derivations._core) and chapter 1's derivations.

Each derived model is held to the numeric model over random parameter sets (hypothesis), to
round-off (tests/derivation_helpers.py says why 1e-12 of each matrix's largest entry).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy
from derivation_helpers import assert_derived
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn import derivations
from raildyn.vibration import SDOF, chain_matrices


@settings(max_examples=30, deadline=None)
@given(m=st.floats(1.0, 1e5), c=st.floats(0.0, 1e5), k=st.floats(1.0, 1e8))
def test_sdof_matches_the_oscillator(m, c, k):
    s = SDOF(m, c, k)
    # On a moving base y: the spring and damper act on x − y, so G_K = k and G_C = c.
    assert_derived(derivations.sdof(), ([[m]], [[c]], [[k]], [[k]], [[c]]), s)


@pytest.mark.parametrize("grounded", [True, False])
@settings(max_examples=20, deadline=None)
@given(data=st.data())
def test_chain_matches_chain_matrices(grounded, data):
    n = data.draw(st.integers(2, 6))
    springs = n if grounded else n - 1
    positive = st.floats(0.1, 1e6)
    p = {
        "masses": np.array(data.draw(st.lists(positive, min_size=n, max_size=n))),
        "stiffnesses": np.array(data.draw(st.lists(positive, min_size=springs, max_size=springs))),
        "dampings": np.array(data.draw(st.lists(st.floats(0.0, 1e4), min_size=springs, max_size=springs))),
    }
    cm = chain_matrices(p["masses"], p["stiffnesses"], dampings=p["dampings"], grounded=grounded)
    assert_derived(derivations.chain(n, grounded), (cm.M, cm.C, cm.K), p)


def test_lagrange_gives_a_pendulum_its_linear_equation():
    # Independent of the models: a pendulum, T = ½ m l² θ̇², V = m g l (1 − cos θ), gives
    # m l² θ̈ + m g l θ = 0 once linearised.
    m, g, l = sympy.symbols("m g l", positive=True)
    (theta,) = derivations.coordinates("theta")
    T = m * l**2 * theta.diff(derivations.time) ** 2 / 2
    V = m * g * l * (1 - sympy.cos(theta))
    M, C, K, GK, GC = derivations.lagrange(T, V, 0, [theta])
    assert M == sympy.Matrix([[m * l**2]]) and K == sympy.Matrix([[m * g * l]]) and C == sympy.zeros(1, 1)
    assert GK.shape == (1, 0)


def test_generalized_forces_by_virtual_work():
    # A force F at the end of a bar of length b turning by ψ works through b ψ: Q_ψ = F b.
    F, b = sympy.symbols("F b")
    y, psi = derivations.coordinates("y psi")
    Q = derivations.generalized_forces([(F, y + b * psi)], [y, psi])
    assert Q == sympy.Matrix([F, F * b])


def test_difference_reports_a_wrong_matrix():
    s = SDOF(1000.0, 2000.0, 4e5)
    d = derivations.sdof()
    assert d.difference(([[1000.0]], [[2000.0]], [[4e5]]), s) == 0.0
    # A stiffness 1 % off is seen as 1 % off.
    assert d.difference(([[1000.0]], [[2000.0]], [[4.04e5]]), s) == pytest.approx(0.04 / 4.04, rel=1e-12)


def test_derivation_refuses_a_symbol_without_a_value():
    m, k = sympy.symbols("m k")
    (x,) = derivations.coordinates("x")
    with pytest.raises(ValueError, match="missing"):
        derivations.Derivation(
            "bad", (x,), sympy.Matrix([[m]]), sympy.zeros(1, 1), sympy.Matrix([[k]]),
            sympy.zeros(1, 0), sympy.zeros(1, 0), parameters=((m, "mass"),),
        )  # fmt: skip
