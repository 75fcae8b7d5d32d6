"""An independent finite-element engine for the bridge checks: OpenSeesPy (tests and benchmarks only).

Not part of raildyn. The same simply supported beam that :mod:`raildyn.bridge.beam` solves by its
modes is meshed here with OpenSees's 2-D Euler–Bernoulli ``elasticBeamColumn`` elements (``Linear``
transformation; consistent mass ``-cMass``, built from the same cubic Hermite shape functions as the
stiffness, so that a few elements give the low modes closely: 40 elements give f₁ and f₂ of a
20 m span to 1e-6), pinned at x = 0 and on a roller at x = L, and integrated in
time by Newmark's average acceleration (γ = 1/2, β = 1/4: unconditionally stable, no numerical
damping; Newmark 1959). Only the vertical displacement and the rotation of each node are free:
the axial motion is not excited by vertical loads on a straight beam and is fixed.

Damping: by default Rayleigh's, a₀M + a₁K fitted to ζ at the first two bending modes (Chopra
2012, §11.4), one linear solve a step. OpenSees's ``modalDamping`` gives every computed mode the
same ζ, as raildyn's beam does, but OpenSees (3.7) puts it in the residual and not in the tangent:
with the one-solve ``Linear`` algorithm it is plainly wrong (a DAF of 0.8 for 1.23 at α = 0.25,
measured), so a step iterates to equilibrium (modified Newton), about three times slower.

Moving loads: each axle's force acts on the element under it as the consistent (Hermite)
equivalent nodal forces and moments, f = P [N₁, N₂, N₃, N₄] at the element's relative position
ξ (Przemieniecki 1968), which a Newmark step sees exactly at the end of the step. Every
node's vertical force and moment histories are tabulated beforehand at the time steps and
applied as ``Path`` time series, one per node and direction.

Sign convention: deflection and loads positive downwards, as in
:func:`raildyn.bridge.beam.moving_force_response`; the bending moment positive sagging.
"""

from __future__ import annotations

import time as _time
from dataclasses import dataclass

import numpy as np
import openseespy.opensees as ops

__all__ = ["FEResponse", "SprungMassFEResponse", "fe_moving_forces", "fe_sprung_mass_crossing"]

G = 9.80665  # m/s², standard gravity (3rd CGPM 1901), for the sprung mass's weight


@dataclass(frozen=True, eq=False)
class FEResponse:
    """The finite-element answer at one point of the beam.

    Attributes
    ----------
    time : ndarray, (k,)
        t, s, from the leading axle's arrival at x = 0.
    deflection : ndarray, (k,)
        w at ``position``, m, downwards positive.
    moment : ndarray, (k,)
        Bending moment at the node nearest ``position``, N·m, sagging positive: the mean of the two
        elements that meet there, each's end moment K u less its axles' equivalent nodal moment.
    position : float
        x, m.
    frequencies_hz : ndarray, (2,)
        The mesh's first two bending frequencies, Hz.
    seconds : float
        Wall time of the OpenSees model and its time stepping, s.
    """

    time: np.ndarray
    deflection: np.ndarray
    moment: np.ndarray
    position: float
    frequencies_hz: np.ndarray
    seconds: float


@dataclass(frozen=True, eq=False)
class SprungMassFEResponse:
    """The finite-element answer for a sprung mass crossing the beam.

    Attributes
    ----------
    time : ndarray, (k,)
        t, s, from the wheel's arrival at x = 0.
    deflection : ndarray, (k,)
        Beam deflection at ``position``, m, downwards positive.
    contact_force : ndarray, (k,)
        Force of the wheel on the beam, N, downwards positive (the weight at rest); 0 once the
        wheel has left.
    body_displacement : ndarray, (k,)
        The sprung mass's displacement from its static equilibrium on a rigid support, m,
        downwards positive.
    iterations : ndarray, (k,)
        ``ops.analyze(1)`` calls each step took to settle the contact force (0 after the wheel left;
        3 as a rule: the previous force, the force it gives, the secant's).
    position : float
        x, m.
    seconds : float
        Wall time, s.
    """

    time: np.ndarray
    deflection: np.ndarray
    contact_force: np.ndarray
    body_displacement: np.ndarray
    iterations: np.ndarray
    position: float
    seconds: float


def _positive(name, value):
    value = float(value)
    if not np.isfinite(value) or value <= 0.0:
        raise ValueError(f"{name} must be finite and > 0, got {value!r}")
    return value


