"""A simply supported Euler–Bernoulli beam under a moving constant force (book chapter 10), modal.

The beam of span L, flexural rigidity EI and mass per length m has the modes sin(jπx/L) at
ω_j = (jπ/L)² √(EI/m). A force P crossing at the speed V loads mode j with
p_j(t) = (2P/(mL)) sin(jπVt/L) while it is on the span (0 ≤ t ≤ L/V), so each modal
coordinate obeys q̈ + 2ξω_j q̇ + ω_j² q = p_j(t): a damped oscillator under a harmonic force
from rest, solved here in closed form, mode by mode (Frýba 1972, ch. 1; Garg & Dukkipati
1984, ch. 10). After the force leaves, each mode vibrates freely. A train of forces is the
sum of one force's response delayed by each axle's distance over the speed; the compiled
``raildyn.bridge._kernel.superpose`` carries the forces that have left as one decaying
phasor, so the cost grows with the samples plus the axles, not their product.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks, _deprecated
from raildyn._tables import Tabular

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.optimize,
# raildyn.bridge._kernel

__all__ = [
    "MovingForceResponse",
    "SimplySupportedBeam",
    "fryba_deflection",
    "moving_force_response",
    "plot_amplification",
]

# The old names of issue 33 (raildyn._deprecated.RENAMED): each warns and gives the new object;
# they go after one issue.
__getattr__ = _deprecated.module_getattr(__name__, globals())

_MAX_MODES = 200  # a simply supported beam's response converges as 1/j⁴: far more than enough


@dataclass(frozen=True)
class SimplySupportedBeam:
    """A simply supported Euler–Bernoulli beam, described by its modes.

    Attributes
    ----------
    span : float
        L, m, in [1, 2000] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "span").
    flexural_rigidity : float
        EI, N·m², in [1, 1e16] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "flexural_rigidity").
    mass_per_length : float
        m, kg/m, in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "beam_mass").
    damping_ratio : float
        ξ of every mode, in [0, 1).
    modes : int
        How many modes the solutions keep, in [1, 200].

    Examples
    --------
    A 20 m span tuned to f₁ = 4 Hz:

    >>> beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4)
    >>> round(float(beam.frequencies_hz[0]), 3)
    3.927
    """

    span: float = 20.0
    flexural_rigidity: float = 1.0e10
    mass_per_length: float = 1.0e4
    damping_ratio: float = 0.0
    modes: int = 10

    def __post_init__(self):
        for name, quantity in (
            ("span", "span"),
            ("flexural_rigidity", "flexural_rigidity"),
            ("mass_per_length", "beam_mass"),
        ):
            _checks.plausible(name, getattr(self, name), quantity)
        _checks.scalar("damping_ratio", self.damping_ratio, low=0.0, high=1.0, high_open=True)
        _checks.integer("modes", self.modes, low=1, high=_MAX_MODES)

    @property
    def frequencies_hz(self) -> np.ndarray:
        """f_j = (j²π/(2L²)) √(EI/m) of the kept modes, Hz."""
        j = np.arange(1, self.modes + 1)
        return j**2 * np.pi / (2 * self.span**2) * np.sqrt(self.flexural_rigidity / self.mass_per_length)

    @property
    def length(self) -> float:
        """The length a load crosses, m: the span."""
        return self.span

    @property
    def modal_masses(self) -> np.ndarray:
        """∫ m φ_j² dx = mL/2 of each kept mode, kg (φ_j = sin(jπx/L))."""
        return np.full(self.modes, self.mass_per_length * self.span / 2)

    def mode_shapes(self, x, derivative: int = 0) -> np.ndarray:
        """φ_j(x) = sin(jπx/L) of the kept modes, or its first or second derivative; 0 off the span.

        Parameters
        ----------
        x : array_like, (k,)
            Positions along the beam, m (finite, at least one; any outside [0, L] give 0).
        derivative : {0, 1, 2}
            φ, φ′ (1/m) or φ″ (1/m²).

        Returns
        -------
        ndarray, (modes, k)
        """
        xs = _checks.array("x", x, ndim=1, allow_empty=False)
        d = _checks.integer("derivative", derivative, low=0, high=2)
        k = np.arange(1, self.modes + 1)[:, None] * np.pi / self.span
        phase = k * xs + d * np.pi / 2  # each derivative advances sin by a quarter turn, times k
        return np.where((xs >= 0) & (xs <= self.span), k**d * np.sin(phase), 0.0)

    def static_midspan_deflection(self, force) -> float:
        """P L³/(48 EI), m: the deflection under a force P at midspan (the beam formula).

        Parameters
        ----------
        force : float
            P, N (finite, either sign).

        Returns
        -------
        float
        """
        return _checks.scalar("force", force) * self.span**3 / (48 * self.flexural_rigidity)


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class MovingForceResponse(Tabular):
    """The deflection at one point of the beam while a force crosses it, for several speeds.

    Attributes
    ----------
    speeds : ndarray, (s,)
        v, m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    time : ndarray, (s, k)
        t, s, from the force's arrival (each row from 0 to twice its crossing time).
    deflection : ndarray, (s, k)
        w at ``position``, m (downwards for a downward force).
    position : float
        x, m, on the span.
    static : float
        The largest static deflection there as the forces pass, m (the beam formula).
    acceleration : ndarray, (s, k) or None
        ẅ at ``position``, m/s² (downwards); None when not computed. Acceleration needs the
        modes up to the frequency of interest (EN 1991-2 §6.4.6.5: 30 Hz, 1.5 f₁ or the third
        mode, whichever is highest) and samples fine enough to catch their peaks.

    Each array is finite.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units; a
    # row for each time step, a column for each speed ("deflection[speeds=20.0] (m)").
    _columns = (("time", "s"), ("deflection", "m"), ("acceleration", "m/s²"))
    _scalars = (("position", "m"), ("static", "m"))
    _labels = (("time", "speeds"), ("deflection", "speeds"), ("acceleration", "speeds"))
    _by_row = ("time", "deflection", "acceleration")

    speeds: np.ndarray
    time: np.ndarray
    deflection: np.ndarray
    position: float
    static: float
    acceleration: np.ndarray | None = None

    def __post_init__(self):
        s = _checks.speeds("speeds", self.speeds).size
        k = _checks.array("time", self.time, shape=(s, None)).shape[1]
        _checks.array("deflection", self.deflection, shape=(s, k))
        _checks.scalar("position", self.position, low=0.0)
        _checks.scalar("static", self.static)
        if self.acceleration is not None:
            _checks.array("acceleration", self.acceleration, shape=(s, k))

    @property
    def peak_acceleration(self) -> np.ndarray:
        """The largest |ẅ| of each speed over the run, m/s² (what EN 1990 A2.4.4.2.1 limits)."""
        if self.acceleration is None:
            raise ValueError("acceleration was not computed for this response (acceleration None)")
        return np.abs(self.acceleration).max(axis=1)

    @property
    def amplification(self) -> np.ndarray:
        """The dynamic amplification factor of each speed: max |w| over the crossing and after, / |static|."""
        return np.abs(self.deflection).max(axis=1) / abs(self.static)

    def plot(self, ax=None, *, alpha_speed=None, artists: dict | None = None, **style) -> dict:
        """Draw the dynamic amplification against speed (km/h), or against α (see :func:`plot_amplification`).

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw; new axes by default. Ignored when ``artists`` is given.
        alpha_speed : float, optional
            2f₁L, m/s (> 0): the speed at α = 1, to draw against α = v/(2f₁L); None: against km/h.
        artists : dict, optional
            What an earlier call returned: the line is moved in place, nothing is drawn anew.
        **style
            Passed to ``Axes.plot`` (``color``, ``lw``, ``label``...).

        Returns
        -------
        dict
            ``{"line": Line2D}``.
        """
        return plot_amplification(
            self.speeds, self.amplification, ax, alpha_speed=alpha_speed, artists=artists, **style
        )


