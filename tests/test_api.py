"""The public surface of raildyn: ``__all__`` everywhere, the API page in step with it, numpydoc docstrings.

What counts as public (decided here, once):

* every module under ``raildyn/`` whose dotted name has no part starting with ``_``,
  the package ``raildyn`` itself included;
* except the figure plug-ins ``raildyn.figures.chNN``: they only register figures
  with :mod:`raildyn.figures` and are reached through ``figures.make``/``figures.show``
  and ``python -m raildyn figures``, never imported by name, so the API page
  documents the registry (``raildyn.figures``) and not them;
* the widget modules ``raildyn.widgets.chapterNN`` *are* public: the API page
  documents them, and their factories are what the notebooks call.
  ``raildyn.__main__`` starts with an underscore and is the command line, documented
  by ``python -m raildyn --help``.

Checks:

a. every public module defines ``__all__``, a list of distinct names it really has;
b. the modules the API page (``book/api.md``) documents with ``automodule`` are exactly
   the public modules with public names, and every name in each ``__all__`` is
   documented there: the object it names appears under ``:members:`` of some
   ``automodule`` (its own module's, or a package's that exports it, or for a name
   a package re-exports, the defining module's);
c. numpydoc's own validation reports, for every public function and method, no
   undocumented parameter (PR01), no unknown documented parameter (PR02) and, for
   code that returns something, no missing Returns section (RT01);
d. the main entry point of each chapter has an ``Examples`` section that runs.
"""

from __future__ import annotations

import doctest
import importlib
import inspect
import pkgutil
import re
from pathlib import Path

import numpydoc.validate
import pytest

import raildyn

ROOT = Path(__file__).resolve().parents[1]
API_PAGE = ROOT / "book" / "api.md"
CODES = ("PR01", "PR02", "RT01")

# The main entry point of each chapter whose models live in these modules: its docstring has an
# Examples section, which runs here (and under pytest's --doctest-modules).
MAIN_ENTRY_POINTS = [
    # chapter 1
    "raildyn.vibration.SDOF",
    "raildyn.vibration.SDOF.free_vibration",
    "raildyn.vibration.modal_analysis",
    "raildyn.vibration.complex_modes",
    "raildyn.random_vibration.response_psd",
    "raildyn.random_vibration.synthesize",
    # chapter 2
    "raildyn.integrators.integrate",
    "raildyn.integrators.newmark",
    "raildyn.integrators.rk4",
    # chapter 3
    "raildyn.track.fra_psd",
    "raildyn.track.german_psd",
    "raildyn.track.band_variance",
    "raildyn.track.synthesize_irregularity",
    "raildyn.track.synthesize_track",
    "raildyn.track.jointed_track",
    # chapter 4
    "raildyn.contact.hertz_contact",
    "raildyn.contact.creep_coefficients",
    "raildyn.contact.polach",
    "raildyn.contact.fastsim",
    "raildyn.contact.contact_geometry",
    "raildyn.contact.lateral_creep_curves",
    # chapter 5
    "raildyn.wheelset.kinematic_wavelength",
    "raildyn.wheelset.Wheelset.linear_system",
    # chapters 5–7: the one protocol of every linear model
    "raildyn.linear_model.Assembler",
    # chapter 6 (vehicle response, ride comfort)
    "raildyn.vehicles.time_domain.periodic_profile",
    "raildyn.ride.ride_quality",
    # chapter 7
    "raildyn.stability.mode_sweep",
    "raildyn.stability.critical_speed",
    "raildyn.stability.limit_cycle_amplitude",
    # chapter 9
    "raildyn.train.braking_model",
    "raildyn.train.simulate",
    "raildyn.train.TrainModel.quasi_static",
]


def _is_private(name: str) -> bool:
    return any(part.startswith("_") for part in name.split("."))


def _is_figure_plugin(name: str) -> bool:
    return re.fullmatch(r"raildyn\.figures\.ch\d+", name) is not None


def _public_module_names() -> list[str]:
    names = ["raildyn"]
    for info in pkgutil.walk_packages(raildyn.__path__, "raildyn."):
        if not _is_private(info.name) and not _is_figure_plugin(info.name):
            names.append(info.name)
    return sorted(names)


PUBLIC = _public_module_names()


def _module(name: str):
    return importlib.import_module(name)


def _public_names(module) -> list[str]:
    """``__all__``, or (for a module still without one) the names it defines that do not start with ``_``."""
    if hasattr(module, "__all__"):
        return list(module.__all__)
    return [
        n
        for n, obj in vars(module).items()
        if not n.startswith("_") and getattr(obj, "__module__", None) == module.__name__
    ]