def _common(span, EI, m, damping_ratio, speed, elements, damping_model):
    """Check the arguments both solvers share."""
    for name, value in (("span", span), ("EI", EI), ("m", m), ("speed", speed)):
        _positive(name, value)
    if not 0.0 <= float(damping_ratio) < 1.0:
        raise ValueError(f"damping_ratio must lie in [0, 1), got {damping_ratio!r}")
    if int(elements) != elements or elements < 2 or elements > 1000 or elements % 2:
        raise ValueError(f"elements must be an even integer in [2, 1000], got {elements!r}")
    if damping_model not in ("rayleigh", "modal"):
        raise ValueError(f"damping_model must be 'rayleigh' or 'modal', got {damping_model!r}")


def _hermite(xi, h, derivative=0):
    """Cubic Hermite shape functions at relative positions ξ of an element, or their x-derivatives.

    (4, …), for v_i, θ_i, v_j, θ_j; ``derivative`` 0, 1 (1/m) or 2 (1/m²).
    """
    xi = np.asarray(xi)
    if derivative == 0:
        n = [
            1 - 3 * xi**2 + 2 * xi**3,
            h * (xi - 2 * xi**2 + xi**3),
            3 * xi**2 - 2 * xi**3,
            h * (xi**3 - xi**2),
        ]
    elif derivative == 1:
        n = [(6 * xi**2 - 6 * xi) / h, 1 - 4 * xi + 3 * xi**2, (6 * xi - 6 * xi**2) / h, 3 * xi**2 - 2 * xi]
    else:
        n = [(12 * xi - 6) / h**2, (6 * xi - 4) / h, (6 - 12 * xi) / h**2, (6 * xi - 2) / h]
    return np.array(n)


def _build(span, EI, m, damping_ratio, elements, damping_model):
    """The mesh, its supports, its damping; returns the first two bending frequencies (rad/s)."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    h = span / elements
    for i in range(elements + 1):
        ops.node(i + 1, i * h, 0.0)
        # Pinned at the left end, a roller at the right: both ends' vertical displacement fixed; the axial
        # motion fixed everywhere (vertical loads on a straight beam never excite it).
        ops.fix(i + 1, 1, int(i in (0, elements)), 0)
    ops.geomTransf("Linear", 1)
    # A = 1 m², E = EI/(1 m⁴) with I = 1 m⁴: only the product EI matters to bending.
    for e in range(elements):
        ops.element("elasticBeamColumn", e + 1, e + 1, e + 2, 1.0, EI, 1.0, 1, "-mass", m, "-cMass")
    # Modes: the lowest eigenvalues of the constrained mesh are bending modes 1, 2, 3, ...
    lam = np.asarray(ops.eigen(min(2 * elements - 2, 40)))  # ARPACK: fewer than the 2n free DOFs
    omega = np.sqrt(lam)
    if damping_ratio > 0.0:
        if damping_model == "modal":
            ops.modalDamping(damping_ratio)
        else:
            w1, w2 = omega[0], omega[1]
            # ζ at ω₁ and ω₂: a₀ = 2ζω₁ω₂/(ω₁+ω₂), a₁ = 2ζ/(ω₁+ω₂) (Chopra 2012, §11.4, equal ratios)
            ops.rayleigh(2 * damping_ratio * w1 * w2 / (w1 + w2), 0.0, 0.0, 2 * damping_ratio / (w1 + w2))
    return h, omega[:2]


def _analysis(damping_model):
    ops.constraints("Plain")
    ops.numberer("RCM")
    ops.system("BandGeneral")
    if damping_model == "modal":
        # OpenSees adds modal damping to the residual but not to the tangent (which would fill the band): a
        # step must iterate to equilibrium. 1e-14 m: far below any deflection compared here (≥ 1e-4 m).
        ops.test("NormDispIncr", 1e-14, 50)
        ops.algorithm("ModifiedNewton")
    else:
        ops.algorithm("Linear")  # a linear model: one solve per step, no equilibrium iteration needed
    ops.integrator("Newmark", 0.5, 0.25)  # average acceleration
    ops.analysis("Transient")


def _state_at(position, span, h, elements):
    """The element holding ``position`` and the relative position in it."""
    e = min(int(position // h), elements - 1)
    return e, (position - e * h) / h


def _deflection(e, xi, h):
    """w at relative position ξ of element e (0-based), downwards, from its nodes' motion."""
    ui = ops.nodeDisp(e + 1)
    uj = ops.nodeDisp(e + 2)
    n = _hermite(np.asarray(xi), h)
    return -(n[0] * ui[1] + n[1] * ui[2] + n[2] * uj[1] + n[3] * uj[2])


