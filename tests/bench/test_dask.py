"""A matrix on a real Dask cluster on loopback: a scheduler and two workers, started with
Dask's own commands as a user would, on free ports, and stopped afterwards."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

pytest.importorskip("distributed")
from distributed import Client

from strips_framework.cli.main import main

from .conftest import PUSH_ONE_BOX, THREE_BOXES, fake, read_rows

DASK = str(Path(sys.executable).parent / "dask")


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def _start(args: list[str], log: Path) -> subprocess.Popen:
    with log.open("w") as out:
        return subprocess.Popen([DASK, *args], stdout=out, stderr=subprocess.STDOUT,
                                start_new_session=True)


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    logs = tmp_path_factory.mktemp("dask")
    address = f"tcp://127.0.0.1:{_free_port()}"
    port = address.rsplit(":", 1)[1]
    processes = [_start(["scheduler", "--host", "127.0.0.1", "--port", port, "--no-dashboard"],
                        logs / "scheduler.log")]
    worker_args = ["worker", address, "--nthreads", "1", "--no-nanny", "--no-dashboard",
                   "--host", "127.0.0.1"]
    processes += [_start(worker_args, logs / f"worker{i}.log") for i in range(2)]
    try:
        with Client(address, timeout="30s") as client:
            client.wait_for_workers(2, timeout=30)
        yield address, [worker.pid for worker in processes[1:]]  # --no-nanny: the worker itself
    finally:
        for process in processes:
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGKILL)
            process.wait()


def test_the_same_matrix_on_dask_gives_the_same_results(cluster, write_matrix, tmp_path):
    address, _ = cluster
    matrix = write_matrix(f"""
[problems]
paper = ["{PUSH_ONE_BOX}", "{THREE_BOXES}"]
[product]
evaluator = ["paper", "goal-count"]
""")
    local, remote = tmp_path / "local.jsonl", tmp_path / "dask.jsonl"
    assert main(["bench", str(matrix), "-o", str(local), "--jobs", "2", "--no-progress"]) == 0
    assert main(["bench", str(matrix), "-o", str(remote), "--scheduler", address,
                 "--no-progress"]) == 0

    def outcomes(path: Path) -> dict:
        return {r["key"]: (r["status"], r["valid"], r["plan"], r["expanded"]) for r in read_rows(path)}

    assert len(outcomes(remote)) == 4
    assert outcomes(remote) == outcomes(local)


def test_a_killed_worker_loses_and_duplicates_nothing(cluster, write_matrix, tmp_path):
    address, pids = cluster
    matrix = write_matrix(f"""
repetitions = 6
[problems]
one = ["{PUSH_ONE_BOX}"]
[configs.slow]
{fake("slow-solve")}
""")
    out = tmp_path / "results.jsonl"
    codes = []
    args = ["bench", str(matrix), "-o", str(out), "--scheduler", address, "--no-progress"]
    runner = threading.Thread(target=lambda: codes.append(main(args)))
    runner.start()
    deadline = time.monotonic() + 30
    while not (out.exists() and out.read_text()) and time.monotonic() < deadline:
        time.sleep(0.05)
    os.kill(pids[0], signal.SIGKILL)  # mid-run: each worker holds a task
    runner.join(timeout=300)  # generous: a loaded CI machine is slow, not wrong
    assert codes == [0]
    keys = [row["key"] for row in read_rows(out)]
    assert sorted(keys) == sorted(set(keys)) and len(keys) == 6
    assert all(row["status"] == "solved" for row in read_rows(out))
