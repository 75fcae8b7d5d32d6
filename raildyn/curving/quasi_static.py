"""Nonlinear quasi-static curving (book chapter 8): a vehicle's equilibrium in a curve with
saturating creep and flange contact, at one point or over a map of speeds and radii.

The model is any :class:`raildyn.wheelset.NonlinearLateral` (``LateralCar().nonlinear()``, the freight
car's, the locomotive's) on a circular arc, in the axes that follow the vehicle (described there
and in :mod:`raildyn.curving.steady`). At rest in those axes its velocities vanish, and the
equilibrium is the zero of its forces (:meth:`~raildyn.wheelset.NonlinearLateral.arc_forces`).

The search: Newton's method on every point at once (:func:`raildyn.wheelset.arc_newton`: the forces
of a batch of states are one evaluation, compiled where the engine holds the model, and so is their
Jacobian, :meth:`~raildyn.wheelset.NonlinearLateral.arc_jacobian`; steps halved until the residual
falls), started from the linear steady state of :func:`raildyn.curving.steady.steady_curving`. Points
where the flange contact or the creep saturation stalls it are continued from their solved
neighbours, then by a homotopy that raises the curve's load from nothing in adaptive steps; a
point left after that is taken up alone by Powell's hybrid method, Levenberg–Marquardt, Powell
from the centred state, and finally Powell after a short run of the dynamics (the creep damps
it towards the equilibrium), before a :class:`~raildyn.errors.SolverError`.

Friction elements (:class:`~raildyn.wheelset.SuspensionElement` laws that depend only on the
rate) carry no force at rest, so the equilibrium found is the one friction does not hold
elsewhere.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import lru_cache, partial

import numpy as np

from raildyn import _checks
from raildyn.constants import GRAVITY
from raildyn.curving.steady import SteadyCurving, steady_curving
from raildyn.errors import SolverError
from raildyn.track import MAXIMUM_CANT, MINIMUM_RADIUS, Curve, balance_speed, unbalanced_acceleration
from raildyn.wheelset import (
    NonlinearLateral,
    arc_newton,
    contact_forces,
    track_on_arc,
    tread_contact_angles,
    wheel_forces,
)

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.optimize.root,
# raildyn.integrators.runner.solve_ivp

__all__ = ["CurvingMap", "QuasiStaticCurving", "curving_map", "quasi_static_curving"]

# The arc reaches this far either side of the vehicle's centre, m: beyond any wheelset (≤ 100 m).
_HALF_ARC = 200.0
# Equilibrium: the largest force left over, as a fraction of the vehicle's weight (a part in 1e9 of
# about 3e5 N is 0.3 mN, far below any force that matters and above the rounding of the sums).
_TOLERANCE = 1.0e-9
# No wheelset on the rails is further from the track's centre line, m (a flange is about 30 mm high and
# a wheel's tread 130 mm wide: beyond this the wheel has left its rail).
_ON_THE_RAILS = 0.05
# The short run of the dynamics that brings a stalled search near the equilibrium, s.
_SETTLE = 3.0
# Newton's steps before the points it leaves go to the single-point searches.
_NEWTON_STEPS = 30
# Rounds of the continuation from solved neighbours (the map's points converge within three or four).
_CONTINUATIONS = 6


@dataclass(frozen=True, eq=False)
class QuasiStaticCurving(SteadyCurving):
    """A nonlinear model's equilibrium in a curve to the left.

    The fields of :class:`~raildyn.curving.steady.SteadyCurving` (the creep forces now
    saturated), and:

    Attributes
    ----------
    guiding_force : ndarray, (k,)
        The rails' whole lateral force on each wheelset (creep, gravity and flange), towards
        the curve's centre, N.
    flange_force : ndarray, (k,)
        The flange's share of it, N (≥ 0 on the outer rail, ≤ 0 on the inner; 0 off the flange).
    flange_contact : ndarray of bool, (k,)
        Whether each wheelset's flange touches a rail (|offset| beyond the flangeway clearance).
    wear_number : ndarray, (k,)
        E_w (the literature's Tγ) of each wheelset's two wheels together: the creep forces' energy
        dissipated per metre run, N (≥ 0).
    wheel_lateral : ndarray, (k, 2)
        Y, the rail's lateral force on each wheel [inner, outer] in the track's plane, towards
        the curve's centre, N: the creep force, the tread's normal force tilted by its contact
        angle, and on a flanging wheel the flange's.
    wheel_vertical : ndarray, (k, 2)
        Q, the rail's vertical force on each wheel [inner, outer], N (> 0): half the axle load
        moved to the outer wheel by the unbalanced acceleration acting at the centre of gravity.

    Y and Q are found from the equilibrium, after it: the lateral model itself keeps equal
    wheel loads (in the creep saturation and the gravitational stiffness), so the sum of an
    axle's two Y differs from its guiding force by the tread's share of the load transfer,
    (Q_o − Q_i) tan ϑ₀, and of the flange's relief, a few per cent of the flange force.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("positions", "m"), ("offset", "m"), ("angle_of_attack", "rad"), ("longitudinal_creep_force", "N"),
        ("lateral_creep_force", "N"), ("guiding_force", "N"), ("flange_force", "N"),
        ("flange_contact", "-"), ("wear_number", "N"), ("wheel_lateral", "N"), ("wheel_vertical", "N"),
    )  # fmt: skip
    _scalars = (("radius", "m"), ("speed", "m/s"), ("cant", "m"), ("unbalanced_acceleration", "m/s²"))

    guiding_force: np.ndarray
    flange_force: np.ndarray
    flange_contact: np.ndarray
    wear_number: np.ndarray
    wheel_lateral: np.ndarray
    wheel_vertical: np.ndarray

    def __post_init__(self):
        super().__post_init__()
        k = len(self.positions)
        _checks.array("wheel_lateral", self.wheel_lateral, shape=(k, 2))
        _checks.array("wheel_vertical", self.wheel_vertical, shape=(k, 2), low=0.0, low_open=True)
        for name in ("guiding_force", "flange_force"):
            _checks.array(name, getattr(self, name), shape=(k,))
        _checks.array("wear_number", self.wear_number, shape=(k,), low=0.0)
        contact = np.asarray(self.flange_contact)
        if contact.dtype != bool or contact.shape != (k,):
            raise ValueError(f"flange_contact must be {k} bools, got {self.flange_contact!r:.80}")

    @property
    def derailment_quotient(self) -> np.ndarray:
        """Y/Q of each wheel [inner, outer], (k, 2): the quotient that Nadal's limit bounds
        (:func:`raildyn.curving.climb.nadal_limit`) on the flanging wheel."""
        return np.abs(self.wheel_lateral) / self.wheel_vertical


