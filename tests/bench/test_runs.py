"""Running a matrix locally: rows, failures with their causes, interruption and resume."""

from __future__ import annotations

import signal
import subprocess
import sys
import time
import tomllib
from collections import Counter
from pathlib import Path

from strips_framework.bench.configs import PlannerConfig, RunFiles, strips_command
from strips_framework.cli.main import main

from .conftest import PUSH_ONE_BOX, ROOT, THREE_BOXES, fake, read_rows

SMALL = f"""
repetitions = 2
seed = 3
[limits]
time = 30
memory = 1024
[problems]
paper = ["{PUSH_ONE_BOX}", "{THREE_BOXES}"]
[product]
evaluator = ["paper", "goal-count"]
[configs.short-goals]
strategy = {{name = "means-ends", max_goals = 1}}
"""


def test_a_small_matrix_gives_one_validated_row_per_run(write_matrix, tmp_path):
    out = tmp_path / "results.jsonl"
    assert main(["bench", str(write_matrix(SMALL)), "-o", str(out), "--jobs", "2",
                 "--no-progress"]) == 0
    rows = read_rows(out)
    assert len(rows) == 2 * 2 * 3
    assert len({row["key"] for row in rows}) == len(rows)
    for row in rows:
        assert row["seed"] == 3 + row["repetition"]
        assert row["machine"]["cpus"] and row["versions"]["strips-framework"]
        assert row["limits"] == {"time": 30.0, "memory_mib": 1024}
        assert row["config_spec"]["kind"] == "planner"
    solved = [row for row in rows if row["config"] != "short-goals"]
    assert all(row["status"] == "solved" and row["valid"] is True for row in solved)
    three_boxes = [row for row in solved if row["problem"].endswith("three-boxes.strips")
                   and row["config"] == "paper"]
    assert {row["plan_length"] for row in three_boxes} == {4}
    assert {row["expanded"] for row in three_boxes} == {9}
    assert all(row["validation"].startswith("valid plan of 4 steps") for row in three_boxes)
    short = [row for row in rows if row["config"] == "short-goals"]
    assert {row["status"] for row in short} == {"unsolved"}  # no room for subgoals
    assert {row["cause"] for row in short} == {"planner status: exhausted"}


def test_a_crash_a_hang_and_a_memory_hog_cost_their_own_runs(write_matrix, tmp_path):
    matrix = write_matrix(f"""
[limits]
time = 3
memory = 400
[problems]
one = ["{PUSH_ONE_BOX}"]
[configs.crash]
{fake("crash")}
[configs.hang]
{fake("hang")}
[configs.hog]
{fake("hog")}
[configs.unsolvable]
{fake("unsolvable")}
[configs.fake-solver]
{fake("solve")}
[configs.json-solver]
{fake("json")}
""")
    out = tmp_path / "results.jsonl"
    assert main(["bench", str(matrix), "-o", str(out), "--jobs", "2", "--no-progress"]) == 0
    rows = {row["config"]: row for row in read_rows(out)}
    assert len(rows) == 6, rows.keys()
    assert rows["crash"]["status"] == "crash"
    assert rows["crash"]["cause"].startswith("killed by SIGABRT")
    assert rows["hang"]["status"] == "timeout"
    assert rows["hang"]["cause"] == "wall-clock limit of 3 s: process group killed"
    assert 3 <= rows["hang"]["wall_seconds"] < 20
    assert rows["hog"]["status"] == "memout"
    assert "MemoryError" in rows["hog"]["cause"]
    assert rows["unsolvable"]["status"] == "unsolved"
    assert rows["unsolvable"]["cause"] == "unsolvable" and rows["unsolvable"]["expanded"] == 7
    fake_solver = rows["fake-solver"]
    assert (fake_solver["status"], fake_solver["expanded"], fake_solver["plan_length"]) == (
        "solved", 3, 2
    )
    assert fake_solver["valid"] is True  # its plan replays in the simulator
    assert fake_solver["config_spec"]["kind"] == "command"
    json_solver = rows["json-solver"]  # figures from the JSON, phases summed
    assert (json_solver["expanded"], json_solver["planner_seconds"]) == (5, 1.0)
    assert json_solver["valid"] is True


def test_an_invalid_plan_is_recorded_as_such(write_matrix, tmp_path, capsys):
    matrix = write_matrix(f'[problems]\np = ["{THREE_BOXES}"]\n[configs.fake]\n{fake("solve")}\n')
    out = tmp_path / "results.jsonl"
    assert main(["bench", str(matrix), "-o", str(out), "--no-progress"]) == 0
    assert "1 runs finished: invalid 1" in capsys.readouterr().err
    [row] = read_rows(out)
    assert row["status"] == "solved" and row["valid"] is False
    assert row["validation"].startswith("the goal fails in the final state")


def test_max_runs_then_resume_completes_without_duplicates(write_matrix, tmp_path, capsys):
    matrix = write_matrix(SMALL)
    out = tmp_path / "results.jsonl"
    args = ["bench", str(matrix), "-o", str(out), "--no-progress", "--jobs", "2"]
    assert main([*args, "--max-runs", "5"]) == 0
    assert len(read_rows(out)) == 5
    assert main(args) == 2  # an existing file is never overwritten by accident
    assert "results file exists: pass --resume" in capsys.readouterr().err
    with out.open("a") as torn:  # a runner killed in the middle of writing a row
        torn.write('{"key": "half a ro')
    assert main([*args, "--resume"]) == 0
    rows = read_rows(out)
    assert len(rows) == 12 and len({row["key"] for row in rows}) == 12
    assert main([*args, "--resume"]) == 0
    assert len(read_rows(out)) == 12
    assert "12 runs in the matrix, 12 already done" in capsys.readouterr().err


