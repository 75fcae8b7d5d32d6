"""Results out as tables (``raildyn._tables``; ARCHITECTURE.md, "Results").

* Which classes are results (decided here, once): every public dataclass with an array field
  (annotated ``ndarray``) is either a table (it inherits :class:`raildyn._tables.Tabular`) or
  listed below, as a parameter set (an input: a vehicle, a track, a profile, a matrix) or as a
  result whose arrays share no axis, each with its reason. A new dataclass with arrays fails
  :func:`test_every_dataclass_with_arrays_is_a_table_or_says_why_not` until it is one or the other,
  and a class with ``plot`` is a result, never a parameter set.
* Each table's declaration names real fields, and each unit is one its class's docstring gives.
* Every table class, on a real result (the fuzz registry's valid call that makes one), gives
  columns of one length with a unit in every name, a CSV that reads back exactly, and a
  DataFrame equal to the columns.
* Bad paths and a missing pandas are refused clearly.
"""

from __future__ import annotations

import csv
import dataclasses
import functools
import importlib
import inspect
import re
import sys

import numpy as np
import numpydoc.validate
import pytest
from fuzz_cases import entries
from fuzzing import resolve, valid_result
from test_api import PUBLIC

from raildyn import integrators, stability, train, vibration, wheelset
from raildyn._tables import DIMENSIONLESS, Tabular

# Public dataclasses with arrays that are inputs, not what an analysis returns.
PARAMETER_SETS = {
    "AxleSequence": "a train's axles: the loads a bridge run takes",
    "MovingLoad": "the loads and masses a bridge run takes",
    "Roughness": "a rail's roughness, an input of the wheel-on-track run",
    "TrackMatrices": "the discrete track's assembled matrices",
    "WheelBlock": "the wheels' assembled matrices",
    "WheelsetCreepages": "creepages of any broadcast shape, an input of the creep laws",
    "Flexibilities": "FASTSIM's flexibilities of any broadcast shape",
    "RailProfile": "a rail's profile",
    "WheelProfile": "a wheel's profile",
    "HertzCoefficients": "Hertz's coefficients of any broadcast shape",
    "JohnsonVermeulenCoefficients": "a creep law's coefficients of any broadcast shape",
    "CreepCoefficients": "Kalker's coefficients of any broadcast shape",
    "KalkerCoefficients": "Kalker's tabulated coefficients of any broadcast shape",
    "CreepForces": "a creep law's forces at inputs of any broadcast shape (one value each: no axis)",
    "WheelForces": "the nonlinear contact's forces at one state, inside a model's right-hand side",
    "ForceJacobian": "a force law's Jacobian matrices, inside an integrator",
    "RecursionMatrices": "a scheme's recursion matrices",
    "LinearSystem": "a linear model's speed-free matrices",
    "SystemMatrices": "a linear model's matrices at one speed",
    "ChainMatrices": "a chain's mass, damping and stiffness matrices",
    "StateSpaceMatrices": "a system's state-space matrices",
    "CreepTerms": "the wheelset's creep matrices",
    "NonlinearLateral": "a nonlinear model",
    "NonlinearWheelset": "a nonlinear model",
    "CompiledRHS": "a compiled right-hand side",
    "FrictionDamper": "a force law's parameters",
    "Consist": "a train's vehicles",
    "Route": "a route's grades and curves",
    "PeriodicProfile": "a rail profile, the input of a time response",
    "Spectrum": "a PSD given to the synthesis (an input)",
}

# Results whose arrays share no row axis, and why (a single state, or a map over a grid).
NO_COMMON_AXIS = {
    "CurvingMap": "a map over radii and speeds, each cell holding a value per wheelset",
    "WheelClimb": "quotients of an axle or of a history of any rank: no fixed row axis",
    "LimitCycle": "one end state; its measures are scalars",
    "PeriodicOrbit": "one state of the orbit and its multipliers: two unrelated vectors",
    "CriticalSpeed": "one mode shape; its measures are scalars",
    "StaticRoll": "the coordinates and the loads of wheels, plates and bearers: no common axis",
    "TrackedModes": "the eigenvalues inside a mode sweep, without their speeds (ModeSweep is the table)",
    "Deviation": "one maximum per coordinate, and the times compared: two axes",
}

