"""The conformance kit, run against E (skipped where the ``eprover`` binary is absent)."""

from __future__ import annotations

import shutil

import pytest

from strips_eprover_prover import EProver
from strips_framework.testing import ProverConformance

pytestmark = pytest.mark.skipif(shutil.which("eprover") is None, reason="eprover not installed")


class TestEProver(ProverConformance):
    prover_class = EProver
