"""The machinery of the project's fuzz test (``tests/test_fuzz.py``): bad values, one at a time.

Every public callable of raildyn (the functions and classes of each public module's
``__all__``, and the public methods those classes define) has one entry in the registry
(``tests/fuzz_cases/``): a valid call, built afresh for each try. The test changes one
argument of that call at a time to a bad value and sorts what happens:

* ``refused``: a ``ValueError`` or ``TypeError`` whose message names the parameter changed
  (as a word) — the answer the package promises;
* ``accepted``: a result that is finite and non-empty everywhere, for a change the entry
  declares valid (the docstring states the range that makes it so, e.g. a damping ≥ 0);
* ``solver``: :class:`raildyn.errors.SolverError` for a value inside the number domain
  (zero, negative, huge): the package's one failure policy, a bounded run that says why;
* everything else is a failure: ``hang`` (over the time limit), ``non-finite`` (a NaN, an
  inf or an empty array anywhere in the result), ``nonsense`` (a finite result for a change
  not declared valid), ``obscure`` (any other exception, or a ValueError/TypeError that does
  not name the parameter).

The bad values follow the kind of the valid one (see :func:`mutations`): for a number
NaN, ±inf, 0, a negative, 1e300, a string, None and a list, and the slips of a careless
user: a complex number, a bool, the number ×1000 (millimetres typed for metres), an absurd
size 1e9 and a vanishing 1e-300; for a speed (a parameter whose name says so) also the
speed typed in km/h (see :func:`kmh`); for an integer NaN, 0, a negative, 10**12, a
fraction, a complex number, a bool, a string, None and a list; for an array a NaN or inf
first entry, a NaN entry in the middle and as the last entry, zeros, negatives, 1e300, an
empty array, an extra axis, complex entries, booleans, a string and None; for a name an
unknown name, a number and None; for a flag a string and None; for a model or other object
a number, a string, None and its class (``Wheelset`` for ``Wheelset()``); for a callback a
non-callable, and a callback whose values are NaN, negative or of the wrong shape; for a
parameter left at None a string. Every callable
also meets an unknown keyword. Parameters in :data:`FREE` (text that labels a plot) take
anything. A parameter that may be zero may also be 1e-300 (``tiny`` is valid wherever
``zero`` is declared valid).

``python tests/test_fuzz.py`` prints, for the whole package, the share of the bad calls
(every changed call not declared valid) that are refused clearly: a ValueError or
TypeError naming the parameter, or the SolverError of the failure policy.
"""

from __future__ import annotations

import contextlib
import dataclasses
import importlib
import inspect
import math
import numbers
import re
import signal
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from test_api import PUBLIC  # noqa: E402  (the one definition of what is public)

from raildyn.errors import SolverError  # noqa: E402

#: Seconds a changed call may take before it counts as a hang; the valid call gets longer
#: (its first run may compile numba kernels).
LIMIT = 5.0
VALID_LIMIT = 60.0

#: Parameters that take any value: text or style that only labels a plot.
FREE = frozenset({"label", "title", "name", "caption", "color", "description_text"})

#: Changes that stay inside the number domain: a SolverError there is the failure policy at work.
DOMAIN = frozenset({"zero", "negative", "huge", "big", "tiny", "mm"})

#: Every change the test makes, by name (the keys of ``accepts`` in an entry).
CHANGES = (
    "nan", "inf", "-inf", "zero", "negative", "huge", "fraction", "list", "empty", "shape",
    "string", "none", "type", "unknown", "returns-nan", "returns-negative", "returns-shape",
    "complex", "bool", "nan-middle", "nan-last", "mm", "kmh", "big", "tiny", "class",
)  # fmt: skip

#: The highest speed the package accepts, m/s (``raildyn.constants.MAXIMUM_SPEED``, written here
#: so that the mutations do not depend on the code under test).
MAXIMUM_SPEED = 200.0

OUTCOMES = ("refused", "accepted", "solver", "hang", "non-finite", "nonsense", "obscure")
FAILURES = ("hang", "non-finite", "nonsense", "obscure")

UNKNOWN_KEYWORD = "not_a_parameter"


@dataclasses.dataclass(frozen=True)
class Call:
    """One valid call: positional and keyword arguments, and the instance for a method."""

    args: tuple
    kwargs: dict
    instance: object = None


