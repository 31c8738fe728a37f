"""The ``strips`` command: solve, validate plans, benchmark, prove TPTP problems, list plugins."""

from __future__ import annotations

import argparse
import contextlib
import os
import sys
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from strips_framework import __version__
from strips_framework.bench import command as bench_command
from strips_framework import exit_codes
from strips_framework.cli import report
from strips_framework.cli import macrops as macrop_command
from strips_framework.cli import prove as prove_command
from strips_framework.errors import StripsError
from strips_framework.limits import Clock, LimitReached
from strips_framework.options import declared
from strips_framework.pddl.files import is_pddl
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config
from strips_framework.plugin.registry import KINDS, Registration, Registry
from strips_framework.result import Result, Status
from strips_framework.user_files import check_writable, write_atomically

if TYPE_CHECKING:
    from strips_framework.progress import Progress


def _parser(command: str | None = None) -> argparse.ArgumentParser:
    """The command line parser: with every command, or only ``command``'s when the
    command line names one (building the arguments of all the others is a measurable
    part of a small task's whole run)."""
    parser = argparse.ArgumentParser(
        prog="strips",
        description="STRIPS (Fikes & Nilsson, 1971): means-ends planning over first-order "
        "world models, with pluggable provers, evaluators and strategies; forward search "
        "with state heuristics on PDDL tasks.",
        epilog="exit codes: 0 plan found, 1 invalid plan (validate), 2 bad input or config, "
        "11 unsolvable, 12 search ended without a plan (incomplete), 22 out of memory, "
        "23 out of time, 32 a plugin raised an exception, 130 interrupted (Ctrl-C); "
        "'strips prove' exits by SZS status (see 'strips prove --help')",
    )
    parser.add_argument("--version", action="version", version=f"strips {__version__}")
    commands = parser.add_subparsers(dest="command", required=True)
    for name, add in COMMAND_PARSERS.items():
        if command in (None, name):
            add(commands)
    return parser


def _add_solve(commands: argparse._SubParsersAction) -> None:
    solve = commands.add_parser("solve", help="search for a plan")
    solve.add_argument(
        "files",
        type=Path,
        nargs="+",
        metavar="[DOMAIN] PROBLEM",
        help="a problem file (e.g. examples/three-boxes.strips), or a PDDL problem with "
        "its domain before it (without one, the domain is looked for beside the problem)",
    )
    solve.add_argument("--config", type=Path, help="TOML config (default: built-in defaults)")
    solve.add_argument("--plan-file", type=Path, help="also write the plan here, IPC style")
    solve.add_argument("--json", action="store_true", help="print the result as JSON")
    solve.add_argument("--tree", type=Path, help="write the search tree as Graphviz DOT")
    solve.add_argument("--explore", type=Path, metavar="FILE.html",
                       help="write the search as an interactive page (one self-contained "
                       "HTML file: the tree, each node's goals, model, scores, difference)")
    solve.add_argument("--search-debugger", metavar="PORT|URL",
                       help="send the search live to the VS Code PDDL extension's search "
                       "debugger listening on this port of 127.0.0.1 (or at this URL)")
    solve.add_argument("--macrops", type=Path, metavar="LIBRARY",
                       help="use the MACROPs of this library (see 'strips learn')")


def _add_validate(commands: argparse._SubParsersAction) -> None:
    validate = commands.add_parser(
        "validate", help="replay a plan in the independent simulator and check the goal"
    )
    validate.add_argument(
        "files",
        type=Path,
        nargs="+",
        metavar="[DOMAIN] PROBLEM PLAN",
        help="problem file (PDDL: with its domain before it, or found beside it) and the "
        "plan: one step a line, ';' comments",
    )


def _add_plugins(commands: argparse._SubParsersAction) -> None:
    commands.add_parser("plugins", help="list the registered implementations and options")


