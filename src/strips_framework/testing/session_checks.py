"""Checks of a prover's sessions (:func:`~strips_framework.worldmodel.proving.open_session`).

A session must answer about a world model exactly what a fresh :class:`ProofTask` over the
model's visible clauses would: a session that let a deleted fact, or a derived clause
whose support was deleted, take part in a proof would make STRIPS apply operators whose
preconditions do not hold. The checks walk long seeded random sequences of models over
one M0 (deletes with ``$`` patterns, additions, derived clauses losing and regaining
their supports) and compare every answer with the fresh task's.
"""

from __future__ import annotations

import random
from collections.abc import Set as AbstractSet

from strips_framework.capabilities import QUANTIFIED_AXIOMS
from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import WILDCARD, Atom, Param
from strips_framework.testing.declaration import ConformanceFailure
from strips_framework.worldmodel.operators import may_delete
from strips_framework.worldmodel.proving import ProofResult, ProofTask, TheoremProver, open_session
from strips_framework.worldmodel.world import InitialModel, WorldModel

M, N = Param("m"), Param("n")
#: Ample for every goal here: a session may spend its effort differently from a fresh
#: task (z3's incremental solver does), so only answers found within the bound compare.
EFFORT = 5000
THINGS = ("ROBOT", "BOX1", "BOX2", "BOX3")
PLACES = ("a", "b", "c", "d")
ROOMS = ("R1", "R2", "R3")

#: The derived facts of the sessions' M0 and the facts each rests on (paper, III.B).
_DERIVED = {
    ("NEAR", "ROBOT", "BOX1"): (("AT", "ROBOT", "a"), ("AT", "BOX1", "a")),
    ("SAMEROOM", "BOX1", "BOX2"): (("INROOM", "BOX1", "R1"), ("INROOM", "BOX2", "R1")),
}


def _pos(*atom: object) -> Clause:
    return Clause([(True, tuple(atom))])


def _neg(*atoms: tuple) -> tuple[Clause, ...]:
    return (Clause([(False, atom) for atom in atoms]),)


def sessions_m0(quantified: bool) -> InitialModel:
    """A small robot world: facts, derived facts with their supports and (if the prover
    reasons with them) rules. Without rules CONNECTS is rigid (the random steps never add
    it), which a prover may use to order its search, as a fresh task's ``rigid`` lets it."""
    facts: list[Atom] = [
        ("AT", "ROBOT", "a"), ("AT", "BOX1", "a"), ("AT", "BOX2", "b"), ("AT", "BOX3", "c"),
        ("INROOM", "ROBOT", "R1"), ("INROOM", "BOX1", "R1"), ("INROOM", "BOX2", "R1"),
        ("INROOM", "BOX3", "R2"), ("CONNECTS", "D1", "R1", "R2"), ("CONNECTS", "D2", "R2", "R3"),
        ("NEXTTO", "BOX2", "BOX3"),
    ]
    clauses = [_pos(*atom) for atom in facts]
    if quantified:
        # CONNECTS(x, y, z) -> CONNECTS(x, z, y); NEXTTO(x, y) -> NEXTTO(y, x)
        clauses.append(Clause([(False, ("CONNECTS", 0, 1, 2)), (True, ("CONNECTS", 0, 2, 1))]))
        clauses.append(Clause([(False, ("NEXTTO", 0, 1)), (True, ("NEXTTO", 1, 0))]))
        # AT(x, a) -> ATA(x)
        clauses.append(Clause([(False, ("AT", 0, "a")), (True, ("ATA", 0))]))
    supports: dict[int, frozenset[int]] = {}
    for atom, rests_on in _DERIVED.items():
        supports[len(clauses)] = frozenset(facts.index(fact) for fact in rests_on)
        clauses.append(Clause([(True, atom)], label="derived"))
    return InitialModel(clauses, supports, rigid=() if quantified else {("CONNECTS", 3)})


