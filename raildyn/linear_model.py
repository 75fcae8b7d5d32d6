"""One protocol for every linear model of raildyn, and the one system every model assembles into.

Every linear model — the wheelset of chapter 5, the bogie and the lateral car of
chapter 7, the vertical passenger car, the freight car and the locomotive of
chapter 6, and each model the later chapters add — follows
:class:`LinearModel`:

* ``linear_system()`` → :class:`LinearSystem`, the assembled equations
  M q̈ + (C₀ + C₁/V) q̇ + K q = G_K w(t) + G_C ẇ(t), with w the track
  irregularities met by the wheels (rail heights, alignment, cross-level);
* ``matrices(speed)`` → :class:`SystemMatrices`: M, C(V), K and the input
  matrices G_K, G_C at one speed;
* ``state_space(speed, outputs=..., derivative=...)`` → a
  ``control.StateSpace`` from the track inputs to the outputs, so that root
  loci, Bode plots and frequency responses come from python-control;
* ``replace(**changes)`` → a validated copy with some parameters changed.

The speed V is given in exactly one place: the call that evaluates the model.
Linear creep forces are proportional to creepages, which are velocities divided
by V, so the wheel–rail damping is C₁/V; models without creep (the vertical
cars) have C₁ = 0 and give the same matrices at every speed.

:class:`Assembler` builds a :class:`LinearSystem` spring by spring: every
spring k (damper c) acts on a relative displacement d = g·q − h·w, so it adds
k g gᵀ to K and k g hᵀ to G_K (c to C₀ and G_C).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from dataclasses import replace as _dataclass_replace
from typing import Protocol, runtime_checkable

import numpy as np

from raildyn import _checks
from raildyn.vibration import first_order_matrix

__all__ = [
    "INPUT_KINDS",
    "Assembler",
    "LinearModel",
    "LinearModelBase",
    "LinearSystem",
    "RailWheelset",
    "SystemMatrices",
    "as_linear_system",
]

INPUT_KINDS = ("vertical", "alignment", "cross_level")
"""What a track input can be: a rail height (on the rail given by ``input_rails``), the alignment
(lateral position of the track centreline) or the cross-level (left rail height − right rail height), m."""


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class SystemMatrices:
    """The matrices of a linear model at one speed: M q̈ + C q̇ + K q = G_K w + G_C ẇ.

    Attributes
    ----------
    M, C, K : ndarray, (n, n)
        Mass (kg, kg·m²; symmetric, positive definite), damping (N·s/m, N·m·s/rad) and
        stiffness (N/m, N·m/rad) at ``speed``; C and K hold creep and gravity terms of either
        sign and need not be symmetric.
    GK, GC : ndarray, (n, q)
        Forces per unit track input and per unit input rate, N/m and N·s/m (either sign).
    labels : tuple of str
        Name of each coordinate, each one different and not empty.
    speed : float
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    """

    M: np.ndarray
    C: np.ndarray
    K: np.ndarray
    GK: np.ndarray
    GC: np.ndarray
    labels: tuple
    speed: float

    def __post_init__(self):
        # Light checks (a few microseconds): a system's matrices() builds one at every speed of a sweep.
        n = _mass_matrix("M", self.M).shape[0]
        for name in ("C", "K"):
            _checks.array(name, getattr(self, name), shape=(n, n))
        q = _checks.array("GK", self.GK, shape=(n, None)).shape[1]
        _checks.array("GC", self.GC, shape=(n, q))
        _checks.strings("labels", self.labels, n, unique=True)
        _checks.speed("speed", self.speed)

    def state_matrix(self) -> np.ndarray:
        """A = [[0, I], [−M⁻¹K, −M⁻¹C]], shape (2n, 2n), 1/s² and 1/s blocks.

        Returns
        -------
        ndarray
            The first-order state matrix, from :func:`raildyn.vibration.first_order_matrix`.
        """
        return first_order_matrix(self.M, self.C, self.K)


def _frozen(name: str, value, shape, low=None) -> np.ndarray:
    arr = _checks.array(name, value, shape=shape, low=low).copy()
    arr.setflags(write=False)
    return arr


def _mass_matrix(name: str, value) -> np.ndarray:
    """A finite, symmetric, positive-definite mass matrix."""
    M = _checks.square_matrix(name, value)
    try:  # a Cholesky factor exists exactly when M is positive definite, at any scale of its entries
        np.linalg.cholesky(M)
    except np.linalg.LinAlgError:
        raise ValueError(
            f"{name} must be positive definite, got eigenvalues {np.linalg.eigvalsh(M)}"
        ) from None
    return M


_OMEGA_MAX = 1.0e7  # rad/s, the highest frequency of a frequency response (1.6 MHz)


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class LinearSystem:
    """A linear model: M q̈ + (C₀ + C₁/V) q̇ + K q = G_K w(t) + G_C ẇ(t).

    Input j is the track met at distance ``input_positions[j]`` behind the
    leading axle, so that at speed V it arrives τ_j = d_j/V later; its kind is
    ``input_kinds[j]`` (one of :data:`INPUT_KINDS`) and, for a rail height, its
    rail ``input_rails[j]`` (+1 left, −1 right, 0 both).

    Attributes
    ----------
    M, C0, C1, K : ndarray, (n, n)
        Mass (kg), speed-independent damping (N·s/m), creep damping times speed
        (N), stiffness (N/m); rotational rows in the matching units.
    GK, GC : ndarray, (n, q) or None
        Forces from the track inputs and their rates, N/m and N·s/m (any sign). None: zeros
        of the other's shape (no inputs when both are None).
    labels : tuple of str
        Name of each of the n coordinates (m or rad); empty: q0, q1, ...
    input_positions : ndarray, (q,) or None
        m, ≥ 0 (behind the leading axle); None: all 0.
    input_kinds : tuple of str, (q,)
        Empty: every input "vertical".
    input_rails : ndarray, (q,) or None
        Each +1, −1 or 0; None: all 0.
    gravity_load : ndarray, (n,) or None
        Generalized weight of the sprung masses, N (down is negative); None: zeros.
    wheelsets : tuple of (int, int, Wheelset)
        Indices of the [y, ψ] coordinates of each wheelset in contact with the
        rails and its parameters (a :class:`RailWheelset`), for the nonlinear counterpart
        (:class:`raildyn.wheelset.NonlinearLateral`).
    input_stiffness, input_damping : ndarray, (q, q) or None
        The inputs' own block of the suspension's stiffness and damping, N/m and N·s/m
        (symmetric), so that the force of the suspension on the wheel at input j, upwards, is
        (G_Kᵀ q + G_Cᵀ q̇ − K_W w − C_W ẇ)_j: what a flexible track or bridge under the vehicle
        needs. None: not known (an input force added directly rather than by an element);
        :meth:`input_forces` then refuses.

    M must be symmetric and positive definite; C₀, C₁ and K hold damper, creep and
    gravity terms of either sign and need not be symmetric.
    """

    M: np.ndarray
    C0: np.ndarray
    C1: np.ndarray
    K: np.ndarray
    GK: np.ndarray = None
    GC: np.ndarray = None
    labels: tuple = ()
    input_positions: np.ndarray = None
    input_kinds: tuple = ()
    input_rails: np.ndarray = None
    gravity_load: np.ndarray = None
    wheelsets: tuple = field(default=())
    input_stiffness: np.ndarray = None
    input_damping: np.ndarray = None

    def __post_init__(self):
        M = _mass_matrix("M", self.M)
        n = M.shape[0]
        set_ = object.__setattr__  # frozen: the validated, read-only arrays replace what was passed
        set_(self, "M", _frozen("M", M, (n, n)))
        for name in ("C0", "C1", "K"):
            set_(self, name, _frozen(name, getattr(self, name), (n, n)))
        if self.GK is None and self.GC is None:
            GK = GC = np.zeros((n, 0))
        else:  # the one given fixes q; the other defaults to zeros of its shape
            given = "GK" if self.GK is not None else "GC"
            q = _checks.array(given, getattr(self, given), shape=(n, None)).shape[1]
            GK, GC = (np.zeros((n, q)) if v is None else v for v in (self.GK, self.GC))
        set_(self, "GK", _frozen("GK", GK, (n, None)))
        q = self.GK.shape[1]
        set_(self, "GC", _frozen("GC", GC, (n, q)))
        positions = np.zeros(q) if self.input_positions is None else self.input_positions
        set_(self, "input_positions", _frozen("input_positions", positions, (q,), low=0.0))
        rails = _frozen("input_rails", np.zeros(q) if self.input_rails is None else self.input_rails, (q,))
        if not np.isin(rails, (-1.0, 0.0, 1.0)).all():
            raise ValueError(f"input_rails must each be +1 (left), -1 (right) or 0 (both), got {rails}")
        set_(self, "input_rails", rails)
        gravity = np.zeros(n) if self.gravity_load is None else self.gravity_load
        set_(self, "gravity_load", _frozen("gravity_load", gravity, (n,)))
        labels = _checks.strings("labels", self.labels) or tuple(f"q{i}" for i in range(n))
        set_(self, "labels", _checks.strings("labels", labels, n, unique=True))
        kinds = _checks.strings("input_kinds", self.input_kinds) or ("vertical",) * q
        if len(kinds) != q or any(k not in INPUT_KINDS for k in kinds):
            raise ValueError(f"input_kinds must be {q} of {INPUT_KINDS}, got {self.input_kinds!r}")
        set_(self, "input_kinds", kinds)
        set_(self, "wheelsets", _wheelsets(self.wheelsets, self.labels))
        if (self.input_stiffness is None) != (self.input_damping is None):
            raise ValueError("input_stiffness and input_damping must be given together or both be None")
        for name in ("input_stiffness", "input_damping"):
            if getattr(self, name) is not None:
                value = getattr(self, name)
                block = _checks.square_matrix(name, value, size=q) if q else _checks.array(name, value)
                set_(self, name, _frozen(name, block, (q, q)))

    @property
    def size(self) -> int:
        """n, the number of coordinates."""
        return self.M.shape[0]

    @property
    def n_inputs(self) -> int:
        """q, the number of track inputs."""
        return self.GK.shape[1]

    @property
    def wheelset_positions(self) -> np.ndarray:
        """x of each wheelset on the rails (in the order of ``wheelsets``) ahead of the vehicle's centre, m.

        From the distance of each wheelset's alignment input behind the leading axle; the
        centre is midway between the first and the last wheelset. A lone wheelset is at 0.

        Raises
        ------
        ValueError
            If a wheelset of several has not exactly one alignment input.
        """
        if len(self.wheelsets) <= 1:
            return np.zeros(len(self.wheelsets))
        behind = []
        for iy, ipsi, _ in self.wheelsets:
            found = [
                j
                for j in range(self.n_inputs)
                if self.input_kinds[j] == "alignment" and np.any(self.GK[[iy, ipsi], j] != 0.0)
            ]
            if len(found) != 1:
                raise ValueError(
                    f"the wheelset on {self.labels[iy]!r} must have one alignment input (it gives the "
                    f"wheelset's place along the track), got {len(found)}"
                )
            behind.append(self.input_positions[found[0]])
        behind = np.array(behind)
        return 0.5 * (behind.min() + behind.max()) - behind

    def input_forces(self, q, qdot, w, wdot) -> np.ndarray:
        """The suspension's force on the wheel at each track input, upwards, N.

        (G_Kᵀ q + G_Cᵀ q̇ − K_W w − C_W ẇ): minus the derivative of the suspension's energy
        with respect to each input, with its damping; displacements from the static position.

        Parameters
        ----------
        q, qdot : array_like, (..., n)
            Coordinates (m, rad) and their rates.
        w, wdot : array_like, (..., q)
            Track inputs (m) and their rates.

        Returns
        -------
        ndarray, (..., q)

        Raises
        ------
        ValueError
            If the system does not know its inputs' own stiffness (``input_stiffness`` None).
        """
        if self.input_stiffness is None:
            raise ValueError(
                "this system does not know its inputs' own stiffness (input_stiffness None): build it with "
                "Assembler.element, which records it"
            )
        n, k = self.size, self.n_inputs
        q = _checks.array("q", q)
        lead = q.shape[:-1] if q.ndim else ()  # the leading axes every argument shares (times, say)
        q = _checks.array("q", q, shape=(*lead, n))
        for name, value, size in (("qdot", qdot, n), ("w", w, k), ("wdot", wdot, k)):
            if np.shape(value) != (*lead, size):
                raise ValueError(
                    f"{name} must have shape {(*lead, size)} (the leading axes of q, shape {q.shape}), "
                    f"got shape {np.shape(value)}"
                )
        qdot, w, wdot = (_checks.array(s, v) for s, v in (("qdot", qdot), ("w", w), ("wdot", wdot)))
        return q @ self.GK + qdot @ self.GC - w @ self.input_stiffness - wdot @ self.input_damping

    # -- the protocol ------------------------------------------------------------------------------

    def linear_system(self) -> LinearSystem:
        """This system itself (the protocol's assembly step).

        Returns
        -------
        LinearSystem
        """
        return self

    def replace(self, **changes) -> LinearSystem:
        """A copy with some fields changed, validated again.

        Parameters
        ----------
        **changes
            Field names and their new values.

        Returns
        -------
        LinearSystem
        """
        return _dataclass_replace(self, **changes)

    def matrices(self, speed) -> SystemMatrices:
        """M, C(V) = C₀ + C₁/V, K, G_K and G_C at the speed V.

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`] (> 0: the creep damping
            divides by it; a speed above 200 m/s is a slip, e.g. km/h typed for m/s).

        Returns
        -------
        SystemMatrices
        """
        V = _checks.speed("speed", speed)
        return SystemMatrices(self.M, self.C0 + self.C1 / V, self.K, self.GK, self.GC, self.labels, V)

    def state_matrices(self, speeds) -> np.ndarray:
        """A(V) = [[0, I], [−M⁻¹K, −M⁻¹C(V)]] for every speed in one pass.

        Parameters
        ----------
        speeds : array_like, (m,)
            m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]; at least one.

        Returns
        -------
        ndarray, (m, 2n, 2n)
        """
        V = _checks.speeds("speeds", speeds)
        C = self.C0[None] + self.C1[None] / V[:, None, None]
        return first_order_matrix(self.M[None], C, self.K[None])

    def output_vector(self, output) -> np.ndarray:
        """The row vector c with output = c·q.

        Parameters
        ----------
        output : str, (str, float) or array_like
            A coordinate label ("body z"); a label and a distance x (m) ahead of
            the body's centre, for the point z + xθ (the label's body must have a
            pitch coordinate "… θ"); or a row of n coefficients.

        Returns
        -------
        ndarray, (n,)
        """
        return self._output_vector(output, "output")

    def _output_vector(self, output, name: str) -> np.ndarray:
        """:meth:`output_vector`, its messages naming ``name`` (the caller's parameter)."""
        if isinstance(output, str):
            if output not in self.labels:
                raise ValueError(f"{name} must be one of {self.labels}; got {output!r}")
            return np.eye(self.size)[self.labels.index(output)]
        if isinstance(output, tuple) and len(output) == 2 and isinstance(output[0], str):
            label, x = output
            base = self._output_vector(label, name)
            x = _checks.scalar(f"{name} position", x)
            pitch = label.rsplit(" ", 1)[0] + " θ"
            if pitch not in self.labels:
                raise ValueError(f"{name} {label!r} has no pitch coordinate {pitch!r} to place a point")
            return base + x * self._output_vector(pitch, name)
        return _checks.array(name, output, shape=(self.size,))

    def state_space(self, speed, outputs=None, derivative: int = 0):
        """The model at speed V as a ``control.StateSpace`` from the q track inputs to the outputs.

        With E = M⁻¹G_C the state x = [q; q̇ − E w] removes the input rate ẇ:

            ẋ = [[0, I], [−M⁻¹K, −M⁻¹C]] x + [[E], [M⁻¹(G_K − C E)]] w,

        and q = [I 0] x, q̇ = [0 I] x + E w, q̈ = [−M⁻¹K, −M⁻¹C] x + M⁻¹(G_K − C E) w + E ẇ.

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
        outputs : sequence, optional
            Output specifications as for :meth:`output_vector` (a list or tuple of them, at
            least one); None: every coordinate.
        derivative : {0, 1, 2}
            Displacement, velocity or acceleration of the outputs.

        Returns
        -------
        control.StateSpace
            Inputs: the track inputs (m); outputs in m, m/s or m/s² (rad for rotations).

        Raises
        ------
        ValueError
            For an acceleration output that a damper couples directly to the
            track (the transfer function would be improper), or a system without inputs.
        """
        import control

        d = _checks.integer("derivative", derivative, low=0, high=2)
        mats = self.matrices(speed)
        if self.n_inputs == 0:
            raise ValueError("this system has no track inputs, so it has no state-space input matrix")
        if outputs is not None and not isinstance(outputs, (list, tuple)):
            raise TypeError(f"outputs must be a list or tuple of output specifications, got {outputs!r:.80}")
        specs = self.labels if outputs is None else outputs
        rows = [self._output_vector(o, f"outputs[{i}]") for i, o in enumerate(specs)]
        if not rows:
            raise ValueError(f"outputs must name at least one output, got {outputs!r}")
        Co = np.array(rows)
        n = self.size
        A = mats.state_matrix()
        E = np.linalg.solve(self.M, self.GC)
        F = np.linalg.solve(self.M, self.GK - mats.C @ E)
        B = np.vstack([E, F])
        zero = np.zeros((len(rows), n))
        if d == 0:
            C, D = np.hstack([Co, zero]), np.zeros((len(rows), self.n_inputs))
        elif d == 1:
            C, D = np.hstack([zero, Co]), Co @ E
        else:
            if np.any(np.abs(Co @ E) > 0.0):
                raise ValueError(
                    "outputs with derivative=2 must not be tied to the track by a damper: their acceleration "
                    "responds to the input rate without bound (improper transfer function)"
                )
            C, D = Co @ A[n:], Co @ F
        names = [o if isinstance(o, str) else f"y{i}" for i, o in enumerate(outputs or self.labels)]
        return control.ss(
            A, B, C, D, inputs=[f"{kind} {j}" for j, kind in enumerate(self.input_kinds)], outputs=names
        )

    # -- responses to the track ---------------------------------------------------------------------

    def static_deflection(self) -> np.ndarray:
        """Displacements under gravity, K q = weight.

        Returns
        -------
        ndarray, (n,)
            m (rad).

        Raises
        ------
        ValueError
            If K is singular (a free rigid-body motion has no static position).
        """
        try:
            return np.linalg.solve(self.K, self.gravity_load)
        except np.linalg.LinAlgError:
            raise ValueError("K is singular: a free rigid-body motion has no static deflection") from None

    def axle_frf(self, omega, speed, output="body z", derivative: int = 0) -> np.ndarray:
        """H_j(ω) from track input j (m) to the output, all frequencies in one batched solve.

        Solves (K − ω²M + iωC(V)) X = G_K + iωG_C at every ω.

        Parameters
        ----------
        omega : array_like, (n_ω,)
            rad/s, at least one, each in [0, 1e7]: far above any mode of a vehicle, and low
            enough that ω²M cannot overflow.
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`] (the creep damping depends on it).
        output : see :meth:`output_vector`
        derivative : {0, 1, 2}
            Output in m, m/s or m/s².

        Returns
        -------
        ndarray, complex, (n_ω, q)
        """
        w = _checks.array("omega", omega, ndim=1, low=0.0, allow_empty=False)
        if w.max() > _OMEGA_MAX:
            raise ValueError(f"omega must be at most {_OMEGA_MAX:g} rad/s, got {w.max()!r}")
        d = _checks.integer("derivative", derivative, low=0, high=2)
        o = self.output_vector(output)
        mats = self.matrices(speed)
        Z = mats.K - w[:, None, None] ** 2 * mats.M + 1j * w[:, None, None] * mats.C
        X = np.linalg.solve(Z, mats.GK + 1j * w[:, None, None] * mats.GC)
        return (1j * w[:, None]) ** d * np.einsum("i,kij->kj", o, X)


@runtime_checkable
class RailWheelset(Protocol):
    """What a :class:`LinearSystem` holds of each wheelset in contact with the rails.

    The parameters that the nonlinear and curving models read from a system's ``wheelsets``;
    :class:`raildyn.wheelset.Wheelset` has them all. Named here so that this module need not
    import the wheelset, which builds on it.

    Attributes
    ----------
    mass : float
        m, kg.
    yaw_inertia : float
        I_z, kg·m².
    rolling_radius, half_gauge : float
        r₀ and a, m.
    conicity : float
        λ.
    axle_load : float
        W, N.
    f11, f22, f23, f33 : float
        Kalker's coefficients of one wheel: N, N, N·m, N·m².
    contact_angle : float
        ϑ₀, rad.
    contact_angle_parameter : float
        ε.
    """

    mass: float
    yaw_inertia: float
    rolling_radius: float
    half_gauge: float
    conicity: float
    axle_load: float
    f11: float
    f22: float
    f23: float
    f33: float
    contact_angle: float
    contact_angle_parameter: float


def _wheelsets(value, labels) -> tuple:
    """The wheelsets of a system: (index of y, index of ψ, Wheelset) each, indices in range."""
    if isinstance(value, str) or not isinstance(value, (tuple, list)):
        raise TypeError(f"wheelsets must be a tuple of (int, int, Wheelset), got {value!r:.80}")
    if value:
        n = len(labels)
        for i, item in enumerate(value):
            if not (isinstance(item, (tuple, list)) and len(item) == 3 and isinstance(item[2], RailWheelset)):
                raise TypeError(f"wheelsets[{i}] must be (int, int, Wheelset), got {item!r:.80}")
            for k in (0, 1):
                _checks.integer(f"wheelsets[{i}][{k}]", item[k], low=0, high=n - 1)
    return tuple(tuple(item) for item in value)


@runtime_checkable
class LinearModel(Protocol):
    """What every linear model of raildyn offers (see the module docstring).

    A parameter set (a frozen dataclass) becomes a linear model by defining
    ``linear_system()`` and inheriting :class:`LinearModelBase`, which supplies
    the rest from it.
    """

    def linear_system(self) -> LinearSystem:
        """The assembled equations of motion with their track inputs."""
        ...

    def matrices(self, speed) -> SystemMatrices:
        """M, C(V), K, G_K, G_C at speed V.

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].

        Returns
        -------
        SystemMatrices
        """
        ...

    def state_space(self, speed, outputs=None, derivative: int = 0):
        """A ``control.StateSpace`` from the track inputs to the outputs at speed V.

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
        outputs : sequence, optional
            Output specifications (coordinate labels by default).
        derivative : {0, 1, 2}
            Displacement, velocity or acceleration outputs.

        Returns
        -------
        control.StateSpace
        """
        ...

    def replace(self, **changes) -> LinearModel:
        """A validated copy with some parameters changed.

        Parameters
        ----------
        **changes
            Parameter names and their new values.

        Returns
        -------
        LinearModel
        """
        ...


class LinearModelBase:
    """The protocol's methods for a frozen-dataclass parameter set that defines ``linear_system()``."""

    def __init__(self):
        # Only the base itself: every model is a dataclass whose generated __init__ replaces this one,
        # so that a stray argument is refused by name.
        pass

    def linear_system(self) -> LinearSystem:  # pragma: no cover - every subclass defines it
        """The assembled equations; defined by each model.

        Returns
        -------
        LinearSystem
        """
        raise NotImplementedError

    def matrices(self, speed) -> SystemMatrices:
        """M, C(V), K, G_K, G_C at the speed V.

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].

        Returns
        -------
        SystemMatrices
        """
        return self.linear_system().matrices(speed)

    def state_space(self, speed, outputs=None, derivative: int = 0):
        """The model at speed V as a ``control.StateSpace`` (see :meth:`LinearSystem.state_space`).

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
        outputs : sequence, optional
            Output specifications (coordinate labels by default).
        derivative : {0, 1, 2}
            Displacement, velocity or acceleration outputs.

        Returns
        -------
        control.StateSpace
        """
        return self.linear_system().state_space(speed, outputs, derivative)

    def replace(self, **changes):
        """A copy with some fields changed, validated again by the dataclass.

        Parameters
        ----------
        **changes
            Field names and their new values.

        Returns
        -------
        The same type as the model.
        """
        return _dataclass_replace(self, **changes)


