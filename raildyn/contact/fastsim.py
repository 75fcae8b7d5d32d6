"""Kalker's simplified theory of rolling contact and its algorithm FASTSIM, compiled.

The simplified theory replaces the elastic half-space by a bed of independent
springs: the tangential displacement at a point is the local traction times a
flexibility L. Rolling turns the no-slip condition into ∂p/∂x = w/L along each
strip of the contact ellipse parallel to the rolling direction, integrated from
the leading edge; wherever the traction would exceed μp_z it is capped and the
point slides (Kalker 1982). With one flexibility per creepage,

    L₁ = 8a/(3C₁₁G),   L₂ = 8a/(3C₂₂G),   L₃ = πa√(a/b)/(4C₂₃G),

the total forces at small creepage equal Kalker's linear theory for γ_x, γ_y and φ.

:func:`fastsim` checks its input and prepares each state with numpy (flexibilities,
pressure, scaling of huge creepages), then marches the cells of every state in a
numba-compiled loop (``raildyn.contact._fastsim_kernel``): on 20 × 20 cells, the
march takes about 0.8 µs per contact and a whole call on a large batch about 1.6 µs.
Each step uses the exact increment of the adhesion solution over the cell, and the
cells are evaluated at their midpoints, so that in full adhesion the forces are exact
along x and accurate to O((1/n_y)²) across.

The same march in numpy (``_fastsim_numpy``) and cell by cell in plain Python
(:func:`~raildyn.contact.fastsim_python.fastsim_reference`), which the tests hold the kernel to,
are in :mod:`raildyn.contact.fastsim_python`.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.constants import STEEL_POISSON_RATIO, STEEL_SHEAR_MODULUS
from raildyn.contact.kalker import _ratio, kalker_coefficients

# Imported where used, to keep this module's import cheap (tests/test_imports.py): numba,
# raildyn.contact._fastsim_kernel

__all__ = ["FastsimResult", "Flexibilities", "fastsim", "flexibilities"]


@dataclass(frozen=True)
class FastsimResult(Tabular):
    """Forces and (optionally) the fields over the contact ellipse from FASTSIM.

    Shapes: the forces have the broadcast shape S of the inputs; the fields
    have shape S + (n_y, n_x), strips along the last-but-one axis (y) and
    cells along the rolling direction x in the last axis (from the leading
    edge x = +a(y) to the trailing edge).

    Attributes
    ----------
    fx, fy : float or ndarray
        Creep forces on the wheel (N), sign convention of :mod:`raildyn.contact.kalker`.
    mz : float or ndarray
        Spin moment about the contact normal (N m).
    x, y : ndarray or None
        Cell centres (m).
    px, py : ndarray or None
        Tangential traction (Pa).
    pz : ndarray or None
        Normal pressure of the simplified theory, p₀(1 − x²/a² − y²/b²), p₀ ≈ 2N/(πab) (Pa).
    slip_x, slip_y : ndarray or None
        Local slip (dimensionless, creepage units): zero in the adhesion zone.
    adhesion : ndarray of bool or None
        True where the cell sticks.
    normal_load : float or ndarray or None
        N (N) of each state.
    friction : float or ndarray or None
        μ of each state.
    a, b : float or ndarray or None
        Semi-axes of each state's ellipse (m).

    The fields (``x`` to ``adhesion``) are all given or all None; given, they share one
    non-empty shape S + (n_y, n_x), and ``adhesion`` holds bools.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units;
    # a row per state; the fields over the ellipse (two more axes) are no columns.
    _columns = (("fx", "N"), ("fy", "N"), ("mz", "N m"))

    fx: np.ndarray | float
    fy: np.ndarray | float
    mz: np.ndarray | float
    x: np.ndarray | None = None
    y: np.ndarray | None = None
    px: np.ndarray | None = None
    py: np.ndarray | None = None
    pz: np.ndarray | None = None
    slip_x: np.ndarray | None = None
    slip_y: np.ndarray | None = None
    adhesion: np.ndarray | None = None
    normal_load: np.ndarray | float | None = None
    friction: np.ndarray | float | None = None
    a: np.ndarray | float | None = None
    b: np.ndarray | float | None = None

    def __post_init__(self):
        _checks.fields(self, flags=("adhesion",))
        grids = {k: getattr(self, k) for k in ("x", "y", "px", "py", "pz", "slip_x", "slip_y", "adhesion")}
        missing = [k for k, v in grids.items() if v is None]
        if missing and len(missing) < len(grids):
            given = next(k for k in grids if k not in missing)
            raise ValueError(
                f"{missing[0]} must be given with {given} (the fields of fastsim come together), got None"
            )
        if missing:
            return
        shape = np.shape(self.x)
        if len(shape) < 2 or 0 in shape:
            raise ValueError(f"x must be a non-empty array of shape S + (n_y, n_x), got shape {shape}")
        for k, v in grids.items():
            if np.shape(v) != shape:
                raise ValueError(f"x and {k} must have one shape, got {shape} and {np.shape(v)}")
        if np.asarray(self.adhesion).dtype != bool:
            raise TypeError(
                f"adhesion must be an array of bool (True where the cell sticks), got {self.adhesion!r:.80}"
            )

    @property
    def adhesion_fraction(self):
        """Share of the contact area that sticks (area-weighted)."""
        if self.adhesion is None:
            raise ValueError("run fastsim(..., fields=True) to get the adhesion zone")
        dx = np.abs(self.x[..., 0:1] - self.x[..., 1:2]) if self.x.shape[-1] > 1 else np.ones_like(self.x)
        weight = np.broadcast_to(dx, self.adhesion.shape)
        return (weight * self.adhesion).sum(axis=(-2, -1)) / weight.sum(axis=(-2, -1))

    @property
    def friction_utilisation(self):
        """|F|/(μN) = √(Fx² + Fy²)/(μN): the share of the friction limit in use, between 0 and 1."""
        if self.friction is None or self.normal_load is None:
            raise ValueError(
                "this result does not hold the friction and the normal load it was computed with"
            )
        value = np.hypot(self.fx, self.fy) / (np.asarray(self.friction) * np.asarray(self.normal_load))
        return float(value) if np.ndim(value) == 0 else value

    def plot_patch(self, ax=None, *, artists=None) -> dict:
        """Draw one state's contact patch: adhesion and slip cells, and the traction as arrows.

        The arrows are scaled so that μp₀ spans a third of the semi-axis b; x
        (the rolling direction, leading edge at the right) and y are in mm.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        artists : dict, optional
            The dict a previous call returned: the cells and arrows move to this
            result (same grid size) instead of being drawn again, as a widget does.

        Returns
        -------
        dict
            ``stick`` and ``slip`` (scatter collections), ``arrows`` (a quiver)
            and ``outline`` (the ellipse).
        """
        if self.adhesion is None or self.adhesion.ndim != 2 or self.friction is None:
            raise ValueError("plot_patch needs the fields of one contact state: fastsim(..., fields=True)")
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict returned by an earlier plot_patch")
        xy = np.c_[1e3 * self.x.ravel(), 1e3 * self.y.ravel()]
        sticks = self.adhesion.ravel()
        b_mm = 1e3 * float(self.b)
        k = b_mm / 3.0 / max(float(self.friction) * float(self.pz.max()), 1.0)
        u, v = k * self.px.ravel(), k * self.py.ravel()
        if artists is None:
            import matplotlib

            from raildyn import plots

            ax = plots.axes_or_new(ax)
            t = np.linspace(0.0, 2.0 * math.pi, 200)
            with matplotlib.rc_context(plots.STYLE):
                (outline,) = ax.plot(1e3 * float(self.a) * np.cos(t), b_mm * np.sin(t), color="0.4", lw=1)
                stick = ax.scatter([], [], s=14, color=plots.COLORS[0], label="adhesion")
                slip = ax.scatter([], [], s=14, color=plots.COLORS[1], label="slip")
                arrows = ax.quiver(
                    xy[:, 0], xy[:, 1], u, v, angles="xy", scale_units="xy", scale=1.0, width=0.004
                )
                ax.set_aspect("equal")
                ax.set_xlabel("x, rolling direction (mm) — leading edge at right")
                ax.set_ylabel("y (mm)")
                ax.legend(loc="upper left", ncol=2)
            artists = {"stick": stick, "slip": slip, "arrows": arrows, "outline": outline}
        artists["stick"].set_offsets(xy[sticks] if sticks.any() else np.empty((0, 2)))
        artists["slip"].set_offsets(xy[~sticks] if (~sticks).any() else np.empty((0, 2)))
        artists["arrows"].set_offsets(xy)
        artists["arrows"].set_UVC(u, v)
        return artists


