"""The pluggy entry point: registers :class:`Z3Prover` under the name ``z3``."""

from __future__ import annotations

from strips_framework.hookspecs import hookimpl
from strips_framework.proving import TheoremProver
from strips_z3_prover.prover import Z3Prover


@hookimpl
def strips_register_provers() -> list[type[TheoremProver]]:
    return [Z3Prover]
