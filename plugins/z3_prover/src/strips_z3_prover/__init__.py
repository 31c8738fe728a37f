"""Z3-based theorem prover for strips-framework, with parameters and answers.

``Z3Prover`` is loaded on first use (PEP 562), so that loading the plugin's entry point
does not import z3 (some 60 ms) for runs that never prove anything."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from strips_z3_prover.prover import Z3Prover

__all__ = ["Z3Prover"]


def __getattr__(name: str) -> Any:
    if name == "Z3Prover":
        from strips_z3_prover.prover import Z3Prover

        return Z3Prover
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
