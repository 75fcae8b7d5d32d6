"""Input checks shared by every raildyn model.

The ground floor of the package, with :mod:`raildyn._numbers` (the one number check,
:func:`scalar`, which :mod:`raildyn.constants` needs too) below it and the table of plausible
ranges of :mod:`raildyn.constants` beside it: _numbers ← constants ← _checks, no loop.

Each check either returns the cleaned value or raises a ``ValueError`` whose
message names the parameter, the value received and what is allowed, so that a
bad number never travels on to become a silent NaN.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from raildyn._numbers import interval_words, scalar
from raildyn.constants import PLAUSIBLE_RANGES


def _show(value) -> str:
    """Short text for a value inside an error message."""
    arr = np.asarray(value)
    if arr.ndim == 0:
        return repr(value)
    text = np.array2string(arr, threshold=6, precision=4)
    return f"{text} (shape {arr.shape})"


def positive(name: str, value) -> float:
    """A finite float > 0 (a mass, a stiffness, a time step)."""
    return scalar(name, value, low=0.0, low_open=True)


def nonnegative(name: str, value) -> float:
    """A finite float >= 0 (a damping coefficient, an amplitude)."""
    return scalar(name, value, low=0.0)


def array(
    name: str, value, *, ndim=None, shape=None, low=None, low_open=False, dtype=float, allow_empty=True
) -> np.ndarray:
    """Return ``value`` as a finite numpy array, checking its rank, shape and lower bound.

    ``shape`` may hold ``None`` for a free axis; ``allow_empty=False`` refuses an array
    with no entries (an empty grid would give an empty, silent answer).
    """
    arr = _numbers(name, value, dtype)
    if arr.ndim == 0 and ndim is None and shape is None and arr.dtype.kind == "f":
        # One number, as laws inside a model's loop take their parameters: checked as a float,
        # a tenth of the cost of the array checks below (which word the message when it fails).
        x = float(arr)
        if math.isfinite(x) and (low is None or (x > low if low_open else x >= low)):
            return arr
    if not allow_empty and arr.size == 0:
        raise ValueError(f"{name} must not be empty, got an array of shape {arr.shape}")
    if ndim is not None and arr.ndim != ndim:
        raise ValueError(
            f"{name} must be a {ndim}-dimensional array, got {arr.ndim} dimensions: {_show(value)}"
        )
    if shape is not None:
        fits = arr.ndim == len(shape)
        fits = fits and all(s is None or s == a for s, a in zip(shape, arr.shape, strict=True))
        if not fits:
            want = "(" + ", ".join("any" if s is None else str(s) for s in shape) + ")"
            raise ValueError(f"{name} must have shape {want}, got shape {arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError(f"{name} must contain only finite numbers, got {_show(value)}")
    if low is not None:
        bad = arr <= low if low_open else arr < low
        if bad.any():
            op = ">" if low_open else ">="
            first = arr[bad].flat[0].item()  # a Python number: its repr is the number alone
            raise ValueError(f"{name} must be {op} {low} everywhere, got {first!r} in {_show(value)}")
    return arr


def _numbers(name: str, value, dtype=float) -> np.ndarray:
    """``value`` as a numeric array of ``dtype``; a TypeError naming ``name`` refuses a string, None,
    an object, booleans (True is no number: a flag passed where a number belongs) and, for a real
    ``dtype``, complex values (cast to real they would lose their imaginary part without a word)."""
    if value is None or isinstance(value, (str, bytes)):
        raise TypeError(f"{name} must be a number or an array of numbers, got {value!r}")
    want = np.dtype(dtype).kind
    try:
        raw = np.asarray(value)
        kind = raw.dtype.kind
        if kind == "b" and want != "b":
            raise TypeError(f"{name} must hold numbers, not booleans, got {_show(raw)}")
        if kind == "c" and want != "c":
            raise TypeError(f"{name} must hold real numbers, got complex values: {_show(raw)}")
        if kind == "O":  # a list of mixed objects: each converted on its own (a complex one refused)
            if any(isinstance(v, (bool, np.bool_, complex, np.complexfloating)) for v in raw.flat):
                raise TypeError(f"{name} must hold real numbers, got {value!r:.80}")
        return raw if raw.dtype == dtype else raw.astype(dtype)
    except TypeError as err:
        if str(err).startswith(name):
            raise
        raise TypeError(
            f"{name} must be a number or an array of numbers, got {value!r:.80} "
            f"of type {type(value).__name__}"
        ) from None
    except ValueError:
        raise TypeError(
            f"{name} must be a number or an array of numbers, got {value!r:.80} "
            f"of type {type(value).__name__}"
        ) from None


def square_matrix(
    name: str, value, *, size=None, symmetric=True, positive_definite=False, positive_semidefinite=False
) -> np.ndarray:
    """Return a finite square matrix, optionally checked for symmetry and definiteness.

    The symmetry tolerance is relative to the largest entry (1e-10), loose enough
    for matrices assembled in floating point and tight enough to catch a typo.
    """
    arr = np.atleast_2d(_numbers(name, value))
    if arr.ndim != 2 or arr.shape[0] != arr.shape[1]:
        raise ValueError(f"{name} must be a square matrix, got shape {np.shape(value)}")
    if size is not None and arr.shape[0] != size:
        raise ValueError(f"{name} must be {size}x{size} to match the other matrices, got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must contain only finite numbers, got {_show(value)}")
    scale = max(np.abs(arr).max(), np.finfo(float).tiny)
    if symmetric and np.abs(arr - arr.T).max() > 1e-10 * scale:
        i, j = np.unravel_index(np.argmax(np.abs(arr - arr.T)), arr.shape)
        raise ValueError(
            f"{name} must be symmetric; {name}[{i},{j}] = {arr[i, j]!r} but {name}[{j},{i}] = {arr[j, i]!r}"
        )
    if positive_definite or positive_semidefinite:
        eig = np.linalg.eigvalsh(0.5 * (arr + arr.T))
        limit = 1e-12 * scale
        if positive_definite and eig.min() <= limit:
            raise ValueError(f"{name} must be positive definite, got smallest eigenvalue {eig.min():.4g}")
        if positive_semidefinite and eig.min() < -limit:
            raise ValueError(
                f"{name} must be positive semi-definite, got smallest eigenvalue {eig.min():.4g}"
            )
    return arr


def generator(rng) -> np.random.Generator:
    """Accept a ``numpy.random.Generator``, an int seed or None, and return a Generator."""
    if isinstance(rng, np.random.Generator):
        return rng
    if rng is None or (
        isinstance(rng, (numbers.Integral, np.integer)) and not isinstance(rng, bool) and rng >= 0
    ):
        return np.random.default_rng(rng)
    raise ValueError(f"rng must be a numpy.random.Generator, a non-negative int seed or None, got {rng!r}")


def integer(name: str, value, *, low=None, high=None) -> int:
    """Return ``value`` as an int within ``[low, high]`` (a count: samples, segments, records).

    Floats, even integral ones, and bools are refused so that a count is never
    silently truncated.
    """
    if isinstance(value, bool) or not isinstance(value, (numbers.Integral, np.integer)):
        raise TypeError(f"{name} must be an integer, got {value!r} of type {type(value).__name__}")
    k = int(value)
    allowed = f"[{'-inf' if low is None else low}, {'inf' if high is None else high}]"
    if (low is not None and k < low) or (high is not None and k > high):
        raise ValueError(f"{name} must be an integer in {allowed}, got {value!r}")
    return k


def hermitian(name: str, value, *, size=None) -> np.ndarray:
    """Return a finite complex array of square matrices ``(..., q, q)``, each Hermitian.

    The tolerance (1e-10) is relative to the largest entry of each matrix on its
    own, so a matrix whose entries are small (a spectrum far down its slope) is
    held to the same relative standard as a large one.
    """
    arr = _numbers(name, value, complex)
    if arr.ndim < 2 or arr.shape[-1] != arr.shape[-2]:
        raise ValueError(f"{name} must be an array of square matrices (..., q, q), got shape {arr.shape}")
    if size is not None and arr.shape[-1] != size:
        raise ValueError(f"{name} must hold {size}x{size} matrices, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must contain only finite numbers, got {_show(value)}")
    if arr.size == 0:
        return arr
    scale = np.maximum(np.abs(arr).max(axis=(-2, -1), keepdims=True), np.finfo(float).tiny)
    misfit = np.abs(arr - np.conj(np.swapaxes(arr, -1, -2))) / scale
    if misfit.max() > 1e-10:
        idx = np.unravel_index(np.argmax(misfit), arr.shape)
        j, k = idx[-2], idx[-1]
        swap = (*idx[:-2], k, j)
        where = ", ".join(str(i) for i in idx)
        raise ValueError(
            f"{name} must be Hermitian (equal to its conjugate transpose); {name}[{where}] = {arr[idx]!r} "
            f"but the conjugate of its mirror entry is {np.conj(arr[swap])!r}"
        )
    return arr


def time_grid(name: str, value, *, uniform: bool = False) -> np.ndarray:
    """Return ``value`` as a 1-D finite array of strictly increasing times (s).

    With ``uniform=True`` every step must also equal the mean step, to within
    1e-9 of it plus a few roundings of the largest time, so that grids made by
    ``np.linspace`` or ``np.arange`` pass and a grid with a missing sample does not.
    """
    t = increasing(name, value)
    steps = np.diff(t)
    if uniform and t.size > 2:
        h = (t[-1] - t[0]) / (t.size - 1)
        misfit = np.abs(steps - h)
        if misfit.max() > 1e-9 * h + 8 * np.finfo(float).eps * np.abs(t).max():
            i = int(np.argmax(misfit))
            raise ValueError(
                f"{name} must be uniformly spaced (mean step {h:.6g} s); step {i} is {steps[i]:.6g} s"
            )
    return t


def interval(name: str, value, *, unit: str = "", low: float = 0.0) -> tuple[float, float]:
    """Return a pair (lo, hi) of finite floats with low < lo < hi (a band of wavelengths or frequencies)."""
    where = f" ({unit})" if unit else ""
    pair = _numbers(name, value)
    if pair.shape != (2,):
        raise ValueError(f"{name} must be a pair (low, high){where}, got {value!r}")
    lo, hi = (float(v) for v in pair)
    if not (np.isfinite(lo) and np.isfinite(hi) and low < lo < hi):
        raise ValueError(
            f"{name} must satisfy {low} < low < high{where}, finite; "
            f"got {value!r} (an empty or impossible band)"
        )
    return lo, hi


def tolerance(name: str, value, *, low: float = 1e-13, high: float = 1.0) -> float:
    """A solver tolerance, finite, in ``[low, high)``.

    The default floor 1e-13 sits above 100 machine epsilons, below which scipy's solvers
    silently raise a relative tolerance, and a tolerance of 1 or more asks for no accuracy.
    """
    return scalar(name, value, low=low, high=high, high_open=True)


def choice(name: str, value, options) -> str:
    """One of the names ``options`` (a TypeError for a non-string, a ValueError listing the names)."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, one of {sorted(options)}, got {value!r}")
    if value not in options:
        raise ValueError(f"{name} must be one of {sorted(options)}, got {value!r}")
    return value


