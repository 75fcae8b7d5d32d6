"""The nonlinear protocol: what every nonlinear model of raildyn offers, beside the linear protocol of
:mod:`raildyn.linear_model`.

* :class:`~raildyn.wheelset.NonlinearModel`: ``rhs(t, state, speed)``, the speed given at the call as
  in the linear protocol; ``replace(**changes)``; ``state_size`` and ``lateral_index``; and
  ``compiled_reason``, which says whether the compiled engine runs the model, or why not;
* :class:`~raildyn.wheelset.CompiledRHS`: a model at one speed as the compiled runner of
  :mod:`raildyn.integrators.runner` takes it.

The models are :class:`~raildyn.wheelset.NonlinearLateral` and its case
:class:`~raildyn.wheelset.NonlinearWheelset` (:mod:`raildyn.wheelset.nonlinear`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np

from raildyn import _checks

__all__ = ["CompiledRHS", "NonlinearModel"]


@runtime_checkable
class NonlinearModel(Protocol):
    """What every nonlinear model of raildyn offers: the protocol beside the linear one.

    :mod:`raildyn.stability` and :mod:`raildyn.curving` run any object that has these; the models
    of raildyn are :class:`NonlinearLateral` and its case :class:`NonlinearWheelset`.

    Attributes
    ----------
    state_size : int
        The length of the state [q; q̇].
    lateral_index : int
        The state entry of the first wheelset's lateral displacement (followed in hunting studies).
    compiled_reason : str or None
        None where the compiled engine runs the whole model; otherwise why it does not (a Python
        force law, a contact function other than a cone or tables), and the model runs on numpy.
    """

    state_size: int
    lateral_index: int
    compiled_reason: str | None

    def rhs(self, t, state, speed):
        """d/dt of the state at time t and speed V.

        Parameters
        ----------
        t : float
            s, finite.
        state : ndarray, (state_size,) or (state_size, k)
            Finite.
        speed : float
            V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].

        Returns
        -------
        ndarray, like ``state``
        """
        ...

    def replace(self, **changes):
        """A validated copy with some fields changed.

        Parameters
        ----------
        **changes
            Field names and their new values.

        Returns
        -------
        NonlinearModel
        """
        ...


@dataclass(frozen=True)
class CompiledRHS:
    """A nonlinear model at one speed, as the compiled runner takes it.

    Attributes
    ----------
    kernel : numba function
        The compiled right-hand side ``kernel(t, state, member, data, out)`` of
        :data:`raildyn.integrators.runner.RHS_SIGNATURE`.
    row : ndarray, (m,)
        The model's row of ``data``: its matrices, wheelsets, contact and curve, and the speed.
    stacked : numba function or None
        The same right-hand side on each column of a stacked state, compiled to the same signature, the
        last row of ``data`` laying the stack out ([n, the data row of column 0, of column 1, ...]);
        None where the model gives none (the shooting then builds one around ``kernel``).
    """

    kernel: object
    row: np.ndarray
    stacked: object = None

    def __post_init__(self):
        import numba.core.registry

        for name in ("kernel", "stacked"):
            value = getattr(self, name)
            if name == "stacked" and value is None:
                continue
            if not isinstance(value, numba.core.registry.CPUDispatcher):
                raise TypeError(
                    f"{name} must be a numba function compiled to raildyn.integrators.runner.RHS_SIGNATURE, "
                    f"got {value!r:.80}"
                )
        object.__setattr__(self, "row", _checks.array("row", self.row, shape=(None,), allow_empty=False))