def _weight(model: NonlinearLateral) -> float:
    """N, of the order of the vehicle's weight (the inertias on the diagonal add a little): the scale of
    the residual."""
    return GRAVITY * float(np.trace(model.system.M))


def _newton(model, q, V, kappa, a_q) -> tuple[np.ndarray, np.ndarray]:
    """Newton's method on the columns of q (n, P) together (:func:`raildyn.wheelset.arc_newton`, the one
    Newton of every model); the converged columns' flags (P,)."""
    return arc_newton(model, q, V, kappa, a_q, tolerance=_TOLERANCE * _weight(model), steps=_NEWTON_STEPS)


def _rescue(model: NonlinearLateral, start: np.ndarray, V: float, R: float, D: float) -> np.ndarray:
    """One point that Newton left, by the searches of the module docstring, or a SolverError."""
    from scipy.optimize import root

    from raildyn.integrators.runner import solve_ivp

    n = model.system.size
    rest = np.zeros(n)
    kappa, a_q = 1.0 / R, unbalanced_acceleration(V, R, D)

    def residual(q):
        return model.arc_forces(q, V, kappa, a_q)

    tolerance = _TOLERANCE * _weight(model)
    trials = [("hybr", start), ("lm", start), ("hybr", rest)]
    best = start
    for k in range(len(trials) + 1):
        if k == len(trials):  # the dynamics on the arc, from the best guess so far, then Powell once more
            arc = Curve(radius=R, cant=D, transition_length=0.0, arc_length=2 * _HALF_ARC, straight=0.0)
            on_arc = model.replace(curve=arc, start=_HALF_ARC)
            label = f"the settling run at V = {V:g} m/s in R = {R:g} m"
            start = np.concatenate([best, rest])
            run = solve_ivp(
                partial(on_arc.rhs, speed=V), (0.0, _SETTLE), start, rtol=1e-6, atol=1e-9, label=label
            )
            trials.append(("hybr", run.y[:n, -1]))
        method, guess = trials[k]
        found = root(residual, guess, method=method, tol=1e-12)
        if np.all(np.isfinite(found.x)):
            error = np.abs(residual(found.x)).max()
            if error <= tolerance:
                return found.x
            if error < np.abs(residual(best)).max():
                best = found.x
    raise SolverError(
        f"no equilibrium at V = {V:g} m/s in R = {R:g} m within {tolerance:.3g} N after {len(trials)} "
        f"searches (the last left {np.abs(residual(best)).max():.3g} N)"
    )