def flag(name: str, value) -> bool:
    """A bool (numpy's included); anything else, even a truthy string, refused."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be True or False, got {value!r}")
    return bool(value)


def not_a_class(name: str, value, what: str = "a model"):
    """Refuse a class passed where an instance of it belongs (``Wheelset`` for ``Wheelset()``).

    Calling a method on the class would fail inside with "missing 1 required positional argument:
    'self'", a message that names nothing the caller passed.
    """
    if isinstance(value, type):
        raise TypeError(
            f"{name} must be {what}, an instance such as {value.__name__}(), "
            f"got the class {value.__name__} itself"
        )
    return value


def instance(name: str, value, kind, what: str | None = None):
    """``value`` itself if it is an instance of ``kind`` (a class or a tuple of classes)."""
    if isinstance(value, type):
        not_a_class(name, value, f"a {what or getattr(kind, '__name__', 'model')}")
    if not isinstance(value, kind):
        if what is None:
            kinds = kind if isinstance(kind, tuple) else (kind,)
            what = " or ".join(k.__name__ for k in kinds)
        raise TypeError(f"{name} must be a {what}, got {value!r:.80} of type {type(value).__name__}")
    return value


def function(name: str, value):
    """``value`` itself if it can be called (a callback: a force, a spectrum, a profile)."""
    if not callable(value):
        raise TypeError(f"{name} must be a callable, got {value!r:.80} of type {type(value).__name__}")
    return value


def returned(name: str, value, *, shape=None, low=None, at: str = "") -> np.ndarray:
    """Check what the callback ``name`` returned: finite numbers, of ``shape``, and ≥ ``low``.

    ``at`` says where it was called (e.g. ``"t = 0.25 s"``) for the message. A spectrum
    callback is held to ``low=0``.
    """
    where = f" at {at}" if at else ""
    try:
        arr = _numbers(name, value)
    except TypeError:
        raise TypeError(f"{name} must return numbers (real ones), returned {value!r:.80}{where}") from None
    if shape is not None and arr.shape != tuple(shape):
        raise ValueError(
            f"{name} must return an array of shape {tuple(shape)}, returned shape {arr.shape}{where}"
        )
    if not np.isfinite(arr).all():
        raise ValueError(f"{name} returned a non-finite value{where}: {_show(arr)}")
    if low is not None and arr.size and arr.min() < low:
        raise ValueError(f"{name} must return values >= {low}, returned {arr.min()!r}{where}")
    return arr


_NUMERIC = ("float", "int", "complex", "ndarray", "np.floating")


def fields(obj, *, skip=(), flags=()) -> None:
    """Check the numeric fields of a dataclass: finite numbers, or None where the type allows it.

    A field counts as numeric when its annotation names ``float``, ``int``, ``complex`` or
    ``ndarray``; a string, an object, a None it does not allow or an array where the
    annotation names no ``ndarray`` is refused by a TypeError, a NaN, an inf or an empty
    array by a ValueError, each naming the field; booleans are refused except in the fields named
    in ``flags`` (a mask: where a patch adheres). For result dataclasses, whose values raildyn
    computes: the check keeps a hand-built result honest and costs one pass.
    """
    import dataclasses

    for f in dataclasses.fields(obj):
        ann = f.type if isinstance(f.type, str) else getattr(f.type, "__name__", str(f.type))
        if f.name in skip or not any(word in ann for word in _NUMERIC):
            continue
        value = getattr(obj, f.name)
        if value is None:
            if "None" in ann:
                continue
            raise TypeError(f"{f.name} must be a number or an array of numbers, got None")
        if isinstance(value, (bool, np.bool_)) and "bool" not in ann:
            raise TypeError(f"{f.name} must be a number, got {value!r}")
        kind = bool if f.name in flags else complex if "complex" in ann else float
        arr = _numbers(f.name, value, kind)
        if "ndarray" not in ann and arr.ndim:
            raise TypeError(f"{f.name} must be a single number, got {_show(value)}")
        if arr.size == 0:
            raise ValueError(f"{f.name} must not be empty, got an array of shape {arr.shape}")
        if not np.isfinite(arr).all():
            raise ValueError(f"{f.name} must contain only finite numbers, got {_show(value)}")


def linear_model(name: str, value):
    """``value`` itself if it follows the linear model protocol (it has ``linear_system()``)."""
    not_a_class(name, value, "a linear model")
    if not callable(getattr(value, "linear_system", None)):
        raise TypeError(
            f"{name} must be a linear model (an object with linear_system(), e.g. raildyn.wheelset."
            f"Wheelset or raildyn.vehicles.LateralCar), got {value!r:.80} of type {type(value).__name__}"
        )
    return value


def increasing(name: str, value, *, low=None, low_open: bool = False) -> np.ndarray:
    """A non-empty 1-D array of finite, strictly increasing numbers, each >= ``low`` (> with ``low_open``).

    For an abscissa that is not a time (a frequency grid, a frequency ratio): :func:`time_grid`
    is the check for times.
    """
    arr = array(name, value, ndim=1, low=low, low_open=low_open, allow_empty=False)
    steps = np.diff(arr)
    if np.any(steps <= 0):
        i = int(np.argmax(steps <= 0))
        raise ValueError(
            f"{name} must be strictly increasing; {name}[{i + 1}] = {arr[i + 1]!r} "
            f"does not exceed {name}[{i}] = {arr[i]!r}"
        )
    return arr


def strings(name: str, value, n=None, *, unique: bool = False) -> tuple:
    """A tuple or list of strings (not one string: its letters are no names), of length ``n`` when given.

    For labels, coordinate names and input kinds; ``unique`` (names that identify something)
    refuses a repeated name and an empty or blank one.
    """
    if isinstance(value, str) or not isinstance(value, (tuple, list)):
        raise TypeError(f"{name} must be a tuple or list of strings, got {value!r:.80}")
    if not all(isinstance(s, str) for s in value):
        raise TypeError(f"{name} must hold only strings, got {value!r:.80}")
    if n is not None and len(value) != n:
        raise ValueError(f"{name} must hold {n} strings, got {len(value)}: {value!r:.80}")
    if unique and len(set(value)) != len(value):
        raise ValueError(f"{name} must not repeat a name, got {value!r:.80}")
    if unique and any(not s.strip() for s in value):
        raise ValueError(f"{name} must not hold an empty name, got {value!r:.80}")
    return tuple(value)


def broadcast(**arrays) -> tuple:
    """The common shape of arguments that must broadcast together; a ValueError names the first misfit."""
    shapes = [np.shape(value) for value in arrays.values()]
    widest = max(shapes, key=len, default=())
    if all(s == widest or s == () for s in shapes):  # the usual case: one shape, and numbers
        return widest
    shape: tuple = ()
    seen: list[str] = []
    for name, value in arrays.items():
        try:
            shape = np.broadcast_shapes(shape, np.shape(value))
        except ValueError:
            raise ValueError(
                f"{name} has shape {np.shape(value)}, which does not broadcast against "
                f"{' and '.join(seen)} (shape {shape})"
            ) from None
        seen.append(name)
    return shape


# --------------------------------------------------------------------------- plausible ranges


def _hint(value: float, quantity: str) -> str:
    """A likely slip behind an implausible value, for the message (empty if none fits)."""
    r = PLAUSIBLE_RANGES[quantity]
    x = abs(value)
    # A slip multiplies by 3.6, 100 or 1000: a value just outside the range suggests none.
    if r.unit == "m/s" and x > 1.2 * r.high and x / 3.6 in r:
        return f": a speed in km/h? {x:g} km/h is {x / 3.6:.4g} m/s"
    if r.unit == "m" and x > 10.0 * r.high and x / 1000.0 in r:
        return f": a length in millimetres? {x:g} mm is {x / 1000.0:.4g} m"
    if r.unit == "" and x > 10.0 * r.high and x / 100.0 in r:
        return f": a percentage? {x:g} % is {x / 100.0:.4g}"
    if r.unit == "kg" and x * 1000.0 in r:
        return f": a mass in tonnes? {x:g} t is {x * 1000.0:.4g} kg"
    return ""


def _implausible(name, value, quantity, low, low_open, high, signed=False) -> str:
    r = PLAUSIBLE_RANGES[quantity]
    unit = f" {r.unit}" if r.unit else ""
    where = f"±{high}" if signed else interval_words(low, high, low_open, False)
    hint = _hint(float(value), quantity) if np.isfinite(value) else ""
    return (
        f"{name} must be {'within ' if signed else 'in '}{where}{unit} (the plausible range of {r.what}: "
        f"raildyn.constants.PLAUSIBLE_RANGES[{quantity!r}]), got {value!r}{hint}"
    )


def plausible(name: str, value, quantity: str, *, low=None, low_open=False, high=None, signed=False) -> float:
    """A finite float in the plausible range of ``quantity`` (a key of
    :data:`raildyn.constants.PLAUSIBLE_RANGES`): a unit slip (km/h for m/s, mm for m, a
    percentage for a friction coefficient) is refused with a message that suggests it.

    ``low`` replaces the range's lower bound (a function that accepts zero, or one that needs
    more), ``low_open`` makes it strict; ``high`` lowers the upper bound (a model valid in part
    of the range); ``signed`` accepts ``-high <= value <= high`` (a velocity that may run
    backwards).
    """
    r = PLAUSIBLE_RANGES[quantity]
    hi = r.high if high is None else min(high, r.high)
    lo = -hi if signed else (r.low if low is None else low)
    x = scalar(name, value)
    if x < lo or (low_open and x == lo) or x > hi:
        raise ValueError(_implausible(name, value, quantity, lo, low_open, hi, signed))
    return x


def plausible_array(
    name: str, value, quantity: str, *, low=None, low_open=False, signed=False, **options
) -> np.ndarray:
    """:func:`array` (with its ``options``: ``ndim``, ``shape``, ``allow_empty``) whose every entry
    is in the plausible range of ``quantity``, as :func:`plausible`."""
    r = PLAUSIBLE_RANGES[quantity]
    arr = array(name, value, **options)
    if arr.size:
        lo = -r.high if signed else (r.low if low is None else low)
        bad = (arr < lo) | (arr > r.high) | ((arr == lo) if low_open else False)
        if bad.any():
            raise ValueError(_implausible(name, arr[bad].flat[0], quantity, lo, low_open, r.high, signed))
    return arr


def plausible_fields(obj, quantity: str, names, *, low=None, low_open=False) -> None:
    """:func:`plausible` for each field of ``obj`` named in ``names`` (a dataclass's masses, say)."""
    for name in names:
        plausible(name, getattr(obj, name), quantity, low=low, low_open=low_open)


def friction(name: str, value, *, low_open=True) -> float:
    """A coefficient of friction μ in (0, 1] (``low_open=False``: [0, 1]); see
    :data:`raildyn.constants.PLAUSIBLE_RANGES` ``"friction"`` (30 for 0.3 is a percentage)."""
    return plausible(name, value, "friction", low=0.0, low_open=low_open)


def speed(name: str, value, *, low=0.0, low_open=True, high=None, signed=False) -> float:
    """A speed, m/s, in (0, :data:`raildyn.constants.MAXIMUM_SPEED`] (``low``, ``low_open``: the
    lower bound; ``high``: a lower upper bound; ``signed``: within ±MAXIMUM_SPEED, for a train
    that may back)."""
    return plausible(name, value, "speed", low=low, low_open=low_open, high=high, signed=signed)


def speeds(name: str, value, *, low=0.0, low_open=True) -> np.ndarray:
    """A non-empty 1-D array of finite speeds, m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]
    (creep forces divide by V; ``low``, ``low_open`` change the lower bound)."""
    V = array(name, np.atleast_1d(value), ndim=1)
    if V.size == 0:
        raise ValueError(f"{name} must not be empty: give at least one speed, m/s")
    return plausible_array(name, V, "speed", low=low, low_open=low_open)


#: The most memory one grid of samples (time steps, grid points) may take, bytes: 1 GiB, far beyond any
#: run the notebooks make (a few MB) and far below what a mistyped step asks for (a step of 1e-9 s over
#: ten seconds: 1e10 samples, tens of GiB).
MAX_BYTES = 2**30


def samples(
    name: str, value, span: float, step: float, *, per_sample: int = 1, limit: float = MAX_BYTES
) -> int:
    """The number of samples, ⌈span/step⌉ + 1, of a grid over ``span`` at ``step``, refused when their
    ``per_sample`` floats (8 bytes each) would take more than ``limit`` bytes.

    ``name`` and ``value`` are the caller's parameter that sets the step (a ``max_step``, a ``dt``);
    the message says how many samples and how much memory it would need, before anything is allocated.
    """
    n = span / step + 1.0 if step > 0 else math.inf
    need = n * max(per_sample, 1) * 8.0
    if not need <= limit:
        raise ValueError(
            f"{name} = {value!r} would need {n:.3g} samples over a span of {span:g}, about {_bytes(need)} "
            f"of memory (at most {_bytes(limit)}): take a larger {name} or a shorter span"
        )
    return int(math.ceil(span / step)) + 1


def _bytes(n: float) -> str:
    """A number of bytes in words (GiB, MiB or bytes)."""
    for unit, size in (("GiB", 2**30), ("MiB", 2**20)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n:.3g} bytes"


def speed_range(name: str, value) -> tuple[float, float]:
    """A pair (low, high) of speeds, m/s, with 0 < low < high <= :data:`~raildyn.constants.MAXIMUM_SPEED`
    (the bracket a critical speed is searched in)."""
    r = array(name, value)
    if r.shape != (2,):
        raise ValueError(f"{name} must be (low, high) in m/s, got {value!r}")
    low = speed(f"{name}[0]", float(r[0]))
    high = speed(f"{name}[1]", float(r[1]), low=low)
    return low, high


#: The largest smoothing speed v_ε of a regularised friction law F tanh(v/v_ε), m/s: the law stands for
#: the sign of v, so v_ε must be far below the sliding speeds it smooths (millimetres to centimetres a
#: second); 1 m/s already blurs the stick-slip of any damper or wedge.
MAX_SMOOTHING_SPEED = 1.0


#: The smallest: below a micrometre a second the smooth law is as steep as the ideal one, and the time
#: step it asks of an explicit scheme (about m v_ε/F) vanishes.
MIN_SMOOTHING_SPEED = 1.0e-6


def smoothing_speed(name: str, value) -> np.ndarray:
    """A non-empty array of smoothing speeds v_ε of a friction law, m/s, each in [1e-6, 1]."""
    arr = array(name, value, low=0.0, low_open=True, allow_empty=False)
    if arr.ndim == 0 and MIN_SMOOTHING_SPEED <= float(arr) <= MAX_SMOOTHING_SPEED:
        return arr
    bad = (arr < MIN_SMOOTHING_SPEED) | (arr > MAX_SMOOTHING_SPEED)
    if bad.any():
        raise ValueError(
            f"{name} must be in [{MIN_SMOOTHING_SPEED:g}, {MAX_SMOOTHING_SPEED:g}] m/s (v_ε smooths the "
            f"sign of a sliding velocity, far below it), got {arr[bad].flat[0]!r}"
        )
    return arr
