"""Several degrees of freedom: M x'' + C x' + K x = F(t) (book chapter 1).

The undamped eigenproblem with mass-normalised modes, modal superposition,
Rayleigh (proportional) damping, complex modes of the first-order form when the
damping is not proportional, state-space matrices for python-control, and the
frequency-response matrix. SI units: m, kg, s, N, rad/s.

Results are frozen dataclasses: :class:`ModalResult`, :class:`ComplexModes`,
:class:`ChainMatrices`, :class:`RayleighCoefficients` and
:class:`StateSpaceMatrices`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg

from raildyn import _checks
from raildyn._checks import array, integer, nonnegative, positive, scalar, square_matrix, time_grid
from raildyn.vibration.sdof import _MAX_COUNT, _MAX_PHASE, _RATE, SDOF

__all__ = [
    "ChainMatrices",
    "ComplexModes",
    "ModalResult",
    "RayleighCoefficients",
    "StateSpaceMatrices",
    "chain_matrices",
    "complex_modes",
    "first_order_matrix",
    "frf_matrix",
    "modal_analysis",
    "modal_damping_ratios",
    "modal_superposition",
    "rayleigh_coefficients",
    "rayleigh_damping",
    "state_space",
    "to_control",
    "uniform_chain_frequencies",
]

# The outputs that state_space can give.
_OUTPUTS = ("displacement", "velocity", "acceleration", "state")

# ---------------------------------------------------------------------------
# Several degrees of freedom


@dataclass(frozen=True)
class ModalResult:
    """Undamped modes of ``M x'' + K x = 0``.

    Attributes
    ----------
    natural_frequencies : ndarray, shape (n,)
        ω_j in rad/s, ascending (0.0 for a rigid-body mode); in Hz as
        :attr:`natural_frequencies_hz`.
    mode_shapes : ndarray, shape (n, n)
        Column j is mode j, scaled so that Φᵀ M Φ = I (units kg^(−1/2)) and its
        largest-magnitude entry is positive.
    """

    natural_frequencies: np.ndarray
    mode_shapes: np.ndarray

    def __post_init__(self):
        w = array("natural_frequencies", self.natural_frequencies, ndim=1, low=0.0, allow_empty=False)
        object.__setattr__(self, "natural_frequencies", w)
        object.__setattr__(
            self, "mode_shapes", array("mode_shapes", self.mode_shapes, shape=(w.size, w.size))
        )

    @property
    def natural_frequencies_hz(self) -> np.ndarray:
        """f_j = ω_j/(2π), Hz."""
        return self.natural_frequencies / (2.0 * np.pi)

    def modal_matrix(self, matrix) -> np.ndarray:
        """A matrix in modal coordinates, Φᵀ X Φ.

        With the mass matrix it gives the identity, with the stiffness matrix
        diag(ω_j²) (the orthogonality of the modes); with a damping matrix it is
        diagonal only for proportional damping.

        Parameters
        ----------
        matrix : array_like, shape (n, n)
            X: M (kg), C (N·s/m), K (N/m) or any other finite (n, n) matrix.

        Returns
        -------
        ndarray, shape (n, n)
            Φᵀ X Φ: dimensionless for M, 1/s for C, 1/s² for K.

        Examples
        --------
        >>> chain = chain_matrices([1.0, 1.0], [1.0, 1.0])
        >>> modes = modal_analysis(chain.M, chain.K)
        >>> np.round(modes.modal_matrix(chain.M), 12)
        array([[1., 0.],
               [0., 1.]])
        """
        n = self.mode_shapes.shape[0]
        X = square_matrix("matrix", matrix, size=n, symmetric=False)
        return self.mode_shapes.T @ X @ self.mode_shapes


@dataclass(frozen=True)
class ComplexModes:
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
class ChainMatrices:
    """Mass, damping and stiffness matrices of a chain of masses (:func:`chain_matrices`).

    Attributes
    ----------
    M : ndarray, shape (n, n)
        Mass matrix, kg (diagonal).
    C : ndarray, shape (n, n)
        Damping matrix, N·s/m (zeros when no dampers were given).
    K : ndarray, shape (n, n)
        Stiffness matrix, N/m.
    """

    M: np.ndarray
    C: np.ndarray
    K: np.ndarray

    def __post_init__(self):
        M = square_matrix("M", self.M)
        object.__setattr__(self, "M", M)
        object.__setattr__(self, "C", square_matrix("C", self.C, size=M.shape[0]))
        object.__setattr__(self, "K", square_matrix("K", self.K, size=M.shape[0]))


@dataclass(frozen=True)
class RayleighCoefficients:
    """Coefficients of Rayleigh (proportional) damping C = a_M M + a_K K.

    Attributes
    ----------
    alpha : float
        a_M, 1/s.
    beta : float
        a_K, s.
    """

    alpha: float
    beta: float

    def __post_init__(self):
        object.__setattr__(self, "alpha", scalar("alpha", self.alpha))
        object.__setattr__(self, "beta", scalar("beta", self.beta))

    def damping_ratio(self, omega):
        """Damping ratio ξ(ω) = a_M/(2ω) + a_Kω/2 that C = a_M M + a_K K gives a mode of frequency ω.

        Parameters
        ----------
        omega : array_like
            ω, rad/s, > 0, any shape (not empty).

        Returns
        -------
        ndarray or float
            ξ, shape of ``omega``.
        """
        w = array("omega", omega, low=0.0, low_open=True, allow_empty=False)
        with np.errstate(over="ignore"):
            xi = self.alpha / (2.0 * w) + self.beta * w / 2.0
        if not np.all(np.isfinite(xi)):
            raise ValueError(f"omega from {w.min():.4g} to {w.max():.4g} rad/s gives a damping ratio beyond "
                             "floating point range")  # fmt: skip
        return xi[()]

    def damping_matrix(self, M, K) -> np.ndarray:
        """C = a_M M + a_K K, N·s/m (see :func:`rayleigh_damping`).

        Parameters
        ----------
        M : array_like, shape (n, n)
            Mass matrix, kg; symmetric positive definite.
        K : array_like, shape (n, n)
            Stiffness matrix, N/m; symmetric positive semi-definite.

        Returns
        -------
        ndarray, shape (n, n)
        """
        return rayleigh_damping(M, K, self.alpha, self.beta)


@dataclass(frozen=True)
class StateSpaceMatrices:
    """The matrices of z' = A z + B u, y = C z + D u (:func:`state_space`).

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