@dataclass(frozen=True)
class Flexibilities:
    """Kalker's flexibilities of the simplified theory, m/Pa (:func:`flexibilities`).

    Attributes
    ----------
    l1 : float or ndarray
        L₁ = 8a/(3C₁₁G), longitudinal.
    l2 : float or ndarray
        L₂ = 8a/(3C₂₂G), lateral.
    l3 : float or ndarray
        L₃ = πa√(a/b)/(4C₂₃G), spin.
    """

    l1: np.ndarray | float
    l2: np.ndarray | float
    l3: np.ndarray | float

    def __post_init__(self):
        _checks.fields(self)


def flexibilities(
    a, b, shear_modulus=STEEL_SHEAR_MODULUS, poisson_ratio=STEEL_POISSON_RATIO
) -> Flexibilities:
    """Kalker's flexibilities L₁, L₂, L₃ that make FASTSIM match the linear theory.

    L₁ = 8a/(3C₁₁G), L₂ = 8a/(3C₂₂G), L₃ = πa√(a/b)/(4C₂₃G) (Kalker 1982, 1990).

    Parameters
    ----------
    a, b : float or array_like
        Semi-axes (m), each in [1e-5, 0.05] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "contact_semi_axis"), a in the rolling direction; 0.1 <= a/b <= 10.
    shear_modulus : float
        G (Pa), > 0; :data:`raildyn.constants.STEEL_SHEAR_MODULUS` by default.
    poisson_ratio : float
        ν in [0, 0.5]; :data:`raildyn.constants.STEEL_POISSON_RATIO` by default.

    Returns
    -------
    Flexibilities
        L₁, L₂, L₃ in m/Pa, of the broadcast shape of ``a`` and ``b``.

    Examples
    --------
    >>> f = flexibilities(6e-3, 6e-3, 8.1e10, 0.25)  # a circle: C₁₁ = 4.12
    >>> round(f.l1 * 1e14, 4)  # 8a/(3 C₁₁ G), 1e-14 m/Pa
    4.7944
    """
    a = _checks.plausible_array("a", a, "contact_semi_axis")
    b = _checks.plausible_array("b", b, "contact_semi_axis")
    g = _checks.positive("shear_modulus", shear_modulus)
    c = kalker_coefficients(_ratio(a, b), poisson_ratio)

    def out(v):
        return float(v) if np.ndim(v) == 0 else v

    return Flexibilities(
        l1=out(8 * a / (3 * c.c11 * g)),
        l2=out(8 * a / (3 * c.c22 * g)),
        l3=out(np.pi * a * np.sqrt(a / b) / (4 * c.c23 * g)),
    )


