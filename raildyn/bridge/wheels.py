"""What rides on the rail: one wheel and its Hertz contact, or a vertical vehicle on its wheels (ch. 3, 10).

:func:`raildyn.bridge.impact.wheel_on_track` needs what stands above the rail as one linear block (the
wheels' unsprung masses and whatever their springs carry; coordinates up positive, measured from the
static state on a rigid rail), where its wheels touch, their static loads and their Hertz constants:
a :class:`WheelBlock`. A :class:`Wheel` gives one wheel with, optionally, a share of the vehicle on a
primary spring; :class:`VehicleWheels` gives any vertical vehicle of :mod:`raildyn.vehicles`, its
model's inputs (the rails under its axles) become wheels of their own.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn.constants import GRAVITY

__all__ = ["VehicleWheels", "Wheel", "WheelBlock"]


@dataclass(frozen=True)
class Wheel:
    """One wheel, its share of the vehicle, and its Hertz contact with the rail.

    Attributes
    ----------
    unsprung_mass : float
        m_w, kg: half a wheelset with its axleboxes, in [10, 1e6]. Default 906.5 kg (half the 1813 kg
        wheelset of the Manchester benchmark car, Iwnicki 1998).
    static_load : float
        Q₀, the wheel's static load, N, in [1, 1e6] and > m_s g. Default 54.5 kN (the Manchester car,
        32 t body, two 2.615 t bogies and four wheelsets, on eight wheels).
    sprung_mass : float
        m_s, kg, the share of the vehicle above the primary suspension that moves with this wheel (≥ 0;
        0: the static load alone, no sprung mass). Default 0.
    primary_stiffness, primary_damping : float
        k₁ (N/m) and c₁ (N·s/m) of one wheel's primary suspension (≥ 0; both 0 without a sprung mass).
    wheel_radius : float
        m, in [0.1, 1.5]. Default 0.46 m.
    rail_head_radius : float
        The rail head's transverse radius, m (≥ 0.05). Default 0.3 m (UIC 60's crown).
    """

    unsprung_mass: float = 1813.0 / 2
    static_load: float = (32000.0 + 2 * 2615.0 + 4 * 1813.0) * GRAVITY / 8
    sprung_mass: float = 0.0
    primary_stiffness: float = 0.0
    primary_damping: float = 0.0
    wheel_radius: float = 0.46
    rail_head_radius: float = 0.3

    def __post_init__(self):
        _checks.plausible("unsprung_mass", self.unsprung_mass, "mass")
        _checks.plausible("static_load", self.static_load, "wheel_load")
        for name in ("sprung_mass", "primary_stiffness", "primary_damping"):
            _checks.nonnegative(name, getattr(self, name))
        _checks.plausible("wheel_radius", self.wheel_radius, "wheel_radius")
        _checks.scalar("rail_head_radius", self.rail_head_radius, low=0.05)
        if self.sprung_mass * GRAVITY >= self.static_load:
            raise ValueError(
                f"sprung_mass must weigh less than static_load ({self.static_load!r} N), "
                f"got {self.sprung_mass!r} kg"
            )
        if self.sprung_mass > 0.0 and self.primary_stiffness == 0.0:
            raise ValueError("primary_stiffness must be > 0 to carry a sprung mass, got 0.0")

    @property
    def hertz_constant(self) -> float:
        """C_H of F = C_H u_N^{3/2}, N/m^{3/2}, by :func:`raildyn.contact.hertz.hertz_contact` at Q₀."""
        return _hertz_constant(self.static_load, self.wheel_radius, self.rail_head_radius)

    @property
    def contact_stiffness(self) -> float:
        """k_H = dF/du_N at the static load, (3/2) C_H^{2/3} Q₀^{1/3}, N/m."""
        return 1.5 * self.hertz_constant ** (2 / 3) * self.static_load ** (1 / 3)

    def receptance(self, frequencies) -> np.ndarray:
        """The wheel's own receptance at the contact, m/N (complex): its motion per unit force on it.

        Parameters
        ----------
        frequencies : array_like
            f, Hz, each > 0.

        Returns
        -------
        ndarray of complex
        """
        f = _checks.array("frequencies", frequencies, ndim=1, low=0.0, low_open=True, allow_empty=False)
        if f.max() > 1e4:
            raise ValueError(f"frequencies must be at most 10000 Hz, got {f.max()!r}")
        w = 2 * np.pi * f
        dynamic = -self.unsprung_mass * w**2 + 0j
        if self.sprung_mass > 0.0:
            spring = self.primary_stiffness + 1j * w * self.primary_damping
            dynamic += spring * (-self.sprung_mass * w**2) / (spring - self.sprung_mass * w**2)
        return 1.0 / dynamic

    def block(self) -> WheelBlock:
        """The wheel (and its sprung mass) as the linear block above the contact.

        Returns
        -------
        WheelBlock
            Coordinates [wheel] or [wheel, sprung mass], up positive.
        """
        one = np.array([[1.0, -1.0], [-1.0, 1.0]])
        if self.sprung_mass > 0.0:
            mass = np.diag([self.unsprung_mass, self.sprung_mass])
            stiffness, damping = self.primary_stiffness * one, self.primary_damping * one
        else:
            mass, stiffness, damping = np.array([[self.unsprung_mass]]), np.zeros((1, 1)), np.zeros((1, 1))
        return WheelBlock(mass, damping, stiffness, np.array([0]), np.array([self.static_load]),
                          np.zeros(1), np.array([self.hertz_constant]))  # fmt: skip


@dataclass(frozen=True, eq=False)
class WheelBlock:
    """What rides on the rail: a linear block (the wheels' unsprung masses and all above them) and where
    its wheels touch; coordinates up positive, from the static state on a rigid rail.

    Attributes
    ----------
    mass, damping, stiffness : ndarray, (n, n)
        kg, N·s/m, N/m (and rotations' units): symmetric, the mass positive definite.
    contact_dofs : ndarray of int, (w,)
        The coordinate of each wheel (its height).
    static_loads : ndarray, (w,)
        Q₀ of each wheel on the rail, N (> 0).
    offsets : ndarray, (w,)
        Each wheel's distance behind the leading one, m (≥ 0; the first 0).
    hertz_constants : ndarray, (w,)
        C_H of each wheel, N/m^{3/2} (> 0).
    """

    mass: np.ndarray
    damping: np.ndarray
    stiffness: np.ndarray
    contact_dofs: np.ndarray
    static_loads: np.ndarray
    offsets: np.ndarray
    hertz_constants: np.ndarray

    def __post_init__(self):
        m = _checks.square_matrix("mass", self.mass)
        n = m.shape[0]
        for name in ("damping", "stiffness"):
            _checks.array(name, getattr(self, name), shape=(n, n))
        try:
            np.linalg.cholesky(m)
        except np.linalg.LinAlgError:
            raise ValueError(
                f"mass must be positive definite, got eigenvalues {np.linalg.eigvalsh(m)}"
            ) from None
        dofs = np.asarray(self.contact_dofs)
        if dofs.dtype.kind not in "iu" or dofs.ndim != 1 or dofs.size == 0:
            raise TypeError(f"contact_dofs must be a non-empty 1-D array of integers, got {dofs!r:.80}")
        if dofs.min() < 0 or dofs.max() >= n or np.unique(dofs).size != dofs.size:
            raise ValueError(
                f"contact_dofs must be distinct coordinates in [0, {n - 1}], got {dofs.tolist()}"
            )
        w = dofs.size
        _checks.array("static_loads", self.static_loads, shape=(w,), low=0.0, low_open=True)
        offsets = _checks.array("offsets", self.offsets, shape=(w,), low=0.0)
        if offsets[0] != 0.0:
            raise ValueError(f"offsets must start at 0 (the leading wheel), got {offsets[0]!r}")
        _checks.array("hertz_constants", self.hertz_constants, shape=(w,), low=0.0, low_open=True)


@dataclass(frozen=True)
class VehicleWheels:
    """A vertical vehicle of :mod:`raildyn.vehicles` on its wheels, over one rail: its
    :meth:`block` is the vehicle's linear model with a wheel's unsprung mass under each of its inputs.

    The vehicle's model takes the rails' heights under its axles as inputs, through its primary (or,
    for a three-piece truck, its only) suspension; here each input is the height of a wheel instead,
    a mass of its own resting on the rail through its Hertz spring. The vehicle being symmetric and the
    rails alike, one rail carries half of it: masses, springs and dampers halved; a model with a left
    and a right input under an axle has them move together (bounce and pitch, no roll).

    Attributes
    ----------
    vehicle : object
        A vehicle with ``linear_system()`` whose system records its inputs' own stiffness (every vertical
        vehicle of :mod:`raildyn.vehicles`: ``VerticalCar``, ``VerticalLocomotive``, ``VerticalFreightCar``).
    wheelset_mass : float
        kg, in [10, 1e6]. Default 1813 kg (the Manchester car's wheelset, Iwnicki 1998).
    wheel_radius : float
        m, in [0.1, 1.5]. Default 0.46 m.
    rail_head_radius : float
        m (≥ 0.05). Default 0.3 m.
    """

    vehicle: object
    wheelset_mass: float = 1813.0
    wheel_radius: float = 0.46
    rail_head_radius: float = 0.3

    def __post_init__(self):
        _checks.not_a_class("vehicle", self.vehicle, "a vertical vehicle")
        if not callable(getattr(self.vehicle, "linear_system", None)):
            raise TypeError(f"vehicle must have a linear_system(), got {type(self.vehicle).__name__}")
        _checks.plausible("wheelset_mass", self.wheelset_mass, "mass")
        _checks.plausible("wheel_radius", self.wheel_radius, "wheel_radius")
        _checks.scalar("rail_head_radius", self.rail_head_radius, low=0.05)

    def block(self) -> WheelBlock:
        """The vehicle's half and its wheels: [vehicle coordinates, wheel heights] (:class:`WheelBlock`).

        Returns
        -------
        WheelBlock

        Raises
        ------
        ValueError
            If the vehicle's system does not record its inputs' own stiffness, or its speed-dependent
            damping is not zero (a lateral model).
        """
        s = self.vehicle.linear_system()
        if s.input_stiffness is None or np.any(s.C1 != 0.0) or s.n_inputs == 0:
            raise ValueError("vehicle must be a vertical model whose inputs are the rails under its axles")
        # Inputs at one position (a left and a right rail) become one wheel on this rail: both rails move
        # alike, so their columns add (exact for the symmetric motion a single rail can drive).
        offsets, group = np.unique(np.asarray(s.input_positions, dtype=float), return_inverse=True)
        merge = np.zeros((s.n_inputs, offsets.size))
        merge[np.arange(s.n_inputs), group] = 1.0
        n, q = s.size, offsets.size
        mw = 0.5 * self.wheelset_mass
        mass = np.zeros((n + q, n + q))
        mass[:n, :n], mass[n:, n:] = 0.5 * s.M, mw * np.eye(q)
        parts = []
        for own, inputs, wheels in ((s.C0, s.GC, s.input_damping), (s.K, s.GK, s.input_stiffness)):
            m = np.zeros((n + q, n + q))
            m[:n, :n], m[:n, n:], m[n:, n:] = own, inputs @ merge, merge.T @ wheels @ merge
            m[n:, :n] = m[:n, n:].T
            m[:n, n:] *= -1.0
            m[n:, :n] *= -1.0
            parts.append(0.5 * m)
        # Each wheel's static load: its own weight and what the suspension passes down at rest on rigid rails.
        at_rest = np.linalg.solve(s.K, s.gravity_load)
        loads = mw * GRAVITY - 0.5 * (at_rest @ s.GK @ merge)
        hertz = [_hertz_constant(load, self.wheel_radius, self.rail_head_radius) for load in loads]
        return WheelBlock(mass, parts[0], parts[1], n + np.arange(q), loads, offsets, np.array(hertz))


def _hertz_constant(load, wheel_radius, rail_head_radius) -> float:
    """C_H = Q₀/u_N^{3/2}, u_N the Hertz approach at the load Q₀ (raildyn.contact.hertz.hertz_contact)."""
    from raildyn.contact import hertz_contact

    return load / hertz_contact(load, wheel_radius, math.inf, rail_head_radius).approach ** 1.5