def call(*args, **kwargs) -> Call:
    """A valid call of a function or a class."""
    return Call(args, kwargs)


def on(instance, *args, **kwargs) -> Call:
    """A valid call of a method of ``instance``."""
    return Call(args, kwargs, instance)


@dataclasses.dataclass(frozen=True)
class Entry:
    """The registry's entry for one public callable.

    ``target`` is its public dotted name; ``make`` builds a valid :class:`Call` afresh;
    ``accepts`` maps a parameter to the changes that are valid for it (a space-separated
    string of names from :data:`CHANGES`; the key ``"*"`` applies to every parameter, for a
    result dataclass whose fields hold whatever a model computes); ``skip`` names parameters
    left unchanged, each with the reason; ``limit`` raises the time limit for a callable
    whose valid call is slow; ``infinite`` names result fields whose documented answer may
    be +inf (see :func:`bad_numbers`); ``patches`` sets module constants while the entry's
    calls run, dotted name → value (a solver's budget lowered, so that a call that spends it
    says so in a quarter of the time and in the same words).
    """

    target: str
    make: Callable[[], Call]
    accepts: dict = dataclasses.field(default_factory=dict)
    skip: dict = dataclasses.field(default_factory=dict)
    limit: float = LIMIT
    infinite: tuple = ()
    patches: dict = dataclasses.field(default_factory=dict)

    def __post_init__(self):
        for param, changes in self.accepts.items():
            unknown = set(changes.split()) - set(CHANGES)
            assert not unknown, f"{self.target}: accepts[{param!r}] names unknown changes {unknown}"


def fuzz(target: str, make: Callable[[], Call], **options) -> Entry:
    """Shorthand for :class:`Entry`."""
    return Entry(target, make, **options)


# --------------------------------------------------------------------------- the public callables


def resolve(target: str, *, static: bool = True):
    """The object a public dotted name refers to.

    Attributes win over submodules (``raildyn.contact.fastsim`` is the function the package
    exports, not its module). With ``static`` a method is the function its class defines
    (its identity); without, what calling it through the class calls (a class method bound
    to its class).
    """
    try:
        obj = _walk(target, static, attributes_first=True)
    except (AttributeError, ImportError):
        obj = _walk(target, static, attributes_first=False)
    return _function(obj) if static else obj


def _walk(target: str, static: bool, *, attributes_first: bool):
    first, *rest = target.split(".")
    obj = importlib.import_module(first)
    path = first
    for attr in rest:
        path = f"{path}.{attr}"
        if inspect.isclass(obj):
            obj = inspect.getattr_static(obj, attr) if static else getattr(obj, attr)
        elif inspect.ismodule(obj) and not (attributes_first and hasattr(obj, attr)):
            try:
                obj = importlib.import_module(path)
            except ImportError:
                obj = getattr(obj, attr)
        else:
            obj = getattr(obj, attr)
    return obj


def _function(obj):
    return obj.__func__ if isinstance(obj, (classmethod, staticmethod)) else obj


def public_callables() -> dict[int, str]:
    """Identity → a public dotted name, for every public function, class and public method.

    A public method that a public class inherits from a base class of a private module (the
    ground floor's :class:`raildyn._tables.Tabular`, whose ``to_csv`` every result shares) is
    public too, under the first public class that has it: it is reached through no public
    name of its own.
    """
    found: dict[int, str] = {}
    inherited: dict[int, str] = {}
    for module_name in PUBLIC:
        module = importlib.import_module(module_name)
        for name in module.__all__:
            obj = getattr(module, name)
            if not callable(obj) or id(obj) in found or getattr(obj, "_is_protocol", False):
                continue  # a typing.Protocol is an interface: calling it is Python's own TypeError
            found[id(obj)] = f"{module_name}.{name}"
            if inspect.isclass(obj):
                for attr, member in vars(obj).items():
                    member = _function(member)
                    if not attr.startswith("_") and inspect.isfunction(member) and id(member) not in found:
                        found[id(member)] = f"{module_name}.{name}.{attr}"
                for base in obj.__mro__[1:]:
                    if not _private_module(base.__module__):
                        continue
                    for attr, member in vars(base).items():
                        member = _function(member)
                        if not attr.startswith("_") and inspect.isfunction(member):
                            inherited.setdefault(id(member), f"{module_name}.{name}.{attr}")
    return {**inherited, **found}


