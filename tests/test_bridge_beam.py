"""The simply supported beam under a moving force (raildyn.bridge.beam): Frýba's series, the beam formula
in the static limit, the modal frequencies, and the amplification against the speed parameter."""

from __future__ import annotations

import numpy as np
import pytest

from raildyn.bridge import SimplySupportedBeam, fryba_deflection, moving_force_response

BEAM = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=20)


def test_the_frequencies_are_the_beams():
    # ω_j = (jπ/L)² √(EI/m) (Frýba 1972, eq. 1.9): exact but for rounding.
    j = np.arange(1, 21)
    expected = (j * np.pi / 20.0) ** 2 * np.sqrt(1.0e10 / 1.0e4) / (2 * np.pi)
    np.testing.assert_allclose(BEAM.frequencies_hz, expected, rtol=1e-14)


@pytest.mark.parametrize("speed", [5.0, 30.0, 90.0, 200.0])
def test_the_modal_solution_is_frybas_series_while_the_force_is_on(speed, reference):
    # The same modes summed two ways, the closed-form oscillators against Frýba's series (eq. 1.30): the
    # same numbers but for rounding (1e-12 of the largest deflection).
    response = moving_force_response(BEAM, speed, 1.0e5, samples=501)
    on = response.time[0] <= 20.0 / speed
    series = fryba_deflection(BEAM, speed, 1.0e5, response.time[0][on])
    gap = np.abs(response.deflection[0][on] - series).max() / np.abs(series).max()
    reference(
        10,
        f"moving force over a simple span, closed form, v = {speed:g} m/s",
        "Frýba 1972 series (eq. 1.30)",
        "closed form",
        gap,
        1e-12,
    )


def test_a_slow_force_bends_the_beam_as_a_static_load():
    # v → 0: the largest midspan deflection tends to PL³/48EI. At 0.1 m/s (α = 6e-4) the dynamic part is
    # of order α (measured 0.06 %), and 20 modes hold the static shape to (1/21)⁴ ≈ 5e-6: rel 2e-3.
    response = moving_force_response(BEAM, 0.1, 1.0e5, samples=4001)
    assert response.static == pytest.approx(1.0e5 * 20.0**3 / (48 * 1.0e10), rel=1e-14)
    assert response.amplification[0] == pytest.approx(1.0, rel=2e-3)


def test_the_amplification_peaks_near_alpha_0_6():
    # The undamped single force: the amplification rises from 1 with α = v/(2 f₁ L) to its largest, 1.73
    # near α = 0.62 (measured on a 0.005 grid of α with 2000 samples a crossing; the peak between samples is
    # within 0.1 %), and falls beyond. Damping lowers it.
    f1 = BEAM.frequencies_hz[0]
    alpha = np.arange(0.3, 0.9, 0.005)
    daf = moving_force_response(BEAM, alpha * 2 * f1 * 20.0, 1.0e5, samples=2000).amplification
    k = int(np.argmax(daf))
    assert daf[k] == pytest.approx(1.73, abs=0.01)
    assert alpha[k] == pytest.approx(0.62, abs=0.02)
    damped = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, damping_ratio=0.05, modes=20)
    assert (
        moving_force_response(damped, alpha[k] * 2 * f1 * 20.0, 1.0e5, samples=2000).amplification[0] < daf[k]
    )


def test_bad_input_is_refused_by_name():
    with pytest.raises(ValueError, match="span"):
        SimplySupportedBeam(span=0.0)
    with pytest.raises(ValueError, match="flexural_rigidity"):
        SimplySupportedBeam(flexural_rigidity=-1.0)
    with pytest.raises(ValueError, match="damping_ratio"):
        SimplySupportedBeam(damping_ratio=1.0)
    with pytest.raises(ValueError, match="speeds"):
        moving_force_response(BEAM, -3.0)
    with pytest.raises(ValueError, match="position"):
        moving_force_response(BEAM, 30.0, position=25.0)
    with pytest.raises(ValueError, match="damping_ratio"):
        fryba_deflection(SimplySupportedBeam(damping_ratio=0.02), 30.0, 1.0, [0.1])
    with pytest.raises(ValueError, match="time"):
        fryba_deflection(BEAM, 30.0, 1.0, [1.0])


def test_the_acceleration_is_the_deflections_second_derivative_and_the_coupled_marchs():
    # Differentiated in closed form, it matches the central second difference of the deflection (error of
    # order (ω₅Δt)²/12 ≈ 2e-5 of the peak with 80001 samples) and the coupled march's deck acceleration
    # for the same forces: Newmark at h = 2.5e-5 s has a period error (ω₅h)²/12 = 2e-5 on the fifth mode,
    # which over its 130 cycles drifts its phase by 0.016 rad; within 1e-3 of the peak.
    from raildyn.bridge import AxleSequence, crossing

    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, damping_ratio=0.02, modes=5)
    coach = AxleSequence([0.0, 2.5, 17.5, 20.0], [1.0e5] * 4)
    closed = moving_force_response(beam, 30.0, coach, samples=80001)
    t, w, a = closed.time[0], closed.deflection[0], closed.acceleration[0]
    second = (w[2:] - 2 * w[1:-1] + w[:-2]) / (t[1] - t[0]) ** 2
    peak = np.abs(a).max()
    assert np.abs(second - a[1:-1]).max() < 1e-3 * peak
    h = t[1] - t[0]  # the same grid: the march's steps fall on the closed form's samples
    run = crossing(beam, coach, 30.0, time_step=h, free_time=0.0)
    k = run.time.size
    np.testing.assert_allclose(run.time, t[:k], atol=1e-12)
    assert np.abs(run.deck_acceleration - a[:k]).max() < 1e-3 * peak
    assert closed.peak_acceleration[0] == pytest.approx(peak)


