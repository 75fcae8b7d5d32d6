"""Tests for the vertical passenger car and the track-response layer (raildyn.vehicles.vertical, .response).

Tiers: closed forms (static deflection, the decoupled bounce/pitch 2-DOF
frequencies, wheelbase-filter zeros), an independent computation (frequency-
domain RMS against a long lsim run over a synthesized track; batched speeds
against one speed at a time), hypothesis properties and bad input.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn import track
from raildyn.constants import GRAVITY, STANDARD_RAIL_SPACING
from raildyn.vehicles import MANCHESTER_CAR
from raildyn.vehicles import response as resp
from raildyn.vehicles.vertical import MANCHESTER_VERTICAL, VerticalCar
from raildyn.vibration import modal_analysis

G = GRAVITY
CAR = MANCHESTER_VERTICAL
FRA4 = track.track_psd("fra", "vertical", 4)
FRA4_ALIGNMENT = track.track_psd("fra", "alignment", 4)
FRA4_CROSS_LEVEL = track.track_psd("fra", "cross_level", 4)


def test_defaults_are_the_manchester_vehicle():
    # Iwnicki 1998: 32 t body, 2615 kg frames, 2.56 m wheelbase, 19 m bogie centres
    assert (CAR.body_mass, CAR.bogie_mass) == (32000.0, 2615.0)
    assert 2 * CAR.semi_wheelbase == pytest.approx(2.56)
    assert 2 * CAR.semi_bogie_spacing == pytest.approx(19.0)
    np.testing.assert_allclose(CAR.axle_positions, [0, 2.56, 19.0, 21.56])


def test_static_deflection_matches_hand_calculation():
    v = CAR.linear_system()
    q = v.static_deflection()
    ks, kp = CAR.secondary_stiffness, CAR.primary_stiffness
    # each bogie carries half the body on one secondary set and (half body + frame) on two wheelsets
    bogie = (CAR.body_mass / 2 + CAR.bogie_mass) * G / (2 * kp)
    body = bogie + CAR.body_mass / 2 * G / ks
    # a linear solve of a well-conditioned 6×6 system: rounding only
    np.testing.assert_allclose(q[[0, 2, 4]], [-body, -bogie, -bogie], rtol=1e-12)
    np.testing.assert_allclose(q[[1, 3, 5]], 0.0, atol=1e-15)


def _two_dof(m1, k1, m2, k2):
    """ω² of m1 on k1 on m2 on k2 (ground): roots of the characteristic quadratic, written out."""
    a = m1 * m2
    b = -(m1 * (k1 + k2) + m2 * k1)
    c = k1 * k2
    disc = np.sqrt(b * b - 4 * a * c)
    return np.sort([(-b - disc) / (2 * a), (-b + disc) / (2 * a)])


def test_undamped_frequencies_match_closed_forms():
    v = CAR.linear_system()
    got = np.sort(modal_analysis(v.M, v.K).natural_frequencies) ** 2
    ks, kp, s, b = CAR.secondary_stiffness, CAR.primary_stiffness, CAR.semi_bogie_spacing, CAR.semi_wheelbase
    mb, Ib = CAR.bogie_mass, CAR.bogie_pitch_inertia
    # bounce: body on 2ks over both frames (2mb) on 4kp; pitch: body inertia on 2ks s² over frames
    # moving ∓ (s·θ each, mass 2 mb s²) on 4kp s²; each frame's pitch alone on 2kp b² (twice).
    bounce = _two_dof(CAR.body_mass, 2 * ks, 2 * mb, 4 * kp)
    pitch = _two_dof(CAR.body_pitch_inertia, 2 * ks * s**2, 2 * mb * s**2, 4 * kp * s**2)
    frame_pitch = 2 * kp * b**2 / Ib
    want = np.sort(np.concatenate([bounce, pitch, [frame_pitch, frame_pitch]]))
    # eigenvalues of a symmetric pencil against a quadratic formula: rounding only
    np.testing.assert_allclose(got, want, rtol=1e-9)


def test_body_frequencies_on_a_rigid_primary():
    stiff = CAR.replace(primary_stiffness=1e13)
    v = stiff.linear_system()
    got = np.sort(modal_analysis(v.M, v.K).natural_frequencies)[:2] / (2 * np.pi)
    want = stiff.body_frequencies()
    # the primary 5 × 10⁶ times stiffer than the secondary shifts them by ~1e-7 relative
    np.testing.assert_allclose(got, sorted([want.bounce_hz, want.pitch_hz]), rtol=1e-6)


@pytest.mark.parametrize("speed", [20.0, 45.0])
def test_wheelbase_filter_zeros(speed):
    """Body bounce sees (1 + e^{-iω2b/V})(1 + e^{-iω2l/V}): zero where λ = 4b/(2n+1) or 4l/(2n+1)."""
    v = CAR.linear_system()
    b, s = CAR.semi_wheelbase, CAR.semi_bogie_spacing
    lam = np.array([4 * b, 4 * b / 3, 4 * s / 3, 4 * s / 5])
    omega = 2 * np.pi * speed / lam
    H = resp.track_frf(v, omega, speed, "body z", derivative=0)
    scale = np.abs(resp.track_frf(v, np.linspace(1, 100, 500), speed, "body z")).max()
    # exact cancellation of equal complex numbers: rounding of the phase terms, ~1e-15
    assert np.abs(H).max() < 1e-12 * scale
    # and bogie pitch (front bogie) sees 1 − e^{-iω2b/V}: zero at λ = 2b/n
    Hp = resp.track_frf(v, 2 * np.pi * speed / np.array([2 * b, b]), speed, "bogie1 θ")
    assert np.abs(Hp).max() < 1e-12 * np.abs(resp.track_frf(v, omega, speed, "bogie1 θ")).max()


def test_low_frequency_body_follows_the_track():
    v = CAR.linear_system()
    H = resp.track_frf(v, np.array([1e-4]), 30.0, "body z")
    # quasi-static: body height = mean of four equal wheel heights; error O(ω) ~ 1e-5
    assert abs(H[0] - 1.0) < 1e-3


def test_response_spectrum_equals_track_frf_squared():
    v = CAR.linear_system()
    w = np.linspace(0.5, 150.0, 800)
    V = 33.0
    spec = resp.response_spectrum(v, FRA4, V, w, "body z", derivative=2)
    H = resp.track_frf(v, w, V, "body z", derivative=2)
    direct = np.abs(H) ** 2 * FRA4(w / V) / V
    # two algebraically equal routes (CSD matrix vs summed FRF): rounding only, relative to the
    # peak (near the filter zeros the sum cancels and the relative error of each route grows)
    np.testing.assert_allclose(spec.psd, direct, rtol=1e-8, atol=1e-12 * direct.max())
    batched = resp.rms_over_speeds(v, FRA4, np.array([V, 20.0]), w, "body z", derivative=2)
    assert batched[0] == pytest.approx(spec.rms, rel=1e-12)


def test_frequency_domain_rms_matches_long_time_domain_run():
    """Body acceleration RMS: ∫|H|²S dω against lsim over a synthesized class-4 track.

    The synthesized sample (period 2000 m) holds exactly the band variance with random
    phases; over one whole period of steady state the mean square of the response is
    Σ|H(ω_k)|² G_k ΔΩ exactly, so the two differ only by the line sum's quadrature of the
    integral (ΔΩ = 3 mrad/m against a resonance 50 mrad/m wide: < 1 %) and lsim's
    first-order hold of the 0.1 m samples (< 0.5 % for 3 m waves); tolerance 1 % (seen: 0.03 %).
    """
    V, L, dx, band = 30.0, 2000.0, 0.1, (3.0, 200.0)
    sample = track.synthesize_irregularity(FRA4, L, dx, band, rng=7)
    z = sample.z[0] if sample.z.ndim == 2 else sample.z
    n = z.size
    slope = np.fft.irfft(1j * 2 * np.pi * np.fft.rfftfreq(n, dx) * np.fft.rfft(z), n=n)
    xs = np.arange(n) * dx

    def periodic(values):
        return lambda x, rails: np.interp(np.mod(x, L), xs, values, period=L)

    v = CAR.linear_system()
    dt = 0.004
    settle = 30.0  # s: the slowest mode decays by e^{-ζωt} ≈ e^{-0.1·6.7·30} ≈ 2e-9
    t = np.arange(0.0, settle + L / V, dt)
    run = resp.time_response(v, periodic(z), V, t, "body z", derivative=2, profile_rate=periodic(slope))
    tail = run.y[t >= settle]
    td = np.sqrt(np.mean(tail**2))
    lo, hi = track.wavelength_band(band)
    w = np.linspace(V * lo, V * hi, 4000)
    fd = resp.response_spectrum(v, FRA4, V, w, "body z", derivative=2).rms
    assert td == pytest.approx(fd, rel=0.01)


@settings(max_examples=50, deadline=None)
@given(
    speed=st.floats(5.0, 80.0),
    ks=st.floats(2e5, 3e6),
    cs=st.floats(0.0, 1e5),
)
def test_property_rms_positive_and_cross_level_gives_no_vertical(speed, ks, cs):
    car = CAR.replace(secondary_stiffness=ks, secondary_damping=cs)
    v = car.linear_system()
    w = np.linspace(1.0, 100.0, 200)
    spec = resp.response_spectrum(v, FRA4, speed, w, "body z")
    assert spec.rms > 0 and np.all(spec.psd >= 0)
    # the vertical model has all inputs on the centreline: cross-level cannot excite it, and a
    # cross-level spectrum is refused rather than answered with a zero
    with pytest.raises(ValueError, match="component 'cross_level' is not an input of this vehicle"):
        resp.response_spectrum(v, FRA4_CROSS_LEVEL, speed, w, "body z", component="cross_level")


def test_bad_input():
    with pytest.raises(ValueError, match="body_mass"):
        VerticalCar(body_mass=-1.0)
    with pytest.raises(ValueError, match="primary_damping"):
        VerticalCar(primary_damping=-5.0)
    with pytest.raises(ValueError, match="semi_wheelbase"):
        VerticalCar(semi_wheelbase=20.0)
    v = CAR.linear_system()
    with pytest.raises(ValueError, match="output"):
        v.axle_frf([1.0], 30.0, "roof z")
    with pytest.raises(ValueError, match="derivative"):
        v.axle_frf([1.0], 30.0, "body z", 3)
    with pytest.raises(ValueError, match="speed"):
        resp.response_spectrum(v, FRA4, -1.0, [1.0, 2.0])
    with pytest.raises(ValueError, match="omega"):
        resp.response_spectrum(v, FRA4, 10.0, [0.0, 2.0])
    with pytest.raises(ValueError, match="component"):
        resp.track_frf(v, [1.0], 10.0, component="gauge")
    with pytest.raises(ValueError, match="t must be uniformly"):
        resp.time_response(v, lambda x, r: 0 * x, 10.0, [0.0, 0.1, 0.3])


def test_callbacks_are_checked_where_they_are_used():
    """Issue 15: a spectrum or a track profile returning NaN, a negative PSD or the wrong shape passed
    straight through rms_over_speeds and time_response."""
    w = np.linspace(1.0, 60.0, 12)
    speeds = np.array([20.0, 30.0])
    for bad, what in (
        (lambda W: np.full_like(W, np.nan), "non-finite"),
        (lambda W: -FRA4(W), ">= 0"),
        (lambda W: np.stack([FRA4(W)] * 2), "shape"),
    ):
        with pytest.raises(ValueError, match=f"psd.*{what}"):
            resp.rms_over_speeds(CAR, bad, speeds, w, component="vertical")
        with pytest.raises(ValueError, match=f"psd.*{what}"):
            resp.response_spectrum(CAR, bad, 30.0, w, component="vertical")
    with pytest.raises(ValueError, match=r"psd\['alignment'\] returned a non-finite"):
        resp.rms_over_speeds(MANCHESTER_CAR, {"alignment": lambda W: W * np.nan}, speeds, w, "body y")
    t = np.linspace(0.0, 0.5, 26)
    with pytest.raises(ValueError, match="profile returned a non-finite"):
        resp.time_response(CAR, lambda x, r: x * np.nan, 30.0, t)
    with pytest.raises(ValueError, match="profile_rate must return an array of shape"):
        resp.time_response(CAR, lambda x, r: 0 * x, 30.0, t, profile_rate=lambda x, r: x[:, 0])
    with pytest.raises(TypeError, match="profile must be a callable"):
        resp.time_response(CAR, 0.01, 30.0, t)
    # a track below the mean line is a track: negative heights pass
    run = resp.time_response(CAR, lambda x, r: -0.01 - 0 * x, 30.0, t)
    assert np.all(np.isfinite(run.y))


def test_arguments_that_are_not_models_are_refused_by_name():
    w = np.array([1.0, 2.0])
    with pytest.raises(TypeError, match="vehicle must be a linear model"):
        resp.track_frf("car", w, 30.0)
    with pytest.raises(TypeError, match="vehicle must be a linear model"):
        resp.rms_over_speeds(None, FRA4, [30.0], w)
    with pytest.raises(ValueError, match="omega must be at most"):
        resp.track_frf(CAR, [1.0, 1e300], 30.0)
    with pytest.raises(ValueError, match="omega must not be empty"):
        resp.rms_over_speeds(CAR, FRA4, [30.0], [])


def test_results_and_profiles_validate_their_fields():
    with pytest.raises(ValueError, match="psd must be >= 0"):
        resp.ResponseSpectrum(np.array([1.0, 2.0]), np.array([1.0, -1.0]), 1.0, 30.0)
    with pytest.raises(ValueError, match="y must have shape"):
        resp.TimeResponse(np.array([0.0, 0.1]), np.zeros(3), np.zeros((2, 4)))
    with pytest.raises(ValueError, match="dx must be"):
        resp.PeriodicProfile(np.zeros(8), 0.0)
    with pytest.raises(ValueError, match="height must not be empty"):
        resp.periodic_profile([], 0.5)
    # the slope is derived from the heights, never given apart from them
    z = 0.01 * np.sin(2 * np.pi * np.arange(16) / 16)
    profile = resp.PeriodicProfile(z, 0.5)
    np.testing.assert_allclose(profile.slopes, resp.periodic_profile(z, 0.5).slopes)
    with pytest.raises(ValueError, match="x must contain only finite"):
        profile.height(np.array([np.nan]))
    with pytest.raises(TypeError, match="rails must be"):
        profile.slope(np.array([1.0]), "left")


# --------------------------------------------------------------------------- lateral car on the track


def test_lateral_car_follows_long_alignment():
    from raildyn.vehicles import MANCHESTER_CAR

    v = MANCHESTER_CAR.linear_system()
    w = np.array([1e-4])
    # a very long alignment wave is followed rigidly: every body moves with the track, nothing rolls;
    # the deviation is O(ω) ~ 1e-4 relative
    for label in ("body y", "frame1 y", "wheelset22 y"):
        H = resp.track_frf(v, w, 30.0, label, component="alignment")
        assert abs(H[0] - 1.0) < 1e-3
    assert abs(resp.track_frf(v, w, 30.0, "body φ", component="alignment")[0]) < 1e-3
    # the lateral car has no vertical input, the vertical car no alignment: refused, not a zero FRF
    with pytest.raises(ValueError, match="component 'vertical' is not an input of this vehicle"):
        resp.track_frf(v, w, 30.0, "body y", component="vertical")
    with pytest.raises(ValueError, match="component 'alignment' is not an input of this vehicle"):
        resp.track_frf(CAR.linear_system(), w, 30.0, "body z", component="alignment")


def test_lateral_car_static_cross_level_balances_the_rail_forces():
    """A constant cross-level c: K q = G_K c. The suspension forces are internal, so the lateral
    wheel–rail forces on the four wheelsets must add to zero:
    Σ [−(Wε/a − 2f₂₃ε/(a r₀)) y + 2f₂₂ψ − W c/(2a_r)] = 0, the gravitational stiffness less the spin of the
    contact-angle difference."""
    from raildyn.vehicles import MANCHESTER_CAR

    v = MANCHESTER_CAR.linear_system()
    c = 0.01
    q = np.linalg.solve(v.K, v.GK[:, 4:] @ np.full(4, c))
    ws = MANCHESTER_CAR.wheelset
    push = -ws.axle_load * c / STANDARD_RAIL_SPACING  # the rails rolled by Δz/(2a_r)
    total = 0.0
    for b in "12":
        for k in "12":
            y, psi = q[v.labels.index(f"wheelset{b}{k} y")], q[v.labels.index(f"wheelset{b}{k} ψ")]
            eps, a = ws.contact_angle_parameter, ws.half_gauge
            lateral = ws.axle_load * eps / a - 2 * ws.f23 * eps / (a * ws.rolling_radius)
            total += -lateral * y + 2 * ws.f22 * psi + push
    # a 15×15 solve with creep coefficients ~10⁷ against pushes ~10³ N: rounding, 1e-6 of the push
    assert total == pytest.approx(0.0, abs=1e-6 * abs(4 * push))
    assert abs(q[v.labels.index("body φ")]) > 0


def test_lateral_car_above_critical_speed_is_refused():
    from raildyn.vehicles import MANCHESTER_CAR

    w = np.linspace(1.0, 60.0, 20)
    with pytest.raises(ValueError, match="critical speed"):
        resp.response_spectrum(MANCHESTER_CAR, FRA4_ALIGNMENT, 150.0, w, "body y", component="alignment")
    with pytest.raises(ValueError, match="critical speed"):
        resp.track_frf(MANCHESTER_CAR, w, 150.0, "body y", component="alignment")


def _lateral_rms_at(car, speed):
    """Lateral body acceleration RMS (m/s²) of a car to class-4 alignment, one matrix solve per ω:
    the reference of the two tests below, written from the car's matrices at ``speed``."""
    w = np.linspace(0.5, 120.0, 1500)
    mats = car.matrices(speed)
    system = car.linear_system()
    Z = mats.K - w[:, None, None] ** 2 * mats.M + 1j * w[:, None, None] * mats.C
    X = np.linalg.solve(Z, mats.GK + 1j * w[:, None, None] * mats.GC)  # (n_ω, n, q)
    tau = system.input_positions / speed
    alignment = np.array([kind == "alignment" for kind in system.input_kinds], dtype=float)
    i = system.labels.index("body y")
    H = -(w**2) * np.sum(X[:, i, :] * alignment * np.exp(-1j * w[:, None] * tau), axis=1)
    S = np.abs(H) ** 2 * FRA4_ALIGNMENT(w / speed) / speed
    return float(np.sqrt(np.trapezoid(S, w))), w


