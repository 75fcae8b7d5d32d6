"""Design codes and design trains (raildyn.bridge.codes, raildyn.bridge.trains): the code formulas at their
clauses' own numbers, resonance and its cancellation against the moving-force solution, the HSLM trains
against an independent encoding of EN 1991-2 Annex E."""

from __future__ import annotations

import numpy as np
import pytest

from raildyn.bridge import SimplySupportedBeam, moving_force_response
from raildyn.bridge.codes import (
    arema_impact_factor,
    cancellation_spans,
    comfort_acceleration_limit,
    deck_acceleration_limit,
    en1991_dynamic_factor,
    en1991_real_train_factor,
    resonance_speeds,
)
from raildyn.bridge.trains import HSLM_A, hslm, regular_train

FT = 0.3048

# ----------------------------------------------------------------------------------------- AREMA


def test_arema_impact_in_feet():
    # AREMA ch. 15 art. 1.3.5 (as Chu, Garg & Dhar 1979 use it): 40 − 3L²/1600 % below 80 ft, 16 + 600/(L −
    # 30) % from 80 ft; the rocking 100/S %. Evaluated by hand at 40, 80 and 130 ft: 37, 28, 22 % (exact
    # decimals; rounding only), 10 ft girders add 10 %.
    assert arema_impact_factor(40 * FT) == pytest.approx(0.37, rel=1e-12)
    assert arema_impact_factor(80 * FT) == pytest.approx(0.28, rel=1e-12)
    assert arema_impact_factor(130 * FT) == pytest.approx(0.22, rel=1e-12)
    assert arema_impact_factor(130 * FT, 10 * FT) == pytest.approx(0.32, rel=1e-12)


def test_arema_impact_is_continuous_and_falls_with_span():
    # The two branches meet at 80 ft (28 %): a step of 1e-9 ft changes I by < 1e-9. The impact falls with
    # the span on both branches.
    below, above = arema_impact_factor(np.array([80 - 1e-9, 80 + 1e-9]) * FT)
    assert below == pytest.approx(above, abs=1e-9)
    spans = np.linspace(1.0, 200.0, 400)
    assert np.all(np.diff(arema_impact_factor(spans)) < 0)


# -------------------------------------------------------------------------------------- EN 1991-2


def test_en1991_phi2_and_phi3():
    # EN 1991-2 eqs 6.4 and 6.5 evaluated by hand at L_Φ = 4 m (√4 − 0.2 = 1.8): Φ₂ = 0.8 + 0.82 = 1.62 and
    # Φ₃ = 1.2 + 0.73 = 1.93; at 100 m both fall below 1 and are held at 1.00; at 1 m both exceed their caps
    # (1.67, 2.00). Exact decimals: rounding only.
    assert en1991_dynamic_factor(4.0) == pytest.approx(1.62, rel=1e-12)
    assert en1991_dynamic_factor(4.0, "standard") == pytest.approx(1.93, rel=1e-12)
    np.testing.assert_allclose(en1991_dynamic_factor([1.0, 100.0]), [1.67, 1.0], rtol=1e-12)
    np.testing.assert_allclose(en1991_dynamic_factor([1.0, 100.0], "standard"), [2.0, 1.0], rtol=1e-12)


def test_en1991_phi_meets_its_cap_continuously():
    # Where the formula reaches the cap (√L = 0.2 + 1.44/0.85) the factor is continuous: 1e-9 m either side
    # differs by < 1e-8. Below it, the cap; above it, falling.
    edge = (0.2 + 1.44 / 0.85) ** 2
    a, b = en1991_dynamic_factor(np.array([edge - 1e-9, edge + 1e-9]))
    assert a == pytest.approx(1.67, abs=1e-8) and b == pytest.approx(1.67, abs=1e-8)
    assert np.all(np.diff(en1991_dynamic_factor(np.linspace(edge, 60, 200))) < 0)


