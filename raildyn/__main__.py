"""Command line: ``python -m raildyn figures --out DIR`` writes the registered figures."""

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
    args = parser.parse_args(argv)

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


if __name__ == "__main__":
    sys.exit(main())
