"""The track as a structure: the point receptance of a rail on a continuous, layered support, held to the
static beam on a Winkler bed (Hetényi) and to the Fourier integral of the beam's equation evaluated by
quadrature, an independent computation."""

import numpy as np
import pytest
from scipy.integrate import quad

from raildyn.bridge import LayeredTrack, WinklerBeam, beam_receptance


def _fourier(EI, s):
    """w(0)/F = (1/π) ∫₀^∞ dk / (EI k⁴ + s), by quadrature of its real and imaginary parts."""
    scale = (abs(s) / EI) ** 0.25  # the wavenumber of the decay: the integrand's width

    def part(fn):
        integrand = lambda u: fn(1.0 / (EI * (u * scale) ** 4 + s))  # noqa: E731
        value, _ = quad(integrand, 0.0, np.inf, epsabs=0.0, epsrel=1e-12, limit=400)
        return value * scale / np.pi

    return part(np.real) + 1j * part(np.imag)


def test_at_rest_the_receptance_is_hetenyis_deflection():
    # α(0) = β/(2k) per newton (Hetényi 1946), WinklerBeam.static_deflection at x = 0: the same number by two
    # formulas, to round-off.
    bed = WinklerBeam(flexural_rigidity=6.4e6, mass_per_length=60.0, foundation_modulus=80e6, damping=3e4)
    assert bed.receptance(0.0)[0] == pytest.approx(bed.static_deflection([0.0], 1.0)[0], rel=1e-12)
    # The layered track at rest: pads and ballast in series, spread over the sleeper spacing.
    track = LayeredTrack()
    k = track.pad_stiffness * track.ballast_stiffness / (track.pad_stiffness + track.ballast_stiffness)
    smeared = WinklerBeam(track.rail_flexural_rigidity, track.rail_mass, k / track.sleeper_spacing)
    assert track.static_stiffness == pytest.approx(1.0 / smeared.static_deflection([0.0], 1.0)[0], rel=1e-12)


@pytest.mark.parametrize("f", [0.0, 40.0, 150.0, 450.0, 1200.0, 3000.0])
def test_the_receptance_is_the_fourier_integral_of_the_beams_equation(f):
    # Below, between and above the track's resonances (the full-track one, the antiresonance, the rail on its
    # pads, and well above the cut-off where s < 0): the closed form against quadrature, to 1e-8 (quad's
    # 1e-12 on each part, the parts of one size).
    track = LayeredTrack()
    w = 2 * np.pi * f
    s = complex(track.support_stiffness(f)[0] - track.rail_mass * w**2)
    closed = track.receptance(f)[0]
    assert closed == pytest.approx(_fourier(track.rail_flexural_rigidity, s), rel=1e-8)
    assert closed == beam_receptance(track.rail_flexural_rigidity, s)[()]


def test_a_rigid_pad_on_a_massless_sleeper_is_the_ballast_alone():
    # Pads a thousand times stiffer and sleepers a millionth of the mass: the ballast alone, a Winkler bed of
    # k_b(1 + iη_b)/d (within the pad's 1e-3 share of the compliance).
    track = LayeredTrack(pad_stiffness=2e13, pad_loss_factor=0.0, sleeper_mass=1e-4)
    f = np.array([0.0, 60.0, 300.0])
    w = 2 * np.pi * f
    k = track.ballast_stiffness * (1 + 1j * track.ballast_loss_factor) / track.sleeper_spacing
    expected = beam_receptance(track.rail_flexural_rigidity, k - track.rail_mass * w**2)
    np.testing.assert_allclose(track.receptance(f), expected, rtol=1e-5)


