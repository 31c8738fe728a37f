"""Cost growth of the ground and the lifted searches as one domain grows: blocks from 100
to 1,100 blocks, logistics from 10 to 1,000 cities (generated here, so no shared files
are needed). For each size and each search: the set-up time (ground: grounding and the
heuristic's set-up; lifted: compiling the task and the heuristic's set-up), the time to
the second expansion (the initial state filed and evaluated once), the time per
expansion after that over the first expansions of lazy greedy search with hFF (and, as
``ground-gc`` and ``lifted-gc``, of the searches with goal count: their own cost without
hFF's, whose ground exploration visits every operator the state lets it reach), and the
bytes a stored state costs; CPU time. An expansion's time is everything the search does
from one expansion to the next: the successors it takes from the open list, their
duplicate tests, their fact bases and evaluations. Both domains' branching grows with the
task (blocks: one unstack per tower; logistics: one drive per truck, one flight per
airport): the ``-listed`` rows list every successor of an expanded state (``deferred =
false``), the others draw them as the open list reaches them, so the table also gives the
successors generated (taken) per expansion and the time per successor. Not a pytest
benchmark: a row takes seconds to minutes, and the table goes into docs/search.md by hand.

    taskset -c 1 .venv/bin/python benchmarks/bench_scaling.py                # both domains
    taskset -c 1 .venv/bin/python benchmarks/bench_scaling.py --domain blocks --sizes 100,300
    taskset -c 1 .venv/bin/python benchmarks/bench_scaling.py --searches lifted
    taskset -c 1 .venv/bin/python benchmarks/bench_scaling.py --searches lifted-gc --expansions 1000

``--budget`` (seconds, default 120) skips a search's larger sizes once its set-up alone
took longer than that (grounding grows faster than the lifted set-up; the row says so).
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from typing import Any

from strips_framework.forward.base import SearchRun
from strips_framework.forward.lazy import LazyGreedySearch
from strips_framework.grounding import ground
from strips_framework.lifted.search import LiftedLazyGreedySearch, LiftedRun
from strips_framework.lifted.successors import Successors
from strips_framework.lifted.task import LiftedTask
from strips_framework.limits import Clock, LimitReached, Limits
from strips_framework.pddl import PddlTask, parse_task
from strips_framework.plugin.registry import Registry

#: Expansions measured per row (``--expansions``): the first 20 by default. A longer
#: window also counts what a long search pays that a short one does not (a larger open
#: list, memory reused rather than touched for the first time).
EXPANSIONS = 20

BLOCKS = """(define (domain blocksworld) (:requirements :strips)
 (:predicates (on ?x ?y) (ontable ?x) (clear ?x) (handempty) (holding ?x))
 (:action pick-up :parameters (?x) :precondition (and (clear ?x) (ontable ?x) (handempty))
  :effect (and (not (ontable ?x)) (not (clear ?x)) (not (handempty)) (holding ?x)))
 (:action put-down :parameters (?x) :precondition (holding ?x)
  :effect (and (not (holding ?x)) (clear ?x) (handempty) (ontable ?x)))
 (:action stack :parameters (?x ?y) :precondition (and (holding ?x) (clear ?y))
  :effect (and (not (holding ?x)) (not (clear ?y)) (clear ?x) (handempty) (on ?x ?y)))
 (:action unstack :parameters (?x ?y) :precondition (and (on ?x ?y) (clear ?x) (handempty))
  :effect (and (holding ?x) (clear ?y) (not (clear ?x)) (not (handempty)) (not (on ?x ?y)))))"""

LOGISTICS = """(define (domain logistics) (:requirements :strips :typing)
 (:types truck airplane - vehicle package vehicle - physobj airport location - place
         city place physobj - object)
 (:predicates (in-city ?loc - place ?city - city) (at ?obj - physobj ?loc - place)
              (in ?pkg - package ?veh - vehicle))
 (:action load-truck :parameters (?pkg - package ?truck - truck ?loc - place)
  :precondition (and (at ?truck ?loc) (at ?pkg ?loc))
  :effect (and (not (at ?pkg ?loc)) (in ?pkg ?truck)))
 (:action load-airplane :parameters (?pkg - package ?airplane - airplane ?loc - place)
  :precondition (and (at ?pkg ?loc) (at ?airplane ?loc))
  :effect (and (not (at ?pkg ?loc)) (in ?pkg ?airplane)))
 (:action unload-truck :parameters (?pkg - package ?truck - truck ?loc - place)
  :precondition (and (at ?truck ?loc) (in ?pkg ?truck))
  :effect (and (not (in ?pkg ?truck)) (at ?pkg ?loc)))
 (:action unload-airplane :parameters (?pkg - package ?airplane - airplane ?loc - place)
  :precondition (and (in ?pkg ?airplane) (at ?airplane ?loc))
  :effect (and (not (in ?pkg ?airplane)) (at ?pkg ?loc)))
 (:action drive-truck :parameters (?truck - truck ?from - place ?to - place ?city - city)
  :precondition (and (at ?truck ?from) (in-city ?from ?city) (in-city ?to ?city))
  :effect (and (not (at ?truck ?from)) (at ?truck ?to)))
 (:action fly-airplane :parameters (?airplane - airplane ?from - airport ?to - airport)
  :precondition (at ?airplane ?from)
  :effect (and (not (at ?airplane ?from)) (at ?airplane ?to))))"""


def blocks(n: int) -> PddlTask:
    """``n`` blocks in towers of 10; the goal moves three blocks (a few steps)."""
    names = [f"b{i}" for i in range(n)]
    init = ["(handempty)"]
    for start in range(0, n, 10):
        tower = names[start : start + 10]
        init.append(f"(ontable {tower[0]})")
        init += [f"(on {upper} {lower})" for lower, upper in zip(tower, tower[1:])]
        init.append(f"(clear {tower[-1]})")
    goal = f"(and (on b9 b19) (on b19 b29) (ontable b{n - 1}))"
    problem = f"""(define (problem blocks{n}) (:domain blocksworld) (:objects {' '.join(names)})
 (:init {' '.join(init)}) (:goal {goal}))"""
    return parse_task(BLOCKS, problem, "blocks-domain", f"blocks{n}")


def logistics(cities: int) -> PddlTask:
    """``cities`` cities of two places (an airport and a post office) and a truck each,
    one airplane, one package per ten cities; the goal moves two packages."""
    objects, init = ["plane - airplane"], ["(at plane a0)"]
    for c in range(cities):
        objects += [f"c{c} - city", f"a{c} - airport", f"l{c} - location", f"t{c} - truck"]
        init += [f"(in-city a{c} c{c})", f"(in-city l{c} c{c})", f"(at t{c} a{c})"]
    packages = max(cities // 10, 2)
    for p in range(packages):
        objects.append(f"p{p} - package")
        init.append(f"(at p{p} l{(p * 7) % cities})")
    goal = f"(and (at p0 l{(1 + 7 * 0 + cities // 2) % cities}) (at p1 a{(3 + cities // 3) % cities}))"
    problem = f"""(define (problem logistics{cities}) (:domain logistics)
 (:objects {' '.join(objects)}) (:init {' '.join(init)}) (:goal {goal}))"""
    return parse_task(LOGISTICS, problem, "logistics-domain", f"logistics{cities}")


DOMAINS: dict[str, tuple[Callable[[int], PddlTask], list[int]]] = {
    "blocks": (blocks, [100, 300, 500, 700, 900, 1100]),
    "logistics": (logistics, [10, 30, 100, 300, 1000]),
}


def _seconds_per_expansion(search: Callable[[Any], object], run: Any) -> tuple[float, float]:
    """Run ``search`` on ``run`` up to the expansion limit: the CPU seconds up to the
    second expansion (the initial state's evaluation and first expansion, which file the
    whole initial state once), and the CPU seconds per expansion after that (each
    expansion's successors, duplicate tests and evaluations), timed at the search's
    limit checks, made once per expansion."""
    times: list[float] = []
    check = run.budget.check

    def timed(expanded: int) -> None:
        times.append(time.process_time())
        check(expanded)

    run.budget.check = timed
    began = time.process_time()
    try:
        search(run)
    except LimitReached:
        pass
    if len(times) < 3:
        return time.process_time() - began, 0.0
    return times[1] - began, (times[-1] - times[1]) / (len(times) - 2)


Row = tuple[float, float, float, float, int, int]


def ground_row(task: PddlTask, registry: Registry, heuristic: str = "ff") -> Row:
    """Set-up seconds, seconds to the second expansion, seconds per expansion after
    it, bytes per state, expansions, successors generated."""
    began = time.process_time()
    grounded = ground(task)
    estimator = registry.get("heuristic", heuristic).cls().for_task(grounded)
    setup = time.process_time() - began
    run = SearchRun(grounded, estimator, _limits(), Clock(600))
    first, per = _seconds_per_expansion(LazyGreedySearch().run, run)
    return setup, first, per, run.space.bytes_per_state(), run.expanded, run.generated


def _limits() -> Limits:
    return Limits(time=600, expansions=EXPANSIONS)


def lifted_row(task: PddlTask, registry: Registry, heuristic: str = "ff", deferred: bool = True) -> Row:
    began = time.process_time()
    successors = Successors(LiftedTask(task))
    estimator = registry.get("lifted-heuristic", heuristic).cls().for_task(task)
    setup = time.process_time() - began
    run = LiftedRun(successors, estimator, _limits(), Clock(600))
    first, per = _seconds_per_expansion(LiftedLazyGreedySearch(deferred=deferred).run, run)
    return setup, first, per, run.space.bytes_per_state(), run.expanded, run.generated


#: ``lifted-gc`` and ``ground-gc`` are the searches with goal count, whose time per
#: expansion is the search's own (successors, duplicates, storing states) with next to
#: nothing for the heuristic;
#: ``-listed`` lists every successor of an expanded state (``deferred = false``) instead
#: of drawing them as the open list reaches them.
SEARCHES: dict[str, Callable[[PddlTask, Registry], Row]] = {
    "ground": ground_row,
    "ground-gc": lambda task, registry: ground_row(task, registry, "goal-count"),
    "lifted": lifted_row,
    "lifted-listed": lambda task, registry: lifted_row(task, registry, "ff", deferred=False),
    "lifted-gc": lambda task, registry: lifted_row(task, registry, "goal-count"),
    "lifted-gc-listed": lambda task, registry: lifted_row(task, registry, "goal-count", deferred=False),
}


def main() -> None:
    global EXPANSIONS
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--domain", choices=sorted(DOMAINS), action="append")
    parser.add_argument("--sizes", help="comma-separated sizes (default: the domain's)")
    parser.add_argument("--searches", default="ground,lifted,lifted-gc")
    parser.add_argument("--budget", type=float, default=120.0)
    parser.add_argument("--expansions", type=int, default=EXPANSIONS, help="expansions measured per row")
    args = parser.parse_args()
    EXPANSIONS = args.expansions
    registry = Registry.from_plugins()
    print("| domain | size | search | set-up s | first expansion ms | ms / expansion | bytes / state | expanded | generated / expansion | µs / generated |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|")
    for name in args.domain or sorted(DOMAINS):
        make, sizes = DOMAINS[name]
        if args.sizes:
            sizes = [int(s) for s in args.sizes.split(",")]
        over: set[str] = set()
        for size in sizes:
            task = make(size)
            for search in args.searches.split(","):
                if search in over:
                    print(f"| {name} | {size} | {search} | skipped: set-up over {args.budget:.0f} s at a smaller size | | | | | | |")
                    continue
                setup, first, per, size_bytes, expanded, generated = SEARCHES[search](task, registry)
                branching = generated / max(expanded, 1)
                if setup > args.budget:
                    over.add(search)
                print(
                    f"| {name} | {size} | {search} | {setup:.2f} | {first * 1000:.1f} | {per * 1000:.3f} | "
                    f"{size_bytes:.0f} | {expanded} | {branching:.0f} | {per * 1e6 / max(branching, 1):.2f} |",
                    flush=True,
                )


if __name__ == "__main__":
    main()
