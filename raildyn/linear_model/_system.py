"""The assembled equations of a linear model: :class:`LinearSystem`, and its matrices at one speed.

Part of :mod:`raildyn.linear_model` (see its docstring for the protocol); import the names from there.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from dataclasses import replace as _dataclass_replace
from typing import Protocol, runtime_checkable

import numpy as np

from raildyn import _checks
from raildyn.constants import MAXIMUM_FREQUENCY
from raildyn.vibration import first_order_matrix

__all__ = ["INPUT_KINDS", "LinearSystem", "RailWheelset", "SystemMatrices"]

# What a track input can be (documented where the package exports it, raildyn.linear_model.INPUT_KINDS)
INPUT_KINDS = ("vertical", "alignment", "cross_level")


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


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class LinearSystem:
    """A linear model: M q̈ + (C₀ + C₁/V) q̇ + K q = G_K w(t) + G_C ẇ(t).

    Input j is the track met at distance ``input_positions[j]`` behind the
    leading axle, so that at speed V it arrives τ_j = d_j/V later; its kind is
    ``input_kinds[j]`` (one of :data:`raildyn.linear_model.INPUT_KINDS`) and, for a rail height, its
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
            rad/s, at least one, each in [0, :data:`~raildyn.constants.MAXIMUM_FREQUENCY`] (10⁶):
            far above any mode of a vehicle, and low enough that ω²M cannot overflow.
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
        if w.max() > MAXIMUM_FREQUENCY:
            raise ValueError(f"omega must be at most {MAXIMUM_FREQUENCY:g} rad/s, got {w.max()!r}")
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
