"""Set-up runs with the cyclic collector paused (:mod:`strips_framework.allocation`):
grounding, the successor generator and the relaxed heuristics' set-up start no
collection however low the collector's threshold, and leave it as they found it."""

from __future__ import annotations

import gc
from collections.abc import Callable, Iterator

import pytest

from strips_evaluators.heuristics.exploration import explorer
from strips_evaluators.heuristics.relaxation import relax
from strips_framework.allocation import collection_paused
from strips_framework.forward.successors import successor_generator
from strips_framework.grounding import ground
from strips_framework.pddl import parse_task

DOMAIN = """(define (domain blocksworld) (:requirements :strips)
 (:predicates (clear ?x) (on-table ?x) (arm-empty) (holding ?x) (on ?x ?y))
 (:action pickup :parameters (?ob)
  :precondition (and (clear ?ob) (on-table ?ob) (arm-empty))
  :effect (and (holding ?ob) (not (clear ?ob)) (not (on-table ?ob)) (not (arm-empty))))
 (:action stack :parameters (?ob ?underob) :precondition (and (clear ?underob) (holding ?ob))
  :effect (and (arm-empty) (clear ?ob) (on ?ob ?underob) (not (clear ?underob))
               (not (holding ?ob)))))"""


def _problem(n: int) -> str:
    names = [f"b{i}" for i in range(n)]
    init = " ".join(f"(on-table {b}) (clear {b})" for b in names)
    return f"""(define (problem p) (:domain blocksworld) (:objects {' '.join(names)})
 (:init (arm-empty) {init}) (:goal (and (on b1 b0))))"""


@pytest.fixture
def collections() -> Iterator[list[str]]:
    """The collections started while the test runs, with the threshold at 1 (a
    collection on nearly every allocation) so that any unpaused set-up starts many."""
    started: list[str] = []

    def callback(phase: str, info: dict) -> None:
        if phase == "start":
            started.append(phase)

    threshold = gc.get_threshold()
    enabled = gc.isenabled()
    gc.enable()
    gc.set_threshold(1)
    gc.callbacks.append(callback)
    try:
        yield started
    finally:
        gc.callbacks.remove(callback)
        gc.set_threshold(*threshold)
        if not enabled:
            gc.disable()


def _stages() -> list[tuple[str, Callable[[], object]]]:
    pddl = parse_task(DOMAIN, _problem(30))
    task = ground(pddl)
    relaxed = relax(task)
    return [
        ("ground", lambda: ground(pddl)),
        ("successor_generator", lambda: successor_generator(task)),
        ("relax", lambda: relax(task)),
        ("explorer", lambda: explorer(relaxed)),
    ]


@pytest.mark.parametrize("stage", ["ground", "successor_generator", "relax", "explorer"])
def test_set_up_starts_no_collection(stage: str, collections: list[str]) -> None:
    build = dict(_stages())[stage]
    collections.clear()
    build()
    started = len(collections)  # before anything else allocates
    # Entering and leaving the pause allocate a few objects with the collector on; the
    # stage itself allocates tens of thousands (unpaused, as many collections start).
    assert started < 20
    assert gc.isenabled()


def test_the_collector_is_on_again_after_set_up() -> None:
    assert gc.isenabled()
    with collection_paused():
        assert not gc.isenabled()
    assert gc.isenabled()


def test_a_pause_inside_a_pause_or_a_disabled_collector_is_left_alone() -> None:
    enabled = gc.isenabled()
    try:
        gc.enable()
        with collection_paused():
            with collection_paused():
                pass
            assert not gc.isenabled()
        assert gc.isenabled()
        gc.disable()
        with collection_paused():
            pass
        assert not gc.isenabled()
    finally:
        (gc.enable if enabled else gc.disable)()


def test_the_collector_comes_back_after_an_error() -> None:
    assert gc.isenabled()
    with pytest.raises(KeyError):
        with collection_paused():
            raise KeyError("x")
    assert gc.isenabled()
