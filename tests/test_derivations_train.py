"""Chapter 9's coupler chain (raildyn.derivations.train) held to the train model's right-hand side.

The package's train is nonlinear, so the derived M, C, K are held to the Jacobian of
``TrainModel.rhs`` by central differences (``loaded_train_matrices``), at states where the
linearisation is exact:

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

from raildyn.derivations.train import coupler_chain, loaded_train_matrices
from raildyn.train import VEHICLES, Consist, DraftGear, TrainModel, davis_resistance

RELATIVE = 1e-9  # see the module docstring


def _model(names, factors, gear, form):
    vehicles = tuple(
        dataclasses.replace(VEHICLES[name], mass=VEHICLES[name].mass * f)
        for name, f in zip(names, factors, strict=True)
    )
    return TrainModel(Consist(vehicles), gear=gear, davis_form=form)


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
    assert_close(coupler_chain(n), loaded_train_matrices(model, speed, deflections, signs), model, speed)


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


def test_loaded_train_matrices_refuse_a_state_off_the_loading_branch():
    model = _model(["SD40-2", "loaded hopper"], [1.0, 1.0], DraftGear(), "original")
    with pytest.raises(ValueError, match="deflection"):
        loaded_train_matrices(model, 20.0, 0.5)  # beyond the travel: the solid branch
    with pytest.raises(ValueError, match="signs"):
        loaded_train_matrices(model, 20.0, 0.01, 0.5)
    with pytest.raises(ValueError, match="speed"):
        loaded_train_matrices(model, 1.0)  # within 40 creep speeds of a stop
