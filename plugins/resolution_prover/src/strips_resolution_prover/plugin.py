"""The pluggy entry point: registers :class:`ResolutionProver` under the name ``resolution``.

The prover is imported inside the hook, which the registry calls only when a prover is
looked up: a forward search on a PDDL task never loads it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from strips_framework.plugin.hookspecs import hookimpl

if TYPE_CHECKING:
    from strips_framework.worldmodel.proving import TheoremProver


@hookimpl
def strips_register_provers() -> list[type[TheoremProver]]:
    from strips_resolution_prover.prover import ResolutionProver

    return [ResolutionProver]
