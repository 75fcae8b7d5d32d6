"""Linear vehicle models driven by the track: FRFs, response spectra and time histories (chapter 6).

A vehicle on rigid wheel–rail contact is a linear system whose inputs are the
rail heights under its wheels:

    M q'' + C q' + K q = G_K w(t) + G_C w'(t),

q the body coordinates, w the q_in track heights at the wheels. Every spring k
(damper c) acts on a relative displacement d = g·q − h·w, so it adds k g gᵀ to
K and k g hᵀ to G_K (c to C and G_C). Input j is the track met at distance d_j
behind the leading axle: w_j(t) = u(t − τ_j) with τ_j = d_j/V, and on the rail
given by ``input_rails`` (+1 left, −1 right, 0 both: the centreline).

* :class:`LinearVehicle` — the matrices and their inputs;
* :meth:`LinearVehicle.axle_frf` — H_j(ω), (output)/(m of input j), all
  frequencies in one batched solve;
* :func:`track_frf` — H(ω) = Σ_j H_j(ω) e^{−iωτ_j}: from the track met by the
  leading axle to the output;
* :func:`response_spectrum` — response PSD and RMS for a spatial track spectrum
  at speed V (:func:`raildyn.track.synthesis.excitation_csd` and
  :func:`raildyn.random_vibration.response_psd`);
* :func:`time_response` — the history over a track profile by
  ``scipy.signal.lsim``;
* :func:`rms_over_speeds` — RMS at many speeds from one batched FRF solve;
* :func:`lateral_vehicle` — the lateral car of chapter 7 driven by alignment
  and cross-level.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn import random_vibration as rv
from raildyn import track as _track

GRAVITY = 9.81  # m/s²


class _Assembler:
    """M, C, K, G_K, G_C of a vehicle, built spring by spring."""

    def __init__(self, labels, n_inputs):
        self.labels = list(labels)
        n = len(self.labels)
        self.M = np.zeros((n, n))
        self.C = np.zeros((n, n))
        self.K = np.zeros((n, n))
        self.GK = np.zeros((n, n_inputs))
        self.GC = np.zeros((n, n_inputs))

    def vector(self, terms: dict) -> np.ndarray:
        g = np.zeros(len(self.labels))
        for label, value in terms.items():
            g[self.labels.index(label)] += value
        return g

    def mass(self, label, value):
        i = self.labels.index(label)
        self.M[i, i] += value

    def element(self, body: dict, stiffness, damping=0.0, inputs: dict | None = None):
        """A spring and damper on d = Σ body coefficients · q − Σ input coefficients · w."""
        g = self.vector(body)
        self.K += stiffness * np.outer(g, g)
        self.C += damping * np.outer(g, g)
        if inputs:
            h = np.zeros(self.GK.shape[1])
            for j, value in inputs.items():
                h[j] += value
            self.GK += stiffness * np.outer(g, h)
            self.GC += damping * np.outer(g, h)


@dataclass(frozen=True)
class LinearVehicle:
    """A linear vehicle model with track inputs.

    Attributes
    ----------
    M, C, K : ndarray, (n, n)
        kg (kg·m²), N·s/m, N/m (per radian for rotations).
    GK, GC : ndarray, (n, q)
        Forces from the track heights and their rates, N/m and N·s/m.
    labels : tuple of str
        Names of the n coordinates (m or rad).
    input_positions : ndarray, (q,)
        Distance of each input behind the leading axle, m.
    input_rails : ndarray, (q,)
        +1 left rail, −1 right rail, 0 both rails (the centreline).
    gravity_load : ndarray, (n,)
        Generalized weight of the sprung masses, N (down is negative).
    input_kinds : tuple of str or None
        What each input is, when it is not a rail height: "alignment" or
        "cross_level" (m). None: rail heights, by ``input_rails``.
    """

    M: np.ndarray
    C: np.ndarray
    K: np.ndarray
    GK: np.ndarray
    GC: np.ndarray
    labels: tuple
    input_positions: np.ndarray
    input_rails: np.ndarray
    gravity_load: np.ndarray
    input_kinds: tuple | None = None

    @property
    def n(self) -> int:
        return self.M.shape[0]

    def output_vector(self, output) -> np.ndarray:
        """A coordinate label ("body z"), ("body z", x) for the point x m ahead of the centre
        (z + xθ), or a row vector of length n."""
        if isinstance(output, str):
            if output not in self.labels:
                raise ValueError(f"output must be one of {self.labels}; got {output!r}")
            return np.eye(self.n)[self.labels.index(output)]
        if isinstance(output, tuple) and len(output) == 2 and isinstance(output[0], str):
            label, x = output
            base = self.output_vector(label)
            x = _checks.scalar("output position", x)
            pitch = label.rsplit(" ", 1)[0] + " θ"
            if pitch not in self.labels:
                raise ValueError(f"output {label!r} has no pitch coordinate {pitch!r} to place a point")
            return base + x * self.output_vector(pitch)
        return _checks.array("output", output, shape=(self.n,))

    def static_deflection(self) -> np.ndarray:
        """Displacements under gravity, m (rad): K q = weight."""
        return np.linalg.solve(self.K, self.gravity_load)

    def axle_frf(self, omega, output="body z", derivative: int = 0) -> np.ndarray:
        """H_j(ω) from input j (m) to the output (m, m/s or m/s² for derivative 0, 1, 2): shape (n_ω, q).

        One batched solve of (K − ω²M + iωC) X = G_K + iωG_C over all frequencies.
        """
        w = _checks.array("omega", omega, ndim=1, low=0.0)
        d = _checks.integer("derivative", derivative, low=0, high=2)
        o = self.output_vector(output)
        Z = self.K - w[:, None, None] ** 2 * self.M + 1j * w[:, None, None] * self.C
        X = np.linalg.solve(Z, self.GK + 1j * w[:, None, None] * self.GC)
        return (1j * w[:, None]) ** d * np.einsum("i,kij->kj", o, X)


_COMPONENTS = ("vertical", "cross_level", "alignment")


def _rail_weights(vehicle: LinearVehicle, component: str) -> np.ndarray:
    """How an irregularity of the given component reaches each input."""
    if component not in _COMPONENTS:
        raise ValueError(f"component must be one of {_COMPONENTS}; got {component!r}")
    if vehicle.input_kinds is not None:
        return np.array([1.0 if kind == component else 0.0 for kind in vehicle.input_kinds])
    rails = vehicle.input_rails
    if component == "vertical":
        return np.ones(rails.shape)
    if component == "cross_level":  # left − right = c: the left rail at +c/2, the right at −c/2
        return 0.5 * rails
    return np.zeros(rails.shape)


def track_frf(
    vehicle: LinearVehicle, omega, speed, output="body z", derivative: int = 0, component: str = "vertical"
) -> np.ndarray:
    """H(ω) = Σ_j a_j H_j(ω) e^{−iωτ_j}: from the track under the leading axle to the output.

    a_j is 1 for a vertical irregularity and ±1/2 on the left/right rail for cross-level.
    """
    tau = _track.axle_delays(vehicle.input_positions, speed)
    Hj = vehicle.axle_frf(omega, output, derivative)
    w = np.asarray(omega, dtype=float)
    phase = np.exp(-1j * w[:, None] * tau[None, :])
    return np.einsum("kj,j,kj->k", Hj, _rail_weights(vehicle, component), phase)


@dataclass(frozen=True)
class ResponseSpectrum:
    """A response spectrum at one speed.

    Attributes
    ----------
    omega : ndarray
        rad/s.
    psd : ndarray
        One-sided PSD of the output, (unit)²/(rad/s).
    rms : float
        √∫S dω over the grid, in the output unit.
    speed : float
        m/s.
    """

    omega: np.ndarray
    psd: np.ndarray
    rms: float
    speed: float

    @property
    def frequency(self) -> np.ndarray:
        """Hz."""
        return self.omega / (2 * np.pi)


def response_spectrum(
    vehicle: LinearVehicle,
    psd: Callable,
    speed,
    omega,
    output="body z",
    derivative: int = 2,
    component: str = "vertical",
) -> ResponseSpectrum:
    """Response PSD and RMS of an output for a spatial track spectrum S(Ω) (m²/(rad/m)) at speed V.

    The inputs' cross-spectral matrix comes from :func:`raildyn.track.synthesis.excitation_csd`
    and the response from :func:`raildyn.random_vibration.response_psd`.
    """
    V = _checks.positive("speed", speed)
    w = _checks.array("omega", omega, ndim=1, low=0.0, low_open=True)
    a = _rail_weights(vehicle, component)
    H = vehicle.axle_frf(w, output, derivative) * a[None, :]
    S_in = _track.excitation_csd(psd, w, vehicle.input_positions, V)
    S = rv.response_psd(H, S_in)
    return ResponseSpectrum(w, S, float(np.sqrt(rv.mean_square(S, w))), V)


def rms_over_speeds(
    vehicle: LinearVehicle, psd: Callable, speeds, omega, output="body z", derivative: int = 2
) -> np.ndarray:
    """RMS of the output (vertical track) at each speed: the FRFs solved once, for all speeds.

    The axle FRFs do not depend on speed; only the delays and the temporal
    spectrum S(ω/V)/V do, so a speed costs one weighted sum over the grid.
    """
    V = _checks.array("speeds", speeds, ndim=1, low=0.0, low_open=True)
    w = _checks.array("omega", omega, ndim=1, low=0.0, low_open=True)
    Hj = vehicle.axle_frf(w, output, derivative)  # (n_ω, q)
    tau = vehicle.input_positions[None, :] - vehicle.input_positions[0]
    phase = np.exp(-1j * w[None, :, None] * tau[:, None, :] / V[:, None, None])  # (n_V, n_ω, q)
    H = np.einsum("kj,vkj->vk", Hj, phase)
    S = np.abs(H) ** 2 * np.asarray(psd(w[None, :] / V[:, None])) / V[:, None]
    return np.sqrt(np.trapezoid(S, w, axis=1))


@dataclass(frozen=True)
class TimeResponse:
    """A time history.

    Attributes
    ----------
    t : ndarray
        s.
    y : ndarray
        Output (m, m/s or m/s²).
    inputs : ndarray, (n_t, q)
        Track heights at the inputs, m.
    """

    t: np.ndarray
    y: np.ndarray
    inputs: np.ndarray


def periodic_profile(height, dx) -> tuple[Callable, Callable]:
    """A track profile sampled over one period, and its slope, as ``profile(x, rails)`` callables.

    ``height`` (m) is sampled every ``dx`` (m) over exactly one period of length
    n·dx (a synthesized sample is periodic); beyond it the profile repeats. The
    slope is the exact derivative of the sample's Fourier series, so the damper
    inputs of :func:`time_response` carry no finite-difference error. The two
    callables take distances x (m) and ignore ``rails`` (both rails alike).

    >>> z = 0.01 * np.sin(2 * np.pi * np.arange(100) * 0.5 / 25.0)
    >>> profile, slope = periodic_profile(z, 0.5)
    >>> round(float(slope(np.array([0.0]), None)[0]), 6)  # 0.01 · 2π/25
    0.002513
    """
    z = _checks.array("height", height, ndim=1)
    dx = _checks.positive("dx", dx)
    n = z.size
    period = n * dx
    rate = np.fft.irfft(2j * np.pi * np.fft.rfftfreq(n, dx) * np.fft.rfft(z), n=n)
    x = np.arange(n) * dx

    def along(values):
        return lambda xx, rails: np.interp(np.mod(xx, period), x, values, period=period)

    return along(z), along(rate)


def time_response(
    vehicle: LinearVehicle,
    profile: Callable,
    speed,
    t,
    output="body z",
    derivative: int = 0,
    profile_rate: Callable | None = None,
) -> TimeResponse:
    """History of an output as the vehicle runs over a profile, by ``scipy.signal.lsim``.

    Parameters
    ----------
    profile : callable
        ``profile(x, rails)`` → track height (m) under each input at distances x
        (m, array (n_t, q)); ``rails`` is ``vehicle.input_rails`` broadcast like x.
        The leading axle is at x = V t.
    profile_rate : callable, optional
        The slope dz/dx with the same signature; without it the damper inputs
        use a finite-difference slope.
    speed : float
        m/s.
    t : array_like
        Uniform times, s, starting from rest at static equilibrium.
    """
    from scipy import signal

    V = _checks.positive("speed", speed)
    tt = _checks.time_grid("t", t, uniform=True)
    d = _checks.integer("derivative", derivative, low=0, high=2)
    o = vehicle.output_vector(output)
    x = V * tt[:, None] - vehicle.input_positions[None, :]
    rails = np.broadcast_to(vehicle.input_rails, x.shape)
    w = np.asarray(profile(x, rails), dtype=float)
    if profile_rate is not None:
        wdot = V * np.asarray(profile_rate(x, rails), dtype=float)
    else:
        wdot = np.gradient(w, tt, axis=0)
    n, q = vehicle.n, w.shape[1]
    Minv = np.linalg.inv(vehicle.M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ vehicle.K, -Minv @ vehicle.C]])
    B = np.vstack([np.zeros((n, 2 * q)), Minv @ np.hstack([vehicle.GK, vehicle.GC])])
    if d == 0:
        Cs, D = np.concatenate([o, np.zeros(n)])[None, :], np.zeros((1, 2 * q))
    elif d == 1:
        Cs, D = np.concatenate([np.zeros(n), o])[None, :], np.zeros((1, 2 * q))
    else:
        Cs, D = (o @ A[n:])[None, :], (o @ B[n:])[None, :]
    _, y, _ = signal.lsim((A, B, Cs, D), np.hstack([w, wdot]), tt)
    return TimeResponse(tt, np.asarray(y, dtype=float).reshape(-1), w)


def lateral_vehicle(car, speed) -> LinearVehicle:
    """The lateral car of chapter 7 (:class:`raildyn.vehicles.Car`) at speed V, driven by the track.

    Eight inputs: the alignment y_a (m) at each of the four wheelsets, then the
    cross-level c (m) there. Alignment enters the wheel–rail terms that depend on
    the wheelset's displacement relative to the rails — the rolling-radius
    difference λ(y − y_a)/r₀ and the gravitational stiffness — while the creepages
    ẏ/V − ψ and aψ̇/V stay absolute. Cross-level tilts the rails by c/(2a): the
    rail reactions push each wheelset sideways by −W c/(2a), and the bogie frames,
    which the model keeps upright on the track, tilt with the mean of their two
    wheelsets, so the secondary roll springs act on φ − c̄/(2a).

    Raises ValueError above the car's critical speed, where no steady response exists.
    """
    from raildyn.wheelset import creep_terms

    V = _checks.positive("speed", speed)
    system = car.linear_system()
    M, C, K = system.matrices(V)
    n = M.shape[0]
    GK, GC = np.zeros((n, 8)), np.zeros((n, 8))
    phi = system.labels.index("body φ")
    for j, (iy, ipsi, ws) in enumerate(system.wheelsets):
        _, K_creep, K_gravity = creep_terms(ws)
        GK[[iy, ipsi], j] = (K_creep + K_gravity)[:, 0]
        a = ws.half_gauge
        GK[iy, 4 + j] = -ws.axle_load / (2 * a)
        GK[phi, 4 + j] = 0.5 * car.roll_stiffness / (2 * a)
        GC[phi, 4 + j] = 0.5 * car.roll_damping / (2 * a)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    growth = np.linalg.eigvals(A).real.max()
    if growth >= 0:
        raise ValueError(
            f"speed {V!r} m/s is at or above the critical speed of this car (an eigenvalue has real part "
            f"{growth:.3g} 1/s >= 0): no steady response"
        )
    b, s = car.bogie.semi_wheelbase, car.semi_bogie_spacing
    positions = np.tile([0.0, 2 * b, 2 * s, 2 * s + 2 * b], 2)
    kinds = ("alignment",) * 4 + ("cross_level",) * 4
    return LinearVehicle(M, C, K, GK, GC, system.labels, positions, np.zeros(8), np.zeros(n), kinds)
