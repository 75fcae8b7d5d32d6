"""One formula, two callers: a checked Python function whose compiled callers get the formula itself.

A law that both numpy code and a numba kernel evaluate is written once, as a *formula*: a plain
function of numbers built from numpy's ufuncs (``np.minimum``, ``np.hypot``, ``np.sin`` …), which
numpy evaluates on arrays and numba compiles for floats. :func:`compiled_as` ties it to a public
function that checks its arguments and then calls the formula: Python callers meet the checks,
while a numba function that calls the public name compiles the formula in its place, without the
checks, which it cannot run and its own caller has already made. This is how the creep saturation
(:func:`raildyn.contact.saturation.saturation_scale`), the creepages
(:func:`raildyn.contact.creepages.creepage_terms`) and the curve's ramp
(:func:`raildyn.track.curve.ramp`) reach the compiled wheel–rail engine of :mod:`raildyn.wheelset`.

Part of raildyn's ground floor (with ``_numbers``, ``_checks`` and ``_progress``): every package may
import it.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable

from numba.extending import overload, register_jitable

__all__ = ["compiled_as", "formula"]


def formula(fn: Callable) -> Callable:
    """Mark ``fn`` as a formula: unchanged for Python, compiled where a numba function calls it."""
    return register_jitable(fn)


def compiled_as(law: Callable) -> Callable[[Callable], Callable]:
    """Decorate a public, checked function so that numba callers compile ``law`` in its place.

    ``law`` (a :func:`formula`) takes the public function's parameters, by the same names and in
    the same order.
    """
    jitted = formula(law)

    def decorate(public: Callable) -> Callable:
        if list(inspect.signature(public).parameters) != list(inspect.signature(law).parameters):
            raise TypeError(
                f"{public.__name__} and its formula {law.__name__} must take the same parameters, got "
                f"{inspect.signature(public)} and {inspect.signature(law)}"
            )

        def implementation(*args):
            return jitted

        # numba matches the typing function's signature to the implementation's
        implementation.__signature__ = inspect.signature(law)
        overload(public)(implementation)
        return public

    return decorate
