"""Print the requirements of one of raildyn's extras, one a line, as pip reads them.

pyproject.toml's lines for the extra, with an extra that names others (``raildyn[tables,book]``) expanded and
raildyn itself left out. ``make install`` installs raildyn first, then these while its kernels compile: a
second ``pip install -e .[dev]`` would reinstall raildyn under the compiling processes.

Usage: ``python scripts/extras.py EXTRA``
"""

from __future__ import annotations

import re
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def requirements(extra: str) -> list[str]:
    """The requirement lines of ``extra``, the extras it names expanded, each line once, in order."""
    extras = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"][
        "optional-dependencies"
    ]
    if extra not in extras:
        raise ValueError(f"extra must be one of {sorted(extras)}, got {extra!r}")
    found: list[str] = []
    for line in extras[extra]:
        named = re.fullmatch(r"raildyn\[([\w,\s-]+)\]", line.strip())
        for requirement in (
            (r for e in named.group(1).split(",") for r in requirements(e.strip())) if named else [line]
        ):
            if requirement not in found:
                found.append(requirement)
    return found


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__.rpartition("Usage: ")[2])
    print("\n".join(requirements(sys.argv[1])))
