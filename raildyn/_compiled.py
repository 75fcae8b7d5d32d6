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

Importing a model must not load numba (a third of a second; ``tests/test_imports.py``), so a formula
defined before numba is loaded waits in a queue, and :func:`ready` hands the queue to numba before it
compiles anything: numba calls it itself, as the ``numba_extensions`` entry point that
``pyproject.toml`` declares (numba runs every such entry point ahead of its first compilation in a
process). A formula defined once numba is loaded is handed over at once.

Part of raildyn's ground floor (with ``_numbers``, ``_checks`` and ``_progress``): every package may
import it.
"""

from __future__ import annotations

import inspect
import sys
from collections.abc import Callable

__all__ = ["compiled_as", "formula", "ready"]

# Registrations waiting for numba to be loaded: see the module's docstring.
_PENDING: list[Callable[[], None]] = []


def _with_numba(register: Callable[[], None]) -> None:
    """Run ``register`` now if numba is loaded (after any waiting before it), else when :func:`ready` runs."""
    _PENDING.append(register)
    if "numba" in sys.modules:
        ready()


def ready() -> None:
    """Hand every formula defined so far to numba (numba's entry point: see the module's docstring)."""
    while _PENDING:
        _PENDING.pop(0)()


def formula(fn: Callable) -> Callable:
    """Mark ``fn`` as a formula: unchanged for Python, compiled where a numba function calls it."""

    def register():
        from numba.extending import register_jitable

        register_jitable(fn)

    _with_numba(register)
    return fn


def compiled_as(law: Callable) -> Callable[[Callable], Callable]:
    """Decorate a public, checked function so that numba callers compile ``law`` in its place.

    ``law`` (a :func:`formula`) takes the public function's parameters, by the same names and in
    the same order.
    """
    formula(law)

    def decorate(public: Callable) -> Callable:
        if list(inspect.signature(public).parameters) != list(inspect.signature(law).parameters):
            raise TypeError(
                f"{public.__name__} and its formula {law.__name__} must take the same parameters, got "
                f"{inspect.signature(public)} and {inspect.signature(law)}"
            )

        def implementation(*args):
            return law

        # numba matches the typing function's signature to the implementation's
        implementation.__signature__ = inspect.signature(law)

        def register():
            from numba.extending import overload

            overload(public)(implementation)

        _with_numba(register)
        return public

    return decorate
