"""The ``strips`` command: solve, validate plans, benchmark, prove TPTP problems, list plugins."""

from __future__ import annotations

import argparse
import json
import sys
import warnings
from collections.abc import Sequence
from pathlib import Path

from strips_framework.bench import markdown_table, run_matrix, write_csv
from strips_framework.capabilities import VOCABULARY, declared, requirements, unknown
from strips_framework.config import Config
from strips_framework.errors import InputError, StripsError
from strips_framework.planner import Planner
from strips_framework.plugins import KINDS, Registration
from strips_framework.search.result import SearchResult
from strips_framework.simulate import replay
from strips_framework.tree_dot import search_tree_to_dot


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="strips",
        description="STRIPS (Fikes & Nilsson, 1971): means-ends planning over first-order "
        "world models, with pluggable provers, evaluators and strategies.",
    )
    commands = parser.add_subparsers(dest="command", required=True)

    solve = commands.add_parser("solve", help="search for a plan")
    solve.add_argument("problem", type=Path, help="problem file (e.g. examples/three-boxes.strips)")
    solve.add_argument("--config", type=Path, help="TOML config (default: built-in defaults)")
    solve.add_argument("--plan-file", type=Path, help="also write the plan here, IPC style")
    solve.add_argument("--json", action="store_true", help="print the result as JSON")
    solve.add_argument("--tree", type=Path, help="write the search tree as Graphviz DOT")

    prove = commands.add_parser("prove", help="prove a TPTP problem and print its SZS status")
    prove.add_argument("problem", type=Path, help="TPTP file (cnf/fof)")
    prove.add_argument("--config", type=Path, help="TOML config choosing the prover")
    prove.add_argument(
        "--effort", type=_positive, help="prover effort (default: [limits] effort)"
    )

    validate = commands.add_parser(
        "validate", help="replay a plan in the independent simulator and check the goal"
    )
    validate.add_argument("problem", type=Path, help="problem file")
    validate.add_argument("plan", type=Path, help="plan file: one step a line, ';' comments")

    bench = commands.add_parser(
        "bench", help="solve problems with every strategy x evaluator x prover; print a table"
    )
    bench.add_argument("problems", type=Path, nargs="+", help="problem files")
    bench.add_argument("--config", type=Path, help="base config (limits, options)")
    bench.add_argument("--strategies", help="comma-separated names (default: the config's)")
    bench.add_argument("--evaluators", help="comma-separated names (default: the config's)")
    bench.add_argument("--provers", help="comma-separated names (default: the config's)")
    bench.add_argument("--all", action="store_true", help="every registered name of each kind")
    bench.add_argument("--csv", type=Path, help="also write the runs as CSV")

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
    args = _parser().parse_args(argv)
    warnings.formatwarning = lambda message, *_: f"strips: warning: {message}\n"
    try:
        config = Config.from_file(args.config) if getattr(args, "config", None) else None
        planner = Planner.create(config)
        if args.command == "solve":
            return _solve(planner, args)
        if args.command == "prove":
            return _prove(planner, args)
        if args.command == "validate":
            return _validate(planner, args)
        if args.command == "bench":
            return _bench(planner, args)
        return _plugins(planner)
    except StripsError as error:
        print(f"strips: error: {error}", file=sys.stderr)
        return 2


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


def _solve(planner: Planner, args: argparse.Namespace) -> int:
    problem = planner.load(args.problem)
    result = planner.solve(problem)
    if args.tree:
        args.tree.write_text(search_tree_to_dot(result, f"{problem.name}: search tree"))
    if args.plan_file and result.plan is not None:
        args.plan_file.write_text("\n".join(_plan_lines(result)) + f"\n; cost = {len(result.plan)} (unit cost)\n")
    if args.json:
        payload = {
            "problem": problem.name,
            "status": result.status,
            "plan": [str(step) for step in result.plan] if result.plan is not None else None,
            "statistics": result.statistics.as_dict(),
            "config": {kind: choice.name for kind, choice in planner.config.choices.items()},
        }
        print(json.dumps(payload, indent=2))
    else:
        print("\n".join(_plan_lines(result) + _statistics_lines(result)))
    return 0 if result.solved else 1


def _prove(planner: Planner, args: argparse.Namespace) -> int:
    from strips_framework.formats.tptp import load_tptp, szs_report

    problem = load_tptp(args.problem)
    effort = args.effort if args.effort is not None else planner.config.limits.effort
    result = planner.prover().prove(problem.task(effort=effort))
    print(szs_report(problem, result))
    return 0


def _validate(planner: Planner, args: argparse.Namespace) -> int:
    problem = planner.load(args.problem)
    try:
        lines = args.plan.read_text(encoding="utf-8").splitlines()
    except OSError as error:
        raise InputError(str(args.plan), None, None, f"cannot read plan: {error.strerror}") from None
    steps = [line.split(";")[0].strip() for line in lines]
    outcome = replay(problem, [step for step in steps if step])
    print(outcome.message)
    return 0 if outcome.valid else 1


def _bench(planner: Planner, args: argparse.Namespace) -> int:
    def names(kind: str, given: str | None) -> list[str]:
        if given:
            return [name.strip() for name in given.split(",") if name.strip()]
        if args.all:
            return planner.registry.names(kind)
        return [planner.config.choices[kind].name]

    runs = run_matrix(
        planner.config,
        args.problems,
        names("strategy", args.strategies),
        names("evaluator", args.evaluators),
        names("prover", args.provers),
    )
    print(markdown_table(runs))
    if args.csv:
        with args.csv.open("w", newline="", encoding="utf-8") as out:
            write_csv(runs, out)
    return 0


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
