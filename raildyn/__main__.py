"""Command line: ``python -m raildyn figures --out DIR`` writes the registered figures;
``python -m raildyn mark ANSWERS.csv KEY.py --out MARKS.csv`` marks a class's answers;
``python -m raildyn compile`` compiles the numba kernels once, into numba's cache on disk."""

from __future__ import annotations

import argparse
import sys


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="raildyn", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    fig = sub.add_parser("figures", help="write the registered figures")
    fig.add_argument("--out", default="figures", help="output folder (default: figures)")
    fig.add_argument("--format", nargs="+", default=["png"], help="file formats, e.g. png svg pdf")
    fig.add_argument("--only", nargs="+", metavar="ID", help="only these figure ids")
    fig.add_argument("--list", action="store_true", help="list the figure ids and captions, write nothing")
    grade = sub.add_parser("mark", help="mark a class's answers (CSV: student, exercise, answer)")
    grade.add_argument("answers", help="the class's answers, a CSV file with a header row")
    grade.add_argument("key", help="a Python file whose EXERCISES lists the raildyn.course.Exercise objects")
    grade.add_argument("--out", default="marks.csv", help="where to write the marks (default: marks.csv)")
    sub.add_parser(
        "compile",
        help="compile raildyn's numba kernels into numba's cache on disk, so that no notebook waits for "
        "them (about two minutes the first time, a few seconds after)",
    )
    args = parser.parse_args(argv)
    if args.command == "mark":
        return _mark(parser, args)
    if args.command == "compile":
        return _compile()

    import matplotlib

    matplotlib.use("Agg")  # the command line draws to files only
    from raildyn import figures

    if args.list:
        for spec in figures.REGISTRY.values():
            book = f" (book Fig. {spec.book_figure})" if spec.book_figure else ""
            print(f"{spec.id}{book}: {spec.caption}")
        return 0
    try:
        paths = figures.save_all(args.out, formats=args.format, ids=args.only)
    except ValueError as err:
        parser.error(str(err))
    for path in paths:
        print(path)
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


def _compile() -> int:
    """The ``compile`` command: run every compiled path once, print each step's time and the cache."""
    import os
    import time

    import raildyn
    from raildyn import _warm

    start = time.perf_counter()
    steps = _warm.warm()
    for label, seconds in steps:
        print(f"{seconds:7.2f} s  {label}")
    loaded, compiled = _warm.cache_counts()
    print(
        f"{time.perf_counter() - start:7.2f} s  in all (imports included): {compiled} kernels compiled, "
        f"{loaded} loaded from the cache, for raildyn at {raildyn.__path__[0]}"
    )
    folders = _warm.cache_folders()
    if folders:
        print(f"numba's cache: under {os.path.commonpath(folders)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
