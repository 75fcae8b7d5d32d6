"""The rail on discrete sleepers: a finite-element track and its point receptance (chapters 3 and 10).

:class:`raildyn.bridge.track.LayeredTrack` spreads each sleeper's support along the rail. Real
sleepers hold the rail at points a distance d apart, and between them the rail is a beam free to
bend: near the frequency at which one bay of rail, pinned at both sleepers, resonates, the *pinned–
pinned resonance* (about 1 kHz on main-line track), the receptance midway between sleepers peaks and
the one above a sleeper dips. :class:`DiscreteTrack` models that: a finite length of rail of
Timoshenko beam elements (bending and shear, with the cross-section's rotary inertia, which
together lower the pinned–pinned frequency by a third from an Euler–Bernoulli beam's), each sleeper
a mass on a pad spring and damper under the rail and on a ballast spring and damper beneath.

Each element's matrices are those of the Timoshenko beam element with interdependent interpolation
(Friedman & Kosmatka 1993, *Computers & Structures* 47(3), 473–481): the deflection cubic and the
rotation quadratic in ξ = x/h, both depending on Φ = 12 EI/(κGA h²), which makes the element's
stiffness exact for a uniform beam. They are integrated here by Gauss quadrature over the shape
functions (exact: the integrands are polynomials of degree ≤ 6). Damping is viscous (c, N·s/m) so
that the same matrices serve a time march under a moving wheel.

The degrees of freedom are numbered node by node (deflection, rotation, then the sleeper under the
node if there is one), so every matrix is banded (half-bandwidth 4) and stored by diagonals:
a banded factorisation solves each frequency in O(n).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from raildyn import _checks
from raildyn.bridge.track import (
    _RAIL_EI,
    _RAIL_MASS,
    _SEARCH,
    _SLEEPER,
    _SPACING,
    _draw_receptance,
    _frequencies,
    _turns,
)

# Imported where used, to keep this module's import cheap (tests/test_imports.py): raildyn.bridge._band

__all__ = ["DiscreteResonances", "DiscreteTrack", "TrackMatrices"]

# The rest of Table 1 of the source of raildyn.bridge.track's defaults (Mathematical Problems in
# Engineering 2017, article 5872419, CC BY 4.0): G = 80.8 GPa, shear coefficient κ = 0.5329,
# A = 7.745e-3 m², ρ = 7750 kg/m³, I = 3.217e-5 m⁴.
_RAIL_SHEAR = 0.5329 * 80.8e9 * 7.745e-3  # κGA, N
_RAIL_ROTARY = 7750.0 * 3.217e-5  # ρI, kg·m
# Table 1 gives the pad's and the ballast's damping as loss factors η (0.25, 1.0). A time march needs
# dampers: each c = η k / ω, ω the resonance at which that layer works hardest in the layered model
# (LayeredTrack().resonances(): the rail on its pads at 457 Hz, the full track at 49 Hz).
_PAD = 225e6
_PAD_DAMPING = 0.25 * 225e6 / (2 * np.pi * 457.0)  # N·s/m, 19.6 kN·s/m
_BALLAST = 20e6
_BALLAST_DAMPING = 1.0 * 20e6 / (2 * np.pi * 49.0)  # N·s/m, 65.0 kN·s/m

# Rail pads in service: from about 20 MN/m (soft pads of baseplated and slab track) to about 2 GN/m
# (stiff polyethylene pads) (Thompson, Railway Noise and Vibration, Elsevier 2009, section 3.5); a value
# outside [5 MN/m, 5 GN/m] is a unit slip (kN/mm typed as N/m) rather than a pad.
PAD_STIFFNESS_RANGE = (5e6, 5e9)
#: Sleepers lie 0.5 to 0.75 m apart on main lines; a value outside [0.3, 1.0] m is no sleeper spacing.
SLEEPER_SPACING_RANGE = (0.3, 1.0)

_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(4)


def _shape(xi, h, phi):
    """(N_w, N_w', N_θ, N_θ') of the element at ξ ∈ [0, 1]: rows of 4, for (w₁, θ₁, w₂, θ₂).

    Friedman & Kosmatka (1993), eqs. 11–12, with μ = 1/(1 + Φ); derivatives per metre.
    """
    mu = 1.0 / (1.0 + phi)
    x2, x3 = xi * xi, xi**3
    nw = mu * np.array(
        [
            2 * x3 - 3 * x2 - phi * xi + 1 + phi,
            h * (x3 - (2 + phi / 2) * x2 + (1 + phi / 2) * xi),
            -(2 * x3 - 3 * x2 - phi * xi),
            h * (x3 - (1 - phi / 2) * x2 - phi / 2 * xi),
        ]
    )
    dnw = (
        mu
        / h
        * np.array(
            [
                6 * x2 - 6 * xi - phi,
                h * (3 * x2 - (4 + phi) * xi + 1 + phi / 2),
                -(6 * x2 - 6 * xi - phi),
                h * (3 * x2 - (2 - phi) * xi - phi / 2),
            ]
        )
    )
    nt = mu * np.array(
        [6 / h * (x2 - xi), 3 * x2 - (4 + phi) * xi + 1 + phi, -6 / h * (x2 - xi), 3 * x2 - (2 - phi) * xi]
    )
    dnt = mu / h * np.array([6 / h * (2 * xi - 1), 6 * xi - 4 - phi, -6 / h * (2 * xi - 1), 6 * xi - 2 + phi])
    return nw, dnw, nt, dnt


def _element(h, EI, kGA, m, rhoI):
    """The element's (mass, stiffness), 4 × 4, by 4-point Gauss quadrature over [0, h]."""
    phi = 12.0 * EI / (kGA * h * h)
    me, ke = np.zeros((4, 4)), np.zeros((4, 4))
    for x, wt in zip(0.5 * (_GAUSS_X + 1.0), 0.5 * h * _GAUSS_W, strict=True):
        nw, dnw, nt, dnt = _shape(x, h, phi)
        shear = dnw - nt
        me += wt * (m * np.outer(nw, nw) + rhoI * np.outer(nt, nt))
        ke += wt * (EI * np.outer(dnt, dnt) + kGA * np.outer(shear, shear))
    return me, ke


