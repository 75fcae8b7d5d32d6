"""A uniform Euler–Bernoulli beam continuous over several spans, by its exact modes (book chapter 10).

Inside each span the free vibration at ω is
w(s) = A sin(Ω_b s) + B cos(Ω_b s) + C sinh(Ω_b s) + D cosh(Ω_b s), Ω_b⁴ = m̄ω²/(EI), with Ω_b the
wavenumber of the bending wave and m̄ the mass per length. Every support holds the beam against
deflection and leaves it free to turn; slope
and bending moment are continuous over the inner supports and the moment vanishes at both ends.
With the deflection fixed at every support, the slopes θ₀ … θₙ at the n + 1 supports are the
only unknowns: each span contributes the exact 2 × 2 dynamic stiffness that relates its end
moments to its end slopes, and the assembled matrix K(ω) is singular at a natural frequency.

The natural frequencies are found by the Wittrick–Williams algorithm (Wittrick & Williams 1971):
the number of natural frequencies below ω is J(ω) = J₀(ω) + s{K(ω)}, with s{K} the number of
negative eigenvalues of K(ω) and J₀ the number of clamped–clamped frequencies of the single spans
below ω (each span's J₀ = i − ½(1 − (−1)ⁱ sgn(1 − cos μ cosh μ)), i = ⌊μ/π⌋, μ = Ω_b L, Williams &
Wittrick 1970). Bisection on that count brackets every frequency, a repeated one included, so
none is missed; each is then located to about 1e-14 of its value. The slopes of a mode are the
null vector of K at its frequency, and each span's shape follows from its end slopes.

Each mode is scaled so that its largest |φ| over the beam is 1 and its slope at x = 0 is
positive (a single span thus gives sin(jπx/L), as :class:`raildyn.bridge.beam.SimplySupportedBeam`).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from raildyn import _checks

__all__ = ["ContinuousBeam"]

_MAX_MODES = 200
_MAX_SPANS = 50
_MAX_SPAN = 10_000.0  # m: far beyond any bridge span
_MAX_RATIO = 20.0  # longest / shortest span: beyond it the short spans are rigid supports, not spans


def _basis(beta, s, span, derivative=0):
    """The span's four functions sin Ω_b s, cos Ω_b s, e^{−Ω_b s}, e^{−Ω_b (L−s)} (or a derivative), (..., 4).

    The two decaying exponentials span the same space as sinh and cosh but stay of order one
    for any Ω_b L, which keeps the 4 × 4 end conditions well conditioned at high modes.
    """
    bs = beta * s
    d = derivative
    trig = np.stack([np.sin(bs + d * np.pi / 2), np.cos(bs + d * np.pi / 2)], axis=-1)
    ex = np.stack([(-1.0) ** d * np.exp(-bs), np.exp(-beta * (span - s))], axis=-1)
    return beta**d * np.concatenate([trig, ex], axis=-1)


def _end_matrix(beta, span):
    """Rows w(0), w′(0), w(L), w′(L) of the four basis functions: (..., 4, 4) for spans of shape (...)."""
    span = np.asarray(span, dtype=float)[..., None]
    ends = np.concatenate([np.zeros_like(span), span], axis=-1)  # (..., 2)
    w = _basis(beta, ends, span, 0)
    dw = _basis(beta, ends, span, 1)
    return np.stack([w[..., 0, :], dw[..., 0, :], w[..., 1, :], dw[..., 1, :]], axis=-2)


_UNIT_SLOPES = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 0.0], [0.0, 1.0]])


def _span_stiffness(beta, span, rigidity):
    """Each span's exact dynamic stiffness: [−EI w″(0), EI w″(L)] = K [θ(0), θ(L)], (..., 2, 2).

    Statically (Ω_b → 0) it tends to (EI/L)[[4, 2], [2, 4]], the slope-deflection stiffness.
    """
    span = np.asarray(span, dtype=float)
    coefficients = np.linalg.solve(_end_matrix(beta, span), _UNIT_SLOPES)  # (..., 4, 2)
    ends = np.stack([np.zeros_like(span), span], axis=-1)[..., None]  # (..., 2, 1)
    curvature = _basis(beta, ends[..., 0], span[..., None], 2) @ coefficients  # (..., 2 ends, 2 slopes)
    return rigidity * np.stack([-curvature[..., 0, :], curvature[..., 1, :]], axis=-2)


def _clamped_count(mu):
    """How many clamped–clamped frequencies a span has below μ = Ω_b L (Williams & Wittrick 1970)."""
    i = np.floor(mu / np.pi)
    sign = np.sign(1.0 - np.cos(mu) * np.cosh(mu))
    return int(np.sum(i - 0.5 * (1 - (-1.0) ** i * sign)))


@dataclass(frozen=True)
class ContinuousBeam:
    """A uniform Euler–Bernoulli beam continuous over simple supports, described by its modes.

    It gives the same modal description as :class:`raildyn.bridge.beam.SimplySupportedBeam`
    (``length``, ``frequencies_hz``, ``modal_masses``, ``mode_shapes``, ``damping_ratio``,
    ``modes``), so a solution written against that protocol runs on either.

    Attributes
    ----------
    spans : tuple of float
        L₁ … Lₙ, m, from the left end: each in [1, 2000] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "span"), the longest at most
        20 times the shortest, at most 50 spans. One span is the simply supported beam.
    flexural_rigidity : float
        EI, N·m², in [1, 1e16] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "flexural_rigidity"), the
        same in every span.
    mass_per_length : float
        m, kg/m, in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "beam_mass").
    damping_ratio : float
        ξ of every mode, in [0, 1).
    modes : int
        How many modes are kept, in [1, 200].

    Notes
    -----
    The modes are exact (see the module docstring), computed once per beam on first use. Each is
    scaled to max |φ| = 1 over the beam, with φ′(0) > 0.

    Examples
    --------
    Two equal spans: the first two frequency parameters Ω_b L are π (each span as a simple span,
    in opposite phase) and 3.9266 (each span as a propped cantilever):

    >>> beam = ContinuousBeam((20.0, 20.0), 1.0e10, 1.0e4, modes=2)
    >>> beta_l = 20.0 * (2 * np.pi * beam.frequencies_hz) ** 0.5 * (1.0e4 / 1.0e10) ** 0.25
    >>> np.round(beta_l, 4)
    array([3.1416, 3.9266])
    """

    spans: tuple = (20.0, 20.0)
    flexural_rigidity: float = 1.0e10
    mass_per_length: float = 1.0e4
    damping_ratio: float = 0.0
    modes: int = 10

    def __post_init__(self):
        lengths = _checks.array("spans", self.spans, ndim=1, low=0.0, low_open=True, allow_empty=False)
        if lengths.size > _MAX_SPANS or lengths.max() > _MAX_SPAN:
            raise ValueError(
                f"spans must hold at most {_MAX_SPANS} spans, each at most {_MAX_SPAN:g} m, got {lengths}"
            )
        if lengths.max() > _MAX_RATIO * lengths.min():
            raise ValueError(
                f"spans must keep the longest within {_MAX_RATIO:g} times the shortest, got {lengths}"
            )
        object.__setattr__(self, "spans", tuple(float(v) for v in lengths))
        _checks.plausible_array("spans", lengths, "span")
        _checks.plausible("flexural_rigidity", self.flexural_rigidity, "flexural_rigidity")
        _checks.plausible("mass_per_length", self.mass_per_length, "beam_mass")
        _checks.scalar("damping_ratio", self.damping_ratio, low=0.0, high=1.0, high_open=True)
        _checks.integer("modes", self.modes, low=1, high=_MAX_MODES)

    # ------------------------------------------------------------------ the modes, once

    @property
    def _supports(self) -> np.ndarray:
        return np.concatenate([[0.0], np.cumsum(self.spans)])

    def _stiffness(self, beta) -> np.ndarray:
        n = len(self.spans)
        blocks = _span_stiffness(beta, np.array(self.spans), 1.0)  # EI scales K, not its signs
        K = np.zeros((n + 1, n + 1))
        i = np.arange(n)
        K[i, i] += blocks[:, 0, 0]
        K[i + 1, i + 1] += blocks[:, 1, 1]
        K[i, i + 1] += blocks[:, 0, 1]
        K[i + 1, i] += blocks[:, 1, 0]
        return K

    def _count(self, beta) -> int:
        """J(Ω_b): the number of natural frequencies below the one whose wavenumber is Ω_b."""
        K = self._stiffness(beta)
        negative = int(np.sum(np.linalg.eigvalsh(0.5 * (K + K.T)) < 0.0))
        return negative + _clamped_count(beta * np.array(self.spans))

    def _off_poles(self, beta, a, b):
        """Ω_b, or a point beside it within (a, b) if a span is within rounding of a clamped frequency."""
        for _ in range(8):
            mu = beta * np.array(self.spans)
            if np.all(np.abs(1.0 / np.cosh(mu) - np.cos(mu)) > 1e-9):
                break
            beta = beta + 0.1 * (b - beta)  # step towards b, staying inside the bracket
        return beta

    def _shape_coefficients(self, beta, slopes) -> np.ndarray:
        """Each span's four basis coefficients for support slopes ``slopes``: (spans, 4)."""
        return np.array(
            [
                np.linalg.solve(_end_matrix(beta, span), [0.0, slopes[i], 0.0, slopes[i + 1]])
                for i, span in enumerate(self.spans)
            ]
        )

    @functools.cached_property
    def _solution(self):
        """Wavenumbers Ω_j (1/m) and the basis coefficients of each mode, (modes, spans, 4)."""
        n = self.modes
        seen = {0.0: 0}  # every count made: later roots start from the tightest bracket already known
        # An irrational start keeps the bisection's points off the spans' clamped–clamped frequencies,
        # which sit within rounding of (k + ½)π/L_i, where K has its poles and the count is ill-defined.
        hi = (1 + np.sqrt(5.0)) / 2 * np.pi / max(self.spans)
        while (count := self._count(hi)) < n:  # J grows without bound: double until it holds n frequencies
            seen[hi] = count
            hi *= 2.0
        seen[hi] = count
        betas = np.empty(n)
        j = 0
        while j < n:
            # Bisect for the smallest Ω_b with J(Ω_b) > j: the (j+1)-th frequency (1e-14 of Ω_b: 50 halvings).
            a = max(beta for beta, c in seen.items() if c <= j)
            b = min(beta for beta, c in seen.items() if c > j)
            while b - a > 1e-14 * b:
                mid = self._off_poles(0.5 * (a + b), a, b)
                seen[mid] = self._count(mid)
                if seen[mid] > j:
                    b = mid
                else:
                    a = mid
            root = 0.5 * (a + b)
            multiplicity = max(min(seen[b] - j, n - j), 1)  # a repeated frequency counts twice at once
            betas[j : j + multiplicity] = root
            j += multiplicity
        coefficients = np.empty((n, len(self.spans), 4))
        j = 0
        while j < n:
            r = int(np.sum(betas == betas[j]))
            vals, vecs = np.linalg.eigh(self._stiffness(betas[j]))
            null = vecs[:, np.argsort(np.abs(vals))[:r]]  # the null space, one vector per repeated mode
            for k in range(r):
                coefficients[j + k] = self._shape_coefficients(betas[j], null[:, k])
            j += r
        shapes = self._normalised(betas, coefficients)
        return betas, shapes

    def _normalised(self, betas, coefficients):
        """Mass-orthogonalise repeated modes, then scale each to max |φ| = 1 and φ′(0) > 0."""
        out = coefficients.copy()
        j = 0
        while j < len(betas):  # Gram–Schmidt within a group of equal frequencies
            r = int(np.sum(betas == betas[j]))
            for a in range(j, j + r):
                for b in range(j, a):
                    out[a] -= (
                        self._inner(betas[a], out[a], out[b]) / self._inner(betas[a], out[b], out[b]) * out[b]
                    )
            j += r
        for j, beta in enumerate(betas):
            peak = self._peak(beta, out[j])
            slope = (_basis(beta, np.array([0.0]), self.spans[0], 1) @ out[j, 0])[0]
            out[j] *= np.sign(slope) / peak if slope != 0 else 1.0 / peak
        return out

    def _gauss(self, beta, span):
        """Gauss–Legendre nodes and weights on [0, span], enough for φ² exactly to rounding."""
        panels = int(np.ceil(beta * span / np.pi)) + 1  # 20 points a half wavelength
        x, w = np.polynomial.legendre.leggauss(20)
        edges = np.linspace(0.0, span, panels + 1)
        h = np.diff(edges)[:, None]
        nodes = (edges[:-1, None] + (x + 1) / 2 * h).ravel()
        return nodes, (w * h / 2).ravel()

    def _inner(self, beta, c1, c2) -> float:
        """∫ φ₁ φ₂ dx over the beam for two shapes of the same Ω_b."""
        total = 0.0
        for i, span in enumerate(self.spans):
            s, w = self._gauss(beta, span)
            basis = _basis(beta, s, span)
            total += np.sum(w * (basis @ c1[i]) * (basis @ c2[i]))
        return float(total)

    def _peak(self, beta, c) -> float:
        """max |φ| over the beam: the best point of a fine grid, refined by Newton's steps on φ′ = 0."""
        best = 0.0
        for i, span in enumerate(self.spans):
            s = np.linspace(0.0, span, 16 * (int(beta * span / np.pi) + 2) + 1)
            values = np.abs(_basis(beta, s, span) @ c[i])
            k = int(np.argmax(values))
            a, b = s[max(k - 1, 0)], s[min(k + 1, s.size - 1)]
            x = np.array([s[k]])
            for _ in range(8):  # quadratic convergence from within 1/32 of a half wave: far below rounding
                slope = (_basis(beta, x, span, 1) @ c[i])[0]
                curvature = (_basis(beta, x, span, 2) @ c[i])[0]
                if curvature == 0.0:
                    break
                x = np.clip(x - slope / curvature, a, b)
            best = max(best, values.max(), abs((_basis(beta, x, span) @ c[i])[0]))
        return best

    # ------------------------------------------------------------------ the modal protocol

    @property
    def length(self) -> float:
        """The length a load crosses, m: the sum of the spans."""
        return float(sum(self.spans))

    @property
    def frequencies_hz(self) -> np.ndarray:
        """f_j = Ω_j² √(EI/m̄)/(2π) of the kept modes, Hz, ascending."""
        betas, _ = self._solution
        return betas**2 * np.sqrt(self.flexural_rigidity / self.mass_per_length) / (2 * np.pi)

    @property
    def modal_masses(self) -> np.ndarray:
        """∫ m φ_j² dx over the beam of each kept mode, kg (φ_j scaled to max |φ_j| = 1)."""
        betas, shapes = self._solution
        return np.array(
            [self.mass_per_length * self._inner(b, c, c) for b, c in zip(betas, shapes, strict=True)]
        )

    def static_deflection(self, force_position, at, force=1.0) -> np.ndarray:
        """The static deflection under a point force, m: one column of the beam's flexibility.

        By the slope-deflection method, exact: the loaded span clamped at both ends first (its
        deflection and end moments P a b²/L² and P a² b/L², Roark's formulas), then the support
        slopes θ that restore moment equilibrium, K θ = −F with K the static stiffness (EI/L)[[4, 2],
        [2, 4]] of every span, and each span's deflection from its end slopes,
        θ_a s(1 − s/L)² − θ_b s²(1 − s/L)/L.

        Parameters
        ----------
        force_position : float
            a, m, from the left end, in [0, length].
        at : array_like, (k,)
            Positions where the deflection is wanted, m (finite, at least one; outside the beam: 0).
        force : float
            P, N (finite; downwards positive gives a downward, positive deflection).

        Returns
        -------
        ndarray, (k,)
            w, m.

        Examples
        --------
        A single span: P L³/(48 EI) at midspan.

        >>> beam = ContinuousBeam((20.0,), 1.0e10, 1.0e4)
        >>> float(beam.static_deflection(10.0, [10.0], 1.0e5)[0]) == 1.0e5 * 20.0**3 / (48 * 1.0e10)
        True
        """
        supports = self._supports
        a_global = _checks.scalar("force_position", force_position, low=0.0, high=supports[-1])
        xs = _checks.array("at", at, ndim=1, allow_empty=False)
        P = _checks.scalar("force", force)
        EI = self.flexural_rigidity
        spans = np.array(self.spans)
        n = spans.size
        i = int(np.clip(np.searchsorted(supports, a_global, side="right") - 1, 0, n - 1))
        L = spans[i]
        a = a_global - supports[i]
        b = L - a
        K = np.zeros((n + 1, n + 1))
        for j, Lj in enumerate(spans):
            K[j : j + 2, j : j + 2] += EI / Lj * np.array([[4.0, 2.0], [2.0, 4.0]])
        F = np.zeros(n + 1)
        F[i : i + 2] = [-P * a * b**2 / L**2, P * a**2 * b / L**2]  # the clamped span's end actions
        theta = np.linalg.solve(K, -F)
        span_index = np.clip(np.searchsorted(supports, xs, side="right") - 1, 0, n - 1)
        inside = (xs >= 0.0) & (xs <= supports[-1])
        s = np.where(inside, xs - supports[span_index], 0.0)  # off the beam: computed at a support, then 0
        Ls = spans[span_index]
        xi = s / Ls
        w = theta[span_index] * s * (1 - xi) ** 2 - theta[span_index + 1] * s * xi * (1 - xi)
        here = span_index == i
        left = here & (s <= a)
        right = here & (s > a)
        # The clamped span under P (Roark): x ≤ a, P b² x² (3aL − (3a + b)x)/(6 EI L³), mirrored beyond.
        w[left] += P * b**2 * s[left] ** 2 * (3 * a * L - (3 * a + b) * s[left]) / (6 * EI * L**3)
        r = L - s[right]
        w[right] += P * a**2 * r**2 * (3 * b * L - (3 * b + a) * r) / (6 * EI * L**3)
        return np.where(inside, w, 0.0)

    def mode_shapes(self, x, derivative: int = 0) -> np.ndarray:
        """φ_j(x) of the kept modes, or its first or second derivative; 0 off the beam.

        Parameters
        ----------
        x : array_like, (k,)
            Positions from the left end, m (finite, at least one; any outside [0, length] give 0).
        derivative : {0, 1, 2}
            φ, φ′ (1/m) or φ″ (1/m²). The slope is continuous over the inner supports; at a
            support itself the span to its right is used (the span to the left at the right end).

        Returns
        -------
        ndarray, (modes, k)

        Examples
        --------
        >>> beam = ContinuousBeam((20.0, 30.0), 1.0e10, 1.0e4, modes=3)
        >>> bool(np.all(np.abs(beam.mode_shapes([0.0, 20.0, 50.0])) < 1e-12))  # zero at every support
        True
        """
        xs = _checks.array("x", x, ndim=1, allow_empty=False)
        d = _checks.integer("derivative", derivative, low=0, high=2)
        betas, shapes = self._solution
        supports = self._supports
        span_index = np.clip(np.searchsorted(supports, xs, side="right") - 1, 0, len(self.spans) - 1)
        inside = (xs >= 0.0) & (xs <= supports[-1])
        out = np.zeros((self.modes, xs.size))
        for i, span in enumerate(self.spans):
            here = inside & (span_index == i)
            if not here.any():
                continue
            s = xs[here] - supports[i]
            for j, beta in enumerate(betas):
                out[j, here] = _basis(beta, s, span, d) @ shapes[j, i]
        return out
