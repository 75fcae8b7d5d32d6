"""The public surface of raildyn.train: ``__all__`` in every module, numpydoc sections, examples."""

import dataclasses
import importlib
import inspect
import pkgutil

import pytest
from numpydoc.docscrape import NumpyDocString
from numpydoc.validate import validate

import raildyn.train

MODULES = ["raildyn.train"] + [
    f"raildyn.train.{m.name}"
    for m in pkgutil.iter_modules(raildyn.train.__path__)
    if not m.name.startswith("_")
]


def _public_objects():
    """(import path, object) of every public function, class, method and property of raildyn.train."""
    out = {}
    for name in MODULES[1:]:
        module = importlib.import_module(name)
        for attr in module.__all__:
            obj = getattr(module, attr)
            if not (inspect.isfunction(obj) or inspect.isclass(obj)):
                continue
            out[f"{name}.{attr}"] = obj
            if inspect.isclass(obj):
                for key, member in vars(obj).items():
                    if not key.startswith("_") and (
                        inspect.isfunction(member)
                        or isinstance(member, property | classmethod | staticmethod)
                    ):
                        out[f"{name}.{attr}.{key}"] = member
    return out


PUBLIC = _public_objects()


@pytest.mark.parametrize("name", MODULES)
def test_every_module_declares_all_and_it_is_complete(name):
    module = importlib.import_module(name)
    assert hasattr(module, "__all__"), f"{name} has no __all__"
    for attr in module.__all__:
        assert hasattr(module, attr), f"{name}.__all__ names {attr}, which it does not define"
    # Every public function or class defined here is listed.
    defined = {
        attr
        for attr, obj in vars(module).items()
        if not attr.startswith("_")
        and (inspect.isfunction(obj) or inspect.isclass(obj))
        and obj.__module__ == name
    }
    assert defined <= set(module.__all__), defined - set(module.__all__)


def test_package_exports_the_modules_main_names():
    for name in MODULES[1:]:
        module = importlib.import_module(name)
        for attr in module.__all__:
            if attr in raildyn.train.__all__:
                assert getattr(raildyn.train, attr) is getattr(module, attr)


@pytest.mark.parametrize("path", sorted(PUBLIC))
def test_numpydoc_parameters_and_returns(path):
    obj = PUBLIC[path]
    errors = {code: message for code, message in validate(path)["errors"]}
    assert "GL08" not in errors, f"{path}: no docstring"
    if inspect.isclass(obj) and dataclasses.is_dataclass(obj):
        # A result dataclass may document its fields as Attributes rather than Parameters.
        doc = NumpyDocString(inspect.getdoc(obj))
        documented = {n.strip() for p in doc["Parameters"] + doc["Attributes"] for n in p.name.split(",")}
        fields = {f.name for f in dataclasses.fields(obj) if f.init}
        assert fields <= documented, f"{path}: fields {fields - documented} not documented"
        return
    for code in ("PR01", "PR02", "RT01", "RT03"):
        if code == "RT01" and isinstance(obj, property):
            continue  # a property's summary line says what it is
        assert code not in errors, f"{path}: {errors.get(code)}"


@pytest.mark.parametrize(
    "path",
    [
        "raildyn.train.longitudinal.braking_model",
        "raildyn.train.longitudinal.simulate",
        "raildyn.train.model.TrainModel.rhs",
        "raildyn.train.model.TrainModel.quasi_static",
        "raildyn.train.model.TrainModel.balancing_speed",
        "raildyn.train.vehicles.make_consist",
        "raildyn.train.resistance.davis_resistance",
        "raildyn.train.lateral.coupler_effects",
        "raildyn.train.lateral.limiting_coupler_force",
    ],
)
def test_main_entry_points_have_examples(path):
    # pytest runs every docstring example of raildyn/ as a doctest (--doctest-modules).
    doc = NumpyDocString(inspect.getdoc(PUBLIC[path]))
    assert any(">>>" in line for line in doc["Examples"]), f"{path} has no Examples section"