@dataclass(frozen=True, eq=False)  # arrays: compared by identity
class TrackMatrices:
    """A discrete track's mass, damping and stiffness, banded, with its numbering.

    Attributes
    ----------
    mass, damping, stiffness : ndarray, (5, n)
        By diagonals: ``a[k, j]`` is the matrix's entry (j + k, j), kg, N·s/m and N/m (and the
        rotations' units, kg·m², N·m·s, N·m).
    deflection : ndarray of int, (nodes,)
        Index of each rail node's deflection (its rotation is the next index).
    sleepers : ndarray of int, (bays,)
        Index of each sleeper's deflection.
    sleeper_nodes : ndarray of int, (bays,)
        The rail node above each sleeper.
    """

    mass: np.ndarray
    damping: np.ndarray
    stiffness: np.ndarray
    deflection: np.ndarray
    sleepers: np.ndarray
    sleeper_nodes: np.ndarray

    def __post_init__(self):
        first = None
        for name in ("mass", "damping", "stiffness"):
            ab = _checks.array(name, getattr(self, name), ndim=2, shape=first)
            if ab.shape[0] < 1 or ab.shape[1] < ab.shape[0]:
                raise ValueError(
                    f"{name} must hold p + 1 diagonals of n ≥ p + 1 entries, got shape {ab.shape}"
                )
            if name == "damping" and np.any(ab[0] < 0.0):
                raise ValueError(f"damping must have a diagonal >= 0, got {ab[0].min()!r}")
            if name != "damping" and np.any(ab[0] <= 0.0):
                raise ValueError(f"{name} must have a diagonal > 0, got {ab[0].min()!r}")
            first = first or ab.shape
            object.__setattr__(self, name, ab)
        for name, high in (("deflection", first[1]), ("sleepers", first[1]), ("sleeper_nodes", None)):
            value = np.asarray(getattr(self, name))
            high = len(self.deflection) if high is None else high
            if value.dtype.kind not in "iu" or value.ndim != 1 or value.size == 0:
                raise TypeError(f"{name} must be a non-empty 1-D array of integers, got {value!r:.80}")
            if value.min() < 0 or value.max() >= high:
                raise ValueError(f"{name} must hold indices in [0, {high}), got {value!r:.80}")
            object.__setattr__(self, name, value)

    @property
    def size(self) -> int:
        """n, the number of unknowns."""
        return self.stiffness.shape[1]

    def dense(self, which: str) -> np.ndarray:
        """One matrix as a full, symmetric n × n array.

        Parameters
        ----------
        which : {"mass", "damping", "stiffness"}
            The matrix.

        Returns
        -------
        ndarray, (n, n)
            kg, N·s/m or N/m (and the rotations' units).
        """
        if which not in ("mass", "damping", "stiffness"):
            raise ValueError(f"which must be 'mass', 'damping' or 'stiffness', got {which!r}")
        ab = getattr(self, which)
        n, out = ab.shape[1], np.zeros((ab.shape[1], ab.shape[1]))
        for k in range(ab.shape[0]):
            i = np.arange(n - k)
            out[i + k, i] = ab[k, : n - k]
            out[i, i + k] = ab[k, : n - k]
        return out


