"""Z3-based theorem prover for strips-framework, with parameters and answers."""

from strips_z3_prover.prover import Z3Prover

__all__ = ["Z3Prover"]