def test_speed_is_given_once_and_reaches_the_creep_damping():
    """Wrong answer fixed (issue 14): a lateral car built at 20 m/s and evaluated at 40 m/s gave
    the RMS of the 20 m/s creep damping (0.244 m/s² instead of 0.391). The speed now enters in one
    place, the call, and both the delays and the creep damping C₁/V follow it. Reference: the same
    sum from the car's own matrices at 40 m/s, on the same grid (so 1e-9, rounding only)."""
    from raildyn.vehicles import MANCHESTER_CAR

    want, w = _lateral_rms_at(MANCHESTER_CAR, 40.0)
    got = resp.response_spectrum(MANCHESTER_CAR, FRA4_ALIGNMENT, 40.0, w, "body y", component="alignment").rms
    assert got == pytest.approx(want, rel=1e-9)
    slow, _ = _lateral_rms_at(MANCHESTER_CAR, 20.0)
    # the creep damping matters: at 20 m/s the same sum differs by far more than the tolerance
    assert abs(slow - want) > 0.1 * want


def test_rms_over_speeds_honours_the_input_kinds():
    """Wrong answer fixed (issue 14): rms_over_speeds ignored the inputs' kinds, so on the lateral car
    it mixed alignment and cross-level inputs into one process (0.083 against 0.154). It now gives
    response_spectrum's RMS at every speed (rel 1e-12: the same computation) and the reference."""
    from raildyn.vehicles import MANCHESTER_CAR

    speeds = np.array([25.0, 40.0])
    want, w = _lateral_rms_at(MANCHESTER_CAR, 40.0)
    S = FRA4_ALIGNMENT
    rms = resp.rms_over_speeds(MANCHESTER_CAR, S, speeds, w, "body y", component="alignment")
    for V, r in zip(speeds, rms, strict=True):
        assert r == pytest.approx(
            resp.response_spectrum(MANCHESTER_CAR, S, V, w, "body y", component="alignment").rms, rel=1e-12
        )
    assert rms[1] == pytest.approx(want, rel=1e-9)