@dataclass(frozen=True)
class DiscreteResonances:
    """Where a discrete track's receptance peaks between 5 Hz and 5 kHz, Hz.

    Read off two receptances: above the sleeper at the middle of the track, and midway between it
    and its neighbour (:meth:`DiscreteTrack.resonances`).

    Attributes
    ----------
    full_track : float
        The first peak above a sleeper: rail and sleepers bouncing together on the ballast, Hz (> 0).
    rail_on_pads : float
        The next peak above a sleeper below the pinned–pinned resonance: the rail bouncing on its pads,
        Hz (> 0; +inf where there is none: a soft pad on stiff ballast merges it with the first). A very
        stiff pad (above about 2 GN/m) lifts the rail's resonance on its pads past the pinned–pinned one;
        the peak found below is then a small one of the rail and sleepers moving together.
    pinned_pinned : float
        The peak midway between sleepers where that receptance most exceeds the one above a sleeper:
        one bay of rail bending between two sleepers that hardly move, Hz (> 0).
    """

    full_track: float
    rail_on_pads: float
    pinned_pinned: float

    def __post_init__(self):
        for name in ("full_track", "pinned_pinned"):
            _checks.scalar(name, getattr(self, name), low=0.0, low_open=True)
        if not (isinstance(self.rail_on_pads, float | int) and self.rail_on_pads == np.inf):
            _checks.scalar("rail_on_pads", self.rail_on_pads, low=0.0, low_open=True)


