"""``strips learn``, ``solve --macrops``, ``table`` and ``execute`` end to end, and one
clear error line for a bad library."""

from __future__ import annotations

import xml.etree.ElementTree as ElementTree

from strips_framework.cli.main import main

from .conftest import ROBOT_WORLD

LIGHT = ROBOT_WORLD / "light.strips"
BOXES = ROBOT_WORLD / "boxes.strips"


def _learn(tmp_path) -> str:
    library = tmp_path / "lib.txt"
    assert main(["learn", str(LIGHT), str(BOXES), "-o", str(library)]) == 0
    return str(library)


def _light_plan(tmp_path):
    plan = tmp_path / "plan.txt"
    plan.write_text("goto2(BOX1)\npushto(BOX1, LIGHTSWITCH1)\nclimbonbox(BOX1)\n"
                    "turnonlight(LIGHTSWITCH1)\n")
    return plan


def test_learn_then_solve_with_the_library(tmp_path, capsys):
    library = _learn(tmp_path)
    out = capsys.readouterr().out
    assert "M1 added (4 steps)" in out and "2 MACROPs written" in out
    plan = tmp_path / "plan.txt"
    assert main(["solve", str(BOXES), "--macrops", library, "--plan-file", str(plan)]) == 0
    assert main(["validate", str(BOXES), str(plan)]) == 0


def test_table_of_a_plan_as_text_svg_and_html(tmp_path, capsys):
    plan = _light_plan(tmp_path)
    svg, html = tmp_path / "t.svg", tmp_path / "t.html"
    assert main(["table", str(LIGHT), str(plan), "--svg", str(svg), "--html", str(html)]) == 0
    out = capsys.readouterr().out
    assert "*NEXTTO(BOX1, LIGHTSWITCH1)" in out
    assert "kernel 5 (the goal): STATUS(LIGHTSWITCH1, ON)" in out
    root = ElementTree.parse(svg).getroot()
    titles = [t.text for t in root.iter("{http://www.w3.org/2000/svg}title")]
    kernels = [title for title in titles if title.startswith("kernel")]  # cells have titles too
    assert kernels == [f"kernel {i}" for i in range(1, 6)]
    assert "<svg" in html.read_text() and "kernel 1" in html.read_text()


def test_table_of_a_macrop(tmp_path, capsys):
    library = _learn(tmp_path)
    capsys.readouterr()
    assert main(["table", str(LIGHT), "--macrops", library, "--name", "M1"]) == 0
    assert "4: turnonlight(p2)" in capsys.readouterr().out


def test_execute_reports_each_step_and_the_rate(tmp_path, capsys):
    plan = _light_plan(tmp_path)
    config = tmp_path / "faults.toml"
    config.write_text("[execution]\nfailure = 0.0\n")
    assert main(["execute", str(LIGHT), "--plan", str(plan), "--config", str(config)]) == 0
    out = capsys.readouterr().out
    assert "step 4, turnonlight(LIGHTSWITCH1)" in out and "goal reached: 1/1 (100%)" in out


def test_execute_with_a_library_plans_first(tmp_path, capsys):
    library = _learn(tmp_path)
    capsys.readouterr()
    assert main(["execute", str(BOXES), "--macrops", library, "--runs", "5"]) == 0
    assert "goal reached: 5/5" in capsys.readouterr().out


def test_a_bad_library_is_one_error_line(tmp_path, capsys):
    library = tmp_path / "lib.txt"
    library.write_text("world robot-world\n  operator goto2(m) 000000000000\n")
    assert main(["solve", str(LIGHT), "--macrops", str(library)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert err[0].startswith(f"strips: error: {library}:2: operator goto2(m) differs")


def test_a_bad_fault_model_is_one_error_line(tmp_path, capsys):
    config = tmp_path / "faults.toml"
    config.write_text("[execution]\nfailure = 2.0\n")
    assert main(["execute", str(LIGHT), "--macrops", str(tmp_path / "none"), "--config",
                 str(config)]) == 2
    assert "execution.failure" in capsys.readouterr().err