def _wheel(e, xi, h, speed):
    """Displacement, velocity and acceleration of a point moving at ``speed`` on the beam, downwards."""
    ui, uj = (np.array(ops.nodeDisp(n))[1:] for n in (e + 1, e + 2))
    vi, vj = (np.array(ops.nodeVel(n))[1:] for n in (e + 1, e + 2))
    ai, aj = (np.array(ops.nodeAccel(n))[1:] for n in (e + 1, e + 2))
    u, v, a = np.r_[ui, uj], np.r_[vi, vj], np.r_[ai, aj]
    n0, n1, n2 = (_hermite(xi, h, d) for d in (0, 1, 2))
    w = -(n0 @ u)
    wd = -(n0 @ v + speed * (n1 @ u))
    wdd = -(n0 @ a + 2 * speed * (n1 @ v) + speed**2 * (n2 @ u))
    return float(w), float(wd), float(wdd)


def _moment(node, elements, fixed_left=0.0, fixed_right=0.0):
    """Sagging moment at a node (1-based), N·m: the mean over the elements meeting there.

    An element's end forces are K u less its loads' consistent equivalent nodal forces (the
    fixed-end forces); ``fixed_left`` and ``fixed_right`` are the equivalent nodal moments at this
    node of the loads on the element to the left and to the right (counterclockwise, N·m).
    """
    values = []
    if node > 1:  # the element to the left: its end j's moment acts counterclockwise under sagging
        values.append(ops.eleForce(node - 1)[5] - fixed_left)
    if node <= elements:  # the element to the right: its end i's moment acts clockwise under sagging
        values.append(-(ops.eleForce(node)[2] - fixed_right))
    return float(np.mean(values))