@dataclass(frozen=True)
class DiscreteTrack:
    """A finite length of rail on discrete sleepers: pads, sleeper masses and ballast.

    The rail runs from x = 0 to ``bays`` × d with free ends; sleeper j lies under x = (j + ½) d.
    Each field is one rail's share (half a sleeper, one rail seat).

    Attributes
    ----------
    rail_flexural_rigidity : float
        EI, N·m², in [1, 1e16]. Default 6.76 MN·m² (UIC 60, as :class:`~raildyn.bridge.track.LayeredTrack`).
    rail_mass : float
        m, kg/m, in [1, 1e6]. Default 60.0 kg/m.
    rail_shear_stiffness : float
        κGA, N (> 0). Default 333 MN (κ = 0.5329, G = 80.8 GPa).
    rail_rotary_inertia : float
        ρI, the cross-section's rotary inertia per length, kg·m (≥ 0; 0 for a Rayleigh-free beam).
        Default 0.249 kg·m.
    pad_stiffness : float
        k_p, N/m a rail seat, in [5e6, 5e9]. Default 225 MN/m.
    pad_damping : float
        c_p, N·s/m (≥ 0). Default 19.6 kN·s/m (the source's loss factor 0.25 at 457 Hz).
    sleeper_mass : float
        m_s, kg, the sleeper's share under one rail (> 0). Default 170 kg.
    ballast_stiffness : float
        k_b, N/m under that share (> 0). Default 20 MN/m.
    ballast_damping : float
        c_b, N·s/m (≥ 0). Default 65.0 kN·s/m (the source's loss factor 1.0 at 49 Hz).
    sleeper_spacing : float
        d, m, in [0.3, 1.0]. Default 0.55 m.
    bays : int
        Number of sleepers, in [4, 400]. Default 40 (22 m at the default spacing).
    quiet_bays : int
        Bays at each end over which the rail's waves are absorbed, in [0, bays // 2 − 1]; default 14.
        Free ends would reflect the bending waves that a point force sends along the rail, and the
        receptance would ripple with the reflections (peaks c_g/(2L) apart above 600 Hz, where pads
        damp the rail little). Over these bays each rail node has a dashpot to ground, c = a m h (h the
        element's length), a rising as the square of the depth into the layer to ``quiet_rate`` at the
        rail's end: the waves die there, as they would travelling away along an endless rail.
    quiet_rate : float
        a at the rail's ends, 1/s (≥ 0). Default 3000/s: with 14 of 40 bays the receptance between the
        middle sleepers matches that of a track of 320 bays to 0.1 % below 600 Hz. Near the pinned–pinned
        frequency the waves hardly travel and hardly move the (damped) sleepers, so the peak there
        depends on the track's length: its frequency within 1 %, its height only within a factor of 10.
    elements_per_bay : int
        Beam elements between two sleepers, even, in [2, 20]. Default 6: the pinned–pinned frequency
        within 0.3 % of its converged value (1,324 Hz against 1,321 Hz with 10 elements).

    Examples
    --------
    Static stiffness under a wheel midway along the track, against the layered model's 63.3 MN/m:

    >>> track = DiscreteTrack()
    >>> round(1e-6 / float(track.receptance(0.0)[0].real), 1)  # MN/m
    60.9
    """

    rail_flexural_rigidity: float = _RAIL_EI
    rail_mass: float = _RAIL_MASS
    rail_shear_stiffness: float = _RAIL_SHEAR
    rail_rotary_inertia: float = _RAIL_ROTARY
    pad_stiffness: float = _PAD
    pad_damping: float = _PAD_DAMPING
    sleeper_mass: float = _SLEEPER
    ballast_stiffness: float = _BALLAST
    ballast_damping: float = _BALLAST_DAMPING
    sleeper_spacing: float = _SPACING
    bays: int = 40
    quiet_bays: int = 14
    quiet_rate: float = 3000.0
    elements_per_bay: int = 6

    def __post_init__(self):
        _checks.plausible("rail_flexural_rigidity", self.rail_flexural_rigidity, "flexural_rigidity")
        _checks.plausible("rail_mass", self.rail_mass, "beam_mass")
        for name in ("rail_shear_stiffness", "sleeper_mass", "ballast_stiffness"):
            _checks.positive(name, getattr(self, name))
        for name in ("rail_rotary_inertia", "pad_damping", "ballast_damping"):
            _checks.nonnegative(name, getattr(self, name))
        _checks.scalar(
            "pad_stiffness", self.pad_stiffness, low=PAD_STIFFNESS_RANGE[0], high=PAD_STIFFNESS_RANGE[1]
        )
        _checks.scalar(
            "sleeper_spacing",
            self.sleeper_spacing,
            low=SLEEPER_SPACING_RANGE[0],
            high=SLEEPER_SPACING_RANGE[1],
        )
        _checks.integer("bays", self.bays, low=4, high=400)
        _checks.integer("quiet_bays", self.quiet_bays, low=0, high=self.bays // 2 - 1)
        _checks.nonnegative("quiet_rate", self.quiet_rate)
        _checks.integer("elements_per_bay", self.elements_per_bay, low=2, high=20)
        if self.elements_per_bay % 2:
            raise ValueError(
                f"elements_per_bay must be even (a node midway between sleepers), got {self.elements_per_bay}"
            )

    @property
    def length(self) -> float:
        """The rail's length, m: ``bays`` × d."""
        return self.bays * self.sleeper_spacing

    @property
    def sleeper_positions(self) -> np.ndarray:
        """x of each sleeper, m, (j + ½) d."""
        return (np.arange(self.bays) + 0.5) * self.sleeper_spacing

    @cached_property
    def matrices(self) -> TrackMatrices:
        """The assembled mass, damping and stiffness, banded (:class:`TrackMatrices`)."""
        e, bays = self.elements_per_bay, self.bays
        nodes = e * bays + 1
        h = self.sleeper_spacing / e
        under = np.arange(bays) * e + e // 2  # the node above each sleeper
        has = np.zeros(nodes, dtype=bool)
        has[under] = True
        size = 2 * nodes + bays
        # Node i's deflection comes after every earlier node's pair and sleeper.
        deflection = 2 * np.arange(nodes) + np.concatenate(([0], np.cumsum(has)[:-1]))
        sleepers = deflection[under] + 2
        mass, damping, stiffness = (np.zeros((5, size)) for _ in range(3))

        def add(ab, i, j, value):
            lo, hi = (i, j) if i >= j else (j, i)
            ab[lo - hi, hi] += value

        me, ke = _element(h, self.rail_flexural_rigidity, self.rail_shear_stiffness, self.rail_mass,
                          self.rail_rotary_inertia)  # fmt: skip
        for i in range(nodes - 1):
            d = (deflection[i], deflection[i] + 1, deflection[i + 1], deflection[i + 1] + 1)
            for a in range(4):
                for b in range(a + 1):
                    add(mass, d[a], d[b], me[a, b])
                    add(stiffness, d[a], d[b], ke[a, b])
        for node, s in zip(under, sleepers, strict=True):
            r = deflection[node]
            for ab, pad, ballast in ((stiffness, self.pad_stiffness, self.ballast_stiffness),
                                     (damping, self.pad_damping, self.ballast_damping)):  # fmt: skip
                add(ab, r, r, pad)
                add(ab, s, r, -pad)
                add(ab, s, s, pad + ballast)
            add(mass, s, s, self.sleeper_mass)
        if self.quiet_bays:
            x = np.arange(nodes) * h
            depth = 1.0 - np.minimum(x, self.length - x) / (self.quiet_bays * self.sleeper_spacing)
            damping[0, deflection] += self.quiet_rate * self.rail_mass * h * np.clip(depth, 0.0, None) ** 2
        return TrackMatrices(mass, damping, stiffness, deflection, sleepers, under)

    def point(self, position) -> tuple[np.ndarray, np.ndarray]:
        """The rail's deflection at x as Σ weights · u[dofs]: the element's shape functions there.

        Parameters
        ----------
        position : float
            x, m, in [0, :attr:`length`].

        Returns
        -------
        (ndarray of int, ndarray)
            The four unknowns (deflection and rotation at the element's two nodes) and their weights
            (1 and m): the same weights share a point force among them.
        """
        x = _checks.scalar("position", position, low=0.0, high=self.length)
        h = self.sleeper_spacing / self.elements_per_bay
        element = min(int(x / h), self.elements_per_bay * self.bays - 1)
        phi = 12.0 * self.rail_flexural_rigidity / (self.rail_shear_stiffness * h * h)
        nw = _shape(x / h - element, h, phi)[0]
        d = self.matrices.deflection
        return np.array([d[element], d[element] + 1, d[element + 1], d[element + 1] + 1]), nw

    def receptance(self, frequencies, position=None) -> np.ndarray:
        """α(f) = w/F of the rail at one point under a harmonic point force there, m/N (complex).

        Parameters
        ----------
        frequencies : float or array_like
            f, Hz, a number or a 1-D array, each in [0, 10 000].
        position : float, optional
            x, m, in [0, :attr:`length`]; default midway between the two middle sleepers.

        Returns
        -------
        ndarray of complex
            One per frequency.
        """
        from raildyn.bridge import _band

        f = _frequencies(frequencies)
        x = 0.5 * self.length if position is None else position
        if position is None and self.bays % 2:
            x += 0.5 * self.sleeper_spacing  # an odd count puts a sleeper at the middle
        dofs, weights = self.point(x)
        m = self.matrices
        alpha, smallest = _band.band_receptance(m.mass, m.damping, m.stiffness, 2 * np.pi * f, dofs, weights)
        if not np.all(smallest > 0.0):
            raise ValueError(
                f"the track's dynamic stiffness is singular at f = {f[np.argmin(smallest)]!r} Hz"
            )
        return alpha

    def resonances(self) -> DiscreteResonances:
        """The full-track, rail-on-pads and pinned–pinned resonances between 5 Hz and 5 kHz.

        Both receptances (midway between the two middle sleepers, and above the sleeper at the middle)
        are evaluated on the geometric grid of
        :meth:`LayeredTrack.resonances <raildyn.bridge.track.LayeredTrack.resonances>` (4001 frequencies,
        0.17 % apart), each turn refined the same way (a parabola in log f through it and its neighbours).

        Returns
        -------
        DiscreteResonances
        """
        middle = np.abs(self.receptance(_SEARCH))
        above = np.abs(self.receptance(_SEARCH, position=float(self.sleeper_positions[self.bays // 2])))
        peaks, k = _turns(middle, 1.0)
        over = _turns(above, 1.0)[0]
        if peaks.size == 0 or over.size == 0:
            raise ValueError(
                "the track's receptance must peak between 5 Hz and 5 kHz, got none (over-damped)"
            )
        pinned = float(peaks[np.argmax(middle[k] / above[k])])
        below = over[1:][over[1:] < pinned]
        return DiscreteResonances(float(over[0]), float(below[0]) if below.size else np.inf, pinned)

    def plot_receptance(
        self, frequencies, ax=None, *, position=None, label=None, color=None, artists=None
    ) -> dict:
        """Draw |α(f)| in m/N on log axes against f in Hz; or move a line drawn before.

        Parameters
        ----------
        frequencies : float or array_like
            f, Hz, as for :meth:`receptance`, each > 0 (a log axis).
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        position : float, optional
            x, m, as for :meth:`receptance`; default midway between the two middle sleepers.
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
        return _draw_receptance(
            frequencies, lambda f: self.receptance(f, position), ax, artists, label, color
        )
