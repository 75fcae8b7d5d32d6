"""Longitudinal dynamics of a whole train: the equations of motion, their integration, quasi-statics.

Vehicle ``i`` (0 at the front) obeys

    m_i a_i = T_i − D_i − B_i − R_i − G_i − K_i − F_i + F_{i−1}

with tractive effort ``T``, dynamic brake ``D``, air brake ``B``, Davis
resistance ``R``, grade ``G`` and curve resistance ``K``, and ``F_i`` the force
in the coupler behind vehicle ``i`` (+ tension). Retarding forces that act
against the motion are multiplied by ``tanh(v/v_c)`` with a creep speed
``v_c`` of a few cm/s, so a stopped train does not chatter between signs.
``TrainModel.rhs`` computes the right-hand side of one state in a compiled loop
(``_kernel``) and of a batch of states (one per column) with numpy, which is
also the readable reference the compiled loop is tested against.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp

from raildyn import _checks
from raildyn._progress import progress_bar
from raildyn.train import _kernel
from raildyn.train.couplers import DraftGear
from raildyn.train.forces import NOTCHES, AirBrake
from raildyn.train.resistance import CURVE_RESISTANCE, Route, davis_resistance
from raildyn.train.vehicles import Consist, G, make_consist


@dataclass(frozen=True)
class TrainModel:
    """A consist on a route with its couplers and its driver's settings.

    Parameters
    ----------
    consist : Consist
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
    creep_speed : float
        v_c of the ``tanh`` regularisation of the retarding forces, m/s (> 0).
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

    def __post_init__(self):
        if not isinstance(self.consist, Consist):
            raise TypeError(f"consist must be a Consist, got {type(self.consist).__name__}")
        _checks.scalar("notch", self.notch, low=0, high=NOTCHES)
        _checks.scalar("dynamic_brake", self.dynamic_brake, low=0.0, high=1.0)
        _checks.positive("creep_speed", self.creep_speed)
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
            "weight": c.mass * G,
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
        s[k.S_CREEP], s[k.S_NOTCH], s[k.S_DYNAMIC] = self.creep_speed, self.notch, self.dynamic_brake
        s[k.S_RESISTANCE], s[k.S_TRACTION] = self.resistance, pre["traction"]
        s[k.S_ROUTE] = not self.route.is_level
        if self.air_brake is not None:
            table[k.ROW_BRAKE], table[k.ROW_ARRIVAL] = pre["brake"], pre["arrival"]
            s[k.S_BRAKE], s[k.S_BRAKE_START] = 1.0, self.air_brake.start
            s[k.S_BUILD_UP] = self.air_brake.build_up_time
        route = np.vstack([self.route._x, self.route._table[:2]])
        return table, s, route

    @property
    def size(self) -> int:
        """Number of vehicles n; the state has 2n entries (positions, then speeds)."""
        return len(self.consist)

    def initial_state(self, speed: float, extension: float = 0.0) -> np.ndarray:
        """State with every vehicle at ``speed`` (m/s) and every coupler at ``extension`` δ (m).

        The state is ``[x_0, δ_0 … δ_{n−2}, v_0 … v_{n−1}]``: the route position of
        the leading vehicle's centre, the coupler extensions and the speeds. Keeping
        the extensions (millimetres) as states, rather than the positions (kilometres),
        lets the relative tolerance of the integrator act on what the couplers feel.
        """
        speed = _checks.scalar("speed", speed)
        extension = _checks.scalar("extension", extension)
        x0 = self.front_start - self._pre["offset"][0]
        return np.r_[x0, np.full(self.size - 1, extension), np.full(self.size, speed)]

    def positions(self, y) -> np.ndarray:
        """Route positions of the vehicle centres (n, ...) from states (2n, ...)."""
        n = self.size
        spacing = self._pre["spacing"].reshape((-1,) + (1,) * (np.ndim(y) - 1))
        behind = np.cumsum(spacing + y[1:n], axis=0)
        return np.concatenate([y[:1], y[:1] - behind])

    def coupler_extension(self, x, v):
        """Coupler extensions δ (m) and their rates (m/s) from positions and speeds (vehicle axis first)."""
        spacing = self._pre["spacing"].reshape((-1,) + (1,) * (np.ndim(x) - 1))
        return x[:-1] - x[1:] - spacing, v[:-1] - v[1:]

    def coupler_forces(self, x, v):
        """Coupler forces, N (+ tension), shape ``(n−1, ...)``."""
        delta, rate = self.coupler_extension(x, v)
        return self.gear.force(delta, rate)

    def external_forces(self, t, x, v):
        """Sum of every force on each vehicle except the couplers, N, shape of ``v``.

        ``x`` (route positions, shape of ``v``) is only read on a route with grades or curves.
        """
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
        peak, fade = 8.0, 20.0  # m/s, the corner speeds of forces.dynamic_brake_force
        shape = np.minimum(speed / peak, np.minimum(1.0, fade / np.maximum(speed, 1e-12)))
        dynamic = self.dynamic_brake * c.max_dynamic_brake.reshape(col) * shape
        return traction - np.tanh(v / self.creep_speed) * dynamic

    def rhs(self, t, y):
        """dy/dt for ``y = [x_0, δ, v]`` (see :meth:`initial_state`), shape ``(2n,)`` or ``(2n, k)``.

        One state goes through the compiled loop, a batch (one state per column) through numpy.
        """
        if np.ndim(y) == 1:
            return _kernel.rhs(float(t), np.asarray(y, dtype=float), *self._packed)
        return self.rhs_numpy(t, y)

    def rhs_numpy(self, t, y):
        """:meth:`rhs` in numpy array operations, for one state or a batch: the reference."""
        n = self.size
        delta, v = y[1:n], y[n:]
        rate = v[:-1] - v[1:]
        f = self.gear.force(delta, rate)
        x = None if self.route.is_level else self.positions(y)  # level track needs no positions
        force = self.external_forces(t, x, v)
        force[:-1] -= f
        force[1:] += f
        inv_mass = self._pre["inv_mass"] if np.ndim(y) == 1 else self._pre_columns["inv_mass"]
        return np.concatenate([v[:1], rate, force * inv_mass])

    def quasi_static(self, speed: float, front_position: float | None = None) -> QuasiStatic:
        """Coupler forces when every vehicle moves with the same speed and acceleration.

        With the couplers at their static positions behind ``front_position``
        (default ``front_start``) and all vehicles at ``speed`` (m/s, >= 0), the
        common acceleration is ``a = ΣF_ext/Σm`` and the force behind vehicle ``j``
        is ``F_j = Σ_{i≤j} (F_ext,i − m_i a)``: at constant speed, the resistance
        of everything behind the coupler.
        """
        speed = _checks.nonnegative("speed", speed)
        front = (
            self.front_start if front_position is None else _checks.scalar("front_position", front_position)
        )
        x = front - self._pre["offset"]
        ext = self.external_forces(
            0.0 if self.air_brake is None else self.air_brake.start, x, np.full(self.size, speed)
        )
        acc = ext.sum() / self.consist.total_mass
        forces = np.cumsum(ext - self.consist.mass * acc)[:-1]
        return QuasiStatic(forces=forces, acceleration=float(acc), external=ext, position=x)


