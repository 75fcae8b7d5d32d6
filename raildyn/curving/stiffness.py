"""Self-steering (book chapter 8): a bogie's bending and shear stiffness, and the stability–curving trade-off.

Two wheelsets held by one frame through primary springs act on each other as if
joined by two springs only (Wickens 2003, ch. 7; Boocock 1969; Elkins & Gostling
1977), once the frame, which carries no load of its own in a steady curve, has
settled where the springs' strain energy is least:

* a **bending** stiffness k_b against their relative yaw ψ₁ − ψ₂;
* a **shear** stiffness k_sh against their relative lateral displacement corrected for
  the bogie's mean yaw, y₁ − y₂ − b(ψ₁ + ψ₂), which a rigid yaw of the pair leaves at zero.

Derivation (written here). Wheelset 1 at x = +b and wheelset 2 at x = −b hang from a
frame (y_f, ψ_f) by a lateral spring k_y and a yaw spring k_ψ each. The strain energy is

    U = ½k_y[(y₁ − y_f − bψ_f)² + (y₂ − y_f + bψ_f)²] + ½k_ψ[(ψ₁ − ψ_f)² + (ψ₂ − ψ_f)²].

With ȳ, ψ̄ the means and Δy, Δψ the differences of the wheelsets' coordinates, the
brackets regroup into

    U = k_y(ȳ − y_f)² + k_y(Δy/2 − bψ_f)² + k_ψ(ψ̄ − ψ_f)² + k_ψΔψ²/4.

∂U/∂y_f = 0 puts the frame at y_f = ȳ. ψ_f then sits between two springs in series,
k_y b² pulling it towards Δy/(2b) and k_ψ towards ψ̄, and ∂U/∂ψ_f = 0 leaves

    U_min = ½ (k_ψ/2) Δψ² + ½ [k_y k_ψ / (2(k_ψ + b² k_y))] (Δy − 2bψ̄)²,

so that

    k_b = k_ψ / 2,        k_sh = k_y k_ψ / (2(k_ψ + b² k_y)).

The two wheelsets' yaw springs are in series for bending; for shear, each wheelset's
lateral spring (k_y, moved to the frame's yaw by b²) is in series with its yaw spring.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.curving.steady import steady_curving
from raildyn.linear_model import AffineFamily, as_linear_system
from raildyn.stability import CRITICAL_SPEED_STATUSES, MAX_SCAN_SPEEDS, StateMatrices, critical_speeds
from raildyn.track import MINIMUM_RADIUS
from raildyn.vehicles import Bogie

__all__ = [
    "BendingShear",
    "SelfSteeringCurving",
    "StabilityCurving",
    "bending_shear_stiffness",
    "self_steering_curving",
    "stability_and_curving",
]


@dataclass(frozen=True)
class BendingShear:
    """A two-axle bogie's inter-wheelset stiffnesses (Wickens 2003, ch. 7).

    Attributes
    ----------
    bending : float
        k_b, against the wheelsets' relative yaw ψ₁ − ψ₂, N·m/rad (≥ 0).
    shear : float
        k_sh, against y₁ − y₂ − b(ψ₁ + ψ₂), N/m (≥ 0).
    """

    bending: float
    shear: float

    def __post_init__(self):
        _checks.nonnegative("bending", self.bending)
        _checks.nonnegative("shear", self.shear)


def _bogie(value) -> Bogie:
    return _checks.instance("bogie", value, Bogie, "raildyn.vehicles.Bogie")


def bending_shear_stiffness(bogie: Bogie) -> BendingShear:
    """The bending and shear stiffness that a bogie's primary suspension gives its two wheelsets.

    k_b = k_ψ/2 and k_sh = k_y k_ψ / (2(k_ψ + b²k_y)), with k_ψ and k_y the primary yaw
    and lateral stiffness of each wheelset and b the semi-wheelbase: the strain energy
    of the primary springs with the frame where it is least, derived in
    :mod:`raildyn.curving.stiffness` (Wickens 2003, ch. 7; Boocock 1969). The secondary
    suspension is left out: it holds the frame, not one wheelset against the other.

    Parameters
    ----------
    bogie : Bogie
        Its ``wheelset.yaw_stiffness`` (N·m/rad), ``wheelset.lateral_stiffness`` (N/m) and
        ``semi_wheelbase`` (m).

    Returns
    -------
    BendingShear
        k_b (N·m/rad) and k_sh (N/m); k_sh is 0 when either primary stiffness is.

    Examples
    --------
    The Manchester bogie: k_ψ = 62.8 MN·m/rad, k_y = 7.77 MN/m, b = 1.28 m:

    >>> from raildyn.vehicles import Bogie
    >>> s = bending_shear_stiffness(Bogie())
    >>> round(s.bending / 1e6, 2), round(s.shear / 1e6, 3)
    (31.39, 3.229)
    """
    _bogie(bogie)
    k_psi, k_y = bogie.wheelset.yaw_stiffness, bogie.wheelset.lateral_stiffness
    b = bogie.semi_wheelbase
    # k_sh = k_y k_ψ / (2(k_ψ + b² k_y)), written so that k_ψ = k_y = 0 gives 0, not 0/0
    series = 0.0 if k_psi == 0.0 or k_y == 0.0 else 1.0 / (1.0 / k_y + b * b / k_psi)
    return BendingShear(0.5 * k_psi, 0.5 * series)


@dataclass(frozen=True, eq=False)  # arrays: compared by identity
class SelfSteeringCurving(Tabular):
    """The closed-form steady state of two wheelsets joined by k_b and k_sh in a curve at balance speed.

    Attributes
    ----------
    radius : float
        R, m (> 0).
    stiffness : BendingShear
        The k_b and k_sh used.
    offset : ndarray, (2,)
        Leading and trailing wheelset's offset towards the outer rail, m.
    angle_of_attack : ndarray, (2,)
        Leading and trailing wheelset's yaw from the local tangent, positive towards the
        outer rail, rad.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("offset", "m"), ("angle_of_attack", "rad"))
    _scalars = (("radius", "m"),)

    radius: float
    stiffness: BendingShear
    offset: np.ndarray
    angle_of_attack: np.ndarray

    def __post_init__(self):
        _checks.positive("radius", self.radius)
        _checks.instance("stiffness", self.stiffness, BendingShear)
        _checks.array("offset", self.offset, shape=(2,))
        _checks.array("angle_of_attack", self.angle_of_attack, shape=(2,))


