"""The ``strips`` command: solve, validate plans, benchmark, prove TPTP problems, list plugins."""

from __future__ import annotations

import argparse
import json
import sys
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from strips_framework import exit_codes
from strips_framework.bench import command as bench_command
from strips_framework.macrops import command as macrop_command
from strips_framework.config import Config
from strips_framework.errors import StripsError
from strips_framework.ipc import plan_text, read_plan
from strips_framework.planner import Planner, is_pddl
from strips_framework.plugins import KINDS, Registration
from strips_framework.search.forward.budget import LimitReached
from strips_framework.search.forward.result import ForwardResult

if TYPE_CHECKING:
    from strips_framework.search.result import SearchResult


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="strips",
        description="STRIPS (Fikes & Nilsson, 1971): means-ends planning over first-order "
        "world models, with pluggable provers, evaluators and strategies; forward search "
        "with state heuristics on PDDL tasks.",
        epilog="exit codes: 0 plan found, 1 invalid plan (validate), 2 bad input or config, "
        "11 unsolvable, 12 search ended without a plan (incomplete), 22 out of memory, "
        "23 out of time",
    )
    commands = parser.add_subparsers(dest="command", required=True)

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
    solve.add_argument("--macrops", type=Path, metavar="LIBRARY",
                       help="use the MACROPs of this library (see 'strips learn')")

    prove = commands.add_parser("prove", help="prove a TPTP problem and print its SZS status")
    prove.add_argument("problem", type=Path, help="TPTP file (cnf/fof)")
    prove.add_argument("--config", type=Path, help="TOML config choosing the prover")
    prove.add_argument(
        "--effort", type=_positive, help="prover effort (default: [limits] effort)"
    )

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

    bench_command.add_parser(commands)
    macrop_command.add_parsers(commands)

    commands.add_parser("plugins", help="list the registered implementations and options")
    return parser


def _positive(text: str) -> int:
    """An argparse type: an integer >= 1 (a bad one is a usage error, not a traceback)."""
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1, got {text!r}")
    return value


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    warnings.formatwarning = lambda message, *_: f"strips: warning: {message}\n"
    try:
        if argv[:2] == ["bench", "report"]:
            return bench_command.report(argv[2:])
        args = _parser().parse_args(argv)
        if args.command == "bench":
            return bench_command.bench(args)
        config = Config.from_file(args.config) if getattr(args, "config", None) else Config.default()
        if args.command == "solve":
            domain, problem = _domain_and_problem(args.files, "solve")
            if is_pddl(problem, domain):
                config = config.for_pddl()
        planner = Planner.create(config)
        if args.command == "solve":
            return _solve(planner, args)
        if args.command == "prove":
            return _prove(planner, args)
        if args.command == "validate":
            return _validate(planner, args)
        if args.command in MACROP_COMMANDS:
            return MACROP_COMMANDS[args.command](planner, args)
        return _plugins(planner)
    except StripsError as error:
        print(f"strips: error: {error}", file=sys.stderr)
        return exit_codes.INPUT_ERROR


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


def _plan_lines(result: SearchResult) -> list[str]:
    return [step.ipc() for step in result.plan or ()]


def _statistics_lines(result: SearchResult) -> list[str]:
    s = result.statistics
    return [
        f"; status: {result.status}",
        f"; plan length: {len(result.plan) if result.plan is not None else '-'}",
        f"; nodes: {s.nodes} in the tree, {s.path_nodes} on the solution path",
        (
            f"; operator applications: {s.applications} in the tree, "
            f"{s.path_applications} on the solution path"
        ),
        (
            f"; time: {s.seconds:.3f} s, proving {s.proving_seconds:.3f} s "
            f"({100 * s.proving_share:.0f}%), {s.proof_attempts} proof attempts"
        ),
        f"; expanded: {s.nodes}",
    ]


def _forward_lines(result: ForwardResult) -> list[str]:
    """The plan, then the figures one a line (``expanded: N`` as Fast Downward's users'
    scripts look for it)."""
    s = result.statistics
    length = len(result.plan) if result.plan is not None else "-"
    cost = result.cost if result.cost is not None else "-"
    return [
        *(result.plan or ()),
        f"status: {result.status}",
        f"plan length: {length}",
        f"plan cost: {cost}",
        f"expanded: {s.expanded}",
        f"evaluated: {s.evaluated}",
        f"generated: {s.generated}",
        f"reopened: {s.reopened}",
        f"dead ends: {s.dead_ends}",
        f"facts: {s.facts}, operators: {s.operators}",
        (
            f"time: parse {s.parse_seconds:.3f} s, ground {s.ground_seconds:.3f} s, "
            f"search {s.search_seconds:.3f} s"
        ),
        f"peak memory: {s.peak_memory_mib:.1f} MiB",
    ]


