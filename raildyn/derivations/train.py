"""Chapter 9's coupler chain derived: n vehicles joined by draft gears, linearised beyond the slack.

The train of :mod:`raildyn.train.longitudinal` is nonlinear: each coupler has a free gap (the slack
e) and a friction draft gear whose loading and unloading branches differ. Once the slack of every
coupler has closed and each gear is being loaded further, the coupler is a linear spring of the
loading stiffness k_l, and the train moves as a chain of masses and springs, damped by the part of
its running resistance that grows with speed. :func:`coupler_chain` derives that chain by
Lagrange's equations (:func:`raildyn.derivations.lagrange`); :func:`loaded_train_matrices` gives the
numbers it is held to, the Jacobian of :meth:`raildyn.train.model.TrainModel.rhs` at a
state where every coupler is loaded beyond its slack.
"""

from __future__ import annotations

import functools

import numpy as np
import sympy

from raildyn import _checks
from raildyn.constants import MAXIMUM_SPEED
from raildyn.derivations._core import Derivation, Step, coordinates, generalized_forces, lagrange, time

__all__ = ["coupler_chain", "loaded_train_matrices"]

_STEP_EXTENSION = 1e-4  # m: central-difference step of the extensions (inside the linear branch)
_STEP_SPEED = 1e-2  # m/s: of the speeds (exact for the quadratic resistance)
_LOADING_RATES = 50.0  # each coupler's rate, in transition rates: 1 − tanh² < 1e-42


def coupler_chain(count: int = 3) -> Derivation:
    """n vehicles in a line, joined by couplers loaded beyond their slack, resisted by Davis's law.

    Vehicle i (0 at the front) of mass m_i runs at the speed V + ẋ_i, where x_i is its
    displacement from a reference motion at the train's speed V. Coupler i, behind vehicle i, has
    the extension Δx_i = Δx_i⁰ + x_i − x_{i+1} (Δx_i⁰ its value in the reference motion); beyond
    the slack e its draft gear deflects by u_i = Δx_i − e/2 in draft (−Δx_i − e/2 in buff) and,
    while it is being loaded further, pushes back with the loading stiffness k_i (Cole 2006;
    :class:`raildyn.train.DraftGear`), storing U_i = ½ k_i u_i². Each vehicle is held back by
    the Davis resistance R_i = A_i + B_i v + C_i v² at its speed v (Davis 1926; book ch. 9),
    which works through x_i. Lagrange's equations about the reference motion give

        m_i ẍ_i + (B_i + 2 C_i V) ẋ_i + k_{i−1}(x_i − x_{i−1}) + k_i(x_i − x_{i+1}) = 0,

    the constant forces (the couplers' preload, A_i + B_i V + C_i V²) setting the reference motion
    and dropping out of the equations for x.

    Parameters
    ----------
    count : int
        n, the number of vehicles, in [2, 8] (the symbolic algebra grows as n²: 4 s at 8).

    Returns
    -------
    Derivation
        Coordinates x_0 … x_{n−1} (m); speed V (m/s); parameters read from a
        :class:`raildyn.train.TrainModel`: m_i from ``consist.mass``, k_i from
        ``gear.loading_stiffness``, B_i and C_i from ``davis_coefficients`` (rows 1 and 2).

    Examples
    --------
    >>> d = coupler_chain(2)
    >>> d.K
    Matrix([
    [ k_0, -k_0],
    [-k_0,  k_0]])
    """
    n = _checks.integer("count", count, low=2, high=8)
    return _coupler_chain(n)


