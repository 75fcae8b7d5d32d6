"""raildyn.vehicles.response: the compiled time stepping against scipy.signal.lsim, its reference; the
spectra a response takes, each of which must say what it describes."""

import numpy as np
import pytest
from scipy import signal

from raildyn import track
from raildyn.vehicles import (
    MANCHESTER_CAR,
    MANCHESTER_VERTICAL,
    VerticalFreightCar,
    periodic_profile,
    response_spectrum,
    rms_over_speeds,
    time_domain,
    time_response,
    track_frf,
)


def _stable_system(rng, n, m):
    """A random stable state-space system: a shifted random A (every eigenvalue in the left half-plane)."""
    A = rng.normal(size=(n, n))
    A -= (np.linalg.eigvals(A).real.max() + 0.5) * np.eye(n)
    return A, rng.normal(size=(n, m)), rng.normal(size=(1, n)), rng.normal(size=(1, m))


@pytest.mark.parametrize("seed", range(4))
def test_first_order_hold_equals_lsim(seed):
    """Same matrix exponential and recurrence as lsim's interp=True: equal to round-off (1e-12 of the peak).

    The recurrence sums in another order than lsim's matrix products; over 2,000 steps of a stable
    system the differences stay at a few ulps of the largest state.
    """
    rng = np.random.default_rng(seed)
    n, m = rng.integers(1, 13), rng.integers(1, 9)
    A, B, C, D = _stable_system(rng, n, m)
    t = np.arange(2000) * 0.01
    U = np.cumsum(rng.normal(size=(t.size, m)), axis=0)
    reference = signal.lsim((A, B, C, D), U, t)[1]
    ours = time_domain._lsim(A, B, C, D, U, 0.01)
    assert np.abs(ours - reference).max() <= 1e-12 * np.abs(reference).max()


def test_one_sample_is_the_output_at_rest():
    rng = np.random.default_rng(7)
    A, B, C, D = _stable_system(rng, 3, 2)
    U = rng.normal(size=(1, 2))
    np.testing.assert_allclose(time_domain._lsim(A, B, C, D, U, 0.0), U @ D[0], rtol=1e-15)


@pytest.mark.parametrize("derivative", [0, 1, 2])
def test_time_response_equals_lsim_on_a_track(derivative):
    """The whole of time_response, its input terms and output rows, against lsim on the same system."""
    rng = np.random.default_rng(derivative)
    track = periodic_profile(1e-3 * rng.normal(size=400), 0.25)
    V, t = 30.0, np.arange(0.0, 4.0, 0.01)
    ours = time_response(MANCHESTER_VERTICAL, track.height, V, t, "body z", derivative, track.slope)
    system = MANCHESTER_VERTICAL.linear_system()
    n, mats = system.size, system.matrices(V)
    A = mats.state_matrix()
    B = np.vstack(
        [np.zeros((n, 2 * system.n_inputs)), np.linalg.solve(mats.M, np.hstack([mats.GK, mats.GC]))]
    )
    o = system.output_vector("body z")
    C = [np.concatenate([o, np.zeros(n)]), np.concatenate([np.zeros(n), o]), o @ A[n:]][derivative]
    D = o @ B[n:] if derivative == 2 else np.zeros(B.shape[1])
    x = V * t[:, None] - system.input_positions[None, :]
    U = np.hstack([track.height(x), V * track.slope(x)])
    reference = signal.lsim((A, B, C[None, :], D[None, :]), U, t)[1]
    assert np.abs(ours.y - reference).max() <= 1e-12 * np.abs(reference).max()


# ------------------------------------------------------------------------ a spectrum says what it describes

W_RIDE = np.linspace(0.2, 2 * np.pi * 30.0, 3000)  # rad/s, the ride grid of chapter 6
ALIGNMENT = track.track_psd("fra", "alignment", 4)