@dataclass(frozen=True)
class QuasiStatic:
    """Quasi-static state of a train.

    Attributes
    ----------
    forces : ndarray (n−1,)
        Coupler forces, N (+ tension), front coupler first.
    acceleration : float
        Common acceleration, m/s².
    external : ndarray (n,)
        Net external force on each vehicle, N.
    position : ndarray (n,)
        Route positions of the vehicle centres, m.
    """

    forces: np.ndarray
    acceleration: float
    external: np.ndarray
    position: np.ndarray


@dataclass(frozen=True)
class TrainRun:
    """A simulated run.

    Attributes
    ----------
    t : ndarray (m,)
        Times, s.
    position : ndarray (n, m)
        Route positions of the vehicle centres, m.
    speed : ndarray (n, m)
        Vehicle speeds, m/s.
    coupler_force : ndarray (n−1, m)
        Coupler forces, N (+ tension).
    success : bool
    message : str
    evaluations : int
        Right-hand-side calls made by the integrator.
    """

    t: np.ndarray
    position: np.ndarray
    speed: np.ndarray
    coupler_force: np.ndarray
    success: bool
    message: str
    evaluations: int

    @property
    def max_tension(self) -> np.ndarray:
        """Largest draft force of each coupler over the run, N (shape (n−1,))."""
        return self.coupler_force.max(axis=1)

    @property
    def max_compression(self) -> np.ndarray:
        """Largest buff force of each coupler over the run, N, as a positive number."""
        return -self.coupler_force.min(axis=1)

    def peak(self) -> tuple[float, int, float]:
        """The force of largest magnitude: (force N, coupler index from the front, time s)."""
        j, k = np.unravel_index(np.argmax(np.abs(self.coupler_force)), self.coupler_force.shape)
        return float(self.coupler_force[j, k]), int(j), float(self.t[k])


