"""Chapter 9's coupler chain (raildyn.derivations.train) held to the train model's right-hand side.

The package's train is nonlinear, so the derived M, C, K are held to the Jacobian of
``TrainModel.rhs`` by central differences, at states where the linearisation is exact:

* K: every coupler beyond its slack and its blend, inside its travel, and being loaded further
  (its rate 50 transition rates in the loading sense, where 1 − tanh² < 1e-42): the force is
  k_l(|Δx| − e/2), linear in Δx, so a central difference has no truncation error;
* C: every vehicle at the speed V with the slack open (Δx = 0, no coupler force whatever the rate):
  the resistance A + Bv + Cv² is quadratic in v, where a central difference is exact too, and
  tanh(v/v_c) is 1 to the last bit (v/v_c ≥ 40).

What is left is round-off, ε|a|/h in each difference: with the steps below it is under 1e-11 of
each matrix's largest entry, so the comparison uses 1e-9 (a hundred times that).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.derivations.train import coupler_chain
from raildyn.train import VEHICLES, Consist, DraftGear, TrainModel, davis_resistance

RELATIVE = 1e-9  # see the module docstring
STEP_EXTENSION = 1e-4  # m: well inside the linear branch (its deflections are 2 mm and more)
STEP_SPEED = 1e-2  # m/s: exact for a quadratic, and v stays far above the creep speed


def _model(names, factors, gear, form):
    vehicles = tuple(
        dataclasses.replace(VEHICLES[name], mass=VEHICLES[name].mass * f)
        for name, f in zip(names, factors, strict=True)
    )
    return TrainModel(Consist(vehicles), gear=gear, davis_form=form)


def _acceleration_jacobian(model, y, rows):
    """∂(v̇)/∂y[rows] by central differences, one column per perturbed state entry."""
    n = model.size
    steps = np.where(np.asarray(rows) < n, STEP_EXTENSION, STEP_SPEED)
    plus = np.repeat(y[:, None], len(rows), axis=1)
    minus = plus.copy()
    plus[rows, np.arange(len(rows))] += steps
    minus[rows, np.arange(len(rows))] -= steps
    return (model.rhs(0.0, plus)[n:] - model.rhs(0.0, minus)[n:]) / (2 * steps)


def package_matrices(model, speed, signs, deflections):
    """M, C, K of the train model linearised as the module docstring says (from its rhs)."""
    n, g = model.size, model.gear
    mass = model.consist.mass
    # K: couplers loaded beyond the slack, each in the sense of its sign (+ draft, − buff).
    extension = signs * (g.slack / 2 + deflections)
    rate = signs * 50 * g.transition_rate  # loading: the extension grows in its own sense
    v = speed - np.r_[0.0, np.cumsum(rate)]
    y = np.r_[model.initial_state(speed)[0], extension, v]
    jz = _acceleration_jacobian(model, y, list(range(n)))  # over [x_0, Δx_0 … Δx_{n−2}]
    # z = P x: x_0 = x_0, Δx_j = x_j − x_{j+1} − spacing
    P = np.zeros((n, n))
    P[0, 0] = 1.0
    for j in range(n - 1):
        P[j + 1, j], P[j + 1, j + 1] = 1.0, -1.0
    K = -mass[:, None] * (jz @ P)
    # C: every vehicle at V, the slack open.
    y = model.initial_state(speed, 0.0)
    C = -mass[:, None] * _acceleration_jacobian(model, y, list(range(n, 2 * n)))
    return np.diag(mass), C, K


def assert_close(derivation, matrices, model, speed):
    for name, mine, theirs in zip("MCK", derivation.numeric(model, speed), matrices, strict=False):
        np.testing.assert_allclose(
            mine, theirs, rtol=0.0, atol=RELATIVE * np.abs(theirs).max(), err_msg=f"{name} differs"
        )


@settings(max_examples=25, deadline=None)
@given(data=st.data())
def test_coupler_chain_is_the_jacobian_of_the_train(data):
    n = data.draw(st.integers(2, 5), label="vehicles")
    names = data.draw(st.lists(st.sampled_from(sorted(VEHICLES)), min_size=n, max_size=n))
    factors = data.draw(st.lists(st.floats(0.5, 2.0), min_size=n, max_size=n))
    k_l = data.draw(st.floats(5e6, 1e8), label="loading stiffness")
    travel = data.draw(st.floats(0.03, 0.12), label="travel")
    gear = DraftGear(
        slack=data.draw(st.floats(0.01, 0.1), label="slack"),
        loading_stiffness=k_l,
        unloading_stiffness=k_l * data.draw(st.floats(0.1, 1.0)),
        travel=travel,
        solid_stiffness=data.draw(st.floats(0.0, 1e9)),
        transition_rate=data.draw(st.floats(0.005, 0.05)),
    )
    model = _model(names, factors, gear, data.draw(st.sampled_from(["original", "modified"])))
    signs = np.array(data.draw(st.lists(st.sampled_from([-1.0, 1.0]), min_size=n - 1, max_size=n - 1)))
    # beyond the blend (2 ε = 2 mm) and short of the solid branch
    deflections = np.array(
        data.draw(st.lists(st.floats(0.003, 0.8 * travel), min_size=n - 1, max_size=n - 1))
    )
    speed = data.draw(st.floats(12.0, 40.0), label="V")
    assert_close(coupler_chain(n), package_matrices(model, speed, signs, deflections), model, speed)


def test_coupler_chain_closed_forms():
    # By hand: the stiffness between neighbours is −k_l, the loading stiffness the gear exposes,
    # and a vehicle's damping is dR/dv = B + 2CV of Davis's law at V (the slope of
    # davis_resistance itself, a quadratic, by a central difference).
    model = _model(["SD40-2", "loaded hopper", "empty hopper"], [1.0] * 3, DraftGear(), "original")
    d = coupler_chain(3)
    speed = 20.0
    M, C, K, GK, GC = d.numeric(model, speed)
    assert K[0, 1] == -model.gear.loading_stiffness and K[1, 1] == 2 * model.gear.loading_stiffness
    v = model.consist.vehicles[2]
    slope = (
        davis_resistance(speed + 1.0, v.mass, v.axles, v.frontal_area, kind=v.kind)
        - davis_resistance(speed - 1.0, v.mass, v.axles, v.frontal_area, kind=v.kind)
    ) / 2.0
    assert C[2, 2] == pytest.approx(slope, rel=1e-12)
    assert np.array_equal(M, np.diag(model.consist.mass)) and GK.shape == (3, 0)


def test_coupler_chain_refuses_a_single_vehicle():
    with pytest.raises(ValueError, match="count"):
        coupler_chain(1)