def test_an_alignment_spectrum_drives_the_lateral_car_without_component():
    """Wrong answer fixed: the lateral car given an alignment spectrum without component= took it for a
    vertical profile, which it has no input for, and returned an RMS of 0.0. The spectrum now names its
    component: the answer is the one component="alignment" gives with a plain callable (the same
    computation, so rel 1e-12), and it is not zero."""
    own = response_spectrum(MANCHESTER_CAR, ALIGNMENT, 30.0, W_RIDE, "body y")
    plain = response_spectrum(
        MANCHESTER_CAR,
        lambda W: track.fra_psd("alignment", 4, W),
        30.0,
        W_RIDE,
        "body y",
        component="alignment",
    )
    assert own.rms > 0.1  # m/s², a lateral ride on class-4 alignment (0.247 here), far from a silent zero
    assert own.rms == pytest.approx(plain.rms, rel=1e-12)
    speeds = np.array([20.0, 30.0])
    np.testing.assert_allclose(
        rms_over_speeds(MANCHESTER_CAR, ALIGNMENT, speeds, W_RIDE, "body y"),
        rms_over_speeds(MANCHESTER_CAR, ALIGNMENT, speeds, W_RIDE, "body y", component="alignment"),
        rtol=1e-12,
    )


def test_the_vertical_car_refuses_an_alignment_it_has_no_input_for():
    """Wrong answers fixed: the vertical car given an alignment spectrum returned 0.0 with
    component="alignment" and, without component=, took it for a vertical profile (RMS 0.394 m/s²).
    Both are refused, each naming the parameter that gave the component, in both functions."""
    for call in (response_spectrum, rms_over_speeds):
        speed = 30.0 if call is response_spectrum else [30.0]
        with pytest.raises(ValueError, match=r"^component 'alignment' is not an input of this vehicle"):
            call(MANCHESTER_VERTICAL, ALIGNMENT, speed, W_RIDE, component="alignment")
        with pytest.raises(ValueError, match=r"^psd describes the 'alignment' component, not an input"):
            call(MANCHESTER_VERTICAL, ALIGNMENT, speed, W_RIDE)
        with pytest.raises(ValueError, match=r"allowed components: \['vertical'\]"):
            call(MANCHESTER_VERTICAL, ALIGNMENT, speed, W_RIDE)
        # a mapping keyed by a component the car has no input for: the same refusal, blamed on psd
        with pytest.raises(ValueError, match=r"^psd describes the 'alignment' component"):
            call(MANCHESTER_VERTICAL, {"alignment": ALIGNMENT}, speed, W_RIDE)


def test_a_spectrum_whose_component_is_unstated_or_contradicted_is_refused():
    plain = lambda W: track.fra_psd("vertical", 4, W)  # noqa: E731
    for call, speed in ((response_spectrum, 30.0), (rms_over_speeds, [30.0])):
        with pytest.raises(
            ValueError, match=r"^psd does not say which irregularity it describes: give component="
        ):
            call(MANCHESTER_VERTICAL, plain, speed, W_RIDE)
        with pytest.raises(
            ValueError, match=r"^component 'vertical' contradicts psd, a spectrum of the 'alignment'"
        ):
            call(MANCHESTER_CAR, ALIGNMENT, speed, W_RIDE, "body y", component="vertical")
        with pytest.raises(
            ValueError, match=r"^psd is a spectrum of the 'gauge' component, which no vehicle"
        ):
            call(MANCHESTER_CAR, track.track_psd("fra", "gauge", 4), speed, W_RIDE, "body y")
        with pytest.raises(
            ValueError, match=r"^psd\['cross_level'\] is a spectrum of the 'alignment' component"
        ):
            call(MANCHESTER_CAR, {"cross_level": ALIGNMENT}, speed, W_RIDE, "body y")
    # a spectrum that repeats its own component, and a plain one that states it, are taken as they are
    vertical = track.track_psd("fra", "vertical", 4)
    stated = response_spectrum(MANCHESTER_VERTICAL, vertical, 30.0, W_RIDE, component="vertical")
    assert stated.rms == response_spectrum(MANCHESTER_VERTICAL, vertical, 30.0, W_RIDE).rms
    assert stated.rms == response_spectrum(MANCHESTER_VERTICAL, plain, 30.0, W_RIDE, component="vertical").rms


