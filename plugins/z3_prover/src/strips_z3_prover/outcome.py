"""What an encoding's attempt decided, before the prover adds the uncompleted proof."""

from __future__ import annotations

import z3
from attrs import frozen

from strips_framework.worldmodel.proving import GAVE_UP, PROVED, SATURATED, Answer


@frozen
class Outcome:
    """An SZS status and, when proved, the answers found (one empty answer without
    parameters); when not, ``lemmas``: ground atoms found entailed on the way, which the
    uncompleted proof may resolve with like facts."""

    status: str
    answers: tuple[Answer, ...] = ()
    lemmas: tuple[tuple, ...] = ()


def status_of(result: z3.CheckSatResult) -> str:
    """The SZS status of a refutation check: unsat is a proof, sat a countermodel."""
    if result == z3.unsat:
        return PROVED
    return SATURATED if result == z3.sat else GAVE_UP