@functools.cache  # the checked count only
def _coupler_chain(n: int) -> Derivation:
    x = coordinates(" ".join(f"x_{i}" for i in range(n)))
    xd = [xi.diff(time) for xi in x]
    V = sympy.Symbol("V", positive=True)
    e = sympy.Symbol("e", nonnegative=True)
    ms = sympy.symbols(f"m_0:{n}", positive=True)
    ks = sympy.symbols(f"k_0:{n - 1}", positive=True)
    A = sympy.symbols(f"A_0:{n}", nonnegative=True)
    B = sympy.symbols(f"B_0:{n}", nonnegative=True)
    C = sympy.symbols(f"C_0:{n}", nonnegative=True)
    reference = sympy.symbols(f"Δx_0:{n - 1}__0", positive=True)  # Δx_i⁰, beyond the slack in draft
    extension = [reference[i] + x[i] - x[i + 1] for i in range(n - 1)]
    deflection = [dx - e / 2 for dx in extension]  # in draft; in buff u = −Δx − e/2, the same k
    speed = [V + v for v in xd]
    resistance = [A[i] + B[i] * speed[i] + C[i] * speed[i] ** 2 for i in range(n)]

    T = sum(m * v**2 for m, v in zip(ms, speed, strict=True)) / 2
    U = sum(k * u**2 for k, u in zip(ks, deflection, strict=True)) / 2
    Q = generalized_forces([(-R, xi) for R, xi in zip(resistance, x, strict=True)], x)
    M, Cm, K, GK, GC = lagrange(T, U, 0, x, forces=Q)

    def davis(row, i):
        return lambda model: model.davis_coefficients[row, i]

    def mass(i):
        return lambda model: model.consist.mass[i]

    parameters = (
        tuple((s, mass(i)) for i, s in enumerate(ms))
        + tuple((s, "gear.loading_stiffness") for s in ks)
        + tuple((s, davis(1, i)) for i, s in enumerate(B))
        + tuple((s, davis(2, i)) for i, s in enumerate(C))
    )
    v = sympy.Symbol("v")
    return Derivation(
        title=f"coupler chain of {n} vehicles (draft gears loaded beyond the slack)",
        coordinates=x,
        M=M,
        C=Cm,
        K=K,
        GK=GK,
        GC=GC,
        parameters=parameters,
        speed=V,
        steps=(
            Step("coupler extension", sympy.Eq(sympy.Symbol("Δx_0"), extension[0])),
            Step(
                "draft-gear deflection beyond the slack (draft)", sympy.Eq(sympy.Symbol("u_0"), deflection[0])
            ),
            Step("Davis resistance", sympy.Eq(sympy.Function("R_0")(v), A[0] + B[0] * v + C[0] * v**2)),
            Step("kinetic energy", sympy.Eq(sympy.Symbol("T"), T)),
            Step("potential energy of the draft gears", sympy.Eq(sympy.Symbol("U"), U)),
            Step(
                "generalized forces of the resistance (virtual work)",
                sympy.Eq(sympy.Matrix(sympy.symbols(f"Q_0:{n}")), Q, evaluate=False),
            ),
        ),
    )


