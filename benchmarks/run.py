"""raildyn benchmarks: each timed task beside its baseline, measured in the same run.

Absolute times drift on a shared machine; the ratios hold. Each case reports the
median of several repeats for raildyn and for the baseline, and their ratio.

    python benchmarks/run.py            # all cases, table to stdout and benchmarks/latest.json
    python benchmarks/run.py --quick    # fewer repeats
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import sys
import time
from dataclasses import dataclass
from datetime import date
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))

from raildyn.widgets import chapter01  # noqa: E402


@dataclass
class Case:
    name: str
    raildyn: list[float]
    baseline: list[float]
    goal: str

    @property
    def ratio(self) -> float:
        return statistics.median(self.baseline) / statistics.median(self.raildyn)


def _timed(fn, repeats: int) -> list[float]:
    times = []
    for i in range(repeats):
        start = time.perf_counter()
        fn(i)
        times.append(time.perf_counter() - start)
    return times


# For each chapter-1 widget: a cycle of control values that a student might drag through.
# A move that rescales an axis redraws the whole picture; the others redraw only the moving curves.
WIDGET_MOVES = {
    "free_vibration ξ": (chapter01.FREE_VIBRATION, "damping_ratio", [0.05, 0.1, 0.3, 0.7, 1.0, 1.5]),
    "free_vibration ω_n": (chapter01.FREE_VIBRATION, "natural_frequency", [3.0, 5.0, 8.0, 12.0, 16.0, 19.0]),
    "chain_modes number of masses": (chapter01.CHAIN_MODES, "dof", [2, 3]),
    "forced_response ξ": (chapter01.FORCED_RESPONSE, "damping_ratio", [0.05, 0.1, 0.2, 0.4, 0.7, 1.0]),
    "chain_modes k_i/k₁": (chapter01.CHAIN_MODES, "stiffness_ratio", [0.5, 0.8, 1.0, 1.5, 2.0, 2.5]),
    "random_response f_n": (chapter01.RANDOM_RESPONSE, "frequency_hz", [0.8, 1.2, 1.6, 2.0, 2.6, 3.2]),
    "random_response seed": (chapter01.RANDOM_RESPONSE, "seed", [2, 3, 4, 5, 6, 7]),
}


def widget_cases(repeats: int) -> list[Case]:
    """Update of the live widget (model + redraw of the same figure) against a new figure per change."""
    cases = []
    for name, (recipe, control, values) in WIDGET_MOVES.items():
        _, update = recipe.build()
        update(**{control: values[-1]})  # warm the caches before timing
        moves = [{control: v} for v in values]
        live = _timed(lambda i, u=update, m=moves: u(**m[i % len(m)]), repeats)
        naive = _timed(lambda i, r=recipe, m=moves: r.fresh_frame(**m[i % len(m)]), repeats)
        cases.append(Case(f"widget {name}", live, naive, "median ≤ 50 ms, ≥ 3× faster"))
    return cases


def table(cases: list[Case]) -> str:
    rows = ["| case | raildyn median (ms) | baseline median (ms) | ratio | goal |", "|---|---|---|---|---|"]
    for c in cases:
        rows.append(
            f"| {c.name} | {1e3 * statistics.median(c.raildyn):.1f} | "
            f"{1e3 * statistics.median(c.baseline):.1f} | {c.ratio:.1f}× | {c.goal} |"
        )
    return "\n".join(rows)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--quick", action="store_true", help="3 repeats instead of 15")
    args = parser.parse_args(argv)
    repeats = 3 if args.quick else 15
    cases = widget_cases(repeats)
    print(
        f"raildyn benchmarks, {date.today()}, {platform.machine()}, Python {platform.python_version()}, "
        f"{repeats} repeats\n"
    )
    print(table(cases))
    out = {c.name: {"raildyn_s": c.raildyn, "baseline_s": c.baseline, "ratio": c.ratio} for c in cases}
    (HERE / "latest.json").write_text(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
