"""Result rows of a made-up benchmark with many configurations (16 by default) over a
few domains: deterministic, shaped like real ones (each configuration has its own
speed and its own share of unsolved problems), for testing and showing the report."""

from __future__ import annotations

import json
import random
from pathlib import Path
from typing import Any

DOMAINS = ("blocksworld", "gripper", "logistics", "depot")


def rows(configs: int = 16, problems: int = 6, seed: int = 7) -> list[dict[str, Any]]:
    chance = random.Random(seed)
    found = []
    for c in range(configs):
        name = f"config-{c + 1:02d}"
        speed = 0.3 + 0.25 * c
        for domain in DOMAINS:
            for p in range(problems):
                problem = f"{domain}/p{p + 1:02d}.pddl"
                hardness = (p + 1) * (1 + DOMAINS.index(domain) * 0.5)
                time = round(speed * hardness * chance.uniform(0.5, 2.0), 3)
                solved = time < 10.0 and chance.random() > 0.05 * (c % 4)
                status = "solved" if solved else ("timeout" if time >= 10 else "memout")
                expanded = int(50 * hardness ** 2.2 * speed * chance.uniform(0.5, 2.0))
                found.append({
                    "key": f"{problem} | {name} | 0", "problem": problem, "problem_set": domain,
                    "config": name, "repetition": 0, "status": status,
                    "planner_seconds": time if solved else None,
                    "wall_seconds": time if solved else 10.0,
                    "expanded": expanded if solved else None,
                    "plan_length": int(4 + 3 * hardness) if solved else None,
                    "valid": True if solved else None, "limits": {"time": 10.0, "memory_mib": 2048},
                })
    return found


def write(path: Path, configs: int = 16) -> Path:
    path.write_text("".join(json.dumps(row) + "\n" for row in rows(configs)), encoding="utf-8")
    return path
