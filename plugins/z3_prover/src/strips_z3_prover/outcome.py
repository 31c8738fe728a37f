"""What an encoding's attempt decided, before the prover adds the uncompleted proof."""

from __future__ import annotations

import z3

from strips_framework.records import Record
from strips_framework.worldmodel.proving import GAVE_UP, PROVED, SATURATED, Answer


class Outcome(Record):
    """An SZS status and, when proved, the answers found (one empty answer without
    parameters); when not, ``lemmas``: ground atoms found entailed on the way, which the
    uncompleted proof may resolve with like facts."""

    status: str
    answers: tuple[Answer, ...]
    lemmas: tuple[tuple, ...]

    __slots__ = ("status", "answers", "lemmas")

    def __init__(
        self,
        status: str,
        answers: tuple[Answer, ...] = (),
        lemmas: tuple[tuple, ...] = (),
    ) -> None:
        self.status = status
        self.answers = answers
        self.lemmas = lemmas


def status_of(result: z3.CheckSatResult) -> str:
    """The SZS status of a refutation check: unsat is a proof, sat a countermodel."""
    if result == z3.unsat:
        return PROVED
    return SATURATED if result == z3.sat else GAVE_UP