def _goals(quantified: bool) -> list[tuple[Clause, ...]]:
    goals = [
        _neg(("AT", "ROBOT", M)),
        _neg(("AT", M, "a")),
        _neg(("INROOM", M, N), ("INROOM", "BOX3", N)),
        _neg(("AT", "ROBOT", M), ("AT", "BOX2", M)),
        _neg(("NEAR", "ROBOT", "BOX1")),
        _neg(("SAMEROOM", "BOX1", M)),
        _neg(("NEXTTO", M, "BOX2")),
        _neg(("CONNECTS", M, N, "R2"), ("INROOM", "ROBOT", N)),
        (Clause([(False, ("AT", "BOX1", "a"))]), Clause([(False, ("AT", "BOX1", "b"))])),
    ]
    if quantified:
        goals.append(_neg(("CONNECTS", M, "R3", N)))
        goals.append(_neg(("NEXTTO", "BOX3", M)))
        # ¬(AT(BOX1, a) -> ATA(BOX1)): a positive goal clause that a deleted fact of M0
        # must not subsume away.
        goals.append((_pos("AT", "BOX1", "a"), *_neg(("ATA", "BOX1"))))
    return goals


def _random_atom(rng: random.Random) -> Atom:
    kind = rng.choice(("AT", "INROOM", "NEXTTO"))
    if kind == "AT":
        return ("AT", rng.choice(THINGS), rng.choice(PLACES))
    if kind == "INROOM":
        return ("INROOM", rng.choice(THINGS), rng.choice(ROOMS))
    return ("NEXTTO", rng.choice(THINGS), rng.choice(THINGS))


def _random_step(model: WorldModel, rng: random.Random) -> WorldModel:
    """Delete what a ``$`` pattern or a ground atom names, then add a few atoms, as an
    operator does."""
    patterns: list[Atom] = [
        (rng.choice(("AT", "INROOM", "NEXTTO")), rng.choice(THINGS), WILDCARD),
        _random_atom(rng),
    ]
    chosen = patterns[: rng.randint(0, 2)]
    deleted = frozenset(
        fact
        for pattern in chosen
        for fact in model.facts_matching(pattern)
        if may_delete(pattern, fact)
    )
    added = frozenset(_random_atom(rng) for _ in range(rng.randint(0, 2)))
    return model.changed(deleted, added)


def _compare(what: str, by_session: ProofResult, fresh: ProofResult) -> None:
    if (by_session.status, by_session.answers) != (fresh.status, fresh.answers):
        raise ConformanceFailure(
            f"{what}: the session answers {by_session.status} {by_session.answers}, a fresh "
            f"task over the model's visible clauses {fresh.status} {fresh.answers}"
        )


def check_session_agrees_with_fresh_tasks(
    prover: TheoremProver, capabilities: AbstractSet[str], seed: int, steps: int = 60
) -> None:
    """Along a seeded random walk of ``steps`` models, every goal is answered by one
    session as by a fresh task per model."""
    quantified = QUANTIFIED_AXIOMS in capabilities
    initial = sessions_m0(quantified)
    session = open_session(prover, initial, unique_names=True)
    goals = _goals(quantified)
    rng = random.Random(seed)
    model = WorldModel(initial)
    for step in range(steps):
        for number in rng.sample(range(len(goals)), 3):
            goal, answers = goals[number], rng.randint(1, 3)
            task = ProofTask.of_model(model, goal, EFFORT, answers, True)
            try:
                fresh = prover.prove(task)
            except (ValueError, NotImplementedError):
                continue  # a task it refuses (check_refuses_unsupported checks refusals)
            what = (
                f"seed {seed}, model {step} (deleted {sorted(model.deletions)}, added "
                f"{sorted(model.additions)}), goal {[str(c) for c in goal]}"
            )
            _compare(what, session.prove(model, goal, EFFORT, answers), fresh)
        model = _random_step(model, rng)
        if rng.random() < 0.1:
            model = WorldModel(initial)  # back to M0: sessions are asked out of order


def check_session_hides_and_revives_derived_clauses(prover: TheoremProver) -> None:
    """A derived clause is seen exactly while all its supports are (paper, III.B)."""
    initial = sessions_m0(quantified=False)
    session = open_session(prover, initial, unique_names=True)
    goal = _neg(("NEAR", "ROBOT", "BOX1"))
    root = WorldModel(initial)
    moved = root.changed(frozenset({("AT", "ROBOT", "a")}), frozenset({("AT", "ROBOT", "b")}))
    back = moved.changed(frozenset({("AT", "ROBOT", "b")}), frozenset({("AT", "ROBOT", "a")}))
    for what, model, follows in (
        ("in M0", root, True),
        ("after its support AT(ROBOT, a) was deleted", moved, False),
        ("after the support was added back", back, True),
    ):
        result = session.prove(model, goal, 300)
        if result.proved is not follows:
            raise ConformanceFailure(
                f"the derived fact NEAR(ROBOT, BOX1) {what}: {result.status}, but it "
                f"{'holds' if follows else 'does not hold'}"
            )
