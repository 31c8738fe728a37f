"""The pluggy entry point: registers :class:`AbstripsSearch` under the name ``abstrips``.

The strategy module is imported inside the hook, which the registry calls only when a
world-model strategy is looked up."""

from __future__ import annotations

from typing import TYPE_CHECKING

from strips_framework.plugin.hookspecs import hookimpl

if TYPE_CHECKING:
    from strips_framework.means_ends.components import SearchStrategy


@hookimpl
def strips_register_strategies() -> list[type[SearchStrategy]]:
    from strips_abstrips.strategy import AbstripsSearch

    return [AbstripsSearch]
