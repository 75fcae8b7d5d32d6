"""The longitudinal model of a whole train: its equations of motion and its quasi-statics.

Vehicle ``i`` (0 at the front) obeys

    m_i a_i = T_i − D_i − B_i − R_i − G_i − K_i − F_i + F_{i−1}

with tractive effort ``T``, dynamic brake ``D``, air brake ``B``, Davis
resistance ``R``, grade ``G`` and curve resistance ``K``, and ``F_i`` the force
in the coupler behind vehicle ``i`` (+ tension). Retarding forces that act
against the motion are multiplied by ``tanh(v/v_c)`` with a creep speed
``v_c`` of a few cm/s, so a stopped train does not chatter between signs.
``TrainModel.rhs`` computes the right-hand side of one state in a compiled loop
(``_kernel``) and of a batch of states (one per column) with numpy, which is
also the readable reference the compiled loop is tested against. Every public
entry checks the shape and finiteness of the state before any compiled code runs.

This module holds :class:`TrainModel` (a consist on a route, its couplers and its driver's
settings); :mod:`raildyn.train.longitudinal` integrates it (``simulate``). Failure policy:
:meth:`TrainModel.balancing_speed` raises :class:`raildyn.errors.SolverError` when Brent's
method does not converge; bad input raises ``ValueError``/``TypeError``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from raildyn import _checks
from raildyn.constants import GRAVITY, MAXIMUM_SPEED
from raildyn.errors import SolverError
from raildyn.train import forces as train_forces
from raildyn.train.couplers import _MAX_EXTENSION, DraftGear, _extension
from raildyn.train.forces import NOTCHES, AirBrake, dynamic_brake_force
from raildyn.train.resistance import CURVE_RESISTANCE, Route, davis_resistance
from raildyn.train.results import QuasiStatic, TrainRun
from raildyn.train.vehicles import Consist, make_consist  # noqa: F401  (the examples use make_consist)

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.optimize.brentq,
# raildyn.train._kernel

__all__ = ["TrainModel"]

# Largest regularisation speed v_c of the retarding forces' tanh, m/s (3.6 km/h): a smoothing of the
# sign of v, far below running speeds (the default is 0.05 m/s).
_MAX_CREEP_SPEED = 1.0


@dataclass(frozen=True)
class TrainModel:
    """A consist on a route with its couplers and its driver's settings.

    Parameters
    ----------
    consist : Consist
        The vehicles, front first.
    gear : DraftGear
        The coupler law, the same for every coupler.
    route : Route
        Grade and curvature; level tangent track by default.
    notch : float
        Throttle notch of every locomotive, 0–8.
    dynamic_brake : float
        Dynamic-brake level of every locomotive, 0–1.
    air_brake : AirBrake or None
        The air-brake application, if any.
    davis_form : {"original", "modified"}
        Form of the Davis resistance formula.
    creep_speed : float
        v_c of the ``tanh`` regularisation of the retarding forces, m/s, in (0, 1]: a
        smoothing of the sign of v, far below running speeds (1 m/s is already 3.6 km/h).
    front_start : float
        Route position of the front coupler face at t = 0, m.
    resistance : bool
        Include Davis and curve resistance (switch off to study the couplers alone).
    """

    consist: Consist
    gear: DraftGear = field(default_factory=DraftGear)
    route: Route = field(default_factory=Route.level)
    notch: float = 0.0
    dynamic_brake: float = 0.0
    air_brake: AirBrake | None = None
    davis_form: str = "original"
    creep_speed: float = 0.05
    front_start: float = 0.0
    resistance: bool = True
    # Per-vehicle quantities computed once (set in __post_init__): as rows, as columns for a
    # batch of states, and packed for the compiled right-hand side.
    _pre: dict = field(init=False, repr=False, compare=False)
    _pre_columns: dict = field(init=False, repr=False, compare=False)
    _packed: tuple = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        for name, kind in (("consist", Consist), ("gear", DraftGear), ("route", Route)):
            _checks.instance(name, getattr(self, name), kind)
        if self.air_brake is not None:
            _checks.instance("air_brake", self.air_brake, AirBrake, "AirBrake or None")
        _checks.flag("resistance", self.resistance)
        _checks.choice("davis_form", self.davis_form, ("original", "modified"))
        _checks.scalar("notch", self.notch, low=0, high=NOTCHES)
        _checks.scalar("dynamic_brake", self.dynamic_brake, low=0.0, high=1.0)
        _checks.scalar("creep_speed", self.creep_speed, low=0.0, low_open=True, high=_MAX_CREEP_SPEED)
        _checks.scalar("front_start", self.front_start)
        c = self.consist
        kinds = [v.kind for v in c.vehicles]
        # The Davis force is a quadratic in speed; get its coefficients from the public function.
        rows = []
        for speed in (0.0, 1.0, 2.0):
            rows.append(
                [
                    davis_resistance(speed, v.mass, v.axles, v.frontal_area, kind=k, form=self.davis_form)
                    for v, k in zip(c.vehicles, kinds, strict=True)
                ]
            )
        r0, r1, r2 = (np.array(r) for r in rows)
        quad = 0.5 * (r2 - 2 * r1 + r0)
        lin = r1 - r0 - quad
        pre = {
            "davis": np.stack([r0, lin, quad]),
            "spacing": 0.5 * (c.length[:-1] + c.length[1:]),
            "offset": c.centre_offsets,
            "inv_mass": 1.0 / c.mass,
            "a0": r0,
            "a1": lin,
            "a2": quad,
            "curve": CURVE_RESISTANCE * c.mass,
            "weight": c.mass * GRAVITY,
        }
        if self.air_brake is not None:
            pre["arrival"] = self.air_brake.arrival(c.centre_offsets)
            pre["brake"] = c.brake_force * self.air_brake.level
        columns = {k: v[:, None] for k, v in pre.items() if k not in ("davis",)}
        pre["traction"] = bool(c.locomotive.any() and (self.notch > 0 or self.dynamic_brake > 0))
        object.__setattr__(self, "_pre", pre)
        object.__setattr__(self, "_pre_columns", columns)
        object.__setattr__(self, "_packed", self._pack(pre))

    def _pack(self, pre):
        """The model as the compiled right-hand side takes it: (table, scalars, route)."""
        from raildyn.train import _kernel

        c, k = self.consist, _kernel
        n = len(c)
        table = np.zeros((k.ROWS, n))
        table[k.ROW_INV_MASS] = pre["inv_mass"]
        table[k.ROW_A0], table[k.ROW_A1], table[k.ROW_A2] = pre["a0"], pre["a1"], pre["a2"]
        table[k.ROW_CURVE], table[k.ROW_WEIGHT] = pre["curve"], pre["weight"]
        table[k.ROW_SPACING, : n - 1] = pre["spacing"]
        table[k.ROW_POWER], table[k.ROW_EFFORT] = c.rail_power, c.max_tractive_effort
        table[k.ROW_DYNAMIC] = c.max_dynamic_brake
        s = np.zeros(k.SCALARS)
        g = self.gear
        s[k.S_SLACK], s[k.S_K_LOAD], s[k.S_K_UNLOAD] = g.slack, g.loading_stiffness, g.unloading_stiffness
        s[k.S_TRAVEL], s[k.S_K_SOLID] = g.travel, g.solid_stiffness
        s[k.S_SMOOTHING], s[k.S_TRANSITION] = g.smoothing, g.transition_rate
        s[k.S_CREEP], s[k.S_THROTTLE], s[k.S_DYNAMIC] = (
            self.creep_speed,
            self.notch / NOTCHES,
            self.dynamic_brake,
        )
        # The corner speeds are read from their one definition when the model is built.
        s[k.S_DYNAMIC_PEAK] = train_forces.DYNAMIC_BRAKE_PEAK_SPEED
        s[k.S_DYNAMIC_FADE] = train_forces.DYNAMIC_BRAKE_FADE_SPEED
        s[k.S_RESISTANCE], s[k.S_TRACTION] = self.resistance, pre["traction"]
        s[k.S_ROUTE] = not self.route.is_level
        if self.air_brake is not None:
            table[k.ROW_BRAKE], table[k.ROW_ARRIVAL] = pre["brake"], pre["arrival"]
            s[k.S_BRAKE], s[k.S_BRAKE_START] = 1.0, self.air_brake.start
            s[k.S_BUILD_UP] = self.air_brake.build_up_time
        route = np.vstack([self.route.positions, self.route.grade, self.route.curvature])
        return table, s, route

    @property
    def size(self) -> int:
        """Number of vehicles n; the state has 2n entries (positions, then speeds)."""
        return len(self.consist)

    @property
    def davis_coefficients(self) -> np.ndarray:
        """Davis resistance of each vehicle as ``a0 + a1 |v| + a2 v²``: rows a0 (N), a1 (N·s/m), a2 (N·s²/m²).

        Shape ``(3, n)``; from ``davis_resistance`` in the model's ``davis_form``.
        """
        return self._pre["davis"].copy()

    def _state(self, y, name="state y"):
        """``y`` as a finite float array of shape (2n,) or (2n, k); ValueError otherwise."""
        m = 2 * self.size
        return _checks.array(name, y, shape=(m,) if np.ndim(y) == 1 else (m, None), allow_empty=False)

    @staticmethod
    def _finite(dydt, y):
        """``dydt`` if finite; else a ValueError naming the state ``y`` whose sizes overflow the forces.

        An integrator's trial state may leave the laws' domain (couplers parted, speeds beyond the
        train's) and still give a finite derivative, which is returned; only sizes at which a force
        overflows (the solid draft gear at 2.5e8 N/m, the v² of the resistance) are refused.
        """
        if math.isfinite(dydt.sum()):
            return dydt
        raise ValueError(
            "y holds sizes at which the forces overflow (coupler extensions or speeds beyond double "
            "precision once multiplied by the stiffnesses and resistances): largest |y| = "
            f"{np.abs(y).max()!r}"
        )

    def _vehicle_array(self, name, value):
        """``value`` as a finite float array with the vehicle axis first: (n,) or (n, k)."""
        n = self.size
        return _checks.array(name, value, shape=(n,) if np.ndim(value) == 1 else (n, None), allow_empty=False)

    def initial_state(self, speed: float, extension: float = 0.0) -> np.ndarray:
        """State with every vehicle at ``speed`` and every coupler at ``extension``.

        The state is ``[x_0, Δx_0 … Δx_{n−2}, v_0 … v_{n−1}]``: the route position of
        the leading vehicle's centre, the coupler extensions and the speeds. Keeping
        the extensions (millimetres) as states, rather than the positions (kilometres),
        lets the relative tolerance of the integrator act on what the couplers feel.

        Parameters
        ----------
        speed : float
            Speed of every vehicle, m/s (negative runs backwards), at most 200 in size
            (above the wheel–rail speed record).
        extension : float
            Extension Δx of every coupler, m (0 centres the slack), within ±1 m.

        Returns
        -------
        ndarray, shape (2n,)
            The state: m, m, m/s.
        """
        speed = _checks.scalar("speed", speed, low=-MAXIMUM_SPEED, high=MAXIMUM_SPEED)
        extension = _checks.scalar("extension", extension, low=-_MAX_EXTENSION, high=_MAX_EXTENSION)
        x0 = self.front_start - self._pre["offset"][0]
        return np.r_[x0, np.full(self.size - 1, extension), np.full(self.size, speed)]

    def positions(self, y) -> np.ndarray:
        """Route positions of the vehicle centres from states.

        Parameters
        ----------
        y : array, shape (2n,) or (2n, k)
            One state, or one per column (see :meth:`initial_state`).

        Returns
        -------
        ndarray, shape (n,) or (n, k)
            Route positions, m, front vehicle first.
        """
        return self._positions(self._state(y))

    def _positions(self, y):
        n = self.size
        spacing = self._pre["spacing"].reshape((-1,) + (1,) * (np.ndim(y) - 1))
        behind = np.cumsum(spacing + y[1:n], axis=0)
        return np.concatenate([y[:1], y[:1] - behind])

    def coupler_extension(self, x, v):
        """Coupler extensions Δx and their rates from positions and speeds.

        Parameters
        ----------
        x : array, shape (n,) or (n, k)
            Route positions of the vehicle centres, m.
        v : array, shape of ``x``
            Vehicle speeds, m/s.

        Returns
        -------
        extension : ndarray, shape (n−1,) or (n−1, k)
            Δx, m (+ stretched).
        rate : ndarray, shape of ``extension``
            dΔx/dt, m/s.
        """
        x = self._vehicle_array("x", x)
        v = self._vehicle_array("v", v)
        if x.shape != v.shape:
            raise ValueError(f"x and v must have the same shape, got {x.shape} and {v.shape}")
        spacing = self._pre["spacing"].reshape((-1,) + (1,) * (np.ndim(x) - 1))
        return x[:-1] - x[1:] - spacing, v[:-1] - v[1:]

    def coupler_forces(self, x, v) -> np.ndarray:
        """Coupler forces from positions and speeds.

        Parameters
        ----------
        x : array, shape (n,) or (n, k)
            Route positions of the vehicle centres, m.
        v : array, shape of ``x``
            Vehicle speeds, m/s.

        Returns
        -------
        ndarray, shape (n−1,) or (n−1, k)
            Coupler forces, N (+ tension), front coupler first.
        """
        delta, rate = self.coupler_extension(x, v)
        _extension("x (the coupler extensions it gives)", delta)
        return self.gear._force(delta, rate)

    def external_forces(self, t, x, v) -> np.ndarray:
        """Sum of every force on each vehicle except the couplers.

        Parameters
        ----------
        t : float
            Time, s (the air brake depends on it).
        x : array or None
            Route positions of the vehicle centres, m, shape of ``v``; only read on a
            route with grades or curves (None is accepted on level track).
        v : array, shape (n,) or (n, k)
            Vehicle speeds, m/s, at most 200 in size (above the wheel–rail speed record).

        Returns
        -------
        ndarray, shape of ``v``
            Net external force on each vehicle, N (+ forward).
        """
        t = _checks.scalar("t", t)
        v = self._vehicle_array("v", v)
        if np.abs(v).max() > MAXIMUM_SPEED:
            raise ValueError(f"v must be within ±{MAXIMUM_SPEED} m/s, got {v.flat[np.argmax(np.abs(v))]!r}")
        if x is not None or not self.route.is_level:
            x = self._vehicle_array("x", x)
            if x.shape != v.shape:
                raise ValueError(f"x and v must have the same shape, got {x.shape} and {v.shape}")
        return self._external_forces(t, x, v)

    def _external_forces(self, t, x, v):
        pre = self._pre if np.ndim(v) == 1 else self._pre_columns
        speed = np.abs(v)
        if self.resistance:
            retard = pre["a0"] + speed * (pre["a1"] + pre["a2"] * speed)
            if not self.route.is_level:
                retard = retard + pre["curve"] * np.abs(self.route.curvature_at(x))
        else:
            retard = np.zeros(np.shape(v))
        brake = self.air_brake
        if brake is not None and t > brake.start:
            since = np.maximum(t - pre["arrival"], 0.0)
            retard = retard - pre["brake"] * np.expm1(since * (-1.0 / brake.build_up_time))
        total = np.tanh(v * (-1.0 / self.creep_speed)) * retard
        if not self.route.is_level:
            grade = self.route.grade_at(x)
            total = total - pre["weight"] * grade / np.sqrt(1.0 + grade**2)
        if self._pre["traction"]:
            total = total + self._locomotive_forces(v, (-1,) + (1,) * (np.ndim(v) - 1))
        return total

    def _locomotive_forces(self, v, col):
        c = self.consist
        speed = np.abs(v)
        power_limit = c.rail_power.reshape(col) / np.maximum(speed, 1e-6)  # finite at standstill
        traction = self.notch / NOTCHES * np.minimum(c.max_tractive_effort.reshape(col), power_limit)
        # The dynamic brake's law per unit of maximum force, scaled by each vehicle's maximum.
        dynamic = dynamic_brake_force(speed, self.dynamic_brake, 1.0) * c.max_dynamic_brake.reshape(col)
        return traction - np.tanh(v / self.creep_speed) * dynamic

    def rhs(self, t, y) -> np.ndarray:
        """dy/dt of the whole train, for one state or a batch.

        One state goes through the compiled loop, a batch (one state per column)
        through numpy (:meth:`rhs_numpy`). The shape and finiteness of ``y`` are
        checked before any compiled code runs.

        Parameters
        ----------
        t : float
            Time, s.
        y : array, shape (2n,) or (2n, k)
            State ``[x_0, Δx, v]`` (see :meth:`initial_state`), or one per column.

        Returns
        -------
        ndarray, shape of ``y``
            Time derivative of the state: m/s, m/s, m/s².

        Raises
        ------
        ValueError
            If ``y`` does not have 2n rows, holds a non-finite number, or holds sizes at which the
            forces overflow (then no derivative is a number).

        Notes
        -----
        The checks cost more than the compiled loop itself (about 10 µs against
        4–6 µs for 152 vehicles). :func:`~raildyn.train.longitudinal.simulate` calls the loop
        without them, from its compiled integrator, as its states have the shape of a checked
        initial state, and checks each derivative for finiteness instead.

        Examples
        --------
        >>> from raildyn.train import braking_model
        >>> model = braking_model(10, 1)
        >>> dydt = model.rhs(1.0, model.initial_state(20.0))
        >>> dydt.shape, bool(dydt[model.size:].max() < 0)  # every vehicle slows down
        ((22,), True)
        """
        t = _checks.scalar("t", t)
        y = self._state(y)
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow is refused by _finite
            dydt = self._rhs_one(t, y) if y.ndim == 1 else self._rhs_numpy(t, y)
        return self._finite(dydt, y)

    def _rhs_one(self, t, y):
        """The compiled right-hand side of one state; ``y`` must already be checked."""
        from raildyn.train import _kernel

        return _kernel.rhs(t, y, *self._packed)

    def rhs_numpy(self, t, y) -> np.ndarray:
        """:meth:`rhs` in numpy array operations, for one state or a batch: the reference.

        Parameters
        ----------
        t : float
            Time, s.
        y : array, shape (2n,) or (2n, k)
            State ``[x_0, Δx, v]`` (see :meth:`initial_state`), or one per column.

        Returns
        -------
        ndarray, shape of ``y``
            Time derivative of the state: m/s, m/s, m/s².
        """
        t = _checks.scalar("t", t)
        y = self._state(y)
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow is refused by _finite
            return self._finite(self._rhs_numpy(t, y), y)

    def _rhs_numpy(self, t, y):
        n = self.size
        delta, v = y[1:n], y[n:]
        rate = v[:-1] - v[1:]
        f = self.gear._force(delta, rate)  # trial states may leave the law's domain
        x = None if self.route.is_level else self._positions(y)  # level track needs no positions
        force = self._external_forces(t, x, v)
        force[:-1] -= f
        force[1:] += f
        inv_mass = self._pre["inv_mass"] if np.ndim(y) == 1 else self._pre_columns["inv_mass"]
        return np.concatenate([v[:1], rate, force * inv_mass])

    def run_from_states(self, t, y, evaluations: int = 0) -> TrainRun:
        """The ``TrainRun`` of a history of states, however it was integrated.

        Parameters
        ----------
        t : array, shape (m,)
            Times, s, strictly increasing.
        y : array, shape (2n, m)
            The state at each time, one per column (see :meth:`initial_state`); coupler
            extensions within ±1 m.
        evaluations : int
            Right-hand-side calls spent on it (>= 0).

        Returns
        -------
        TrainRun
            Positions, speeds and coupler forces at the times ``t``.
        """
        t = _checks.time_grid("t", t)
        y = _checks.array("y", y, shape=(2 * self.size, t.size))
        evaluations = _checks.integer("evaluations", evaluations, low=0)
        n = self.size
        delta, v = y[1:n], y[n:]
        if delta.size:
            _extension("y (its coupler extensions)", delta)
        return TrainRun(
            t=t,
            position=self._positions(y),
            speed=v,
            coupler_force=self.gear._force(delta, v[:-1] - v[1:]),
            coupler_offsets=self.consist.coupler_offsets,
            evaluations=evaluations,
        )

    def quasi_static(self, speed: float, front_position: float | None = None) -> QuasiStatic:
        """Coupler forces when every vehicle moves with the same speed and acceleration.

        With the couplers at their static positions behind ``front_position``
        and all vehicles at ``speed``, the common acceleration is
        ``a = ΣF_ext/Σm`` and the force behind vehicle ``j`` is
        ``F_j = Σ_{i≤j} (F_ext,i − m_i a)``: at constant speed, the resistance
        of everything behind the coupler.

        Parameters
        ----------
        speed : float
            Speed of the train, m/s (0 to 200, above the wheel–rail speed record).
        front_position : float, optional
            Route position of the front coupler face, m; default ``front_start``.

        Returns
        -------
        QuasiStatic
            Coupler forces, common acceleration and external forces.

        Examples
        --------
        >>> model = TrainModel(make_consist("2 SD40-2 + 50 loaded hopper"), notch=8)
        >>> qs = model.quasi_static(10.0)
        >>> bool(qs.coupler_force[1] > 0), round(qs.acceleration, 3)  # the locomotives pull
        (True, 0.038)
        """
        speed = _checks.scalar("speed", speed, low=0.0, high=MAXIMUM_SPEED)
        front = (
            self.front_start if front_position is None else _checks.scalar("front_position", front_position)
        )
        x = front - self._pre["offset"]
        ext = self._external_forces(
            0.0 if self.air_brake is None else self.air_brake.start, x, np.full(self.size, speed)
        )
        acc = ext.sum() / self.consist.total_mass
        forces = np.cumsum(ext - self.consist.mass * acc)[:-1]
        return QuasiStatic(
            coupler_force=forces,
            acceleration=float(acc),
            external_force=ext,
            position=x,
            coupler_offsets=self.consist.coupler_offsets,
        )

    def balancing_speed(
        self, low: float = 0.5, high: float = 50.0, front_position: float | None = None
    ) -> float:
        """The speed the train can hold: where the quasi-static acceleration is zero.

        With the locomotives' traction (or dynamic brake) against resistance and
        grade, the common acceleration ``a(v) = ΣF_ext(v)/Σm`` of
        :meth:`quasi_static` changes sign at the balancing speed; it is found by
        Brent's method in ``[low, high]``.

        Parameters
        ----------
        low, high : float
            Speeds that bracket the balancing speed, m/s; 0 <= low < high <= 200 (above
            the wheel–rail speed record).
        front_position : float, optional
            Route position of the front coupler face, m; default ``front_start``.

        Returns
        -------
        float
            Balancing speed, m/s (to 1e-9 m/s).

        Raises
        ------
        ValueError
            If the acceleration has the same sign at ``low`` and ``high`` (no balance in between).
        raildyn.errors.SolverError
            If Brent's method does not converge.

        Examples
        --------
        >>> consist = make_consist("2 SD40-2 + 60 loaded hopper")
        >>> climb = TrainModel(consist, route=Route((0.0,), (0.01,)), notch=8)
        >>> round(3.6 * climb.balancing_speed(), 1)  # km/h on a 1 % climb
        14.7
        """
        from scipy.optimize import brentq

        low = _checks.scalar("low", low, low=0.0, high=MAXIMUM_SPEED)
        high = _checks.scalar("high", high, low=0.0, high=MAXIMUM_SPEED)
        if not low < high:
            raise ValueError(f"low must be < high, got low = {low!r} m/s and high = {high!r} m/s")

        def acceleration(v):
            return self.quasi_static(v, front_position).acceleration

        a_low, a_high = acceleration(low), acceleration(high)
        if a_low * a_high > 0:
            raise ValueError(
                f"low and high must bracket the balancing speed; the acceleration is {a_low:.4g} m/s² at "
                f"low = {low!r} m/s and {a_high:.4g} m/s² at high = {high!r} m/s (same sign)"
            )
        speed, info = brentq(
            acceleration, low, high, xtol=1e-9, rtol=4 * np.finfo(float).eps, full_output=True, disp=False
        )
        if not info.converged:
            raise SolverError(f"Brent's method did not converge: {info.flag}", step=info.iterations)
        return float(speed)
