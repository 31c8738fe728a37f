"""PDDL input: the reader, the lifted task, plan validation and translation to the
framework's first-order :class:`~strips_framework.worldmodel.problem.Problem`.

Only the reader is imported eagerly: the CLI's start-up time counts when solving small
tasks, and validation and translation pull in more of the framework.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from strips_framework.pddl.files import find_domain, is_pddl, load_task, parse_task
from strips_framework.pddl.task import PddlTask

if TYPE_CHECKING:
    from strips_framework.worldmodel.problem import Problem

__all__ = ["PddlTask", "find_domain", "is_pddl", "load_task", "parse_task", "to_problem"]


def to_problem(task: PddlTask) -> Problem:
    """The framework problem of ``task`` (see :mod:`strips_framework.pddl.translation`)."""
    from strips_framework.pddl.translation import to_problem as translate

    return translate(task)