@lru_cache(maxsize=32)
def _linear_basis(system) -> tuple[np.ndarray, np.ndarray]:
    """u and w with the linear steady state u κ + w a_q, from two solves (cached for the system).

    The curve's loads on the wheelsets are proportional to κ = 1/R whatever the speed, and the cant
    deficiency's to a_q, so one solve at the balance speed (a_q = 0) gives u and one with a_q ≠ 0 gives w.
    """
    R0 = 1000.0
    u = R0 * steady_curving(system, balance_speed(R0, 0.1), R0, 0.1).displacement
    fast = steady_curving(system, 30.0, R0, 0.0)
    return u, (fast.displacement - u / R0) / fast.unbalanced_acceleration


def _linear_starts(system, V: np.ndarray, R: np.ndarray, D: float) -> np.ndarray:
    """The linear steady states (n, P) at each (V, R) of a cant h_t."""
    u, w = _linear_basis(system)
    return np.outer(u, 1.0 / R) + np.outer(w, unbalanced_acceleration(V, R, D))


def _solve(model: NonlinearLateral, V: np.ndarray, R: np.ndarray, D: float, start=None) -> np.ndarray:
    """The equilibria (n, P) at the points (V, R) of a cant h_t.

    Newton on all the points from ``start`` (n, P) if given, else from their linear states; then, a
    few times over, on the points it left, each from the equilibrium of its nearest solved neighbour
    in (1/R, a_q) moved by the linear model's change between the two (a continuation with a linear
    predictor: the flange and the saturation that stall Newton from far away are crossed in small
    steps); then each point still left alone, by :func:`_homotopy` and failing that :func:`_rescue`.
    """
    kappa, a_q = 1.0 / R, unbalanced_acceleration(V, R, D)
    q0 = _linear_starts(model.system, V, R, D)
    q, done = _newton(model, q0 if start is None else start, V, kappa, a_q)
    where = np.stack([kappa / np.ptp(kappa) if np.ptp(kappa) else kappa, a_q / (np.ptp(a_q) or 1.0)])
    for _ in range(_CONTINUATIONS):
        left = np.flatnonzero(~done)
        if left.size == 0 or not done.any():
            break
        solved = np.flatnonzero(done)
        gap = ((where[:, left, None] - where[:, None, solved]) ** 2).sum(axis=0)
        nearest = solved[gap.argmin(axis=1)]
        # the neighbour's equilibrium moved by the linear model's change between the two points
        start = q[:, nearest] + q0[:, left] - q0[:, nearest]
        q[:, left], done[left] = _newton(model, start, V[left], kappa[left], a_q[left])
    for p in np.flatnonzero(~done):
        found = _homotopy(model, float(V[p]), float(kappa[p]), float(a_q[p]))
        q[:, p] = found if found is not None else _rescue(model, q0[:, p], float(V[p]), float(R[p]), D)
    return q


