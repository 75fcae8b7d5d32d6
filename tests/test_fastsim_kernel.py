"""Tests of FASTSIM's compiled march: equal to the numpy march it replaced, to 1e-12.

``raildyn.contact.fastsim.fastsim`` calls the numba kernel of
``raildyn.contact._fastsim_kernel``; ``_fastsim_numpy`` is the numpy version that
came before it, kept as the reference. The two do the same arithmetic but for the
order of the sums (per strip, then times the cell area) and |t| (√(t_x² + t_y²)
against ``hypot``, within an ulp): over 400 cells that moves the forces by some 1e-14
of the largest force, so 1e-12 leaves a margin and still catches any change of the
algorithm (a cell or strip dropped or misplaced moves them by more than 1e-4).
"""

import importlib

import numba
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.contact import fastsim

module = importlib.import_module("raildyn.contact.fastsim_python")  # where _fastsim_numpy lives
TOL = 1e-12
# Plus this much absolute: results in the subnormal range (from creepages like 5e-324, which
# hypothesis finds) have lost their relative precision; no physical force or field is this small.
FLOOR = 1e-300
N, MU, A, B = 1e5, 0.3, 6e-3, 4e-3
FIELDS = ("x", "y", "px", "py", "pz", "slip_x", "slip_y")


def _assert_same(args, **kw):
    """fastsim and _fastsim_numpy on ``args``: forces to 1e-12 of each state's scale, fields too."""
    new = fastsim(*args, **kw)
    ref = module._fastsim_numpy(*args, **kw)
    fx, fy, mz = (np.asarray(v) for v in (ref.fx, ref.fy, ref.mz))
    # Each state's scale: its largest force, or μN where there is none (zero creepage).
    mu_n = np.broadcast_to(np.asarray(ref.friction) * np.asarray(ref.normal_load), fx.shape)
    scale = np.maximum(np.maximum(np.abs(fx), np.abs(fy)), np.where((fx == 0) & (fy == 0), mu_n, 0.0))
    length = np.maximum(ref.a, ref.b)
    assert np.shape(new.fx) == fx.shape
    assert np.all(np.abs(new.fx - fx) <= TOL * scale + FLOOR)
    assert np.all(np.abs(new.fy - fy) <= TOL * scale + FLOOR)
    assert np.all(np.abs(new.mz - mz) <= TOL * scale * length + FLOOR)
    for k in ("normal_load", "friction", "a", "b"):
        np.testing.assert_array_equal(getattr(new, k), getattr(ref, k))
    if kw.get("fields", True):
        np.testing.assert_array_equal(new.adhesion, ref.adhesion)
        for k in FIELDS:
            got, want = getattr(new, k), getattr(ref, k)
            assert got.shape == want.shape
            # Per state: relative to the field's largest entry over that state's patch.
            size = np.max(np.abs(want), axis=(-2, -1), keepdims=True)
            assert np.all(np.abs(got - want) <= TOL * size + FLOOR), k
    return new, ref


@given(
    st.lists(
        st.tuples(
            st.floats(-1e-2, 1e-2),
            st.floats(-1e-2, 1e-2),
            st.floats(-3.0, 3.0),
            st.floats(1e3, 2e5),
            st.floats(0.05, 0.8),
            st.floats(2e-3, 1e-2),
            st.floats(0.3, 3.0),
        ),
        min_size=1,
        max_size=20,
    ),
    st.sampled_from([(20, 20), (7, 13), (2, 2), (31, 5)]),
    st.booleans(),
)
@settings(max_examples=60, deadline=None)
def test_compiled_march_equals_the_numpy_march(states, grid, fields):
    xi, eta, phi, load, mu, a, ratio = (np.array(v) for v in zip(*states, strict=True))
    _assert_same((xi, eta, phi, load, mu, a, a / ratio), n_x=grid[0], n_y=grid[1], fields=fields)


