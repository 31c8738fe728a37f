"""Robot worlds of any size, as ``.strips`` text: the paper's world (Table 1) grown to
more rooms, doors and boxes, plus facts about unrelated objects, up to a number of
formulas (facts and axioms).

The operators and the goal are those of ``examples/robot-world/world.inc`` and
``boxes.strips``: the robot gathers BOX1..BOX3 in ROOM1. The extra rooms hang off the
corridor ROOM5 as ROOM1..ROOM4 do; each has a door, a few locations and boxes; what is
left of the budget goes to unrelated facts (``COLOUR(THINGk, REDk)``-like atoms) and to
axioms over them, so the task keeps its plan while the world model grows.

    .venv/bin/python benchmarks/robot_worlds.py 100000 > /tmp/world.strips
"""

from __future__ import annotations

import sys
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "robot-world"
#: Of the formulas, how many are axioms (the rest facts).
AXIOM_SHARE = 0.05


def robot_world(formulas: int, rooms: int | None = None) -> str:
    """A robot-world task whose initial model holds about ``formulas`` facts and axioms.

    ``rooms`` extra rooms (by default one per 40 formulas, at most 2,000) hang off the
    corridor. Give ``rooms=0`` to grow M0 by unrelated facts and axioms alone: the
    rooms, doors and boxes are what a goal can be reached through, so they make a
    failed proof offer more alternatives, which unrelated formulas must not.
    """
    world = (EXAMPLES / "world.inc").read_text()
    base_facts, base_axioms = 25, 2  # world.inc's, counted by hand (see the test)
    if rooms is None:
        rooms = max(0, min(formulas // 40, 2000))
    constants: list[str] = []
    facts: list[str] = []
    for r in range(rooms):
        room, door = f"XROOM{r}", f"XDOOR{r}"
        constants += [room, door]
        facts += [f"TYPE({door}, DOOR)", f"CONNECTS({door}, {room}, ROOM5)"]
        for k in range(2):
            place, box = f"xloc{r}_{k}", f"XBOX{r}_{k}"
            constants += [place, box]
            facts += [
                f"LOCINROOM({place}, {room})",
                f"AT({box}, {place})",
                f"INROOM({box}, {room})",
                f"PUSHABLE({box})",
                f"TYPE({box}, BOX)",
            ]
    budget = max(0, formulas - base_facts - base_axioms - len(facts))
    axioms = int(budget * AXIOM_SHARE)
    unrelated = budget - axioms
    things = max(1, unrelated // 4)
    for t in range(unrelated):
        facts.append(f"COLOUR(THING{t % things}, SHADE{t})")
    constants += [f"THING{t}" for t in range(things)]
    constants += [f"SHADE{t}" for t in range(unrelated)]
    axiom_lines = [
        f"forall x, y: COLOUR(x, y) & MARKED{i}(y) -> NOTED{i}(x)" for i in range(axioms)
    ]
    lines = ["problem robot-large", world]
    for start in range(0, len(constants), 12):
        lines.append("constants " + " ".join(constants[start : start + 12]))
    lines.append("facts")
    lines += [f"  {fact}" for fact in facts]
    if axiom_lines:
        lines.append("axioms")
        lines += [f"  {axiom}" for axiom in axiom_lines]
    lines.append("goal NEXTTO(BOX1, BOX2) & NEXTTO(BOX2, BOX3)")  # boxes.strips
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.stdout.write(robot_world(int(sys.argv[1])))
