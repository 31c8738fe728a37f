"""The one output of ``strips solve``, for both families of search: the text form (the
plan in IPC form, then ``; name: value`` comment lines, so that the whole output is itself
a valid plan file) and the JSON document (``docs/output.md`` gives its schema)."""

from __future__ import annotations

from typing import Any

from strips_framework import exit_codes
from strips_framework.result import Result, Status, limit_key

#: The ``schema`` field of the JSON document: bumped when a field changes meaning or goes.
SCHEMA = "strips-result/1"


def text_lines(result: Result) -> list[str]:
    """The plan steps, then the status, plan length and cost, the run's time and the
    family's figures as comments."""
    length = len(result.plan) if result.plan is not None else "-"
    cost = result.cost if result.cost is not None else "-"
    header = [
        f"status: {result.status}",
        f"plan length: {length}",
        f"plan cost: {cost}",
        f"time: {result.seconds:.3f} s",
    ]
    return [*(result.plan or ()), *(f"; {line}" for line in header + result.statistics.lines())]


def limit_lines(status: Status, seconds: float) -> list[str]:
    """The text output of a run that a limit ended before any search began."""
    return [
        f"; status: {status} (before the search began: while reading or grounding)",
        f"; time: {seconds:.3f} s",
    ]


def document(
    result: Result | None,
    status: Status,
    seconds: float,
    problem: str,
    domain: str | None,
    config: dict[str, str],
) -> dict[str, Any]:
    """The JSON document of a run; ``result`` is ``None`` when a limit ended it before the
    search began (``family`` and ``statistics`` are then ``null``)."""
    plan = result.plan if result is not None else None
    return {
        "schema": SCHEMA,
        "problem": problem,
        "domain": domain,
        "status": str(status),
        "limit": limit_key(status),
        "exit_code": exit_codes.for_status(status),
        "plan": list(plan) if plan is not None else None,
        "plan_length": len(plan) if plan is not None else None,
        "cost": result.cost if result is not None else None,
        "uses_costs": result.uses_costs if result is not None else False,
        "seconds": round(seconds, 4),
        "family": result.statistics.family if result is not None else None,
        "statistics": result.statistics.as_dict() if result is not None else None,
        "config": config,
    }

