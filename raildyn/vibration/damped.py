"""Damped many-degree-of-freedom systems M x'' + C x' + K x = B u: the first-order form.

Complex modes of the first-order form when the damping is not proportional, state-space matrices
and their python-control form, and the frequency-response matrix. SI units: m, kg, s, N, rad/s.
The undamped eigenproblem, Rayleigh damping and modal superposition are in
:mod:`raildyn.vibration.mdof`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg

from raildyn import _checks, _deprecated
from raildyn._checks import array, integer, square_matrix
from raildyn._tables import Tabular
from raildyn.vibration._domain import _pivots

__all__ = [
    "ComplexModes",
    "StateSpaceMatrices",
    "complex_modes",
    "first_order_matrix",
    "frf_matrix",
    "state_space_matrices",
    "to_control",
]

# The old names of issue 33 (raildyn._deprecated.RENAMED): each warns and gives the new object;
# they go after one issue.
__getattr__ = _deprecated.module_getattr(__name__, globals())


# The outputs that state_space_matrices can give.
_OUTPUTS = ("displacement", "velocity", "acceleration", "state")


@dataclass(frozen=True)
class ComplexModes(Tabular):
    """Modes of ``M x'' + C x' + K x = 0`` from its first-order form.

    Attributes
    ----------
    eigenvalues : complex ndarray, shape (2n,)
        The characteristic roots s_r, rad/s, ascending in |s_r|; each conjugate pair adjacent,
        Im s_r >= 0 first.
    mode_shapes : complex ndarray, shape (n, 2n)
        Displacement part of each eigenvector, scaled so its largest-magnitude
        entry is 1 + 0j (dimensionless).
    natural_frequencies : ndarray, shape (2n,)
        |s_r|, rad/s (the undamped ω_j when damping is proportional); in Hz as
        :attr:`natural_frequencies_hz`.
    damping_ratios : ndarray, shape (2n,)
        −Re s_r/|s_r| (1 for a real, overdamped eigenvalue; 0 for s_r = 0).
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("eigenvalues", "rad/s"), ("natural_frequencies", "rad/s"), ("damping_ratios", "-"),
        ("mode_shapes", "-"),
    )  # fmt: skip
    _by_row = ("mode_shapes",)

    eigenvalues: np.ndarray
    mode_shapes: np.ndarray
    natural_frequencies: np.ndarray
    damping_ratios: np.ndarray

    def __post_init__(self):
        lam = array("eigenvalues", self.eigenvalues, dtype=complex, ndim=1, allow_empty=False)
        if lam.size % 2:
            raise ValueError(f"eigenvalues must hold 2n values (n coordinates), got {lam.size}")
        n2 = (lam.size,)
        object.__setattr__(self, "eigenvalues", lam)
        shapes = array("mode_shapes", self.mode_shapes, dtype=complex, shape=(lam.size // 2, lam.size))
        object.__setattr__(self, "mode_shapes", shapes)
        w = array("natural_frequencies", self.natural_frequencies, shape=n2, low=0.0)
        object.__setattr__(self, "natural_frequencies", w)
        object.__setattr__(self, "damping_ratios", array("damping_ratios", self.damping_ratios, shape=n2))

    @property
    def natural_frequencies_hz(self) -> np.ndarray:
        """|s_r|/(2π), Hz."""
        return self.natural_frequencies / (2.0 * np.pi)

    def relative_phase(self, coordinate: int, reference: int) -> np.ndarray:
        """Phase of one coordinate relative to another in each mode, arg(φ_coordinate/φ_reference).

        Zero or ±π for a real (proportionally damped) mode: the two move in or
        against phase; anything else shows that damping couples the modes.

        Parameters
        ----------
        coordinate : int
            Index of the coordinate, 0 <= coordinate < n.
        reference : int
            Index of the reference coordinate, 0 <= reference < n; its entry must not vanish.

        Returns
        -------
        ndarray, shape (2n,)
            Phase in rad, in (−π, π], one per eigenvalue.

        Examples
        --------
        >>> modes = complex_modes(np.eye(2), np.zeros((2, 2)), [[2.0, -1.0], [-1.0, 2.0]])
        >>> np.round(np.degrees(modes.relative_phase(1, 0)[::2]), 6)
        array([  0., 180.])
        """
        n = self.mode_shapes.shape[0]
        i = integer("coordinate", coordinate, low=0, high=n - 1)
        j = integer("reference", reference, low=0, high=n - 1)
        ref = self.mode_shapes[j]
        if np.any(ref == 0):
            raise ValueError(
                f"reference must be a coordinate that moves in every mode; coordinate {j} is at rest "
                f"in mode(s) {np.flatnonzero(ref == 0).tolist()}"
            )
        return np.angle(self.mode_shapes[i] / ref)


@dataclass(frozen=True)
class StateSpaceMatrices:
    """The matrices of z' = A z + B u, y = C z + D u (:func:`state_space_matrices`).

    Attributes
    ----------
    A : ndarray, shape (2n, 2n)
        State matrix, blocks in 1/s² and 1/s.
    B : ndarray, shape (2n, m)
        Input matrix.
    C : ndarray, shape (p, 2n)
        Output matrix.
    D : ndarray, shape (p, m)
        Feedthrough matrix.
    """

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray

    def __post_init__(self):
        A = square_matrix("A", self.A, symmetric=False)
        B = array("B", self.B, shape=(A.shape[0], None), allow_empty=False)
        C = array("C", self.C, shape=(None, A.shape[0]), allow_empty=False)
        D = array("D", self.D, shape=(C.shape[0], B.shape[1]))
        for name, value in zip("ABCD", (A, B, C, D), strict=True):
            object.__setattr__(self, name, value)

    def to_control(self):
        """The same system as a ``control.StateSpace`` (python-control).

        Returns
        -------
        control.StateSpace
        """
        import control  # imported here so that importing raildyn does not pull in python-control

        return control.ss(self.A, self.B, self.C, self.D)


def _damped_matrices(M, C, K) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Checked M, C, K of a damped system.

    C and K may be non-symmetric (creep forces make them so in the wheelset
    models of later chapters); M must be symmetric positive definite.
    """
    M = square_matrix("M", M, positive_definite=True)
    C = square_matrix("C", C, size=M.shape[0], symmetric=False)
    K = square_matrix("K", K, size=M.shape[0], symmetric=False)
    return M, C, K


def first_order_matrix(M, C, K) -> np.ndarray:
    """The state matrix A of z' = A z, z = [x; x'], for M x'' + C x' + K x = 0: the one builder in raildyn.

    A = [[0, I], [−M⁻¹K, −M⁻¹C]] (Garg & Dukkipati 1984, ch. 1, the state-space
    form). C and K may be non-symmetric; M must be symmetric positive definite.
    M, C and K may also be stacks of shape (m, n, n) (for example one C per
    speed of a sweep): A then has shape (m, 2n, 2n).

    Parameters
    ----------
    M, C, K : array_like, (n, n) or (m, n, n)
        Mass, damping and stiffness, in consistent units, finite; M (each M of a
        stack) symmetric positive definite, C and K any real matrices.

    Returns
    -------
    ndarray, (2n, 2n) or (m, 2n, 2n)
        1/s² and 1/s blocks as in the equation.

    Examples
    --------
    >>> first_order_matrix([[2.0]], [[4.0]], [[8.0]])
    array([[ 0.,  1.],
           [-4., -2.]])
    """
    Ms, Cs, Ks = (array(name, X) for name, X in (("M", M), ("C", C), ("K", K)))
    if max(Ms.ndim, Cs.ndim, Ks.ndim) == 2:
        Ms, Cs, Ks = _damped_matrices(Ms, Cs, Ks)
    else:
        Ms, Cs, Ks = _stacks(Ms, Cs, Ks)
    n = Ms.shape[-1]
    A = np.zeros(Ms.shape[:-2] + (2 * n, 2 * n))
    A[..., :n, n:] = np.eye(n)
    A[..., n:, :] = -np.linalg.solve(Ms, np.concatenate([Ks, Cs], axis=-1))
    return A


def _stacks(M: np.ndarray, C: np.ndarray, K: np.ndarray) -> tuple[np.ndarray, ...]:
    """Finite stacks of square matrices broadcast together; each M symmetric positive definite."""
    for name, X in (("M", M), ("C", C), ("K", K)):
        if X.ndim not in (2, 3) or X.shape[-1] != X.shape[-2] or X.size == 0:
            raise ValueError(
                f"{name} must be a square matrix (n, n) or a stack of them (m, n, n), got {X.shape}"
            )
    try:
        Ms, Cs, Ks = np.broadcast_arrays(M, C, K)
    except ValueError:
        raise ValueError(
            f"M, C and K must be stacks of one size, got {M.shape}, {C.shape} and {K.shape}"
        ) from None
    if np.abs(M - np.swapaxes(M, -1, -2)).max() > 1e-10 * np.abs(M).max():
        raise ValueError("M must hold symmetric matrices")
    try:
        np.linalg.cholesky(M)
    except np.linalg.LinAlgError:
        raise ValueError("M must hold positive definite matrices") from None
    return Ms, Cs, Ks


def _first_order(M, C, K) -> tuple[np.ndarray, np.ndarray]:
    """Checked M and the matrix A of :func:`first_order_matrix`."""
    M, C, K = _damped_matrices(M, C, K)
    return M, first_order_matrix(M, C, K)


def complex_modes(M, C, K) -> ComplexModes:
    """Eigenvalues and complex mode shapes of ``M x'' + C x' + K x = 0``, any damping.

    Writes the system in first-order form z' = A z with
    A = [[0, I], [−M⁻¹K, −M⁻¹C]] and solves A z = s_r z (scipy.linalg.eig). For
    an underdamped mode s_r = −ξω ± iω√(1 − ξ²), the multi-degree-of-freedom
    counterpart of the roots s₁, s₂ of eq. (1.9).

    Parameters
    ----------
    M : array_like, shape (n, n)
        Mass matrix, kg; symmetric positive definite.
    C, K : array_like, shape (n, n)
        Damping (N·s/m) and stiffness (N/m) matrices; any finite real matrices
        (they need not be symmetric, and an unstable system has modes too).

    Returns
    -------
    ComplexModes
        Eigenvalues s_r (rad/s), complex shapes, |s_r| and damping ratios.

    Notes
    -----
    An undamped rigid-body mode has a defective double eigenvalue 0; rounding
    splits it into a pair of size about √ε times the other eigenvalues.

    Examples
    --------
    >>> modes = complex_modes([[1.0]], [[0.2]], [[1.0]])
    >>> np.round(modes.eigenvalues, 6), np.round(modes.damping_ratios, 6)
    (array([-0.1+0.994987j, -0.1-0.994987j]), array([0.1, 0.1]))
    """
    M, A = _first_order(M, C, K)
    n = M.shape[0]
    lam, vec = scipy.linalg.eig(A)
    # LAPACK returns real eigenvalues of a real matrix with Im exactly 0 and complex ones in exact
    # conjugate pairs; keep the upper member of each pair and rebuild the lower as its conjugate.
    keep = np.flatnonzero(lam.imag >= 0.0)
    keep = keep[np.argsort(np.abs(lam[keep]), kind="stable")]
    shapes = vec[:n, keep]
    pivots = _pivots(shapes)
    shapes = shapes / shapes[pivots]
    shapes[pivots] = 1.0  # exactly, rather than z/z rounded
    values, columns = [], []
    for i, j in enumerate(keep):
        values.append(lam[j])
        columns.append(shapes[:, i])
        if lam[j].imag > 0.0:
            values.append(np.conj(lam[j]))
            columns.append(np.conj(shapes[:, i]))
    values = np.array(values)
    freq = np.abs(values)
    ratio = np.divide(-values.real, freq, out=np.zeros(freq.shape), where=freq > 0)
    return ComplexModes(
        eigenvalues=values,
        mode_shapes=np.stack(columns, axis=1),
        natural_frequencies=freq,
        damping_ratios=ratio,
    )


def state_space_matrices(M, C, K, B, output: str = "displacement") -> StateSpaceMatrices:
    """State-space matrices of ``M x'' + C x' + K x = B u`` with state z = [x; x'].

    z' = A z + B_s u, y = C_s z + D u, with A = [[0, I], [−M⁻¹K, −M⁻¹C]] and
    B_s = [[0], [M⁻¹B]].

    Parameters
    ----------
    M, C, K : array_like, shape (n, n)
        Mass (kg), damping (N·s/m) and stiffness (N/m) matrices; M symmetric
        positive definite, C and K any finite real matrices (creep forces make
        them non-symmetric, and a model may be unstable).
    B : array_like, shape (n, m) or (n,)
        How each of the m >= 1 inputs (N, or whatever unit makes B u a force)
        loads each coordinate, any finite values.
    output : {"displacement", "velocity", "acceleration", "state"}
        y = x (m), x' (m/s), x'' (m/s², with D = M⁻¹B) or the whole state z.

    Returns
    -------
    StateSpaceMatrices
        A, B = B_s, C = C_s and D, of shapes (2n, 2n), (2n, m), (p, 2n), (p, m),
        with p = 2n for "state" and n otherwise.

    Examples
    --------
    >>> state_space_matrices([[2.0]], [[0.0]], [[8.0]], [[1.0]]).A
    array([[ 0.,  1.],
           [-4., -0.]])
    """
    output = _checks.choice("output", output, _OUTPUTS)
    M, A = _first_order(M, C, K)
    n = M.shape[0]
    Bm = array("B", B)
    Bm = array("B", Bm[:, None] if Bm.ndim == 1 else Bm, shape=(n, None), allow_empty=False)
    m = Bm.shape[1]
    accel_input = np.linalg.solve(M, Bm)
    Bs = np.vstack([np.zeros((n, m)), accel_input])
    zeros = np.zeros((n, m))
    if output == "displacement":
        Cs, D = np.hstack([np.eye(n), np.zeros((n, n))]), zeros
    elif output == "velocity":
        Cs, D = np.hstack([np.zeros((n, n)), np.eye(n)]), zeros
    elif output == "acceleration":
        Cs, D = A[n:].copy(), accel_input
    else:
        Cs, D = np.eye(2 * n), np.zeros((2 * n, m))
    return StateSpaceMatrices(A=A, B=Bs, C=Cs, D=D)


def to_control(M, C, K, B, output: str = "displacement"):
    """The system of :func:`state_space_matrices` as a ``control.StateSpace`` (python-control).

    Parameters
    ----------
    M, C, K : array_like, shape (n, n)
        Mass (kg), damping (N·s/m) and stiffness (N/m) matrices, as for
        :func:`~raildyn.vibration.state_space_matrices`.
    B : array_like, shape (n, m) or (n,)
        How each input loads each coordinate, as for :func:`~raildyn.vibration.state_space_matrices`.
    output : {"displacement", "velocity", "acceleration", "state"}
        As for :func:`state_space_matrices`.

    Returns
    -------
    control.StateSpace

    Examples
    --------
    >>> import control
    >>> sys = to_control([[1.0]], [[0.4]], [[4.0]], [[1.0]])
    >>> np.round(np.sort_complex(control.poles(sys)), 6)
    array([-0.2-1.989975j, -0.2+1.989975j])
    """
    return state_space_matrices(M, C, K, B, output).to_control()


def frf_matrix(M, C, K, omega) -> np.ndarray:
    """Receptance matrix H(ω) = (K − ω²M + iωC)⁻¹, m/N, at each circular frequency.

    The MDOF counterpart of :meth:`SDOF.receptance`: X = H(ω) F for a
    harmonic force F e^(iωt). All frequencies are solved in one batched call.

    Parameters
    ----------
    M, C, K : array_like, shape (n, n)
        Mass (kg), damping (N·s/m) and stiffness (N/m) matrices; M symmetric
        positive definite, C and K any finite real matrices.
    omega : array_like, shape (n_omega,)
        rad/s, >= 0, not empty.

    Returns
    -------
    complex ndarray, shape (n_omega, n, n)

    Raises
    ------
    ValueError
        If K − ω²M + iωC is singular, as for an undamped system exactly at a
        natural frequency.

    Examples
    --------
    >>> frf_matrix([[1.0]], [[0.0]], [[4.0]], [0.0, 1.0])[:, 0, 0]
    array([0.25      +0.j, 0.33333333+0.j])
    """
    M, C, K = _damped_matrices(M, C, K)
    n = M.shape[0]
    w = np.atleast_1d(array("omega", omega, low=0.0, allow_empty=False))
    if w.ndim != 1:
        raise ValueError(f"omega must be a number or a 1-dimensional array, got shape {w.shape}")
    # Z/s² with s = max(ω, 1 rad/s), and H = (Z/s²)⁻¹/s²: every term stays finite for any finite ω
    # (1e300 included), and nothing changes for ω <= 1.
    inv = (1.0 / np.maximum(w, 1.0))[:, None, None]
    u = w[:, None, None] * inv
    Z = K * (inv * inv) - (u * u) * M + 1j * (u * inv) * C
    try:
        return np.linalg.solve(Z, np.broadcast_to(np.eye(n, dtype=complex), Z.shape)) * (inv * inv)
    except np.linalg.LinAlgError:
        bad = [float(x) for x, z in zip(w, Z, strict=True) if np.linalg.matrix_rank(z) < n]
        raise ValueError(
            f"K − ω²M + iωC is singular at omega = {bad} rad/s (an undamped natural frequency?); "
            "the response there is unbounded"
        ) from None