def _pivots(vectors: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Index arrays (rows, columns) of the entry of largest magnitude in each column.

    Ties within a relative 1e-8 (a symmetric chain has entries ±a) go to the
    first such row, so the sign or phase convention does not hang on rounding.
    """
    mag = np.abs(vectors)
    rows = np.argmax(mag >= (1.0 - 1e-8) * mag.max(axis=0), axis=0)
    return rows, np.arange(vectors.shape[1])


def _mass_and_stiffness(M, K):
    M = square_matrix("M", M, positive_definite=True)
    K = square_matrix("K", K, size=M.shape[0], positive_semidefinite=True)
    return M, K


def _modes(M: np.ndarray, K: np.ndarray) -> ModalResult:
    lam, phi = scipy.linalg.eigh(K, M)  # eigh scales the vectors so that Φᵀ M Φ = I
    # Eigenvalues within rounding of zero are rigid-body modes: the computed value carries no correct
    # digit below about n ε ‖K‖/λ_min(M), so it is set to exactly zero (negatives included).
    noise = 1e3 * lam.size * np.finfo(float).eps * np.abs(K).max() / np.linalg.eigvalsh(M)[0]
    lam = np.where(lam > noise, lam, 0.0)
    phi = phi * np.sign(phi[_pivots(phi)])
    return ModalResult(natural_frequencies=np.sqrt(lam), mode_shapes=phi)


def modal_analysis(M, K) -> ModalResult:
    """Natural frequencies and mass-normalised mode shapes of ``M x'' + K x = 0``.

    Solves the generalised eigenproblem K φ = ω² M φ (scipy.linalg.eigh), with
    Φᵀ M Φ = I and Φᵀ K Φ = diag(ω²). An eigenvalue ω² smaller than the
    rounding error of the solve (about 1e3 n ε ‖K‖/λ_min(M)) has no correct
    digit and is reported as exactly 0: a rigid-body mode.

    Parameters
    ----------
    M : array_like, shape (n, n)
        Mass matrix, kg (or kg·m² for rotations); symmetric positive definite.
    K : array_like, shape (n, n)
        Stiffness matrix, N/m; symmetric positive semi-definite (a free-free
        system has zero-frequency rigid-body modes).

    Returns
    -------
    ModalResult
        ω_j (rad/s, also in Hz) and the mass-normalised shapes.

    Examples
    --------
    >>> chain = chain_matrices([1.0, 1.0], [1.0, 1.0])
    >>> np.round(modal_analysis(chain.M, chain.K).natural_frequencies ** 2, 6)  # (3 ∓ √5)/2
    array([0.381966, 2.618034])
    """
    return _modes(*_mass_and_stiffness(M, K))


def _chain_assembly(name: str, values, n: int, grounded: bool, low_open: bool) -> np.ndarray:
    """The matrix of springs (or dampers) joining a chain of n masses in order."""
    want = n if grounded else n - 1
    k = array(name, values, ndim=1, low=0.0, low_open=low_open)
    if k.size != want:
        kind = "grounded (fixed-free)" if grounded else "free-free"
        raise ValueError(f"{name} must have {want} entries for a {kind} chain of {n} masses, got {k.size}")
    right = np.arange(n - want, n)  # the mass at the far end of each spring
    left = right - 1  # −1 is the ground
    K = np.zeros((n, n))
    np.add.at(K, (right, right), k)
    inner = left >= 0
    np.add.at(K, (left[inner], left[inner]), k[inner])
    np.add.at(K, (left[inner], right[inner]), -k[inner])
    np.add.at(K, (right[inner], left[inner]), -k[inner])
    return K


def chain_matrices(masses, stiffnesses, *, dampings=None, grounded: bool = True) -> ChainMatrices:
    """Mass, damping and stiffness matrices of masses in a line joined by springs (and dampers).

    Springs join neighbouring masses in order. With ``grounded=True`` there is
    one more spring, listed first, tying mass 0 to the ground, and the last
    mass is free (fixed-free); otherwise both ends are free (free-free, with one
    rigid-body mode). Dampers, if given, sit beside the springs.

    Parameters
    ----------
    masses : array_like, shape (n,)
        kg, > 0.
    stiffnesses : array_like, shape (n,) if grounded else (n − 1,)
        N/m, > 0.
    dampings : array_like, optional
        N·s/m, >= 0 (zero: that damper is absent), one beside each spring; no damping by default.
    grounded : bool
        Whether the first spring (and damper) ties mass 0 to the ground.

    Returns
    -------
    ChainMatrices
        M (kg), C (N·s/m) and K (N/m), each (n, n).

    Examples
    --------
    >>> chain_matrices([1.0, 2.0], [3.0, 4.0]).K
    array([[ 7., -4.],
           [-4.,  4.]])
    """
    m = array("masses", masses, ndim=1, low=0.0, low_open=True)
    if m.size == 0:
        raise ValueError("masses must hold at least one mass, got an empty array")
    grounded = _checks.flag("grounded", grounded)
    K = _chain_assembly("stiffnesses", stiffnesses, m.size, grounded, low_open=True)
    C = (
        np.zeros_like(K)
        if dampings is None
        else _chain_assembly("dampings", dampings, m.size, grounded, low_open=False)
    )
    return ChainMatrices(M=np.diag(m), C=C, K=K)


def uniform_chain_frequencies(count: int, mass: float, stiffness: float) -> np.ndarray:
    """Natural frequencies of a uniform fixed-free chain in closed form.

    For n equal masses m joined by n equal springs k, the first tied to the
    ground (``chain_matrices([m] * n, [k] * n)``), the modes are discrete
    sines and ω_j = 2√(k/m) sin((2j − 1)π / (2(2n + 1))), j = 1 … n.

    Parameters
    ----------
    count : int
        n, from 1 to 1_000_000 (a bound on the memory asked for).
    mass : float
        m, kg, > 0.
    stiffness : float
        k, N/m, > 0.

    Returns
    -------
    ndarray, shape (n,)
        ω_j, rad/s, ascending.

    Examples
    --------
    >>> np.round(uniform_chain_frequencies(2, 1.0, 1.0) ** 2, 6)  # (3 ∓ √5)/2
    array([0.381966, 2.618034])
    """
    n = integer("count", count, low=1, high=_MAX_COUNT)
    m = positive("mass", mass)
    k = positive("stiffness", stiffness)
    j = np.arange(1, n + 1)
    return 2.0 * np.sqrt(k / m) * np.sin((2 * j - 1) * np.pi / (2 * (2 * n + 1)))


def rayleigh_coefficients(omega1: float, omega2: float, xi1: float, xi2: float) -> RayleighCoefficients:
    """Coefficients (a_M, a_K) of C = a_M M + a_K K that give damping ratios ξ₁ at ω₁ and ξ₂ at ω₂.

    Mode j then has ξ_j = a_M/(2ω_j) + a_Kω_j/2 (Rayleigh damping; see Clough &
    Penzien, *Dynamics of Structures*, 2nd ed., 1993). Very unequal ratios can
    make a_M or a_K negative, which damps some other frequencies negatively; check
    the result.

    Parameters
    ----------
    omega1, omega2 : float
        Distinct circular frequencies, rad/s, > 0.
    xi1, xi2 : float
        Damping ratios wanted there, >= 0.

    Returns
    -------
    RayleighCoefficients
        a_M (1/s) and a_K (s), in the fields ``alpha`` and ``beta``.

    Examples
    --------
    >>> c = rayleigh_coefficients(1.0, 3.0, 0.05, 0.05)
    >>> round(c.alpha, 6), round(c.beta, 6)
    (0.075, 0.025)
    """
    w1, w2 = positive("omega1", omega1), positive("omega2", omega2)
    if w1 == w2:
        raise ValueError(f"omega2 must differ from omega1 to fix two coefficients, both are {w1!r}")
    x1, x2 = nonnegative("xi1", xi1), nonnegative("xi2", xi2)
    # ω₂² − ω₁² = (ω₂ − ω₁)(ω₂ + ω₁), divided by one factor at a time so that nothing overflows
    d, s = w2 - w1, w2 + w1
    alpha = 2.0 * (w1 / s) * w2 * (x1 * w2 - x2 * w1) / d
    beta = 2.0 * (x2 * w2 - x1 * w1) / d / s
    if not (np.isfinite(alpha) and np.isfinite(beta)):
        raise ValueError(
            f"omega1 = {w1!r}, omega2 = {w2!r}, xi1 = {x1!r} and xi2 = {x2!r} give coefficients beyond "
            f"floating point range (alpha = {alpha!r}, beta = {beta!r})"
        )
    return RayleighCoefficients(alpha=alpha, beta=beta)


def rayleigh_damping(M, K, alpha: float, beta: float) -> np.ndarray:
    """Proportional damping matrix C = a_M M + a_K K (Rayleigh damping).

    Parameters
    ----------
    M : array_like, shape (n, n)
        Mass matrix, kg; symmetric positive definite.
    K : array_like, shape (n, n)
        Stiffness matrix, N/m; symmetric positive semi-definite.
    alpha : float
        a_M, 1/s (any finite value).
    beta : float
        a_K, s (any finite value).

    Returns
    -------
    ndarray, shape (n, n)
        C, N·s/m.

    Examples
    --------
    >>> rayleigh_damping(np.eye(1), 4.0 * np.eye(1), 0.5, 0.25)
    array([[1.5]])
    """
    M, K = _mass_and_stiffness(M, K)
    a, b = scalar("alpha", alpha), scalar("beta", beta)
    with np.errstate(over="ignore", invalid="ignore"):
        C = a * M + b * K
    if not np.all(np.isfinite(C)):
        raise ValueError(
            f"alpha = {a!r} and beta = {b!r} with these M and K give a C beyond floating point range"
        )
    return C


def modal_damping_ratios(M, C, K) -> np.ndarray:
    """Damping ratio of each undamped mode, ξ_j = (Φᵀ C Φ)_jj / (2ω_j), for proportional damping.

    Parameters
    ----------
    M, C, K : array_like, shape (n, n)
        Mass (kg), damping (N·s/m) and stiffness (N/m) matrices.

    Returns
    -------
    ndarray, shape (n,)
        In the order of :func:`modal_analysis`. An undamped rigid-body mode
        (ω_j = 0) gets 0.

    Raises
    ------
    ValueError
        If Φᵀ C Φ is not diagonal to 1e-8 of its largest entry: the modes
        are then coupled by damping, and :func:`complex_modes` applies. Also
        if C damps a rigid-body mode, whose ratio c/(2ω_j) is then unbounded.

    Examples
    --------
    >>> chain = chain_matrices([1.0, 1.0], [1.0, 1.0])
    >>> np.round(modal_damping_ratios(chain.M, 0.1 * chain.K, chain.K), 6)  # ξ_j = 0.1 ω_j / 2
    array([0.030902, 0.080902])
    """
    M, K = _mass_and_stiffness(M, K)
    C = square_matrix("C", C, size=M.shape[0], symmetric=False)
    modes = _modes(M, K)
    phi = modes.mode_shapes
    modal = phi.T @ C @ phi
    scale = max(np.abs(modal).max(), np.finfo(float).tiny)
    coupling = np.abs(modal - np.diag(np.diag(modal))).max() / scale
    if coupling > 1e-8:
        raise ValueError(
            f"C is not proportional damping for the modes of M and K: Φᵀ C Φ has off-diagonal terms up "
            f"to {coupling:.3g} of its largest entry; use complex_modes for non-proportional damping"
        )
    c, w = np.diag(modal), modes.natural_frequencies
    if np.any((w == 0) & (c > 1e-8 * scale)):
        raise ValueError(
            "C damps a rigid-body (zero-frequency) mode of M and K, whose damping ratio c/(2 omega) is "
            "unbounded; use complex_modes"
        )
    return np.divide(c, 2.0 * w, out=np.zeros_like(c), where=w > 0)


def _rigid_body_response(h: float, f: np.ndarray, q0: float, v0: float) -> np.ndarray:
    """Exact q(t) of q'' = f for f linear between samples h apart (a zero-frequency mode)."""
    v = v0 + np.concatenate([[0.0], np.cumsum(0.5 * h * (f[:-1] + f[1:]))])
    step = h * v[:-1] + h**2 * (2.0 * f[:-1] + f[1:]) / 6.0
    return q0 + np.concatenate([[0.0], np.cumsum(step)])


def modal_superposition(M, K, t, x0=None, v0=None, force=None, damping_ratios=None) -> np.ndarray:
    """Response of ``M x'' + C x' + K x = F(t)`` as a sum of uncoupled modal responses.

    With x = Φ q, each modal coordinate obeys q_j'' + 2ξ_jω_j q_j' + ω_j² q_j = φ_jᵀ F,
    solved exactly by :meth:`SDOF.free_response` or :meth:`SDOF.forced_response`
    (force linear between samples). Damping is modal: C never appears, only ξ_j.
    A rigid-body mode (ω_j = 0) is integrated exactly and undamped, whatever
    its ξ_j (its modal damping 2ξ_jω_j is zero).

    Parameters
    ----------
    M, K : array_like, shape (n, n)
        Mass (kg) and stiffness (N/m) matrices, as in :func:`modal_analysis`.
    t : array_like, shape (n_t,)
        Strictly increasing times, s; t[0] is the initial instant. Uniformly
        spaced when ``force`` is given, with ω_j h <= 1e12 rad for the step h
        (as for :meth:`~raildyn.vibration.SDOF.forced_response`).
    x0, v0 : array_like, shape (n,), optional
        Initial displacements (m) and velocities (m/s), any sign; zero by default.
    force : array_like, shape (n, n_t), optional
        Force on each coordinate (N) at the times ``t``.
    damping_ratios : float or array_like, shape (n,), optional
        ξ for every mode or for each, >= 0, with 2ξ_jω_j <= 1e300 1/s (the domain of
        :class:`~raildyn.vibration.SDOF`); zero by default.

    Returns
    -------
    ndarray, shape (n, n_t)
        Displacements, m.

    Examples
    --------
    >>> chain = chain_matrices([1.0], [4.0])
    >>> np.round(modal_superposition(chain.M, chain.K, [0.0, np.pi / 2], x0=[1.0]), 12)
    array([[ 1., -1.]])
    """
    M, K = _mass_and_stiffness(M, K)
    n = M.shape[0]
    t = time_grid("t", t, uniform=force is not None)
    x0 = np.zeros(n) if x0 is None else array("x0", x0, shape=(n,))
    v0 = np.zeros(n) if v0 is None else array("v0", v0, shape=(n,))
    xi = np.zeros(n) if damping_ratios is None else array("damping_ratios", damping_ratios, low=0.0)
    if xi.ndim != 0 and xi.shape != (n,):
        raise ValueError(f"damping_ratios must be a number or have shape ({n},), got shape {xi.shape}")
    xi = np.broadcast_to(xi, (n,))
    modes = _modes(M, K)
    w = modes.natural_frequencies
    if np.any(2.0 * xi * w > _RATE):
        raise ValueError(
            f"damping_ratios must keep 2 xi_j omega_j <= 1e300 1/s (the domain of SDOF), got "
            f"{(2.0 * xi * w).max():.4g} with these M and K"
        )
    if force is not None and t.size > 1 and w.max() * (t[-1] - t[0]) / (t.size - 1) > _MAX_PHASE:
        raise ValueError(
            f"t must have a step h with omega_j h <= {_MAX_PHASE:g} rad for every mode of M and K; the "
            f"highest omega_j = {w.max():.4g} rad/s with h = {(t[-1] - t[0]) / (t.size - 1):.4g} s exceeds it"
        )
    phi = modes.mode_shapes
    q0, qd0 = phi.T @ M @ x0, phi.T @ M @ v0  # Φᵀ M Φ = I inverts x = Φ q
    tau = t - t[0]
    fq = None if force is None else phi.T @ array("force", force, shape=(n, t.size))
    q = np.empty((n, t.size))
    for j, w in enumerate(modes.natural_frequencies):
        if w == 0.0:
            h = tau[-1] / (t.size - 1) if t.size > 1 else 0.0
            q[j] = q0[j] + qd0[j] * tau if fq is None else _rigid_body_response(h, fq[j], q0[j], qd0[j])
        else:
            mode = SDOF.from_modal(w, xi[j])
            q[j] = (
                mode.free_response(tau, q0[j], qd0[j])
                if fq is None
                else mode.forced_response(t, fq[j], q0[j], qd0[j])
            )
    return phi @ q


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


def state_space(M, C, K, B, output: str = "displacement") -> StateSpaceMatrices:
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
    >>> state_space([[2.0]], [[0.0]], [[8.0]], [[1.0]]).A
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
    """The system of :func:`state_space` as a ``control.StateSpace`` (python-control).

    Parameters
    ----------
    M, C, K : array_like, shape (n, n)
        Mass (kg), damping (N·s/m) and stiffness (N/m) matrices, as for
        :func:`~raildyn.vibration.state_space`.
    B : array_like, shape (n, m) or (n,)
        How each input loads each coordinate, as for :func:`~raildyn.vibration.state_space`.
    output : {"displacement", "velocity", "acceleration", "state"}
        As for :func:`state_space`.

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
    return state_space(M, C, K, B, output).to_control()


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
