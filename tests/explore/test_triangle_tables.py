"""Triangle tables that read: every clause whole (wrapped, the cell's full text on
hover), kernels told apart (offset outlines in SVG, one at a time in HTML)."""

from __future__ import annotations

import re
from xml.etree import ElementTree

import pytest

import figures
from strips_framework import Planner
from strips_framework.formats.ipc import read_plan
from strips_framework.logic.terms import atom_to_str
from strips_framework.macrops.ground_table import ground_table, parse_plan
from strips_framework.macrops.render import _MAX_CHARS, svg_table

LIGHT = figures.ROOT / "examples/robot-world/light.strips"
SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def light_table(tmp_path_factory):
    plan = tmp_path_factory.mktemp("table") / "light.plan"
    figures.solve(["solve", str(LIGHT), "--plan-file", str(plan)])
    problem = Planner.create().load(LIGHT)
    return ground_table(problem, parse_plan(problem, read_plan(plan))).table


def _cells(svg: str):
    root = ElementTree.fromstring(svg)
    for group in root.iter(f"{SVG}g"):
        if group.get("class") == "cell":
            texts = [t.text or "" for t in group.iter(f"{SVG}text")]
            yield group, group.find(f"{SVG}title").text, texts, group.find(f"{SVG}rect")


def test_every_clause_is_whole_in_its_cell_and_fits_its_width(light_table):
    svg = svg_table(light_table, "light")
    n = light_table.size
    seen = set()
    for group, title, lines, rect in _cells(svg):
        row, col = int(group.get("data-row")), int(group.get("data-col"))
        joined = "".join(line.strip() for line in lines).replace(" ", "")
        for line in title.split("\n") if title != "(empty)" else []:
            assert line.replace(" ", "") in joined, (row, col, line)  # whole, maybe wrapped
            seen.add(line.lstrip("*"))
        width = float(rect.get("width"))
        for line in lines:
            assert len(line) <= _MAX_CHARS + 2
            assert len(line) * 7.3 <= width
        if col == row and row <= n:
            assert title == f"{row}: {light_table.steps[row - 1]}"
    for (row, col), atoms in light_table.marked.items():
        for atom in atoms:
            assert atom_to_str(atom) in seen


def test_kernel_outlines_are_offset_and_labelled(light_table):
    svg = svg_table(light_table)
    root = ElementTree.fromstring(svg)
    kernels = [g for g in root.iter(f"{SVG}g") if g.get("class") == "kernel"]
    assert [g.get("data-kernel") for g in kernels] == [str(i) for i in range(1, light_table.size + 2)]
    rects = [g.find(f"{SVG}rect") for g in kernels]
    lefts = [float(r.get("x")) for r in rects]
    bottoms = [float(r.get("y")) + float(r.get("height")) for r in rects]
    colours = [r.get("stroke") for r in rects]
    assert len(set(lefts)) == len(lefts) and len(set(bottoms)) == len(bottoms)
    assert len(set(colours)) == len(colours)
    assert [g.find(f"{SVG}text").text for g in kernels] == [f"K{i}" for i in range(1, len(kernels) + 1)]
    # The outlines' shared edges run in the gutter, left of and below every cell.
    cells = [rect for _, _, _, rect in _cells(svg)]
    first_cell = min(float(r.get("x")) for r in cells)
    last_row = max(float(r.get("y")) + float(r.get("height")) for r in cells)
    assert max(lefts) < first_cell and min(bottoms) > last_row


def test_repr_svg_is_the_picture(light_table):
    assert light_table._repr_svg_() == svg_table(light_table)


def test_html_table_shows_one_kernel_at_a_time(launched, tmp_path, light_table):
    shot = figures.triangle_table_light(launched, tmp_path)
    assert shot.read_bytes().startswith(b"\x89PNG")
    page, problems = figures.open_page(launched, tmp_path / "light-table.html")
    page.click("#kernels button[data-kernel='3']")
    visible = page.evaluate("""[...document.querySelectorAll('svg .kernel')]
        .filter((g) => getComputedStyle(g).display !== 'none').map((g) => g.dataset.kernel)""")
    assert visible == ["3"]
    inside = page.evaluate("""[...document.querySelectorAll('svg .cell.inside')]
        .map((c) => [+c.dataset.row, +c.dataset.col])""")
    n = light_table.size
    assert sorted(map(tuple, inside)) == sorted((r, c) for r in range(3, n + 2) for c in range(min(r, 3)))
    text = page.inner_text("#kernel-text")
    assert text.startswith("kernel 3: ")
    assert re.sub(r"\s", "", text.split(": ", 1)[1]) == re.sub(
        r"\s", "", ", ".join(atom_to_str(a) for a in light_table.kernel(3)))
    page.click("svg .cell[data-row='5'][data-col='5']")  # op_5's cell: its kernel
    assert page.inner_text("#kernel-text").startswith("kernel 5: ")
    assert not problems, problems
