"""Several degrees of freedom: M x'' + C x' + K x = F(t) (book chapter 1).

The undamped eigenproblem with mass-normalised modes, spring–mass chains, modal superposition and
Rayleigh (proportional) damping. SI units: m, kg, s, N, rad/s. Results are frozen dataclasses:
:class:`ModalResult`, :class:`ChainMatrices` and :class:`RayleighCoefficients`.

Damping that is not proportional (the first-order form, complex modes, state-space matrices,
python-control, the frequency-response matrix) is in :mod:`raildyn.vibration.damped`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg

from raildyn import _checks, _deprecated
from raildyn._checks import array, integer, nonnegative, positive, scalar, square_matrix, time_grid
from raildyn._tables import Tabular
from raildyn.vibration._domain import _MAX_COUNT, _MAX_PHASE, _RATE, _pivots

# Moved to raildyn.vibration.damped (issue 33): re-exported here so that the old import paths keep
# working for one issue; then these lines go.
from raildyn.vibration.damped import (  # noqa: F401
    ComplexModes,
    StateSpaceMatrices,
    complex_modes,
    first_order_matrix,
    frf_matrix,
    state_space_matrices,
    to_control,
)
from raildyn.vibration.sdof import SDOF

__all__ = [
    "ChainMatrices",
    "ModalResult",
    "RayleighCoefficients",
    "chain_matrices",
    "modal_analysis",
    "modal_damping_ratios",
    "modal_superposition",
    "rayleigh_coefficients",
    "rayleigh_damping",
    "uniform_chain_frequencies",
]

# The old names of issue 33 (raildyn._deprecated.RENAMED): each warns and gives the new object;
# they go after one issue.
__getattr__ = _deprecated.module_getattr(__name__, globals())


# ---------------------------------------------------------------------------
# Several degrees of freedom


@dataclass(frozen=True)
class ModalResult(Tabular):
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

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("natural_frequencies", "rad/s"), ("mode_shapes", "kg^(−1/2)"))
    _by_row = ("mode_shapes",)

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
