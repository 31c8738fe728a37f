"""A stand-in planner for the bench's tests, run through a matrix's ``command`` config.

    python fake_planner.py MODE PROBLEM PLAN

MODE: ``solve`` (writes the plan of tests/data/push-one-box.strips, prints
``expanded: 3``), ``slow-solve`` (the same after a second), ``crash`` (aborts: SIGABRT),
``hang`` (sleeps forever), ``hog`` (allocates memory until the limit stops it), ``unsolvable`` (exit code 11),
``json`` (the plan, and a result as ``strips solve --json`` prints it for PDDL tasks).
"""

import json
import os
import sys
import time

PLAN = ["(goto a b)", "(push BOX1 b c)"]


def main() -> None:
    mode, _problem, plan = sys.argv[1:4]
    if mode == "crash":
        os.abort()
    if mode == "hang":
        time.sleep(3600)
    if mode == "hog":
        blocks = []
        while True:
            blocks.append(bytearray(64 * 1024 * 1024))
    if mode == "unsolvable":
        print("expanded: 7")
        sys.exit(11)
    if mode == "slow-solve":
        time.sleep(1)
    with open(plan, "w", encoding="utf-8") as out:
        out.write("\n".join(PLAN) + "\n; cost = 2 (unit cost)\n")
    if mode == "json":
        statistics = {"expanded": 5, "parse_seconds": 0.5, "ground_seconds": 0.25,
                      "search_seconds": 0.25}
        print(json.dumps({"status": "solved", "plan": PLAN, "statistics": statistics}))
    else:
        print("expanded: 3")


if __name__ == "__main__":
    main()
