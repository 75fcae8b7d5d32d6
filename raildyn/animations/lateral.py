"""Lateral motion in plan, from the nonlinear models' own runs: the hunting wheelset (chapter 5), the
hunting bogie (chapter 7) and the bogie through a curve's entry (chapter 8).

Each function runs the model (:func:`raildyn.stability.nonlinear.simulate`,
:func:`raildyn.curving.entry.curve_entry`), picks evenly spaced times of the run, and moves a schematic of
:mod:`raildyn.diagrams` to the state at each (:class:`~raildyn.diagrams.rolling.WheelsetPlan`,
:class:`~raildyn.diagrams.vehicles.BogiePlan`), with the run's trace below and a cursor at the frame's
time. Hunting amplitudes are millimetres and milliradians on a track 1.5 m wide: the plan draws them
exaggerated, by the round factor that fits the run's largest motion, and says so on the picture.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks, diagrams
from raildyn.animations import _frames
from raildyn.animations.player import Animation, record
from raildyn.curving import curve_entry
from raildyn.stability import simulate
from raildyn.track import Curve
from raildyn.vehicles import Bogie
from raildyn.wheelset import NonlinearWheelset, WheelRailContact, Wheelset

__all__ = ["bogie_curve_entry", "hunting_bogie", "hunting_wheelset"]

# Chapter 5's soft wheelset (notebook 05: k_ψ = 2 MN·m/rad, k_y = 1 MN/m), which hunts at 60 m/s.
_SOFT = Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)
# Chapter 8's entry: a 600 m curve with 100 mm of cant and 60 m transitions (the widget's curve).
_ENTRY = Curve(radius=600.0, cant=0.1, transition_length=60.0, arc_length=80.0, straight=20.0)


def _window(duration, window) -> tuple[float, float]:
    T = _checks.scalar("duration", duration, low=0.1, high=30.0)
    w = _checks.scalar("window", window, low=0.05, high=T)
    return T, w


def _start(initial_displacement) -> float:
    y0 = _checks.scalar("initial_displacement", initial_displacement, low=-0.02, high=0.02)
    if abs(y0) < 1e-6:
        # a centred wheelset never starts to hunt, and one off by less than a micrometre not in seconds
        raise ValueError(f"initial_displacement must be 1e-06 m to 0.02 m either side, got {y0!r}")
    return y0


def hunting_wheelset(
    ws: Wheelset | None = None,
    speed: float = 60.0,
    *,
    duration: float = 3.0,
    window: float = 0.8,
    frames: int = 36,
    initial_displacement: float = 0.008,
) -> Animation:
    """The nonlinear wheelset hunting, in plan: its own run, the last ``window`` seconds animated.

    The wheelset with its cone, saturating creep and flange (:class:`~raildyn.wheelset.NonlinearWheelset`
    on a :class:`~raildyn.wheelset.WheelRailContact`) starts ``initial_displacement`` to the side
    and runs ``duration`` seconds at ``speed`` (:func:`raildyn.stability.nonlinear.simulate`); the frames
    cover the run's last ``window`` seconds, where above the critical speed it has settled on its
    limit cycle. Below: y and ψ over the whole run, the window shaded.

    Parameters
    ----------
    ws : raildyn.wheelset.Wheelset, optional
        The wheelset; default chapter 5's soft one (k_ψ = 2 MN·m/rad, k_y = 1 MN/m).
    speed : float
        V, m/s, in [1, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    duration : float
        s run, in [0.1, 30].
    window : float
        s animated at the run's end, in [0.05, ``duration``].
    frames : int
        In [2, 400].
    initial_displacement : float
        y₀, m, either side, 10⁻⁶ ≤ |y₀| ≤ 0.02.

    Returns
    -------
    Animation
    """
    ws = _SOFT if ws is None else _checks.instance("ws", ws, Wheelset, "raildyn.wheelset.Wheelset")
    T, w = _window(duration, window)
    n = _frames.frame_count(frames)
    y0 = _start(initial_displacement)
    run = simulate(NonlinearWheelset(ws, WheelRailContact()), speed, [y0, 0.0, 0.0, 0.0], T)
    y, psi = run.states[0], run.states[1]
    pick = _frames.picks(run.t, T - w, T, n)
    a = ws.half_gauge
    factor = min(
        _frames.exaggeration(np.abs(y[pick]).max(), 0.9 * 0.25 * a),
        _frames.exaggeration(np.abs(psi[pick]).max(), 0.9 * np.pi / 6),
    )
    fig, (ax_plan, ax_time) = _frames.figure()
    plan = diagrams.wheelset_plan(ws, exaggerate=factor, ax=ax_plan)
    cursor = _frames.trace(
        ax_time, run.t, {"y (mm)": 1e3 * y, "ψ (mrad)": 1e3 * psi}, ylabel="y, ψ", window=(T - w, T)
    )

    def draw(i: int) -> None:
        k = pick[i]
        plan.update(y[k], psi[k])
        cursor.set_xdata([run.t[k]])

    labels = [f"t = {run.t[k]:.3f} s, V = {run.speed:g} m/s" for k in pick]
    moving = _frames.artists({k: v for k, v in plan.artists.items() if k != "rails"}, cursor)
    title = f"the nonlinear wheelset hunting at {run.speed:g} m/s, in plan"
    return record(fig, draw, labels, title=title, moving=moving)


def hunting_bogie(
    bogie: Bogie | None = None,
    speed: float = 80.0,
    *,
    duration: float = 3.0,
    window: float = 0.6,
    frames: int = 36,
    initial_displacement: float = 0.008,
) -> Animation:
    """The bogie hunting, in plan: frame and wheelsets from the nonlinear bogie's own run.

    The bogie's nonlinear model (``bogie.nonlinear()``: cone, saturating creep, flange) starts with
    its leading wheelset ``initial_displacement`` to the side and runs ``duration`` seconds at
    ``speed`` (:func:`raildyn.stability.nonlinear.simulate`); the frames cover the run's last ``window``
    seconds. :class:`~raildyn.diagrams.vehicles.BogiePlan` moves the frame and both wheelsets, springs
    stretching between them; below, each wheelset's y over the whole run.

    Parameters
    ----------
    bogie : raildyn.vehicles.Bogie, optional
        Default :class:`~raildyn.vehicles.Bogie` (chapter 7's), which hunts at 80 m/s.
    speed : float
        V, m/s, in [1, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    duration : float
        s run, in [0.1, 30].
    window : float
        s animated at the run's end, in [0.05, ``duration``].
    frames : int
        In [2, 400].
    initial_displacement : float
        y₀ of the leading wheelset, m, either side, 10⁻⁶ ≤ |y₀| ≤ 0.02.

    Returns
    -------
    Animation
    """
    bogie = Bogie() if bogie is None else _checks.instance("bogie", bogie, Bogie, "raildyn.vehicles.Bogie")
    T, w = _window(duration, window)
    n = _frames.frame_count(frames)
    y0 = _start(initial_displacement)
    model = bogie.nonlinear()
    labels = list(model.system.labels)
    state = np.zeros(model.state_size)
    state[model.lateral_index] = y0
    run = simulate(model, speed, state, T)
    order = np.argsort(-model.system.wheelset_positions)  # the leading wheelset (x = +b) first
    rows = [model.system.wheelsets[j][:2] for j in order]
    frame = run.states[[labels.index("frame y"), labels.index("frame ψ")]]
    wheelsets = np.stack([run.states[list(r)] for r in rows])  # (2, 2, n_t)
    pick = _frames.picks(run.t, T - w, T, n)
    a = bogie.wheelset.half_gauge
    ys = np.concatenate([frame[0, pick], wheelsets[:, 0, pick].ravel()])
    psis = np.concatenate([frame[1, pick], wheelsets[:, 1, pick].ravel()])
    factor = min(
        _frames.exaggeration(np.abs(ys).max(), 0.9 * 0.25 * a),
        _frames.exaggeration(np.abs(psis).max(), 0.9 * np.pi / 12),
    )
    fig, (ax_plan, ax_time) = _frames.figure(heights=(2.4, 1.0))
    plan = diagrams.BogiePlan(bogie, exaggerate=factor, ax=ax_plan)
    cursor = _frames.trace(
        ax_time,
        run.t,
        {"leading y (mm)": 1e3 * wheelsets[0, 0], "trailing y (mm)": 1e3 * wheelsets[1, 0]},
        ylabel="y (mm)",
        window=(T - w, T),
    )

    def draw(i: int) -> None:
        k = pick[i]
        plan.update(frame[:, k], wheelsets[:, :, k])
        cursor.set_xdata([run.t[k]])

    labels = [f"t = {run.t[k]:.3f} s, V = {run.speed:g} m/s" for k in pick]
    moving = _frames.artists(_bogie_moving(plan), cursor)
    return record(fig, draw, labels, title=f"the bogie hunting at {run.speed:g} m/s, in plan", moving=moving)


def bogie_curve_entry(
    bogie: Bogie | None = None,
    speed: float = 25.0,
    curve: Curve | None = None,
    *,
    frames: int = 40,
) -> Animation:
    """The bogie running from straight track into a curve, in plan on the straightened track.

    :func:`raildyn.curving.entry.curve_entry` runs the nonlinear bogie through the curve's transition onto
    its arc. Each frame draws the bogie on the track straightened (the rails straight, the curve's
    own turning taken out), each wheelset at its offset towards the outer rail (up the page) and
    its angle of attack, both exaggerated by the factor the picture states; the frame stands at the
    mean of its wheelsets. Below: each wheelset's offset against the distance run, the transition
    shaded, and a cursor at the frame's place.

    Parameters
    ----------
    bogie : raildyn.vehicles.Bogie, optional
        Default :class:`~raildyn.vehicles.Bogie`.
    speed : float
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    curve : raildyn.track.Curve, optional
        Default a 600 m curve with 100 mm of cant, 20 m of straight, a 60 m transition, 80 m of arc.
    frames : int
        In [2, 400].

    Returns
    -------
    Animation
    """
    bogie = Bogie() if bogie is None else _checks.instance("bogie", bogie, Bogie, "raildyn.vehicles.Bogie")
    curve = _ENTRY if curve is None else _checks.instance("curve", curve, Curve, "raildyn.track.Curve")
    n = _frames.frame_count(frames)
    run = curve_entry(bogie.nonlinear(), speed, curve)
    order = np.argsort(-run.positions)
    offset, attack = run.offset[order], run.angle_of_attack[order]
    s = run.distance
    pick = _frames.picks(s, s[0], s[-1], n)
    a, b = bogie.wheelset.half_gauge, bogie.semi_wheelbase
    # The frame is drawn on the chord through the wheelsets' centres: its yaw is their offsets' difference
    # over the wheelbase, which the exaggeration must keep within the plan too.
    chord = (offset[0] - offset[1]) / (2 * b)
    factor = min(
        _frames.exaggeration(np.abs(offset).max(), 0.9 * 0.25 * a),
        _frames.exaggeration(max(np.abs(attack).max(), np.abs(chord).max()), 0.9 * np.pi / 12),
    )
    fig, (ax_plan, ax_run) = _frames.figure(heights=(2.4, 1.0))
    plan = diagrams.BogiePlan(bogie, exaggerate=factor, ax=ax_plan)
    ax_plan.text(
        0.0,
        1.0,
        "outer rail ↑ (track straightened)",
        transform=ax_plan.transAxes,
        size=7,
        color="0.35",
        va="top",
    )
    start = curve.straight
    cursor = _frames.trace(
        ax_run,
        s,
        {"leading (mm)": 1e3 * offset[0], "trailing (mm)": 1e3 * offset[1]},
        ylabel="offset (mm)",
        xlabel="distance of the bogie's centre (m)",
        window=(start, start + curve.transition_length),
    )

    def draw(i: int) -> None:
        k = pick[i]
        # The model's coordinates are to the left; the run's offset and attack are towards the outer
        # rail, which the picture puts up the page, as y to the left.
        ws = np.stack([offset[:, k], attack[:, k]], axis=1)
        plan.update((offset[:, k].mean(), chord[k]), ws)
        cursor.set_xdata([s[k]])

    labels = [f"s = {s[k]:.1f} m, curvature {1e3 * curve.curvature(s[k]):.3f} 1/km" for k in pick]
    title = f"the bogie entering a {curve.radius:g} m curve at {run.speed:g} m/s"
    return record(fig, draw, labels, title=title, moving=_frames.artists(_bogie_moving(plan), cursor))


def _bogie_moving(plan: diagrams.BogiePlan) -> dict:
    """The artists of a bogie's plan that its ``update`` moves (not the rails, not the labels)."""
    return {k: v for k, v in plan.artists.items() if k not in ("rails", "texts")}