def self_steering_curving(bogie: Bogie, radius) -> SelfSteeringCurving:
    """Closed-form steady curving of a two-axle bogie described by its bending and shear stiffness.

    Linear creep with no spin (f₂₃ = f₃₃ = 0), no gravitational stiffness, no
    secondary suspension and no unbalanced lateral force (the balance speed): the
    four equilibrium equations of the two wheelsets (lateral force and yaw moment
    each), with the creep forces 2f₂₂ψᵢ and −2af₁₁(a/R + λyᵢ/r₀) and the spring
    forces of k_b and k_sh, solved by hand (derived in chapter 8 of the companion;
    the method is Wickens' 2003, ch. 7, after Boocock 1969). With
    χ = a λ f₁₁ f₂₂ / r₀ (per wheel f₁₁, f₂₂):

        α₁ = −α₂ = (b/R) k_b k_sh / (k_b k_sh + χ)
        ȳ = r₀a/(λR) + r₀ b f₂₂ α₁ / (λ a f₁₁),       y₁ − y₂ = 2 f₂₂ α₁ / k_sh,

    offsets towards the outer rail. A soft bending stiffness lets the wheelsets take up
    radial positions (α → 0 as k_b → 0); a rigid bogie (k_b, k_sh → ∞) has α = b/R and
    the offset r₀a(1 + b²f₂₂/(a²f₁₁))/(λR).

    Parameters
    ----------
    bogie : Bogie
        Its wheelset's r₀, a, λ (> 0), f₁₁ and f₂₂ (> 0), its primary stiffnesses and b.
        The wheelset's spin and gravitational terms are ignored here.
    radius : float
        R, m, at least :data:`~raildyn.track.cant.MINIMUM_RADIUS` (50 m).

    Returns
    -------
    SelfSteeringCurving

    Examples
    --------
    >>> s = self_steering_curving(Bogie(), 600.0)
    >>> [round(1e3 * float(a), 3) for a in s.angle_of_attack]
    [1.741, -1.741]
    """
    _bogie(bogie)
    R = _checks.scalar("radius", radius, low=MINIMUM_RADIUS)
    ws = bogie.wheelset
    r0, a, b = ws.rolling_radius, ws.half_gauge, bogie.semi_wheelbase
    lam = _checks.positive("bogie.wheelset.conicity", ws.conicity)
    f11 = _checks.positive("bogie.wheelset.f11", ws.f11)
    f22 = _checks.positive("bogie.wheelset.f22", ws.f22)
    k = bending_shear_stiffness(bogie)
    if k.shear == 0.0:
        raise ValueError(
            f"bogie must have a shear stiffness > 0 (both primary stiffnesses > 0), got yaw_stiffness "
            f"{ws.yaw_stiffness!r} and lateral_stiffness {ws.lateral_stiffness!r}"
        )
    kappa = a * lam * f11 * f22 / r0
    alpha = (b / R) * k.bending * k.shear / (k.bending * k.shear + kappa)
    mean = r0 * a / (lam * R) + r0 * b * f22 * alpha / (lam * a * f11)
    half_difference = f22 * alpha / k.shear
    return SelfSteeringCurving(
        R, k, np.array([mean + half_difference, mean - half_difference]), np.array([alpha, -alpha])
    )


