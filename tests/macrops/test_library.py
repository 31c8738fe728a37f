"""The MACROP library file: written and read back, and every mistake named by file and
line; a library learned on another world is refused."""

from __future__ import annotations

import pytest

from strips_framework.errors import InputError
from strips_framework.logic.formulas import And
from strips_framework.macrops.library_file import library_text, read_library
from strips_framework.macrops.macrop import Library, Macrop, subsumes


@pytest.fixture
def library(generalized) -> Library:
    found = Library()
    for name, item in generalized.items():
        found, _ = found.added(Macrop(found.fresh_name(), item.table, f"{name}.strips", item.example))
    return found


def test_written_library_reads_back_the_same(tmp_path, robot, library):
    path = tmp_path / "lib.txt"
    path.write_text(library_text(library, "robot-world"))
    again = read_library(path, robot["light"])
    assert again.names() == library.names()
    for old, new in zip(library.macrops, again.macrops):
        assert [str(s) for s in new.table.steps] == [str(s) for s in old.table.steps]
        assert new.table.marked == old.table.marked
        assert new.table.unmarked == old.table.unmarked
        assert new.table.distinct == old.table.distinct
        assert new.example == old.example


def _broken(tmp_path, library, old: str, new: str):
    text = library_text(library, "robot-world")
    assert old in text
    path = tmp_path / "lib.txt"
    path.write_text(text.replace(old, new, 1))
    line = text[: text.index(old)].count("\n") + 1
    return path, line


@pytest.mark.parametrize(("old", "new", "message"), [
    ("step 2 pushto(p1, p2)", "step 3 pushto(p1, p2)", "expected step 2"),
    ("step 2 pushto(p1, p2)", "step 2 pushto(p1)", "takes 2 argument"),
    ("step 1 goto2(p1)", "step 1 fly(p1)", "'world' block does not list"),
    ("row 1 col 0 ONFLOOR", "row 1 col 1 ONFLOOR", "not in the triangle"),
    ("row 1 col 0 ONFLOOR", "row 1 col 0 ONFLOOR, INROOM(ROBOT, q9)", "'q9' is neither a parameter"),
    ("  distinct", "  distinct p3 p1 row 5", "expected 'distinct TERM TERM row R step K'"),
    ("  learned-from", "  learnt-from", "expected 'learned-from', 'parameters'"),
])
def test_a_mistake_names_its_line(tmp_path, robot, library, old, new, message):
    path, line = _broken(tmp_path, library, old, new)
    with pytest.raises(InputError, match=message) as caught:
        read_library(path, robot["light"])
    assert caught.value.line == line
    assert str(caught.value).startswith(f"{path}:{line}")


def test_a_library_from_another_world_is_refused(tmp_path, robot, library):
    """The same operator names with another definition: pushto that needs no box."""
    path = tmp_path / "lib.txt"
    path.write_text(library_text(library, "robot-world"))
    problem = robot["light"]
    changed = [
        s._replace(precondition=And(s.precondition.parts[1:])) if s.name == "pushto" else s
        for s in problem.operators
    ]
    other = problem._replace(operators=changed)
    with pytest.raises(InputError, match="learned on another world") as caught:
        read_library(path, other)
    assert "pushto(m, n)" in str(caught.value) and caught.value.line is not None


def test_a_missing_end_is_named(tmp_path, robot, library):
    text = library_text(library, "robot-world").rstrip().removesuffix("end")
    path = tmp_path / "lib.txt"
    path.write_text(text)
    with pytest.raises(InputError, match="has no 'end'"):
        read_library(path, robot["light"])


def test_an_edited_part_is_subsumed_and_not_added(generalized):
    light = generalized["light"].table
    library, _ = Library().added(Macrop("M1", light))
    part = light.edited(2)  # goto2, pushto
    assert subsumes(light, part)
    same, note = library.added(Macrop("M2", part))
    assert same.names() == ["M1"] and "M1 subsumes it" in note
    assert not subsumes(part, light)


def test_a_more_general_macrop_replaces_the_one_it_subsumes(generalized):
    light = generalized["light"].table
    special = light.substituted({p: "BOX1" for p in light.parameters()[:1]})
    library, _ = Library().added(Macrop("M1", special))
    grown, note = library.added(Macrop("M2", light))
    assert grown.names() == ["M2"] and "subsumes M1" in note