def test_en1991_annex_c_real_train():
    # EN 1991-2 eqs C.1–C.4 by hand: L_Φ = 20 m, n₀ = 80/20 = 4 Hz makes the φ″ second term vanish; at v = 40
    # m/s, K = 0.25, φ′ = 0.25/(0.75 + 0.25⁴), α = 1, φ″ = 0.56 e^{−4}. At K ≥ 0.76 φ′ is 1.325. At v = 11
    # m/s, α = 0.5. Rounding only: 1e-12.
    K = 0.25
    phi1 = K / (1 - K + K**4)
    phi2 = 0.56 * np.exp(-4.0)
    assert en1991_real_train_factor(40.0, 20.0, 4.0) == pytest.approx(1 + phi1 + phi2 / 2, rel=1e-12)
    assert en1991_real_train_factor(40.0, 20.0, 4.0, "standard") == pytest.approx(1 + phi1 + phi2, rel=1e-12)
    fast = 0.8 * 2 * 20.0 * 4.0
    assert en1991_real_train_factor(fast, 20.0, 4.0, "standard") == pytest.approx(1 + 1.325 + phi2, rel=1e-12)
    K = 11.0 / 160.0
    slow = 1 + K / (1 - K + K**4) + 0.5 * phi2
    assert en1991_real_train_factor(11.0, 20.0, 4.0, "standard") == pytest.approx(slow, rel=1e-12)


def test_en1990_limits_by_name():
    # EN 1990 A2.4.4.2.1(4)P and Table A2.9, recommended values.
    assert deck_acceleration_limit("ballasted") == 3.5
    assert deck_acceleration_limit("direct") == 5.0
    assert [comfort_acceleration_limit(k) for k in ("very good", "good", "acceptable")] == [1.0, 1.3, 2.0]
    with pytest.raises(ValueError, match="track"):
        deck_acceleration_limit("slab")
    with pytest.raises(ValueError, match="level"):
        comfort_acceleration_limit("excellent")


# ---------------------------------------------------------------------------- resonance, cancellation


def test_resonance_speeds_of_the_issue():
    # Issue 18: a 20 m span at f₁ = 4 Hz under an 18 m spacing resonates at 72, 36 and 24 m/s (v = n₀d/i).
    np.testing.assert_allclose(resonance_speeds(4.0, 18.0, 3), [72.0, 36.0, 24.0], rtol=1e-15)


def test_cancellation_spans_formula():
    # L/d = (2k + 1)/(2i): first resonance 1.5, 2.5, 3.5 d; second 0.75, 1.25, 1.75 d.
    np.testing.assert_allclose(cancellation_spans(10.0, 1, 3), [15.0, 25.0, 35.0], rtol=1e-15)
    np.testing.assert_allclose(cancellation_spans(10.0, 2, 3), [7.5, 12.5, 17.5], rtol=1e-15)


def residual(beam, alpha, samples=3001):
    """Largest midspan deflection after one force has left the span, at α = v/(2 f₁ L), by
    moving_force_response."""
    v = alpha * 2 * beam.frequencies_hz[0] * beam.span
    r = moving_force_response(beam, v, 1.0e5, samples=samples)
    after = r.time[0] > beam.span / v
    return np.abs(r.deflection[0][after]).max()


def test_one_force_leaves_no_vibration_at_alpha_one_third():
    # The derived cancellation of the single force: α = 1/(2k + 1) leaves the first mode at rest. Checked on
    # raildyn's moving-force solution (an independent path: the damped oscillator's closed form) with one
    # mode: at α = 1/3 and 1/5 the residual is rounding (< 1e-9 of the static deflection), at α = 0.4 it is
    # the derived (Q/ω²) 2α/(1 − α²) |cos(π/(2α))| × (the mode's midspan value 1), to 1e-9.
    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=1)
    static = 1.0e5 * 20.0**3 / (48 * 1.0e10)
    assert residual(beam, 1 / 3) < 1e-9 * static
    assert residual(beam, 1 / 5) < 1e-9 * static
    omega = 2 * np.pi * beam.frequencies_hz[0]
    Q = 2 * 1.0e5 / (1.0e4 * 20.0)
    alpha = 0.4
    expected = Q / omega**2 * 2 * alpha / (1 - alpha**2) * abs(np.cos(np.pi / (2 * alpha)))
    # The sampled peak of the free vibration: 30 000 samples over two crossings (α = 0.4: 2.5 periods), a
    # sample every 0.03° of phase, so it misses the amplitude by at most (5e-4 rad)²/2 ~ 1e-7.
    assert residual(beam, alpha, samples=30_001) == pytest.approx(expected, rel=1e-7)


