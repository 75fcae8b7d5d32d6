"""The protocol every linear model follows (:class:`LinearModel`), its base (:class:`LinearModelBase`) and
:func:`as_linear_system`.

Part of :mod:`raildyn.linear_model` (see its docstring); import the names from there.
"""

from __future__ import annotations

from dataclasses import replace as _dataclass_replace
from typing import Protocol, runtime_checkable

from raildyn import _checks
from raildyn.linear_model._system import LinearSystem, SystemMatrices

__all__ = ["LinearModel", "LinearModelBase", "as_linear_system"]


@runtime_checkable
class LinearModel(Protocol):
    """What every linear model of raildyn offers (see the module docstring).

    A parameter set (a frozen dataclass) becomes a linear model by defining
    ``linear_system()`` and inheriting :class:`LinearModelBase`, which supplies
    the rest from it.
    """

    def linear_system(self) -> LinearSystem:
        """The assembled equations of motion with their track inputs."""
        ...

    def matrices(self, speed) -> SystemMatrices:
        """M, C(V), K, G_K, G_C at speed V.

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].

        Returns
        -------
        SystemMatrices
        """
        ...

    def state_space(self, speed, outputs=None, derivative: int = 0):
        """A ``control.StateSpace`` from the track inputs to the outputs at speed V.

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
        outputs : sequence, optional
            Output specifications (coordinate labels by default).
        derivative : {0, 1, 2}
            Displacement, velocity or acceleration outputs.

        Returns
        -------
        control.StateSpace
        """
        ...

    def replace(self, **changes) -> LinearModel:
        """A validated copy with some parameters changed.

        Parameters
        ----------
        **changes
            Parameter names and their new values.

        Returns
        -------
        LinearModel
        """
        ...


class LinearModelBase:
    """The protocol's methods for a frozen-dataclass parameter set that defines ``linear_system()``."""

    def __init__(self):
        # Only the base itself: every model is a dataclass whose generated __init__ replaces this one,
        # so that a stray argument is refused by name.
        pass

    def linear_system(self) -> LinearSystem:  # pragma: no cover - every subclass defines it
        """The assembled equations; defined by each model.

        Returns
        -------
        LinearSystem
        """
        raise NotImplementedError

    def matrices(self, speed) -> SystemMatrices:
        """M, C(V), K, G_K, G_C at the speed V.

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].

        Returns
        -------
        SystemMatrices
        """
        return self.linear_system().matrices(speed)

    def state_space(self, speed, outputs=None, derivative: int = 0):
        """The model at speed V as a ``control.StateSpace`` (see :meth:`LinearSystem.state_space`).

        Parameters
        ----------
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
        outputs : sequence, optional
            Output specifications (coordinate labels by default).
        derivative : {0, 1, 2}
            Displacement, velocity or acceleration outputs.

        Returns
        -------
        control.StateSpace
        """
        return self.linear_system().state_space(speed, outputs, derivative)

    def replace(self, **changes):
        """A copy with some fields changed, validated again by the dataclass.

        Parameters
        ----------
        **changes
            Field names and their new values.

        Returns
        -------
        The same type as the model.
        """
        return _dataclass_replace(self, **changes)


def as_linear_system(model) -> LinearSystem:
    """The :class:`LinearSystem` of a linear model, or the system itself.

    Parameters
    ----------
    model : LinearModel or LinearSystem

    Returns
    -------
    LinearSystem

    Raises
    ------
    TypeError
        If ``model`` does not follow :class:`LinearModel`.
    """
    if isinstance(model, LinearSystem):
        return model
    _checks.not_a_class("model", model, "a linear model")
    if isinstance(model, LinearModel):
        system = model.linear_system()
        if isinstance(system, LinearSystem):
            return system
        raise TypeError(
            f"model.linear_system() must return a LinearSystem, got {type(system).__name__} "
            f"(model of type {type(model).__name__})"
        )
    raise TypeError(f"model must be a raildyn linear model (LinearModel), got {type(model).__name__}")
