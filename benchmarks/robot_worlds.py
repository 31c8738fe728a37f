"""Robot worlds of any size, for measuring how STRIPS scales with |M0| (paper, III.D).

The world is the paper's Table 1 (five rooms on a corridor, three boxes and a light switch
in ROOM1) grown in every direction a large world model grows: more rooms on the corridor,
each with a door, boxes and locations of its own, and facts about objects that no task
mentions (colours, weights, owners). The robot's task is the same in every size, so a
planner that scales makes the same search with the same proof attempts; only M0 grows.

    python benchmarks/robot_worlds.py 100000 > big.strips    # about 100,000 formulas
"""

from __future__ import annotations

import sys

#: The operators of the paper's robot world (Table 1), shared by every size.
OPERATORS = """\
operator goto1(m)
  pre    ONFLOOR & exists x [INROOM(ROBOT, x) & LOCINROOM(m, x)]
  delete AT(ROBOT, $), NEXTTO(ROBOT, $)
  add    AT(ROBOT, m)

operator goto2(m)
  pre    ONFLOOR & exists x [INROOM(ROBOT, x) & INROOM(m, x)]
  delete AT(ROBOT, $), NEXTTO(ROBOT, $)
  add    NEXTTO(ROBOT, m)

operator pushto(m, n)
  pre    PUSHABLE(m) & ONFLOOR & NEXTTO(ROBOT, m) & exists x [INROOM(m, x) & INROOM(n, x)]
  delete AT(ROBOT, $), NEXTTO(ROBOT, $), AT(m, $), NEXTTO(m, $), NEXTTO($, m)
  add    NEXTTO(m, n), NEXTTO(n, m), NEXTTO(ROBOT, m)

operator turnonlight(m)
  pre    exists n [TYPE(n, BOX) & ON(ROBOT, n) & NEXTTO(n, m)] & TYPE(m, LIGHTSWITCH)
  delete STATUS(m, OFF)
  add    STATUS(m, ON)

operator climbonbox(m)
  pre    ONFLOOR & TYPE(m, BOX) & NEXTTO(ROBOT, m)
  delete AT(ROBOT, $), ONFLOOR
  add    ON(ROBOT, m)

operator climboffbox(m)
  pre    TYPE(m, BOX) & ON(ROBOT, m)
  delete ON(ROBOT, m)
  add    ONFLOOR

operator gothrudoor(k, l, m)
  pre    NEXTTO(ROBOT, k) & CONNECTS(k, l, m) & INROOM(ROBOT, l) & TYPE(k, DOOR) & ONFLOOR
  delete AT(ROBOT, $), NEXTTO(ROBOT, $), INROOM(ROBOT, $)
  add    INROOM(ROBOT, m)
"""

#: Table 1's own facts: the task's part of the world, the same in every size.
CORE_FACTS = """\
  INROOM(ROBOT, ROOM1), AT(ROBOT, e), ONFLOOR
  AT(BOX1, a), AT(BOX2, b), AT(BOX3, c)
  INROOM(BOX1, ROOM1), INROOM(BOX2, ROOM1), INROOM(BOX3, ROOM1)
  PUSHABLE(BOX1), PUSHABLE(BOX2), PUSHABLE(BOX3)
  TYPE(BOX1, BOX), TYPE(BOX2, BOX), TYPE(BOX3, BOX)
  AT(LIGHTSWITCH1, d), INROOM(LIGHTSWITCH1, ROOM1), STATUS(LIGHTSWITCH1, OFF)
  TYPE(LIGHTSWITCH1, LIGHTSWITCH)
  TYPE(DOOR1, DOOR), TYPE(DOOR2, DOOR), TYPE(DOOR3, DOOR), TYPE(DOOR4, DOOR)
  CONNECTS(DOOR1, ROOM1, ROOM5), CONNECTS(DOOR2, ROOM2, ROOM5)
  CONNECTS(DOOR3, ROOM3, ROOM5), CONNECTS(DOOR4, ROOM4, ROOM5)
  LOCINROOM(f, ROOM4)
"""

CORE_CONSTANTS = (
    "a b c d e f ROBOT BOX1 BOX2 BOX3 LIGHTSWITCH1 ROOM1 ROOM2 ROOM3 ROOM4 ROOM5 "
    "DOOR1 DOOR2 DOOR3 DOOR4 BOX DOOR LIGHTSWITCH ON OFF"
)

#: Goals of the paper's tasks, by name.
GOALS = {
    "boxes": "NEXTTO(BOX1, BOX2) & NEXTTO(BOX3, BOX2)",
    "light": "STATUS(LIGHTSWITCH1, ON)",
    "other-room": "AT(ROBOT, f)",
}

#: Formulas one extra room brings: its door (TYPE, CONNECTS), a location, 4 boxes with 5
#: facts each, 2 unrelated objects with 3 facts each, and 4 constants' worth of colours.
_PER_ROOM = 2 + 1 + 4 * 5 + 2 * 3


def robot_world(formulas: int, goal: str = "boxes") -> str:
    """A ``.strips`` problem with about ``formulas`` facts and axioms (at least Table 1's)."""
    rooms = max(0, (formulas - 40) // _PER_ROOM)
    constants: list[str] = ["RED", "GREEN", "BLUE", "ALICE", "BOB"]
    facts: list[str] = []
    colours = ("RED", "GREEN", "BLUE")
    for k in range(6, 6 + rooms):
        room, door, loc = f"ROOM{k}", f"DOOR{k}", f"loc{k}"
        constants += [room, door, loc]
        facts.append(f"TYPE({door}, DOOR), CONNECTS({door}, {room}, ROOM5), LOCINROOM({loc}, {room})")
        for b in range(4):
            box = f"BOX{k}-{b}"
            spot = f"spot{k}-{b}"
            constants += [box, spot]
            facts.append(
                f"AT({box}, {spot}), INROOM({box}, {room}), PUSHABLE({box}), "
                f"TYPE({box}, BOX), COLOUR({box}, {colours[b % 3]})"
            )
        for t in range(2):
            thing = f"THING{k}-{t}"
            constants.append(thing)
            facts.append(
                f"INROOM({thing}, {room}), WEIGHT({thing}, {('ALICE', 'BOB')[t]}), "
                f"COLOUR({thing}, {colours[(k + t) % 3]})"
            )
    lines = [
        f"# A generated robot world: Table 1 and {rooms} more rooms "
        f"(benchmarks/robot_worlds.py {formulas} {goal}).",
        f"problem robot-{goal}-{formulas}",
        f"constants {CORE_CONSTANTS}",
    ]
    lines += [f"constants {' '.join(constants[i:i + 12])}" for i in range(0, len(constants), 12)]
    lines += ["primitive AT/2 NEXTTO/2 INROOM/2 ONFLOOR/0 ON/2 STATUS/2", "", "facts"]
    lines.append(CORE_FACTS.rstrip("\n"))
    lines += [f"  {line}" for line in facts]
    lines += [
        "",
        "axioms",
        "  forall x, y, z: CONNECTS(x, y, z) -> CONNECTS(x, z, y)",
        "  forall x, r1, r2: CONNECTS(x, r1, r2) -> INROOM(x, r1)",
        "",
        OPERATORS,
        f"goal {GOALS[goal]}",
        "",
    ]
    return "\n".join(lines)


if __name__ == "__main__":
    size = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    sys.stdout.write(robot_world(size, sys.argv[2] if len(sys.argv) > 2 else "boxes"))