def plot_amplification(speeds, amplification, ax=None, *, alpha_speed=None, artists=None, **style) -> dict:
    """Draw a dynamic amplification against speed (km/h) or against α = v/(2f₁L): chapter 10's curves.

    One function for every amplification curve of chapter 10, in its figures and its widgets
    (:meth:`MovingForceResponse.plot` calls it; a curve pieced together from several responses
    is drawn by it directly). A fresh drawing labels the axes.

    Parameters
    ----------
    speeds : array_like, (s,)
        v, m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    amplification : array_like, (s,)
        The largest deflection over the static one at each speed (finite, ≥ 0).
    ax : matplotlib Axes, optional
        Where to draw; new axes by default. Ignored when ``artists`` is given.
    alpha_speed : float, optional
        2f₁L, m/s (> 0): the speed at α = 1, to draw against α = v/(2f₁L); None: against km/h.
    artists : dict, optional
        What an earlier call returned: the line is moved in place (``set_data``), nothing is
        drawn anew.
    **style
        Passed to ``Axes.plot`` (``color``, ``lw``, ``label``...).

    Returns
    -------
    dict
        ``{"line": Line2D}``.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=3)
    >>> drawn = moving_force_response(beam, [20.0, 40.0], 1.0e5).plot(Figure().subplots())
    >>> drawn["line"].get_xdata().tolist()
    [72.0, 144.0]
    """
    import matplotlib
    import matplotlib.lines

    from raildyn import plots

    v = _checks.speeds("speeds", speeds)
    daf = _checks.array("amplification", amplification, shape=v.shape, low=0.0)
    scale = None if alpha_speed is None else _checks.positive("alpha_speed", alpha_speed)
    x = 3.6 * v if scale is None else v / scale
    try:  # a keyword that is no line property is refused before anything is drawn
        matplotlib.lines.Line2D([], [], **style)
    except AttributeError as err:
        raise TypeError(f"style: {err} (keywords must be properties of matplotlib's Line2D)") from None
    if artists is not None:
        _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
        if "line" not in artists:
            raise ValueError("artists must come from plot_amplification, got one without 'line'")
        artists["line"].set_data(x, daf)
        return artists
    ax = plots.axes_or_new(ax)
    with matplotlib.rc_context(plots.STYLE):
        (line,) = ax.plot(x, daf, **style)
        ax.set_xlabel("V (km/h)" if scale is None else "α = V/(2f₁L)")
        ax.set_ylabel("dynamic amplification")
    return {"line": line}