def test_the_track_resonates_where_its_layers_say():
    # The default track: the full-track resonance (rail and sleepers bouncing on the ballast) near
    # √(k_b/(m_s + m d))/(2π), the antiresonance (each sleeper resonating between its pad and the ballast
    # under a rail held still) at √((k_p + k_b)/m_s)/(2π), where the support's stiffness has its pole, and
    # the rail's resonance on its pads above. The lumped estimates leave out the rail's bending, which
    # spreads the load over several sleepers: the resonance within a factor 2, the antiresonance 10 %.
    track = LayeredTrack()
    f = np.linspace(10.0, 1500.0, 14901)
    a = np.abs(track.receptance(f))
    peaks = f[1:-1][(a[1:-1] > a[:-2]) & (a[1:-1] > a[2:])]
    trough = f[1:-1][(a[1:-1] < a[:-2]) & (a[1:-1] < a[2:])]
    assert peaks.size == 2 and trough.size == 1
    d = track.sleeper_spacing
    full = np.sqrt(track.ballast_stiffness / (track.sleeper_mass + track.rail_mass * d)) / (2 * np.pi)
    anti = np.sqrt((track.pad_stiffness + track.ballast_stiffness) / track.sleeper_mass) / (2 * np.pi)
    assert 0.5 * full < peaks[0] < 2.0 * full  # measured 49 Hz against 52 Hz
    assert trough[0] == pytest.approx(anti, rel=0.1)  # measured 199 Hz against 193 Hz
    assert peaks[0] < trough[0] < peaks[1]


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="sleeper_spacing"):
        LayeredTrack(sleeper_spacing=3.0)
    with pytest.raises(ValueError, match="pad_loss_factor"):
        LayeredTrack(pad_loss_factor=-0.1)
    with pytest.raises(ValueError, match="frequencies"):
        LayeredTrack().receptance(2e4)
    with pytest.raises(ValueError, match="dynamic_stiffness"):
        beam_receptance(6.4e6, 1e6 - 1e5j)


def test_the_resonances_are_the_turns_of_the_curve():
    # TrackResonances against the turns read off a fine linear grid by hand (0.1 Hz apart): within 0.5 %
    # (the method's geometric grid is 0.17 % apart, refined by a parabola). A stiffer pad lifts the rail's
    # resonance and the antiresonance; a stiffer ballast lifts the full-track resonance.
    track = LayeredTrack()
    f = np.linspace(10.0, 1500.0, 14901)
    a = np.abs(track.receptance(f))
    peaks = f[1:-1][(a[1:-1] > a[:-2]) & (a[1:-1] > a[2:])]
    trough = f[1:-1][(a[1:-1] < a[:-2]) & (a[1:-1] < a[2:])]
    turns = track.resonances()
    np.testing.assert_allclose([turns.full_track, turns.rail_on_pads], peaks, rtol=5e-3)
    assert turns.antiresonance == pytest.approx(trough[0], rel=5e-3)
    stiff_pad = LayeredTrack(pad_stiffness=1e9).resonances()
    assert stiff_pad.rail_on_pads > 1.5 * turns.rail_on_pads and stiff_pad.antiresonance > turns.antiresonance
    assert LayeredTrack(ballast_stiffness=100e6).resonances().full_track > 1.5 * turns.full_track
    # A soft pad on stiff ballast: the full-track resonance and the rail's on its pads merge into one peak.
    merged = LayeredTrack(pad_stiffness=50e6, ballast_stiffness=200e6).resonances()
    assert merged.antiresonance == np.inf and merged.rail_on_pads == np.inf


def test_the_receptance_widget_marks_the_tracks_resonances():
    from raildyn.widgets import chapter10

    container, update = chapter10.track_receptance()
    update(pad_mn=600.0, ballast_mn=80.0)
    turns = LayeredTrack(pad_stiffness=600e6, ballast_stiffness=80e6).resonances()
    ax = container.live.figure.axes[0]
    live = ax.lines[1]
    f = live.get_xdata()
    expected = np.abs(LayeredTrack(pad_stiffness=600e6, ballast_stiffness=80e6).receptance(f))
    np.testing.assert_allclose(live.get_ydata(), expected, rtol=1e-12)
    marked = [line.get_xdata()[0] for line in ax.lines[2:5]]
    np.testing.assert_allclose(
        marked, [turns.full_track, turns.antiresonance, turns.rail_on_pads], rtol=1e-12
    )
    status = container.children[-2].children[-1].value
    assert f"full track {turns.full_track:.0f} Hz" in status
