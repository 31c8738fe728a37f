from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))

import figures  # noqa: E402


@pytest.fixture(scope="session")
def launched():
    """Headless Chromium (Debian's), or a skip saying why it cannot be had."""
    reason = figures.unavailable()
    if reason is not None:
        pytest.skip(reason)
    return figures.shared_browser()
