"""docs/api.md's examples run as written, from the repository root, in one namespace (a
later block may use what an earlier one imported); each block's assertions are the
claims the text makes."""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
API = ROOT / "docs" / "api.md"
BLOCKS = re.findall(r"```python\n(.*?)```", API.read_text(), re.DOTALL)


def test_the_api_document_has_examples():
    assert len(BLOCKS) >= 3


def test_the_examples_run(monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]):
    monkeypatch.chdir(ROOT)
    namespace: dict[str, object] = {}
    for number, block in enumerate(BLOCKS, 1):
        exec(compile(block, f"{API}:block {number}", "exec"), namespace)
    printed = capsys.readouterr().out
    assert "(goto2 BOX1)" in printed and "world-model" in printed


def test_version_is_the_distribution_version():
    from importlib.metadata import version

    import strips_framework

    assert strips_framework.__version__ == version("strips-framework")
    assert os.fspath(API)  # the document exists where README links it