_CELLS_MAX = 1000  # cells per strip and strips: the error, O(1/n²), is then far below the theory's own
# States per thread below which a batch is marched on the calling thread alone: starting numba's
# threads costs a few µs, the march of a few states, and far more (a time slice of the system,
# milliseconds) when other processes hold the cores, a risk worth taking only for a large batch.
_STATES_PER_THREAD = 64
_SLIDING = 1e12  # creepage, in units of the one of full sliding, beyond which creepages are scaled down


def _within_sliding(xi, eta, phi, a, b, l1, l2, l3, bound):
    """γ_x, γ_y, φ scaled down together (direction kept) to at most 1e12 times the size of full sliding.

    The rigid-slip traction grows over the patch by |γ_x|a_c/L₁, |γ_y|a_c/L₂ and |φ|max(a_c, b_c)a_c/L₃; past
    ``bound`` (μp₀) every cell slides along the rigid slip, so the forces depend on the creepages'
    ratios only and the scaling changes them by ~1/_SLIDING, while no traction rate can overflow.
    """
    size = np.maximum(np.maximum(np.abs(xi), np.abs(eta)), np.abs(phi) * np.maximum(a, b))
    safe = np.where(size > 0, size, 1.0)
    # Growth across the patch in units of the bound, per unit of ``size``: finite, moderate.
    growth = np.maximum(
        np.maximum(np.abs(xi) / safe * (a / (l1 * bound)), np.abs(eta) / safe * (a / (l2 * bound))),
        np.abs(phi) * np.maximum(a, b) / safe * (a / (l3 * bound)),
    )
    with np.errstate(over="ignore", divide="ignore"):  # an inf here means "far from sliding": no scaling
        target = _SLIDING / growth  # the size at which the patch slides _SLIDING times over
        factor = np.where(size > target, target / safe, 1.0)
    return xi * factor, eta * factor, phi * factor


