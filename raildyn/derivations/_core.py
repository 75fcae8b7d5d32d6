"""The one shape of a symbolic derivation, and Lagrange's equations that produce it.

A :class:`Derivation` holds linear equations of motion

    M q̈ + C q̇ + K q = G_K w + G_C ẇ

as sympy matrices, the steps that led to them (energies, creepages, forces) for a notebook to
display, and the map from each symbol to the number a raildyn model holds, so that
:meth:`Derivation.numeric` evaluates the derived matrices for that model and a test can hold them
to the model's own ``matrices(speed)``.

:func:`lagrange` writes Lagrange's equations d/dt ∂T/∂q̇ − ∂T/∂q + ∂V/∂q + ∂D/∂q̇ = Q for given
kinetic and potential energies, Rayleigh's dissipation function and generalized forces, and
linearises them about q = 0; :func:`generalized_forces` gives Q from forces and the displacements
they work through (virtual work).
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import sympy
from sympy.physics.mechanics import dynamicsymbols

from raildyn import _checks

__all__ = ["Derivation", "Step", "coordinates", "generalized_forces", "lagrange", "time"]

time = dynamicsymbols._t
"""The time t that every coordinate and input is a function of."""


def coordinates(names: str) -> tuple:
    """Functions of time for coordinates or track inputs, e.g. ``coordinates("y psi")``.

    Parameters
    ----------
    names : str
        Names separated by spaces, as for ``sympy.symbols``; Greek names print as letters.

    Returns
    -------
    tuple of sympy functions of ``time``
    """
    _checks.instance("names", names, str)
    if not names.split():
        raise ValueError(f"names must name at least one coordinate, got {names!r}")
    out = dynamicsymbols(names)
    return tuple(out) if isinstance(out, (list, tuple)) else (out,)


@dataclass(frozen=True)
class Step:
    """One step of a derivation, shown in its notebook: a caption and the equation it states.

    Attributes
    ----------
    caption : str
        What the step is, in words ("kinetic energy").
    equation : sympy.Basic
        The step itself, usually a ``sympy.Eq``.
    """

    caption: str
    equation: sympy.Basic

    def __post_init__(self):
        _checks.instance("caption", self.caption, str)
        _checks.instance("equation", self.equation, sympy.Basic)

    def _repr_latex_(self) -> str:
        return f"$\\displaystyle {sympy.latex(self.equation)}$"


def _functions_of_time(name: str, value, allow_empty: bool = True) -> tuple:
    """A tuple of distinct functions of ``time`` (coordinates or inputs)."""
    if not isinstance(value, tuple) or not all(
        isinstance(f, sympy.Function) and f.args == (time,) for f in value
    ):
        raise TypeError(f"{name} must be a tuple of functions of t (from coordinates()), got {value!r:.80}")
    if not allow_empty and not value:
        raise ValueError(f"{name} must hold at least one function of t, got an empty tuple")
    if len(set(value)) != len(value):
        raise ValueError(f"{name} must be distinct, got {value}")
    return value


def _expression(name: str, value):
    """A sympy expression (a plain 0 or other real number is turned into one)."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        value = _checks.scalar(name, value)
        return sympy.Integer(0) if value == 0 else sympy.Float(value)
    if not isinstance(value, sympy.Expr):
        raise TypeError(f"{name} must be a sympy expression, got {value!r:.80}")
    if value.has(sympy.nan, sympy.zoo, sympy.oo, -sympy.oo):
        raise ValueError(f"{name} must be finite, got {value}")
    return value


def _getter(name, source) -> Callable:
    """A function of the model giving a parameter's value: a dotted attribute path or a callable."""
    if callable(source):
        return source
    if isinstance(source, str) and source:
        return lambda model: functools.reduce(getattr, source.split("."), model)
    raise TypeError(f"parameter {name} must map to an attribute path (str) or a callable, got {source!r:.80}")


