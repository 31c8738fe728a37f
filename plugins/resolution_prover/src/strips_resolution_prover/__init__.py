"""Native resolution theorem prover for strips-framework, with parameters and answers.

``ResolutionProver`` is loaded on first use (PEP 562), so that loading the plugin's entry
point does not import the prover for runs that never prove anything."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from strips_resolution_prover.prover import ResolutionProver

__all__ = ["ResolutionProver"]


def __getattr__(name: str) -> Any:
    if name == "ResolutionProver":
        from strips_resolution_prover.prover import ResolutionProver

        return ResolutionProver
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
