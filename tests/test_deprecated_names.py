"""The names issue 33 renamed: each old one still works for one issue, warns, and is no longer public.

Every old module attribute, reached through each module and package that exported it, gives the very
object of its new name with a ``DeprecationWarning`` that names the new name, and is absent from that
module's ``__all__`` (where the new name is). SDOF's old method name gives the new method's result.
These are the only calls of the old names in the repository (pytest turns any other into an error).
"""

from __future__ import annotations

import importlib
import inspect

import numpy as np
import pytest

from raildyn import _deprecated

# (module, old name, new name): every old name written out here, independently of raildyn._deprecated.
OLD_NAMES = [
    ("raildyn.vehicles", "Car", "LateralCar"),
    ("raildyn.vehicles.lateral", "Car", "LateralCar"),
    ("raildyn.vehicles", "FreightCar", "VerticalFreightCar"),
    ("raildyn.vehicles.freight", "FreightCar", "VerticalFreightCar"),
    ("raildyn.vehicles", "Locomotive", "VerticalLocomotive"),
    ("raildyn.vehicles.locomotive", "Locomotive", "VerticalLocomotive"),
    ("raildyn.bridge", "moving_force", "moving_force_response"),
    ("raildyn.bridge.beam", "moving_force", "moving_force_response"),
    ("raildyn.bridge", "moving_forces", "moving_load"),
    ("raildyn.bridge.loads", "moving_forces", "moving_load"),
    ("raildyn.vibration", "state_space", "state_space_matrices"),
    ("raildyn.vibration.damped", "state_space", "state_space_matrices"),
    ("raildyn.vibration.mdof", "state_space", "state_space_matrices"),  # a re-export kept since the move
]
IDS = [f"{module}.{old}" for module, old, _ in OLD_NAMES]


@pytest.mark.parametrize(("module_name", "old", "new"), OLD_NAMES, ids=IDS)
def test_an_old_name_warns_and_gives_the_new_object(module_name, old, new):
    module = importlib.import_module(module_name)
    with pytest.warns(DeprecationWarning, match=rf"^{module_name}\.{old} is deprecated; use {new}$"):
        value = getattr(module, old)
    assert value is getattr(module, new)


@pytest.mark.parametrize(("module_name", "old", "new"), OLD_NAMES, ids=IDS)
def test_an_old_name_imports_with_the_warning(module_name, old, new):
    namespace: dict = {}
    with pytest.warns(DeprecationWarning, match=new):
        exec(f"from {module_name} import {old}", namespace)  # the statement a caller writes
    assert namespace[old] is getattr(importlib.import_module(module_name), new)


@pytest.mark.parametrize(("module_name", "old", "new"), OLD_NAMES, ids=IDS)
def test_an_old_name_is_not_public(module_name, old, new):
    module = importlib.import_module(module_name)
    assert old not in module.__all__
    assert old not in vars(module)  # only __getattr__ serves it
    if module_name != "raildyn.vibration.mdof":  # mdof re-exports the moved functions outside __all__
        assert new in module.__all__


def test_the_table_of_old_names_is_the_one_tested_here():
    table = {(m, old, new) for m, names in _deprecated.RENAMED.items() for old, new in names.items()}
    assert table == set(OLD_NAMES)


def test_other_missing_names_are_still_attribute_errors():
    vehicles = importlib.import_module("raildyn.vehicles")
    with pytest.raises(AttributeError, match="raildyn.vehicles.*has no attribute 'Carriage'"):
        vehicles.Carriage  # noqa: B018
    assert not hasattr(vehicles, "Carriage")
    with pytest.raises(ImportError):
        exec("from raildyn.bridge import moving_mass_response", {})


def test_the_old_method_name_warns_and_gives_the_new_result():
    from raildyn.vibration import SDOF

    oscillator = SDOF(2.0, 0.4, 8.0)
    with pytest.warns(
        DeprecationWarning, match=r"^SDOF\.state_space is deprecated; use SDOF\.state_space_matrices$"
    ):
        old = oscillator.state_space()
    new = oscillator.state_space_matrices()
    for field in ("A", "B", "C", "D"):
        np.testing.assert_array_equal(getattr(old, field), getattr(new, field))


def test_the_old_method_name_is_not_a_public_method():
    from raildyn.vibration import SDOF

    # Not a function of the class: the API checks and the fuzz registry enumerate functions only.
    assert not inspect.isfunction(inspect.getattr_static(SDOF, "state_space"))
    assert isinstance(inspect.getattr_static(SDOF, "state_space"), _deprecated.renamed_method)
