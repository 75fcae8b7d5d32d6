"""Command line: ``python -m raildyn figures --out DIR`` writes the registered figures;
``python -m raildyn notebooks DIR`` copies the chapter notebooks into DIR;
``python -m raildyn mark ANSWERS.csv KEY.py --out MARKS.csv`` marks a class's answers;
``python -m raildyn compile [--jobs N]`` compiles the numba kernels once, into numba's cache on disk.

The ``compile`` command: raildyn's compiled kernels carry ``cache=True``, so the first process that calls
one compiles it (1–30 s a path, 10–15 s for a chapter) and writes the machine code beside its source, in
the ``__pycache__`` folder of the kernel's module (or under ``NUMBA_CACHE_DIR`` where that is set, or the
user's cache where the package's folder cannot be written); every later process that imports the same
source file loads the code in milliseconds. :func:`warm` runs each compiled path once, on small inputs
of the types the chapters pass, so that an installation (the Makefile's ``install``, Binder's
``postBuild``, the notebooks' Colab cell) leaves the cache built before a reader's first click. Run on a
built cache, each step loads instead of compiling, and the whole takes a few seconds. numba keys a
cache entry on the source file (its path and modification time) and on the machine's processor: the
cache serves the processes that import the same files on the same kind of machine.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="raildyn", description=__doc__.partition("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    fig = sub.add_parser("figures", help="write the registered figures")
    fig.add_argument("--out", default="figures", help="output folder (default: figures)")
    fig.add_argument("--format", nargs="+", default=["png"], help="file formats, e.g. png svg pdf")
    fig.add_argument("--only", nargs="+", metavar="ID", help="only these figure ids")
    fig.add_argument("--list", action="store_true", help="list the figure ids and captions, write nothing")
    fig.add_argument("--data", action="store_true", help="also write each figure's data beside it, <id>.csv")
    books = sub.add_parser("notebooks", help="copy the chapter notebooks into a folder, to open in Jupyter")
    books.add_argument("out", help="the folder to copy them into (created if missing)")
    books.add_argument("--force", action="store_true", help="replace the notebooks of the same names there")
    grade = sub.add_parser("mark", help="mark a class's answers (CSV: student, exercise, answer)")
    grade.add_argument("answers", help="the class's answers, a CSV file with a header row")
    grade.add_argument("key", help="a Python file whose EXERCISES lists the raildyn.course.Exercise objects")
    grade.add_argument("--out", default="marks.csv", help="where to write the marks (default: marks.csv)")
    comp = sub.add_parser(
        "compile",
        help="compile raildyn's numba kernels into numba's cache on disk, so that no notebook waits for "
        "them (under a minute the first time, a few seconds after)",
    )
    comp.add_argument(
        "--jobs", type=int, default=1,
        help="processes to compile in, each taking the next path as it comes free (default 1; a kernel "
        "that two paths share may then be compiled twice, or loaded from the other's cache)",
    )  # fmt: skip
    args = parser.parse_args(argv)
    if args.command == "mark":
        return _mark(parser, args)
    if args.command == "notebooks":
        return _notebooks(parser, args)
    if args.command == "compile":
        if not 1 <= args.jobs <= 64:
            parser.error(f"--jobs must be an integer in [1, 64], got {args.jobs}")
        return _compile(args.jobs)

    import matplotlib

    matplotlib.use("Agg")  # the command line draws to files only
    from raildyn import figures

    if args.list:
        for spec in figures.REGISTRY.values():
            book = f" (book Fig. {spec.book_figure})" if spec.book_figure else ""
            print(f"{spec.id}{book}: {spec.caption}")
        return 0
    try:
        paths = figures.save_all(args.out, formats=args.format, ids=args.only, data=args.data)
    except ValueError as err:
        parser.error(str(err))
    for path in paths:
        print(path)
    return 0


def notebook_files() -> list[Path]:
    """The chapter notebooks that came with raildyn: in an installed wheel, the package's ``_notebooks``
    folder (setup.py copies them there); in a clone of the repository, its ``notebooks`` folder.

    Returns
    -------
    list of pathlib.Path
        The eleven ``.ipynb`` files, in chapter order.
    """
    package = Path(__file__).resolve().parent
    for folder in (package / "_notebooks", package.parent / "notebooks"):
        found = sorted(folder.glob("[0-9][0-9]_*.ipynb"))
        if found:
            return found
    raise FileNotFoundError(
        f"raildyn at {package} carries no chapter notebooks (no _notebooks, no ../notebooks)"
    )


def _notebooks(parser, args) -> int:
    """The ``notebooks`` command: copy the chapter notebooks into ``args.out``, never over a reader's own
    edits unless ``--force``."""
    import shutil

    out = Path(args.out)
    if out.exists() and not out.is_dir():
        parser.error(f"out must be a folder, got the file {args.out!r}")
    sources = notebook_files()
    taken = [p.name for p in sources if (out / p.name).exists()]
    if taken and not args.force:
        parser.error(f"{args.out!r} already holds {', '.join(taken)}: choose another folder or pass --force")
    out.mkdir(parents=True, exist_ok=True)
    for source in sources:
        shutil.copyfile(source, out / source.name)
        print(out / source.name)
    return 0


def _mark(parser, args) -> int:
    """The ``mark`` command: load KEY.py's EXERCISES, mark, print each student's score."""
    import importlib.util

    from raildyn import course

    spec = importlib.util.spec_from_file_location("raildyn_marking_key", args.key)
    if spec is None or not args.key.endswith(".py"):
        parser.error(f"key must be a Python file, got {args.key!r}")
    key = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(key)
        exercises = key.EXERCISES
    except (OSError, AttributeError) as err:
        parser.error(f"key {args.key!r} must define EXERCISES: {err}")
    try:
        totals = course.mark_csv(args.answers, exercises, args.out)
    except (ValueError, TypeError) as err:
        parser.error(str(err))
    for student, score in sorted(totals.items()):
        print(f"{student}: {score} of {len(exercises)}")
    print(f"marks written to {args.out}")
    return 0


def _compile(jobs: int = 1) -> int:
    """The ``compile`` command: run every compiled path once (in ``jobs`` processes), print each step's
    time and the cache."""
    import raildyn

    start = time.perf_counter()
    if jobs == 1:
        steps = warm()
        loaded, compiled = cache_counts()
        folders = cache_folders()
    else:
        import importlib
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor

        from raildyn._progress import progress_bar

        # New interpreters, not forks: each imports what its paths need, as a reader's kernel does. They
        # find the step by this module's importable name (run as ``-m``, it is ``__main__`` here).
        one = importlib.import_module("raildyn.__main__")._warm_one
        with ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("spawn")) as pool:
            done = list(progress_bar(pool.map(one, range(len(STEPS))), total=len(STEPS),
                                     desc="compiling raildyn's kernels"))  # fmt: skip
        steps = [(label, seconds) for label, seconds, _, _ in done]
        loaded, compiled = (sum(step[2][k] for step in done) for k in (0, 1))
        folders = sorted({f for step in done for f in step[3]})
    for label, seconds in steps:
        print(f"{seconds:7.2f} s  {label}")
    print(
        f"{time.perf_counter() - start:7.2f} s  in all (imports included): {compiled} kernels compiled, "
        f"{loaded} loaded from the cache, for raildyn at {raildyn.__path__[0]}"
    )
    if folders:
        print(f"numba's cache: under {os.path.commonpath(folders)}")
    return 0


def kernels() -> dict[str, object]:
    """Every numba function of raildyn imported so far, by its qualified name (``module.function``)."""
    from numba.core.registry import CPUDispatcher

    found = {}
    for name, module in list(sys.modules.items()):
        if name.startswith("raildyn.") and module is not None:
            for attr, value in list(vars(module).items()):
                if isinstance(value, CPUDispatcher) and value.py_func.__module__ == name:
                    found[f"{name}.{attr}"] = value
    return found


def _nonlinear_car():
    from raildyn import stability
    from raildyn.vehicles import LateralCar

    car = LateralCar().nonlinear()
    stability.bifurcation_diagram(car, [60.0, 90.0], duration=0.2, refine=1, progress=False)


def _nonlinear_wheelset():
    from raildyn import stability
    from raildyn.wheelset import NonlinearWheelset, WheelRailContact, Wheelset

    model = NonlinearWheelset(Wheelset(), WheelRailContact())
    stability.limit_cycle_amplitude(model, 60.0, duration=0.1)
    # The shooting's stacked right-hand side (the branch of limit cycles): two columns, one evaluation.
    rhs = model.compiled_rhs(60.0)
    n = model.state_size
    data = np.zeros((2, max(rhs.row.size, 3)))
    data[0, : rhs.row.size] = rhs.row
    data[1, :3] = [n, 0, 0]
    rhs.stacked(0.0, np.zeros(2 * n), 0, data, np.empty(2 * n))


def _profile_contact():
    from raildyn.contact import s1002_wheel, uic60_rail
    from raildyn.wheelset import Wheelset, contact_forces, profile_contact, wheel_forces

    pair = profile_contact(s1002_wheel(), uic60_rail(1 / 40))
    y = np.linspace(-5e-3, 5e-3, 3)
    contact_forces(Wheelset(), pair, y, 0.0, 0.0, 0.0, 30.0)
    wheel_forces(Wheelset(), pair, y, 0.0, 0.0, 0.0, 30.0)


def _curving():
    from raildyn.curving import quasi_static_curving
    from raildyn.vehicles import LateralCar

    quasi_static_curving(LateralCar().nonlinear(), 20.0, 1000.0, 0.1)


def _fastsim():
    import numba

    from raildyn.contact import fastsim

    # A batch large enough to share among numba's threads, where there are several, and a single state,
    # marched on the calling thread; each with and without the fields (a kernel compiled for each).
    xi = np.linspace(-2e-3, 2e-3, 64 * max(2, numba.get_num_threads()))
    for creepage in (1e-3, xi):
        for fields in (True, False):
            fastsim(creepage, 0.0, 0.0, 100e3, 0.3, 6e-3, 4e-3, fields=fields)


def _train():
    from raildyn import train

    model = train.braking_model(4, 1)
    train.simulate(model, 2.0, 20.0, initial_extension=model.gear.slack / 2, samples=3)
    model.rhs(0.0, np.zeros(2 * model.size))


def _bridge():
    from raildyn.bridge import AxleSequence, SimplySupportedBeam, crossing, moving_force_response, vehicle
    from raildyn.vehicles import VerticalCar

    beam = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=3)
    # A train of axle loads (the HSLM trains of chapter 10) and a vehicle take the same compiled paths.
    moving_force_response(beam, [20.0, 40.0], AxleSequence([0.0, 2.5], [1.0e5, 1.0e5]), samples=50)
    crossing(beam, vehicle(VerticalCar(), 1813.0), 40.0)


def _impact():
    from raildyn.bridge import DippedJoint, DiscreteTrack, Wheel, wheel_on_track

    track = DiscreteTrack(bays=30, quiet_bays=8)
    start = 9 * track.sleeper_spacing
    joint = DippedJoint(start + 0.1, (0.004, 0.004), 0.1)
    wheel_on_track(Wheel(), 30.0, joint, track=track, start=start, distance=0.3)
    track.receptance([50.0, 500.0])


def _rocking():
    from raildyn.vehicles import RockingFreightCar, rocking_run

    car = RockingFreightCar()
    car.static_roll(1.0e4)
    rocking_run(car, car.roll_resonance_speed(), cycles=4)


def _time_response():
    from raildyn.vehicles import VerticalCar, time_response

    t = np.linspace(0.0, 0.5, 51)
    time_response(VerticalCar(), lambda x, rails: 0.01 * np.sin(x), 30.0, t)


# The compiled paths, in the order of the chapters that meet them first.
STEPS: tuple[tuple[str, Callable[[], None]], ...] = (
    ("track: a wheel over a dipped joint, the discrete track's receptance", _impact),
    ("contact: FASTSIM, one state and a batch", _fastsim),
    ("wheelset: the nonlinear wheelset's limit cycle and its shooting", _nonlinear_wheelset),
    ("vehicle response: the ride's time march", _time_response),
    ("vehicle response: the rocking freight car", _rocking),
    ("stability: the nonlinear car's bifurcation diagram", _nonlinear_car),
    ("stability: the car on worn profiles", _profile_contact),
    ("curving: the quasi-static curving of the nonlinear car", _curving),
    ("train: a braking train", _train),
    ("bridge: moving forces and a car crossing a span", _bridge),
)


def warm(progress: bool = True) -> list[tuple[str, float]]:
    """Run every compiled path of raildyn once, so that numba compiles it and writes its cache.

    Parameters
    ----------
    progress : bool
        Show a progress bar over the steps.

    Returns
    -------
    list of (str, float)
        Each step's description and its wall time in seconds: the compile time on an empty cache, the
        load time on a built one.
    """
    from raildyn._progress import progress_bar

    times = []
    steps = progress_bar(STEPS, desc="compiling raildyn's kernels") if progress else STEPS
    for label, step in steps:
        start = time.perf_counter()
        step()
        times.append((label, time.perf_counter() - start))
    return times


def _warm_one(index: int) -> tuple[str, float, tuple[int, int], list[str]]:
    """One step of :data:`STEPS`, in a process of ``compile --jobs``: its label, its time, the kernels it
    loaded and compiled, and the cache's folders."""
    label, step = STEPS[index]
    before = cache_counts()
    start = time.perf_counter()
    step()
    seconds = time.perf_counter() - start
    after = cache_counts()
    return label, seconds, (after[0] - before[0], after[1] - before[1]), cache_folders()


def cache_counts() -> tuple[int, int]:
    """How many of the kernels run so far numba loaded from its cache, and how many it compiled."""
    loaded = compiled = 0
    for kernel in kernels().values():
        loaded += sum(kernel.stats.cache_hits.values())
        compiled += sum(kernel.stats.cache_misses.values())
    return loaded, compiled


def cache_folders() -> list[str]:
    """The folders of numba's cache of the kernels run so far: ``__pycache__`` beside each kernel's module,
    or under ``NUMBA_CACHE_DIR`` where that is set (or the user's cache where the package is read-only)."""
    return sorted({k.stats.cache_path for k in kernels().values() if k.stats.cache_path})


if __name__ == "__main__":
    sys.exit(main())