def _homotopy(model: NonlinearLateral, V: float, kappa: float, a_q: float) -> np.ndarray | None:
    """One point by a homotopy in the curve's load: κ and a_q raised from 0 to theirs, Newton at each
    share started from the last; a share that fails is approached in halved steps. None if the step
    falls below a thousandth."""
    q = np.zeros((model.system.size, 1))
    share, step = 0.0, 0.1
    while share < 1.0:
        trial = min(1.0, share + step)
        found, ok = _newton(model, q, np.array([V]), np.array([trial * kappa]), np.array([trial * a_q]))
        if ok[0]:
            q, share, step = found, trial, min(2 * step, 0.25)
        else:
            step /= 2
            if step < 1e-3:
                return None
    return q[:, 0]


def _wheels(
    model: NonlinearLateral,
    q: np.ndarray,
    V: np.ndarray,
    R: np.ndarray,
    D: float,
    h: float,
):
    """Per-wheelset results for the equilibria q (n, P) at the speeds V and radii R (P,): a dict of arrays
    whose first axis is the wheelset (k) and then P (and 2 wheels [inner, outer] for Y and Q)."""
    system = model.system
    x = system.wheelset_positions
    iy = np.array([w[0] for w in system.wheelsets])
    ipsi = np.array([w[1] for w in system.wheelsets])
    # relative to the track where each wheelset runs on the arc (y_t = ½x²/R, its tangent x/R)
    y_t, psi_t = track_on_arc(x[:, None], 1.0 / R[None, :])
    y, psi = q[iy] - y_t, q[ipsi] - psi_t
    if np.abs(y).max() > _ON_THE_RAILS:
        raise SolverError(
            f"the only equilibrium found has a wheelset {1e3 * np.abs(y).max():.4g} mm off the track's "
            f"centre line, beyond the {1e3 * _ON_THE_RAILS:g} mm at which a wheel leaves its rail: it derails"
        )
    a_q = unbalanced_acceleration(V, R, D)
    k, P = y.shape
    out = {name: np.empty((k, P)) for name in ("longitudinal", "lateral", "guiding", "flange", "wear")}
    Y, Q = np.empty((k, 2, P)), np.empty((k, 2, P))
    for j, (_, _, ws) in enumerate(system.wheelsets):
        forces = wheel_forces(ws, model.contact, y[j], psi[j], 0.0, V / R, V)
        out["longitudinal"][j] = forces.longitudinal[1]  # the right wheel, outer in a left-hand curve
        out["lateral"][j] = -forces.lateral.sum(axis=0)  # towards the outer rail
        out["flange"][j] = forces.flange.sum(axis=0)
        out["wear"][j] = forces.wear_number.sum(axis=0)
        out["guiding"][j] = contact_forces(ws, model.contact, y[j], psi[j], 0.0, V / R, V)[0]
        # Q: each wheel's share of the axle load with the roll moment of m a_q at h; a flange bears
        # its flange_vertical of it, the tread the rest, tilted by its contact angle
        # (tread_contact_angles) towards the track's centre line (inner wheel: to the right, outer: left).
        a, W = ws.half_gauge, ws.axle_load
        transfer = 0.5 * W * h / a * a_q / GRAVITY
        Q[j] = 0.5 * W - transfer, 0.5 * W + transfer
        tread = Q[j] - forces.flange_vertical
        tilt = tread_contact_angles(ws, model.contact, y[j])
        Y[j] = forces.lateral + forces.flange + np.array([[-1.0], [1.0]]) * tread * np.tan(tilt)
    if np.any(Q <= 0.0):
        raise SolverError(
            f"the inner wheels are lifted: an unbalanced acceleration of up to {np.max(a_q):.4g} m/s² at "
            f"cg_height = {h:g} m moves more than the whole wheel load to the outer rail (the car overturns)"
        )
    out.update(offset=-y, angle_of_attack=-psi, contact=np.abs(y) > model.contact.flange_clearance, Y=Y, Q=Q)
    return out


