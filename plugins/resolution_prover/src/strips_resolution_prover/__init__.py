"""Native resolution theorem prover for strips-framework, with parameters and answers."""

from strips_resolution_prover.prover import ResolutionProver

__all__ = ["ResolutionProver"]
