"""The Binder configuration alone gives an environment in which the notebooks run (tests/binder_env.py).

The environment is built in the background from the start of the session (tests/conftest.py starts it
once this module is collected); the test waits for it and reads what it printed.
"""

from __future__ import annotations

import pytest


@pytest.mark.slow
def test_binder_configuration_alone_runs_notebook_01(binder_run):
    proc, out, work = binder_run
    assert proc.returncode == 0, out[-4000:]
    assert "notebook ran:" in out
    # raildyn came from the Binder environment's own install, not from this checkout.
    assert f"raildyn from {work / 'venv'}" in out