def as_linear_system(model) -> LinearSystem:
    """The :class:`LinearSystem` of a linear model, or the system itself.

    Parameters
    ----------
    model : LinearModel or LinearSystem

    Returns
    -------
    LinearSystem

    Raises
    ------
    TypeError
        If ``model`` does not follow :class:`LinearModel`.
    """
    if isinstance(model, LinearSystem):
        return model
    _checks.not_a_class("model", model, "a linear model")
    if isinstance(model, LinearModel):
        system = model.linear_system()
        if isinstance(system, LinearSystem):
            return system
        raise TypeError(
            f"model.linear_system() must return a LinearSystem, got {type(system).__name__} "
            f"(model of type {type(model).__name__})"
        )
    raise TypeError(f"model must be a raildyn linear model (LinearModel), got {type(model).__name__}")


class _AffineFamily:
    """The matrices M, C₀, C₁ and K of ``make(*p)`` for many parameter vectors p at once.

    A model's matrices are often affine in the parameters a study moves: in the conicity (the creep
    stiffness 2af₁₁λ/r₀, and the gravitational stiffnesses Wε/a and −Waϑ₀ whose ε and ϑ₀ follow λ:
    :func:`raildyn.wheelset.creep_terms`) and in each spring, with no product of two of them. Then
    A(p) = A(p₀) + Σᵢ (pᵢ − p₀ᵢ) ∂A/∂pᵢ, each slope from one assembly at ``origin`` moved to ``far``
    in that parameter alone: a sweep over many points assembles the model 2 + len(p) times. The
    point halfway between ``origin`` and ``far`` checks the plane to round-off (1e-12 of each
    matrix): it sees both a curve along one parameter and a product of two. Where the check fails,
    :attr:`affine` is False and every point is assembled.

    ``make(*p)`` returns a linear model or its system. :attr:`assembled` maps each point assembled
    here (a tuple) to its :class:`LinearSystem`.
    """

    _NAMES = ("M", "C0", "C1", "K")

    def __init__(self, make, origin, far):
        self.make = make
        self.origin = np.asarray(origin, dtype=float)
        far = np.asarray(far, dtype=float)
        self.assembled = {tuple(self.origin.tolist()): as_linear_system(make(*self.origin))}
        base = self.assembled[tuple(self.origin.tolist())]
        self.base = {n: getattr(base, n) for n in self._NAMES}
        self.slopes = []
        for i in range(self.origin.size):
            p = self.origin.copy()
            p[i] = far[i]
            moved = self.assembled.setdefault(tuple(p.tolist()), as_linear_system(make(*p)))
            self.slopes.append(
                {n: (getattr(moved, n) - self.base[n]) / (far[i] - self.origin[i]) for n in self._NAMES}
            )
        middle = 0.5 * (self.origin + far)
        check = self.assembled.setdefault(tuple(middle.tolist()), as_linear_system(make(*middle)))
        guess = self._plane(middle[None])
        self.affine = all(
            np.abs(guess[n][0] - getattr(check, n)).max() <= 1e-12 * np.abs(getattr(check, n)).max()
            for n in self._NAMES
        )

    def _plane(self, points: np.ndarray) -> dict:
        step = points - self.origin
        return {
            n: self.base[n] + sum(step[:, i, None, None] * slope[n] for i, slope in enumerate(self.slopes))
            for n in self._NAMES
        }

    def constant(self, name: str) -> bool:
        """Whether matrix ``name`` ("M", "C0", "C1", "K") stays put as every parameter moves (affine only)."""
        return self.affine and not any(np.any(slope[name]) for slope in self.slopes)

    def stacks(self, points) -> dict:
        """{"M", "C0", "C1", "K"}: each (m, n, n), the model's matrices at each row of ``points``."""
        points = np.atleast_2d(np.asarray(points, dtype=float))
        if self.affine:
            return self._plane(points)
        systems = [as_linear_system(self.make(*p)) for p in points]
        return {n: np.stack([getattr(s, n) for s in systems]) for n in self._NAMES}