NAME = re.compile(r"^\S.* \((?P<unit>[^()]*(?:\([^()]*\)[^()]*)*)\)$")  # "field (unit)", the unit nested


def _public_dataclasses() -> dict[str, type]:
    found = {}
    for module_name in PUBLIC:
        module = importlib.import_module(module_name)
        for name in module.__all__:
            obj = getattr(module, name)
            if inspect.isclass(obj) and dataclasses.is_dataclass(obj):
                # the lists above name a class by its name alone: two of one name would hide one
                assert found.setdefault(obj.__name__, obj) is obj, f"two public dataclasses named {name}"
    return found


def _has_arrays(cls) -> bool:
    return any("ndarray" in str(field.type) for field in dataclasses.fields(cls))


TABLES = sorted(
    (cls for cls in _public_dataclasses().values() if issubclass(cls, Tabular)), key=lambda c: c.__name__
)


def test_every_dataclass_with_arrays_is_a_table_or_says_why_not():
    with_arrays = {name: cls for name, cls in _public_dataclasses().items() if _has_arrays(cls)}
    unclassified = sorted(
        name
        for name, cls in with_arrays.items()
        if not issubclass(cls, Tabular) and name not in PARAMETER_SETS and name not in NO_COMMON_AXIS
    )
    assert not unclassified, (
        f"results with arrays but no table (inherit raildyn._tables.Tabular): {unclassified}"
    )
    plotted = sorted(name for name in PARAMETER_SETS if hasattr(with_arrays.get(name), "plot"))
    assert not plotted, f"classes with a plot are results, not parameter sets: {plotted}"
    stale = sorted((set(PARAMETER_SETS) | set(NO_COMMON_AXIS)) - set(with_arrays))
    assert not stale, f"listed, but no public dataclass with arrays: {stale}"
    both = sorted(
        name for name in {**PARAMETER_SETS, **NO_COMMON_AXIS} if issubclass(with_arrays[name], Tabular)
    )
    assert not both, f"listed as without a table, yet tables: {both}"


def _docstrings(cls) -> str:
    return "\n".join(inspect.getdoc(base) or "" for base in cls.__mro__ if base not in (Tabular, object))


@pytest.mark.parametrize("cls", TABLES, ids=lambda c: c.__name__)
def test_a_declaration_names_fields_and_units_from_the_docstring(cls):
    fields = {field.name for field in dataclasses.fields(cls)}
    columns = [name for name, _ in cls._columns]
    scalars = [name for name, _ in cls._scalars]
    assert columns, f"{cls.__name__} declares no column"
    assert len(set(columns + scalars)) == len(columns) + len(scalars), "a field declared twice"
    assert set(columns + scalars) <= fields, f"not fields: {set(columns + scalars) - fields}"
    assert set(cls._by_row) <= set(columns) and {f for f, _ in cls._labels} <= set(columns)
    doc = _docstrings(cls)
    invented = [(f, u) for f, u in cls._columns + cls._scalars if u != DIMENSIONLESS and u not in doc]
    assert not invented, f"units not found in the docstring of {cls.__name__}: {invented}"


# --------------------------------------------------------------------------- real results


@functools.cache
def _candidates() -> dict[type, list]:
    """Each table class → the registry's entries that give one: a method's instance, or a call
    that returns it (the widgets' are left to the widgets' tests)."""
    out: dict[type, list] = {}
    by_name = {cls.__name__: cls for cls in TABLES}
    for entry in entries():
        if entry.target.startswith("raildyn.widgets"):
            continue
        owner = resolve(entry.target.rsplit(".", 1)[0], static=False)
        if inspect.isclass(owner) and owner in by_name.values():
            out.setdefault(owner, []).append(("instance", entry))
        fn = resolve(entry.target, static=False)
        if inspect.isroutine(fn):
            returned = inspect.signature(fn).return_annotation
            returned = returned if isinstance(returned, str) else getattr(returned, "__name__", "")
            if returned in by_name:
                out.setdefault(by_name[returned], []).append(("returns", entry))
    return out


