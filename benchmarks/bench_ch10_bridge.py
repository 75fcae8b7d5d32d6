"""Chapter 10: the amplification over 500 speeds, and a coupled crossing beside a finite-element engine.

DAF spectrum. raildyn (:func:`raildyn.bridge.moving_force_response`) evaluates each mode's closed form for
every speed in one compiled pass. The baseline is the straightforward time-stepping loop: for each speed, the
modal equations under the sampled modal loads integrated by chapter 2's average-acceleration Newmark
(:func:`raildyn.integrators.average_acceleration`), twenty steps per period of the highest mode kept. The
two spectra must agree to 5e-3 (the baseline's period error on the higher modes and both samplings of
the peak) before the timing counts.

Coupled crossings, beside OpenSeesPy (``tests/opensees_beam.py``: forty elastic beam elements, consistent
mass, Newmark average acceleration, Rayleigh damping). Like for like: Biggs's sprung mass, which the FE
engine couples by iterating on the contact force each step, against raildyn's compiled modal march
(:func:`raildyn.bridge.crossing`) at the same time step. And the Manchester car, coupled in raildyn,
beside the FE beam under the car's axle loads as moving forces: what the modal, compiled path costs for a
whole vehicle against the FE engine's simplest load.

The rail on discrete sleepers: its receptance by banded solves beside dense solves of the same matrices.
A wheel rolling over 10 m of it, through a dipped joint, by the compiled Newmark march
(:func:`raildyn.bridge.wheel_on_track`) beside scipy's RK45 on the same equations, timed over the first
0.4 m (the joint and its P1 and P2) and scaled by distance: the two answers agree first.

The chapter's widgets, each update against a new figure per change (``benchmarks.common.widget_case``).
"""

from __future__ import annotations

import numpy as np

from benchmarks.common import Case, timed, widget_case
from raildyn.bridge import SimplySupportedBeam, crossing, moving_force_response, sprung_mass, vehicle
from raildyn.integrators import average_acceleration
from raildyn.vehicles import VerticalCar

BEAM = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, damping_ratio=0.02, modes=10)  # f₁ = 3.93 Hz
SPEEDS = np.linspace(5.0, 150.0, 500)  # m/s: α from 0.03 to 0.95
FORCE = 1.0e5  # N
SAMPLES = 400


def _stepping_spectrum() -> np.ndarray:
    """DAF at each speed by Newmark on the modal equations, one speed at a time."""
    L, mu = BEAM.span, BEAM.modal_masses
    omega = 2 * np.pi * BEAM.frequencies_hz
    j = np.arange(1, BEAM.modes + 1)
    h = 1.0 / (20 * BEAM.frequencies_hz[-1])
    mid = np.sin(j * np.pi / 2)
    peaks = np.empty(SPEEDS.size)
    for i, v in enumerate(SPEEDS):
        t = np.arange(0.0, 2 * L / v + h, h)
        on = t <= L / v
        load = FORCE * np.sin(np.outer(j, np.pi * v * t / L)) * on  # (modes, m): mode j's load while on
        run = average_acceleration(
            np.diag(mu), np.diag(2 * BEAM.damping_ratio * omega * mu), np.diag(omega**2 * mu), t,
            np.zeros(BEAM.modes), np.zeros(BEAM.modes), load,
        )  # fmt: skip
        peaks[i] = np.abs(mid @ run.x).max()
    return peaks / BEAM.static_midspan_deflection(FORCE)


