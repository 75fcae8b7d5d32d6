"""The package's shape, as ARCHITECTURE.md describes it: read from the code's own imports (every import,
a function's lazy one included) and line counts.

* The packages of raildyn (``raildyn.contact``, ``raildyn.wheelset``, … and each top-level module) import
  each other without a circle, so they stand in layers, each using only those below it.
* No package imports another's private name (a module or object whose name starts with an underscore);
  ``raildyn._numbers``, ``raildyn._checks`` and ``raildyn._progress`` are the shared ground floor that
  every package uses, with ``raildyn._deprecated`` (the old names kept for one issue) and ``raildyn._tables``
  (the one table, CSV and DataFrame of every result).
* A module holds at most 600 lines, or its docstring says why it is not split; none holds more than 800.
"""

from __future__ import annotations

import ast
from graphlib import CycleError, TopologicalSorter
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "raildyn"
SHARED = {
    "raildyn._numbers",
    "raildyn._checks",
    "raildyn._progress",
    "raildyn._compiled",
    "raildyn._deprecated",
    "raildyn._tables",  # the mixin that gives every result with arrays its table, CSV and DataFrame
}
LONG, LONGEST = 600, 800
KNOWN_REACHES: set[str] = set()  # none: every name another package needs is public


def _name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _unit(module: str) -> str:
    """The package a module belongs to: raildyn.contact for raildyn.contact.creep."""
    return ".".join(module.split(".")[:2])


def _imports(path: Path):
    """(line, imported module, names) for every import of raildyn in one file, relative ones resolved."""
    module = _name(path)
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.startswith("raildyn"):
                    yield node.lineno, alias.name, []
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if target.startswith("raildyn"):
                yield node.lineno, target, [alias.name for alias in node.names]


def _modules():
    return sorted(PACKAGE.rglob("*.py"))


def _dependencies() -> dict[str, dict[str, list[str]]]:
    """package -> {package it imports: [where]}."""
    graph: dict[str, dict[str, list[str]]] = {}
    for path in _modules():
        source = _unit(_name(path))
        graph.setdefault(source, {})
        for line, target, names in _imports(path):
            # "from raildyn import contact" imports the package raildyn.contact
            targets = [f"raildyn.{n}" for n in names] if target == "raildyn" else [target]
            for t in targets:
                if _unit(t) != source and _unit(t) != "raildyn":
                    where = f"{path.relative_to(PACKAGE.parent)}:{line}"
                    graph[source].setdefault(_unit(t), []).append(where)
    return graph


def test_the_packages_import_each_other_without_a_circle():
    graph = _dependencies()
    try:
        order = list(TopologicalSorter({k: set(v) for k, v in graph.items()}).static_order())
    except CycleError as error:
        circle = error.args[1]
        where = [f"{a} -> {b} ({graph[a][b][0]})" for a, b in zip(circle, circle[1:], strict=False)]
        pytest.fail("an import circle between packages: " + "; ".join(where))
    assert set(order) >= set(graph)
    # The ground floor: the scalar check imports nothing of raildyn's, the constants only it.
    assert graph["raildyn._numbers"] == {} and graph["raildyn._progress"] == {}
    assert graph["raildyn._deprecated"] == {}  # the old names of issue 33 import nothing of raildyn's
    assert set(graph["raildyn.constants"]) <= {"raildyn._numbers"}


def test_no_package_reaches_for_another_s_private_name():
    reaches = []
    for path in _modules():
        source = _unit(_name(path))
        for _line, target, names in _imports(path):
            candidates = [f"{target}.{n}" for n in names] if names else [target]
            for full in candidates:
                if _unit(full) in (source, "raildyn") or full in SHARED or _unit(full) in SHARED:
                    continue
                if any(part.startswith("_") for part in full.split(".")[1:]):
                    reaches.append(f"{path.relative_to(PACKAGE.parent)}: {full}")
    assert set(reaches) == KNOWN_REACHES, "private names used across packages:\n" + "\n".join(reaches)


@pytest.mark.parametrize("path", _modules(), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_a_module_is_a_file_a_reader_can_hold(path):
    lines = len(path.read_text(encoding="utf-8").splitlines())
    assert lines <= LONGEST, f"{lines} lines"
    if lines > LONG:
        doc = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8"))) or ""
        assert "split" in doc, f"{lines} lines, and its docstring does not say why it is not split"
