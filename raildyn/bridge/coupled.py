"""A vehicle or a train crossing a bridge, the two coupled through the wheel forces (chapter 10).

The beam moves in its modes, w(x, t) = Σ φ_i(x) b_i(t) (downwards), each with its modal
mass μ_i, frequency ω_i and damping ratio ξ. Axle j stands at x_j = Vt − d_j; its wheel
rides on the rail, whose height there is u_j = −w(x_j, t) + r(x_j) (r: the track's
irregularity, upwards), so that its rate and acceleration carry the moving point:

    u̇_j = −(φ_j·ḃ + V φ′_j·b) + V r′,     ü_j = −(φ_j·b̈ + 2V φ′_j·ḃ + V² φ″_j·b) + V² r″.

The sprung vehicle answers the rail heights, M q̈ + C q̇ + K q = G_K u + G_C u̇, and the
wheel presses on the rail with

    F_j = W_j + m_j ü_j − (G_Kᵀ q + G_Cᵀ q̇ − K_W u − C_W u̇)_j

(its static load, its unsprung mass's inertia, less the suspension's dynamic pull upwards).
The beam's modes take the forces of the axles on it, μ_i(b̈_i + 2ξω_i ḃ_i + ω_i² b_i) =
Σ_j φ_i(x_j) F_j. Put together, the coupled matrices change as the axles move, and each
step of the average-acceleration Newmark scheme (chapter 2's, unconditionally stable) is
assembled and solved afresh; the loop is compiled (``raildyn.bridge._kernel``).
(Frýba 1972, ch. 1 and 8; Biggs 1964; Yang, Yau & Wu 2004, ch. 2.)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.bridge.loads import AxleSequence, MovingLoad, moving_load
from raildyn.errors import SolverError
from raildyn.plots import axes_or_new

# Imported where used, to keep this module's import cheap (tests/test_imports.py):
# scipy.interpolate.CubicSpline, raildyn.bridge._kernel

__all__ = ["BridgeCrossing", "crossing"]

_STEPS_PER_PERIOD = 20  # of the shortest period kept: the scheme's period error is then below 1 %
_SPAN_STEPS = 200  # at least this many steps while one axle crosses the span
_MAX_STEPS = 2_000_000
_MAX_AXLE_SAMPLES = 10_000_000  # the rail under every axle at every step: 240 MB at most
_TABLE_POINTS_PER_MODE = 200  # Hermite tables: φ to ~1e-10 of its peak (module _kernel)


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class BridgeCrossing(Tabular):
    """The beam and the vehicle while the vehicle crosses, and after it has left.

    Attributes
    ----------
    speed : float
        v, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    at : float
        x of the beam's output point, m.
    time : ndarray, (k,)
        t, s, from the leading axle's arrival on the beam.
    deflection : ndarray, (k,)
        w at ``at``, m (downwards).
    static_deflection : ndarray, (k,)
        The same loads' deflection there if they crossed slowly: their static loads on the
        modes kept, m.
    moment : ndarray, (k,)
        −EI w″ at ``at``, N·m (sagging positive).
    deck_acceleration : ndarray, (k,)
        ẅ at ``at``, m/s² (downwards).
    contact_forces : ndarray, (k, a)
        Each axle's force on the rail, N (downwards).
    modal : ndarray, (k, 2, modes)
        The beam's modal coordinates and their rates, m and m/s (the scale of the modes).
    vehicle : ndarray, (k, 3, p) or None
        The sprung vehicle's coordinates from rest, their rates and accelerations; None when
        nothing is sprung (moving forces or masses).
    vehicle_labels : tuple of str
        The names of the p coordinates (empty with no vehicle).

    Each array is finite.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units;
    # the modal and vehicle states (their units mixed along an axis) are no columns.
    _columns = (
        ("time", "s"), ("deflection", "m"), ("static_deflection", "m"), ("moment", "N·m"),
        ("deck_acceleration", "m/s²"), ("contact_forces", "N"),
    )  # fmt: skip
    _scalars = (("speed", "m/s"), ("at", "m"))

    speed: float
    at: float
    time: np.ndarray
    deflection: np.ndarray
    static_deflection: np.ndarray
    moment: np.ndarray
    deck_acceleration: np.ndarray
    contact_forces: np.ndarray
    modal: np.ndarray
    vehicle: np.ndarray
    vehicle_labels: tuple

    def __post_init__(self):
        _checks.speed("speed", self.speed)
        _checks.scalar("at", self.at)
        k = _checks.array("time", self.time, ndim=1, allow_empty=False).size
        for name in ("deflection", "static_deflection", "moment", "deck_acceleration"):
            _checks.array(name, getattr(self, name), shape=(k,))
        _checks.array("contact_forces", self.contact_forces, shape=(k, None))
        _checks.array("modal", self.modal, shape=(k, 2, None))
        p = 0 if self.vehicle is None else _checks.array("vehicle", self.vehicle, shape=(k, 3, None)).shape[2]
        labels = _checks.strings("vehicle_labels", self.vehicle_labels)
        if len(labels) != p:
            raise ValueError(
                f"vehicle_labels must name the {p} coordinates of vehicle (none when vehicle is None), "
                f"got {len(labels)}: {labels!r:.80}"
            )

    @property
    def amplification(self) -> float:
        """The dynamic amplification factor: max |w| over the run / max |w| of the slow crossing."""
        return float(np.abs(self.deflection).max() / np.abs(self.static_deflection).max())

    def vehicle_acceleration(self, label: str) -> np.ndarray:
        """One vehicle coordinate's acceleration over the run, m/s² (rad/s²).

        Parameters
        ----------
        label : str
            One of ``vehicle_labels``, such as ``"body z"``.

        Returns
        -------
        ndarray, (k,)
        """
        if self.vehicle is None:
            raise ValueError(
                f"label {label!r}: this crossing has no sprung vehicle (moving forces or masses)"
            )
        i = self.vehicle_labels.index(_checks.choice("label", label, self.vehicle_labels))
        return self.vehicle[:, 2, i]

    @property
    def body_acceleration(self) -> np.ndarray:
        """The car body's vertical acceleration over the run, m/s², (k,): the mean over every coordinate
        whose label ends in "body z" (one car's body, or the bodies of a train of sprung masses).

        Raises
        ------
        ValueError
            If the crossing has no sprung vehicle, or none of its coordinates is a body's bounce.
        """
        bodies = [label for label in self.vehicle_labels if label.endswith("body z")]
        if self.vehicle is None or not bodies:
            raise ValueError(
                f"this crossing has no body to accelerate (vehicle coordinates {self.vehicle_labels!r:.80})"
            )
        return np.mean([self.vehicle[:, 2, self.vehicle_labels.index(label)] for label in bodies], axis=0)

    def plot(
        self, ax=None, *, quantity: str = "deflection", static: bool = True, artists=None, **style
    ) -> dict:
        """Draw the deflection at the output point, or the body's acceleration, against the leading axle.

        The deflection in mm, downwards drawn down, beside the slow crossing (dashed, drawn
        first); or the body's vertical acceleration (``body_acceleration``), m/s². The one
        drawing of chapter 10's crossings, for its figures and its widgets.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw; new axes by default. Ignored when ``artists`` is given.
        quantity : {"deflection", "body acceleration"}
            What to draw.
        static : bool
            Draw the slow crossing too (deflection only).
        artists : dict, optional
            What an earlier call returned: its lines are moved to this crossing in place
            (``set_data``), nothing is drawn anew.
        **style
            Passed to ``Axes.plot`` for the crossing's line (``color``, ``lw``, ``label``...;
            the label defaults to the speed in km/h).

        Returns
        -------
        dict
            ``line`` (the crossing's Line2D) and ``static`` (the slow crossing's, or None).
        """
        import matplotlib
        import matplotlib.lines

        from raildyn import plots

        _checks.choice("quantity", quantity, ("deflection", "body acceleration"))
        static = _checks.flag("static", static) and quantity == "deflection"
        try:  # a keyword that is no line property is refused before anything is drawn
            matplotlib.lines.Line2D([], [], **style)
        except AttributeError as err:
            raise TypeError(f"style: {err} (keywords must be properties of matplotlib's Line2D)") from None
        x = self.speed * self.time
        y = 1e3 * self.deflection if quantity == "deflection" else self.body_acceleration
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
            if "line" not in artists:
                raise ValueError("artists must come from BridgeCrossing.plot, got one without 'line'")
            artists["line"].set_data(x, y)
            if artists.get("static") is not None:
                artists["static"].set_data(x, 1e3 * self.static_deflection)
            return artists
        ax = axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            slow = None
            if static:
                (slow,) = ax.plot(x, 1e3 * self.static_deflection, "k--", lw=1, label="slow crossing")
            (line,) = ax.plot(x, y, **({"label": f"{self.speed * 3.6:.0f} km/h"} | style))
            ax.set_xlabel("leading axle's position (m)")
            if quantity == "deflection":
                ax.set_ylabel(f"deflection at x = {self.at:g} m (mm)")
                if not ax.yaxis_inverted():
                    ax.invert_yaxis()  # downwards is down
            else:
                ax.set_ylabel("body acceleration (m/s²)")
        return {"line": line, "static": slow}


