"""How STRIPS scales with the size of M0: the same robot task in worlds of 100 to 100,000
formulas (:mod:`robot_worlds`: Table 1 grown by rooms, boxes, unrelated facts and
axioms), per size the load time, the prover session's opening
(M0 imported and indexed once), proof attempts, time per attempt and memory.

    .venv/bin/python benchmarks/bench_world_scale.py            # the table, up to 100,000
    .venv/bin/python benchmarks/bench_world_scale.py --provers=resolution,z3,eprover 100 1000
    .venv/bin/python -m pytest benchmarks/bench_world_scale.py --benchmark-only

The paper's claim (III.D) is that a proof costs the same at any |M0|, since every model
is M0 plus short ADDITIONS and DELETIONS lists. The table's last line runs a 1,000-node
search (the five-part goal of ``examples/robot-world/five-goals.strips``) on the largest
world and compares peak memory with the memory after loading: M0 is shared, not copied.
In the normal test run the smallest sizes run once, as a smoke test.
"""

from __future__ import annotations

import resource
import sys
import time
from pathlib import Path

import pytest
from robot_worlds import robot_world

from strips_framework.means_ends.goal_prover import GoalProver
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config

SIZES = (100, 1_000, 10_000, 100_000)
#: The goal of ``examples/robot-world/five-goals.strips``.
FIVE_GOALS = (
    "NEXTTO(BOX2, BOX3) & NEXTTO(BOX3, DOOR1) & STATUS(LIGHTSWITCH1, ON) & NEXTTO(BOX1, BOX2)"
    " & INROOM(ROBOT, ROOM2)"
)


def _rss_mib() -> float:
    """The resident set now (Linux), in MiB."""
    with open("/proc/self/statm") as statm:
        pages = int(statm.read().split()[1])
    return pages * resource.getpagesize() / 2**20


def _peak_mib() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def measure(
    size: int,
    folder: Path,
    goal: str = "boxes",
    nodes: int = 400,
    rooms: int | None = None,
    prover: str = "resolution",
) -> dict[str, float]:
    """Load, open and solve the generated world of ``size`` formulas (``rooms`` extra
    rooms, :func:`robot_world`'s default when None) with ``prover``; the figures."""
    path = folder / f"world-{size}-{goal}-{rooms}.strips"
    text = robot_world(size, rooms)
    if goal == "five-goals":
        text = text.replace("goal NEXTTO(BOX1, BOX2) & NEXTTO(BOX2, BOX3)", f"goal {FIVE_GOALS}")
    path.write_text(text)
    limits = {"nodes": nodes, "time": 600}
    planner = Planner.create(Config.from_dict({"limits": limits, "prover": {"name": prover}}))
    started = time.perf_counter()
    problem = planner.load(path)
    loaded = time.perf_counter()
    opened: list[float] = []
    original = GoalProver._open

    def timed(self: GoalProver) -> None:
        begin = time.perf_counter()
        original(self)
        opened.append(time.perf_counter() - begin)
        measured["rss_after_load_mib"] = _rss_mib()

    measured: dict[str, float] = {}
    GoalProver._open = timed  # type: ignore[method-assign]
    try:
        result = planner.solve(problem)
    finally:
        GoalProver._open = original  # type: ignore[method-assign]
    statistics = result.statistics
    attempts = statistics.proof_attempts
    measured.update(
        formulas=len(problem.facts) + len(problem.axioms) + len(problem.derived),
        load_s=loaded - started,
        open_s=opened[0],
        nodes=statistics.nodes,
        attempts=attempts,
        ms_per_attempt=1000 * statistics.proving_seconds / max(attempts, 1),
        search_s=statistics.seconds,
        peak_mib=_peak_mib(),
        solved=float(result.solved),
    )
    return measured


@pytest.mark.parametrize("size", SIZES[:2])
def test_world_scale(benchmark, size: int, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    figures = benchmark.pedantic(measure, args=(size, tmp_path), rounds=1, iterations=1)
    benchmark.extra_info.update(figures)
    assert figures["solved"] and figures["nodes"] == 9  # the same search at every size


def provers_per_attempt(sizes: list[int], provers: list[str], folder: Path) -> None:
    """``--provers a,b,...``: the boxes task at each size with each prover, per attempt."""
    print("formulas  prover      nodes  attempts  ms/attempt  x resolution")
    for size in sizes:
        base = None
        for prover in provers:
            f = measure(size, folder, prover=prover)
            base = base or f["ms_per_attempt"]
            print(
                f"{f['formulas']:8.0f}  {prover:<10} {f['nodes']:6.0f} {f['attempts']:9.0f}"
                f" {f['ms_per_attempt']:11.3f} {f['ms_per_attempt'] / base:12.1f}"
            )


def main() -> None:
    import tempfile

    folder = Path(tempfile.mkdtemp())
    args = sys.argv[1:]
    if args and args[0].startswith("--provers="):
        sizes = [int(arg) for arg in args[1:]] or list(SIZES[:2])
        return provers_per_attempt(sizes, args[0].split("=", 1)[1].split(","), folder)
    sizes = [int(arg) for arg in args] or list(SIZES)
    print("formulas   load s   open s  nodes  attempts  ms/attempt  peak MiB")
    for size in sizes:
        f = measure(size, folder)
        print(
            f"{f['formulas']:8.0f} {f['load_s']:8.2f} {f['open_s']:8.2f} {f['nodes']:6.0f}"
            f" {f['attempts']:9.0f} {f['ms_per_attempt']:11.3f} {f['peak_mib']:9.0f}"
        )
    print("five-part goal, 1,000-node limit; ms/attempt with the extra rooms / without them")
    for size in sizes:
        grown = measure(size, folder, goal="five-goals", nodes=1000)
        plain = measure(size, folder, goal="five-goals", nodes=1000, rooms=0)
        print(
            f"{grown['formulas']:8.0f} formulas: {grown['nodes']:.0f} / {plain['nodes']:.0f}"
            f" nodes, {grown['ms_per_attempt']:.3f} / {plain['ms_per_attempt']:.3f} ms/attempt"
        )
    f = grown
    print(
        f"five-part goal on {f['formulas']:.0f} formulas: {f['nodes']:.0f} nodes, "
        f"{f['attempts']:.0f} attempts, {f['ms_per_attempt']:.3f} ms/attempt, "
        f"memory after loading {f['rss_after_load_mib']:.0f} MiB, peak {f['peak_mib']:.0f} MiB "
        f"({f['peak_mib'] / f['rss_after_load_mib']:.2f}x)"
    )


if __name__ == "__main__":
    main()
