"""The nonlinear lateral models (book chapters 5, 7 and 8), cases of the protocol of
:mod:`raildyn.wheelset.protocol`.

* :class:`~raildyn.wheelset.NonlinearLateral`: any lateral linear system with its wheelsets' linear
  wheel–rail terms replaced by the nonlinear contact forces of :mod:`raildyn.wheelset.contact`,
  optional nonlinear suspension elements (:class:`~raildyn.wheelset.SuspensionElement`) and an
  optional curve (:class:`raildyn.track.curve.Curve`) to run through;
* :class:`~raildyn.wheelset.NonlinearWheelset`: the suspended wheelset of
  :mod:`raildyn.wheelset.linear` as such a model.

SI units throughout.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from raildyn import _checks
from raildyn._checks import nonnegative, scalar
from raildyn.linear_model import LinearSystem
from raildyn.track.curve import Curve
from raildyn.wheelset.contact import ContactTable, ContactTables, WheelRailContact, _contact_forces
from raildyn.wheelset.curved import track_on_arc
from raildyn.wheelset.linear import Wheelset, creep_terms
from raildyn.wheelset.protocol import CompiledRHS

__all__ = ["NonlinearLateral", "NonlinearWheelset", "SuspensionElement"]


def _speed(speed) -> float:
    return _checks.speed("speed", speed)


def _state(state, n: int) -> np.ndarray:
    """A finite state of n rows, (n,) or (n, k): the cheap check of a right-hand side's argument."""
    x = state if type(state) is np.ndarray and state.dtype == np.float64 else _checks.array("state", state)
    if not 1 <= x.ndim <= 2 or x.shape[0] != n:
        raise ValueError(f"state must have shape ({n},) or ({n}, k), got shape {x.shape}")
    if not math.isfinite(x.sum()):  # one sum at every step; the full check only to word the message
        _checks.array("state", x)
    return x


_ELEMENT_PROBE = (np.array([-1.0e-3, 0.0, 1.0e-3]), np.array([-0.01, 0.0, 0.01]))  # m (rad), m/s (rad/s)


@dataclass(frozen=True)
class SuspensionElement:
    """A nonlinear suspension element of a :class:`NonlinearLateral`: a force law along one deflection.

    The element acts on the deflection d = Σ cᵢ qᵢ, a linear combination of the
    model's coordinates (a relative displacement such as y_frame − y_bolster, or a
    relative yaw), and pulls it back with the force F = f(d, ḋ) (N, or N·m on an
    angle): the generalized forces are −F cᵢ. The linear model may hold a linear
    spring k and damper c on the same deflection (an equivalent viscous damper
    standing for friction, a spring standing for a clearance); ``stiffness`` and
    ``damping`` name them, and the nonlinear model removes k c cᵀ from K and
    c c cᵀ from C₀ so that the law replaces them. Examples of laws, from
    :mod:`raildyn.suspension`:

    * friction wedges, F = F_f tanh(ḋ/v_ε):
      ``lambda d, v: coulomb_friction(v, F_f, velocity_scale=v_eps)``;
    * a spring k in parallel with friction: ``lambda d, v: k * d + coulomb_friction(v, ...)``;
    * a lateral play (clearance g, stop k_s beyond it):
      ``lambda d, v: clearance_force(d, g, k_s)``.

    Attributes
    ----------
    coordinates : dict of str to float
        Label of a coordinate of the model → its coefficient cᵢ (finite, at least one
        non-zero).
    force : callable
        f(d, ḋ) → F, vectorised: given two float arrays of one shape (m and m/s, or rad and
        rad/s), an array of that shape (N or N·m, finite). Tried once, at
        d = (−1, 0, 1) mm and ḋ = (−10, 0, 10) mm/s, and what it returns checked.
    stiffness, damping : float
        The linear spring (N/m) and damper (N·s/m) on d that the linear model holds in the
        element's place, each ≥ 0 (per radian for an angle); 0 where it holds none.
    """

    coordinates: dict
    force: Callable
    stiffness: float = 0.0
    damping: float = 0.0

    def __post_init__(self):
        _checks.instance("coordinates", self.coordinates, dict, "dict of coordinate label to coefficient")
        values = []
        for label, value in self.coordinates.items():
            _checks.instance("coordinates key", label, str, "str (a coordinate label)")
            values.append(scalar(f"coordinates[{label!r}]", value))
        if not any(values):
            raise ValueError(
                f"coordinates must give at least one non-zero coefficient, got {self.coordinates!r}"
            )
        law = _checks.function("force", self.force)
        d, v = _ELEMENT_PROBE
        _checks.returned("force", law(d.copy(), v.copy()), shape=d.shape, at=f"d = {d}, ḋ = {v}")
        nonnegative("stiffness", self.stiffness)
        nonnegative("damping", self.damping)


