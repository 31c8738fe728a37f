"""The pluggy entry point: registers :class:`EProver` under the name ``eprover``.

The prover is imported inside the hook, so loading the entry point costs nothing for runs
that never prove anything."""

from __future__ import annotations

from typing import TYPE_CHECKING

from strips_framework.plugin.hookspecs import hookimpl

if TYPE_CHECKING:
    from strips_framework.worldmodel.proving import TheoremProver


@hookimpl
def strips_register_provers() -> list[type[TheoremProver]]:
    from strips_eprover_prover.prover import EProver

    return [EProver]