@dataclass(frozen=True, eq=False)  # sympy matrices: compared by identity
class Derivation:
    """Linear equations of motion M q̈ + C q̇ + K q = G_K w + G_C ẇ, derived symbolically.

    Attributes
    ----------
    title : str
        The model ("wheelset on its primary suspension").
    coordinates : tuple of sympy functions of t
        q, n of them (m or rad).
    M, C, K : sympy.Matrix, (n, n)
        Mass, damping and stiffness; C may hold the speed V (creep damping C₁/V).
    GK, GC : sympy.Matrix, (n, p)
        Forces per unit track input and per unit input rate (p may be 0).
    inputs : tuple of sympy functions of t
        w, the p track inputs.
    parameters : tuple of (sympy.Symbol, str or callable)
        Each symbol of the matrices and where a model holds its value: a dotted attribute path
        (``"wheelset.f11"``) or a function of the model.
    speed : sympy.Symbol or None
        V, the forward speed, if the matrices hold it.
    steps : tuple of Step
        The derivation, step by step, for a notebook to show.
    """

    title: str
    coordinates: tuple
    M: sympy.Matrix
    C: sympy.Matrix
    K: sympy.Matrix
    GK: sympy.Matrix
    GC: sympy.Matrix
    inputs: tuple = ()
    parameters: tuple = ()
    speed: sympy.Symbol | None = None
    steps: tuple = ()

    def __post_init__(self):
        _checks.instance("title", self.title, str)
        n = len(_functions_of_time("coordinates", self.coordinates, allow_empty=False))
        p = len(_functions_of_time("inputs", self.inputs))
        if not isinstance(self.parameters, tuple) or not all(
            isinstance(item, tuple) and len(item) == 2 and isinstance(item[0], sympy.Symbol)
            for item in self.parameters
        ):
            raise TypeError(
                f"parameters must be a tuple of (sympy.Symbol, source) pairs, got {self.parameters!r:.80}"
            )
        for symbol, source in self.parameters:
            _getter(symbol, source)
        if self.speed is not None and not isinstance(self.speed, sympy.Symbol):
            raise TypeError(f"speed must be a sympy Symbol or None, got {self.speed!r:.80}")
        if not isinstance(self.steps, tuple):
            raise TypeError(f"steps must be a tuple of Step, got {self.steps!r:.80}")
        for name, rows, cols in (("M", n, n), ("C", n, n), ("K", n, n), ("GK", n, p), ("GC", n, p)):
            value = getattr(self, name)
            if not isinstance(value, sympy.MatrixBase) or value.shape != (rows, cols):
                raise ValueError(f"{name} must be a sympy Matrix of shape {(rows, cols)}, got {value!r:.80}")
        for i, step in enumerate(self.steps):
            _checks.instance(f"steps[{i}]", step, Step)
        symbols = [s for s, _ in self.parameters]
        free = set().union(*(getattr(self, m).free_symbols for m in ("M", "C", "K", "GK", "GC")))
        free -= {self.speed, time}
        missing = free - set(symbols)
        if missing:
            raise ValueError(
                f"parameters must give a value for every symbol of the matrices; missing {missing}"
            )

    @property
    def labels(self) -> tuple:
        """The coordinates' names, in order."""
        return tuple(str(q.func) for q in self.coordinates)

    def equations(self) -> sympy.Eq:
        """The equations of motion as one matrix equation, M q̈ + C q̇ + K q = G_K w + G_C ẇ.

        Returns
        -------
        sympy.Eq
        """
        q = sympy.Matrix(self.coordinates)
        w = sympy.Matrix(self.inputs)
        left = self.M * q.diff(time, 2) + self.C * q.diff(time) + self.K * q
        right = self.GK * w + self.GC * w.diff(time) if self.inputs else sympy.zeros(len(q), 1)
        return sympy.Eq(sympy.simplify(left), sympy.simplify(right))

    @functools.cached_property
    def _functions(self):
        """The five matrices as one numpy function of the parameters and the speed (lambdified once)."""
        args = [s for s, _ in self.parameters] + [self.speed if self.speed is not None else sympy.Dummy()]
        return sympy.lambdify(args, [self.M, self.C, self.K, self.GK, self.GC], modules="numpy")

    def values(self, model) -> dict:
        """The value of every parameter symbol for a model.

        Parameters
        ----------
        model : object
            Whatever holds the numbers (a raildyn parameter set, a dict read through callables).

        Returns
        -------
        dict
            sympy.Symbol → float.
        """
        out = {}
        for symbol, source in self.parameters:
            try:
                value = _getter(symbol, source)(model)
            except (AttributeError, KeyError, IndexError, TypeError) as error:
                raise TypeError(
                    f"model must hold the parameters of the {self.title} ({symbol} from {source!r}), got "
                    f"{type(model).__name__} {model!r:.60}: {error}"
                ) from None
            out[symbol] = _checks.scalar(f"model parameter {symbol}", value)
        return out

    def numeric(self, model, speed=None) -> tuple:
        """The derived M, C, K, G_K, G_C evaluated for a model, as float arrays.

        Parameters
        ----------
        model : object
            Holds the parameters' values (see ``parameters``).
        speed : float, optional
            V, m/s (> 0); needed when the matrices hold the speed.

        Returns
        -------
        tuple of ndarray
            (M, C, K, GK, GC), shapes (n, n) × 3 and (n, p) × 2.
        """
        if self.speed is not None:
            speed = _checks.speed("speed", speed)
        elif speed is not None:  # unused by a speed-free model, but still a speed
            speed = _checks.speed("speed", speed, signed=True)
        values = list(self.values(model).values())
        n, p = len(self.coordinates), len(self.inputs)
        shapes = ((n, n),) * 3 + ((n, p),) * 2
        return tuple(
            np.broadcast_to(np.asarray(a, dtype=float), s).copy()
            for a, s in zip(self._functions(*values, 1.0 if speed is None else speed), shapes, strict=True)
        )

    def difference(self, matrices, model, speed=None) -> float:
        """The largest difference between the derived matrices and a model's, relative to each matrix.

        Parameters
        ----------
        matrices : sequence of array_like
            (M, C, K) or (M, C, K, GK, GC) of the model, e.g. from its ``matrices(speed)``.
        model, speed
            As for :meth:`numeric`.

        Returns
        -------
        float
            max over the matrices of max|derived − given| / max(max|given|, tiny).
        """
        derived = self.numeric(model, speed)
        if not isinstance(matrices, Sequence) or len(matrices) not in (3, 5):
            raise TypeError(f"matrices must be (M, C, K) or (M, C, K, GK, GC), got {matrices!r:.80}")
        worst = 0.0
        for name, mine, theirs in zip(("M", "C", "K", "GK", "GC"), derived, matrices, strict=False):
            theirs = _checks.array(f"matrices {name}", theirs, shape=mine.shape)
            scale = max(np.abs(theirs).max(initial=0.0), np.finfo(float).tiny)
            worst = max(worst, float(np.abs(mine - theirs).max(initial=0.0) / scale))
        return worst

    def _repr_latex_(self) -> str:
        return f"$\\displaystyle {sympy.latex(self.equations())}$"


