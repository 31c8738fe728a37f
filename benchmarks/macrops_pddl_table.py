"""docs/macrops.md's PDDL table, generated: MACROPs learned from tasks 1-3 of an IPC domain
by lazy greedy search with hFF, then tasks 4 and 5 solved by means-ends
(examples/configs/paper.toml) and by the same forward search, each without and with the
library, with a 70 s limit. Prints the table's rows; ``--write`` puts them into the doc
between its ``<!-- generated: macrops-pddl-table -->`` markers.

    python benchmarks/macrops_pddl_table.py --write        # needs ../shared/bench/ipc

Times come from the machine it runs on; node and expansion counts and plan lengths do not.
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from shared_bench import shared_bench

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "macrops.md"
STRIPS = Path(sys.executable).with_name("strips")
DOMAINS = ("blocks", "gripper", "logistics", "miconic")
TASKS = ("04", "05")
FORWARD = '[strategy]\nname = "lazy-gbfs"\n[limits]\ntime = 70\n'
MEANS_ENDS = ROOT / "examples" / "configs" / "paper.toml"
MARKED = re.compile(r"(<!-- generated: macrops-pddl-table -->\n)(.*?)(<!-- /generated -->)", re.DOTALL)


def _solve(domain: Path, task: Path, config: Path, library: Path | None) -> str:
    """``nodes / s / steps`` (forward search: expanded / search s / steps) of one run."""
    argv = [str(STRIPS), "solve", str(domain), str(task), "--config", str(config), "--json"]
    if library is not None:
        argv += ["--macrops", str(library)]
    run = subprocess.run(argv, capture_output=True, text=True, check=False)
    result = json.loads(run.stdout)
    statistics = result["statistics"]
    if result["status"] != "solved":
        limit = statistics.get("nodes") if result["family"] == "world-model" else None
        return f"{result['status']}" + (f" ({limit})" if limit else "")
    if result["family"] == "forward":
        return f"{statistics['expanded']} / {statistics['search_seconds']:.3g} / {result['plan_length']}"
    return f"{statistics['nodes']} / {result['seconds']:.2g} / {result['plan_length']}"


def rows(ipc: Path) -> list[str]:
    found = []
    with tempfile.TemporaryDirectory() as folder:
        forward = Path(folder) / "fwd.toml"
        forward.write_text(FORWARD)
        for name in DOMAINS:
            domain = ipc / name / "domain.pddl"
            library = Path(folder) / f"{name}.lib"
            learned = [str(ipc / name / f"task0{i}.pddl") for i in (1, 2, 3)]
            subprocess.run([str(STRIPS), "learn", "--domain", str(domain), *learned, "-o", str(library),
                            "--config", str(forward)], capture_output=True, check=True)
            for number in TASKS:
                task = ipc / name / f"task{number}.pddl"
                cells = [_solve(domain, task, config, lib)
                         for config in (MEANS_ENDS, forward) for lib in (None, library)]
                found.append(f"| {name} | {number} | " + " | ".join(cells) + " |")
                print(found[-1], flush=True)
    return found


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write", action="store_true", help="rewrite the table in docs/macrops.md")
    args = parser.parse_args()
    ipc = shared_bench("ipc")
    if ipc is None or not all((ipc / name / "task05.pddl").exists() for name in DOMAINS):
        sys.exit("needs ../shared/bench/ipc (tasks 1-5 of blocks, gripper, logistics, miconic)")
    table = "\n".join(rows(ipc)) + "\n"
    if args.write:
        text = DOC.read_text()
        header = MARKED.search(text).group(2).split("\n")[:2]
        DOC.write_text(MARKED.sub(lambda m: m.group(1) + "\n".join(header) + "\n" + table + m.group(3), text))


if __name__ == "__main__":
    main()
