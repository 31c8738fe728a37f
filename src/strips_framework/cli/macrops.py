"""The MACROP subcommands of ``strips``: ``learn``, ``table`` and ``execute`` (``solve
--macrops`` is an option of ``solve``)."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING

from strips_framework import exit_codes
from strips_framework.errors import InputError, StripsError
from strips_framework.user_files import write_atomically

if TYPE_CHECKING:
    from strips_framework.planner import Planner
    from strips_framework.worldmodel.problem import Problem

# The macrops package, the world-model layer and the renderers are imported inside the
# commands: `strips` builds these parsers on every start, and `strips solve` on a PDDL
# task needs none of them.


def add_learn(commands: argparse._SubParsersAction) -> None:
    learn = commands.add_parser(
        "learn", help="solve problems in turn, learning MACROPs from each plan"
    )
    learn.add_argument("problems", type=Path, nargs="+", metavar="PROBLEM",
                       help="problem files, solved in this order (PDDL: with --domain)")
    learn.add_argument("-o", "--output", type=Path, required=True, metavar="LIBRARY",
                       help="write the MACROP library here")
    learn.add_argument("--macrops", type=Path, metavar="LIBRARY",
                       help="start from this library instead of an empty one")
    learn.add_argument("--domain", type=Path, help="the PDDL domain of the problems")
    learn.add_argument("--config", type=Path, help="TOML config (strategy, [learner], limits)")


def add_table(commands: argparse._SubParsersAction) -> None:
    table = commands.add_parser("table", help="draw a plan's or a MACROP's triangle table")
    table.add_argument("files", type=Path, nargs="+", metavar="[DOMAIN] PROBLEM [PLAN]",
                       help="the problem and a plan for it (or --macrops and --name)")
    table.add_argument("--macrops", type=Path, metavar="LIBRARY", help="draw a MACROP of this library")
    table.add_argument("--name", help="the MACROP to draw (default: the first)")
    table.add_argument("--html", type=Path, help="also write the picture as an HTML page")
    table.add_argument("--svg", type=Path, help="also write the picture as SVG")
    table.add_argument("--kernel", type=int, help="outline only this kernel in the picture")
    table.add_argument("--config", type=Path, help="TOML config")


def add_execute(commands: argparse._SubParsersAction) -> None:
    run = commands.add_parser(
        "execute", help="run a plan under PLANEX monitoring in a simulated, faulty world"
    )
    run.add_argument("files", type=Path, nargs="+", metavar="[DOMAIN] PROBLEM")
    source = run.add_mutually_exclusive_group(required=True)
    source.add_argument("--plan", type=Path, help="the plan to execute")
    source.add_argument("--macrops", type=Path, metavar="LIBRARY",
                        help="plan with this library, then execute (replans use it too)")
    run.add_argument("--runs", type=int, default=1, help="executions (seeds seed/0 .. seed/N-1)")
    run.add_argument("--config", type=Path, help="TOML config; [execution] is the fault model")


def _problem(planner: Planner, files: list[Path], rest: int, command: str) -> Problem:
    """The problem of ``[DOMAIN] PROBLEM`` (PDDL translated to a first-order problem)."""
    given = files[: len(files) - rest]
    if not 1 <= len(given) <= 2:
        raise StripsError(f"usage: strips {command} [DOMAIN] PROBLEM{' PLAN' * rest}")
    domain, path = (given[0] if len(given) == 2 else None), given[-1]
    from strips_framework.pddl.files import is_pddl

    if is_pddl(path, domain):
        from strips_framework.pddl import to_problem

        return to_problem(planner.load_pddl(path, domain))
    return planner.load(path)


def learn(planner: Planner, args: argparse.Namespace) -> int:
    from strips_framework.learning import learn_sequence
    from strips_framework.macrops.library_file import read_library, write_library
    from strips_framework.macrops.macrop import Library

    problems = [(args.domain, path) for path in args.problems]
    first = _problem(planner, [*([args.domain] if args.domain else []), args.problems[0]], 0,
                     "learn")
    library = read_library(args.macrops, first) if args.macrops else Library()
    learner = planner.config.build(planner.registry, "learner")
    library, lessons = learn_sequence(planner, problems, library, learner)
    print(f"{'problem':<24} {'status':<11} {'nodes':>7} {'seconds':>8} {'steps':>5} "
          f"{'macros':>6}  learned")
    for lesson in lessons:
        length = "-" if lesson.plan_length is None else lesson.plan_length
        print(f"{lesson.problem:<24} {lesson.status:<11} {lesson.nodes:>7} "
              f"{lesson.seconds:>8.3f} {length:>5} {lesson.macrops_used:>6}  {lesson.note}")
    write_library(args.output, library, Path(args.problems[0]).parent.name or "world")
    print(f"; {len(library.macrops)} MACROPs written to {args.output}")
    return exit_codes.SOLVED


def table(planner: Planner, args: argparse.Namespace) -> int:
    from strips_framework.formats.ipc import read_plan
    from strips_framework.macrops.ground_table import ground_table, parse_plan
    from strips_framework.macrops.library_file import read_library
    from strips_framework.macrops.proofs import MacroError
    from strips_framework.macrops.render import html_table, svg_table, text_table

    if args.macrops:
        problem = _problem(planner, args.files, 0, "table")
        library = read_library(args.macrops, problem)
        if not library.macrops:
            raise InputError(str(args.macrops), None, None, "the library has no MACROPs")
        chosen = next((m for m in library.macrops if m.name == (args.name or m.name)), None)
        if chosen is None:
            raise StripsError(f"{args.macrops}: no MACROP {args.name!r} "
                              f"(it has {', '.join(library.names())})")
        drawn, title = chosen.table, f"MACROP {chosen.name}"
    else:
        if len(args.files) < 2:
            raise StripsError("usage: strips table [DOMAIN] PROBLEM PLAN (or --macrops LIBRARY)")
        problem = _problem(planner, args.files, 1, "table")
        try:
            steps = parse_plan(problem, read_plan(args.files[-1]))
            drawn = ground_table(problem, steps).table
        except MacroError as error:
            raise StripsError(f"{args.files[-1]}: {error}") from None
        title = f"{problem.name}: {args.files[-1].name}"
    if args.kernel is not None and not 1 <= args.kernel <= drawn.size + 1:
        raise StripsError(f"--kernel must be between 1 and {drawn.size + 1}")
    print(text_table(drawn, title), end="")
    if args.svg:
        write_atomically(args.svg, svg_table(drawn, title, args.kernel), "the SVG table")
    if args.html:
        write_atomically(args.html, html_table(drawn, title, args.kernel), "the HTML table")
    return exit_codes.SOLVED


def execute_command(planner: Planner, args: argparse.Namespace) -> int:
    from strips_framework.formats.ipc import read_plan
    from strips_framework.macrops.ground_table import parse_plan, solution_steps
    from strips_framework.macrops.library_file import read_library
    from strips_framework.macrops.macrop import Library
    from strips_framework.macrops.planex import FaultModel, Summary, execute
    from strips_framework.result import Status

    if args.runs < 1:
        raise StripsError(f"--runs must be at least 1, got {args.runs}")
    problem = _problem(planner, args.files, 0, "execute")
    faults: FaultModel = planner.config.section("execution")
    library = read_library(args.macrops, problem) if args.macrops else Library()

    def replan(current: Problem):
        result = planner.solve(current, library=library if library.macrops else None)
        return solution_steps(result)

    if args.plan:
        steps = parse_plan(problem, read_plan(args.plan))
    else:
        steps = replan(problem)
        if steps is None:
            print("no plan found: nothing to execute")
            return exit_codes.for_status(Status.EXHAUSTED)
    executions = [execute(problem, steps, replan, faults, run) for run in range(args.runs)]
    if args.runs == 1:
        for event in executions[0].events:
            print(f"{event.step:>4}  {event.text}")
    for line in Summary.of(executions).lines():
        print(f"; {line}")
    return exit_codes.SOLVED if all(e.reached for e in executions) else exit_codes.INVALID_PLAN

