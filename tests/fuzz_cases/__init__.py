"""The fuzz test's registry: one valid call for every public callable of raildyn.

Each module here holds ``ENTRIES``, the entries of one part of the package (see
``tests/fuzzing.py`` for what an entry is and what the test does with it). A new public
function, class or method needs an entry in the module of its part, or the fuzz test fails.
"""

from __future__ import annotations

import importlib
import pkgutil

from fuzzing import Entry


def entries() -> list[Entry]:
    """Every entry of every module of the registry."""
    found: list[Entry] = []
    for info in pkgutil.iter_modules(__path__):
        found.extend(importlib.import_module(f"{__name__}.{info.name}").ENTRIES)
    return found