def moving_force_response(beam: SimplySupportedBeam, speeds, force=1.0, *, position=None, samples: int = 400):
    """The deflection at a point of the beam as a constant force, or a train of them, crosses it.

    Each mode's response is the closed form of the module docstring; the deflection is their
    sum, Σ q_j(t) sin(jπx/L), over the beam's kept modes. A train is the sum of its axles'
    responses, each delayed by its distance behind the leader over the speed.

    Parameters
    ----------
    beam : SimplySupportedBeam
    speeds : float or array_like
        v, m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    force : float or AxleSequence
        P, N (finite; positive downwards gives a positive deflection), or the axles of a train.
    position : float, optional
        x, m, in [0, L]; None: midspan.
    samples : int
        Time samples per speed, in [10, 100 000], from the leading axle's arrival until the
        last has been off the span as long as one crossing takes.

    Returns
    -------
    MovingForceResponse
        Its ``static`` is the largest static deflection there as the loads pass.

    Examples
    --------
    Slowly, the force bends the beam as a static load does:

    >>> beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=20)
    >>> r = moving_force_response(beam, 0.5, 1.0e5, samples=2001)
    >>> round(float(r.amplification[0]), 3)
    1.003
    """
    from raildyn.bridge import _kernel
    from raildyn.bridge.loads import AxleSequence  # loads builds on this module

    _checks.instance("beam", beam, SimplySupportedBeam)
    v = _checks.speeds("speeds", speeds)
    if isinstance(force, AxleSequence):
        # writable copies of its read-only arrays: numba would compile the kernel anew for read-only ones
        delays, loads = np.array(force.positions), np.array(force.loads)
    else:
        delays, loads = np.zeros(1), np.array([_checks.scalar("force", force)])
    L = beam.span
    x = L / 2 if position is None else _checks.scalar("position", position, low=0.0, high=L)
    n = _checks.integer("samples", samples, low=10, high=100_000)
    end = (2 * L + delays[-1]) / v  # the last force off the span for as long as one crossing takes
    t = np.linspace(0.0, 1.0, n)[None, :] * end[:, None]  # (s, k)
    j = np.arange(1, beam.modes + 1)
    shape = 2 / (beam.mass_per_length * L) * np.sin(j * np.pi * x / L)
    w, acceleration = np.zeros_like(t), np.zeros_like(t)
    omega = 2 * np.pi * beam.frequencies_hz
    _kernel.superpose(omega, float(beam.damping_ratio), L, v, end, n, delays, loads, shape, w, acceleration)
    static = _largest_static(beam, x, delays, loads)
    return MovingForceResponse(v, t, w, float(x), float(static), acceleration)