def test_track_frf_refuses_a_component_without_inputs():
    """A zero FRF says nothing: the lateral car has no rail-height input, the vertical car no alignment."""
    with pytest.raises(
        ValueError, match=r"^component 'vertical' is not an input .* \['alignment', 'cross_level'\]"
    ):
        track_frf(MANCHESTER_CAR, [1.0], 30.0, "body y")
    with pytest.raises(ValueError, match=r"^component 'cross_level' is not an input of this vehicle"):
        track_frf(MANCHESTER_VERTICAL, [1.0], 30.0, "body z", component="cross_level")
    # the freight car stands on two rails: its rail heights take a cross-level as ±c/2
    assert abs(track_frf(VerticalFreightCar(), [5.0], 10.0, "body φ", component="cross_level")[0]) > 0


def test_track_spectrum_is_the_function_it_names():
    for family, component, grade, fn in (
        ("fra", "cross_level", 3, lambda W: track.fra_psd("cross_level", 3, W)),
        ("german", "alignment", "high", lambda W: track.german_psd("alignment", "high", W)),
    ):
        psd = track.track_psd(family, component, grade)
        assert (psd.family, psd.component, psd.grade) == (family, component, grade)
        W = np.geomspace(0.01, 10.0, 7).reshape(7, 1)
        np.testing.assert_array_equal(psd(W), fn(W))  # the same function: bit for bit
    assert track.track_psd("fra", "vertical", np.int64(4)) == track.TrackSpectrum("fra", "vertical", 4)
    with pytest.raises(ValueError, match=r"^family must be one of \['fra', 'german'\]"):
        track.TrackSpectrum("sncf", "vertical", 4)
    with pytest.raises(ValueError, match=r"^component must be one of"):
        track.TrackSpectrum("fra", "twist", 4)
    with pytest.raises(TypeError, match=r"^grade must be a string, one of \['high', 'low'\]"):
        track.TrackSpectrum("german", "vertical", 4)


def test_a_wavenumber_so_small_that_the_fra_spectrum_overflows_is_refused():
    # S ∝ 1/Ω² towards 0: at Ω = 1e-160 rad/m it exceeds double precision; at 1e-100 it is 1.3e195
    with pytest.raises(ValueError, match=r"^wavenumber must be large enough that S\(Ω\)"):
        track.fra_psd("vertical", 4, [1.0, 1e-160])
    assert np.isfinite(track.fra_psd("alignment", 4, [1e-100])).all()
    # the German spectra stay bounded (flat below Ω_r; the cross-level and gauge vanish) as Ω → 0
    assert np.isfinite(track.german_psd("gauge", "low", [1e-300])).all()


@pytest.mark.parametrize(("speed", "output"), [(20.0, "body z"), (30.0, "body θ")])
def test_a_response_that_cancels_at_a_wheelbase_node_is_not_refused_for_its_rounding(speed, output):
    # FRA class 4 under the Manchester car, 0.05–30 Hz: at these speeds a bogie's or the car's wheelbase
    # filter has a node on the grid, where the response PSD is zero but for rounding (it was refused as a
    # PSD below zero, -4e-23 and -5e-26). At the node the response is within rounding of zero; elsewhere
    # it is positive.
    omega = 2 * np.pi * np.geomspace(0.05, 30.0, 400)
    psd = track.track_psd("fra", "vertical", 4)
    result = response_spectrum(MANCHESTER_VERTICAL, psd, speed, omega, output=output)
    assert np.all(result.psd >= 0.0) and np.count_nonzero(result.psd) >= len(omega) - 2