def _options(speed_name, radius_name, speed, radius, cant, cg_height, flange_angle, model):
    """The checked (V, R, h_t, h) of either public function, and the model with the flange angle ϑ_f
    given (the model contact's by default) in its contact."""
    if flange_angle is None:
        flange_angle = model.contact.flange_angle
    V = np.atleast_1d(_checks.plausible_array(speed_name, speed, "speed", low_open=True, allow_empty=False))
    R = np.atleast_1d(_checks.array(radius_name, radius, low=MINIMUM_RADIUS, allow_empty=False))
    D = _checks.scalar("cant", cant, low=0.0, high=MAXIMUM_CANT)
    h = _checks.scalar("cg_height", cg_height, low=0.0, low_open=True, high=4.0)
    delta = _checks.scalar(
        "flange_angle", flange_angle, low=0.0, high=np.pi / 2, low_open=True, high_open=True
    )
    if delta != model.contact.flange_angle:
        model = model.replace(contact=replace(model.contact, flange_angle=delta))
    return V, R, D, h, model


def quasi_static_curving(
    model, speed, radius, cant=0.0, *, cg_height=1.8, flange_angle=None, start=None
) -> QuasiStaticCurving:
    """The equilibrium of a nonlinear lateral model in a curve to the left, flanges included.

    Parameters
    ----------
    model : NonlinearLateral
        The vehicle with nonlinear contact (e.g. ``LateralCar().nonlinear()``); its speed, curve
        and start are replaced.
    speed : float
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    radius : float
        R, m (≥ :data:`~raildyn.track.cant.MINIMUM_RADIUS`, 50 m).
    cant : float
        h_t, m, in [0, :data:`~raildyn.track.cant.MAXIMUM_CANT`] (0.2 m).
    cg_height : float
        h, height of the vehicle's centre of gravity above the rails, m, in (0, 4]: the
        unbalanced acceleration moves ΔQ = (W/2)(h/a)(a_q/g) of each axle's load W to the
        outer wheel. Default 1.8 m, the Manchester car's body (Iwnicki 1998).
    flange_angle : float, optional
        ϑ_f, the flange's contact angle, rad, in (0, π/2): the flange's normal force, whose
        lateral part the flange spring gives, bears F/tan ϑ_f of the wheel's load (so that
        the tread bears the rest). Default: the ``flange_angle`` of the model's
        :class:`~raildyn.wheelset.WheelRailContact` (70° on a cone, the S1002 wheel's flank,
        and a profile pair's own); given, it replaces the contact's (on a two-point contact
        it shapes the flange's creep forces too).
    start : QuasiStaticCurving, optional
        A nearby equilibrium of the same model: Newton starts from it, moved by the linear
        model's change from its point to this one, so that a widget moving one control
        re-solves in a step or two. None: from the linear steady state.

    Returns
    -------
    QuasiStaticCurving

    Raises
    ------
    SolverError
        If no search finds the equilibrium (the module docstring), or the one found has a
        wheelset more than 50 mm off the centre line (off its rail).

    Examples
    --------
    The Manchester car in a 600 m curve at its balance speed for 100 mm of cant: the
    leading wheelsets run on their flanges at about 3.8 mrad.

    >>> from raildyn.track import balance_speed
    >>> from raildyn.vehicles import LateralCar
    >>> state = quasi_static_curving(LateralCar().nonlinear(), balance_speed(600.0, 0.1), 600.0, 0.1)
    >>> state.flange_contact.tolist(), round(1e3 * float(state.angle_of_attack[0]), 1)
    ([True, False, True, False], 3.8)
    """
    _checks.instance("model", model, NonlinearLateral)
    _checks.scalar("speed", speed)
    _checks.scalar("radius", radius)
    V, R, D, h, model = _options("speed", "radius", speed, radius, cant, cg_height, flange_angle, model)
    if start is not None:
        _checks.instance("start", start, QuasiStaticCurving)
        if start.labels != model.system.labels:
            raise ValueError(
                f"start must be an equilibrium of this model {model.system.labels}, got {start.labels}"
            )
        here = _linear_starts(model.system, V, R, D)
        there = _linear_starts(model.system, np.array([start.speed]), np.array([start.radius]), start.cant)
        start = start.displacement[:, None] + here - there
    q = _solve(model, V, R, D, start)
    out = _wheels(model, q, V, R, D, h)
    system = model.system
    return QuasiStaticCurving(
        float(R[0]), float(V[0]), D, unbalanced_acceleration(float(V[0]), float(R[0]), D), system.labels,
        q[:, 0], system.wheelset_positions, out["offset"][:, 0], out["angle_of_attack"][:, 0],
        out["longitudinal"][:, 0], out["lateral"][:, 0], out["guiding"][:, 0], out["flange"][:, 0],
        out["contact"][:, 0], out["wear"][:, 0], out["Y"][:, :, 0], out["Q"][:, :, 0],
    )  # fmt: skip


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class CurvingMap:
    """Quasi-static curving over a grid of radii and speeds.

    Attributes
    ----------
    radii : ndarray, (r,)
        R, m.
    speeds : ndarray, (s,)
        V, m/s.
    cant : float
        h_t, m.
    unbalanced_acceleration : ndarray, (r, s)
        a_q, m/s².
    offset, angle_of_attack, flange_force, wear_number : ndarray, (r, s, k)
        As in :class:`QuasiStaticCurving`, for each wheelset.
    derailment_quotient : ndarray, (r, s, k, 2)
        Y/Q of each wheel [inner, outer].

    All finite; radii ≥ 50 m and speeds > 0.
    """

    radii: np.ndarray
    speeds: np.ndarray
    cant: float
    unbalanced_acceleration: np.ndarray
    offset: np.ndarray
    angle_of_attack: np.ndarray
    flange_force: np.ndarray
    wear_number: np.ndarray
    derailment_quotient: np.ndarray

    def __post_init__(self):
        r = _checks.array("radii", self.radii, ndim=1, low=MINIMUM_RADIUS, allow_empty=False).size
        s = _checks.speeds("speeds", self.speeds).size
        _checks.nonnegative("cant", self.cant)
        _checks.array("unbalanced_acceleration", self.unbalanced_acceleration, shape=(r, s))
        k = _checks.array("offset", self.offset, shape=(r, s, None)).shape[2]
        for name in ("angle_of_attack", "flange_force"):
            _checks.array(name, getattr(self, name), shape=(r, s, k))
        _checks.array("wear_number", self.wear_number, shape=(r, s, k), low=0.0)
        _checks.array("derailment_quotient", self.derailment_quotient, shape=(r, s, k, 2), low=0.0)

    def plot(self, ax=None, *, quantity: str = "angle_of_attack", wheelset: int = 0) -> dict:
        """Contours of one quantity of one wheelset over speed (km/h) and radius (m).

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (a new figure when None).
        quantity : str
            "angle_of_attack" (mrad), "offset" (mm), "flange_force" (kN), "wear_number" (N) or
            "derailment_quotient" (the outer wheel's Y/Q).
        wheelset : int
            Which wheelset, in [0, k − 1] (0: the leading one).

        Returns
        -------
        dict
            ``contours`` (the filled contour set) and ``colorbar``.
        """
        from raildyn.plots import axes_or_new

        name = _checks.choice("quantity", quantity, _MAP_UNITS)
        j = _checks.integer("wheelset", wheelset, low=0, high=self.offset.shape[2] - 1)
        scale, unit = _MAP_UNITS[name]
        values = getattr(self, name)[:, :, j]
        if name == "derailment_quotient":
            values = values[..., 1]
        ax = axes_or_new(ax)
        contours = ax.contourf(3.6 * self.speeds, self.radii, scale * values, levels=12)
        colorbar = ax.figure.colorbar(contours, ax=ax, label=f"{name.replace('_', ' ')} ({unit})")
        ax.set_xlabel("speed (km/h)")
        ax.set_ylabel("radius (m)")
        ax.set_yscale("log")
        ax.set_title(f"wheelset {j + 1}, cant {1e3 * self.cant:g} mm")
        return {"contours": contours, "colorbar": colorbar}


