"""Resource limits of one search (the ``[limits]`` table of the config)."""

from __future__ import annotations

from attrs import field, frozen, validators

_positive = [validators.instance_of((int, float)), validators.gt(0)]


@frozen
class Limits:
    """``time`` in wall-clock seconds, ``nodes`` generated, ``effort`` per proof attempt
    (in the prover's unit; for the resolution prover, given clauses processed)."""

    time: float = field(default=60.0, validator=_positive)
    nodes: int = field(default=10_000, validator=[validators.instance_of(int), validators.gt(0)])
    effort: int = field(default=300, validator=[validators.instance_of(int), validators.gt(0)])
