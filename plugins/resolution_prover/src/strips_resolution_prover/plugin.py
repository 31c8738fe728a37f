"""The pluggy entry point: registers :class:`ResolutionProver` under the name ``resolution``."""

from __future__ import annotations

from strips_framework.hookspecs import hookimpl
from strips_framework.proving import TheoremProver
from strips_resolution_prover.prover import ResolutionProver


@hookimpl
def strips_register_provers() -> list[type[TheoremProver]]:
    return [ResolutionProver]