def _rail(irregularity, load: MovingLoad, length: float, x: np.ndarray) -> np.ndarray:
    """r, r′, r″ under each axle at each time, (k, a, 3); zeros when there is no irregularity."""
    from scipy.interpolate import CubicSpline

    out = np.zeros((*x.shape, 3))
    if irregularity is None:
        return out
    if not isinstance(irregularity, (tuple, list)) or len(irregularity) != 2:
        raise TypeError(f"irregularity must be a pair (x, z) of arrays or None, got {irregularity!r:.80}")
    xs = _checks.array("irregularity x", irregularity[0], ndim=1)
    zs = _checks.array("irregularity z", irregularity[1], shape=xs.shape)
    if xs.size < 4 or np.any(np.diff(xs) <= 0.0):
        raise ValueError(f"irregularity x must be at least 4 increasing positions, got {xs[:6]}")
    if xs[0] > -load.length or xs[-1] < length:
        raise ValueError(
            f"irregularity x must cover the crossing, [{-load.length:g}, {length:g}] m, "
            f"got [{xs[0]:g}, {xs[-1]:g}]"
        )
    spline = CubicSpline(xs, zs)
    inside = np.clip(x, xs[0], xs[-1])  # beyond the samples the rail stays level at the last height
    level = inside == x
    for d in range(3):
        out[..., d] = spline(inside, d) * (level if d else 1.0)
    return out