#: Each command's parser, in the order ``strips --help`` lists them.
COMMAND_PARSERS = {
    "solve": _add_solve,
    "prove": prove_command.add_parser,
    "validate": _add_validate,
    "bench": bench_command.add_parser,
    "learn": macrop_command.add_learn,
    "table": macrop_command.add_table,
    "execute": macrop_command.add_execute,
    "plugins": _add_plugins,
}


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    warnings.formatwarning = lambda message, *_: f"strips: warning: {message}\n"
    planner: Planner | None = None
    try:
        if argv[:2] == ["bench", "report"]:
            return bench_command.report(argv[2:])
        args = _parser(argv[0] if argv and argv[0] in COMMAND_PARSERS else None).parse_args(argv)
        if args.command == "bench":
            return bench_command.bench(args)
        if args.command == "plugins":  # what is installed, whatever a config would choose
            return _plugins(Registry.from_plugins())
        config = Config.from_file(args.config) if getattr(args, "config", None) else Config.default()
        if args.command == "solve":
            domain, problem = _domain_and_problem(args.files, "solve")
            if is_pddl(problem, domain):
                config = config.for_pddl()
        planner = Planner.create(config)
        if args.command == "solve":
            return _solve(planner, args)
        if args.command == "prove":
            return prove_command.prove(planner, args)
        if args.command == "validate":
            return _validate(planner, args)
        return MACROP_COMMANDS[args.command](planner, args)
    except StripsError as error:
        print(f"strips: error: {error}", file=sys.stderr)
        return exit_codes.INPUT_ERROR
    except KeyboardInterrupt:  # outside a search (a search reports its statistics)
        print("strips: interrupted", file=sys.stderr)
        return exit_codes.INTERRUPTED
    except BrokenPipeError:  # `strips plugins | head`: the reader has what it wanted
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # no error at exit
        return exit_codes.SOLVED
    except OSError as error:
        if error.filename is None:
            raise
        # A file the user named could not be read or written (a folder, no permission,
        # a full disk): the file and the reason, as for every other bad input.
        print(f"strips: error: {error.filename}: {error.strerror}", file=sys.stderr)
        return exit_codes.INPUT_ERROR
    except Exception as error:
        culprit = planner.registry.raised_in(error) if planner is not None else None
        if culprit is None:
            raise  # a bug in the core: the traceback is what a bug report needs
        registration, where = culprit
        origin = registration.distribution or registration.plugin
        print(
            f"strips: error: {KINDS[registration.kind][1]} {registration.name!r} (plugin "
            f"{origin}) raised {type(error).__name__}: {error} (at {where})",
            file=sys.stderr,
        )
        return exit_codes.PLUGIN_ERROR


MACROP_COMMANDS = {
    "learn": macrop_command.learn,
    "table": macrop_command.table,
    "execute": macrop_command.execute_command,
}


def _domain_and_problem(files: list[Path], command: str, rest: int = 0) -> tuple[Path | None, Path]:
    """``[DOMAIN] PROBLEM`` from the positional arguments (``rest`` more follow them)."""
    if not 1 <= len(files) - rest <= 2:
        names = "[DOMAIN] PROBLEM" + " PLAN" * rest
        raise StripsError(f"usage: strips {command} {names} (got {len(files)} files)")
    given = files[: len(files) - rest]
    return (given[0] if len(given) == 2 else None), given[-1]


def _solve(planner: Planner, args: argparse.Namespace) -> int:
    from strips_framework.cli.process_limits import enforced

    domain, problem = _domain_and_problem(args.files, "solve")
    for path, what in ((args.plan_file, "the plan"), (args.tree, "the search tree"),
                       (args.explore, "the explorer page")):
        if path is not None:
            check_writable(path, what)  # before the search, not after it
    planner, watchers = _watched(planner, args)
    clock = Clock(planner.config.limits.time)
    result: Result | None = None
    progress: Progress | None = None
    if sys.stderr.isatty():  # the progress line's module (and threading) only then
        from strips_framework.progress import Progress

        progress = Progress(sys.stderr)
    try:
        with enforced(planner.config.limits, clock), progress or contextlib.nullcontext():
            result = planner._replace(progress=progress).run(problem, domain, clock, args.macrops)
    except LimitReached as limit:  # while reading or grounding: no search statistics yet
        status = limit.status
    except MemoryError:
        status = Status.MEMORY_LIMIT
    except KeyboardInterrupt:  # Ctrl-C while reading or grounding (searches catch their own)
        status = Status.INTERRUPTED
    else:
        status = result.status
    if result is not None:
        _write_files(args, problem, result)
        if args.explore is not None:
            from strips_framework.explore.page import explorer_page

            title = problem.stem if domain is None else f"{domain.parent.name}/{problem.stem}"
            write_atomically(args.explore, explorer_page(watchers[0].document(title)))
    if args.json:
        chosen = planner.config
        config = {chosen.table_of(kind): chosen.choice(kind).name for kind in planner.kinds_used()}
        where = str(domain) if domain is not None else None
        document = report.document(result, status, clock.elapsed(), str(problem), where, config)
        import json  # only --json needs it: start-up counts on small tasks

        print(json.dumps(document, indent=2))
    elif result is not None:
        print("\n".join(report.text_lines(result)))
    else:
        print("\n".join(report.limit_lines(status, clock.elapsed())))
    return exit_codes.for_status(status)


