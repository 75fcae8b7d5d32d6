"""The project's fuzz test: every public callable refuses bad input clearly (issue 15).

For each public callable the registry (``tests/fuzz_cases/``) gives one valid call; the
test changes one argument at a time to a bad value (``tests/fuzzing.py`` lists them) and
requires each changed call to be refused with a ValueError or TypeError naming that
parameter, or to return a finite result for a change the entry declares valid. Hangs,
silent NaN/inf/empty results, accepted nonsense and obscure exceptions fail.

``python tests/test_fuzz.py [prefix ...]`` prints the counts of every outcome by kind and the
share of the bad calls refused clearly (see :func:`fuzzing.share_refused`).
"""

from __future__ import annotations

import collections
import inspect
import os
import sys
import tempfile
import time
import warnings

import pytest
from fuzz_cases import entries
from fuzzing import (
    FAILURES,
    OUTCOMES,
    bad_numbers,
    public_callables,
    resolve,
    run,
    share_refused,
    valid_result,
)

ENTRIES = entries()
BY_TARGET = {e.target: e for e in ENTRIES}

#: The outcomes counted by ``test_bad_input_is_refused_clearly``, by target, for the package's share.
SEEN: dict[str, collections.Counter] = {}


def test_every_public_callable_has_one_entry():
    targets = collections.Counter(id(resolve(e.target)) for e in ENTRIES)
    public = public_callables()
    twice = [e.target for e in ENTRIES if targets[id(resolve(e.target))] > 1]
    assert not twice, f"callables with more than one registry entry: {twice}"
    missing = sorted(name for key, name in public.items() if key not in targets)
    assert not missing, f"{len(missing)} public callables without a fuzz registry entry: {missing}"
    strays = sorted(e.target for e in ENTRIES if id(resolve(e.target)) not in public)
    assert not strays, f"registry entries for callables that are not public: {strays}"


@pytest.mark.parametrize("target", sorted(BY_TARGET))
def test_bad_input_is_refused_clearly(target, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # a changed path argument (a relative "abc") writes here
    entry = BY_TARGET[target]
    if inspect.signature(resolve(entry.target, static=False)).parameters:
        # Without parameters (a widget factory) only the unknown keyword applies, which Python
        # refuses before the body runs; the widget tests make the valid call.
        where = bad_numbers(valid_result(entry), entry.infinite)
        assert where is None, f"the registry's valid call of {target} returns {where}"
    outcomes = run(entry)
    SEEN[target] = collections.Counter(o.kind for o in outcomes)
    failures = [o for o in outcomes if o.kind in FAILURES]
    assert not failures, f"{len(failures)} bad outcomes:\n" + "\n".join(map(str, failures))


def test_every_bad_call_is_refused_or_declared_valid():
    """Over every entry the test above ran: the share of bad calls refused clearly is 1 (all)."""
    if not SEEN:
        pytest.skip("no entry ran (a selection without test_bad_input_is_refused_clearly)")
    counts = sum(SEEN.values(), collections.Counter())
    share = share_refused(counts)
    print(f"\nfuzz: {share:.2%} of {counts.total() - counts['accepted']} bad calls refused clearly "
          f"over {len(SEEN)} callables: {dict(counts)}")  # fmt: skip
    assert share == 1.0, f"only {share:.4%} of the bad calls are refused clearly: {dict(counts)}"


def report(*prefixes: str) -> collections.Counter:
    """Count the outcomes of every entry whose target starts with one of ``prefixes``; print the failures."""
    counts = collections.Counter()
    start = time.perf_counter()
    for entry in ENTRIES:
        if prefixes and not entry.target.startswith(prefixes):
            continue
        for outcome in run(entry):
            counts[outcome.kind] += 1
            if outcome.kind in FAILURES:
                print(outcome)
    print({kind: counts[kind] for kind in OUTCOMES}, f"{time.perf_counter() - start:.1f} s")
    bad = counts.total() - counts["accepted"]
    clear = counts["refused"] + counts["solver"]
    print(f"bad calls refused clearly: {share_refused(counts):.2%} ({clear} of {bad}; {bad - clear} not)")
    return counts


if __name__ == "__main__":
    warnings.simplefilter("error")  # as under pytest (filterwarnings = error)
    with tempfile.TemporaryDirectory() as folder:
        os.chdir(folder)  # a changed path argument (a relative "abc") writes here
        report(*sys.argv[1:])