def _solve(planner: Planner, args: argparse.Namespace) -> int:
    from strips_framework.process_limits import enforced

    domain, problem = _domain_and_problem(args.files, "solve")
    try:
        with enforced(planner.config.limits):
            result = planner.run(problem, domain, args.macrops)
    except LimitReached as limit:  # while reading or grounding: no search statistics yet
        return _report_limit(args, limit.status)
    except MemoryError:
        return _report_limit(args, "memory-limit")
    if isinstance(result, ForwardResult):
        return _report_forward(planner, args, problem, result)
    if args.tree:
        from strips_framework.tree_dot import search_tree_to_dot

        args.tree.write_text(search_tree_to_dot(result, f"{problem.stem}: search tree"))
    if args.plan_file and result.plan is not None:
        args.plan_file.write_text(plan_text(_plan_lines(result), len(result.plan), False))
    if args.json:
        payload = {
            "problem": problem.stem,
            "status": result.status,
            "plan": [str(step) for step in result.plan] if result.plan is not None else None,
            "statistics": result.statistics.as_dict(),
            "config": {kind: choice.name for kind, choice in planner.config.choices.items()},
        }
        print(json.dumps(payload, indent=2))
    else:
        print("\n".join(_plan_lines(result) + _statistics_lines(result)))
    return exit_codes.for_status(result.status)


def _report_forward(
    planner: Planner, args: argparse.Namespace, problem: Path, result: ForwardResult
) -> int:
    if args.plan_file and result.plan is not None and result.cost is not None:
        args.plan_file.write_text(plan_text(result.plan, result.cost, result.uses_costs))
    code = exit_codes.for_status(result.status)
    if args.json:
        payload = {
            "problem": str(problem),
            "status": result.status,
            "limit": result.limit,
            "exit_code": code,
            "plan": list(result.plan) if result.plan is not None else None,
            "plan_length": len(result.plan) if result.plan is not None else None,
            "cost": result.cost,
            "statistics": result.statistics.as_dict(),
            "config": {kind: choice.name for kind, choice in planner.config.choices.items()},
        }
        print(json.dumps(payload, indent=2))
    else:
        print("\n".join(_forward_lines(result)))
    return code


def _report_limit(args: argparse.Namespace, status: str) -> int:
    """A limit hit before the search began (reading or grounding)."""
    code = exit_codes.for_status(status)
    if args.json:
        print(
            json.dumps(
                {
                    "status": status,
                    "limit": status.removesuffix("-limit"),
                    "exit_code": code,
                    "plan": None,
                    "statistics": None,
                },
                indent=2,
            )
        )
    else:
        print(f"status: {status} (before the search began)")
    return code


def _prove(planner: Planner, args: argparse.Namespace) -> int:
    from strips_framework.formats.tptp import load_tptp, szs_report

    problem = load_tptp(args.problem)
    effort = args.effort if args.effort is not None else planner.config.limits.effort
    result = planner.prover().prove(problem.task(effort=effort))
    print(szs_report(problem, result))
    return 0


def _validate(planner: Planner, args: argparse.Namespace) -> int:
    domain, problem = _domain_and_problem(args.files, "validate", rest=1)
    steps = read_plan(args.files[-1])
    if is_pddl(problem, domain):
        from strips_framework.pddl.validate import validate_plan

        check = validate_plan(planner.load_pddl(problem, domain), steps)
        print(check.message)
        return exit_codes.SOLVED if check.valid else exit_codes.INVALID_PLAN
    from strips_framework.simulate import replay

    outcome = replay(planner.load(problem), steps)
    print(outcome.message)
    return exit_codes.SOLVED if outcome.valid else exit_codes.INVALID_PLAN


def _plugins(planner: Planner) -> int:
    for kind, (_, _, plural) in KINDS.items():
        print(f"{plural}:")
        for registration in planner.registry.registrations(kind):
            origin = registration.distribution or "builtin"
            print(f"  {registration.name:<20} {origin} ({registration.plugin})")
            doc = (registration.cls.__doc__ or "").strip().splitlines()
            if doc:
                print(f"      {doc[0]}")
            for line in _capability_lines(registration):
                print(f"      {line}")
            for name, default in registration.options():
                print(f"      {name} = {default!r}")
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
