"""ABSTRIPS against plain means-ends analysis on the robot world: the paper's tasks, the
five-part goal, and robot worlds of 10 to 100 extra rooms (benchmarks/robot_worlds.py),
with its goal (gather the boxes in ROOM1) and with one across the corridor (the robot at
a location of the last extra room).
Prints a markdown table (nodes, proof attempts, search seconds, plan length) for
docs/abstrips.md. Not a pytest benchmark: it is one table, run by hand on a quiet core.

    taskset -c 0 .venv/bin/python benchmarks/abstrips_vs_means_ends.py
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

from robot_worlds import EXAMPLES, robot_world

from strips_framework.planner import Planner

CONFIGS = {"means-ends": {}, "abstrips": {"strategy": {"name": "abstrips"}}}
TASKS = ["boxes", "light", "other-room", "door-room2", "five-goals"]
ROOMS = [10, 25, 50, 100]


def problems() -> list[tuple[str, Path]]:
    found = [(name, EXAMPLES / f"{name}.strips") for name in TASKS]
    folder = Path(tempfile.mkdtemp(prefix="abstrips-bench-"))
    for rooms in ROOMS:
        path = folder / f"rooms{rooms}.strips"
        text = robot_world(rooms * 40, rooms)
        path.write_text(text)
        found.append((f"{rooms} rooms, boxes goal", path))
        far = folder / f"rooms{rooms}-far.strips"
        goal = text.rindex("goal ")
        far.write_text(text[:goal] + f"goal AT(ROBOT, xloc{rooms - 1}_0)\n")
        found.append((f"{rooms} rooms, robot to the last room", far))
    return found


def main() -> None:
    print("| task | strategy | status | length | nodes | proof attempts | search s |")
    print("|---|---|---|---|---|---|---|")
    for name, path in problems():
        for label, config in CONFIGS.items():
            planner = Planner.create({**config, "limits": {"time": 120, "nodes": 20000}})
            result = planner.run(path)
            stats = result.statistics
            length = "-" if result.plan is None else len(result.plan)
            print(f"| {name} | {label} | {result.status} | {length} | {stats.nodes} | "
                  f"{stats.proof_attempts} | {stats.seconds:.3f} |")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