def _api_page() -> dict[str, set[str] | None]:
    """Module name → names documented by its ``automodule`` (None: all of ``__all__``; empty: none).

    ``:members:`` with a list documents those names; ``.. autodata:: module.NAME`` (and
    ``autofunction``, ``autoclass``, ``autoexception``) after the module's ``automodule``
    documents one more.
    """
    documented: dict[str, set[str] | None] = {}
    current = None
    for line in API_PAGE.read_text(encoding="utf-8").splitlines():
        single = re.match(r"\s*\.\. auto(?:data|function|class|exception)::\s+(\S+)\.(\w+)\s*$", line)
        if single:  # one object documented on its own (module-level data without a docstring)
            module_name, name = single.groups()
            assert documented.get(module_name) is not None, f"auto… for {module_name} before its automodule"
            documented[module_name].add(name)
            current = None
            continue
        directive = re.match(r"\s*\.\. automodule::\s+(\S+)", line)
        if directive:
            current = directive.group(1)
            assert current not in documented, f"{current} has two automodule directives on the API page"
            documented[current] = set()
            continue
        members = re.match(r"\s+:members:(.*)$", line)
        if members and current is not None:
            listed = [m.strip() for m in members.group(1).split(",") if m.strip()]
            documented[current] = set(listed) if listed else None
        elif not line.startswith(" "):
            current = None
    return documented


def _documented_names(module_name: str, page: dict) -> set[str]:
    entry = page.get(module_name, set())
    if entry is None:
        return set(_public_names(_module(module_name)))
    return entry


def _documented_objects(page: dict) -> set[int]:
    """Identities of every object some ``automodule`` of the page documents."""
    found = set()
    for module_name in page:
        module = _module(module_name)
        found |= {id(getattr(module, n)) for n in _documented_names(module_name, page) if hasattr(module, n)}
    return found


# --------------------------------------------------------------------------- a. __all__


@pytest.mark.parametrize("name", PUBLIC)
def test_every_public_module_defines_all(name):
    module = _module(name)
    assert hasattr(module, "__all__"), f"{name} defines no __all__"
    names = list(module.__all__)
    assert all(isinstance(n, str) for n in names), f"{name}.__all__ holds a non-string"
    assert len(set(names)) == len(names), f"{name}.__all__ repeats a name"
    missing = [n for n in names if not hasattr(module, n)]
    assert not missing, f"{name}.__all__ names what the module does not have: {missing}"


# --------------------------------------------------------------------------- b. the API page


def test_api_page_documents_exactly_the_public_modules_with_public_names():
    page = _api_page()
    with_names = {name for name in PUBLIC if _public_names(_module(name))}
    assert set(page) - set(PUBLIC) == set(), "the API page documents modules that are not public ones"
    assert with_names - set(page) == set(), "public modules with public names missing from the API page"
    assert set(page) - with_names == set(), "the API page documents public modules without public names"


@pytest.mark.parametrize("name", PUBLIC)
def test_every_public_name_is_on_the_api_page(name):
    page = _api_page()
    module = _module(name)
    documented = _documented_objects(page)
    missing = [
        public
        for public in module.__all__
        if public not in _documented_names(name, page) and id(getattr(module, public)) not in documented
    ]
    assert not missing, f"{name}: {missing} are in __all__ but not documented on book/api.md"


# --------------------------------------------------------------------------- c. numpydoc


def _targets(module) -> list[str]:
    """Dotted names of the public functions and methods defined in ``module``."""
    out = []
    for public in _public_names(module):
        obj = getattr(module, public)
        if getattr(obj, "__module__", None) != module.__name__:
            continue  # validated in the module that defines it
        if inspect.isfunction(obj):
            out.append(f"{module.__name__}.{public}")
        elif inspect.isclass(obj):
            for attr, member in vars(obj).items():
                if attr.startswith("_"):
                    continue
                if inspect.isfunction(member) or isinstance(member, (classmethod, staticmethod)):
                    out.append(f"{module.__name__}.{public}.{attr}")
    return out


@pytest.mark.parametrize("name", PUBLIC)
def test_numpydoc_parameters_and_returns(name):
    problems = []
    for target in _targets(_module(name)):
        report = numpydoc.validate.validate(target)
        problems += [f"{target}: {code} {text}" for code, text in report["errors"] if code in CODES]
    assert not problems, "\n".join(problems)


def test_the_numpydoc_check_catches_what_it_should():
    # A function missing its parameters and its Returns must be reported, or the check above proves nothing.
    errors = {code for code, _ in numpydoc.validate.validate("tests.test_api._undocumented")["errors"]}
    assert {"PR01", "RT01"} <= errors


def _undocumented(a, b):
    """Add two numbers."""
    return a + b


# --------------------------------------------------------------------------- d. examples that run


def _resolve(dotted: str):
    """The object a dotted name reaches by attribute access from the top package.

    (``raildyn.contact.fastsim`` is the function the package exports, not the module of that name.)
    """
    parts = dotted.split(".")
    obj = importlib.import_module(parts[0])
    for i, attr in enumerate(parts[1:], start=2):
        try:
            obj = getattr(obj, attr)
        except AttributeError:
            obj = importlib.import_module(".".join(parts[:i]))
    return obj


@pytest.mark.parametrize("dotted", MAIN_ENTRY_POINTS)
def test_main_entry_points_have_examples_that_run(dotted):
    obj = _resolve(dotted)
    examples = numpydoc.validate.Validator(numpydoc.validate.get_doc_object(obj)).examples
    assert examples and any(">>>" in line for line in examples), f"{dotted} has no Examples with >>>"
    home = importlib.import_module(obj.__module__)
    tests = doctest.DocTestFinder(recurse=False).find(obj, dotted, globs=dict(vars(home)))
    assert tests and tests[0].examples, f"{dotted}: no doctest found"
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    for test in tests:
        runner.run(test)
    assert runner.failures == 0, f"{dotted}: {runner.failures} example(s) failed"