_MAX_INPUTS = 10_000


class Assembler:
    """Builds a :class:`LinearSystem` element by element.

    Parameters
    ----------
    labels : sequence of str
        Names of the coordinates (at least one, each once, none empty).
    n_inputs : int
        Number of track inputs q, in [0, 10 000] (one per wheel of a long train is far fewer).

    Examples
    --------
    Two masses on springs, the lower one on the track:

    >>> asm = Assembler(["body z", "wheel z"], n_inputs=1)
    >>> asm.mass("body z", 1000.0); asm.mass("wheel z", 100.0)
    >>> asm.element({"body z": 1.0, "wheel z": -1.0}, 1e5, 2e3)
    >>> asm.element({"wheel z": 1.0}, 1e7, inputs={0: 1.0})
    >>> asm.system().GK[:, 0]
    array([       0., 10000000.])
    """

    def __init__(self, labels: Sequence[str], n_inputs: int = 0):
        self.labels = list(_checks.strings("labels", labels, unique=True))
        n = len(self.labels)
        if n == 0:
            raise ValueError("labels must name at least one coordinate, got an empty sequence")
        q = _checks.integer("n_inputs", n_inputs, low=0, high=_MAX_INPUTS)
        self.M = np.zeros((n, n))
        self.C0 = np.zeros((n, n))
        self.C1 = np.zeros((n, n))
        self.K = np.zeros((n, n))
        self.GK = np.zeros((n, q))
        self.GC = np.zeros((n, q))
        self.KW = np.zeros((q, q))  # the inputs' own block, known while every input enters by an element
        self.CW = np.zeros((q, q))
        self.input_block_known = True
        self.wheelsets: list = []

    def index(self, label: str) -> int:
        """Position of a coordinate.

        Parameters
        ----------
        label : str
            One of the labels.

        Returns
        -------
        int
        """
        return self.labels.index(_checks.choice("label", label, self.labels))

    def vector(self, terms: dict) -> np.ndarray:
        """g with g·q = Σ coefficient · coordinate.

        Parameters
        ----------
        terms : dict of str to float
            Label → finite coefficient.

        Returns
        -------
        ndarray, (n,)
        """
        return self._vector(terms, "terms")

    def _vector(self, terms, name: str) -> np.ndarray:
        """:meth:`vector`, its messages naming ``name`` (the caller's parameter)."""
        _checks.instance(name, terms, dict, "dict of label to coefficient")
        g = np.zeros(len(self.labels))
        for label, value in terms.items():
            i = self.labels.index(_checks.choice(f"{name} key", label, self.labels))
            g[i] += _checks.scalar(f"{name}[{label!r}]", value)
        return g

    def mass(self, label: str, value: float) -> None:
        """Add a mass (kg) or inertia (kg·m²) on one coordinate.

        Parameters
        ----------
        label : str
            One of the labels.
        value : float
            > 0.
        """
        i = self.index(label)
        self.M[i, i] += _checks.positive("value", value)

    def element(self, body: dict, stiffness, damping=0.0, inputs: dict | None = None) -> None:
        """A spring and damper on d = Σ body coefficients · q − Σ input coefficients · w.

        Parameters
        ----------
        body : dict of str to float
            Coefficients of the coordinates in the deflection.
        stiffness, damping : float
            N/m and N·s/m (per radian for rotations), each ≥ 0 (a negative stiffness, such
            as gravity's, enters through :meth:`block`).
        inputs : dict of int to float, optional
            Coefficients of the track inputs in the deflection (input index in [0, q − 1]).
        """
        g = self._vector(body, "body")
        k = _checks.nonnegative("stiffness", stiffness)
        c = _checks.nonnegative("damping", damping)
        h = np.zeros(self.GK.shape[1])
        if inputs is not None:
            _checks.instance("inputs", inputs, dict, "dict of input index to coefficient or None")
            for j, value in inputs.items():
                h[self._input("inputs key", j)] += _checks.scalar(f"inputs[{j!r}]", value)
        self.K += k * np.outer(g, g)
        self.C0 += c * np.outer(g, g)
        self.GK += k * np.outer(g, h)
        self.GC += c * np.outer(g, h)
        self.KW += k * np.outer(h, h)
        self.CW += c * np.outer(h, h)

    def _input(self, name: str, j) -> int:
        """A track input index in [0, q − 1]."""
        q = self.GK.shape[1]
        if q == 0:
            raise ValueError(f"{name}: this assembly has no track inputs (n_inputs = 0), got {j!r}")
        return _checks.integer(name, j, low=0, high=q - 1)

    def block(self, labels: Sequence[str], *, C1=None, K=None) -> None:
        """Add a block of creep damping C₁ (N) and stiffness (N/m) on some coordinates.

        Parameters
        ----------
        labels : sequence of str
            The coordinates of the block's rows and columns, each once.
        C1, K : array_like, (k, k), optional
            Finite, of either sign (creep and gravity terms).
        """
        rows = [
            self.labels.index(_checks.choice("labels", s, self.labels))
            for s in _checks.strings("labels", labels, unique=True)
        ]
        k = len(rows)
        C1 = None if C1 is None else _checks.array("C1", C1, shape=(k, k))
        K = None if K is None else _checks.array("K", K, shape=(k, k))
        idx = np.ix_(rows, rows)
        if C1 is not None:
            self.C1[idx] += C1
        if K is not None:
            self.K[idx] += K

    def track_force(self, label: str, j: int, stiffness: float, damping: float = 0.0) -> None:
        """Add G_K[label, j] (N/m) and G_C[label, j] (N·s/m): a force on one coordinate per unit of input j.

        Parameters
        ----------
        label : str
            One of the labels.
        j : int
            Index of the track input, in [0, q − 1].
        stiffness, damping : float
            N/m and N·s/m per unit input, finite, of either sign.
        """
        i = self.index(label)
        j = self._input("j", j)
        self.GK[i, j] += _checks.scalar("stiffness", stiffness)
        self.GC[i, j] += _checks.scalar("damping", damping)
        self.input_block_known = False  # a force with no element: the reaction on the input is not known

    def system(self, **inputs) -> LinearSystem:
        """The assembled :class:`LinearSystem`.

        Parameters
        ----------
        **inputs
            ``input_positions``, ``input_kinds``, ``input_rails``, ``gravity_load``.

        Returns
        -------
        LinearSystem
        """
        known = self.input_block_known
        return LinearSystem(
            self.M, self.C0, self.C1, self.K, self.GK, self.GC, tuple(self.labels),
            wheelsets=tuple(self.wheelsets), input_stiffness=self.KW if known else None,
            input_damping=self.CW if known else None, **inputs,
        )  # fmt: skip
