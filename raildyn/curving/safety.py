"""Running safety in a curve (book chapter 8): wheel climb, track shift, wheel unloading on twisted
track and overturning, for one vehicle through one curve, each against its limit.

The criteria, each in closed form over the quasi-static equilibrium of
:func:`raildyn.curving.quasi_static.quasi_static_curving` and the vehicle's own data
(:class:`raildyn.vehicles.LateralCar`):

* **Wheel climb** — each wheel's Y/Q against Nadal's limit at the contact's own flange angle
  and friction, and each axle's Σ|Y/Q| against Weinstock's (:func:`raildyn.curving.climb.wheel_climb`).
* **Track shift** — each axle's ΣY = Y_inner + Y_outer against Prud'homme's limit
  (:func:`prudhomme_limit`): (ΣY)_lim = α_P (10 + W/3) kN, W the axle load in kN (Prud'homme 1967;
  EN 14363 writes it α (10 + 2Q₀/3) kN with Q₀ the static wheel load, the same number).
* **Wheel unloading on twisted track** — ΔQ/Q₀ of the most unloaded wheel when the car stands on
  a track twisted by the limit twist over its bogie wheelbase 2b and over its bogie-centre
  distance 2l (EN 14363's 2a⁺ and 2a*; :func:`limit_twist`, :func:`twist_unloading`), against
  ΔQ/Q₀ ≤ 0.6, in the manner of the EN 14363 twist test (a rigid body and frames on their springs
  on a twisted plane; no friction in the suspension, no torsional flexibility of the body or the
  frames).
* **Overturning** — the quasi-static unloading of the wheels on the unloaded rail under the
  unbalanced lateral acceleration a_q (cant deficiency, or excess), with the body's roll on its
  secondary suspension (the flexibility coefficient s_φ from its roll stiffness) and an optional
  side wind, and the cant deficiency at which they lift.

Units: N, m, m/s, rad; twists in m/m (× 1000 for ‰); quotients and ratios are plain numbers.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.constants import GRAVITY
from raildyn.curving.climb import wheel_climb
from raildyn.curving.quasi_static import QuasiStaticCurving, quasi_static_curving
from raildyn.track import MAXIMUM_CANT, MINIMUM_RADIUS, cant_deficiency
from raildyn.track.cant import STANDARD_RAIL_SPACING
from raildyn.vehicles import LateralCar, VerticalCar
from raildyn.wheelset import WheelRailContact

__all__ = [
    "MANCHESTER_PRIMARY_ROLL_STIFFNESS",
    "TWIST_UNLOADING_LIMIT",
    "SafetyAssessment",
    "limit_twist",
    "prudhomme_limit",
    "safety_assessment",
    "twist_unloading",
]

# Iwnicki (1998), the Manchester benchmark vehicle: primary vertical springs 1220 kN/m per axlebox
# (VerticalCar.primary_stiffness is the wheelset's two, 2440 kN/m) at 1.0 m either side of the
# track's centre line, so the primary roll stiffness of a wheelset is 2 k (1.0 m)².
_PRIMARY_SEMI_SPACING = 1.0
MANCHESTER_PRIMARY_ROLL_STIFFNESS = VerticalCar().primary_stiffness * _PRIMARY_SEMI_SPACING**2
"""k_φp = k_p d² = 2.44 MN·m/rad, the primary roll stiffness of one wheelset of the Manchester
benchmark vehicle (Iwnicki 1998: k_p/2 = 1220 kN/m per axlebox at d = 1.0 m either side)."""

# Prud'homme's α: 1 and 0.85 are the standard's; a network's own rule is not expected below a half.
_LOWEST_FACTOR = 0.5

TWIST_UNLOADING_LIMIT = 0.6
"""The limit of ΔQ/Q₀ on twisted track, 0.6, as EN 14363 and UIC 530-2 apply it to the most
unloaded wheel."""


def prudhomme_limit(axle_load, factor=1.0):
    """Prud'homme's limit of an axle's track shift force: α_P (10 + W/3) kN, W the axle load in kN.

    (ΣY)_lim = α_P (10 kN + W/3) (Prud'homme 1967, from tests of the lateral resistance of ballasted
    track; the form α (10 + 2Q₀/3) kN of EN 14363:2016, Q₀ = W/2 the static wheel load, is the same
    number). α_P (the standard's α) = 1 for locomotives and passenger vehicles, 0.85 for freight wagons.

    Parameters
    ----------
    axle_load : float or array_like
        W, the static axle load, N, in [1, 2e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "axle_load").
    factor : float
        α_P, in [0.5, 1].

    Returns
    -------
    float or ndarray
        The limiting ΣY, N.

    Examples
    --------
    >>> prudhomme_limit(120e3)  # 10 + 40 kN
    50000.0
    >>> round(prudhomme_limit(200e3, 0.85))  # a freight wagon: 0.85 × (10 + 66.7) kN
    65167
    """
    P = _checks.plausible_array("axle_load", axle_load, "axle_load", allow_empty=False)
    alpha = _checks.scalar("factor", factor, low=_LOWEST_FACTOR, high=1.0)
    limit = alpha * (10.0e3 + P / 3.0)
    return float(limit) if np.ndim(axle_load) == 0 else limit


def limit_twist(base):
    """The limit twist of the track over a base b_t, m/m: 7 ‰ below 4 m, (20 m/b_t + 2) ‰ to 20 m, 3 ‰ beyond.

    The twist that the EN 14363 (and UIC 530-2) test on twisted track applies over a vehicle's
    bogie wheelbase 2b (the standard's 2a⁺) and over its bogie-centre distance 2l (2a*), as the
    authors recall it from EN 14363:2005 (section on safety against derailment on twisted track)
    and UIC 530-2: it could not be checked here against the text of either standard (neither is
    openly published), so treat it as the usual form, not as a quotation. The three pieces meet at
    4 m (7 ‰) and 20 m (3 ‰).

    Parameters
    ----------
    base : float or array_like
        b_t, the base of the twist, m (> 0).

    Returns
    -------
    float or ndarray
        The limit twist t_w, m/m (× 1000 for ‰).

    Examples
    --------
    >>> round(1e3 * limit_twist(2.56), 3), round(1e3 * limit_twist(19.0), 3)  # the Manchester car
    (7.0, 3.053)
    """
    two_a = _checks.array("base", base, low=0.0, low_open=True, allow_empty=False)
    permille = np.clip(20.0 / two_a + 2.0, 3.0, 7.0)
    return float(1e-3 * permille) if np.ndim(base) == 0 else 1e-3 * permille


def twist_unloading(
    axle_load,
    half_gauge,
    semi_wheelbase,
    semi_bogie_spacing,
    primary_roll_stiffness,
    secondary_roll_stiffness,
    bogie_twist=None,
    car_twist=None,
) -> float:
    """ΔQ/Q₀ of the most unloaded wheel of a car on two two-axle bogies standing on twisted track.

    One rail rises by t_w x relative to the other, x along the track, so a wheelset at x rolls by
    t_w x/(2a) (2a between its contact points). The body and the frames are rigid, each on its
    springs; the body does not roll and the frames roll with the mean of their wheelsets' track, so
    the twist splits into two independent parts (a linear model: they add):

    * over the bogie wheelbase 2b (twist t_w^b): each wheelset rolls ± t_w^b b/(2a) against its frame,
      and its primary roll stiffness k_φp moves ΔQ^b = k_φp t_w^b b/(4a²) between its wheels;
    * over the bogie-centre distance 2l (twist t_w^l): each bogie's track rolls ± t_w^l l/(2a) against
      the body through its two wheelsets' primaries (2 k_φp) in series with its secondary k_φ,
      k = 2k_φp k_φ/(2k_φp + k_φ); the moment k t_w^l l/(2a) is shared by its two wheelsets:
      ΔQ^l = k t_w^l l/(8a²).

    The leading wheel on the falling rail loses both: ΔQ/Q₀ = (ΔQ^b + ΔQ^l)/(W/2). Left out: the
    body's and frames' torsional flexibility, the friction and hysteresis of the suspension, the
    weight's roll moment and the vertical tolerances of a real test (EN 14363 adds them).

    Parameters
    ----------
    axle_load : float
        W, the static axle load, N, in [1, 2e6].
    half_gauge : float
        a, half the distance between the contact points, m, in [0.15, 1.1].
    semi_wheelbase : float
        b, half the bogie wheelbase, m, in [0.01, 100].
    semi_bogie_spacing : float
        l, half the distance between bogie centres, m, in [0.01, 100] and > ``semi_wheelbase``.
    primary_roll_stiffness : float
        k_φp, per wheelset, N·m/rad, in [1e3, 1e9): k_p d², k_p/2 the vertical spring of each
        axlebox at ±d.
    secondary_roll_stiffness : float
        k_φ, per bogie, N·m/rad, in [1e3, 1e9): the secondary vertical springs and any anti-roll
        bar.
    bogie_twist : float, optional
        t_w^b, m/m, in [0, 0.05]; :func:`limit_twist` of 2b if None.
    car_twist : float, optional
        t_w^l, m/m, in [0, 0.05]; :func:`limit_twist` of 2l if None.

    Returns
    -------
    float
        ΔQ/Q₀ (≥ 0; above 1 the wheel would lift).

    Examples
    --------
    The Manchester car (Iwnicki 1998) on the limit twists, 7 ‰ over 2.56 m and 3.05 ‰ over 19 m:

    >>> round(twist_unloading(109054.85, 0.75, 1.28, 9.5, 2.44e6, 1.8e6), 3)
    0.334
    """
    P = _checks.plausible("axle_load", axle_load, "axle_load")
    a = _checks.plausible("half_gauge", half_gauge, "half_gauge")
    b = _checks.plausible("semi_wheelbase", semi_wheelbase, "vehicle_length")
    s = _checks.plausible("semi_bogie_spacing", semi_bogie_spacing, "vehicle_length")
    if s <= b:
        raise ValueError(
            f"semi_bogie_spacing must exceed semi_wheelbase ({b!r} m), got {semi_bogie_spacing!r}"
        )
    k1 = _roll_stiffness("primary_roll_stiffness", primary_roll_stiffness)
    k2 = _roll_stiffness("secondary_roll_stiffness", secondary_roll_stiffness)
    g_bogie = limit_twist(2 * b) if bogie_twist is None else _twist("bogie_twist", bogie_twist)
    g_car = limit_twist(2 * s) if car_twist is None else _twist("car_twist", car_twist)
    bogie = k1 * g_bogie * b / (4 * a**2)
    series = 2 * k1 * k2 / (2 * k1 + k2)
    car = series * g_car * s / (8 * a**2)
    return (bogie + car) / (0.5 * P)


def _roll_stiffness(name: str, value) -> float:
    # N·m/rad: 1 kN·m/rad is a toy's, 1 GN·m/rad a rigid joint's (real suspensions: 0.3 to 10 MN·m/rad)
    return _checks.scalar(name, value, low=1.0e3, high=1.0e9, high_open=True)


def _twist(name: str, value) -> float:
    # 50 ‰ is far beyond any track (the limit twists are 3 ‰ to 7 ‰): a larger number is most likely ‰
    return _checks.scalar(name, value, low=0.0, high=0.05)


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class SafetyAssessment(Tabular):
    """The running-safety criteria of one vehicle through one curve, each with its limit.

    Attributes
    ----------
    speed : float
        V, m/s (> 0).
    radius : float
        R, m (> 0).
    cant : float
        h_t, m (≥ 0).
    cant_deficiency : float
        h_d = G V²/(g R) − h_t on G = 1.5 m, m (negative: a cant excess).
    wheel_quotient : ndarray, (k, 2)
        |Y/Q| of each wheel [inner, outer] of each axle, front to back (≥ 0).
    nadal_limit : float
        Nadal's limit at the contact's flange angle and friction.
    axle_sum : ndarray, (k,)
        Σ|Y/Q| of each axle (≥ 0).
    weinstock_limit : float
        Weinstock's limit: Nadal's plus the friction of the other wheel.
    flange_angle : float
        ϑ_f, the contact's flange angle, rad.
    friction : float
        μ at the flange (and the other wheel), the contact's.
    track_shift_force : ndarray, (k,)
        |ΣY| = |Y_inner + Y_outer| of each axle, N (≥ 0).
    prudhomme_limit : float
        α_P (10 + W/3) kN, N.
    bogie_twist, car_twist : float
        t_w^b over the bogie wheelbase and t_w^l over the bogie-centre distance, m/m.
    twist_unloading : float
        ΔQ/Q₀ of the most unloaded wheel on that twist (≥ 0).
    twist_limit : float
        0.6 (:data:`TWIST_UNLOADING_LIMIT`).
    flexibility : float
        s_φ, the body's roll on its suspension per radian of track roll standing on cant (≥ 0).
    wind_force : float
        F_w, the side wind's force on the vehicle, N (≥ 0), at ``wind_height``, m.
    wind_height : float
        m above the rails (> 0).
    overturning_unloading : float
        ΔQ/Q₀ on the unloaded rail (the inner one under a deficiency, the outer under an excess)
        from a_q, the body's roll and the wind (≥ 0; at 1 the wheels lift).
    overturning_limit : float
        The ΔQ/Q₀ held as overturning, in [0.5, 1].
    overturning_deficiency : float
        The cant deficiency (or excess) at which ``overturning_unloading`` reaches
        ``overturning_limit`` with this wind, m (≥ 0; 0: the wind alone reaches it).
    equilibrium : QuasiStaticCurving
        The quasi-static equilibrium the curve's criteria come from (a nearby assessment's
        ``start``).
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("wheel_quotient", "-"), ("axle_sum", "-"), ("track_shift_force", "N"))
    _scalars = (
        ("speed", "m/s"), ("radius", "m"), ("cant", "m"), ("cant_deficiency", "m"), ("nadal_limit", "-"),
        ("weinstock_limit", "-"), ("prudhomme_limit", "N"),
    )  # fmt: skip

    speed: float
    radius: float
    cant: float
    cant_deficiency: float
    wheel_quotient: np.ndarray
    nadal_limit: float
    axle_sum: np.ndarray
    weinstock_limit: float
    flange_angle: float
    friction: float
    track_shift_force: np.ndarray
    prudhomme_limit: float
    bogie_twist: float
    car_twist: float
    twist_unloading: float
    twist_limit: float
    flexibility: float
    wind_force: float
    wind_height: float
    overturning_unloading: float
    overturning_limit: float
    overturning_deficiency: float
    equilibrium: QuasiStaticCurving

    def __post_init__(self):
        _checks.fields(self)
        _checks.instance("equilibrium", self.equilibrium, QuasiStaticCurving)
        k = _checks.array("wheel_quotient", self.wheel_quotient, shape=(None, 2), low=0.0).shape[0]
        _checks.array("axle_sum", self.axle_sum, shape=(k,), low=0.0)
        _checks.array("track_shift_force", self.track_shift_force, shape=(k,), low=0.0)
        _checks.speed("speed", self.speed)
        for name in ("radius", "nadal_limit", "weinstock_limit", "prudhomme_limit", "twist_limit"):
            _checks.positive(name, getattr(self, name))
        for name in ("cant", "twist_unloading", "flexibility", "wind_force", "overturning_unloading"):
            _checks.nonnegative(name, getattr(self, name))
        _checks.nonnegative("overturning_deficiency", self.overturning_deficiency)
        _checks.positive("wind_height", self.wind_height)
        _checks.scalar("overturning_limit", self.overturning_limit, low=0.5, high=1.0)

    @property
    def criteria(self) -> dict:
        """Each criterion's (value, limit): the worst wheel or axle of the vehicle.

        Keys: ``"Nadal Y/Q"``, ``"Weinstock Σ|Y/Q|"``, ``"Prud'homme ΣY (kN)"``, ``"twist ΔQ/Q₀"``,
        ``"overturning ΔQ/Q₀"``.
        """
        return {
            "Nadal Y/Q": (float(self.wheel_quotient.max()), self.nadal_limit),
            "Weinstock Σ|Y/Q|": (float(self.axle_sum.max()), self.weinstock_limit),
            "Prud'homme ΣY (kN)": (1e-3 * float(self.track_shift_force.max()), 1e-3 * self.prudhomme_limit),
            "twist ΔQ/Q₀": (self.twist_unloading, self.twist_limit),
            "overturning ΔQ/Q₀": (self.overturning_unloading, self.overturning_limit),
        }

    @property
    def utilisation(self) -> dict:
        """Each criterion's value over its limit (≥ 0; above 1 the criterion fails), keyed as
        :attr:`criteria`."""
        return {name: value / limit for name, (value, limit) in self.criteria.items()}

    @property
    def safe(self) -> bool:
        """Whether every criterion stays within its limit."""
        return all(u <= 1.0 for u in self.utilisation.values())

    def plot(self, ax=None, *, artists: dict | None = None) -> dict:
        """Each criterion's utilisation (value over limit) as a bar, with the limit at 1.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        artists : dict, optional
            What an earlier call returned: its artists are updated in place (``ax`` unused).

        Returns
        -------
        dict
            ``bars`` (one rectangle per criterion, top to bottom as :attr:`criteria`), ``labels``
            (one text each, "value / limit") and ``limit`` (the line at 1).
        """
        import matplotlib

        from raildyn import plots

        criteria = self.criteria
        use = [value / limit for value, limit in criteria.values()]
        texts = [f"{value:.3g} / {limit:.3g}" for value, limit in criteria.values()]
        colours = [plots.COLORS[1] if u > 1.0 else plots.COLORS[2] for u in use]
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier plot() returned")
            if len(artists.get("bars", ())) != len(use) or len(artists.get("labels", ())) != len(use):
                raise ValueError(
                    f"artists must come from an earlier SafetyAssessment.plot, got {artists!r:.60}"
                )
            rows = zip(artists["bars"], artists["labels"], use, texts, colours, strict=True)
            for bar, label, u, text, colour in rows:
                bar.set_width(u)
                bar.set_color(colour)
                label.set_x(min(u, 1.9) + 0.03)
                label.set_text(text)
            return artists
        ax = plots.axes_or_new(ax)
        rows = np.arange(len(use))[::-1]
        with matplotlib.rc_context(plots.STYLE):
            bars = ax.barh(rows, use, color=colours, height=0.6)
            labels = [
                ax.text(min(u, 1.9) + 0.03, row, text, va="center", fontsize=8)
                for u, row, text in zip(use, rows, texts, strict=True)
            ]
            limit = ax.axvline(1.0, color="k", ls="--", lw=1.2)
            ax.set_yticks(rows, list(criteria))
            ax.set_xlim(0.0, 2.4)
            ax.set_xlabel("utilisation: value / limit")
        return {"bars": list(bars.patches), "labels": labels, "limit": limit}