# ---------------------------------------------------------------------------
# The trade-off between stability and curving


@dataclass(frozen=True, eq=False)  # arrays: compared by identity
class StabilityCurving(Tabular):
    """Critical speed and angle of attack in a curve against the primary yaw stiffness.

    Attributes
    ----------
    yaw_stiffness : ndarray, (m,)
        k_ψ of each wheelset, N·m/rad (≥ 0, increasing).
    critical_speed : ndarray, (m,)
        Linear critical speed at each k_ψ, m/s (> 0; ``inf`` where stable over ``speed_range``,
        the lower end of the range where already unstable there: see ``status``).
    status : tuple of str
        Per k_ψ, as :class:`raildyn.stability.linear.CriticalSpeed`: "crossing", "stable over the range"
        or "unstable at the lowest speed".
    angle_of_attack : ndarray, (m,)
        The leading wheelset's angle of attack in the curve, rad, positive towards the
        outer rail (:func:`raildyn.curving.steady.steady_curving`).
    speed : float
        V in the curve, m/s (> 0).
    radius : float
        R, m (> 0).
    cant : float
        h_t, m (≥ 0).
    speed_range : tuple of float
        The speeds searched for the critical speed, m/s.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("yaw_stiffness", "N·m/rad"), ("critical_speed", "m/s"), ("status", "-"),
        ("angle_of_attack", "rad"),
    )  # fmt: skip
    _scalars = (("speed", "m/s"), ("radius", "m"), ("cant", "m"))

    yaw_stiffness: np.ndarray
    critical_speed: np.ndarray
    status: tuple
    angle_of_attack: np.ndarray
    speed: float
    radius: float
    cant: float
    speed_range: tuple

    def __post_init__(self):
        k = _checks.increasing("yaw_stiffness", self.yaw_stiffness, low=0.0)
        m = k.size
        statuses = _checks.strings("status", self.status, m)
        for s in statuses:
            _checks.choice("status", s, CRITICAL_SPEED_STATUSES)
        v = _checks._numbers("critical_speed", self.critical_speed)
        stable = np.array([s == CRITICAL_SPEED_STATUSES[1] for s in statuses])
        if v.shape != (m,):
            raise ValueError(f"critical_speed must have shape ({m},), got {v.shape}")
        if np.any(np.isposinf(v) != stable):
            raise ValueError(
                f"critical_speed must be inf exactly where the status is {CRITICAL_SPEED_STATUSES[1]!r}, "
                f"got {v!r:.80}"
            )
        _checks.plausible_array("critical_speed", np.where(stable, 1.0, v), "speed", low_open=True)
        _checks.array("angle_of_attack", self.angle_of_attack, shape=(m,))
        _checks.speed("speed", self.speed)
        _checks.positive("radius", self.radius)
        _checks.nonnegative("cant", self.cant)
        _range(self.speed_range)

    def plot(self, ax=None, *, artists: dict | None = None) -> dict:
        """Critical speed (km/h, left axis) and angle of attack (mrad, right axis) against k_ψ.

        The k_ψ axis is in MN·m/rad, logarithmic when every k_ψ is > 0. Where the model is
        stable over the whole range searched the critical-speed line is left blank.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (a new figure when None); its twin on the right is made here.
        artists : dict, optional
            What an earlier call returned: the two lines are moved in place (the axes'
            limits are left to the caller); nothing is drawn anew.

        Returns
        -------
        dict
            ``critical`` and ``attack`` (the two Line2D) and ``axes`` (left and right Axes).
        """
        x = self.yaw_stiffness / 1e6
        kmh = np.where(np.isfinite(self.critical_speed), 3.6 * self.critical_speed, np.nan)
        mrad = 1e3 * self.angle_of_attack
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
            missing = {"critical", "attack", "axes"} - set(artists)
            if missing:
                raise ValueError(f"artists must come from StabilityCurving.plot, missing {sorted(missing)}")
            artists["critical"].set_data(x, kmh)
            artists["attack"].set_data(x, mrad)
            return artists
        import matplotlib

        from raildyn import plots

        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            right = ax.twinx()
            (critical,) = ax.plot(x, kmh, color=plots.COLORS[0], marker="o", ms=3, label="critical speed")
            (attack,) = right.plot(
                x, mrad, color=plots.COLORS[1], marker="s", ms=3, ls="--", label="angle of attack"
            )
            if np.all(x > 0):
                ax.set_xscale("log")
            ax.set_xlabel("primary yaw stiffness k_ψ per wheelset (MN·m/rad)")
            ax.set_ylabel("linear critical speed (km/h)", color=plots.COLORS[0])
            right.set_ylabel("leading wheelset's angle of attack (mrad)", color=plots.COLORS[1])
            ax.set_title(
                f"R = {self.radius:g} m, V = {3.6 * self.speed:.0f} km/h, cant {1e3 * self.cant:.0f} mm",
                fontsize="medium",
            )
            ax.legend(handles=[critical, attack], loc="upper left", fontsize="small")
        return {"critical": critical, "attack": attack, "axes": (ax, right)}


def _range(speed_range) -> tuple[float, float]:
    return _checks.speed_range("speed_range", speed_range)


def _stiffness_matrices(model, ks: np.ndarray):
    """The model's system at the largest k_ψ and one K per k_ψ (M, C₀ and C₁ do not change).

    K is affine in k_ψ when ``replace(yaw_stiffness=...)`` changes only the primary yaw springs:
    the model as an affine family in k_ψ (:class:`raildyn.linear_model.AffineFamily`, three
    assemblies, checked at k_top/2) gives every K; where the check fails, every K is built.
    """
    top = float(ks[-1]) if ks[-1] > 0 else 1.0

    def make(k):
        try:
            return model.replace(yaw_stiffness=k)
        except TypeError as err:
            raise TypeError(f"model: replace(yaw_stiffness=...) failed: {err}") from None

    family = AffineFamily(make, (0.0,), (top,))
    s1 = family.assembled[(top,)]
    if family.affine and all(family.constant(n) for n in ("M", "C0", "C1")):
        return s1, family.stacks(ks[:, None])["K"]
    systems = [as_linear_system(make(float(k))) for k in ks]
    if not all(np.array_equal(getattr(s, n), getattr(s1, n)) for s in systems for n in ("M", "C0", "C1")):
        raise ValueError("model: replace(yaw_stiffness=...) must change only the stiffness matrix")
    return s1, np.stack([s.K for s in systems])


# The stiffness matrices and the critical speeds depend on the model and the stiffnesses alone, not
# on the curve: a call that changes only the curve (a radius slider) reuses them. The models are
# frozen dataclasses, hashed by their parameters; the last 32 are kept, and an unhashable model is
# searched afresh every time.
_KEPT = 32


@lru_cache(maxsize=_KEPT)
def _kept_matrices(model, ks: tuple):
    system, Ks = _stiffness_matrices(model, np.array(ks))
    Ks.setflags(write=False)  # shared by every call that reuses it
    return system, Ks


@lru_cache(maxsize=_KEPT)
def _kept_critical_speeds(model, ks: tuple, low: float, high: float, tol: float, scan: int):
    system, Ks = _kept_matrices(model, ks)
    return _search(system, Ks, low, high, tol, scan)


def _search(system, Ks, low: float, high: float, tol: float, scan: int) -> tuple[tuple, tuple]:
    """The status and critical speed at each k_ψ: chapter 7's batched search (M, C₀ and C₁ shared)."""
    found = critical_speeds(
        StateMatrices(system.M, Ks, system.C0, system.C1), (low, high), tol=tol, scan=scan
    )
    return found.status, tuple(found.speeds)