def _private_module(name: str) -> bool:
    """Whether ``name`` is a private module of raildyn (a part of its dotted name starts with ``_``)."""
    return name.startswith("raildyn.") and any(part.startswith("_") for part in name.split(".")[1:])


# --------------------------------------------------------------------------- the changes


def _is_number(value) -> bool:
    return isinstance(value, (numbers.Real, np.floating, np.integer)) and not isinstance(
        value, (bool, np.bool_)
    )


def _is_integer(value) -> bool:
    return isinstance(value, (numbers.Integral, np.integer)) and not isinstance(value, (bool, np.bool_))


def _is_numeric_array(value) -> bool:
    if isinstance(value, np.ndarray):
        return value.dtype.kind in "iufc" and value.ndim > 0
    if isinstance(value, (list, tuple)) and value:
        try:
            arr = np.asarray(value)
        except (ValueError, TypeError):
            return False
        return arr.dtype.kind in "iuf"
    return False


def _returns(fn, change):
    """A callback like ``fn`` whose values are changed."""

    def changed(*args, **kwargs):
        out = np.asarray(fn(*args, **kwargs), dtype=float)
        if change == "returns-nan":
            return np.full_like(out, np.nan)
        if change == "returns-negative":
            return -np.abs(out) - 1.0
        return np.stack([out, out])

    return changed


def is_speed(param: str) -> bool:
    """Whether a parameter holds a speed in m/s, by its name (``speed``, ``speeds``,
    ``initial_speed``, ``speed_range``...; not ``speed_kmh``, which is in km/h)."""
    return "speed" in param and "kmh" not in param


def kmh(value):
    """A speed typed in km/h for m/s: the valid value ×3.6; where that would still be a
    plausible speed (≤ :data:`MAXIMUM_SPEED`, a slip no check can tell from a real speed), the
    plain 300 that a student types for a 300 km/h train (for an array, scaled so that its
    largest entry is 300)."""
    if isinstance(value, (np.ndarray, list, tuple)):
        arr = np.asarray(value, dtype=float)
        top = np.abs(arr).max()
        if top == 0:
            return np.full_like(arr, 300.0)
        return 3.6 * arr if 3.6 * top > MAXIMUM_SPEED else arr * (300.0 / top)
    v = abs(float(value))
    return 3.6 * v if 3.6 * v > MAXIMUM_SPEED else 300.0


def _at(arr: np.ndarray, index: int, bad) -> np.ndarray:
    """A copy of ``arr`` with its flat entry ``index`` set to ``bad``."""
    out = arr.copy()
    out.flat[index] = bad
    return out