def _roll(car: LateralCar, cg_height: float):
    """(s, h_b, denominator) of the body's roll on its secondary suspension: 2k_φ − m_b g h_b > 0."""
    m_b, h_b = car.body_mass, car.body_height
    if h_b >= cg_height:
        raise ValueError(
            f"cg_height must exceed the body's height above its secondary springs, body_height = {h_b!r} m "
            f"(the springs stand above the rails), got {cg_height!r}"
        )
    stiff = 2 * car.roll_stiffness - m_b * GRAVITY * h_b  # > 0: LateralCar checks it
    return m_b * GRAVITY * h_b / stiff, h_b, stiff


def safety_assessment(
    model,
    speed,
    radius,
    cant=0.0,
    *,
    contact=None,
    cg_height=1.8,
    primary_roll_stiffness=MANCHESTER_PRIMARY_ROLL_STIFFNESS,
    factor=1.0,
    wind_force=0.0,
    wind_height=2.0,
    overturning_limit=1.0,
    start=None,
) -> SafetyAssessment:
    """The running safety of a car through a circular curve to the left, every criterion against its limit.

    The curve's criteria come from the quasi-static equilibrium
    (:func:`raildyn.curving.quasi_static.quasi_static_curving`: Y and Q of each wheel, the
    load moved by a_q at ``cg_height``); wheel climb from
    :func:`raildyn.curving.climb.wheel_climb` at the contact's flange angle and friction;
    track shift from :func:`prudhomme_limit` of the car's axle load; twist from
    :func:`twist_unloading` on the :func:`limit_twist` of its wheelbase and bogie spacing; and
    overturning from the moment balance about the unloaded rail, in the track's plane:

        ΔQ/Q₀ = [4W h_g |a_q|/g + m_b g h (φ_a + φ_w) + F_w h_w] / (4aW),

    W the axle load (4W the car's weight), h_g = ``cg_height``, a the half gauge, m_b and h the
    body's mass and height above its secondary springs, and the body's roll on those springs
    φ_a = s_φ |a_q|/g (s_φ = m_b g h/(2k_φ − m_b g h), the flexibility coefficient s of EN 15273: the
    body's roll per radian of track roll standing on cant) and φ_w = F_w (h_w − h_g + h)/(2k_φ − m_b g h)
    from the wind at h_w. The wind is taken to blow towards the unloaded rail; it enters the overturning only
    (not Y, Q or ΣY). Setting ΔQ/Q₀ to ``overturning_limit`` gives the cant deficiency of overturning.

    Parameters
    ----------
    model : LateralCar
        The car (:class:`raildyn.vehicles.LateralCar`): its nonlinear model, masses, heights, roll
        stiffness and axle spacing are used.
    speed : float
        V, m/s, in (0, 200].
    radius : float
        R, m (≥ 50).
    cant : float
        h_t, m, in [0, 0.2].
    contact : WheelRailContact, optional
        The wheel–rail contact (its flange angle and friction are Nadal's); the default
        :class:`~raildyn.wheelset.WheelRailContact` if None.
    cg_height : float
        h_g, the vehicle's centre of gravity above the rails, m, in (``model.body_height``, 4].
    primary_roll_stiffness : float
        k_φp per wheelset, N·m/rad, in [1e3, 1e9); the Manchester car's by default
        (:data:`MANCHESTER_PRIMARY_ROLL_STIFFNESS`): give another car's.
    factor : float
        Prud'homme's α_P, in [0.5, 1]: 1 for locomotives and passenger vehicles, 0.85 for freight.
    wind_force : float
        F_w, the side wind's resultant force on the vehicle, N, in [0, 1e6] (0: no wind).
    wind_height : float
        h_w, its height above the rails, m, in [0.5, 6].
    overturning_limit : float
        The ΔQ/Q₀ on the unloaded rail taken as overturning, in [0.5, 1]: 1 when the wheels lift.
    start : QuasiStaticCurving, optional
        A nearby equilibrium of the same car (a nearby assessment's ``equilibrium``), as for
        :func:`~raildyn.curving.quasi_static.quasi_static_curving`.

    Returns
    -------
    SafetyAssessment

    Raises
    ------
    SolverError
        Where the curve has no quasi-static equilibrium (its inner wheels lifted at ``cg_height``).

    Examples
    --------
    >>> from raildyn.vehicles import LateralCar
    >>> r = safety_assessment(LateralCar(), 100 / 3.6, 600.0, 0.1)
    >>> round(1e3 * r.cant_deficiency), round(r.twist_unloading, 2), round(1e3 * r.overturning_deficiency)
    (97, 0.33, 603)
    """
    car = _checks.instance("model", model, LateralCar)
    V = _checks.speed("speed", speed)
    R = _checks.scalar("radius", radius, low=MINIMUM_RADIUS)
    D = _checks.scalar("cant", cant, low=0.0, high=MAXIMUM_CANT)
    if contact is not None:
        _checks.instance("contact", contact, WheelRailContact)
    h = _checks.scalar("cg_height", cg_height, low=0.0, low_open=True, high=4.0)
    k1 = _roll_stiffness("primary_roll_stiffness", primary_roll_stiffness)
    alpha = _checks.scalar("factor", factor, low=_LOWEST_FACTOR, high=1.0)
    F_w = _checks.scalar("wind_force", wind_force, low=0.0, high=1.0e6)
    h_w = _checks.scalar("wind_height", wind_height, low=0.5, high=6.0)
    limit = _checks.scalar("overturning_limit", overturning_limit, low=0.5, high=1.0)
    s, h_b, stiff = _roll(car, h)
    nonlinear = car.nonlinear(contact)
    state = quasi_static_curving(nonlinear, V, R, D, cg_height=h, start=start)
    ws, bogie = car.wheelset, car.bogie
    flange_angle, mu = nonlinear.contact.flange_angle, nonlinear.contact.friction
    climb = wheel_climb(state.wheel_lateral, state.wheel_vertical, flange_angle, mu)
    P, a = ws.axle_load, ws.half_gauge
    W = 4 * P  # the car's weight on its four axles
    g_bogie, g_car = limit_twist(2 * bogie.semi_wheelbase), limit_twist(2 * car.semi_bogie_spacing)
    twist = twist_unloading(
        P, a, bogie.semi_wheelbase, car.semi_bogie_spacing, k1, car.roll_stiffness, g_bogie, g_car
    )
    m_b = car.body_mass
    # the moment about the unloaded rail per unit a_q (N·m per m/s²), and the wind's (N·m)
    per_acceleration = W * h / GRAVITY + m_b * h_b * s
    wind = F_w * h_w + m_b * GRAVITY * h_b * F_w * (h_w - h + h_b) / stiff
    a_q = abs(state.unbalanced_acceleration)
    unloading = (per_acceleration * a_q + wind) / (a * W)
    tipping = max(0.0, (limit * a * W - wind) / per_acceleration)  # a_q at the limit, m/s²
    return SafetyAssessment(
        speed=V,
        radius=R,
        cant=D,
        cant_deficiency=float(cant_deficiency(V, R, D)),
        wheel_quotient=np.abs(climb.wheel_quotient),
        nadal_limit=climb.nadal_limit,
        axle_sum=np.asarray(climb.axle_sum, dtype=float),
        weinstock_limit=climb.weinstock_limit,
        flange_angle=float(flange_angle),
        friction=float(mu),
        track_shift_force=np.abs(state.wheel_lateral.sum(axis=1)),
        prudhomme_limit=prudhomme_limit(P, alpha),
        bogie_twist=g_bogie,
        car_twist=g_car,
        twist_unloading=twist,
        twist_limit=TWIST_UNLOADING_LIMIT,
        flexibility=s,
        wind_force=F_w,
        wind_height=h_w,
        overturning_unloading=unloading,
        overturning_limit=limit,
        overturning_deficiency=tipping * STANDARD_RAIL_SPACING / GRAVITY,
        equilibrium=state,
    )
