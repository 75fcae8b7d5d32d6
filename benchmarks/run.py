"""raildyn benchmarks: each timed task beside its baseline, measured in the same run.

Absolute times drift on a shared machine; the ratios hold. Each case reports the
median of several repeats for raildyn and for its baseline, and their ratio.
Cases live in ``benchmarks/bench_*.py`` (see ``benchmarks/common.py``).

    python benchmarks/run.py                 # all cases: a table, and benchmarks/latest.json
    python benchmarks/run.py --quick         # 3 repeats instead of 15
    python benchmarks/run.py --only ch01     # files whose name contains "ch01"
    python benchmarks/run.py --only cold     # first calls in fresh processes, numba's cache empty or built
    python benchmarks/run.py --only imports  # each chapter's cold import (bench_imports.py)
"""

from __future__ import annotations

import argparse
import importlib
import json
import os
import platform
import statistics
import sys
from datetime import date
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))


def table(cases) -> str:
    rows = [
        "| case | raildyn median (ms) | baseline | baseline median (ms) | ratio | goal |",
        "|---|---|---|---|---|---|",
    ]
    for c in cases:
        rows.append(
            f"| {c.name} | {1e3 * statistics.median(c.raildyn):.2f} | {c.baseline_name} | "
            f"{1e3 * statistics.median(c.baseline):.2f} | {c.ratio:.1f}× | {c.goal} |"
        )
    return "\n".join(rows)


def main(argv=None) -> int:
    raw = argparse.RawDescriptionHelpFormatter
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=raw)
    parser.add_argument("--quick", action="store_true", help="3 repeats instead of 15")
    parser.add_argument("--only", default="", help="run only the files whose name contains this text")
    args = parser.parse_args(argv)
    repeats = 3 if args.quick else 15
    files = sorted(p.stem for p in HERE.glob("bench_*.py") if args.only in p.stem)
    cases = []
    for name in files:
        cases += importlib.import_module(f"benchmarks.{name}").cases(repeats)
    threads = os.environ.get("OPENBLAS_NUM_THREADS", "default")
    print(
        f"raildyn benchmarks, {date.today()}, {platform.machine()}, Python {platform.python_version()}, "
        f"{repeats} repeats, BLAS threads: {threads}\n"
    )
    print(table(cases))
    out = {c.name: {"raildyn_s": c.raildyn, "baseline_s": c.baseline, "ratio": c.ratio} for c in cases}
    (HERE / "latest.json").write_text(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