def _hashable(model) -> bool:
    try:
        hash(model)
    except TypeError:
        return False
    return True


def stability_and_curving(
    model, yaw_stiffnesses, speed, radius, cant=0.0, *, speed_range=(1.0, 150.0), tol=0.05, scan=24
) -> StabilityCurving:
    """The trade-off: linear critical speed and angle of attack in a curve against the primary yaw stiffness.

    For each k_ψ, the model with ``model.replace(yaw_stiffness=k_ψ)`` gives its linear
    critical speed (chapter 7, :func:`raildyn.stability.linear.critical_speed`: the lowest
    speed where the largest real part of the eigenvalues crosses zero) and its
    leading wheelset's angle of attack in a curve (:func:`raildyn.curving.steady.steady_curving`).
    A stiff yaw suspension holds the wheelsets against hunting and raises the critical
    speed; it also holds them square to the bogie frame, so that in a curve they cannot
    turn radial and the leading wheelset runs at an angle of attack near b/R (Wickens
    2003, ch. 7; Garg & Dukkipati 1984, ch. 8).

    Vectorised: the stiffness matrix is linear in k_ψ (checked), so every critical
    speed comes from one batched coarse scan and a few batched refinement steps, and
    every steady state from one batched linear solve with the curve's loads of one
    :func:`~raildyn.curving.steady.steady_curving` call. The critical speeds do not depend
    on the curve: a call that changes only ``speed``, ``radius`` or ``cant`` reuses those of
    an earlier call with the same model and stiffnesses (the last 32 kept).

    Parameters
    ----------
    model : LinearModel
        A lateral model with wheelsets whose ``replace(yaw_stiffness=...)`` sets the primary
        yaw stiffness of every wheelset (:class:`~raildyn.wheelset.Wheelset`,
        :class:`~raildyn.vehicles.Bogie`, :class:`~raildyn.vehicles.LateralCar`, the freight car,
        the locomotive).
    yaw_stiffnesses : array_like, (m,)
        k_ψ per wheelset, N·m/rad: at least one, ≥ 0, strictly increasing.
    speed : float
        V in the curve, m/s (as :func:`~raildyn.curving.steady.steady_curving`).
    radius : float
        R, m (≥ 50 m).
    cant : float
        h_t, m, in [0, 0.2].
    speed_range : (float, float)
        Speeds searched for the critical speed, m/s (0 < low < high).
    tol : float
        Absolute tolerance on each critical speed, m/s (> 0).
    scan : int
        Speeds of the coarse scan, in [8, 10 000]; a crossing and recrossing between two
        of them would be missed, as in :func:`raildyn.stability.linear.critical_speed`.

    Returns
    -------
    StabilityCurving

    Examples
    --------
    The Manchester car at its balance speed in a 600 m curve with 100 mm cant:

    >>> from raildyn.track import balance_speed
    >>> from raildyn.vehicles import LateralCar
    >>> r = stability_and_curving(LateralCar(), [5e6, 60e6], balance_speed(600.0, 0.1), 600.0, 0.1)
    >>> [round(3.6 * v) for v in r.critical_speed], [round(1e3 * float(a), 2) for a in r.angle_of_attack]
    ([154, 280], [0.16, 1.72])
    """
    _checks.linear_model("model", model)
    if not callable(getattr(model, "replace", None)):
        raise TypeError(f"model must have replace(yaw_stiffness=...), got {type(model).__name__}")
    ks = _checks.increasing("yaw_stiffnesses", yaw_stiffnesses, low=0.0)
    low, high = _range(speed_range)
    tol = _checks.positive("tol", tol)
    scan = _checks.integer("scan", scan, low=8, high=MAX_SCAN_SPEEDS)
    kept = _hashable(model)
    key = (model, tuple(ks.tolist()))
    # system: the model at the largest k_ψ
    system, Ks = _kept_matrices(*key) if kept else _stiffness_matrices(model, ks)
    if not system.wheelsets:
        raise ValueError(f"model must have wheelsets on the rails, got one with coordinates {system.labels}")
    state = steady_curving(system, speed, radius, cant)  # checks speed, radius and cant
    # The curve's loads f do not depend on the suspension: f = K q at the largest k_ψ.
    f = system.K @ state.displacement
    q = np.linalg.solve(Ks, np.broadcast_to(f, (ks.size, f.size))[..., None])[..., 0]
    residual = np.abs(np.einsum("kij,kj->ki", Ks, q) - f).max(axis=1)
    bad = ~np.all(np.isfinite(q), axis=1) | (residual > 1e-8 * np.abs(f).max())
    if bad.any():
        raise ValueError(
            f"yaw_stiffnesses: at {ks[bad][0]!r} N·m/rad the model's stiffness matrix is singular, "
            "so it has no steady state in a curve"
        )
    lead = int(np.argmax(state.positions))
    ipsi = system.wheelsets[lead][1]
    # α = −(ψ − x/R): the same change of yaw in the vehicle's axes changes α by its opposite
    alpha = state.angle_of_attack[lead] - (q[:, ipsi] - state.displacement[ipsi])
    # The critical speeds: chapter 7's search, all stiffnesses at once (M, C₀ and C₁ are shared).
    if kept:
        status, speeds = _kept_critical_speeds(*key, low, high, tol, scan)
    else:
        status, speeds = _search(system, Ks, low, high, tol, scan)
    return StabilityCurving(
        ks, np.array(speeds), tuple(status), alpha, state.speed, state.radius, state.cant, (low, high)
    )