def lagrange(kinetic, potential, dissipation, coords: Sequence, forces=None, inputs: Sequence = ()) -> tuple:
    """Lagrange's equations, linearised about q = 0: M, C, K, G_K, G_C.

    Forms E_i = d/dt ∂T/∂q̇_i − ∂T/∂q_i + ∂U/∂q_i + ∂D/∂q̇_i − Q_i for each coordinate, then takes
    M = ∂E/∂q̈, C = ∂E/∂q̇, K = ∂E/∂q, G_K = −∂E/∂w and G_C = −∂E/∂ẇ at rest (q, q̇, w, ẇ = 0).
    Nonlinear terms (a pendulum's cos θ, a body's weight on a roll angle) linearise exactly; the
    entries are expanded, not simplified, so that a model of fifteen coordinates takes seconds.

    Parameters
    ----------
    kinetic, potential, dissipation : sympy expression
        T, U and Rayleigh's D, in the coordinates, their rates and the inputs.
    coords : sequence of sympy functions of t
        q.
    forces : sympy.Matrix, optional
        Q, the generalized forces not in U or D (e.g. creep forces), one per coordinate.
    inputs : sequence of sympy functions of t
        w, the track inputs.

    Returns
    -------
    tuple of sympy.Matrix
        (M, C, K, GK, GC).

    Examples
    --------
    A wheel of mass m on the primary spring k and damper c of a body of mass M, each moving
    vertically (z_w, z_b); the track lifts the spring k_t under the wheel by w:

    >>> import sympy
    >>> m, M, k, c, kt = sympy.symbols("m M k c k_t", positive=True)
    >>> zw, zb, w = coordinates("z_w z_b w")
    >>> T = (m * zw.diff() ** 2 + M * zb.diff() ** 2) / 2
    >>> U = (k * (zb - zw) ** 2 + kt * (zw - w) ** 2) / 2
    >>> D = c * (zb.diff() - zw.diff()) ** 2 / 2
    >>> M_, C, K, GK, GC = lagrange(T, U, D, [zw, zb], inputs=[w])
    >>> K
    Matrix([
    [k + k_t, -k],
    [     -k,  k]])
    >>> GK.T
    Matrix([[k_t, 0]])
    """
    kinetic = _expression("kinetic", kinetic)
    potential = _expression("potential", potential)
    dissipation = _expression("dissipation", dissipation)
    q = list(_functions_of_time("coords", tuple(coords) if isinstance(coords, list) else coords, False))
    w = list(_functions_of_time("inputs", tuple(inputs) if isinstance(inputs, list) else inputs))
    if forces is not None and not isinstance(forces, sympy.MatrixBase):
        raise TypeError(
            f"forces must be a sympy Matrix (one generalized force per coordinate), got {forces!r:.80}"
        )
    Q = sympy.zeros(len(q), 1) if forces is None else forces
    if Q.shape != (len(q), 1):
        raise ValueError(
            f"forces must hold one generalized force per coordinate ({len(q)}), got shape {Q.shape}"
        )
    # Plain symbols stand in for the coordinates, the inputs and their rates (sympy differentiates a
    # function of t slowly); a derivative is replaced whole, before the function inside it.
    n, p = len(q), len(w)
    qs, qds, qdds = (sympy.symbols(f"{k}0:{n}") for k in ("_q", "_qd", "_qdd"))
    ws, wds, wdds = (sympy.symbols(f"{k}0:{p}") for k in ("_w", "_wd", "_wdd")) if p else ((), (), ())
    plain = {c.diff(time, 2): s for c, s in zip(q + w, qdds + wdds, strict=True)}
    plain |= {c.diff(time): s for c, s in zip(q + w, qds + wds, strict=True)}
    plain |= dict(zip(q + w, qs + ws, strict=True))
    T, U, D = (e.xreplace(plain) for e in (kinetic, potential, dissipation))
    Q = Q.xreplace(plain)
    rates = list(zip(qs + ws + qds + wds, qds + wds + qdds + wdds, strict=True))

    def ddt(f):  # the total time derivative of f(q, q̇, w, ẇ, t): t may remain in other functions of t
        return sum((sympy.diff(f, x) * dx for x, dx in rates), sympy.diff(f, time))

    E = [
        ddt(sympy.diff(T, qd)) - sympy.diff(T, qi) + sympy.diff(U, qi) + sympy.diff(D, qd) - Q[i]
        for i, (qi, qd) in enumerate(zip(qs, qds, strict=True))
    ]
    rest = dict.fromkeys(qs + qds + qdds + ws + wds + wdds, 0)
    if p and any(sympy.diff(e, x).xreplace(rest) != 0 for e in E for x in wdds):
        raise ValueError(
            "kinetic must not couple the coordinates' rates to the inputs' rates (an input acceleration)"
        )

    def coefficients(variables):  # ∂E_i/∂v_j at rest: the linear equations' matrix for those variables
        if not variables:
            return sympy.zeros(n, 0)
        return sympy.Matrix(
            n, len(variables), lambda i, j: sympy.expand(sympy.diff(E[i], variables[j]).xreplace(rest))
        )

    return coefficients(qdds), coefficients(qds), coefficients(qs), -coefficients(ws), -coefficients(wds)


def generalized_forces(pairs: Sequence, coords: Sequence) -> sympy.Matrix:
    """Q_i = Σ_k F_k ∂u_k/∂q_i: generalized forces by virtual work.

    Parameters
    ----------
    pairs : sequence of (force, displacement)
        Each force F_k (a sympy expression) and the displacement u_k of its point along its line
        of action, in the coordinates (and inputs).
    coords : sequence of sympy functions of t
        q.

    Returns
    -------
    sympy.Matrix, (n, 1)
    """
    coords = _functions_of_time("coords", tuple(coords) if isinstance(coords, list) else coords, False)
    if not isinstance(pairs, (list, tuple)) or not all(
        isinstance(p, (list, tuple)) and len(p) == 2 for p in pairs
    ):
        raise TypeError(f"pairs must be a sequence of (force, displacement), got {pairs!r:.80}")
    pairs = [
        (_expression(f"pairs[{i}] force", f), _expression(f"pairs[{i}] displacement", u))
        for i, (f, u) in enumerate(pairs)
    ]
    Q = sympy.zeros(len(coords), 1)
    for force, displacement in pairs:
        for i, c in enumerate(coords):
            Q[i] += force * sympy.diff(displacement, c)
    return Q
