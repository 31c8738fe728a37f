"""The macro learner's plugin kind, and the builtin macro learner.

A macro learner turns a solved problem and its plan into a library with (perhaps) one
more MACROP; it is a plugin kind (``[learner]`` in the config, registered through
``strips_register_macro_learners``), so other generalization methods can be swapped in like
provers and evaluators. The workflow that solves problems and learns from their plans,
``strips learn``, drives the planner facade, so it lives beside it
(:mod:`strips_framework.learning`).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import ClassVar, Protocol

from strips_framework.macrops.elimination import eliminate
from strips_framework.macrops.generalize import generalize
from strips_framework.macrops.ground_table import ground_table
from strips_framework.macrops.macrop import Library, Macrop
from strips_framework.macrops.table import Step
from strips_framework.options import Configurable, Option
from strips_framework.worldmodel.problem import Problem


class MacroLearner(Protocol):
    name: ClassVar[str]

    def learn(self, problem: Problem, plan: Sequence[Step], library: Library) -> tuple[Library, str]:
        """The library after learning from ``plan`` (a valid plan for ``problem``), and a
        line saying what was learned."""
        ...


class TriangleTableLearner(Configurable):
    """The 1972 paper's learner: the plan's triangle table, generalized, as one MACROP.

    ``eliminate`` first drops the steps the plan can do without (a MACROP inherits every
    detour of its plan); plans shorter than ``min_steps`` teach nothing a single operator
    does not; ``max_macrops`` caps the library (the oldest MACROP goes first), since every
    MACROP costs relevance tests at every node of later searches.
    """

    name: ClassVar[str] = "triangle-table"
    capabilities: ClassVar[frozenset[str]] = frozenset()
    options = (
        Option("eliminate", bool, True, doc="drop the steps the plan can do without first"),
        Option("min_steps", int, 2, minimum=1, doc="shorter plans teach nothing"),
        Option("max_macrops", int, 50, minimum=1, doc="the library's size (oldest dropped)"),
    )
    eliminate: bool
    min_steps: int
    max_macrops: int

    def learn(self, problem: Problem, plan: Sequence[Step], library: Library) -> tuple[Library, str]:
        steps = eliminate(problem, plan) if self.eliminate else list(plan)
        if len(steps) < self.min_steps:
            return library, f"nothing learned: {len(steps)} step(s) after elimination"
        found = generalize(ground_table(problem, steps))
        name = library.fresh_name()
        grown, note = library.added(Macrop(name, found.table, Path(problem.source).name,
                                           found.example))
        if len(grown.macrops) > self.max_macrops:
            oldest = grown.macrops[0]
            grown = Library(grown.macrops[1:])
            note += f"; {oldest.name} dropped (max_macrops = {self.max_macrops})"
        return grown, note
