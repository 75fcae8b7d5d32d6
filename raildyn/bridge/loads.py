"""What crosses a bridge, in increasing fidelity (chapter 10).

An :class:`AxleSequence` is the moving-force model of a train: the axles at fixed
distances behind the leading one, each a constant vertical force. A :class:`MovingLoad`
adds what the bridge feels back: each axle's unsprung mass riding on the rail, and the
sprung vehicle above it as a linear model whose track inputs are the rail heights under
the axles. The factories build the classical cases on one shape, so one solver
(:func:`raildyn.bridge.coupled.crossing`) takes them all:

* :func:`moving_load` — constant forces (the mass of the vehicle ignored);
* :func:`moving_mass` — a mass riding on the beam, its inertia felt by the beam;
* :func:`sprung_mass` — Biggs's sprung mass: a body on a spring and damper above a wheel;
* :func:`vehicle` — any vertical model of :mod:`raildyn.vehicles`, on its axles;
* :func:`train` — several of these coupled one behind the other.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.linalg import block_diag

from raildyn import _checks, _deprecated
from raildyn.constants import GRAVITY
from raildyn.linear_model import Assembler, LinearSystem, as_linear_system

__all__ = ["AxleSequence", "MovingLoad", "moving_load", "moving_mass", "sprung_mass", "train", "vehicle"]

# The old names of issue 33 (raildyn._deprecated.RENAMED): each warns and gives the new object;
# they go after one issue.
__getattr__ = _deprecated.module_getattr(__name__, globals())

_MAX_AXLES = 10_000  # a 2 km freight train has about 600


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class AxleSequence:
    """A train as constant axle forces at fixed spacings.

    Attributes
    ----------
    positions : ndarray, (a,)
        Distance of each axle behind the leading one, m: the first 0, then non-decreasing
        (at most 10 000 axles).
    loads : ndarray, (a,)
        Force of each axle on the rail, N (> 0, downwards).
    name : str
        What the sequence is, for legends.

    Examples
    --------
    Two bogies of two axles, 2.5 m apart in the bogie and 17.5 m between bogie centres:

    >>> train = AxleSequence([0.0, 2.5, 17.5, 20.0], [170e3] * 4, "coach")
    >>> train.length
    20.0
    """

    positions: np.ndarray
    loads: np.ndarray
    name: str = ""

    def __post_init__(self):
        x = _checks.array("positions", self.positions, ndim=1, low=0.0, allow_empty=False)
        if x.size > _MAX_AXLES:
            raise ValueError(f"positions must hold at most {_MAX_AXLES} axles, got {x.size}")
        if x[0] != 0.0 or np.any(np.diff(x) < 0.0):
            raise ValueError(
                f"positions must start at 0 (the leading axle) and never decrease, got {x[:8]}"
                + (" …" if x.size > 8 else "")
            )
        p = _checks.array("loads", self.loads, shape=x.shape, low=0.0, low_open=True)
        _checks.instance("name", self.name, str)
        x, p = x.copy(), p.copy()  # never freeze the caller's own arrays
        x.setflags(write=False)
        p.setflags(write=False)
        object.__setattr__(self, "positions", x)
        object.__setattr__(self, "loads", p)

    @property
    def length(self) -> float:
        """From the leading to the last axle, m."""
        return float(self.positions[-1])


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class MovingLoad:
    """Axles that press on the rail, their unsprung masses, and the sprung vehicle above them.

    Attributes
    ----------
    positions : ndarray, (a,)
        Distance of each axle behind the leading one, m (as :class:`AxleSequence`).
    static_loads : ndarray, (a,)
        Each axle's force on the rail at rest on a rigid track, N (> 0): its share of the
        sprung weight and its own.
    unsprung_masses : ndarray, (a,)
        The mass that rides rigidly on the rail at each axle, kg (≥ 0).
    system : LinearSystem or None
        The sprung vehicle, its coordinates measured from rest on a rigid track; track input j
        is the rail's height under axle j (vertical, both rails), and the system knows its
        inputs' own stiffness (:meth:`raildyn.linear_model.LinearSystem.input_forces`). None: no
        sprung part.
    name : str
        For legends.
    """

    positions: np.ndarray
    static_loads: np.ndarray
    unsprung_masses: np.ndarray
    system: LinearSystem | None = None
    name: str = ""

    def __post_init__(self):
        shape = _checks.array("positions", self.positions, ndim=1, allow_empty=False).shape
        loads = _checks.array("static_loads", self.static_loads, shape=shape, low=0.0, low_open=True)
        axles = AxleSequence(self.positions, loads)  # the same checks of place and load
        a = axles.positions.size
        m = _checks.array("unsprung_masses", self.unsprung_masses, shape=(a,), low=0.0).copy()
        m.setflags(write=False)
        _checks.instance("name", self.name, str)
        if self.system is not None:
            _checks.instance("system", self.system, LinearSystem)
            _sprung_system(self.system, a)
        object.__setattr__(self, "positions", axles.positions)
        object.__setattr__(self, "static_loads", axles.loads)
        object.__setattr__(self, "unsprung_masses", m)

    @property
    def length(self) -> float:
        """From the leading to the last axle, m."""
        return float(self.positions[-1])

    @property
    def axles(self) -> AxleSequence:
        """The same train as constant forces: the moving-force model of it."""
        return AxleSequence(self.positions, self.static_loads, self.name)


def _sprung_system(system: LinearSystem, axles: int) -> None:
    """Refuse a sprung system that cannot ride on the axles: inputs, kinds, reactions."""
    if system.n_inputs != axles:
        raise ValueError(f"system must have one track input per axle ({axles}), got {system.n_inputs}")
    if any(kind != "vertical" for kind in system.input_kinds) or np.any(system.input_rails != 0.0):
        raise ValueError(
            f"system's inputs must each be the height of both rails (vertical, rail 0), got kinds "
            f"{system.input_kinds} on rails {system.input_rails}"
        )
    if system.input_stiffness is None:
        raise ValueError("system must know its inputs' own stiffness (built by Assembler.element), got None")


def moving_load(axles: AxleSequence) -> MovingLoad:
    """Constant forces at the axles, nothing riding on the rail: the moving-force model.

    Parameters
    ----------
    axles : AxleSequence

    Returns
    -------
    MovingLoad

    Examples
    --------
    >>> load = moving_load(AxleSequence([0.0], [1.0e5]))
    >>> load.unsprung_masses
    array([0.])
    """
    _checks.instance("axles", axles, AxleSequence)
    return MovingLoad(axles.positions, axles.loads, np.zeros(axles.positions.size), None, axles.name)


def moving_mass(mass) -> MovingLoad:
    """One mass riding on the rail: its weight Mg, and its inertia, which the beam carries too.

    Parameters
    ----------
    mass : float
        M, kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass").

    Returns
    -------
    MovingLoad
    """
    M = _checks.plausible("mass", mass, "mass")
    return MovingLoad([0.0], [M * GRAVITY], [M], None, "moving mass")


def sprung_mass(mass, stiffness, damping=0.0, unsprung_mass=0.0) -> MovingLoad:
    """Biggs's sprung mass: a body on a spring and damper above a wheel that rides on the rail.

    The body of mass M_v moves z (up) on a spring k_v and damper c_v whose foot is the wheel,
    at the rail's height; the wheel's mass m_w rides rigidly on the rail (Biggs 1964, ch. 8;
    Yang & Yau 1997).

    Parameters
    ----------
    mass : float
        M_v, kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass").
    stiffness : float
        k_v, N/m (> 0).
    damping : float
        c_v, N·s/m (≥ 0).
    unsprung_mass : float
        m_w, kg, 0 or in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass").

    Returns
    -------
    MovingLoad

    Examples
    --------
    A 5.75 t body at 1.5 Hz on its spring:

    >>> import numpy as np
    >>> load = sprung_mass(5750.0, 5750.0 * (2 * np.pi * 1.5) ** 2)
    >>> round(float(load.static_loads[0]))
    56388
    """
    M = _checks.plausible("mass", mass, "mass")
    k = _checks.positive("stiffness", stiffness)
    c = _checks.nonnegative("damping", damping)
    m = _checks.nonnegative("unsprung_mass", unsprung_mass)
    if m:
        _checks.plausible("unsprung_mass", m, "mass")
    asm = Assembler(["body z"], n_inputs=1)
    asm.mass("body z", M)
    asm.element({"body z": 1.0}, k, c, inputs={0: 1.0})
    system = asm.system(gravity_load=np.array([-M * GRAVITY]))
    return MovingLoad([0.0], [(M + m) * GRAVITY], [m], system, "sprung mass")


def vehicle(model, wheelset_mass=0.0) -> MovingLoad:
    """A vertical vehicle model on its axles, each wheelset riding on the rail.

    The model's track inputs must be the rail heights under its axles (as
    :class:`raildyn.vehicles.VerticalCar`); its coordinates are measured from rest.
    Each axle's static load is its wheelset's weight and what the suspension presses on it
    at rest (:meth:`raildyn.linear_model.LinearSystem.input_forces`).

    Parameters
    ----------
    model : LinearModel or LinearSystem
        A vertical model of the protocol whose inputs are the axles.
    wheelset_mass : float
        kg, each wheelset's unsprung mass, 0 or in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "mass"; the Manchester vehicle's is 1813 kg,
        Iwnicki 1998, as :class:`raildyn.wheelset.Wheelset`).

    Returns
    -------
    MovingLoad

    Examples
    --------
    >>> from raildyn.vehicles import VerticalCar
    >>> load = vehicle(VerticalCar(), 1813.0)
    >>> round(float(load.static_loads.sum() / 9.80665))
    44482
    """
    system = as_linear_system(model)
    m = _checks.nonnegative("wheelset_mass", wheelset_mass)
    if m:
        _checks.plausible("wheelset_mass", m, "mass")
    if system.n_inputs == 0:
        raise ValueError(f"model must have track inputs (its axles), got {type(model).__name__} with none")
    _sprung_system(system, system.n_inputs)
    order = np.argsort(system.input_positions, kind="stable")
    if np.any(order != np.arange(system.n_inputs)):
        raise ValueError(f"model's inputs must be in axle order, got positions {system.input_positions}")
    rest = system.static_deflection()
    zeros = np.zeros(system.n_inputs)
    carried = -system.input_forces(rest, 0 * rest, zeros, zeros)  # downwards on each wheel
    positions = system.input_positions - system.input_positions[0]
    return MovingLoad(
        positions, carried + m * GRAVITY, np.full(positions.size, m), system, type(model).__name__
    )


def train(loads, gaps) -> MovingLoad:
    """Several moving loads one behind the other, each riding on its own axles.

    Parameters
    ----------
    loads : sequence of MovingLoad
        From the front, at least one.
    gaps : float or array_like, (len(loads) − 1,)
        Distance from each load's last axle to the next one's first, m (≥ 0); one number
        for all.

    Returns
    -------
    MovingLoad
        The sprung parts side by side (block-diagonal; labels prefixed ``"1: "``, ``"2: "``…).

    Examples
    --------
    >>> two = train([moving_mass(1000.0), moving_mass(2000.0)], 10.0)
    >>> two.positions
    array([ 0., 10.])
    """
    loads = (
        list(loads) if isinstance(loads, (list, tuple)) else _checks.instance("loads", loads, (list, tuple))
    )
    if not loads:
        raise ValueError("loads must hold at least one MovingLoad, got an empty sequence")
    for i, load in enumerate(loads):
        _checks.instance(f"loads[{i}]", load, MovingLoad)
    g = _checks.array("gaps", gaps, low=0.0)
    if g.ndim == 0:
        g = np.full(len(loads) - 1, float(g))
    elif g.shape != (len(loads) - 1,):
        raise ValueError(f"gaps must be one number or {len(loads) - 1} of them, got shape {g.shape}")
    lengths = np.array([ld.length for ld in loads[:-1]])
    starts = np.concatenate([[0.0], np.cumsum(lengths + g)])  # each load's first axle behind the leader
    positions = np.concatenate([s + ld.positions for s, ld in zip(starts, loads, strict=True)])
    sprung = [(i, ld) for i, ld in enumerate(loads) if ld.system is not None]
    system = None
    if sprung:
        columns = np.cumsum([0] + [ld.positions.size for ld in loads])
        blocks = {
            name: block_diag(*(getattr(ld.system, name) for _, ld in sprung))
            for name in ("M", "C0", "C1", "K")
        }
        size = sum(ld.system.size for _, ld in sprung)
        GK, GC = np.zeros((size, positions.size)), np.zeros((size, positions.size))
        row = 0
        for i, ld in sprung:
            rows = slice(row, row + ld.system.size)
            GK[rows, columns[i] : columns[i + 1]] = ld.system.GK
            GC[rows, columns[i] : columns[i + 1]] = ld.system.GC
            row += ld.system.size
        KW, CW = (
            block_diag(*(_input_block(ld, name) for ld in loads))
            for name in ("input_stiffness", "input_damping")
        )
        system = LinearSystem(
            **blocks, GK=GK, GC=GC,
            labels=tuple(f"{i + 1}: {label}" for i, ld in sprung for label in ld.system.labels),
            input_positions=positions,
            gravity_load=np.concatenate([ld.system.gravity_load for _, ld in sprung]),
            input_stiffness=KW, input_damping=CW,
        )  # fmt: skip
    return MovingLoad(
        positions,
        np.concatenate([ld.static_loads for ld in loads]),
        np.concatenate([ld.unsprung_masses for ld in loads]),
        system,
        " + ".join(ld.name for ld in loads),
    )


def _input_block(load: MovingLoad, name: str) -> np.ndarray:
    """A load's input stiffness or damping block; zeros for axles with no sprung part."""
    a = load.positions.size
    return np.zeros((a, a)) if load.system is None else getattr(load.system, name)
