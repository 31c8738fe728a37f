"""docs/output.md documents one JSON schema for both families: the document
``strips solve --json`` prints has exactly the fields of its table, for a world-model
search, a forward search and a run stopped before its search."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from strips_framework.cli.main import main
from strips_framework.cli.report import SCHEMA

ROOT = Path(__file__).resolve().parents[1]
DOC = (ROOT / "docs" / "output.md").read_text()
FIELDS = re.findall(r"^\| `(\w+)` \|", DOC.split("## JSON", 1)[1].split("\n## ", 1)[0], re.M)


def _statistics_fields(family: str) -> set[str]:
    """The fields the document lists for ``family``'s statistics record."""
    start = re.search(f'(?i)for `"{family}"`:', DOC)
    assert start is not None, f"docs/output.md lists no statistics for {family}"
    text = DOC[start.end():].split("For `", 1)[0].split("\n\n", 1)[0]
    return set(re.findall(r"`(\w+)`", text))


@pytest.mark.parametrize(("args", "family"), [
    (["examples/three-boxes.strips"], "world-model"),
    (["examples/pddl/blocksworld/p4.pddl"], "forward"),
    (["examples/pddl/blocksworld/p4.pddl", "--config", "examples/configs/lifted.toml"], "lifted"),
])
def test_the_json_document_has_the_documented_fields(monkeypatch, capsys, args, family):
    monkeypatch.chdir(ROOT)
    assert main(["solve", *args, "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert list(document) == FIELDS
    assert document["schema"] == SCHEMA == "strips-result/1"
    assert document["family"] == family
    assert set(document["statistics"]) == _statistics_fields(family)


def test_statistics_in_json_keep_field_order_and_round_only_their_float_figures():
    from strips_framework.forward.result import ForwardStatistics
    from strips_framework.lifted.result import LiftedStatistics

    forward = ForwardStatistics(expanded=3, search_seconds=0.123456789, peak_memory_mib=17.84)
    assert list(forward.as_dict()) == list(ForwardStatistics.FIELDS)
    assert forward.as_dict()["expanded"] == 3
    assert forward.as_dict()["search_seconds"] == 0.1235
    assert forward.as_dict()["peak_memory_mib"] == 17.8
    lifted = LiftedStatistics(states=2, bytes_per_state=173.96, setup_seconds=1.000049)
    assert list(lifted.as_dict()) == list(LiftedStatistics.FIELDS)
    assert (lifted.as_dict()["bytes_per_state"], lifted.as_dict()["setup_seconds"]) == (174.0, 1.0)