def _real(cls):
    """A real result of ``cls``, from the first registry entry that makes one."""
    for how, entry in _candidates().get(cls, []):
        result = entry.make().instance if how == "instance" else valid_result(entry)
        if isinstance(result, cls):
            return result
    pytest.fail(f"no fuzz registry entry makes a {cls.__name__}: add one (or a method's) to tests/fuzz_cases")


def _read(path):
    """The scalar comment lines, the header and the rows of a CSV written by ``to_csv``."""
    with path.open(newline="", encoding="utf-8") as file:
        lines = file.read().splitlines()
    comments = [line for line in lines if line.startswith("# ")]
    reader = list(csv.reader(line for line in lines if not line.startswith("# ")))
    return comments, reader[0], reader[1:]


def _same(column: np.ndarray, text: list[str]) -> bool:
    """Whether the CSV's cells hold exactly the column's values (NaN where it has NaN)."""
    if column.dtype.kind in "US":
        return list(column) == text
    read = np.array([float(cell) for cell in text])
    return np.array_equal(read, column.astype(float), equal_nan=True)


def _check_table(result, tmp_path):
    names, columns = result.table()
    rows = len(columns[0])
    assert rows >= 1 and all(column.shape == (rows,) for column in columns)
    # as many rows as the row axis has entries: the first declared field that the result holds
    field = next(f for f, _ in type(result)._columns if getattr(result, f) is not None)
    axis = np.atleast_1d(getattr(result, field))
    assert rows == (axis.shape[-1] if field in type(result)._by_row else axis.shape[0])
    assert len(set(names)) == len(names), "two columns of one name"
    assert all(NAME.match(name) and NAME.match(name)["unit"] for name in names), names
    # the CSV reads back exactly: the same names, and every number to the last bit
    path = result.to_csv(tmp_path / "result.csv")
    comments, header, body = _read(path)
    assert header == names and len(body) == rows
    for j, column in enumerate(columns):
        assert _same(column, [row[j] for row in body]), names[j]
    scalars = {f"{field} ({unit})": getattr(result, field) for field, unit in type(result)._scalars}
    assert len(comments) == len(scalars)
    for line, (key, value) in zip(comments, scalars.items(), strict=True):
        written_key, written = line[2:].rsplit(" = ", 1)
        assert written_key == key and _same(np.array([value]), [written])
    # the DataFrame holds the same columns and the scalars in its attrs
    frame = result.to_pandas()
    assert list(frame.columns) == names and len(frame) == rows
    for name, column in zip(names, columns, strict=True):
        np.testing.assert_array_equal(frame[name].to_numpy(), column)
    assert frame.attrs == scalars


@pytest.mark.parametrize("cls", TABLES, ids=lambda c: c.__name__)
def test_a_real_result_gives_its_table_csv_and_frame(cls, tmp_path):
    _check_table(_real(cls), tmp_path)


def test_a_two_dof_run_reads_back_from_numpy_loadtxt(tmp_path):
    # Newmark's average acceleration on a two-storey chain: 2 coordinates × (x, v, a) + t.
    M = np.diag([1.0, 2.0])
    K = 400.0 * np.array([[2.0, -1.0], [-1.0, 1.0]])
    t = np.linspace(0.0, 1.0, 51)
    run = integrators.newmark(M, 0.01 * K, K, t, np.array([0.01, 0.02]), np.zeros(2))
    path = run.to_csv(tmp_path / "run.csv")
    data = np.loadtxt(path, delimiter=",", skiprows=1 + len(run._scalars))
    names, _ = run.table()
    assert names[:3] == ["t (s)", "x[0] (m)", "x[1] (m)"] and names[-1] == "a[1] (m/s²)"
    assert data.shape == (t.size, 7)
    np.testing.assert_array_equal(data[:, 0], run.t)
    np.testing.assert_array_equal(data[:, 1:3].T, run.x)
    np.testing.assert_array_equal(data[:, 5:7].T, run.a)


