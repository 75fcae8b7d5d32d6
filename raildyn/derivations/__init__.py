"""Equations of motion derived symbolically (sympy), one module per chapter's models.

Each function returns a :class:`Derivation`: the matrices M, C, K, G_K, G_C of a raildyn model
derived from energies and forces (Lagrange's equations, :func:`lagrange`), the steps a notebook
shows, and the map from each symbol to the model's parameter. The tests lambdify the derived
matrices and hold them to the model's ``matrices(speed)`` over random parameter sets, so a reader
sees that the code implements exactly the equations derived. Derivations are cached: the first
call does the algebra, later calls are free.

One module per chapter's models: :mod:`~raildyn.derivations.vibration` (chapter 1),
:mod:`~raildyn.derivations.contact` (4), :mod:`~raildyn.derivations.wheelset` (5),
:mod:`~raildyn.derivations.vertical` (6), :mod:`~raildyn.derivations.lateral` and
:mod:`~raildyn.derivations.trucks` (7), :mod:`~raildyn.derivations.curving` (8),
:mod:`~raildyn.derivations.train` (9) and :mod:`~raildyn.derivations.bridge` (10).

sympy is imported only when this package is, never by the numerical models.
"""

from raildyn.derivations._core import Derivation, Step, coordinates, generalized_forces, lagrange
from raildyn.derivations._core import time as time
from raildyn.derivations.vibration import chain, sdof

# ``time`` (the symbol t every coordinate is a function of) is importable from here but not listed:
# it is sympy's own symbol, whose docstring is sympy's.
__all__ = ["Derivation", "Step", "chain", "coordinates", "generalized_forces", "lagrange", "sdof"]
