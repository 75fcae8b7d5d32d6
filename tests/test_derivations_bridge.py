"""Chapter 10's beam derived (raildyn.derivations.bridge), held to raildyn.bridge.

* :func:`beam_modes` against :class:`SimplySupportedBeam`: diag(μ_j), diag(2ξω_jμ_j), diag(ω_j²μ_j)
  from its ``modal_masses`` and ``frequencies_hz``.
* The moving force and the moving mass against the coupled matrices that the time march of
  :func:`raildyn.bridge.crossing` assembles (``raildyn.bridge._kernel._assemble``, the only place
  that builds them: the march solves them at once), with the load on a node of the kernel's table of
  mode shapes, where the table holds sin(jπx/L) and its derivatives exactly and the interpolation
  gives them back to round-off. So the comparison is to round-off, as tests/derivation_helpers.py
  says (1e-12 of each matrix's largest entry); the input column G_K is held to the kernel's load
  vector divided by the load.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from derivation_helpers import assert_derived
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.bridge import AxleSequence, SimplySupportedBeam, _kernel, moving_load, moving_mass
from raildyn.derivations.bridge import beam_modes, beam_under_moving_force, beam_under_moving_mass

POINTS_PER_MODE = 200  # the table crossing() builds (raildyn.bridge.coupled._TABLE_POINTS_PER_MODE)


def beams(modes):
    return st.builds(
        SimplySupportedBeam,
        span=st.floats(5.0, 60.0),
        flexural_rigidity=st.floats(1e8, 1e12),
        mass_per_length=st.floats(1e3, 5e4),
        damping_ratio=st.floats(0.0, 0.1),
        modes=st.just(modes),
    )


def modal_matrices(beam):
    """diag(μ), diag(2ξωμ), diag(ω²μ) of the beam, as crossing() passes them to the march."""
    mu = beam.modal_masses
    omega = 2 * np.pi * beam.frequencies_hz
    return np.diag(mu), np.diag(2 * beam.damping_ratio * omega * mu), np.diag(omega**2 * mu)


def assembled(beam, load, speed, node):
    """The kernel's coupled A, B, Z and load f with the load's one axle on table node ``node``."""
    n, L = beam.modes, beam.span
    grid = np.linspace(0.0, L, POINTS_PER_MODE * n + 1)
    tables = [np.ascontiguousarray(beam.mode_shapes(grid, d)) for d in range(3)]
    _, C, K = modal_matrices(beam)
    a = load.positions.size
    A, B, Z = (np.empty((n, n)) for _ in range(3))
    f = np.empty(n)
    empty = np.zeros((0, 0))
    _kernel._assemble(
        grid[node] / speed, speed, L, grid[1] - grid[0], *tables, beam.modal_masses, np.diag(C).copy(),
        np.diag(K).copy(), empty, empty, empty, np.zeros((0, a)), np.zeros((0, a)), np.zeros((a, a)),
        np.zeros((a, a)), load.static_loads, load.unsprung_masses, load.positions, np.zeros((a, 3)),
        A, B, Z, f, np.empty((a, 3, n)),
    )  # fmt: skip
    return A, B, Z, f, grid[node]


@settings(max_examples=20, deadline=None)
@given(data=st.data())
def test_beam_modes_match_the_beam(data):
    n = data.draw(st.integers(1, 4))
    beam = data.draw(beams(n))
    assert_derived(beam_modes(n), modal_matrices(beam), SimpleNamespace(beam=beam))


def test_beam_modes_closed_form():
    # By hand: μ_j = mL/2 and k_j = EI (jπ/L)⁴ L/2 (the integrals of sin² and of its curvature²).
    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, damping_ratio=0.02, modes=3)
    M, C, K, _, _ = beam_modes(3).numeric(SimpleNamespace(beam=beam))
    assert M[2, 2] == pytest.approx(1.0e4 * 20.0 / 2, rel=1e-15)
    assert K[2, 2] == pytest.approx(1.0e10 * (3 * np.pi / 20.0) ** 4 * 20.0 / 2, rel=1e-14)
    assert K[0, 1] == 0.0 and M[0, 2] == 0.0


@settings(max_examples=20, deadline=None)
@given(data=st.data())
def test_moving_force_matches_the_assembled_march(data):
    n = data.draw(st.integers(1, 4))
    beam = data.draw(beams(n))
    force = data.draw(st.floats(1e3, 1e6))
    speed = data.draw(st.floats(1.0, 150.0))
    A, B, Z, f, place = assembled(
        beam, moving_load(AxleSequence([0.0], [force])), speed, data.draw(st.integers(1, 200 * n - 1))
    )
    model = SimpleNamespace(beam=beam, position=place)
    assert_derived(beam_under_moving_force(n), (A, B, Z, f[:, None] / force, np.zeros((n, 1))), model)


def test_moving_force_closed_form():
    # The modal load of book ch. 10 / Frýba's eq. 1.12 per unit modal mass: 2P/(mL) sin(jπs/L),
    # the factor beam.moving_force_response multiplies each mode by.
    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=3)
    M, _, _, GK, _ = beam_under_moving_force(3).numeric(SimpleNamespace(beam=beam, position=7.0))
    expected = 2 / (1.0e4 * 20.0) * np.sin(np.arange(1, 4) * np.pi * 7.0 / 20.0)
    np.testing.assert_allclose(np.linalg.solve(M, GK[:, 0]), expected, rtol=1e-14)


@settings(max_examples=20, deadline=None)
@given(data=st.data())
def test_moving_mass_matches_the_assembled_march(data):
    n = data.draw(st.integers(1, 3))
    beam = data.draw(beams(n))
    load = moving_mass(data.draw(st.floats(100.0, 1e5)))
    speed = data.draw(st.floats(1.0, 150.0))
    A, B, Z, f, place = assembled(beam, load, speed, data.draw(st.integers(1, 200 * n - 1)))
    model = SimpleNamespace(beam=beam, load=load, position=place)
    W = load.static_loads[0]
    # C's entries 2MV φ_j φ_k′ cancel to round-off where the mass stands at a node of a slope (midspan
    # for mode 1): held to the size of the terms, 2MV nπ/L, there.
    scales = {"C": 2 * load.unsprung_masses[0] * speed * n * np.pi / beam.span}
    assert_derived(
        beam_under_moving_mass(n), (A, B, Z, f[:, None] / W, np.zeros((n, 1))), model, speed, scales=scales
    )


def test_moving_mass_closed_form():
    # By hand: C₁₂ = 2MV φ₁(s) φ₂′(s), K₂₁ = MV² φ₂(s) φ₁″(s), M₁₂ = M φ₁(s) φ₂(s) beside the beam's.
    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, damping_ratio=0.0, modes=2)
    Mc, v, s, L = 5000.0, 30.0, 6.0, 20.0
    model = SimpleNamespace(beam=beam, load=moving_mass(Mc), position=s)
    M, C, K, _, _ = beam_under_moving_mass(2).numeric(model, v)
    phi1, phi2 = np.sin(np.pi * s / L), np.sin(2 * np.pi * s / L)
    assert C[0, 1] == pytest.approx(
        2 * Mc * v * phi1 * (2 * np.pi / L) * np.cos(2 * np.pi * s / L), rel=1e-13
    )
    assert K[1, 0] == pytest.approx(-Mc * v**2 * phi2 * (np.pi / L) ** 2 * phi1, rel=1e-13)
    assert M[0, 1] == pytest.approx(Mc * phi1 * phi2, rel=1e-13)


def test_counts_are_checked():
    for f in (beam_modes, beam_under_moving_force, beam_under_moving_mass):
        with pytest.raises(ValueError, match="count"):
            f(0)