def train_response(L_over_d, axles=10):
    """Midspan deflection of a one-mode span under a regular train at its first resonance, by superposition.

    moving_force_response gives one force's response over two crossing times T; at the first resonance the
    axle interval d/v is one period of the mode, and the free vibration after the force has left (undamped,
    one mode) repeats with that period, so the single response extends exactly to any later time.
    """
    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=1)
    f1 = beam.frequencies_hz[0]
    d = 20.0 / L_over_d
    v = f1 * d  # first resonance
    per = 400  # samples a period
    n = int(round(2 * L_over_d * per)) + 1  # samples over 2T
    single = moving_force_response(beam, v, 1.0e5, samples=n).deflection[0]
    after_exit = int(round(L_over_d * per))  # index of T

    def extended(idx):
        idx = np.asarray(idx)
        out = np.zeros(idx.shape)
        inside = (idx >= 0) & (idx < n)
        out[inside] = single[idx[inside]]
        late = idx >= n
        back = np.ceil((idx[late] - (n - 1)) / per).astype(int) * per  # whole periods back into (T, 2T]
        out[late] = single[idx[late] - back]
        assert np.all(idx[late] - back > after_exit)
        return out

    total_samples = (axles - 1) * per + n + 2 * per
    k = np.arange(total_samples)
    w = sum(extended(k - a * per) for a in range(axles))
    static = 1.0e5 * 20.0**3 / (48 * 1.0e10)
    return w / static


def test_a_regular_train_builds_up_at_resonance_unless_the_span_cancels_it():
    # L = d: every axle leaves the same free vibration in phase: after the last axle the amplitude is 10 times
    # one axle's (α = 0.5: (Q/ω²)·(4/3)|cos π| ≠ 0), to rounding (1e-9). L = 1.5 d: α = 1/3, each axle leaves
    # nothing: the free vibration after the train is rounding, and the largest deflection stays one axle's
    # (measured: 1.48 of the static for L = 1.5 d; 13.4 for L = d, whose residual is 10 × 1.31).
    build = train_response(1.0)
    cancel = train_response(1.5)
    single = train_response(1.0, axles=1)
    assert np.abs(build[-800:]).max() == pytest.approx(10 * np.abs(single[-800:]).max(), rel=1e-9)
    assert np.abs(cancel).max() < 1.5  # one axle's static-plus-dynamic deflection (1.48)
    assert np.abs(cancel[-800:]).max() < 1e-9
    assert np.abs(build).max() > 5 * np.abs(cancel).max()


# -------------------------------------------------------------------------------------------- trains

# CALDINTAV (K. Nguyen Gia & J. M. Goicolea, Universidad Politécnica de Madrid; github.com/khanh-nguyen-gia/
# caldintav, caldintav/trains/a01.def … a10.def) tabulates every axle of HSLM-A1 … A10. Its last-axle
# positions, m, and the position of the first axle of the first shared bogie:
CALDINTAV_LAST = [397.525, 398.525, 397.525, 394.525, 389.525, 382.525, 397.525, 387.525, 375.525, 388.525]
CALDINTAV_FIRST_SHARED = [
    35.7625,
    36.0125,
    37.7625,
    38.2625,
    39.7625,
    40.7625,
    41.7625,
    42.5125,
    43.7625,
    44.7625,
]


@pytest.mark.parametrize("number", range(1, 11))
def test_hslm_trains_against_annex_e(number):
    # EN 1991-2 Table E.4 / Figure E.8: two power cars (4 axles), two end coaches (a free bogie each) and N +
    # 1 shared bogies: 2N + 14 axles of P kN; the shared bogies at the regular spacing D, each of axle spacing
    # d; the positions against CALDINTAV's files (decimals given to 4 places: 1e-9 m).
    N, D, d, P = HSLM_A[number]
    train = hslm(number)
    x = train.positions
    assert x.size == 2 * N + 14
    np.testing.assert_allclose(train.loads, P * 1e3, rtol=0)
    assert train.length == pytest.approx(CALDINTAV_LAST[number - 1], abs=1e-9)
    assert x[6] == pytest.approx(CALDINTAV_FIRST_SHARED[number - 1], abs=1e-9)
    shared = x[6 : 6 + 2 * (N + 1)].reshape(N + 1, 2)
    np.testing.assert_allclose(np.diff(shared.mean(axis=1)), D, rtol=1e-12)
    np.testing.assert_allclose(np.diff(shared, axis=1), d, rtol=1e-12)
    np.testing.assert_allclose(x[-1] - x[::-1], x, atol=1e-9)  # the train is symmetric
    assert train.name == f"HSLM-A{number}"