def fe_moving_forces(
    span,
    EI,
    m,
    damping_ratio,
    positions,
    loads,
    speed,
    *,
    elements=40,
    time_step=None,
    duration=None,
    at=None,
    damping_model="rayleigh",
):
    """The deflection and moment at a point of the beam as constant axle forces cross it, by OpenSees.

    Parameters
    ----------
    span, EI, m : float
        L (m), EI (N·m²), mass per length (kg/m).
    damping_ratio : float
        ζ in [0, 1): of every computed mode (``damping_model="modal"``) or of the first two bending
        modes (``"rayleigh"``).
    positions, loads : array_like, (a,)
        Each axle's distance behind the leading one (m) and its downward force (N), as in
        :class:`raildyn.bridge.loads.AxleSequence`.
    speed : float
        v, m/s.
    elements : int
        Elements in the span, even (so that midspan is a node), in [2, 1000].
    time_step : float, optional
        Δt, s; None: the smaller of T₁/200 and the time an axle takes to cross a quarter element.
    duration : float, optional
        s; None: the train's crossing, (L + its length)/v, and L/v after.
    at : float, optional
        x, m; None: midspan.
    damping_model : {"rayleigh", "modal"}
        Rayleigh's: one linear solve a step. Modal: OpenSees puts it in the residual only, so each
        step iterates (modified Newton), about three times slower.

    Returns
    -------
    FEResponse
    """
    start = _time.perf_counter()
    _common(span, EI, m, damping_ratio, speed, elements, damping_model)
    positions = np.atleast_1d(np.asarray(positions, float))
    loads = np.atleast_1d(np.asarray(loads, float))
    if positions.shape != loads.shape or positions[0] != 0.0 or np.any(np.diff(positions) < 0.0):
        raise ValueError(f"positions must start at 0 and never decrease, one per load, got {positions}")
    L = float(span)
    x_at = L / 2 if at is None else float(at)
    h, omega = _build(L, EI, m, damping_ratio, elements, damping_model)
    if duration is None:
        duration = (L + positions[-1]) / speed + L / speed
    if time_step is None:
        time_step = min(2 * np.pi / omega[0] / 200, h / speed / 4)
    steps = int(np.ceil(duration / time_step - 1e-9))
    dt = duration / steps
    t = np.arange(steps + 1) * dt

    # Every axle's equivalent nodal forces and moments at every time step, in global axes (y up).
    x = speed * t[:, None] - positions[None, :]  # (k, a): where each axle stands
    on = (x >= 0.0) & (x <= L)
    e = np.clip((x // h).astype(int), 0, elements - 1)
    xi = np.clip(x / h - e, 0.0, 1.0)
    shape = _hermite(xi, h) * np.where(on, -loads[None, :], 0.0)[None]  # (4, k, a): downward loads
    fy = np.zeros((steps + 1, elements + 1))
    mz = np.zeros((steps + 1, elements + 1))
    rows = np.broadcast_to(np.arange(steps + 1)[:, None], x.shape)
    np.add.at(fy, (rows, e), shape[0])
    np.add.at(mz, (rows, e), shape[1])
    np.add.at(fy, (rows, e + 1), shape[2])
    np.add.at(mz, (rows, e + 1), shape[3])
    node_at = int(round(x_at / h))  # 0-based: the node nearest x, where the moment is read
    fixed_left = np.where(e == node_at - 1, shape[3], 0.0).sum(axis=-1)
    fixed_right = np.where(e == node_at, shape[1], 0.0).sum(axis=-1)

    tag = 0
    for node in range(elements + 1):
        for dof, history in ((1, fy[:, node]), (2, mz[:, node])):
            if node in (0, elements) and dof == 1:
                continue  # a support takes its vertical load directly
            if not np.any(history):
                continue
            tag += 1
            ops.timeSeries("Path", tag, "-dt", dt, "-values", *history.tolist())
            ops.pattern("Plain", tag, tag)
            ops.load(node + 1, 0.0, *((1.0, 0.0) if dof == 1 else (0.0, 1.0)))

    _analysis(damping_model)
    e_at, xi_at = _state_at(x_at, L, h, elements)
    w = np.zeros(steps + 1)
    moment = np.zeros(steps + 1)
    for k in range(1, steps + 1):
        if ops.analyze(1, dt) != 0:
            raise RuntimeError(f"OpenSees failed at step {k} (t = {t[k]:.4g} s)")
        w[k] = _deflection(e_at, xi_at, h)
        moment[k] = _moment(node_at + 1, elements, fixed_left[k], fixed_right[k])
    seconds = _time.perf_counter() - start
    ops.wipe()
    return FEResponse(t, w, moment, x_at, omega / (2 * np.pi), seconds)


def fe_sprung_mass_crossing(
    span,
    EI,
    m,
    damping_ratio,
    mass,
    stiffness,
    speed,
    *,
    damping=0.0,
    unsprung_mass=0.0,
    elements=40,
    time_step=None,
    duration=None,
    at=None,
    damping_model="rayleigh",
    tolerance=1e-9,
    max_iterations=20,
):
    """A sprung mass (Biggs) crossing the OpenSees beam, coupled by iteration on the contact force each step.

    The vehicle: a mass M on a spring k and a damper c over a wheel of mass m_w that stays on the
    beam (Biggs 1964, ch. 8). Displacements downwards, the body's from its static equilibrium on a
    rigid support, the wheel's z_w = w(vt, t) following the beam:

        M z̈ + c(ż − ż_w) + k(z − z_w) = 0,
        F = (M + m_w) g + k(z − z_w) + c(ż − ż_w) − m_w z̈_w  (the force on the beam).

    Each step, ``ops.analyze(1)`` advances the beam under a trial contact force F at the wheel
    (consistent nodal loads). The wheel's displacement is then the beam's under it (Hermite
    interpolation); its velocity and acceleration, and the body's motion, follow from the same
    Newmark average-acceleration rule as the beam's (so the wheel's convective terms v∂w/∂x and
    v²∂²w/∂x² are in them). That gives a new F; the beam's committed state (nodal displacements,
    velocities, accelerations, time) is restored and the step repeated, the trial forces updated by
    the secant rule, until F changes by less than ``tolerance`` times the weight.

    Parameters
    ----------
    span, EI, m, damping_ratio : float
        The beam, as in :func:`fe_moving_forces`.
    mass, stiffness : float
        M (kg), k (N/m).
    speed : float
        v, m/s.
    damping : float
        c, N·s/m.
    unsprung_mass : float
        m_w, kg.
    elements, time_step, duration, at, damping_model
        As in :func:`fe_moving_forces`; the default duration is 2L/v.
    tolerance : float
        Change of the contact force, relative to the weight, that ends a step's iteration.
    max_iterations : int

    Returns
    -------
    SprungMassFEResponse
    """
    start = _time.perf_counter()
    _common(span, EI, m, damping_ratio, speed, elements, damping_model)
    _positive("mass", mass)
    _positive("stiffness", stiffness)
    if damping < 0.0 or unsprung_mass < 0.0:
        raise ValueError(f"damping and unsprung_mass must be >= 0, got {damping!r} and {unsprung_mass!r}")
    L = float(span)
    x_at = L / 2 if at is None else float(at)
    h, omega = _build(L, EI, m, damping_ratio, elements, damping_model)
    if duration is None:
        duration = 2 * L / speed
    if time_step is None:
        time_step = min(2 * np.pi / omega[0] / 200, h / speed / 4)
    steps = int(np.ceil(duration / time_step - 1e-9))
    dt = duration / steps
    t = np.arange(steps + 1) * dt
    weight = (mass + unsprung_mass) * G
    free = [(n + 1, d) for n in range(elements + 1) for d in (2, 3) if not (d == 2 and n in (0, elements))]

    def apply(force, x):
        """The contact force as the consistent nodal loads of the element under the wheel (pattern 1)."""
        ops.remove("loadPattern", 1)
        ops.pattern("Plain", 1, 1)
        if 0.0 <= x <= L:
            e, xi = _state_at(x, L, h, elements)
            f = _hermite(np.asarray(xi), h) * -force
            ops.load(e + 1, 0.0, float(f[0]), float(f[1]))
            ops.load(e + 2, 0.0, float(f[2]), float(f[3]))

    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    _analysis(damping_model)
    e_at, xi_at = _state_at(x_at, L, h, elements)
    w = np.zeros(steps + 1)
    F = np.zeros(steps + 1)
    z = np.zeros(steps + 1)
    iterations = np.zeros(steps + 1, int)
    F[0] = weight
    body = (0.0, 0.0, 0.0)  # z, ż, z̈ of the body, from its equilibrium
    force = weight
    for k in range(1, steps + 1):
        x = speed * t[k]
        if x > L:  # the wheel has left: the beam vibrates freely
            apply(0.0, x)
            if ops.analyze(1, dt) != 0:
                raise RuntimeError(f"OpenSees failed at step {k} (t = {t[k]:.4g} s)")
            w[k] = _deflection(e_at, xi_at, h)
            continue
        saved = [(n, d, ops.nodeDisp(n, d), ops.nodeVel(n, d), ops.nodeAccel(n, d)) for n, d in free]
        e, xi = _state_at(x, L, h, elements)
        trials, residuals = [], []
        for iteration in range(1, max_iterations + 1):
            iterations[k] = iteration
            apply(force, x)
            if ops.analyze(1, dt) != 0:
                raise RuntimeError(f"OpenSees failed at step {k} (t = {t[k]:.4g} s)")
            # The wheel rides on the beam at x = vt: ż_w = ∂w/∂t + v ∂w/∂x and
            # z̈_w = ∂²w/∂t² + 2v ∂²w/∂x∂t + v² ∂²w/∂x², from the nodes' motion by the Hermite functions.
            zw1, vw1, aw1 = _wheel(e, xi, h, speed)
            # The body by the same rule: M z̈₁ + c(ż₁ − ż_w1) + k(z₁ − z_w1) = 0 with
            # z₁ = z₀ + Δt ż₀ + Δt²/4 (z̈₀ + z̈₁), ż₁ = ż₀ + Δt/2 (z̈₀ + z̈₁).
            zb0, vb0, ab0 = body
            zp = zb0 + dt * vb0 + dt**2 / 4 * ab0
            vp = vb0 + dt / 2 * ab0
            ab1 = -(damping * (vp - vw1) + stiffness * (zp - zw1)) / (
                mass + damping * dt / 2 + stiffness * dt**2 / 4
            )
            zb1, vb1 = zp + dt**2 / 4 * ab1, vp + dt / 2 * ab1
            new = weight + stiffness * (zb1 - zw1) + damping * (vb1 - vw1) - unsprung_mass * aw1
            if abs(new - force) <= tolerance * weight:
                break
            # Not yet: the next trial by the secant rule on the residual new − force (the step is linear in
            # the force, so two trials find it up to rounding), then back to the committed state.
            trials.append(force)
            residuals.append(new - force)
            if len(trials) >= 2 and residuals[-1] != residuals[-2]:
                slope = (residuals[-1] - residuals[-2]) / (trials[-1] - trials[-2])
                force = trials[-1] - residuals[-1] / slope
            else:
                force = new
            ops.setTime(float(t[k - 1]))
            for n, d, u, v, a in saved:
                ops.setNodeDisp(n, d, u, "-commit")
                ops.setNodeVel(n, d, v, "-commit")
                ops.setNodeAccel(n, d, a, "-commit")
            ops.domainChange()
        else:
            raise RuntimeError(
                f"the contact force did not converge in {max_iterations} iterations at step {k}"
            )
        body = (zb1, vb1, ab1)
        F[k] = force
        z[k] = zb1
        w[k] = _deflection(e_at, xi_at, h)
    seconds = _time.perf_counter() - start
    ops.wipe()
    return SprungMassFEResponse(t, w, F, z, iterations, x_at, seconds)