def _spectrum_case(repeats: int) -> Case:
    ours = moving_force_response(BEAM, SPEEDS, FORCE, samples=SAMPLES).amplification
    theirs = _stepping_spectrum()
    gap = np.abs(ours - theirs).max()
    if gap > 5e-3:
        raise AssertionError(f"DAF spectra disagree by {gap:.3g}")
    fast = timed(lambda i: moving_force_response(BEAM, SPEEDS, FORCE, samples=SAMPLES), repeats)
    slow = timed(lambda i: _stepping_spectrum(), max(1, repeats // 5))
    return Case(
        f"DAF spectrum, one force, 500 speeds × 10 modes (agree to {gap:.1e})",
        fast,
        slow,
        "≥ 20× faster",
        "Newmark per speed on the modal equations",
    )


def _crossing_cases(repeats: int) -> list[Case]:
    try:
        from tests.opensees_beam import fe_moving_forces, fe_sprung_mass_crossing
    except (ImportError, RuntimeError):  # OpenSeesPy raises RuntimeError without libblas3/liblapack3
        return []
    beam = (BEAM.span, BEAM.flexural_rigidity, BEAM.mass_per_length, BEAM.damping_ratio)
    v = 0.25 * 2 * BEAM.frequencies_hz[0] * BEAM.span  # α = 0.25
    body, spring = 2.0e4, 2.0e4 * (2 * np.pi * 3.0) ** 2  # a 20 t body at 3 Hz
    fe = fe_sprung_mass_crossing(*beam, body, spring, v)
    h = fe.time[1] - fe.time[0]
    load = sprung_mass(body, spring)
    ours = crossing(BEAM, load, v, time_step=h, free_time=fe.time[-1] - (BEAM.span / v))
    gap = np.abs(ours.deflection[: fe.time.size] - fe.deflection[: ours.time.size]).max()
    if gap > 5e-3 * np.abs(fe.deflection).max():
        raise AssertionError(f"the coupled crossings disagree by {gap:.3g} m")
    sprung = Case(
        f"Biggs's sprung mass over a 20 m span at α = 0.25, {fe.time.size} steps (agree to {gap:.1e} m)",
        timed(lambda i: crossing(BEAM, load, v, time_step=h), repeats),
        timed(lambda i: fe_sprung_mass_crossing(*beam, body, spring, v), max(1, repeats // 5)),
        "report the ratio",
        "OpenSeesPy, 40 elements, coupled by iteration",
    )
    car = vehicle(VerticalCar(), 1813.0)
    axles = car.axles
    whole = Case(
        "the Manchester car over a 20 m span at 144 km/h, coupled (raildyn) vs its axle loads (FE)",
        timed(lambda i: crossing(BEAM, car, 40.0), repeats),
        timed(lambda i: fe_moving_forces(*beam, axles.positions, axles.loads, 40.0), max(1, repeats // 5)),
        "report the ratio",
        "OpenSeesPy, 40 elements, moving forces",
    )
    return [sprung, whole]


def _receptance_case(repeats: int) -> Case:
    # The layered track's point receptance at 2,000 frequencies (0 to 3 kHz), in closed form, against the
    # Fourier integral of the same beam equation by quadrature, timed on 50 of the frequencies and scaled
    # to 2,000 (each frequency's quadrature costs about the same). The two agree to 1e-8 first.
    from scipy.integrate import quad

    from raildyn.bridge import LayeredTrack

    track = LayeredTrack()
    f = np.linspace(0.0, 3000.0, 2000)
    subset = f[::40]
    EI = track.rail_flexural_rigidity

    def by_quadrature(freqs):
        w = 2 * np.pi * freqs
        s = track.support_stiffness(freqs) - track.rail_mass * w**2
        out = np.empty(freqs.size, dtype=complex)
        for i, si in enumerate(s):
            scale = (abs(si) / EI) ** 0.25  # the decay's wavenumber: the integrand's width

            def integrand(u, fn, si=si, scale=scale):
                return fn(1.0 / (EI * (u * scale) ** 4 + si))

            re, im = (quad(integrand, 0.0, np.inf, args=(fn,), epsabs=0.0, epsrel=1e-12, limit=400)[0]
                      for fn in (np.real, np.imag))  # fmt: skip
            out[i] = (re + 1j * im) * scale / np.pi
        return out

    np.testing.assert_allclose(track.receptance(subset), by_quadrature(subset), rtol=1e-8)
    scaled = [t * f.size / subset.size for t in timed(lambda i: by_quadrature(subset), 3)]
    return Case(
        "receptance of the layered track, 2000 frequencies (closed form; quadrature on 50, scaled)",
        timed(lambda i: track.receptance(f), repeats),
        scaled,
        "≤ 50 ms",
        "the Fourier integral by quadrature",
    )


def _discrete_receptance_cases(repeats: int) -> list[Case]:
    # The rail on discrete sleepers, its point receptance at 2,000 frequencies (10 Hz to 3 kHz) by banded
    # L D Lᵀ solves, against the straightforward dense solve of the same matrices (numpy's LU), timed on 50
    # frequencies and scaled to 2,000. The two agree to 1e-10 first. The default track (6 elements a bay,
    # 522 unknowns) and a coarser one (4 a bay, 362 unknowns; its pinned–pinned peak 0.8 % higher).
    from raildyn.bridge import DiscreteTrack

    f = np.geomspace(10.0, 3000.0, 2000)
    subset = f[::40]
    out = []
    for label, track in (("default, 6 elements a bay", DiscreteTrack()),
                         ("4 elements a bay", DiscreteTrack(elements_per_bay=4))):  # fmt: skip
        m = track.matrices
        K, M, C = (m.dense(name) for name in ("stiffness", "mass", "damping"))
        dofs, weights = track.point(0.5 * track.length)

        def dense(freqs, K=K, M=M, C=C, dofs=dofs, weights=weights, n=m.size):
            force = np.zeros(n, dtype=complex)
            force[dofs] = weights
            w = 2 * np.pi * freqs
            return np.array([weights @ np.linalg.solve(K - x * x * M + 1j * x * C, force)[dofs] for x in w])

        np.testing.assert_allclose(track.receptance(subset), dense(subset), rtol=1e-10)
        scaled = [t * f.size / subset.size for t in timed(lambda i, dense=dense: dense(subset), 3)]
        out.append(
            Case(
                f"receptance of the discrete track, 2000 frequencies ({label}; dense on 50, scaled)",
                timed(lambda i, track=track: track.receptance(f), repeats),
                scaled,
                "≤ 50 ms",
                "dense LU solves of the same matrices",
            )
        )
    return out


def _wheel_case(repeats: int) -> Case:
    # 44 sleepers, 12 quiet at each end: the wheel runs 9.9 m between the quiet layers at 30 m/s,
    # meeting the bottom of a joint of 2α = 8 mrad 0.12 m after it starts. RK45 is timed over the first
    # 0.4 m (which holds the joint's P1 and P2) and scaled to 9.9 m: its step is set by the rail's
    # shortest elements, the same all along. The forces agree to 1 % of the peak first (Newmark's
    # period error).
    from raildyn.bridge import DippedJoint, DiscreteTrack, Wheel, wheel_on_track

    track = DiscreteTrack(bays=44, quiet_bays=12)
    start = 13 * track.sleeper_spacing
    joint = DippedJoint(start + 0.12, (0.004, 0.004), 0.1)
    wheel = Wheel()

    def run(distance, method):
        return wheel_on_track(wheel, 30.0, joint, track=track, start=start, distance=distance, method=method)

    short = [run(0.4, m) for m in ("newmark", "scipy")]
    gap = np.abs(short[0].contact_force - short[1].contact_force).max()
    assert gap < 0.01 * short[1].contact_force.max(), gap
    whole = 9.9
    return Case(
        "a wheel over 10 m of discrete track through a dipped joint, 30 m/s (RK45 on 0.4 m, scaled)",
        timed(lambda i: run(whole, "newmark"), repeats),
        [t * whole / 0.4 for t in timed(lambda i: run(0.4, "scipy"), 1)],
        "≥ 20× faster",
        "scipy's RK45 on the same equations",
    )


def cases(repeats: int):
    from raildyn.widgets import chapter10

    widgets = [
        widget_case(label, recipe, control, values, repeats)
        for label, recipe, control, values in chapter10.BENCH_MOVES
    ]
    return [
        _spectrum_case(repeats),
        *_crossing_cases(repeats),
        _receptance_case(repeats),
        *_discrete_receptance_cases(repeats),
        _wheel_case(repeats),
        *widgets,
    ]
