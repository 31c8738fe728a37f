"""Set-up cost of the ground path against task size: blocks with N blocks, all on the
table, goal three ``on`` relations (the shape of the hard-to-ground set's
``blocksworld-large-simple`` tasks), made in memory.

    taskset -c 1 .venv/bin/python benchmarks/setup_scaling.py 100 200 400

For each N it prints the number of facts and ground operators and the seconds spent
grounding, building the successor generator, setting up the compiled hFF and hadd (the
relaxation and its C arrays), the first hFF value, and the bytes the ground operators
hold. Set-up is linear when the seconds per fact stay flat as N doubles (facts grow as
N squared). Process CPU time, best of ``--rounds`` (default 1).
"""

from __future__ import annotations

import argparse
import sys
import time

from strips_evaluators.heuristics.additive import AdditiveHeuristic
from strips_evaluators.heuristics.ff import FFHeuristic
from strips_framework.forward.successors import successor_generator
from strips_framework.grounding import ground
from strips_framework.pddl import PddlTask, parse_task

DOMAIN = """(define (domain blocksworld) (:requirements :strips)
 (:predicates (clear ?x) (on-table ?x) (arm-empty) (holding ?x) (on ?x ?y))
 (:action pickup :parameters (?ob)
  :precondition (and (clear ?ob) (on-table ?ob) (arm-empty))
  :effect (and (holding ?ob) (not (clear ?ob)) (not (on-table ?ob)) (not (arm-empty))))
 (:action putdown :parameters (?ob) :precondition (holding ?ob)
  :effect (and (clear ?ob) (arm-empty) (on-table ?ob) (not (holding ?ob))))
 (:action stack :parameters (?ob ?underob) :precondition (and (clear ?underob) (holding ?ob))
  :effect (and (arm-empty) (clear ?ob) (on ?ob ?underob) (not (clear ?underob))
               (not (holding ?ob))))
 (:action unstack :parameters (?ob ?underob)
  :precondition (and (on ?ob ?underob) (clear ?ob) (arm-empty))
  :effect (and (holding ?ob) (clear ?underob) (not (on ?ob ?underob)) (not (clear ?ob))
               (not (arm-empty)))))"""


def blocks(n: int) -> PddlTask:
    names = [f"b{i}" for i in range(1, n + 1)]
    init = " ".join(f"(on-table {b}) (clear {b})" for b in names)
    problem = f"""(define (problem blocks-{n}) (:domain blocksworld)
 (:objects {' '.join(names)}) (:init (arm-empty) {init})
 (:goal (and (on b1 b3) (on b2 b4) (on b3 b2))))"""
    return parse_task(DOMAIN, problem)


def _timed(function, rounds: int):
    best, result = float("inf"), None
    for _ in range(rounds):
        start = time.process_time()
        result = function()
        best = min(best, time.process_time() - start)
    return best, result


def main(argv: list[str]) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sizes", nargs="*", type=int, default=[100, 200, 400])
    parser.add_argument("--rounds", type=int, default=1)
    args = parser.parse_args(argv)
    print("blocks  facts  operators  ground_s  successors_s  hff_setup_s  hadd_setup_s  "
          "hff_init_ms  us_per_fact_setup")  # fmt: skip
    for n in args.sizes:
        task = blocks(n)
        grounding, grounded = _timed(lambda: ground(task), args.rounds)
        successors, _ = _timed(lambda: successor_generator(grounded), args.rounds)
        ff_setup, ff = _timed(lambda: FFHeuristic().for_task(grounded), args.rounds)
        hadd_setup, _ = _timed(lambda: AdditiveHeuristic().for_task(grounded), args.rounds)
        first, value = _timed(lambda: ff.estimate(grounded.init), args.rounds)
        facts = len(grounded.facts)
        per_fact = 1e6 * (successors + ff_setup) / facts
        print(f"{n:6d} {facts:6d} {len(grounded.operators):10d} {grounding:9.2f} "
              f"{successors:13.2f} {ff_setup:12.2f} {hadd_setup:13.2f} {1000 * first:12.1f} "
              f"{per_fact:18.1f}   h={value}", flush=True)  # fmt: skip


if __name__ == "__main__":
    main(sys.argv[1:])