def test_limits_full_adhesion_full_slip_pure_spin_zero_creepage():
    new, _ = _assert_same((1e-8, -2e-8, 0.0, N, MU, A, B))
    assert new.adhesion.all()  # full adhesion
    new, _ = _assert_same((0.3, 0.2, 0.0, N, MU, A, B))
    assert new.adhesion.mean() < 0.06 and np.hypot(new.fx, new.fy) == pytest.approx(MU * N, rel=2e-3)
    new, _ = _assert_same((0.0, 0.0, 3.0, N, MU, A, B))
    assert abs(new.fy) > 1e3 and abs(new.fx) < 1e-9 * abs(new.fy)  # pure spin: a lateral force only
    new, _ = _assert_same((0.0, 0.0, 0.0, N, MU, A, B))
    assert (new.fx, new.fy, new.mz) == (0.0, 0.0, 0.0) and new.adhesion.all()
    # A batch mixing all four, broadcast to a 2-D shape.
    xi = np.array([[1e-8], [0.3], [0.0], [0.0]])
    new, _ = _assert_same((xi, np.array([0.0, 0.2, 1e-3]), np.array([0.0, 0.0, 3.0]), N, MU, A, B))
    assert np.shape(new.fx) == (4, 3) and new.px.shape == (4, 3, 20, 20)


def test_bounds_outside_the_fast_slide_test_and_huge_creepages(monkeypatch):
    # μp₀ beyond 1e100 Pa or below 1e-100 Pa: the kernel takes hypot, as numpy does, so that no
    # square overflows or underflows; huge creepages are scaled down before either march.
    for mu in (1e-200, 1e-95):
        for creep in (1e-3, 1e300):
            _assert_same((creep, 0.5 * creep, 1.0, N, mu, A, B))
    # A friction coefficient above 1 is refused (raildyn.constants.PLAUSIBLE_RANGES), so μp₀ beyond
    # 1e100 Pa no longer comes from outside; the two marches are still held together there, with the
    # plausible ranges lifted for this test.
    for mu in (1e200, 1e95):
        with pytest.raises(ValueError, match="friction must be in"):
            fastsim(1e-3, 5e-4, 1.0, N, mu, A, B)
    array = module._checks.array
    monkeypatch.setattr(
        module._checks,
        "plausible_array",
        lambda name, value, quantity, low=None, low_open=False: array(name, value),
    )
    for mu in (1e200, 1e95):
        for creep in (1e-3, 1e300):
            _assert_same((creep, 0.5 * creep, 1.0, N, mu, A, B))


def test_one_thread_and_several_give_the_same_bits():
    rng = np.random.default_rng(1)
    args = (
        rng.uniform(-5e-3, 5e-3, 101),
        rng.uniform(-5e-3, 5e-3, 101),
        rng.uniform(-1, 1, 101),
        N,
        MU,
        A,
        B,
    )
    threads = numba.get_num_threads()
    try:
        numba.set_num_threads(1)
        one = fastsim(*args, fields=False)
        numba.set_num_threads(numba.config.NUMBA_NUM_THREADS)
        many = fastsim(*args, fields=False)
    finally:
        numba.set_num_threads(threads)
    # Each state is marched by one thread in the same order: no result depends on the split.
    np.testing.assert_array_equal(one.fx, many.fx)
    np.testing.assert_array_equal(one.mz, many.mz)
    _assert_same(args)  # the parallel march, fields too, equals numpy's as the serial one does


def test_forces_do_not_depend_on_asking_for_the_fields():
    args = (np.array([1e-4, 2e-3, 0.0]), 1e-3, np.array([0.5, 0.0, -1.0]), N, MU, A, B)
    with_fields, without = fastsim(*args), fastsim(*args, fields=False)
    np.testing.assert_array_equal(with_fields.fx, without.fx)
    np.testing.assert_array_equal(with_fields.fy, without.fy)
    np.testing.assert_array_equal(with_fields.mz, without.mz)
    assert without.px is None


def test_bad_input_is_refused_before_the_kernel():
    with pytest.raises(ValueError, match="spin"):
        fastsim(1e-3, 0.0, np.nan, N, MU, A, B)
    with pytest.raises(ValueError, match="n_y"):
        fastsim(1e-3, 0.0, 0.0, N, MU, A, B, n_y=1)
    with pytest.raises(ValueError, match="a/b must be in"):
        fastsim(1e-3, 0.0, 0.0, N, MU, A / 4, 5 * A)  # a/b = 1/20, each semi-axis plausible
