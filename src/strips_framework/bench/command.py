"""The ``strips bench`` command line: run a matrix, the quick form, and ``bench report``.

    strips bench MATRIX.toml [--output RESULTS.jsonl] [--resume] [--jobs N | --scheduler tcp://HOST:PORT]
    strips bench PROBLEM... [--strategies a,b] [--evaluators ...] [--provers ...] [--all]
    strips bench report RESULTS.jsonl [--output FOLDER] [--pair A,B]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from strips_framework import exit_codes
from strips_framework.errors import ConfigError, StripsError

if TYPE_CHECKING:
    from strips_framework.bench.matrix import Matrix

# The runner, results and summary modules are imported inside the commands: `strips`
# builds this parser on every start, and `strips solve` must not pay for them.

EXTRA_HINT = "pip install 'strips-framework[bench]'"


def add_parser(commands: argparse._SubParsersAction) -> None:
    bench = commands.add_parser(
        "bench",
        help="run a benchmark matrix (or problems x strategies x evaluators x provers); "
        "'strips bench report RESULTS' summarizes and plots",
        description="Run every problem under every configuration, each run in its own "
        "process under time and memory limits; rows stream to a JSON lines file. "
        "'strips bench report RESULTS' makes the table and plots (see docs/bench.md).",
    )
    bench.add_argument("targets", type=Path, nargs="+", help="a matrix file (.toml) or problem files")
    bench.add_argument("-o", "--output", type=Path,
                       help="results file (default for a matrix: MATRIX-results.jsonl)")
    bench.add_argument("--resume", action="store_true", help="continue a results file: skip runs in it")
    bench.add_argument("--jobs", type=int, default=1, help="runs at a time on this machine (default 1)")
    bench.add_argument("--scheduler", help="run on the Dask cluster at tcp://HOST:PORT instead")
    bench.add_argument("--max-runs", type=int, help="stop after this many runs (continue with --resume)")
    bench.add_argument("--no-progress", action="store_true", help="no progress bar")
    quick = bench.add_argument_group("quick form (problem files instead of a matrix)")
    quick.add_argument("--config", type=Path, help="base strips.toml (options, planner limits)")
    for kind, plural in (("strategy", "strategies"), ("evaluator", "evaluators"), ("prover", "provers")):
        quick.add_argument(f"--{plural}", help=f"comma-separated {kind} names (default: the config's)")
    quick.add_argument("--all", action="store_true", help="every registered name of each kind")
    quick.add_argument("--time", type=float, default=60.0, help="seconds per run (default 60)")
    quick.add_argument("--memory", type=int, default=2048, help="MiB per run (default 2048)")


def report_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="strips bench report",
        description="Summary table per configuration, cactus and scatter plots (PNG, SVG), "
        "a Markdown report embedding them, and an HTML report (report.html: coverage and "
        "score tables per domain, a sortable per-task table, scatter plots named on hover).",
    )
    parser.add_argument("results", type=Path, help="a results file written by 'strips bench'")
    parser.add_argument("-o", "--output", type=Path, help="folder (default: RESULTS-report/)")
    parser.add_argument("--pair", help="the scatter plot's two configurations: A,B (default: first two)")
    parser.add_argument("--lab", action="store_true",
                        help="also write the results as Downward Lab properties (FOLDER/properties)")
    return parser


def _require_bench_extra() -> None:
    """``strips bench`` needs the ``bench`` extra's libraries (rich, tomli-w), which the
    core does not depend on: without them, one line saying how to get them."""
    import importlib.util

    missing = [name for name in ("rich", "tomli_w") if importlib.util.find_spec(name) is None]
    if missing:
        raise StripsError(
            f"strips bench needs {', '.join(missing)}: pip install 'strips-framework[bench]'"
        )


def bench(args: argparse.Namespace) -> int:
    _require_bench_extra()
    # Imported here, not at the top: every run's child is a `strips solve`, and its
    # start-up should not pay for the progress bar and the executors.
    from strips_framework.bench.executors import DaskExecutor, LocalExecutor, run_matrix
    from strips_framework.bench.matrix import Matrix
    from strips_framework.bench.results import ResultsFile, RowList, read_rows
    from strips_framework.bench.summary import (
        COLUMNS,
        markdown,
        per_problem_rows,
        summary_rows,
        tasks,
    )

    if args.jobs < 1:
        raise ConfigError(f"--jobs: expected a number >= 1, got {args.jobs}")
    matrix_form = len(args.targets) == 1 and args.targets[0].suffix == ".toml"
    matrix = Matrix.from_file(args.targets[0]) if matrix_form else _quick_matrix(args)
    for note in matrix.notes():
        print(f"strips: note: {note}", file=sys.stderr)
    output = args.output
    if output is None and matrix_form:
        output = Path(f"{args.targets[0].stem}-results.jsonl")
    sink = ResultsFile(output, args.resume) if output else RowList()
    specs = matrix.runs()
    if isinstance(sink, ResultsFile):
        sink.check_unchanged(specs)
    executor = DaskExecutor(args.scheduler) if args.scheduler else LocalExecutor(args.jobs)
    before = len(sink.done)
    print(f"{len(specs)} runs in the matrix, {before} already done"
          + (f"; results: {output}" if output else ""), file=sys.stderr)
    try:
        tally = run_matrix(specs, sink, executor, not args.no_progress, args.max_runs)
    except KeyboardInterrupt:
        print(f"\ninterrupted: {len(sink.done) - before} runs written"
              + (f" to {output}; continue with --resume" if output else ""), file=sys.stderr)
        return exit_codes.INTERRUPTED
    except ImportError as error:
        raise ConfigError(f"--scheduler needs dask.distributed ({error}): {EXTRA_HINT}") from None
    finally:
        sink.close()
    counts = ", ".join(f"{status} {count}" for status, count in sorted(tally.items()))
    print(f"{sum(tally.values())} runs finished: {counts or 'none'}", file=sys.stderr)
    if not matrix_form:  # the quick form shows its results at once
        found = tasks(sink.rows if isinstance(sink, RowList) else read_rows(output))
        header, rows = per_problem_rows(found)
        print(markdown(header, rows) + "\n\n" + markdown(COLUMNS, summary_rows(found)))
    return 1 if tally["lost"] else 0


def _quick_matrix(args: argparse.Namespace) -> Matrix:
    from strips_framework.bench.matrix import Matrix
    from strips_framework.plugin.config import Config
    from strips_framework.plugin.registry import Registry
    from strips_framework.user_files import is_file

    """The matrix the quick form's options describe: its problems, the product of the
    named (or, with --all, every registered) strategies, evaluators and provers; --all
    takes the ground-task strategies only when a problem is PDDL (the matrix runs them on
    the PDDL problems alone)."""
    registry = Registry.from_plugins()
    product: dict[str, Any] = {}
    base_config = Config.from_file(args.config) if args.config else Config.default()
    if args.config:
        product["base"] = str(args.config.resolve())
    for kind, given in (("strategy", args.strategies), ("evaluator", args.evaluators),
                        ("prover", args.provers)):
        if given:
            product[kind] = [name.strip() for name in given.split(",") if name.strip()]
        else:
            product[kind] = registry.names(kind) if args.all else [base_config.choices[kind].name]
    if args.all and not args.strategies and any(p.suffix == ".pddl" for p in args.targets):
        product["strategy"] += registry.names("ground-strategy")
    missing = [str(path) for path in args.targets if not is_file(path)]
    if missing:
        raise ConfigError(f"no such problem file: {', '.join(missing)}")
    data = {
        "problems": {"command line": [str(path.resolve()) for path in args.targets]},
        "product": product,
        "limits": {"time": args.time, "memory": args.memory},
    }
    return Matrix.from_dict(data, "strips bench", Path.cwd())


def report(argv: list[str]) -> int:
    args = report_parser().parse_args(argv)
    try:
        from strips_framework.bench.report import write_report
    except ImportError as error:
        raise StripsError(f"the report needs matplotlib ({error}): {EXTRA_HINT}") from None
    from strips_framework.bench.results import read_rows

    rows = read_rows(args.results)
    folder = args.output or args.results.with_name(f"{args.results.stem}-report")
    pair = [name.strip() for name in args.pair.split(",")] if args.pair else None
    if pair is not None and len(pair) != 2:
        raise ConfigError(f"--pair: expected two configuration names A,B, got {args.pair!r}")
    print(write_report(rows, args.results, folder, pair, args.lab))
    extra = ", properties" if args.lab else ""
    print(f"\nwritten: {folder / 'report.html'}, report.md, summary.csv{extra}, cactus and "
          "scatter plots (PNG, SVG)", file=sys.stderr)
    return 0