def loaded_train_matrices(model, speed: float, deflection=0.01, signs=1.0) -> tuple:
    """M, C, K of a train model linearised numerically, where :func:`coupler_chain` holds.

    Central differences of :meth:`raildyn.train.model.TrainModel.rhs` (its accelerations times the
    masses), at the two states where the chain is the exact linearisation:

    * K, at a state where every coupler is ``deflection`` beyond its slack (in draft where
      ``signs`` is +1, in buff where it is −1) and is being loaded further, each coupler's rate
      50 of the gear's transition rates in its own sense (1 − tanh² < 1e-42: the loading branch).
      There the force k_l(|Δx| − e/2) is linear in Δx, so the difference (step 0.1 mm) has no
      truncation error. The front vehicle runs at ``speed``, each one behind at its coupler's rate
      less.
    * C, with every vehicle at ``speed`` and every slack centred (no coupler force, whatever the
      rate): the resistance A + Bv + Cv² is quadratic in v, where the difference (step 1 cm/s) is
      exact too.

    What is left is round-off, ε|a|/h: under 1e-11 of the matrices' largest entries for real
    trains. The derived chain leaves out traction, dynamic brake, grade and curvature, so it
    matches a model on level track with the throttle at idle (the air brake adds only constant
    forces above the creep speed).

    Parameters
    ----------
    model : raildyn.train.TrainModel
        The train (2 to 1000 vehicles).
    speed : float
        V, m/s: every vehicle's speed for C, the front vehicle's for K; every vehicle's speed
        must stay within [40 v_c, 200] (v_c the model's creep speed, so that tanh(v/v_c) = 1).
    deflection : float or array_like (n−1,)
        Each draft gear's deflection beyond the slack, m: at least the gear's ``smoothing``
        plus 0.2 mm (past the rounded corner) and at most its ``travel`` less 0.2 mm (short
        of the solid branch).
    signs : float or array_like (n−1,)
        +1 (draft) or −1 (buff) for each coupler.

    Returns
    -------
    tuple of ndarray
        (M, C, K), each (n, n): kg, N·s/m, N/m, in the vehicles' displacements x_0 … x_{n−1}.

    Examples
    --------
    >>> from raildyn.train import TrainModel, make_consist
    >>> model = TrainModel(make_consist("1 SD40-2 + 2 loaded hopper"))
    >>> M, C, K = loaded_train_matrices(model, 20.0)
    >>> round(float(K[0, 1] / model.gear.loading_stiffness), 9)
    -1.0
    """
    from raildyn.train import TrainModel  # the numerical model, only when it is asked for

    _checks.instance("model", model, TrainModel)
    n = model.size
    if n < 2:
        raise ValueError(f"model must have at least 2 vehicles (one coupler), got {n}")
    gear = model.gear
    speed = _checks.speed("speed", speed, low=40 * model.creep_speed, low_open=False)
    u = _per_coupler("deflection", deflection, n)
    low = (gear.smoothing if gear.slack > 0 else 0.0) + 2 * _STEP_EXTENSION
    high = gear.travel - 2 * _STEP_EXTENSION
    if u.min() < low or u.max() > high:
        raise ValueError(
            f"deflection must lie in [{low:.6g}, {high:.6g}] m (past the slack's rounded corner, short "
            f"of the solid branch), got {deflection!r:.80}"
        )
    sign = _per_coupler("signs", signs, n)
    if not np.all(np.abs(sign) == 1.0):
        raise ValueError(f"signs must each be +1 (draft) or -1 (buff), got {signs!r:.80}")
    rate = sign * _LOADING_RATES * gear.transition_rate
    v = speed - np.r_[0.0, np.cumsum(rate)]
    if v.min() < 40 * model.creep_speed or v.max() > MAXIMUM_SPEED:
        raise ValueError(
            f"speed must keep every vehicle within [{40 * model.creep_speed:.6g}, {MAXIMUM_SPEED:g}] m/s "
            f"while the "
            f"couplers load at {_LOADING_RATES * gear.transition_rate:.3g} m/s each; got {speed!r}, "
            f"which gives [{v.min():.6g}, {v.max():.6g}]"
        )
    x0 = model.initial_state(speed)[0]
    loaded = np.r_[x0, sign * (gear.slack / 2 + u), v]
    jz = _jacobian(model, loaded, np.arange(n), _STEP_EXTENSION)  # over [x_0, Δx_0 … Δx_{n−2}]
    # [x_0, Δx] = P x: Δx_j = x_j − x_{j+1} − (its spacing)
    P = np.zeros((n, n))
    P[0, 0] = 1.0
    P[np.arange(1, n), np.arange(n - 1)] = 1.0
    P[np.arange(1, n), np.arange(1, n)] = -1.0
    mass = model.consist.mass
    K = -mass[:, None] * (jz @ P)
    C = -mass[:, None] * _jacobian(model, model.initial_state(speed, 0.0), np.arange(n, 2 * n), _STEP_SPEED)
    return np.diag(mass), C, K


def _per_coupler(name, value, n):
    """One number for every coupler, or one each: a float array (n − 1,)."""
    arr = _checks.array(name, value)
    if arr.ndim == 0:
        return np.full(n - 1, float(arr))
    return _checks.array(name, arr, shape=(n - 1,))


def _jacobian(model, y, rows, step):
    """∂(v̇)/∂y[rows] of the model at y, by central differences (one batched rhs call)."""
    n, k = model.size, len(rows)
    plus = np.repeat(y[:, None], k, axis=1)
    minus = plus.copy()
    plus[rows, np.arange(k)] += step
    minus[rows, np.arange(k)] -= step
    return (model.rhs(0.0, plus)[n:] - model.rhs(0.0, minus)[n:]) / (2 * step)
