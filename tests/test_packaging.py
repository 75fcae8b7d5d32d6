"""raildyn as a package: one source for its dependency ranges, one tested set of versions, and a wheel that
installs and runs.

* pyproject.toml holds every range (the package's dependencies and its extras); requirements.txt only
  installs the package with its "dev" extra, so the two cannot disagree;
* constraints.txt pins one version of each dependency that ``make install`` installs with, each inside
  pyproject.toml's ranges;
* ``python -m build`` gives an sdist and a wheel built from it; the wheel carries the data the models read
  and the chapter notebooks, with its licence as an SPDX expression; installed in a fresh environment it
  passes tests/smoke.py.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import sysconfig
import tomllib
import zipfile
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

ROOT = Path(__file__).resolve().parents[1]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]


def _ranges() -> dict[str, list[Requirement]]:
    """Every requirement pyproject.toml writes, by package: its dependencies and each extra's."""
    found: dict[str, list[Requirement]] = {}
    lines = PYPROJECT["dependencies"] + [
        r for extra in PYPROJECT["optional-dependencies"].values() for r in extra
    ]
    for line in lines:
        req = Requirement(line)
        if canonicalize_name(req.name) != "raildyn":  # the "dev" extra names the others
            found.setdefault(canonicalize_name(req.name), []).append(req)
    return found


def _pins() -> dict[str, str]:
    pins = {}
    for line in (ROOT / "constraints.txt").read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            match = re.fullmatch(r"([A-Za-z0-9._-]+)==([^\s;]+)", line.strip())
            assert match, f"constraints.txt: {line!r} is not name==version"
            pins[canonicalize_name(match.group(1))] = match.group(2)
    return pins


def test_requirements_txt_writes_no_range_of_its_own():
    lines = [line.strip() for line in (ROOT / "requirements.txt").read_text(encoding="utf-8").splitlines()]
    assert [line for line in lines if line and not line.startswith("#")] == ["-e .[dev]"]
    assert set(PYPROJECT["optional-dependencies"]["dev"][0].partition("[")[2].rstrip("]").split(",")) == (
        set(PYPROJECT["optional-dependencies"]) - {"dev"}
    ), "the dev extra gathers every other extra"


def test_the_install_in_two_steps_installs_what_requirements_txt_names():
    # make install: raildyn (`-e .`) with its dependencies, then scripts/extras.py's list of the dev
    # extra while the kernels compile; together, what `-e .[dev]` installs.
    sys.path.insert(0, str(ROOT / "scripts"))
    import extras

    listed = extras.requirements("dev")
    assert len(listed) == len(set(listed))
    assert set(listed) == {
        r for name, rs in PYPROJECT["optional-dependencies"].items() if name != "dev" for r in rs
    }
    assert not any(canonicalize_name(Requirement(r).name) == "raildyn" for r in listed)
    with pytest.raises(
        ValueError, match=r"extra must be one of \['app', 'book', 'dev', 'tables', 'test'\], got 'docs'"
    ):
        extras.requirements("docs")


def test_every_range_is_pinned_inside_it():
    pins = _pins()
    for name, requirements in _ranges().items():
        assert name in pins, f"constraints.txt pins no version of {name}"
        for req in requirements:
            assert req.specifier.contains(pins[name], prereleases=True), (
                f"constraints.txt pins {name}=={pins[name]}, outside pyproject.toml's {req}"
            )


def test_the_running_environment_is_the_tested_set():
    # What make install installed is what constraints.txt pins (after an upgrade: make constraints).
    from importlib.metadata import version

    pins = _pins()
    drift = {name: (version(name), pins[name]) for name in _ranges() if version(name) != pins[name]}
    assert not drift, f"installed differs from constraints.txt (installed, pinned): {drift}"


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> dict[str, Path]:
    """The sdist and the wheel that ``python -m build`` makes (the wheel from the sdist, as it does)."""
    out = tmp_path_factory.mktemp("dist")
    subprocess.run(
        [sys.executable, "-m", "build", "--no-isolation", "--outdir", str(out), str(ROOT)],
        check=True, capture_output=True, text=True,
    )  # fmt: skip
    (sdist,) = out.glob("raildyn-*.tar.gz")
    (wheel,) = out.glob("raildyn-*.whl")
    return {"sdist": sdist, "wheel": wheel}


@pytest.mark.slow  # builds the sdist and the wheel (about 10 s)
def test_the_wheel_carries_the_data_the_notebooks_and_an_spdx_licence(built):
    names = zipfile.ZipFile(built["wheel"]).namelist()
    notebooks = sorted(p.name for p in (ROOT / "notebooks").glob("*.ipynb"))
    assert sorted(n.rsplit("/", 1)[1] for n in names if n.startswith("raildyn/_notebooks/")) == notebooks
    for data in ("raildyn/contact/data/worn_wheel_na_heavy_haul.txt", "raildyn/validation/data/README.md"):
        assert data in names
    assert any(n.startswith("raildyn/validation/data/") and n.endswith(".npz") for n in names)
    assert not any("__pycache__" in n or n.startswith("tests/") for n in names)
    metadata = zipfile.ZipFile(built["wheel"]).read("raildyn-0.1.0.dist-info/METADATA").decode()
    assert "License-Expression: MIT" in metadata and "License-File: LICENSE" in metadata
    assert "raildyn-0.1.0.dist-info/licenses/LICENSE" in names


@pytest.mark.slow  # a fresh environment and the smoke test (about 15 s)
def test_the_wheel_installs_in_a_fresh_environment_and_runs(built, tmp_path):
    # A new virtual environment holds the wheel alone; its dependencies are the tested set of this one,
    # reached through a path file (plain paths: the editable raildyn's own finder is not loaded there).
    fresh = tmp_path / "fresh"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(fresh)], check=True)
    python = fresh / "bin" / "python"
    subprocess.run(
        [sys.executable, "-m", "pip", "--python", str(python), "install", "--quiet", "--no-deps",
         "--no-index", str(built["wheel"])],
        check=True, capture_output=True, text=True,
    )  # fmt: skip
    site = subprocess.run(
        [python, "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
        check=True, capture_output=True, text=True,
    ).stdout.strip()  # fmt: skip
    Path(site, "tested_dependencies.pth").write_text(sysconfig.get_path("purelib") + "\n", encoding="utf-8")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    env["RAILDYN_PROGRESS"] = "0"
    run = subprocess.run(
        [python, str(ROOT / "tests" / "smoke.py"), str(tmp_path)],
        cwd=tmp_path, env=env, capture_output=True, text=True,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr[-3000:]
    out = run.stdout
    assert f"raildyn from {Path(site) / 'raildyn'}" in out, out  # the wheel's copy, not this checkout
    assert "notebooks copied: 11" in out and "fig1.4.csv" in out and "data read:" in out
    # Every dependency the wheel declares is met there, by the tested set.
    requires = subprocess.run(
        [python, "-c", "from importlib.metadata import requires, version\n"
         "from packaging.requirements import Requirement\n"
         "for line in requires('raildyn'):\n"
         "    r = Requirement(line)\n"
         "    if r.marker is None or r.marker.evaluate({'extra': ''}):\n"
         "        print(r.name, r.specifier.contains(version(r.name), prereleases=True))"],
        check=True, capture_output=True, text=True, env=env, cwd=tmp_path,
    ).stdout.split("\n")  # fmt: skip
    declared = [line.split() for line in requires if line]
    assert len(declared) == len(PYPROJECT["dependencies"])
    assert all(ok == "True" for _, ok in declared), declared