def test_coordinate_labels_name_the_columns(tmp_path):
    sweep = stability.mode_sweep(wheelset.Wheelset(), np.array([10.0, 20.0, 30.0]))
    names, columns = sweep.table()
    label = sweep.labels[0]
    assert f"frequencies_hz[{label}] (Hz)" in names
    k = names.index(f"frequencies_hz[{label}] (Hz)")
    np.testing.assert_array_equal(columns[k], sweep.frequencies_hz[:, 0])
    # a complex field gives its real and imaginary parts, side by side
    k = names.index(f"eigenvalues[{label}].real (1/s)")
    assert names[k + 1] == f"eigenvalues[{label}].imag (1/s)"
    np.testing.assert_array_equal(columns[k] + 1j * columns[k + 1], sweep.eigenvalues[:, 0])


def test_a_mode_per_row_and_its_shape_across(tmp_path):
    M = np.diag([1.0, 2.0, 3.0])
    K = 1e4 * np.array([[2.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 1.0]])
    modes = vibration.modal_analysis(M, K)
    names, columns = modes.table()
    assert names == ["natural_frequencies (rad/s)"] + [f"mode_shapes[{i}] (kg^(−1/2))" for i in range(3)]
    np.testing.assert_array_equal(np.column_stack(columns[1:]), modes.mode_shapes.T)  # row j: mode j


def test_scalars_go_to_the_comment_lines_and_the_attrs(tmp_path):
    run = train.simulate(train.braking_model(2, 1), 1.0, 10.0, samples=11)
    comments, header, body = _read(run.to_csv(tmp_path / "run.csv"))
    assert comments == [f"# evaluations (-) = {run.evaluations}"]
    assert run.to_pandas().attrs == {"evaluations (-)": run.evaluations}
    assert header[0] == "t (s)" and len(body) == run.t.size


# --------------------------------------------------------------------------- bad input


@functools.cache
def _small():
    return integrators.newmark(np.eye(1), np.zeros((1, 1)), np.eye(1), np.linspace(0.0, 1.0, 5), 1.0, 0.0)


@pytest.mark.parametrize("path", [3.0, None, b"table.csv", True, ["table.csv"]])
def test_a_path_of_the_wrong_type_is_refused(path):
    with pytest.raises(TypeError, match=r"^path must be a file name"):
        _small().to_csv(path)


def test_a_path_in_a_missing_folder_is_refused(tmp_path):
    missing = tmp_path / "no such folder" / "table.csv"
    with pytest.raises(ValueError, match=r"path must be in an existing folder.*no such folder"):
        _small().to_csv(missing)
    assert not missing.parent.exists()


def test_a_folder_is_no_file_name(tmp_path):
    with pytest.raises(ValueError, match=r"path must name a file"):
        _small().to_csv(tmp_path)


def test_to_csv_accepts_a_str_and_replaces_the_file(tmp_path):
    target = tmp_path / "table.csv"
    target.write_text("old")
    written = _small().to_csv(str(target))
    assert written == target and target.read_text(encoding="utf-8").startswith("# steps (-) =")


def test_without_pandas_to_pandas_says_what_to_do(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # an import of pandas now fails
    with pytest.raises(ImportError, match=r"IntegrationResult\.to_pandas needs pandas.*to_csv"):
        _small().to_pandas()
    _, columns = _small().table()  # the table itself needs no pandas
    assert columns


@pytest.mark.parametrize("method", ["table", "to_csv", "to_pandas"])
def test_the_methods_are_documented(method):
    # tests/test_api.py validates the methods a public class defines; these it inherits.
    report = numpydoc.validate.validate(f"raildyn._tables.Tabular.{method}")
    problems = [(code, text) for code, text in report["errors"] if code in ("PR01", "PR02", "RT01")]
    assert not problems
