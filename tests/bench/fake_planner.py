"""A stand-in planner for the bench's tests, run through a matrix's ``command`` config.

    python fake_planner.py MODE PROBLEM PLAN

MODE: ``solve`` (writes the plan of tests/data/push-one-box.strips, prints
``expanded: 3``), ``slow-solve`` (the same after a second), ``crash`` (aborts: SIGABRT), ``hang`` (sleeps forever),
``hog`` (allocates memory until the limit stops it), ``unsolvable`` (exit code 11).
"""

import os
import sys
import time


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
        out.write("(goto a b)\n(push BOX1 b c)\n; cost = 2 (unit cost)\n")
    print("expanded: 3")


if __name__ == "__main__":
    main()
