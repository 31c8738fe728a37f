"""Where runs execute: a local thread pool or an existing Dask cluster.

Either way each run is :func:`~strips_framework.bench.runner.execute`, i.e. a child
process under limits; the executor only decides where that function is called. Results
come back to this process as they complete and are written here, one writer, so a
rescheduled Dask task (its worker died) or a resumed matrix never yields a second row.
"""

from __future__ import annotations

import uuid
from collections import Counter
from collections.abc import Generator, Sequence
from concurrent.futures import ThreadPoolExecutor, as_completed
from typing import Any, Protocol

from rich.console import Console
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)

from strips_framework.bench.isolation import LiveGroups
from strips_framework.bench.matrix import RunSpec
from strips_framework.bench.runner import FAILURES, SOLVED, execute
from strips_framework.errors import ConfigError
from strips_framework.records import Record


class Completed(Record):
    """A finished run: its row, or why the executor lost it (no row is written then)."""

    spec: RunSpec
    row: dict[str, Any] | None
    lost: str | None

    __slots__ = ("spec", "row", "lost")

    def __init__(self, spec: RunSpec, row: dict[str, Any] | None, lost: str | None = None) -> None:
        self.spec = spec
        self.row = row
        self.lost = lost


class Executor(Protocol):
    def results(self, specs: Sequence[RunSpec]) -> Generator[Completed, None, None]:
        """Runs as they complete; closing the generator stops the rest."""


class Sink(Protocol):
    done: set[str]

    def write(self, row: dict[str, Any]) -> bool: ...


class LocalExecutor(Record):
    """``jobs`` runs at a time on this machine (threads, each waiting on its child)."""

    jobs: int

    __slots__ = ("jobs",)

    def __init__(self, jobs: int = 1) -> None:
        self.jobs = jobs

    def results(self, specs: Sequence[RunSpec]) -> Generator[Completed, None, None]:
        live = LiveGroups()
        pool = ThreadPoolExecutor(self.jobs, thread_name_prefix="strips-bench")
        futures = {pool.submit(execute, spec, live): spec for spec in specs}
        try:
            for future in as_completed(futures):
                yield Completed(futures[future], future.result())
        finally:
            pool.shutdown(wait=False, cancel_futures=True)
            live.close()


class DaskExecutor(Record):
    """The runs as tasks on the Dask cluster whose scheduler is at ``address``."""

    address: str

    __slots__ = ("address",)

    def __init__(self, address: str) -> None:
        self.address = address

    def results(self, specs: Sequence[RunSpec]) -> Generator[Completed, None, None]:
        from distributed import Client
        from distributed import as_completed as dask_completed

        try:
            client = Client(self.address, timeout="20s")
        except (OSError, TimeoutError) as error:
            raise ConfigError(f"--scheduler {self.address}: cannot connect: {error}") from None
        with client:
            futures = {
                client.submit(execute, spec, key=f"strips-bench-{uuid.uuid4().hex}", pure=False): spec
                for spec in specs
            }
            try:
                for future in dask_completed(futures):
                    try:
                        yield Completed(futures[future], future.result())
                    except Exception as error:  # noqa: BLE001 -- a task the cluster gave up on (KilledWorker)
                        yield Completed(futures[future], None, f"{type(error).__name__}: {error}")
            finally:
                client.cancel(list(futures))


def run_matrix(
    specs: Sequence[RunSpec],
    sink: Sink,
    executor: Executor,
    progress: bool = True,
    max_runs: int | None = None,
) -> Counter[str]:
    """Run what ``sink`` does not hold yet, writing rows as they come; counts by status
    (and ``lost`` for runs the executor could not finish, to be run again by --resume)."""
    todo = [spec for spec in specs if spec.key not in sink.done]
    if max_runs is not None:
        todo = todo[:max_runs]
    tally: Counter[str] = Counter()
    columns = (
        TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
        TextColumn("solved {task.fields[solved]}, failed {task.fields[failed]}"),
        TimeElapsedColumn(), TextColumn("left"), TimeRemainingColumn(),
    )
    with Progress(*columns, console=Console(stderr=True), disable=not progress) as bar:
        task = bar.add_task("runs", total=len(todo), solved=0, failed=0)
        results = executor.results(todo)
        try:
            for completed in results:
                if completed.row is None:
                    tally["lost"] += 1
                    bar.console.print(f"lost {completed.spec.key}: {completed.lost}")
                elif sink.write(completed.row):
                    tally[_outcome(completed.row)] += 1
                failed = sum(tally[status] for status in FAILURES)
                bar.update(task, advance=1, solved=tally[SOLVED], failed=failed)
        finally:
            results.close()
    return tally


def _outcome(row: dict[str, Any]) -> str:
    """The row's status, except that a plan the validator rejected counts as invalid."""
    return "invalid" if row["valid"] is False else row["status"]