@dataclass(frozen=True)
class NonlinearLateral:
    """Any lateral :class:`~raildyn.linear_model.LinearSystem` with its linear wheel–rail terms replaced
    by :func:`contact_forces`, and optional nonlinear suspension elements.

    M q̈ = −C_s q̇ − K_s q + Σ F_contact − Σ_e F_e c_e, where K_s is K without the creep and
    gravitational terms of each wheelset and without each element's linear spring, C_s is C₀
    without each element's linear damper, and F_e = f_e(c_e·q, c_e·q̇) is the force of
    :class:`SuspensionElement` e on its deflection c_e·q. State [q; q̇]; ``rhs(t, state, speed)``
    (the :class:`NonlinearModel` protocol).

    On a ``curve`` the coordinates are taken in axes that follow the vehicle: their origin
    runs along the track's centre line at V, at s_c = ``start`` + V t, turning with the
    track's tangent there at V κ(s_c) (the steady-curving axes of
    :func:`raildyn.curving.steady.steady_curving`, here with a curvature that varies). A wheelset
    x ahead of the origin meets the track displaced by y_t = ∫₀ˣ (x − u) κ(s_c + u) du,
    computed as ½x² κ(s_c + x/3), exact where κ is linear in s (a clothoid); its contact
    forces are those of :func:`contact_forces` at y − y_t, with the yaw ψ − x κ(s_c) that the
    axes' own turning gives its path, and the yaw rate ψ̇ + V κ(s_c). Every lateral
    coordinate (label ending in " y") carries −m a_q, a_q = V²κ(s_c) − g D(s_c)/G
    (:meth:`raildyn.track.curve.Curve.unbalanced_acceleration`). The
    Coriolis and Euler forces of the turning axes (of order m V κ ẏ) are left out.

    Attributes
    ----------
    system : LinearSystem
        With at least one wheelset on the rails.
    contact : WheelRailContact
    elements : tuple of SuspensionElement
        Nonlinear suspension elements, each naming coordinates of ``system``; empty by default.
    curve : raildyn.track.curve.Curve or None
        The track's curve (turning left); None: tangent track.
    start : float
        s_c at t = 0, the distance of the vehicle's centre along ``curve``, m (finite).
    compiled_reason : str or None
        Derived: None where the compiled engine runs the model; otherwise why it does not.
    """

    system: LinearSystem
    contact: WheelRailContact = field(default_factory=WheelRailContact)
    elements: tuple = ()
    curve: object = None
    start: float = 0.0
    # Derived once from the fields above (not arguments): the suspension stiffness and damping, M⁻¹,
    # the wheelsets grouped by their parameters, and the elements' deflection rows and laws.
    _K_suspension: np.ndarray = field(init=False, repr=False, compare=False)
    _C_suspension: np.ndarray = field(init=False, repr=False, compare=False)
    _M_inv: np.ndarray = field(init=False, repr=False, compare=False)
    _groups: list = field(init=False, repr=False, compare=False)
    _G: np.ndarray | None = field(init=False, repr=False, compare=False)
    _laws: tuple = field(init=False, repr=False, compare=False)
    _lateral_mass: np.ndarray = field(init=False, repr=False, compare=False)
    _positions: np.ndarray | None = field(init=False, repr=False, compare=False)
    compiled_reason: str | None = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        if self.curve is not None:
            _checks.instance("curve", self.curve, Curve)
        scalar("start", self.start)
        _checks.instance("system", self.system, LinearSystem)
        _checks.instance("contact", self.contact, WheelRailContact)
        if not self.system.wheelsets:
            raise ValueError("system has no wheelsets in contact with the rails")
        if isinstance(self.elements, str) or not isinstance(self.elements, (tuple, list)):
            raise TypeError(f"elements must be a tuple of SuspensionElement, got {self.elements!r:.80}")
        labels = self.system.labels
        n = self.system.size
        G = np.zeros((len(self.elements), n))
        for i, element in enumerate(self.elements):
            _checks.instance(f"elements[{i}]", element, SuspensionElement)
            for label, value in element.coordinates.items():
                if label not in labels:
                    raise ValueError(
                        f"elements[{i}] coordinates must be labels of system {labels}, got {label!r}"
                    )
                G[i, labels.index(label)] += value
        object.__setattr__(self, "elements", tuple(self.elements))
        K_s = np.array(self.system.K, dtype=float, copy=True)
        C_s = np.array(self.system.C0, dtype=float, copy=True)
        for iy, ipsi, ws in self.system.wheelsets:
            terms = creep_terms(ws)
            idx = np.ix_([iy, ipsi], [iy, ipsi])
            K_s[idx] -= terms.K_creep + terms.K_gravity
        for g, element in zip(G, self.elements, strict=True):
            K_s -= element.stiffness * np.outer(g, g)
            C_s -= element.damping * np.outer(g, g)
        object.__setattr__(self, "_K_suspension", K_s)
        object.__setattr__(self, "_C_suspension", C_s)
        object.__setattr__(self, "_M_inv", np.linalg.inv(self.system.M))
        # Wheelsets with equal parameters are evaluated together in one vectorised call.
        # Each wheelset's place along the vehicle, for a curve; a system that does not give them (no
        # alignment inputs) runs on tangent track only.
        try:
            positions = self.system.wheelset_positions
        except ValueError as err:
            if self.curve is not None:
                raise ValueError(f"system cannot run on a curve: {err}") from None
            positions = None
        object.__setattr__(self, "_positions", positions)
        if positions is None:
            positions = np.zeros(len(self.system.wheelsets))
        groups: dict = {}
        for (iy, ipsi, ws), x in zip(self.system.wheelsets, positions, strict=True):
            groups.setdefault(ws, ([], [], []))
            for column, value in zip(groups[ws], (iy, ipsi, x), strict=True):
                column.append(value)
        object.__setattr__(
            self, "_groups", [(ws, np.array(a), np.array(b), np.array(x)) for ws, (a, b, x) in groups.items()]
        )
        lateral = np.array([label.endswith(" y") for label in self.system.labels], dtype=float)
        object.__setattr__(self, "_lateral_mass", self.system.M @ lateral)
        object.__setattr__(self, "_G", G if self.elements else None)  # None: no elements
        object.__setattr__(self, "_laws", tuple(e.force for e in self.elements))
        object.__setattr__(self, "compiled_reason", _compiled_reason(self))

    @functools.cached_property
    def _row(self) -> np.ndarray | None:
        """The model packed for the engine's forces on arcs (no speed); None where the engine cannot run it.

        Packed at first use, so that numba's engine loads only when a model needs it.
        """
        if self.compiled_reason is not None:
            return None
        from raildyn.wheelset import _engine

        return _engine.pack(self)

    @property
    def state_size(self) -> int:
        return 2 * self.system.size

    @property
    def lateral_index(self) -> int:
        """State entry of the first wheelset's lateral displacement (followed in hunting studies)."""
        return self.system.wheelsets[0][0]

    def replace(self, **changes) -> NonlinearLateral:
        """A validated copy with some fields changed (``system``, ``contact``, ``elements``, ``curve``,
        ``start``).

        Parameters
        ----------
        **changes
            Field names and their new values.

        Returns
        -------
        NonlinearLateral
        """
        return _replace(self, changes, ("system", "contact", "elements", "curve", "start"))

    def compiled_rhs(self, speed) -> CompiledRHS:
        """The model at speed V as the compiled runner takes it.

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].

        Returns
        -------
        CompiledRHS

        Raises
        ------
        ValueError
            If the compiled engine does not run the model (``compiled_reason`` says why).
        """
        V = _speed(speed)
        if self.compiled_reason is not None:
            raise ValueError(f"the compiled engine cannot run this model: {self.compiled_reason}")
        from raildyn.wheelset import _engine

        return CompiledRHS(_engine.lateral_rhs, _engine.pack(self, V), _engine.stacked_lateral_rhs)

    def rhs(self, t, state, speed):
        """Time derivative of [q; q̇] at speed V.

        Parameters
        ----------
        t : float
            s, finite (on tangent track the model is autonomous: unused).
        state : ndarray, (2n,) or (2n, k)
            [q; q̇], finite.
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].

        Returns
        -------
        ndarray, like ``state``
            [q̇; q̈].
        """
        scalar("t", t)
        V = _speed(speed)
        n = self.system.size
        state = _state(state, 2 * n)
        q, qdot = state[:n], state[n:]
        force = -self._C_suspension @ qdot - self._K_suspension @ q
        force = np.array(force, dtype=float, copy=True)
        if self.curve is None:
            for ws, iy, ipsi, _ in self._groups:
                fy, mz = _contact_forces(ws, self.contact, q[iy], q[ipsi], qdot[iy], qdot[ipsi], V)
                force[iy] += fy
                force[ipsi] += mz
        else:
            self._curve_forces(t, q, qdot, V, force)
        if self._laws:
            d, v = self._G @ q, self._G @ qdot
            pull = np.array([law(d[i], v[i]) for i, law in enumerate(self._laws)], dtype=float)
            force -= self._G.T @ pull
        return np.concatenate([qdot, self._M_inv @ force])

    def relative_to_track(self, t, state, speed) -> tuple[np.ndarray, np.ndarray]:
        """Each wheelset's lateral displacement and yaw relative to the track where it runs.

        On tangent track these are its coordinates; on a ``curve``, y − y_t and ψ − ψ_t with
        y_t = ½x²κ(s_c + x/3) and the track's tangent ψ_t = x κ(s_c + x/2) (both exact where κ
        is linear in s).

        Parameters
        ----------
        t : float or ndarray, (k,)
            s, finite: one time for every column of ``state``, or each column's own time
            (a run's samples at once).
        state : ndarray, (2n,) or (2n, k)
            [q; q̇], finite.
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]: the vehicle's centre is at
            s_c = ``start`` + V t.

        Returns
        -------
        offset : ndarray, (w,) or (w, k)
            m, to the left, one row per wheelset in the order of ``system.wheelsets``.
        yaw : ndarray, like ``offset``
            rad, anticlockwise.
        """
        V = _speed(speed)
        n = self.system.size
        q = _state(state, 2 * n)[:n]
        if np.ndim(t) and q.ndim == 1:
            raise ValueError(f"t must be a number for a state of shape ({2 * n},), got shape {np.shape(t)}")
        t = scalar("t", t) if np.ndim(t) == 0 else _checks.array("t", t, shape=(q.shape[1],))
        iy = np.array([w[0] for w in self.system.wheelsets])
        ipsi = np.array([w[1] for w in self.system.wheelsets])
        if self.curve is None:
            return q[iy].copy(), q[ipsi].copy()
        x = self.system.wheelset_positions.reshape((-1,) + (1,) * (q.ndim - 1))  # a column against (2n, k)
        s_c = self.start + V * t
        y_t = 0.5 * x * x * self.curve.curvature(s_c + x / 3.0)
        psi_t = x * self.curve.curvature(s_c + x / 2.0)
        return q[iy] - y_t, q[ipsi] - psi_t

    def arc_forces(self, q, speed, curvature, unbalanced_acceleration) -> np.ndarray:
        """The generalized forces on the model at rest on circular arcs, for a batch of states at once.

        In the axes that follow the vehicle round an arc of curvature κ at the speed V (the
        class docstring, with κ the same under every wheelset: y_t = ½x²κ, the path's yaw x κ,
        the yaw rate V κ) and with q̇ = 0. Their zero is the quasi-static equilibrium of
        :func:`raildyn.curving.quasi_static.quasi_static_curving`. The model's own ``curve`` and ``start``
        are not used. The compiled engine evaluates them where it runs the model, numpy otherwise.

        Parameters
        ----------
        q : ndarray, (n,) or (n, k)
            Coordinates, finite; one column per state of the batch.
        speed : float or array_like, (k,)
            V, m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
        curvature : float or array_like, (k,)
            κ = 1/R, 1/m, finite (positive: turning left).
        unbalanced_acceleration : float or array_like, (k,)
            a_q, m/s², finite (positive outwards).

        Returns
        -------
        ndarray, like ``q``
            N and N·m on each coordinate.
        """
        return self._forces_on_arcs(*self._on_arcs(q, speed, curvature, unbalanced_acceleration))

    def arc_jacobian(self, q, speed, curvature, unbalanced_acceleration) -> np.ndarray:
        """∂F/∂q of :meth:`arc_forces`, for a batch of states at once.

        The suspension's part is −K_s exactly. Each wheelset's contact forces depend on its own
        y and ψ only, so their 2 × 2 blocks come from forward differences of every wheelset at
        once (two more evaluations of the contact, not n); each nonlinear element's from one more
        evaluation of the laws, through its deflection row. The step, 1e-7 m (rad), is well
        above rounding and below the scale of the flange's and the saturation's bends.

        Parameters
        ----------
        q, speed, curvature, unbalanced_acceleration
            As for :meth:`arc_forces`.

        Returns
        -------
        ndarray, (n, n) or (k, n, n)
            N/m, N, N·m/rad … : row i, column j is ∂F_i/∂q_j; one matrix per column of ``q``.
        """
        return self._jacobians_on_arcs(*self._on_arcs(q, speed, curvature, unbalanced_acceleration))

    def _on_arcs(self, q, speed, curvature, unbalanced_acceleration) -> tuple:
        """The checked arguments of :meth:`arc_forces`: q, V, κ and a_q as float arrays."""
        if self._positions is None:
            raise ValueError(
                "system cannot run on a curve: its wheelsets have no alignment inputs to place them"
            )
        n = self.system.size
        q = _checks.array("q", q)
        if not 1 <= q.ndim <= 2 or q.shape[0] != n:
            raise ValueError(f"q must have shape ({n},) or ({n}, k), got shape {q.shape}")
        batch = () if q.ndim == 1 else (q.shape[1],)
        V = _checks.plausible_array("speed", speed, "speed", low_open=True)
        kappa = _checks.array("curvature", curvature)
        a_q = _checks.array("unbalanced_acceleration", unbalanced_acceleration)
        for name, value in (("speed", V), ("curvature", kappa), ("unbalanced_acceleration", a_q)):
            if value.shape not in ((), batch):
                raise ValueError(
                    f"{name} must be a float or have the shape {batch} of q's batch, got {value.shape}"
                )
        track_on_arc(0.0, kappa)  # its check of the curvature
        return q, V, kappa, a_q

    def _forces_on_arcs(self, q, V, kappa, a_q) -> np.ndarray:
        """:meth:`arc_forces` of checked arguments: on the compiled engine where it holds the model."""
        n = self.system.size
        if self._row is not None:
            shape = (n, q.size // n)
            return self._compiled_on_arcs("arc_forces", q, (V, kappa, a_q), shape).reshape(q.shape)
        column = (slice(None),) + (None,) * (q.ndim - 1)
        force = -self._K_suspension @ q
        self._add_curved_contact(
            q, np.zeros_like(q), V, kappa, lambda x: track_on_arc(x[column], kappa)[0], force
        )
        if self._laws:
            d = self._G @ q
            pull = np.array([law(d[i], np.zeros_like(d[i])) for i, law in enumerate(self._laws)], dtype=float)
            force -= self._G.T @ pull
        force -= self._lateral_mass[column] * a_q
        return force

    def _jacobians_on_arcs(self, q, V, kappa, a_q) -> np.ndarray:
        """:meth:`arc_jacobian` of checked arguments: on the compiled engine where it holds the model."""
        n, h = self.system.size, 1.0e-7
        if self._row is not None:
            J = self._compiled_on_arcs("arc_jacobian", q, (V, kappa, a_q), (q.size // n, n, n))
            return J[0] if q.ndim == 1 else J
        column = (slice(None),) + (None,) * (q.ndim - 1)
        J = np.broadcast_to(-self._K_suspension, (*q.shape[1:], n, n)).copy()
        for ws, iy, ipsi, x in self._groups:
            y_t, psi_t = track_on_arc(x[column], kappa)
            y, psi = q[iy] - y_t, q[ipsi] - psi_t
            rate = np.zeros_like(y) + V * kappa

            def forces(dy, dpsi, ws=ws, y=y, psi=psi, rate=rate):
                return _contact_forces(ws, self.contact, y + dy, psi + dpsi, 0.0 * y, rate, V)

            fy, mz = forces(0.0, 0.0)
            for j, shifted in ((iy, forces(h, 0.0)), (ipsi, forces(0.0, h))):
                for i, base, moved in ((iy, fy, shifted[0]), (ipsi, mz, shifted[1])):
                    # one entry per wheelset: its own rows and columns
                    slope = np.moveaxis(np.asarray((moved - base) / h), 0, -1)
                    J[..., i, j] += slope
        if self._laws:
            d = self._G @ q
            rest = np.zeros_like(d[0])
            slope = np.array(
                [(law(d[i] + h, rest) - law(d[i], rest)) / h for i, law in enumerate(self._laws)]
            )
            J -= np.einsum("ei,e...,ej->...ij", self._G, slope, self._G)
        return J

    def _compiled_on_arcs(self, kernel: str, q, arcs, shape) -> np.ndarray:
        """The engine's ``kernel`` (forces or Jacobian on arcs) on q's columns, as an array of ``shape``."""
        from raildyn.wheelset import _engine

        n = self.system.size
        columns = np.ascontiguousarray(q.reshape(n, -1), dtype=float)
        P = columns.shape[1]
        V, kappa, a_q = (_column_values(v, P) for v in arcs)
        out = np.empty(shape)
        getattr(_engine, kernel)(self._row, columns, V, kappa, a_q, out)
        return out

    def _add_curved_contact(self, q, qdot, V, kappa, track, force) -> None:
        """Add the wheel–rail forces in the axes that follow a curve to ``force``: each wheelset at y − y_t
        with y_t = ``track``(x), the yaw ψ − x κ of its path and the yaw rate ψ̇ + V κ."""
        column = (slice(None),) + (None,) * (q.ndim - 1)  # a wheelset's x against a batch of states
        for ws, iy, ipsi, x in self._groups:
            psi_path = x[column] * kappa  # the direction of the wheelset's path, not the track's tangent
            fy, mz = _contact_forces(
                ws, self.contact, q[iy] - track(x), q[ipsi] - psi_path, qdot[iy], qdot[ipsi] + V * kappa, V
            )
            force[iy] += fy
            force[ipsi] += mz

    def _curve_forces(self, t: float, q, qdot, V: float, force) -> None:
        """Add the contact forces on the curve and the unbalanced weight to ``force`` (see the class)."""
        curve = self.curve
        s_c = self.start + V * t
        kappa = float(curve.curvature(s_c))
        a_q = float(curve.unbalanced_acceleration(s_c, V))
        column = (slice(None),) + (None,) * (q.ndim - 1)
        self._add_curved_contact(
            q, qdot, V, kappa, lambda x: (0.5 * x * x * curve.curvature(s_c + x / 3.0))[column], force
        )
        force -= self._lateral_mass[column] * a_q


def _column_values(value: np.ndarray, count: int) -> np.ndarray:
    """One float per column, as the engine's kernels take them: writable and contiguous (a copy only where
    ``value`` is not so already, as a broadcast float is not)."""
    if (
        value.shape == (count,)
        and value.dtype == np.float64
        and value.flags.writeable
        and value.flags.c_contiguous
    ):
        return value
    return np.array(np.broadcast_to(value, (count,)), dtype=float)


def _compiled_reason(model: NonlinearLateral) -> str | None:
    """None where the compiled engine holds ``model``; otherwise what it holds that the engine cannot."""
    if model.elements:
        return "its nonlinear suspension elements have force laws in Python"
    contact = model.contact
    for name in ("rolling_radius_difference", "contact_angle_difference"):
        fn = getattr(contact, name)
        if fn is not None and type(fn) is not ContactTable:
            return f"its contact's {name} is a Python function, not a profile table"
    angles = contact.tread_angles
    if angles is not None and not (
        type(angles) is ContactTables
        and len(angles.tables) == 2
        and all(type(t) is ContactTable for t in angles.tables)
    ):
        return "its contact's tread_angles is a Python function, not two profile tables"
    return None


def _replace(model, changes: dict, fields: tuple[str, ...]):
    """``model`` with ``changes`` to its ``fields``, built and validated afresh."""
    for name in changes:
        if name not in fields:
            raise TypeError(f"{type(model).__name__}.replace() takes the fields {fields}, got {name!r}")
    return type(model)(**{name: changes.get(name, getattr(model, name)) for name in fields})


class NonlinearWheelset(NonlinearLateral):
    """The suspended wheelset of chapter 5 with nonlinear contact: a :class:`NonlinearLateral`.

    The system is the wheelset's own :meth:`~raildyn.wheelset.Wheelset.linear_system`: state
    [y, ψ, ẏ, ψ̇] (m, rad, m/s, rad/s), its frame running straight.

    Parameters
    ----------
    wheelset : Wheelset, optional
        Default :class:`~raildyn.wheelset.Wheelset`.
    contact : WheelRailContact, optional
        Default :class:`~raildyn.wheelset.WheelRailContact`.

    Attributes
    ----------
    wheelset : Wheelset
    contact : WheelRailContact
    """

    def __init__(self, wheelset: Wheelset | None = None, contact: WheelRailContact | None = None):
        wheelset = Wheelset() if wheelset is None else _checks.instance("wheelset", wheelset, Wheelset)
        contact = (
            WheelRailContact() if contact is None else _checks.instance("contact", contact, WheelRailContact)
        )
        object.__setattr__(self, "wheelset", wheelset)
        super().__init__(wheelset.linear_system(), contact)

    def replace(self, **changes) -> NonlinearWheelset:
        """A validated copy with ``wheelset`` or ``contact`` changed.

        Parameters
        ----------
        **changes
            ``wheelset`` or ``contact`` and its new value.

        Returns
        -------
        NonlinearWheelset
        """
        return _replace(self, changes, ("wheelset", "contact"))

    def __repr__(self) -> str:
        return f"NonlinearWheelset(wheelset={self.wheelset!r}, contact={self.contact!r})"
