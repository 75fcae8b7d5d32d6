"""Dynamic curve entry (book chapter 8): a nonlinear vehicle run from straight track through a
transition onto the arc of a :class:`~raildyn.track.curve.Curve`.

The run is the nonlinear model on the curve (:class:`raildyn.wheelset.NonlinearLateral` with
``curve``), integrated by :func:`raildyn.stability.nonlinear.simulate` from the centred state
with every wheelset on the straight. On the transition the wheelsets shift out and the flanges
take up the curving force; on a long enough arc the motion dies away to the quasi-static
equilibrium of :func:`raildyn.curving.quasi_static.quasi_static_curving`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.stability.nonlinear import simulate
from raildyn.track import Curve
from raildyn.wheelset import NonlinearLateral, wheel_forces

__all__ = ["CurveEntry", "curve_entry"]

# The front wheelset starts this far before the curve's s = 0 (on the straight), m.
_LEAD_IN = 5.0


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class CurveEntry(Tabular):
    """A run through a curve's entry, sampled at the solver's steps.

    Attributes
    ----------
    speed : float
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    curve : Curve
    distance : ndarray, (m,)
        s_c, the vehicle centre's distance along the curve, m (increasing).
    positions : ndarray, (k,)
        x of each wheelset ahead of the vehicle's centre, m.
    offset : ndarray, (k, m)
        Each wheelset's lateral displacement from the track's centre line, towards the outer
        rail, m.
    angle_of_attack : ndarray, (k, m)
        Each wheelset's yaw from the track's tangent, rad, positive pointing to the outer rail.
    flange_force : ndarray, (k, m)
        The flange's lateral force on each wheelset, towards the curve's centre, N (0 off the
        flange).

    All finite and of the shapes above.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("distance", "m"), ("offset", "m"), ("angle_of_attack", "rad"), ("flange_force", "N"))
    _scalars = (("speed", "m/s"),)
    _by_row = ("offset", "angle_of_attack", "flange_force")

    speed: float
    curve: Curve
    distance: np.ndarray
    positions: np.ndarray
    offset: np.ndarray
    angle_of_attack: np.ndarray
    flange_force: np.ndarray

    def __post_init__(self):
        _checks.speed("speed", self.speed)
        _checks.instance("curve", self.curve, Curve)
        m = _checks.array("distance", self.distance, ndim=1, allow_empty=False).shape[0]
        k = _checks.array("positions", self.positions, ndim=1, allow_empty=False).shape[0]
        for name in ("offset", "angle_of_attack", "flange_force"):
            _checks.array(name, getattr(self, name), shape=(k, m))

    def plot(self, ax=None, *, artists: dict | None = None, quantity: str = "flange_force") -> dict:
        """One quantity of every wheelset against the distance of the vehicle's centre.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (a new figure when None).
        artists : dict, optional
            What an earlier call returned: its lines are updated in place.
        quantity : str
            "flange_force" (kN), "offset" (mm) or "angle_of_attack" (mrad).

        Returns
        -------
        dict
            ``lines`` (one per wheelset) and ``marks`` (the start and end of the entry transition).
        """
        from raildyn.plots import axes_or_new

        name = _checks.choice("quantity", quantity, _UNITS)
        scale, unit = _UNITS[name]
        values = scale * getattr(self, name)
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
            if len(artists.get("lines", ())) != len(values):
                n = len(values)
                raise ValueError(f"artists must come from a plot of {n} wheelsets, got {artists!r:.60}")
            for line, row in zip(artists["lines"], values, strict=True):
                line.set_data(self.distance, row)
            return artists
        ax = axes_or_new(ax)
        lines = [
            ax.plot(self.distance, row, label=f"wheelset at x = {x:+.2f} m")[0]
            for row, x in zip(values, self.positions, strict=True)
        ]
        start = self.curve.straight
        marks = [ax.axvline(s, color="0.6", ls=":") for s in (start, start + self.curve.transition_length)]
        ax.set_xlabel("distance of the vehicle's centre along the curve (m)")
        ax.set_ylabel(f"{name.replace('_', ' ')} ({unit})")
        ax.legend(fontsize=8)
        return {"lines": lines, "marks": marks}


_UNITS = {"flange_force": (1e-3, "kN"), "offset": (1e3, "mm"), "angle_of_attack": (1e3, "mrad")}


def curve_entry(model, speed, curve, *, max_step: float = 0.01, rtol: float = 1e-6) -> CurveEntry:
    """Run a nonlinear lateral model from straight track into a curve and along its arc.

    The vehicle starts centred and at rest in the axes that follow it, its front wheelset
    5 m before the curve's s = 0, and runs until its front wheelset reaches the end of the arc.

    Parameters
    ----------
    model : NonlinearLateral
        The vehicle with nonlinear contact (e.g. ``LateralCar().nonlinear()``); its speed, curve
        and start are replaced.
    speed : float
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    curve : Curve
        Its run, from the start to the arc's end, must take at most 120 s; its arc must be
        longer than the vehicle.
    max_step, rtol : float
        As for :func:`raildyn.stability.nonlinear.simulate` (the default step of 10 ms resolves
        the vehicle's modes, below 10 Hz).

    Returns
    -------
    CurveEntry

    Raises
    ------
    SolverError
        If the integration fails.

    Examples
    --------
    >>> from raildyn.vehicles import Bogie
    >>> run = curve_entry(Bogie().nonlinear(), 25.0, Curve(radius=1500.0, cant=0.05, arc_length=60.0))
    >>> run.offset.shape[0], round(float(run.distance[-1]), 6)  # the arc's end, 50 + 60 + 60 m, less b
    (2, 168.72)
    """
    _checks.instance("model", model, NonlinearLateral)
    V = _checks.speed("speed", speed)
    _checks.instance("curve", curve, Curve)
    x = model.system.wheelset_positions
    start = -x.max() - _LEAD_IN
    end = curve.straight + curve.transition_length + curve.arc_length - x.max()  # all on the arc
    on_curve = model.replace(curve=curve, start=start)
    if end <= curve.straight + curve.transition_length - x.min():
        raise ValueError(
            f"curve must have an arc longer than the vehicle ({np.ptp(x):.4g} m), got {curve.arc_length!r} m"
        )
    duration = (end - start) / V
    if duration > 120.0:
        raise ValueError(
            f"curve must be run within 120 s at speed {V:g} m/s, got {end - start:.4g} m ({duration:.4g} s)"
        )
    run = simulate(on_curve, V, np.zeros(on_curve.state_size), duration, max_step=max_step, rtol=rtol)
    offset, yaw = on_curve.relative_to_track(run.t, run.states, V)
    flange = np.empty_like(offset)
    for i, (_, _, ws) in enumerate(on_curve.system.wheelsets):
        forces = wheel_forces(ws, model.contact, offset[i], 0.0, 0.0, 0.0, V)
        flange[i] = forces.flange.sum(axis=0)
    return CurveEntry(V, curve, start + V * run.t, x, -offset, -yaw, flange)