def fryba_deflection(beam: SimplySupportedBeam, speed, force, time, position=None) -> np.ndarray:
    """Frýba's series for the undamped beam while the force is on it, m.

    w(x, t) = w₀ Σ_j 1/(j²(j² − α²)) [sin jωt − (α/j) sin ω_j t] sin(jπx/L), with
    ω = πv/L, α = ω/ω₁ and w₀ = 2PL³/(π⁴EI) (Frýba 1972, eq. 1.30), over the beam's modes.

    Parameters
    ----------
    beam : SimplySupportedBeam
        Its damping ratio must be 0 (the series is the undamped one).
    speed : float
        v, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`], not at a resonance α = j (j ≤ modes).
    force : float
        P, N (finite).
    time : array_like, (k,)
        t, s, each in [0, L/v]; at least one.
    position : float, optional
        x, m, in [0, L]; None: midspan.

    Returns
    -------
    ndarray, (k,)
        w, m.
    """
    _checks.instance("beam", beam, SimplySupportedBeam)
    if beam.damping_ratio != 0.0:
        raise ValueError(
            f"beam must be undamped for Frýba's series, got damping_ratio {beam.damping_ratio!r}"
        )
    v = _checks.speed("speed", speed)
    P = _checks.scalar("force", force)
    L = beam.span
    t = _checks.array("time", time, ndim=1, low=0.0, allow_empty=False)
    if t.max() > L / v:
        raise ValueError(f"time must lie within the crossing [0, {L / v:.6g}] s, got {t.max()!r}")
    x = L / 2 if position is None else _checks.scalar("position", position, low=0.0, high=L)
    omega1 = 2 * np.pi * beam.frequencies_hz[0]
    w = np.pi * v / L
    alpha = w / omega1
    j = np.arange(1, beam.modes + 1)
    if np.any(np.isclose(j, alpha, rtol=1e-9)):
        raise ValueError(f"speed must not put a mode at resonance (α = {alpha:.6g}), got {v!r}")
    w0 = 2 * P * L**3 / (np.pi**4 * beam.flexural_rigidity)
    tt = t[..., None]
    terms = (np.sin(j * w * tt) - alpha / j * np.sin(j**2 * omega1 * tt)) / (j**2 * (j**2 - alpha**2))
    return w0 * (terms * np.sin(j * np.pi * x / L)).sum(axis=-1)


def _influence(beam: SimplySupportedBeam, x, a):
    """Static deflection at x under a unit force at a, m/N (the beam formula, both sides)."""
    L, EI = beam.span, beam.flexural_rigidity
    lo, hi = np.minimum(x, a), np.maximum(x, a)  # the nearer end's point and the other
    return lo * (L - hi) * (L**2 - lo**2 - (L - hi) ** 2) / (6 * EI * L)


def _largest_static(beam: SimplySupportedBeam, x, delays, loads) -> float:
    """Max over the front's positions of Σ P_k × influence(x, front − d_k): the slow crossing's peak."""
    import scipy.optimize

    L = beam.span

    def static(front):
        at = np.asarray(front)[..., None] - delays
        on = (at >= 0.0) & (at <= L)
        return np.where(on, _influence(beam, x, np.clip(at, 0.0, L)), 0.0) @ loads

    # the sum of piecewise cubics peaks at a kink (an axle at x) or inside a piece: the kinks and a
    # coarse grid find the piece, and Brent's method its peak, to 1e-10 of the value
    fronts = np.unique(np.concatenate([np.linspace(0.0, L + delays[-1], 401), x + delays]))
    values = static(fronts)
    i = int(np.argmax(values))
    lo, hi = fronts[max(i - 1, 0)], fronts[min(i + 1, fronts.size - 1)]
    refined = scipy.optimize.minimize_scalar(
        lambda f: -static(f), bounds=(lo, hi), method="bounded", options={"xatol": 1e-10 * (L + delays[-1])}
    )
    return float(max(values[i], -refined.fun))
