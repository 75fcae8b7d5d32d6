"""Chapter 2 widgets driven without a browser: every control changes the picture, in place."""

from raildyn.widgets import chapter02


def _status(container):
    return container.children[-2].children[-1].value


def test_scheme_response_prints_errors_and_reports_instability():
    container, update = chapter02.scheme_response()
    update(method="average_acceleration", dt_over_T=0.1, damping_ratio=0.0)
    status = _status(container)
    # Average acceleration at Δt/T = 0.1: period elongation 0.2π/(2 arctan 0.1π) − 1 = 3.21 %, no decay.
    assert "largest error" in status and "+3.21 %" in status and "+0.00 %" in status
    update(method="central_difference", dt_over_T=0.5)
    assert "unstable" in _status(container) and "diverged at step" in _status(container)


def test_accuracy_chart_gives_the_stability_limit():
    container, update = chapter02.accuracy_chart()
    update(method="central_difference", damping_ratio=0.0)
    assert "Δt/T ≤ 0.3183" in _status(container)  # 1/π
    update(method="houbolt")
    assert "unconditionally stable" in _status(container)