def test_independent_components_add_their_response_spectra():
    """Alignment and cross-level are independent processes: the spectrum for both is the sum of the
    two spectra (exactly, rel 1e-12), and neither input kind leaks into the other's response."""
    from raildyn.vehicles import MANCHESTER_CAR

    w = np.linspace(1.0, 80.0, 200)
    Sa, Sc = FRA4_ALIGNMENT, FRA4_CROSS_LEVEL
    both = resp.response_spectrum(MANCHESTER_CAR, {"alignment": Sa, "cross_level": Sc}, 30.0, w, "body y")
    a = resp.response_spectrum(MANCHESTER_CAR, Sa, 30.0, w, "body y", component="alignment")
    c = resp.response_spectrum(MANCHESTER_CAR, Sc, 30.0, w, "body y", component="cross_level")
    np.testing.assert_allclose(both.psd, a.psd + c.psd, rtol=1e-12)
    assert a.rms > 0 and c.rms > 0


def test_time_response_to_a_sinusoid_matches_the_frf():
    """Deterministic input: a 25 m sinusoid at 30 m/s; the steady amplitude of the body acceleration
    equals |H(ω)|·A. lsim holds the input linearly between 2 ms samples of a 0.83 s period wave:
    error ~ (ωΔt)²/12 ≈ 1e-5; the transient has decayed by e^{-ζω t} < 1e-6 after 30 s; 1e-3."""
    V, lam, A = 30.0, 25.0, 0.005
    omega = 2 * np.pi * V / lam
    t = np.arange(0.0, 40.0, 0.002)
    run = resp.time_response(
        CAR.linear_system(),
        lambda x, r: track.sinusoid(x, A, lam),
        V,
        t,
        "body z",
        derivative=2,
        profile_rate=lambda x, r: track.sinusoid(x, A, lam, derivative=1),
    )
    tail = run.y[t >= 30.0]
    H = resp.track_frf(CAR.linear_system(), np.array([omega]), V, "body z", derivative=2)[0]
    assert 0.5 * (tail.max() - tail.min()) == pytest.approx(abs(H) * A, rel=1e-3)


