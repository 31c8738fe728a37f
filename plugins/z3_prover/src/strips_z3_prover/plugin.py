"""The pluggy entry point: registers :class:`Z3Prover` under the name ``z3``.

The prover (and z3 with it, some 60 ms to import) is imported inside the hook, which the
registry calls only when a prover is looked up: a forward search never loads it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from strips_framework.plugin.hookspecs import hookimpl

if TYPE_CHECKING:
    from strips_framework.worldmodel.proving import TheoremProver


@hookimpl
def strips_register_provers() -> list[type[TheoremProver]]:
    from strips_z3_prover.prover import Z3Prover

    return [Z3Prover]