_MAP_UNITS = {
    "angle_of_attack": (1e3, "mrad"),
    "offset": (1e3, "mm"),
    "flange_force": (1e-3, "kN"),
    "wear_number": (1.0, "N"),
    "derailment_quotient": (1.0, "outer wheel"),
}


def curving_map(model, speeds, radii, cant=0.0, *, cg_height=1.8, flange_angle=None) -> CurvingMap:
    """Quasi-static curving of a nonlinear lateral model over every pair of radius and speed.

    All the points are solved together (the module docstring): a 40 × 30 map of the bogie takes
    about the time of 40 single points.

    Parameters
    ----------
    model : NonlinearLateral
        As for :func:`quasi_static_curving`.
    speeds : array_like, (s,)
        V, m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    radii : array_like, (r,)
        R, m, each ≥ :data:`~raildyn.track.cant.MINIMUM_RADIUS`.
    cant : float
        h_t, m, in [0, :data:`~raildyn.track.cant.MAXIMUM_CANT`].
    cg_height : float
        As for :func:`quasi_static_curving`.
    flange_angle : float, optional
        As for :func:`quasi_static_curving`.

    Returns
    -------
    CurvingMap

    Raises
    ------
    SolverError
        If a point has no equilibrium with the wheels on the rails (as
        :func:`quasi_static_curving`).

    Examples
    --------
    >>> from raildyn.vehicles import Bogie
    >>> m = curving_map(Bogie().nonlinear(), [15.0, 25.0], [300.0, 600.0, 1200.0], 0.1)
    >>> m.angle_of_attack.shape
    (3, 2, 2)
    """
    _checks.instance("model", model, NonlinearLateral)
    s = _checks.array("speeds", speeds, ndim=1, allow_empty=False).size
    r = _checks.array("radii", radii, ndim=1, allow_empty=False).size
    V, R, D, h, model = _options("speeds", "radii", speeds, radii, cant, cg_height, flange_angle, model)
    # The points run over the speeds within each radius: point p is radius p // s, speed p % s.
    speeds, radii = np.tile(V, r), np.repeat(R, s)
    out = _wheels(model, _solve(model, speeds, radii, D), speeds, radii, D, h)
    k = len(model.system.wheelsets)
    fields = {
        name: out[key].T.reshape(r, s, k)
        for name, key in (("offset", "offset"), ("angle_of_attack", "angle_of_attack"),
                          ("flange_force", "flange"), ("wear_number", "wear"))
    }  # fmt: skip
    quotient = np.moveaxis(np.abs(out["Y"]) / out["Q"], 2, 0).reshape(r, s, k, 2)
    a_q = unbalanced_acceleration(V[None, :], R[:, None], D)
    return CurvingMap(R, V, D, a_q, **fields, derailment_quotient=quotient)
