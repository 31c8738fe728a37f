"""The fuzz benchmark: ten thousand and more mutated inputs through ``strips``, in this
process, and the table issue 12 asks for.

    .venv/bin/python benchmarks/fuzz_inputs.py                  # 1,250 per format: 10,000
    .venv/bin/python benchmarks/fuzz_inputs.py --per-format 200 --formats native,tptp

Inputs are mutants of the shipped examples, of the PDDL test tasks (costs, derived
predicates, ADL conditions) and, when ``shared/bench/tptp`` is beside the repository, of
a few of its problems, seeded by their number: a run is
reproducible, and ``--show LABEL`` prints one input's command and output again. Prints,
per format: inputs, clean errors (exit 2, one ``error:`` line), errors naming the file
and file:line, inputs accepted (a plan, a verdict, a limit), tracebacks and hangs
(20 s of CPU); then each distinct crash cause. Not a test: pytest does not collect this
file (``tests/test_fuzz.py`` runs a few hundred per format).
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

from shared_bench import shared_bench

from strips_framework.testing import fuzz

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "pddl" / "data"
#: PDDL tasks with costs, derived predicates and ADL conditions, beside the example's.
TASKS = [(DATA / f"{name}-domain.pddl", DATA / f"{name}-{n}.pddl")
         for name, n in (("rooms", 1), ("lamps", 1), ("crates", 3))]
SHARED_TPTP = ("dev/PUZ001-1.p", "dev/PUZ047+1.p", "dev/SET146+3.p", "dev/MSC002-1.p")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--per-format", type=int, default=1250)
    parser.add_argument("--formats", default=",".join(fuzz.FORMATS))
    parser.add_argument("--show", help="print one input (e.g. native-17) and how it ended")
    args = parser.parse_args()
    formats = [name for name in args.formats.split(",") if name]
    tptp = shared_bench("tptp")
    extra = [tptp / name for name in SHARED_TPTP if tptp and (tptp / name).is_file()]
    with tempfile.TemporaryDirectory() as folder:
        space = fuzz.Workspace.create(Path(folder), ROOT / "examples", extra, TASKS)
        if args.show:
            fmt, number = args.show.rsplit("-", 1)
            case = next(c for c in fuzz.cases(space, int(number) + 1, [fmt]) if c.label == args.show)
            outcome = fuzz.run_case(space, case)
            print(" ".join(case.argv), f"-> exit {outcome.exit_code}")
            print(outcome.traceback or outcome.stderr)
            return 0
        started = time.perf_counter()
        outcomes = []
        for case in fuzz.cases(space, args.per_format, formats):
            outcomes.append(fuzz.run_case(space, case))
            if len(outcomes) % 1000 == 0:  # the table so far, for a run stopped early
                print(f"{len(outcomes)} inputs, {time.perf_counter() - started:.0f} s\n"
                      f"{fuzz.table(outcomes)}", file=sys.stderr)
        seconds = time.perf_counter() - started
    print(fuzz.table(outcomes))
    print(f"\n{len(outcomes)} inputs in {seconds:.0f} s ({len(outcomes) / seconds:.0f} per second)")
    for cause, count in fuzz.causes(outcomes).most_common():
        print(f"{count:5}  {cause}")
    return 1 if any(o.crashed or o.hung for o in outcomes) else 0


if __name__ == "__main__":
    sys.exit(main())
