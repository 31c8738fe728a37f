"""The default test run disables benchmarking (``--benchmark-disable`` in addopts): each
case runs once, as a smoke test. Asking for timings (``--benchmark-only``, ``--benchmark-save``,
``--benchmark-autosave``, ``--benchmark-compare``) turns benchmarking back on, as
``--benchmark-enable`` would."""

from __future__ import annotations

import pytest

TIMING_OPTIONS = ("benchmark_only", "benchmark_save", "benchmark_autosave", "benchmark_compare")


@pytest.hookimpl(tryfirst=True)
def pytest_configure(config: pytest.Config) -> None:
    if any(config.getoption(option, None) for option in TIMING_OPTIONS):
        config.option.benchmark_enable = True