def simulate(
    model: TrainModel,
    duration: float,
    initial_speed: float,
    *,
    initial_extension: float = 0.0,
    samples: int = 601,
    rtol: float = 1e-7,
    atol: float | None = None,
    method: str = "RK45",
    max_step: float = np.inf,
    progress: bool = False,
) -> TrainRun:
    """Integrate the longitudinal equations of the whole train with ``scipy.integrate.solve_ivp``.

    Parameters
    ----------
    model : TrainModel
    duration : float
        Simulated time, s (> 0).
    initial_speed : float
        Speed of every vehicle at t = 0, m/s.
    initial_extension : float
        Coupler extension δ at t = 0, m: 0 centres the slack, ``+slack/2`` starts stretched
        and ``−slack/2`` bunched.
    samples : int
        Number of output times (>= 2), uniform over [0, duration].
    rtol, atol : float
        Integrator tolerances. Explicit methods are held back by the stiff draft gear
        rather than by accuracy, so a tight ``rtol`` costs little: for the standard
        braking run 1e-5 misplaces the peak coupler force by ~13 % and 1e-7 agrees with
        an implicit solution to 0.1 %; ``atol`` defaults to 1e-6 m on positions and 1e-5 m/s on speeds.
    method : str
        A ``solve_ivp`` method.
    max_step : float
        Largest step, s.
    progress : bool
        Show a tqdm bar of simulated time.

    Returns
    -------
    TrainRun
    """
    if not isinstance(model, TrainModel):
        raise TypeError(f"model must be a TrainModel, got {type(model).__name__}")
    duration = _checks.positive("duration", duration)
    samples = _checks.integer("samples", samples, low=2)
    rtol = _checks.positive("rtol", rtol)
    n = model.size
    if atol is None:
        atol = np.r_[1e-3, np.full(n - 1, 1e-6), np.full(n, 1e-5)]
    y0 = model.initial_state(initial_speed, initial_extension)
    t_eval = np.linspace(0.0, duration, samples)
    fun = model.rhs
    bar = None
    if progress:
        bar = progress_bar(total=round(duration), desc="simulated time (s)")

        def fun(t, y, _rhs=model.rhs):
            step = int(t) - bar.n
            if step > 0:
                bar.update(step)
            return _rhs(t, y)

    try:
        sol = solve_ivp(
            fun, (0.0, duration), y0, method=method, t_eval=t_eval, rtol=rtol, atol=atol,
            max_step=max_step,
        )  # fmt: skip
    finally:
        if bar is not None:
            bar.close()
    if not sol.success:
        raise RuntimeError(f"the train simulation failed at t = {sol.t[-1]:.3f} s: {sol.message}")
    delta, v = sol.y[1:n], sol.y[n:]
    return TrainRun(
        t=sol.t,
        position=model.positions(sol.y),
        speed=v,
        coupler_force=model.gear.force(delta, v[:-1] - v[1:]),
        success=bool(sol.success),
        message=str(sol.message),
        evaluations=int(sol.nfev),
    )


def braking_model(
    cars: int = 100,
    locomotives: int = 2,
    *,
    slack: float = 0.025,
    propagation_speed: float = 250.0,
    gear: DraftGear | None = None,
    route: Route | None = None,
) -> TrainModel:
    """The chapter's standard case: ``locomotives`` SD40-2 + ``cars`` loaded hoppers in emergency.

    The throttle is at idle and the emergency air brake is applied at t = 0 from
    the front; the couplers use :class:`DraftGear` with the given ``slack`` (m).
    """
    cars = _checks.integer("cars", cars, low=1)
    locomotives = _checks.integer("locomotives", locomotives, low=0)
    text = f"{cars} loaded hopper" if locomotives == 0 else f"{locomotives} SD40-2 + {cars} loaded hopper"
    gear = DraftGear(slack=slack) if gear is None else gear
    return TrainModel(
        make_consist(text),
        gear=gear,
        route=Route.level() if route is None else route,
        air_brake=AirBrake(start=0.0, propagation_speed=propagation_speed),
    )
