"""The join engine as a prover ('joins') passes the conformance kit for what it declares."""

from __future__ import annotations

from strips_framework.lifted.prover import JoinProver
from strips_framework.testing import ProverConformance


class TestJoinProver(ProverConformance):
    prover_class = JoinProver
