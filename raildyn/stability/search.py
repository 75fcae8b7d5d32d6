"""The batched critical-speed search (book chapter 7): many linear systems, one eigenvalue call a step.

:func:`critical_speeds` is the search behind :func:`raildyn.stability.linear.critical_speed`,
:func:`raildyn.stability.linear.critical_speed_map` and the stability–curving trade-off of
:mod:`raildyn.curving.stiffness`, open to any caller with a stack of systems: a coarse
batched scan of g(V) = max Re s_r(V) brackets each system's first upward zero, and a
bracketed refinement narrows every bracket at once. :class:`StateMatrices` holds the
blocks of A(V) = [[0, I], [−M⁻¹K, −M⁻¹(C₀ + C₁/V)]] of one system or of a stack of
systems of one size, with M solved once, so that A at any speed costs one sum. A
family of models affine in its parameters (:class:`raildyn.linear_model.AffineFamily`)
gives such a stack without assembling each member.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.errors import SolverError
from raildyn.linear_model import LinearSystem, as_linear_system

__all__ = ["CRITICAL_SPEED_STATUSES", "MAX_SCAN_SPEEDS", "CriticalSpeeds", "StateMatrices", "critical_speeds"]

CRITICAL_SPEED_STATUSES = ("crossing", "stable over the range", "unstable at the lowest speed")
"""What a critical-speed search can find: the largest real part crosses zero upwards inside the range;
it stays negative over the whole range; or it is already ≥ 0 at the lowest speed."""

MAX_SCAN_SPEEDS = 10_000
"""The most speeds a coarse scan may take: the refinement narrows the bracket, so more only cost time."""

_MAX_STEPS = 400  # of the refinement: every three steps at least halve a bracket, so far more than needed


def _range(speed_range) -> tuple[float, float]:
    return _checks.speed_range("speed_range", speed_range)


def _blocks(M, K, C0, C1):
    """The four matrices checked: each (n, n) or a stack (m, n, n), one n and one m; M positive definite."""
    mats = {}
    for name, value in (("M", M), ("K", K), ("C0", C0), ("C1", C1)):
        arr = _checks.array(name, value)
        if arr.ndim not in (2, 3) or arr.shape[-1] != arr.shape[-2] or arr.shape[-1] == 0:
            raise ValueError(
                f"{name} must be a square matrix (n, n) or a stack of them (m, n, n), got shape {arr.shape}"
            )
        mats[name] = arr
    n = mats["M"].shape[-1]
    counts = {a.shape[0] for a in mats.values() if a.ndim == 3}
    for name, arr in mats.items():
        if arr.shape[-1] != n:
            raise ValueError(f"{name} must be {n} × {n} as M is, got shape {arr.shape}")
    if len(counts) > 1:
        raise ValueError(
            f"the stacks of M, K, C0 and C1 must hold as many systems each, got {sorted(counts)}"
        )
    if 0 in counts:
        raise ValueError("the stacks of M, K, C0 and C1 must hold one system at least, got an empty stack")
    M = mats["M"]
    if np.any(np.abs(M - np.swapaxes(M, -1, -2)) > 1e-9 * np.abs(M).max(axis=(-2, -1), keepdims=True)):
        raise ValueError("M must be symmetric (each matrix of the stack)")
    try:  # a Cholesky factor exists exactly when M is positive definite
        np.linalg.cholesky(M)
    except np.linalg.LinAlgError:
        raise ValueError("M must be positive definite (each matrix of the stack)") from None
    return mats["M"], mats["K"], mats["C0"], mats["C1"]


class StateMatrices:
    """A(V) = [[0, I], [−M⁻¹K, −M⁻¹C₀ − M⁻¹C₁/V]] of one system or of a stack of systems of one size.

    :func:`critical_speeds` asks for A at a dozen or more single speeds (the scan, then each
    step of the refinement); :meth:`raildyn.linear_model.LinearSystem.state_matrices` checks
    the speeds and M and solves with M at every call, which took about as long as the
    eigenvalues of a 30-state car. Here the three blocks are solved once; A(V) differs from
    that method's by round-off only. A matrix shared by the whole stack is solved once.

    Parameters
    ----------
    M : array_like, (n, n) or (m, n, n)
        Mass matrix, kg (kg·m² for rotations): symmetric, positive definite.
    K : array_like, (n, n) or (m, n, n)
        Stiffness, N/m (N·m/rad), of either sign (creep and gravity terms).
    C0 : array_like, (n, n) or (m, n, n)
        Speed-independent damping, N·s/m.
    C1 : array_like, (n, n) or (m, n, n)
        Creep damping times speed, N (the damping at V is C₀ + C₁/V).

    Each is finite; the stacks, where given, hold the same number m of systems.

    Examples
    --------
    >>> from raildyn.wheelset import Wheelset
    >>> state = StateMatrices.of(Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6))
    >>> state.count, state.n, state.state_matrices([30.0]).shape
    (1, 2, (1, 4, 4))
    """

    _CHUNK = 1024  # state matrices per eigenvalue call: a long scan of many systems stays within memory

    def __init__(self, M, K, C0, C1):
        M, K, C0, C1 = _blocks(M, K, C0, C1)
        self.n = n = M.shape[-1]
        self.count = max([1] + [x.shape[0] for x in (M, K, C0, C1) if x.ndim == 3])
        if M.ndim == 2 and C0.ndim == 2 and C1.ndim == 2:  # only K varies (or nothing): M⁻¹C once
            self.stiffness = -np.linalg.solve(M, K)
            damping = -np.linalg.solve(M, np.concatenate([C0, C1], axis=1))
            self.damping, self.creep = damping[:, :n], damping[:, n:]
        else:
            stack = np.concatenate(np.broadcast_arrays(K, C0, C1), axis=-1)
            blocks = -np.linalg.solve(M, stack)
            self.stiffness, self.damping, self.creep = (
                blocks[..., :n],
                blocks[..., n : 2 * n],
                blocks[..., 2 * n :],
            )

    @classmethod
    def of(cls, model) -> StateMatrices:
        """The state matrices of one linear model (or system).

        Parameters
        ----------
        model : LinearModel or LinearSystem
            A linear model of :mod:`raildyn.wheelset` or :mod:`raildyn.vehicles`, or its system.

        Returns
        -------
        StateMatrices
            Of one system (``count`` 1).
        """
        system = as_linear_system(model)
        return cls(system.M, system.K, system.C0, system.C1)

    def _which(self, which, size: int) -> np.ndarray:
        if which is None:
            if self.count != 1:
                raise ValueError(f"which must name a system for each speed: this stack holds {self.count}")
            return np.zeros(size, dtype=int)
        arr = _checks.array("which", np.atleast_1d(which), shape=(size,), low=0)
        if np.any(arr != np.round(arr)) or np.any(arr > self.count - 1):
            raise ValueError(
                f"which must hold whole numbers in [0, {self.count - 1}] (indices into the stack), "
                f"got {which!r:.80}"
            )
        return arr.astype(int)

    def _at(self, speeds: np.ndarray, which: np.ndarray) -> np.ndarray:
        n = self.n

        def pick(block):
            return block[which] if block.ndim == 3 else block

        A = np.zeros((speeds.size, 2 * n, 2 * n))
        A[:, :n, n:] = np.eye(n)
        A[:, n:, :n] = pick(self.stiffness)
        A[:, n:, n:] = pick(self.damping) + pick(self.creep) / speeds[:, None, None]
        return A

    def state_matrices(self, speeds, which=None) -> np.ndarray:
        """A of system ``which[k]`` at ``speeds[k]``, for each k.

        Parameters
        ----------
        speeds : array_like, (k,)
            V, m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]; at least one.
        which : array_like of int, (k,), optional
            Index of each speed's system in the stack, in [0, count − 1]; None for a stack of one.

        Returns
        -------
        ndarray, (k, 2n, 2n)
            1/s² and 1/s blocks.
        """
        V = _checks.speeds("speeds", np.atleast_1d(speeds))
        return self._at(V, self._which(which, V.size))

    def _largest(self, which: np.ndarray, speeds: np.ndarray) -> np.ndarray:
        out = np.empty(speeds.size)
        for start in range(0, speeds.size, self._CHUNK):
            part = slice(start, start + self._CHUNK)
            out[part] = np.linalg.eigvals(self._at(speeds[part], which[part])).real.max(axis=-1)
        return out

    def largest_real_part(self, speeds, which=None) -> np.ndarray:
        """max Re s_r of A for each pair (system ``which[k]``, ``speeds[k]``).

        Parameters
        ----------
        speeds : array_like, (k,)
            V, m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]; at least one.
        which : array_like of int, (k,), optional
            Index of each speed's system in the stack, in [0, count − 1]; None for a stack of one.

        Returns
        -------
        ndarray, (k,)
            1/s: positive where the system is unstable at that speed.
        """
        V = _checks.speeds("speeds", np.atleast_1d(speeds))
        return self._largest(self._which(which, V.size), V)


def _crossings(state: StateMatrices, low: float, high: float, tol: float, scan: int):
    """The status and critical speed of every system of ``state`` (arguments checked by the caller).

    The definition of :func:`critical_speed`, for a stack of systems at once: a coarse scan of
    ``scan`` speeds brackets each system's first upward zero of g(V) = max Re s_r(V), then a
    bracketed refinement narrows every bracket below 2 tol; the midpoint is returned. The scan
    goes up in batches of 4 speeds, then of half the speeds done so far, and leaves a system at
    its first upward crossing: a crossing low in the range costs a few eigenvalue problems, a
    system stable over the range a few batched calls. The refinement is the Illinois variant of
    regula falsi, each point kept at least tol/2 inside its bracket; where two steps have not
    halved a bracket, a bisection follows, so that a kink of g (two modes trading places) cannot
    stall it.

    Returns (status, speed): an object array of :data:`CRITICAL_SPEED_STATUSES` and V_c in m/s (inf where
    stable over the range, ``low`` where unstable at the lowest speed), each of shape (m,).
    """
    m = state.count
    V = np.linspace(low, high, scan)
    speed = np.full(m, np.inf)
    status = np.full(m, CRITICAL_SPEED_STATUSES[1], dtype=object)
    every = np.arange(m)
    g_low = state._largest(every, np.full(m, low))
    unstable = g_low >= 0.0
    speed[unstable], status[unstable] = low, CRITICAL_SPEED_STATUSES[2]
    open_, g_last = every[~unstable], g_low[~unstable]
    todo, a, b, ga, gb = [], [], [], [], []
    done = 1  # speeds of the scan behind every open system, all with g < 0
    while open_.size and done < scan:
        batch = V[done : done + max(4, done // 2)]
        g = state._largest(np.repeat(open_, batch.size), np.tile(batch, open_.size)).reshape(open_.size, -1)
        up = g >= 0.0
        crossed = np.flatnonzero(up.any(axis=1))
        k = up[crossed].argmax(axis=1)  # the first speed of the batch where g ≥ 0
        before = np.where(k == 0, g_last[crossed], g[crossed, k - 1])
        todo.append(open_[crossed])
        a.append(V[done - 1 + k])
        b.append(V[done + k])
        ga.append(before)
        gb.append(g[crossed, k])
        stay = ~up.any(axis=1)
        open_, g_last = open_[stay], g[stay, -1]
        done += batch.size
    if not todo or not sum(t.size for t in todo):
        return status, speed
    todo, a, b, ga, gb = (np.concatenate(x) for x in (todo, a, b, ga, gb))
    side = np.zeros(todo.size, dtype=int)  # which end the last step kept: −1 a, +1 b
    bisect = np.zeros(todo.size, dtype=bool)
    before = np.full(todo.size, np.inf)  # each bracket's width when the previous step began
    for _ in range(_MAX_STEPS):
        # a bracket as narrow as the speeds' round-off is done too, whatever tol asked for
        active = (b - a > 2.0 * tol) & (b - a > 8.0 * np.spacing(b))
        if not active.any():
            break
        i = np.flatnonzero(active)
        width = b[i] - a[i]
        falsi = (a[i] * gb[i] - b[i] * ga[i]) / (gb[i] - ga[i])
        c = np.where(bisect[i], 0.5 * (a[i] + b[i]), np.clip(falsi, a[i] + 0.5 * tol, b[i] - 0.5 * tol))
        gc = state._largest(todo[i], c)
        right = gc >= 0.0  # the zero lies in [a, c]: c becomes b
        for mask, keep in ((right, -1), (~right, 1)):
            j = i[mask]
            if keep == -1:
                b[j], gb[j] = c[mask], gc[mask]
                ga[j] = np.where(side[j] == -1, 0.5 * ga[j], ga[j])  # Illinois: a kept twice
            else:
                a[j], ga[j] = c[mask], gc[mask]
                gb[j] = np.where(side[j] == 1, 0.5 * gb[j], gb[j])
            side[j] = keep
        # two steps that have not halved the bracket are followed by a bisection
        bisect[i] = b[i] - a[i] > 0.5 * before[i]
        before[i] = width
    else:  # pragma: no cover - every three steps at least halve each bracket
        raise SolverError("the critical-speed refinement did not converge")
    speed[todo], status[todo] = 0.5 * (a + b), CRITICAL_SPEED_STATUSES[0]
    return status, speed


@dataclass(frozen=True, eq=False)  # arrays: compared by identity
class CriticalSpeeds(Tabular):
    """The linear critical speed of each system of a stack, from one batched search.

    Attributes
    ----------
    speeds : ndarray, (m,)
        V_c of each system, m/s (> 0): ``inf`` where stable over the range, the lower end of the
        range where already unstable there (see ``status``).
    status : tuple of str, (m,)
        Each one of :data:`CRITICAL_SPEED_STATUSES`.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("speeds", "m/s"), ("status", "-"))

    speeds: np.ndarray
    status: tuple

    def __post_init__(self):
        statuses = _checks.strings("status", self.status)
        for s in statuses:
            _checks.choice("status", s, CRITICAL_SPEED_STATUSES)
        v = _checks._numbers("speeds", self.speeds)
        if v.shape != (len(statuses),) or not statuses:
            raise ValueError(
                f"speeds must have shape ({len(statuses)},), one per status (at least one), got {v.shape}"
            )
        stable = np.array([s == CRITICAL_SPEED_STATUSES[1] for s in statuses])
        if np.any(np.isposinf(v) != stable):
            raise ValueError(
                f"speeds must be inf exactly where the status is {CRITICAL_SPEED_STATUSES[1]!r}, "
                f"got {v!r:.80}"
            )
        _checks.plausible_array("speeds", np.where(stable, 1.0, v), "speed", low_open=True)

    @property
    def found(self) -> np.ndarray:
        """True where the largest real part crosses zero inside the range (status "crossing"), (m,)."""
        return np.array([s == CRITICAL_SPEED_STATUSES[0] for s in self.status])