def mutations(value, param: str = "") -> dict[str, object]:
    """The bad values for a parameter ``param`` whose valid value is ``value``, by change name."""
    if value is None:
        return {"string": "abc"}
    if isinstance(value, (bool, np.bool_)):
        return {"string": "yes", "none": None}
    speed = is_speed(param)
    if _is_integer(value) and not speed:
        return {
            "nan": math.nan, "zero": 0, "negative": -abs(int(value)) - 1, "huge": 10**12,
            "fraction": int(value) + 0.5, "string": "abc", "none": None, "list": [value, value],
            "complex": complex(int(value), 1), "bool": True,
        }  # fmt: skip
    if _is_number(value):
        v = float(value)
        changes = {
            "nan": math.nan, "inf": math.inf, "-inf": -math.inf, "zero": 0.0,
            "negative": -abs(v) if v else -1.0, "huge": 1e300, "string": "abc", "none": None,
            "list": [v, v], "complex": complex(v, 1.0), "bool": True, "big": 1e9, "tiny": 1e-300,
        }  # fmt: skip
        if v:
            changes["mm"] = 1000.0 * v
        if speed:
            changes["kmh"] = kmh(v)
        return changes
    if isinstance(value, str):
        return {"unknown": "no-such-name", "type": 1.0, "none": None}
    if _is_numeric_array(value):
        arr = np.array(value)
        real = arr.dtype.kind != "c"
        arr = arr.astype(float if real else complex)
        first = np.zeros(arr.size, dtype=bool)
        first[0] = True
        first = first.reshape(arr.shape)
        changes = {
            "nan": np.where(first, np.nan, arr), "inf": np.where(first, np.inf, arr),
            "zero": np.zeros_like(arr), "negative": -np.abs(arr) - (arr == 0),
            "huge": np.where(first, 1e300, arr), "empty": np.empty((0,) + arr.shape[1:]),
            "shape": np.stack([arr, arr]), "string": "abc", "none": None,
        }  # fmt: skip
        if arr.size > 2:
            changes["nan-middle"] = _at(arr, arr.size // 2, np.nan)
        if arr.size > 1:
            changes["nan-last"] = _at(arr, arr.size - 1, np.nan)
        if real:
            changes["complex"] = arr + 1j
            changes["bool"] = np.ones(arr.shape, dtype=bool)
        if speed:
            changes["kmh"] = kmh(arr)
        return changes
    if inspect.isfunction(value) or inspect.ismethod(value) or isinstance(value, np.ufunc):
        return {
            "type": 1.0, "returns-nan": _returns(value, "returns-nan"),
            "returns-negative": _returns(value, "returns-negative"),
            "returns-shape": _returns(value, "returns-shape"),
        }  # fmt: skip
    changes = {"type": 1.0, "string": "abc", "none": None}
    if not isinstance(value, type) and type(value).__module__ != "builtins":
        changes["class"] = type(value)  # the class where an instance of it belongs: Wheelset for Wheelset()
    return changes


# --------------------------------------------------------------------------- running and sorting


class Hang(BaseException):
    """Raised by the timer inside a call that ran past its limit (BaseException: nothing catches it)."""


def _on_alarm(signum, frame):
    raise Hang


def bad_numbers(result, infinite=(), depth=0) -> str | None:
    """Where the result holds a NaN, an inf or an empty array (None if nowhere).

    A dataclass field named in ``infinite`` may hold +inf: a documented answer, such as a
    critical speed of +inf for a model stable over the whole range; ``"return"`` names the
    value returned itself.
    """
    if depth == 0 and "return" in infinite and isinstance(result, float) and result == math.inf:
        return None
    if depth > 4 or result is None or isinstance(result, (str, bytes, bool)):
        return None
    if isinstance(result, (numbers.Number, np.number)):
        return None if np.isfinite(complex(result)) else f"the value {result!r}"
    if isinstance(result, np.ndarray):
        if result.dtype.kind not in "iufc":
            return None
        if result.size == 0:
            return f"an empty array of shape {result.shape}"
        return None if np.isfinite(result).all() else "an array holding NaN or inf"
    if dataclasses.is_dataclass(result) and not isinstance(result, type):
        for field in dataclasses.fields(result):
            value = getattr(result, field.name)
            if field.name in infinite and (_is_number(value) or _is_numeric_array(value)):
                value = np.where(np.isposinf(value), 0.0, value)
            where = bad_numbers(value, infinite, depth + 1)
            if where:
                return f"{type(result).__name__}.{field.name}: {where}"
        return None
    if isinstance(result, (tuple, list)):
        for i, item in enumerate(result[:50]):
            where = bad_numbers(item, infinite, depth + 1)
            if where:
                return f"[{i}]: {where}"
        return None
    if isinstance(result, dict):
        for key, item in list(result.items())[:50]:
            where = bad_numbers(item, infinite, depth + 1)
            if where:
                return f"[{key!r}]: {where}"
    return None


def _names(message: str, param: str) -> bool:
    """Whether ``message`` names ``param`` as a word (``a``, which is also the article, only
    before "must", "=", an index, a comma or "and")."""
    after = r"(?=\s+must|\s*=|\[|\s*,|\s+and\s)" if param == "a" else r"(?!\w)"
    return re.search(rf"(?<![\w.]){re.escape(param)}{after}", message) is not None


def _invoke(fn, c: Call, limit: float):
    previous = signal.signal(signal.SIGALRM, _on_alarm)
    signal.setitimer(signal.ITIMER_REAL, limit)
    try:
        return fn(*c.args, **c.kwargs)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def _callable_of(entry: Entry, c: Call):
    if c.instance is None:
        return resolve(entry.target, static=False)
    return getattr(c.instance, entry.target.rsplit(".", 1)[1])


@dataclasses.dataclass(frozen=True)
class Outcome:
    """What one changed call did."""

    target: str
    param: str
    change: str
    kind: str
    detail: str

    def __str__(self):
        return f"{self.target}({self.param}: {self.change}) → {self.kind}: {self.detail}"


def declared(entry: Entry, param: str) -> set[str]:
    """The changes declared valid for ``param`` (``tiny`` wherever ``zero`` is: a value that may
    vanish may be vanishingly small)."""
    valid = set((entry.accepts.get(param, "") + " " + entry.accepts.get("*", "")).split())
    if "zero" in valid:
        valid.add("tiny")
    return valid


def _sort(entry: Entry, param: str, change: str, run: Callable[[], object]) -> Outcome:
    import matplotlib.pyplot as plt

    accepted = change in declared(entry, param)
    try:
        result = run()
    except Hang:
        return Outcome(entry.target, param, change, "hang", f"over {entry.limit} s")
    except SolverError as err:
        kind = "solver" if change in DOMAIN else "obscure"
        return Outcome(entry.target, param, change, kind, f"SolverError: {err}")
    except (ValueError, TypeError) as err:
        message = str(err)
        kind = "refused" if _names(message, param) else "obscure"
        return Outcome(entry.target, param, change, kind, f"{type(err).__name__}: {message[:300]}")
    except Exception as err:  # noqa: BLE001 — sorting every other exception is the point
        return Outcome(entry.target, param, change, "obscure", f"{type(err).__name__}: {str(err)[:300]}")
    finally:
        plt.close("all")
    where = bad_numbers(result, entry.infinite)
    if where:
        return Outcome(entry.target, param, change, "non-finite", where)
    if accepted or change == "huge":
        # 1e300 may be answered by a formulation that stays finite (issue 15, item 5).
        return Outcome(entry.target, param, change, "accepted", "a finite result")
    return Outcome(entry.target, param, change, "nonsense", f"returned {type(result).__name__}, not refused")


def share_refused(counts) -> float:
    """The share of bad calls refused clearly: refused (or the solver's failure policy) over every
    changed call that is not declared valid (outcome ``accepted``); 1.0 when there is none."""
    bad = sum(counts[k] for k in OUTCOMES) - counts["accepted"]
    return (counts["refused"] + counts["solver"]) / bad if bad else 1.0


def valid_result(entry: Entry):
    """Run the valid call once (compiling what needs compiling) and return its result."""
    c = entry.make()
    return _invoke(_callable_of(entry, c), c, VALID_LIMIT)


def run(entry: Entry) -> list[Outcome]:
    """Every changed call of one entry, sorted (with the entry's ``patches`` in place)."""
    from unittest import mock

    with contextlib.ExitStack() as patched:
        for name, value in entry.patches.items():
            patched.enter_context(mock.patch(name, value))
        return _run(entry)


def _run(entry: Entry) -> list[Outcome]:
    c0 = entry.make()
    fn = _callable_of(entry, c0)
    signature = inspect.signature(fn)
    bound = signature.bind(*c0.args, **c0.kwargs)
    values = dict(bound.arguments)
    params = signature.parameters
    for name, p in params.items():  # the defaults are valid values too
        if name not in values and p.default is not inspect.Parameter.empty and p.kind != p.VAR_KEYWORD:
            values[name] = p.default
    outcomes = []
    for param, value in values.items():
        kind = params[param].kind if param in params else None
        if param in FREE or param in entry.skip or kind in (inspect.Parameter.VAR_POSITIONAL,):
            continue
        if kind == inspect.Parameter.VAR_KEYWORD:
            continue
        for change, bad in mutations(value, param).items():

            def changed(param=param, bad=bad):
                c = entry.make()
                f = _callable_of(entry, c)
                b = inspect.signature(f).bind(*c.args, **c.kwargs)
                b.arguments[param] = bad
                return _invoke(f, Call(b.args, b.kwargs), entry.limit)

            outcomes.append(_sort(entry, param, change, changed))

    def unknown_keyword():
        c = entry.make()
        f = _callable_of(entry, c)
        return _invoke(f, Call(c.args, {**c.kwargs, UNKNOWN_KEYWORD: 1.0}), entry.limit)

    outcomes.append(_sort(entry, UNKNOWN_KEYWORD, "unknown", unknown_keyword))
    return outcomes