def test_an_undamped_resonance_has_its_finite_limit():
    # At α = 1 exactly the first mode is forced at its own frequency: q = (sin ωs − ωs cos ωs)/(2ω²) while
    # the force is on. The answer is the limit of its neighbours: within 1e-6 of α(1 ± 1e-7) (the series'
    # slope in α times 1e-7 is ~1e-7), and the deflection is finite everywhere.
    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=5)
    v = 2 * beam.frequencies_hz[0] * beam.span  # α = 1
    at, below, above = (
        moving_force_response(beam, v * f, 1.0e5, samples=2001) for f in (1.0, 1 - 1e-7, 1 + 1e-7)
    )
    assert np.isfinite(at.deflection).all() and np.isfinite(at.acceleration).all()
    assert at.amplification[0] == pytest.approx(
        0.5 * (below.amplification[0] + above.amplification[0]), rel=1e-6
    )
    np.testing.assert_allclose(at.deflection, below.deflection, atol=1e-6 * np.abs(at.deflection).max())


def _force_by_force(beam, speed, axles, time, x):
    """The closed form of raildyn.bridge._kernel.superpose evaluated axle by axle, mode by mode, in numpy.

    Mode j under a unit modal load sin Ωs while on the span (0 ≤ s = t − τ ≤ T):
    q = a sin Ωs + b cos Ωs + Re{(c − id) e^{λs}}, then Re{C_e e^{λ(s − T)}} from its state at exit.
    """
    L, v, zeta = beam.span, speed, beam.damping_ratio
    T = L / v
    total = np.zeros_like(time)
    second = np.zeros_like(time)
    for j, w in enumerate(2 * np.pi * beam.frequencies_hz, start=1):
        wd, Om = w * np.sqrt(1 - zeta**2), j * np.pi * v / L
        den = (w * w - Om * Om) ** 2 + (2 * zeta * w * Om) ** 2
        a, b = (w * w - Om * Om) / den, -2 * zeta * w * Om / den
        c, lam = -b, complex(-zeta * w, wd)
        d = (zeta * w * c - a * Om) / wd
        cf = complex(c, -d)
        q_end = a * np.sin(Om * T) + b * np.cos(Om * T) + (cf * np.exp(lam * T)).real
        qd_end = a * Om * np.cos(Om * T) - b * Om * np.sin(Om * T) + (lam * cf * np.exp(lam * T)).real
        ce = complex(q_end, -(qd_end + zeta * w * q_end) / wd)
        shape = 2 / (beam.mass_per_length * L) * np.sin(j * np.pi * x / L)
        for tau, P in zip(axles.positions / v, axles.loads, strict=True):
            s = time - tau
            on, off = (s >= 0) & (s < T), s >= T
            harmonic = a * np.sin(Om * s) + b * np.cos(Om * s)
            q = np.where(on, harmonic + (cf * np.exp(lam * s)).real, 0.0)
            q += np.where(off, (ce * np.exp(lam * (s - T))).real, 0.0)
            qdd = np.where(on, -Om * Om * harmonic + (lam**2 * cf * np.exp(lam * s)).real, 0.0)
            qdd += np.where(off, (lam**2 * ce * np.exp(lam * (s - T))).real, 0.0)
            total += P * shape * q
            second += P * shape * qdd
    return total, second


@pytest.mark.parametrize(
    ("speed", "samples", "damping", "coaches"),
    # the last: 10 samples over 11 crossing times, so axles come on and go off within one step
    [(30.0, 3001, 0.01, 6), (80.0, 400, 0.0, 6), (15.0, 10, 0.05, 10)],
)
def test_a_train_is_the_sum_of_its_axles_closed_forms(speed, samples, damping, coaches):
    # superpose carries the axles on the span and those gone as running phasors; summed axle by axle
    # here, the same numbers to round-off (1e-11 of the largest).
    from raildyn.bridge.trains import regular_train

    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=3, damping_ratio=damping)
    axles = regular_train(coaches, 18.0, 2.5, 1.7e5)
    r = moving_force_response(beam, speed, axles, samples=samples)
    deflection, acceleration = _force_by_force(beam, speed, axles, r.time[0], 10.0)
    for mine, theirs in ((r.deflection[0], deflection), (r.acceleration[0], acceleration)):
        np.testing.assert_allclose(mine, theirs, rtol=0, atol=1e-11 * np.abs(theirs).max())