def fastsim(
    longitudinal,
    lateral,
    spin,
    normal_load,
    friction,
    a,
    b,
    shear_modulus=STEEL_SHEAR_MODULUS,
    poisson_ratio=STEEL_POISSON_RATIO,
    *,
    n_x: int = 20,
    n_y: int = 20,
    fields: bool = True,
) -> FastsimResult:
    """Creep forces and traction over the ellipse by Kalker's FASTSIM (simplified theory).

    Parameters
    ----------
    longitudinal, lateral : float or array_like
        Creepages γ_x, γ_y (dimensionless).
    spin : float or array_like
        Spin creepage φ (1/m).
    normal_load : float or array_like
        N (N), in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_load").
    friction : float or array_like
        μ, in (0, 1] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "friction").
    a, b : float or array_like
        Semi-axes (m), each in [1e-5, 0.05] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "contact_semi_axis"): a in the rolling direction; 0.1 ≤ a/b ≤ 10.
    shear_modulus : float
        G (Pa); :data:`raildyn.constants.STEEL_SHEAR_MODULUS` by default.
    poisson_ratio : float
        ν in [0, 0.5]; :data:`raildyn.constants.STEEL_POISSON_RATIO` by default.
    n_x, n_y : int, keyword
        Cells per strip and number of strips, 2 to 1000: the forces converge as 1/n², so that
        1000 is far past any accuracy the simplified theory has (a few per cent).
    fields : bool, keyword
        Keep the traction and slip fields (memory S × n_y × n_x per field).

    Notes
    -----
    Past full sliding the forces depend on the direction of the creepages only (every cell
    slides along the rigid slip): creepages beyond 10¹² times the size that makes the
    patch slide are scaled down together to that size, which changes the forces by less
    than 1e-9 of μN and keeps every traction rate finite, however large the creepage.

    The cells are marched in compiled code, the states of a batch shared among numba's
    threads (``numba.set_num_threads`` sets how many); each state is marched by one thread
    in a fixed order, so the result does not depend on their number.

    Returns
    -------
    FastsimResult
        All inputs broadcast together; a batch of states is one call. With
        ``fields`` and a single state, ``.plot_patch(ax)`` draws the patch.

    Examples
    --------
    >>> r = fastsim(1e-4, 0.0, 0.0, 1e5, 0.3, 6e-3, 6e-3)
    >>> r.fx < 0 and bool(r.adhesion.any())
    True
    """
    import numba

    from raildyn.contact import _fastsim_kernel

    state = _prepare(
        longitudinal,
        lateral,
        spin,
        normal_load,
        friction,
        a,
        b,
        shear_modulus,
        poisson_ratio,
        n_x,
        n_y,
        fields,
    )
    shape = state.xi.shape
    per_state = (state.xi, state.eta, state.phi, state.a, state.b, state.l1, state.l2, state.l3, state.limit)
    flat = [np.ascontiguousarray(v).reshape(-1) for v in per_state]
    n_states = flat[0].size
    forces = np.empty((3, n_states))
    if state.fields:
        out = np.empty((5, n_states, state.n_y, state.n_x))
        stick = np.empty((n_states, state.n_y, state.n_x), dtype=bool)
    else:
        out = stick = None
    # All of numba's threads or none: a parallel loop starts them all, and an idle one can keep the
    # others waiting for it when the machine is busy.
    threads = numba.get_num_threads()
    common = (*flat, state.eta_y, state.root, state.shape_by_cell, forces, out, stick)
    if threads > 1 and n_states >= threads * _STATES_PER_THREAD:
        _fastsim_kernel.march_parallel(*common, threads)
    else:
        _fastsim_kernel.march(*common)
    fx, fy, mz = (v.reshape(shape) for v in forces)
    if not state.fields:
        return _result(state, fx, fy, mz)
    grid = shape + (state.n_y, state.n_x)
    x, px, py, slip_x, slip_y = (v.reshape(grid) for v in out)
    return _result(state, fx, fy, mz, x=x, px=px, py=py, slip_x=slip_x, slip_y=slip_y,
                   adhesion=stick.reshape(grid))  # fmt: skip


