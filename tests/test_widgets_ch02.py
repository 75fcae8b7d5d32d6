"""Chapter 2 widgets driven without a browser: every control changes the picture, in place."""

import numpy as np
import pytest
from widget_helpers import status_line

from raildyn import integrators
from raildyn.errors import SolverError
from raildyn.widgets import chapter02


def test_scheme_response_prints_errors_and_reports_instability():
    container, update = chapter02.scheme_response()
    update(method="average_acceleration", dt_over_T=0.1, damping_ratio=0.0)
    status = status_line(container)
    # Average acceleration at Δt/T = 0.1: period elongation 0.2π/(2 arctan 0.1π) − 1 = 3.21 %, no decay.
    assert "largest error" in status and "+3.21 %" in status and "+0.00 %" in status
    update(method="central_difference", dt_over_T=0.5)
    assert "unstable" in status_line(container) and "diverged at step" in status_line(container)


def test_accuracy_chart_gives_the_stability_limit():
    container, update = chapter02.accuracy_chart()
    update(method="central_difference", damping_ratio=0.0)
    assert "Δt/T ≤ 0.3183" in status_line(container)  # 1/π
    update(method="houbolt")
    assert "unconditionally stable" in status_line(container)


def test_an_unstable_run_draws_the_part_computed_before_the_blow_up():
    container, update = chapter02.scheme_response()
    update(method="central_difference", dt_over_T=0.5, damping_ratio=0.0)
    scheme = next(ln for ln in container.live.figure.axes[0].lines if ln.get_label() == "scheme")
    t = np.arange(11) * 0.5  # five periods of T = 1 s
    with pytest.raises(SolverError) as info:
        integrators.central_difference(1.0, 0.0, (2 * np.pi) ** 2, t, 1.0, 0.0)
    part = info.value.partial
    # The drawn samples are the error's partial history (clipped to ±10 x₀ for drawing).
    assert np.array_equal(scheme.get_xdata(), part.t)
    assert np.array_equal(scheme.get_ydata(), np.clip(part.x[0], -10.0, 10.0))
    assert f"diverged at step {info.value.step} (t = {info.value.time:.2f} s)" in status_line(container)
    # Back to a stable step: the whole run is drawn.
    update(dt_over_T=0.25)
    assert scheme.get_xdata().size == 21 and "largest error" in status_line(container)