def crossing(
    beam, load, speed, *, irregularity=None, at=None, time_step=None, free_time=None
) -> BridgeCrossing:
    """A moving load crossing a beam at a constant speed, the two coupled (module docstring).

    At t = 0 the leading axle arrives at x = 0; the beam is at rest and the vehicle at rest
    on level track. The run lasts until the last axle leaves, and ``free_time`` after.

    Parameters
    ----------
    beam : SimplySupportedBeam or a beam of the same modal protocol
        Gives ``length``, ``frequencies_hz``, ``modal_masses``, ``damping_ratio``,
        ``flexural_rigidity`` and ``mode_shapes(x, derivative)``.
    load : MovingLoad or AxleSequence
        What crosses (an axle sequence: as constant forces).
    speed : float
        v, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    irregularity : (array_like, array_like), optional
        x (m, increasing, covering from minus the load's length to the beam's end) and the
        rail's height z there (m, upwards): a cubic spline gives r, r′, r″. None: level.
    at : float, optional
        The output point, m, in [0, length]; None: the middle of the first span.
    time_step : float, optional
        h, s, in (0, 0.1]; None: a twentieth of the shortest period of the beam's modes and
        the vehicle's, and at most 1/200 of one axle's crossing.
    free_time : float, optional
        s, in [0, 100]; None: two periods of the first mode.

    Returns
    -------
    BridgeCrossing

    Raises
    ------
    SolverError
        If the state stops being finite (the partial result is attached).

    Examples
    --------
    A moving force at α = 0.6, near the largest amplification of one force (Frýba 1972, ch. 1):

    >>> from raildyn.bridge import AxleSequence, SimplySupportedBeam
    >>> beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=5)
    >>> v = 0.6 * 2 * beam.frequencies_hz[0] * 20.0
    >>> run = crossing(beam, AxleSequence([0.0], [1.0e5]), v)
    >>> round(run.amplification, 2)
    1.73
    """
    from raildyn.bridge import _kernel

    _checks.not_a_class("beam", beam, "a beam")
    for name in (
        "length",
        "frequencies_hz",
        "modal_masses",
        "damping_ratio",
        "flexural_rigidity",
        "mode_shapes",
    ):
        if not hasattr(beam, name):
            raise TypeError(
                f"beam must give the modal protocol of SimplySupportedBeam (no {name!r}), "
                f"got {type(beam).__name__}"
            )
    if isinstance(load, AxleSequence):
        load = moving_load(load)
    _checks.instance("load", load, MovingLoad, "MovingLoad or AxleSequence")
    v = _checks.speed("speed", speed)
    L = float(beam.length)
    first_span = getattr(beam, "spans", (L,))[0]  # a continuous beam's middle may be a support
    x_out = first_span / 2 if at is None else _checks.scalar("at", at, low=0.0, high=L)
    f1 = float(beam.frequencies_hz[0])
    free = 2.0 / f1 if free_time is None else _checks.scalar("free_time", free_time, low=0.0, high=100.0)

    system = load.system
    p = 0 if system is None else system.size
    mats = None if system is None else system.matrices(v)
    highest = float(beam.frequencies_hz[-1])
    if system is not None:
        w2 = np.linalg.eigvals(np.linalg.solve(mats.M, mats.K)).real
        highest = max(highest, float(np.sqrt(max(w2.max(), 0.0)) / (2 * np.pi)))
    h_auto = min(1.0 / (_STEPS_PER_PERIOD * highest), L / (v * _SPAN_STEPS))
    h = (
        h_auto
        if time_step is None
        else _checks.scalar("time_step", time_step, low=0.0, low_open=True, high=0.1)
    )
    duration = (L + load.length) / v + free
    steps = int(np.ceil(duration / h))
    if steps > _MAX_STEPS or (steps + 1) * load.positions.size > _MAX_AXLE_SAMPLES:
        raise ValueError(
            f"time_step {h!r} s gives {steps} steps over the {duration:.4g} s run (at speed {v!r} m/s) for "
            f"{load.positions.size} axles; at most {_MAX_STEPS} steps and {_MAX_AXLE_SAMPLES:.0e} "
            "axle-steps are allowed (a longer step, fewer modes or a shorter train)"
        )
    time = np.arange(steps + 1) * h
    x_axles = v * time[:, None] - load.positions[None, :]
    rail = _rail(irregularity, load, L, x_axles)

    grid = np.linspace(0.0, L, _TABLE_POINTS_PER_MODE * len(beam.frequencies_hz) + 1)
    tables = [np.ascontiguousarray(beam.mode_shapes(grid, d)) for d in range(3)]
    omega = 2 * np.pi * np.asarray(beam.frequencies_hz, dtype=float)
    mu = np.asarray(beam.modal_masses, dtype=float)
    n, a = omega.size, load.positions.size
    if system is None:
        M = C = K = np.zeros((0, 0))
        GK = GC = np.zeros((0, a))
        KW = CW = np.zeros((a, a))
    else:
        M, C, K, GK, GC = mats.M, mats.C, mats.K, mats.GK, mats.GC
        KW, CW = system.input_stiffness, system.input_damping
    X, V, A = (np.zeros((steps + 1, n + p)) for _ in range(3))
    F = np.zeros((steps + 1, a))
    # Writable copies, whatever the vehicle's own arrays are: numba compiles a kernel anew for read-only
    # arguments, and a crossing by axle loads alone and one by a vehicle share one compiled march.
    bad = _kernel.march(
        h, steps, v, L, grid[1] - grid[0], *tables, mu, 2 * beam.damping_ratio * omega * mu, omega**2 * mu,
        *(np.array(z, dtype=float, order="C") for z in (M, C, K, GK, GC, KW, CW)),
        load.static_loads, load.unsprung_masses, load.positions, rail, X, V, A, F,
    )  # fmt: skip

    at_out = [beam.mode_shapes([x_out], d)[:, 0] for d in (0, 2)]
    flexibility = at_out[0] / (mu * omega**2)  # w(x_out) per unit modal force, by the modes kept
    influence = np.interp(x_axles, grid, flexibility @ tables[0], left=0.0, right=0.0)
    last = steps + 1 if bad < 0 else max(bad, 1)  # the partial result: the steps that stayed finite
    result = BridgeCrossing(
        speed=v,
        at=float(x_out),
        time=time[:last],
        deflection=X[:last, :n] @ at_out[0],
        static_deflection=influence[:last] @ load.static_loads,
        moment=-beam.flexural_rigidity * (X[:last, :n] @ at_out[1]),
        deck_acceleration=A[:last, :n] @ at_out[0],
        contact_forces=F[:last],
        modal=np.stack([X[:last, :n], V[:last, :n]], axis=1),
        vehicle=None if system is None else np.stack([X[:last, n:], V[:last, n:], A[:last, n:]], axis=1),
        vehicle_labels=() if system is None else system.labels,
    )
    if bad >= 0:
        raise SolverError("the coupled state became non-finite", step=bad, time=bad * h, partial=result)
    return result
