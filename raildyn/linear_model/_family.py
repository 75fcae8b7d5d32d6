"""A family of linear models affine in some parameters: the matrices of many members without assembling each.

Part of :mod:`raildyn.linear_model` (see its docstring); import :class:`AffineFamily` from there.
The batched critical-speed search of :mod:`raildyn.stability.search` takes its stacks.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn.linear_model._protocol import as_linear_system

__all__ = ["AffineFamily"]

_NAMES = ("M", "C0", "C1", "K")


class AffineFamily:
    """The matrices M, C₀, C₁ and K of ``make(*p)`` for many parameter vectors p at once.

    A model's matrices are often affine in the parameters a study moves: in the conicity (the
    creep stiffness 2af₁₁λ/r₀, and the gravitational stiffnesses Wε/a and −Waϑ₀ whose ε and ϑ₀
    follow λ: :func:`raildyn.wheelset.creep_terms`) and in each spring, with no product of two
    of them. Then A(p) = A(p₀) + Σᵢ (pᵢ − p₀ᵢ) ∂A/∂pᵢ, each slope from one assembly at ``origin``
    moved to ``far`` in that parameter alone: a sweep over many points assembles the model
    2 + len(p) times. The point halfway between ``origin`` and ``far`` checks the plane to
    round-off (1e-12 of each matrix): it sees both a curve along one parameter and a product
    of two. Where the check fails, ``affine`` is False and every point is assembled.

    Parameters
    ----------
    make : callable
        ``make(*p)`` returns a linear model (or its :class:`~raildyn.linear_model.LinearSystem`)
        for a parameter vector p (each parameter in its own unit); every member has the same
        coordinates.
    origin : array_like, (k,)
        p₀, the point the plane is built about (finite, at least one parameter).
    far : array_like, (k,)
        The point each parameter is moved to, alone, for its slope (finite; each entry differs
        from ``origin``'s). Put ``origin`` and ``far`` at the corners of the range to be swept.

    Attributes
    ----------
    affine : bool
        Whether the matrices are affine in p (the halfway check passed).
    assembled : dict
        Each point assembled here (a tuple) and its :class:`~raildyn.linear_model.LinearSystem`.

    Raises
    ------
    ValueError, TypeError
        If ``make`` fails at one of the points assembled (the point is named), or returns models
        of different sizes.

    Examples
    --------
    >>> from raildyn.wheelset import Wheelset
    >>> def wheelset(lam, k):
    ...     return Wheelset(conicity=lam, yaw_stiffness=k, lateral_stiffness=1e6)
    >>> family = AffineFamily(wheelset, (0.05, 1e6), (0.4, 5e6))
    >>> family.affine, family.constant("M"), family.stacks([(0.1, 2e6), (0.2, 3e6)])["K"].shape
    (True, True, (2, 2, 2))
    """

    def __init__(self, make, origin, far):
        self.make = _checks.function("make", make)
        self.origin = _checks.array("origin", np.atleast_1d(origin), ndim=1, allow_empty=False).copy()
        far = _checks.array("far", np.atleast_1d(far), shape=self.origin.shape)
        if np.any(far == self.origin):
            raise ValueError(f"far must differ from origin in every parameter, got {far} and {self.origin}")
        self.assembled = {}
        base = self._assemble(self.origin, "origin")
        self.base = {n: getattr(base, n) for n in _NAMES}
        self.slopes = []
        for i in range(self.origin.size):
            p = self.origin.copy()
            p[i] = far[i]
            moved = self._assemble(p, f"origin with parameter {i} moved to far")
            self.slopes.append(
                {n: (getattr(moved, n) - self.base[n]) / (far[i] - self.origin[i]) for n in _NAMES}
            )
        middle = 0.5 * (self.origin + far)
        check = self._assemble(middle, "halfway between origin and far")
        guess = self._plane(middle[None])
        self.affine = all(
            np.abs(guess[n][0] - getattr(check, n)).max() <= 1e-12 * np.abs(getattr(check, n)).max()
            for n in _NAMES
        )

    def _assemble(self, p: np.ndarray, where: str):
        """The system of ``make(*p)``, kept in :attr:`assembled`; a failure names the point (``where``)."""
        key = tuple(p.tolist())
        if key not in self.assembled:
            try:
                system = as_linear_system(self.make(*p))
            except (ValueError, TypeError) as err:
                kind = ValueError if isinstance(err, ValueError) else TypeError
                raise kind(f"make failed at {where}, {key}: {err}") from err
            if self.assembled and system.size != next(iter(self.assembled.values())).size:
                raise ValueError(
                    f"make must return models of one size, got {system.size} coordinates at {where}, {key}"
                )
            self.assembled[key] = system
        return self.assembled[key]

    def _plane(self, points: np.ndarray) -> dict:
        step = points - self.origin
        return {
            n: self.base[n] + sum(step[:, i, None, None] * slope[n] for i, slope in enumerate(self.slopes))
            for n in _NAMES
        }

    def constant(self, name: str) -> bool:
        """Whether one matrix stays put as every parameter moves (False for a family that is not affine).

        Parameters
        ----------
        name : {"M", "C0", "C1", "K"}
            The matrix.

        Returns
        -------
        bool
        """
        _checks.choice("name", name, _NAMES)
        return self.affine and not any(np.any(slope[name]) for slope in self.slopes)

    def stacks(self, points) -> dict:
        """The matrices of the members at many points: from the plane when affine, else each assembled.

        Parameters
        ----------
        points : array_like, (m, k)
            Parameter vectors, one per row (finite; a single vector (k,) is one row). A point
            far outside ``origin``–``far`` is as exact as one inside when the family is affine.

        Returns
        -------
        dict
            ``{"M", "C0", "C1", "K"}``, each an ndarray (m, n, n) in the units of
            :class:`~raildyn.linear_model.LinearSystem`: keyword arguments for
            :class:`raildyn.stability.StateMatrices`.
        """
        k = self.origin.size
        points = _checks.array("points", np.atleast_2d(points), shape=(None, k), allow_empty=False)
        if self.affine:
            return self._plane(points)
        systems = [self._member(p) for p in points]
        return {n: np.stack([getattr(s, n) for s in systems]) for n in _NAMES}

    def _member(self, p):
        try:
            return as_linear_system(self.make(*p))
        except (ValueError, TypeError) as err:
            kind = ValueError if isinstance(err, ValueError) else TypeError
            raise kind(f"make failed at points row {tuple(p.tolist())}: {err}") from err