@dataclass(frozen=True)
class _State:
    """The checked, broadcast input of :func:`fastsim` with what every march needs (shape S each)."""

    xi: np.ndarray  # creepages, huge ones scaled down by _within_sliding
    eta: np.ndarray
    phi: np.ndarray
    load: np.ndarray
    mu: np.ndarray
    a: np.ndarray
    b: np.ndarray
    l1: np.ndarray
    l2: np.ndarray
    l3: np.ndarray
    p0: np.ndarray  # peak pressure (Pa)
    limit: np.ndarray  # μp₀ (Pa), inf for an absurd μ
    eta_y: np.ndarray  # (n_y,): y/b of each strip
    root: np.ndarray  # (n_y,): √(1 − (y/b)²)
    shape: np.ndarray  # (n_y, n_x): pressure shape p_z/p₀ of each cell
    shape_by_cell: np.ndarray  # its transpose (n_x, n_y), contiguous: the kernel's order
    n_x: int
    n_y: int
    fields: bool


@functools.lru_cache(maxsize=16)
def _grid(n_x: int, n_y: int):
    """Strips, the pressure shape of each cell and its grid integral (→ π/2), read-only."""
    # Strips: midpoints of n_y equal bands across the ellipse.
    eta_y = (np.arange(n_y) + 0.5) / n_y * 2.0 - 1.0  # y/b
    root = np.sqrt(1.0 - eta_y**2)  # a(y)/a, half-length of each strip
    x_rel = root[:, None] * (1.0 - (np.arange(n_x) + 0.5) * 2.0 / n_x)
    shape = np.clip(1.0 - x_rel**2 - eta_y[:, None] ** 2, 0.0, None)
    area = (shape * (2.0 * root / n_x)[:, None]).sum() * 2.0 / n_y
    by_cell = np.ascontiguousarray(shape.T)
    for v in (eta_y, root, shape, by_cell):
        v.flags.writeable = False
    return eta_y, root, shape, by_cell, area


def _prepare(
    longitudinal, lateral, spin, normal_load, friction, a, b, shear_modulus, poisson_ratio, n_x, n_y, fields
) -> _State:
    """Check fastsim's input and compute the flexibilities, the pressure and the scaled creepages."""
    xi = _checks.array("longitudinal", longitudinal, allow_empty=False)
    eta = _checks.array("lateral", lateral, allow_empty=False)
    phi = _checks.array("spin", spin, allow_empty=False)
    load = _checks.plausible_array("normal_load", normal_load, "wheel_load")
    mu = _checks.plausible_array("friction", friction, "friction", low=0.0, low_open=True)
    a = _checks.plausible_array("a", a, "contact_semi_axis")
    b = _checks.plausible_array("b", b, "contact_semi_axis")
    g_mod = _checks.positive("shear_modulus", shear_modulus)
    n_x = _checks.integer("n_x", n_x, low=2, high=_CELLS_MAX)
    n_y = _checks.integer("n_y", n_y, low=2, high=_CELLS_MAX)
    fields = _checks.flag("fields", fields)
    flex = flexibilities(a, b, g_mod, poisson_ratio)
    xi, eta, phi, load, mu, a, b, l1, l2, l3 = np.broadcast_arrays(
        xi, eta, phi, load, mu, a, b, flex.l1, flex.l2, flex.l3
    )
    eta_y, root, shape, by_cell, grid_area = _grid(n_x, n_y)
    # Peak of the parabolic pressure of the simplified theory, 2N/(πab) in the continuum; here scaled
    # so that the pressure summed over the grid is exactly N, which makes full sliding give exactly μN.
    p0 = load / (a * b * grid_area)
    with np.errstate(over="ignore"):  # μp₀ = inf for an absurd μ: nothing slides, which is what it means
        limit = mu * p0
    xi, eta, phi = _within_sliding(xi, eta, phi, a, b, l1, l2, l3, limit)
    return _State(
        xi, eta, phi, load, mu, a, b, l1, l2, l3, p0, limit, eta_y, root, shape, by_cell, n_x, n_y, fields
    )


def _result(state: _State, fx, fy, mz, **fields) -> FastsimResult:
    """The FastsimResult of a march: forces of shape S, and the fields if given (with y and p_z added)."""

    def scalar_or(v):
        return float(v) if np.ndim(v) == 0 else v

    kept = {k: scalar_or(getattr(state, k)) for k in ("load", "mu", "a", "b")}
    result = {"normal_load": kept["load"], "friction": kept["mu"], "a": kept["a"], "b": kept["b"]}
    if fields:
        e = (..., None)
        grid = fields["x"].shape
        fields["y"] = np.broadcast_to((state.b[e] * state.eta_y)[..., None], grid).copy()
        fields["pz"] = state.p0[e][e] * state.shape
    return FastsimResult(scalar_or(fx), scalar_or(fy), scalar_or(mz), **result, **fields)