def test_periodic_profile_slope_is_the_exact_derivative_and_repeats():
    from raildyn.vehicles import periodic_profile

    dx, n = 0.25, 400  # one 100 m period
    x = np.arange(n) * dx
    z = 0.003 * np.sin(2 * np.pi * x / 20.0) + 0.001 * np.cos(2 * np.pi * x / 12.5)
    sample = periodic_profile(z, dx)
    profile, slope = sample.height, sample.slope
    exact = 0.003 * 2 * np.pi / 20.0 * np.cos(2 * np.pi * x / 20.0) - 0.001 * 2 * np.pi / 12.5 * np.sin(
        2 * np.pi * x / 12.5
    )
    # Whole numbers of periods: the Fourier derivative is exact to rounding (1e-15 of the slope).
    assert np.allclose(slope(x, None), exact, rtol=0, atol=1e-15)
    assert np.allclose(profile(x + n * dx, None), z, rtol=0, atol=1e-15)


def test_every_manchester_inertia_turns_about_its_own_axis():
    """Wrong answer fixed (issue 14): the vertical car's bogie pitch inertia was the frame's roll
    inertia (1722 kg·m², about x). Iwnicki (1998) gives the frame 1722 about x (roll), 1476 about y
    (pitch) and 3067 kg·m² about z (yaw); the body 5.68 × 10⁴ (x), 1.97 × 10⁶ (y) and 1.97 × 10⁶
    (z); the wheelset 1120 about z. Each model takes the inertia of the axis its coordinate turns
    about. (D. Cantero's TTB-2D, TrainProp_Manchester_BenchMark.m, takes 1476 for the bogie in the
    vertical plane too.) Exact values: ==."""
    from raildyn.vehicles import MANCHESTER_CAR

    frame_x, frame_y, frame_z = 1722.0, 1476.0, 3067.0
    body_x, body_y, body_z = 5.68e4, 1.97e6, 1.97e6
    assert MANCHESTER_VERTICAL.bogie_pitch_inertia == frame_y  # "bogie θ": pitch, about y
    assert MANCHESTER_VERTICAL.body_pitch_inertia == body_y
    assert MANCHESTER_CAR.bogie.frame_yaw_inertia == frame_z  # "frame ψ": yaw, about z
    assert MANCHESTER_CAR.body_yaw_inertia == body_z
    assert MANCHESTER_CAR.body_roll_inertia == body_x  # "body φ": roll, about x
    assert MANCHESTER_CAR.wheelset.yaw_inertia == 1120.0
    assert frame_x not in (MANCHESTER_VERTICAL.bogie_pitch_inertia, MANCHESTER_CAR.bogie.frame_yaw_inertia)
    # and the matrix carries it on the bogie's pitch coordinates
    M = MANCHESTER_VERTICAL.linear_system().M
    for label in ("bogie1 θ", "bogie2 θ"):
        i = MANCHESTER_VERTICAL.linear_system().labels.index(label)
        assert M[i, i] == frame_y


def test_response_spectrum_plot_draws_the_psd_per_hz_and_moves_in_place():
    """The chart of figure 6.ride and the ride widget: PSD per Hz = 2π × PSD per rad/s (the
    package's conversion; exact), against f = ω/2π; a second spectrum moves the same line."""
    import matplotlib.pyplot as plt

    w = np.linspace(1.0, 100.0, 50)
    slow = resp.response_spectrum(CAR, FRA4, 20.0, w)
    fast = resp.response_spectrum(CAR, FRA4, 40.0, w)
    fig, ax = plt.subplots()
    artists = slow.plot(ax)
    x, y = artists["line"].get_data()
    np.testing.assert_allclose(x, w / (2 * np.pi), rtol=1e-15)
    np.testing.assert_allclose(y, 2 * np.pi * slow.psd, rtol=1e-15)
    line = artists["line"]
    assert fast.plot(artists=artists)["line"] is line
    np.testing.assert_allclose(line.get_ydata(), 2 * np.pi * fast.psd, rtol=1e-15)
    plt.close(fig)