def test_ctrl_c_loses_no_finished_run_and_resume_finishes(write_matrix, tmp_path):
    matrix = write_matrix(f"""
[limits]
time = 60
[problems]
one = ["{PUSH_ONE_BOX}"]
[configs.quick]
{fake("solve")}
[configs.slow]
{fake("hang")}
""")
    out = tmp_path / "results.jsonl"
    command = [*strips_command("bench", str(matrix), "-o", str(out)), "--jobs", "2", "--no-progress"]
    # A shell that starts this suite in the background hands its children SIGINT ignored
    # (POSIX: asynchronous commands without job control); the runner must see the
    # Ctrl-C a terminal would send, so it starts with SIGINT's default action.
    runner = subprocess.Popen(command, stderr=subprocess.PIPE, text=True,
                              preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    # Generous waits: on a loaded machine a start-up can take many seconds.
    deadline = time.monotonic() + 120
    while not (out.exists() and out.read_text()) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert out.exists() and out.read_text(), "the quick run never finished"
    runner.send_signal(signal.SIGINT)
    _, err = runner.communicate(timeout=120)
    assert runner.returncode == 130, err
    assert "continue with --resume" in err
    assert [row["config"] for row in read_rows(out)] == ["quick"]
    hung = _running(f"fake_planner.py hang {PUSH_ONE_BOX}")
    assert hung == []  # the hung child was killed with the runner
    # 'slow' has no row yet, so its command may change (not 'quick''s, nor the limits).
    matrix.write_text(matrix.read_text().replace(fake("hang"), fake("solve")))
    assert main(["bench", str(matrix), "-o", str(out), "--resume", "--no-progress"]) == 0
    assert Counter(row["config"] for row in read_rows(out)) == {"quick": 1, "slow": 1}


def _running(fragment: str) -> list[int]:
    """The processes whose command line holds ``fragment``, read from /proc (as
    ``pgrep -f``, which a bare machine may lack)."""
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            command = (entry / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
        except OSError:  # the process ended while we looked
            continue
        if fragment in command:
            found.append(int(entry.name))
    return found


def test_running_finds_a_process_by_its_command_line():
    marker = "strips-test-marker-4711"
    child = subprocess.Popen([sys.executable, "-c", "import sys, time; time.sleep(60)", marker])
    try:
        deadline = time.monotonic() + 30
        while child.pid not in _running(marker) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert _running(marker) == [child.pid]
    finally:
        child.kill()
        child.wait()
    assert _running(marker) == []


def test_the_matrixs_time_limit_reaches_the_planner(tmp_path):
    """The planner gets the matrix's time limit (a fifth less, at most 5 s less, for
    start-up), so a long search ends by its own limit, with its statistics, instead of
    being killed without them; a config's own shorter limit stays."""
    files = RunFiles(THREE_BOXES, None, tmp_path)
    for own, matrix, expected in ((None, 10, 8.0), (None, 120, 115.0), (3, 120, 3)):
        data = {"evaluator": "paper"} | ({"limits": {"time": own}} if own else {})
        command = PlannerConfig("p", data).command(files, matrix)
        written = tomllib.loads((tmp_path / "strips.toml").read_text())
        assert written["limits"]["time"] == expected
        assert command[command.index("--config") + 1] == str(tmp_path / "strips.toml")


def test_a_planner_stopped_by_its_own_limit_is_a_timeout_with_statistics(write_matrix, tmp_path):
    five_goals = ROOT / "examples" / "robot-world" / "five-goals.strips"
    matrix = write_matrix(f"""
[limits]
time = 60
memory = 1024
[problems]
hard = ["{five_goals}"]
[configs.bfs]
evaluator = "breadth-first"
limits = {{time = 3, nodes = 100000000}}
""")
    out = tmp_path / "results.jsonl"
    assert main(["bench", str(matrix), "-o", str(out), "--no-progress"]) == 0
    (row,) = read_rows(out)
    assert row["status"] == "timeout" and row["exit_code"] == 23, row["cause"]
    assert row["cause"] == "the planner's own time limit (exit code 23)"
    assert row["statistics"]["nodes"] > 0 and row["planner_status"] == "time-limit"


def test_resume_refuses_a_matrix_whose_configs_or_limits_changed(write_matrix, tmp_path, capsys):
    out = tmp_path / "results.jsonl"
    args = ["-o", str(out), "--no-progress", "--jobs", "2"]
    assert main(["bench", str(write_matrix(SMALL)), *args]) == 0
    assert len(read_rows(out)) == 12
    changed_limits = SMALL.replace("time = 30", "time = 20")
    assert main(["bench", str(write_matrix(changed_limits)), *args, "--resume"]) == 2
    assert "cannot resume: the limits of 'paper' changed" in capsys.readouterr().err
    changed_options = SMALL.replace("max_goals = 1", "max_goals = 2")
    assert main(["bench", str(write_matrix(changed_options)), *args, "--resume"]) == 2
    assert "cannot resume: the configuration of 'short-goals' changed" in capsys.readouterr().err
    more = SMALL.replace('["paper", "goal-count"]', '["paper", "goal-count", "breadth-first"]')
    assert main(["bench", str(write_matrix(more)), *args, "--resume"]) == 0  # only added
    assert len(read_rows(out)) == 16