def test_table_e4_rows():
    # EN 1991-2 Table E.4, spot rows: A1 (18, 18, 2.0, 170), A2 (17, 19, 3.5, 200), A10 (11, 27, 2.0, 210).
    assert HSLM_A[1] == (18, 18.0, 2.0, 170.0)
    assert HSLM_A[2] == (17, 19.0, 3.5, 200.0)
    assert HSLM_A[10] == (11, 27.0, 2.0, 210.0)
    assert [HSLM_A[k][1] for k in range(1, 11)] == list(np.arange(18.0, 28.0))


def test_regular_trains():
    # Articulated: N + 1 bogies at D; conventional: bogie centres a apart, coaches D long.
    art = regular_train(5, 20.0, 2.5, 1.5e5)
    assert art.positions.size == 12
    np.testing.assert_allclose(np.diff(art.positions[::2]), 20.0)
    conv = regular_train(3, 26.0, 2.5, 1.5e5, bogie_centres=19.0)
    assert conv.positions.size == 12
    np.testing.assert_allclose(np.diff(conv.positions[1::4]), 26.0)  # each coach's second axle: D apart
    assert conv.positions[2] - conv.positions[0] == pytest.approx(19.0)
    assert conv.length == pytest.approx(2 * 26.0 + 19.0 + 2.5)


def test_bad_input_is_refused_by_name():
    with pytest.raises(ValueError, match="span"):
        arema_impact_factor(0.0)
    with pytest.raises(ValueError, match="girder_spacing"):
        arema_impact_factor(20.0, -1.0)
    with pytest.raises(ValueError, match="maintenance"):
        en1991_dynamic_factor(20.0, "poor")
    with pytest.raises(ValueError, match="determinant_length"):
        en1991_dynamic_factor(-3.0)
    with pytest.raises(ValueError, match="speed"):
        en1991_real_train_factor(-1.0, 20.0, 4.0)
    with pytest.raises(ValueError, match="count"):
        resonance_speeds(4.0, 18.0, 0)
    with pytest.raises(ValueError, match="frequency_hz"):
        resonance_speeds(0.0, 18.0)
    with pytest.raises(ValueError, match="order"):
        cancellation_spans(18.0, 0)
    with pytest.raises(ValueError, match="number"):
        hslm(11)
    with pytest.raises(ValueError, match="bogie_centres"):
        regular_train(2, 20.0, 2.5, 1e5, bogie_centres=19.0)
    with pytest.raises(ValueError, match="bogie_axle_spacing"):
        regular_train(2, 20.0, 25.0, 1e5)


@pytest.mark.parametrize("L_over_d", [1.0, 1.5])
def test_the_superposition_is_moving_force_with_an_axle_sequence(L_over_d):
    # The same train through moving_force_response's own axle sequence (each axle's closed form, delayed): on
    # the same time grid (a sample every 1/400 of the period, from the first arrival until the last axle has
    # been off for one crossing) the two agree to rounding, 1e-9 of the peak.
    from raildyn.bridge import AxleSequence

    axles, per = 10, 400
    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=1)
    d = 20.0 / L_over_d
    v = beam.frequencies_hz[0] * d
    train = AxleSequence(d * np.arange(axles), np.full(axles, 1.0e5), "regular")
    periods = (2 * 20.0 + (axles - 1) * d) / d  # the run's length in periods (d/v is one period)
    n = int(round(periods * per)) + 1
    direct = moving_force_response(beam, v, train, samples=n).deflection[0] / (
        1.0e5 * 20.0**3 / (48 * 1.0e10)
    )
    superposed = train_response(L_over_d, axles)[:n]
    np.testing.assert_allclose(direct, superposed, atol=1e-9 * np.abs(superposed).max())
