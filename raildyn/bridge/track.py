"""The track as a structure: the point receptance of a rail on a continuous, layered support (ch. 3, 10).

A wheel rolling over a joint, a flat or short-wave roughness sees the track through its
*receptance*: the rail's deflection at the wheel per unit harmonic force, α(ω) = w/F (m/N,
complex). For a rail of bending stiffness EI and mass m per length on a support of dynamic
stiffness k_f(ω) per length (N/m²), harmonic motion at ω turns the beam's equation into

    EI w'''' + s(ω) w = F δ(x),   s(ω) = k_f(ω) − m ω²,

whose point receptance is, as for the static beam on a Winkler bed (Hetényi 1946), but with a complex
wavenumber (Grassie, Gregory, Harrison & Johnson 1982; Knothe & Grassie 1993):

    α(ω) = 1 / (8 EI Ω_W³),   Ω_W = (s(ω)/(4EI))^{1/4},

the root taken with the argument of s(ω) in (−π, π] (the one that continues the static root as damping
grows). :func:`beam_receptance` evaluates it for any support; :class:`LayeredTrack` gives the support
of a ballasted track: rail pads of stiffness k_p on sleepers of mass m_s on ballast of stiffness k_b,
each rail seat's values spread over the sleeper spacing d, and each spring's damping a loss factor η
(k(1 + iη)):

    k_f(ω) = k_p* (k_b* − m_s ω²) / (k_p* + k_b* − m_s ω²) / d.

Its receptance rises to the *full-track resonance*, rail and sleepers bouncing on the ballast, falls
to an antiresonance where the sleepers resonate between pads and ballast and hold the rail still, and
peaks again at the rail's resonance on its pads. The sleepers' discreteness (the pinned–pinned resonance
near 1 kHz) is outside this continuous model.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks

__all__ = ["LayeredTrack", "TrackResonances", "beam_receptance"]


def beam_receptance(flexural_rigidity, dynamic_stiffness) -> np.ndarray:
    """The point receptance of an infinite Euler–Bernoulli beam whose support and inertia give s(ω).

    Parameters
    ----------
    flexural_rigidity : float
        EI, N·m², in [1, 1e16] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "flexural_rigidity").
    dynamic_stiffness : complex or array_like of complex
        s(ω) = k_f(ω) − m ω², N/m² per metre of beam: the support's dynamic stiffness less the beam's
        own inertia, finite and not zero; its imaginary part (damping) ≥ 0. A number or a non-empty
        1-D array.

    Returns
    -------
    ndarray of complex
        α = w/F, m/N, one per ``dynamic_stiffness``.

    Examples
    --------
    At rest on a 50 MN/m² bed, a UIC 60 rail gives under each newton (Hetényi's PΩ_W/(2k)):

    >>> round(1e9 * float(beam_receptance(6.4155e6, 50e6)[()].real), 3)  # nm
    11.815
    """
    EI = _checks.plausible("flexural_rigidity", flexural_rigidity, "flexural_rigidity")
    try:
        s = np.asarray(dynamic_stiffness, dtype=complex)
    except (TypeError, ValueError):
        raise TypeError(
            f"dynamic_stiffness must be a complex number or an array of them, got {dynamic_stiffness!r:.80}"
        ) from None
    if s.ndim > 1 or s.size == 0:
        raise ValueError(f"dynamic_stiffness must be a number or a non-empty 1-D array, got shape {s.shape}")
    if not np.all(np.isfinite(s)) or np.any(s == 0):
        raise ValueError(f"dynamic_stiffness must be finite and not zero, got {s!r:.80}")
    if np.any(s.imag < 0):
        raise ValueError(f"dynamic_stiffness must have an imaginary part (damping) >= 0, got {s!r:.80}")
    beta = (s / (4.0 * EI)) ** 0.25  # numpy's principal root: argument of s in (−π, π] over 4
    return 1.0 / (8.0 * EI * beta**3)


@dataclass(frozen=True)
class TrackResonances:
    """Where a layered track's receptance |α(f)| peaks and dips between 5 Hz and 5 kHz, Hz.

    On a usual ballasted track there are two peaks and a dip between them. A soft pad on stiff
    ballast merges the first two into one peak: then there is no dip and no second peak, and those
    two fields are +inf.

    Attributes
    ----------
    full_track : float
        The first peak: rail and sleepers bouncing together on the ballast, Hz (> 0).
    antiresonance : float
        The dip above it: each sleeper resonating between its pad and the ballast, the rail held
        still, Hz (> 0; +inf without one).
    rail_on_pads : float
        The second peak: the rail bouncing on its pads over sleepers that hardly move, Hz (> 0; +inf
        without one, with the antiresonance).
    """

    full_track: float
    antiresonance: float
    rail_on_pads: float

    def __post_init__(self):
        _checks.scalar("full_track", self.full_track, low=0.0, low_open=True)
        for name in ("antiresonance", "rail_on_pads"):
            value = getattr(self, name)
            if not (isinstance(value, float | int) and value == np.inf):
                _checks.scalar(name, value, low=0.0, low_open=True)
        if (self.antiresonance == np.inf) != (self.rail_on_pads == np.inf):
            raise ValueError(
                "antiresonance and rail_on_pads must both be frequencies or both +inf (one peak), got "
                f"{self.antiresonance!r} and {self.rail_on_pads!r}"
            )


_SEARCH = np.geomspace(5.0, 5000.0, 4001)  # Hz: the grid on which the turns of |α| are found (0.17 % apart)


def _turns(magnitude, sign):
    """The peaks (``sign`` 1) or dips (−1) of ``magnitude`` = |α| on the search grid, Hz, refined.

    Each turn's frequency comes from the parabola through it and its two neighbours in (log f, log |α|).
    Returns the refined frequencies and the turns' indices on the grid.
    """
    a, x = np.log(magnitude), np.log(_SEARCH)
    k = np.flatnonzero((sign * a[1:-1] > sign * a[:-2]) & (sign * a[1:-1] > sign * a[2:])) + 1
    y0, y1, y2 = a[k - 1], a[k], a[k + 1]
    return np.exp(x[k] + 0.5 * (y0 - y2) / (y0 - 2 * y1 + y2) * (x[k + 1] - x[k])), k


# A ballasted track of UIC 60 rail on concrete sleepers: Table 1 of "Study on transmission
# characteristics of vertical rail vibrations in ballast track", Mathematical Problems in Engineering
# 2017, article 5872419 (Hindawi, CC BY 4.0; www.hindawi.com/journals/mpe/2017/5872419/tab1/):
# E = 210 GPa, I = 3.217e-5 m⁴, A = 7.745e-3 m², ρ = 7750 kg/m³; pad 225 kN/mm, loss factor 0.25;
# sleepers 0.55 m apart, 170 kg a half sleeper; ballast 20 kN/mm a half sleeper, loss factor 1.0.
_RAIL_EI = 210e9 * 3.217e-5  # N·m²
_RAIL_MASS = 7.745e-3 * 7750.0  # kg/m
_PAD = 225e6  # N/m a rail seat
_PAD_LOSS = 0.25
_SLEEPER = 170.0  # kg, half a sleeper
_BALLAST = 20e6  # N/m under half a sleeper
_BALLAST_LOSS = 1.0
_SPACING = 0.55  # m


@dataclass(frozen=True)
class LayeredTrack:
    """A rail on pads, sleepers and ballast, the supports spread along it: its point receptance.

    Attributes
    ----------
    rail_flexural_rigidity : float
        EI of one rail, N·m², in [1, 1e16]. Default 6.76 MN·m² (UIC 60; the module's source).
    rail_mass : float
        m, kg/m, in [1, 1e6]. Default 60.0 kg/m.
    pad_stiffness : float
        k_p, N/m a rail seat (> 0). Default 225 MN/m.
    pad_loss_factor : float
        η_p, in [0, 2]. Default 0.25.
    sleeper_mass : float
        m_s, kg, the sleeper's share under one rail (> 0). Default 170 kg.
    ballast_stiffness : float
        k_b, N/m under that share (> 0). Default 20 MN/m.
    ballast_loss_factor : float
        η_b, in [0, 2]. Default 1.0.
    sleeper_spacing : float
        d, m, in [0.3, 1.0] (sleepers lie 0.5 to 0.75 m apart). Default 0.55 m.

    Examples
    --------
    The track's static stiffness under one wheel, and its full-track resonance:

    >>> track = LayeredTrack()
    >>> round(1e-6 * track.static_stiffness, 1)  # MN/m
    63.3
    >>> f = np.linspace(20.0, 400.0, 1901)
    >>> round(float(f[np.argmax(np.abs(track.receptance(f)))]))  # Hz
    49
    """

    rail_flexural_rigidity: float = _RAIL_EI
    rail_mass: float = _RAIL_MASS
    pad_stiffness: float = _PAD
    pad_loss_factor: float = _PAD_LOSS
    sleeper_mass: float = _SLEEPER
    ballast_stiffness: float = _BALLAST
    ballast_loss_factor: float = _BALLAST_LOSS
    sleeper_spacing: float = _SPACING

    def __post_init__(self):
        _checks.plausible("rail_flexural_rigidity", self.rail_flexural_rigidity, "flexural_rigidity")
        _checks.plausible("rail_mass", self.rail_mass, "beam_mass")
        for name in ("pad_stiffness", "sleeper_mass", "ballast_stiffness"):
            _checks.positive(name, getattr(self, name))
        for name in ("pad_loss_factor", "ballast_loss_factor"):
            _checks.scalar(name, getattr(self, name), low=0.0, high=2.0)
        _checks.scalar("sleeper_spacing", self.sleeper_spacing, low=0.3, high=1.0)

    def support_stiffness(self, frequencies) -> np.ndarray:
        """k_f(ω), the pads, sleepers and ballast as a dynamic stiffness per metre of rail, N/m² (complex).

        Parameters
        ----------
        frequencies : float or array_like
            f, Hz, a number or a 1-D array, each in [0, 10 000] (beyond, the rail's cross-section
            deforms and a beam is no model).

        Returns
        -------
        ndarray of complex
            One per frequency.
        """
        w = 2.0 * np.pi * _frequencies(frequencies)
        pad = self.pad_stiffness * (1.0 + 1j * self.pad_loss_factor)
        below = self.ballast_stiffness * (1.0 + 1j * self.ballast_loss_factor) - self.sleeper_mass * w**2
        return pad * below / (pad + below) / self.sleeper_spacing

    def receptance(self, frequencies) -> np.ndarray:
        """α(f) = w/F of the rail under a harmonic point force, m/N (complex; the module docstring).

        Parameters
        ----------
        frequencies : float or array_like
            f, Hz, a number or a 1-D array, each in [0, 10 000] (beyond, the rail's cross-section
            deforms and a beam is no model).

        Returns
        -------
        ndarray of complex
            One per frequency.
        """
        f = _frequencies(frequencies)
        s = self.support_stiffness(f) - self.rail_mass * (2.0 * np.pi * f) ** 2
        return beam_receptance(self.rail_flexural_rigidity, s)

    def resonances(self) -> TrackResonances:
        """The peaks and dips of |α(f)| between 5 Hz and 5 kHz.

        Found on a geometric grid of 4001 frequencies (0.17 % apart) and refined by a parabola
        through each turn and its neighbours in log f.

        Returns
        -------
        TrackResonances
        """
        magnitude = np.abs(self.receptance(_SEARCH))
        peaks, dips = _turns(magnitude, 1.0)[0], _turns(magnitude, -1.0)[0]
        if peaks.size == 0:
            raise ValueError(
                "the track's receptance must peak between 5 Hz and 5 kHz, got none (over-damped)"
            )
        between = dips[dips > peaks[0]]
        if peaks.size < 2 or between.size == 0:
            return TrackResonances(float(peaks[0]), np.inf, np.inf)
        return TrackResonances(float(peaks[0]), float(between[0]), float(peaks[1]))

    def plot_receptance(self, frequencies, ax=None, *, label=None, color=None, artists=None) -> dict:
        """Draw |α(f)| in m/N on log axes against f in Hz; or move a line drawn before.

        Parameters
        ----------
        frequencies : float or array_like
            f, Hz, as for :meth:`receptance`, each > 0 (a log axis).
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        label : str, optional
            Legend label.
        color : color, optional
            Line colour.
        artists : dict, optional
            The dict a previous call returned (same frequencies): its line takes this track's curve.

        Returns
        -------
        dict
            ``{"receptance": line}``.
        """
        return _draw_receptance(frequencies, self.receptance, ax, artists, label, color)

    @property
    def static_stiffness(self) -> float:
        """The track's stiffness under a wheel at rest, N/m: pads and ballast in series, spread over the
        sleeper spacing, without their loss factors (a loss factor damps motion, and at rest there is none).
        """
        series = self.pad_stiffness * self.ballast_stiffness / (self.pad_stiffness + self.ballast_stiffness)
        return float(
            1.0 / beam_receptance(self.rail_flexural_rigidity, series / self.sleeper_spacing)[()].real
        )


_MAX_FREQUENCY = 1.0e4  # Hz: far above the pinned–pinned resonance, where the rail's cross-section deforms


def _draw_receptance(frequencies, receptance, ax, artists, label, color) -> dict:
    """|α(f)| of one track (``receptance(f)``) on log axes, or moved onto an earlier line: the one
    drawing of both track models' ``plot_receptance``."""
    f = _frequencies(frequencies)
    if f.min() <= 0.0:
        raise ValueError(f"frequencies must be > 0 Hz on the log axis, got {f.min()!r}")
    from raildyn import plots

    return plots.movable_line(
        ax, artists, "receptance", f, np.abs(receptance(f)), label=label, color=color,
        xlabel="frequency f (Hz)", ylabel="|α| (m/N)", log=True,
    )  # fmt: skip


def _frequencies(frequencies) -> np.ndarray:
    """f (Hz) as a 1-D array, each in [0, 10 kHz] (an Euler–Bernoulli rail is no model beyond)."""
    f = np.atleast_1d(_checks.array("frequencies", frequencies, low=0.0, allow_empty=False))
    if f.ndim != 1:
        raise ValueError(f"frequencies must be a number or a 1-D array, got shape {f.shape}")
    if f.max() > _MAX_FREQUENCY:
        raise ValueError(
            f"frequencies must be at most {_MAX_FREQUENCY:g} Hz (a beam model of the rail), got {f.max()!r}"
        )
    return f