def _stacks(systems) -> list[tuple[np.ndarray, StateMatrices]]:
    """(indices, state matrices) of each group of systems of one size."""
    if isinstance(systems, StateMatrices):
        return [(np.arange(systems.count), systems)]
    if isinstance(systems, LinearSystem) or callable(getattr(systems, "linear_system", None)):
        return [(np.zeros(1, dtype=int), StateMatrices.of(systems))]
    if isinstance(systems, (str, bytes)) or not isinstance(systems, (list, tuple)) or not systems:
        raise TypeError(
            "systems must be StateMatrices, a linear model or a non-empty list of linear models, "
            f"got {systems!r:.80}"
        )
    built = []
    for i, model in enumerate(systems):
        try:
            built.append(as_linear_system(model))
        except TypeError as err:
            raise TypeError(f"systems[{i}]: {err}") from None
    groups = []
    for n in sorted({s.size for s in built}):
        index = np.array([i for i, s in enumerate(built) if s.size == n])
        group = [built[i] for i in index]
        stacks = {name: np.stack([getattr(s, name) for s in group]) for name in ("M", "K", "C0", "C1")}
        groups.append((index, StateMatrices(**stacks)))
    return groups


def critical_speeds(
    systems, speed_range=(1.0, 150.0), *, tol: float = 0.01, scan: int = 64
) -> CriticalSpeeds:
    """The linear critical speed of many systems at once: one eigenvalue call per step for all of them.

    The definition of :func:`raildyn.stability.linear.critical_speed` (the lowest speed where the
    largest real part of the eigenvalues crosses zero upwards), for a stack of systems: a coarse
    scan of ``scan`` speeds brackets each system's first upward zero of g(V) = max Re s_r(V),
    then a bracketed refinement (regula falsi, Illinois variant, with bisection where two steps
    have not halved a bracket) narrows every bracket below 2 tol; the midpoint is returned. The
    scan goes up in batches of 4 speeds, then of half the speeds done so far, and leaves a system
    at its first upward crossing.

    Parameters
    ----------
    systems : StateMatrices, LinearModel or list of them
        A stack of systems (:class:`StateMatrices`; a family of models gives one through
        :meth:`raildyn.linear_model.AffineFamily.stacks`), one linear model or system, or a
        non-empty list of linear models or systems (of any sizes: those of one size are
        searched together).
    speed_range : (float, float)
        Lowest and highest speed, m/s (0 < low < high ≤ :data:`~raildyn.constants.MAXIMUM_SPEED`).
    tol : float
        Absolute tolerance on each V_c, m/s (> 0).
    scan : int
        Number of speeds in the coarse scan, in [8, :data:`MAX_SCAN_SPEEDS`]; a crossing and
        recrossing between two of them would be missed.

    Returns
    -------
    CriticalSpeeds
        V_c (m/s) and status of each system, in the order given.

    Examples
    --------
    >>> from raildyn.wheelset import Wheelset
    >>> wheelsets = [Wheelset(yaw_stiffness=k, lateral_stiffness=1.0e6) for k in (1e6, 2e6)]
    >>> found = critical_speeds(wheelsets, (1.0, 200.0))
    >>> found.status, found.speeds.round(1)
    (('crossing', 'crossing'), array([42.5, 54.5]))
    """
    groups = _stacks(systems)
    low, high = _range(speed_range)
    tol = _checks.positive("tol", tol)
    scan = _checks.integer("scan", scan, low=8, high=MAX_SCAN_SPEEDS)
    m = sum(index.size for index, _ in groups)
    speeds = np.empty(m)
    status = np.empty(m, dtype=object)
    for index, state in groups:
        status[index], speeds[index] = _crossings(state, low, high, tol, scan)
    return CriticalSpeeds(speeds, tuple(status))