def _watched(planner: Planner, args: argparse.Namespace) -> tuple[Planner, list[Any]]:
    """The planner with the observers ``--explore`` and ``--search-debugger`` ask for
    (the explorer's record first), and those observers."""
    watchers: list[Any] = []
    if args.explore is not None:
        from strips_framework.explore.record import SearchRecord

        watchers.append(SearchRecord())
    if args.search_debugger is not None:
        from strips_framework.explore.feed import DebuggerFeed

        watchers.append(DebuggerFeed.connect(args.search_debugger))
    if not watchers:
        return planner, watchers
    return planner._replace(observers=(*planner.observers, *watchers)), watchers


def _write_files(args: argparse.Namespace, problem: Path, result: Result) -> None:
    """The ``--tree`` and ``--plan-file`` outputs of a finished search."""
    if args.tree:
        if result.tree is None:
            warnings.warn(
                f"--tree: the {result.statistics.family} search keeps no tree to draw "
                f"(only the world-model strategies do; --explore shows its states); "
                f"{args.tree} not written",
                stacklevel=1,
            )
        else:
            from strips_framework.cli.tree_dot import search_tree_to_dot

            dot = search_tree_to_dot(result.tree, f"{problem.stem}: search tree")
            write_atomically(args.tree, dot, "the search tree")
    if args.plan_file and result.plan is not None and result.cost is not None:
        from strips_framework.formats.ipc import plan_text  # only --plan-file needs it

        write_atomically(args.plan_file, plan_text(result.plan, result.cost, result.uses_costs), "the plan")


def _validate(planner: Planner, args: argparse.Namespace) -> int:
    domain, problem = _domain_and_problem(args.files, "validate", rest=1)
    from strips_framework.formats.ipc import read_plan

    steps = read_plan(args.files[-1], ipc_only=is_pddl(problem, domain))
    if is_pddl(problem, domain):
        from strips_framework.pddl.validate import validate_plan

        check = validate_plan(planner.load_pddl(problem, domain), steps)
        print(check.message)
        return exit_codes.SOLVED if check.valid else exit_codes.INVALID_PLAN
    from strips_framework.worldmodel.simulate import replay

    outcome = replay(planner.load(problem), steps)
    print(outcome.message)
    return exit_codes.SOLVED if outcome.valid else exit_codes.INVALID_PLAN


def _plugins(registry: Registry) -> int:
    for kind, (_, _, plural) in KINDS.items():
        print(f"{plural}:")
        for registration in registry.registrations(kind):
            origin = registration.distribution or "builtin"
            print(f"  {registration.name:<20} {origin} ({registration.plugin})")
            doc = (registration.cls.__doc__ or "").strip().splitlines()
            if doc:
                print(f"      {doc[0]}")
            for line in _capability_lines(registration):
                print(f"      {line}")
            for option in declared(registration.cls):
                doc = f"  # {option.doc}" if option.doc else ""
                print(f"      {option.name} = {option.default!r}{doc}")
    return 0


def _capability_lines(registration: Registration) -> list[str]:
    """``capabilities: ...`` (unknown words marked) and ``requires: ...``, for the kinds
    that have a capability vocabulary or when the class declares anything."""
    from strips_framework.capabilities import VOCABULARY, declared, requirements, unknown

    kind, cls = registration.kind, registration.cls
    have = declared(cls, kind)
    needs = requirements(cls)
    lines = []
    if have is not None or VOCABULARY.get(kind):
        if have is None:
            lines.append("capabilities: undeclared")
        else:
            strange = unknown(have, kind)
            words = [c + (" (unknown)" if c in strange else "") for c in sorted(have)]
            lines.append(f"capabilities: {', '.join(words) or 'none'}")
    if needs:
        shown = [
            f"{KINDS[n.kind][1]} with {n.capability}" + ("" if n.strict else " (soft: a warning if missing)")
            for n in needs
        ]
        lines.append(f"requires: {'; '.join(shown)}")
    return lines
