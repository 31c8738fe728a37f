"""The E theorem prover as a strips-framework prover: tasks written as TPTP, answers read back.

``EProver`` is loaded on first use (PEP 562)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from strips_eprover_prover.prover import EProver

__all__ = ["EProver"]


def __getattr__(name: str) -> Any:
    if name == "EProver":
        from strips_eprover_prover.prover import EProver

        return EProver
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
