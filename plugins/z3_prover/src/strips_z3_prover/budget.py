"""The effort bound as a Z3 resource limit.

Z3's ``rlimit`` counts internal operations, not seconds, so a run gives the same answer on
any machine and under any load. One attempt (one :class:`~strips_framework.worldmodel.proving.ProofTask`)
gets ``effort * scale`` units in all, shared by its checks: each check may use what the
previous ones left. Z3 notices the limit between operations, so a check may overrun it
slightly; the overrun is charged, and the next check gets nothing.
"""

from __future__ import annotations

from collections.abc import Sequence

import z3


class Budget:
    """What is left of one attempt's resource limit."""

    def __init__(self, effort: int, scale: int) -> None:
        self.effort = effort
        self.scale = scale
        self.used = 0

    @property
    def exhausted(self) -> bool:
        return self.used >= self.effort * self.scale

    def check(self, solver: z3.Solver, assumptions: Sequence[z3.BoolRef] = ()) -> z3.CheckSatResult:
        """``solver.check`` within the remaining limit (``unknown`` once it is spent)."""
        if self.exhausted:
            return z3.unknown
        before = _count(solver)
        solver.set("rlimit", self.effort * self.scale - self.used)
        result = _check(solver, assumptions)
        self.used += _count(solver) - before
        return result

    def effort_used(self) -> int:
        """The units used, in the config's effort unit (rounded up, at most the effort)."""
        return min(self.effort, -(-self.used // self.scale))


def _check(solver: z3.Solver, assumptions: Sequence[z3.BoolRef]) -> z3.CheckSatResult:
    """``solver.check(*assumptions)`` for Boolean constants, without z3py's conversion of
    each assumption (sort checks through Python, a third of a small attempt's check)."""
    array = (z3.Ast * len(assumptions))(*[a.as_ast() for a in assumptions])
    context = solver.ctx.ref()
    return z3.CheckSatResult(
        z3.Z3_solver_check_assumptions(context, solver.solver, len(assumptions), array)
    )


def _count(solver: z3.Solver) -> int:
    """Z3's resource counter (absent until the first check), read from the solver's
    statistics in one pass over the C API (z3py's lookup builds every key twice)."""
    context = solver.ctx.ref()
    statistics = z3.Z3_solver_get_statistics(context, solver.solver)
    z3.Z3_stats_inc_ref(context, statistics)
    try:
        for index in range(z3.Z3_stats_size(context, statistics)):
            if z3.Z3_stats_get_key(context, statistics, index) == "rlimit count":
                return int(z3.Z3_stats_get_uint_value(context, statistics, index))
        return 0
    finally:
        z3.Z3_stats_dec_ref(context, statistics)
