"""The conformance kit, run against the Z3 prover in both of its modes."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from strips_z3_prover import Z3Prover

from strips_framework.testing import ProverConformance


class TestZ3Prover(ProverConformance):
    prover_class = Z3Prover
    session_steps = 8  # a query costs Z3 about 0.3 s


class TestZ3ProverWithoutSession(ProverConformance):
    prover_class = Z3Prover
    options: ClassVar[Mapping[str, object]] = {"incremental": False}
    session_steps = 2  # each attempt starts afresh anyway
