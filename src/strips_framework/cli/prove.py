"""``strips prove``: a TPTP problem posed to a prover, as an automated theorem prover's
command line works (E, Vampire): a CPU time limit and no other bound by default, the SZS
status and answers printed (or ``--json``), the exit code by the status
(:data:`~strips_framework.exit_codes.BY_SZS`).

The planner asks its prover thousands of small questions, each with ``[limits] effort``
(300 given clauses); a TPTP problem is one question worth all the time there is, so
here the effort is unbounded unless ``--effort`` is given and ``--time`` (CPU seconds)
is what stops a search. The prover's own schedule (the resolution prover's automatic
mode) then runs with shares of an unbounded effort: its phases are interleaved until
one decides or the time runs out.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import TYPE_CHECKING, Any

from strips_framework import exit_codes
from strips_framework.limits import LimitReached
from strips_framework.plugin.config import Choice

if TYPE_CHECKING:  # the TPTP reader only when proving: `strips solve` starts without it
    from strips_framework.formats.tptp import TptpOutcome
    from strips_framework.planner import Planner

#: ``strips prove``'s default CPU time limit in seconds: a TPTP prover's, not the
#: planner's per-attempt effort (which a TPTP problem would outgrow).
PROVE_TIME = 60.0

#: The effort ``strips prove`` gives without ``--effort``: no bound a run reaches before
#: its time limit (effort is an int in every prover's unit; E takes it as a clause count).
UNBOUNDED_EFFORT = 2**31 - 1


def _positive_seconds(text: str) -> float:
    """An argparse type: a number of seconds > 0."""
    try:
        value = float(text)
    except ValueError:
        value = 0.0
    if not value > 0 or value == float("inf"):
        raise argparse.ArgumentTypeError(f"expected a number of seconds > 0, got {text!r}")
    return value


def _positive(text: str) -> int:
    """An argparse type: an integer >= 1."""
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1, got {text!r}")
    return value


def add_parser(commands: argparse._SubParsersAction) -> None:
    prove = commands.add_parser(
        "prove",
        help="prove a TPTP problem and print its SZS status (and a question's answers)",
        epilog="exit codes: 0 Theorem/Unsatisfiable, 1 CounterSatisfiable/Satisfiable, "
        "2 bad input, 12 GaveUp, 13 Inappropriate (e.g. arithmetic), 22 MemoryOut, "
        "23 Timeout, 32 a plugin raised an exception, 130 User (Ctrl-C)",
    )
    prove.add_argument("problem", type=Path, help="TPTP file (cnf/fof)")
    prove.add_argument("--config", type=Path, help="TOML config choosing the prover")
    prove.add_argument(
        "--time",
        type=_positive_seconds,
        default=PROVE_TIME,
        metavar="SECONDS",
        help=f"CPU time limit (default {PROVE_TIME:g}); SZS status Timeout when it runs out",
    )
    prove.add_argument(
        "--effort",
        type=_positive,
        help="prover effort (for the resolution prover: given clauses); default: unbounded, "
        "the time limit stops the search",
    )
    prove.add_argument(
        "--prover", help="a registered prover by name (default: the config's [prover] name)"
    )
    prove.add_argument(
        "--json", action="store_true", help="print status, answers, statistics and phases as JSON"
    )


def prove(planner: Planner, args: argparse.Namespace) -> int:
    """``strips prove``: the problem posed within the CPU limit; the SZS lines (or JSON)
    printed whatever happens, and the exit code by the status (:data:`exit_codes.BY_SZS`)."""
    from strips_framework.cli.process_limits import cpu_limited
    from strips_framework.formats.tptp import Inappropriate, TptpOutcome, load_tptp, prove_tptp

    config = planner.config
    if args.prover is not None and args.prover != config.choices["prover"].name:
        # Another prover than the config's: with its own defaults, not the config's options.
        choices = {**config.choices, "prover": Choice("prover", args.prover)}
        config = config._replace(choices=choices)
    prover = config.build(planner.registry, "prover")
    effort = args.effort if args.effort is not None else UNBOUNDED_EFFORT
    name = args.problem.name.removesuffix(".p")
    started = time.process_time()
    outcome = TptpOutcome("GaveUp")
    settled: list[TptpOutcome] = []  # a question's status, known before its answer search
    try:
        problem = load_tptp(args.problem)
        name = problem.name
        with cpu_limited(args.time):
            outcome = prove_tptp(prover, problem, effort, settled.append)
    except Inappropriate as error:
        print(f"strips: error: {error}", file=sys.stderr)
        outcome = TptpOutcome("Inappropriate")
    except LimitReached:
        outcome = settled[-1] if settled else TptpOutcome("Timeout")
    except MemoryError:
        outcome = settled[-1] if settled else TptpOutcome("MemoryOut")
    except KeyboardInterrupt:
        outcome = TptpOutcome("User")
    seconds = time.process_time() - started
    if args.json:
        import json

        document = _document(outcome, str(args.problem), name, prover, args, seconds)
        print(json.dumps(document, indent=2))
    else:
        lines = [f"% SZS status {outcome.status} for {name}"]
        if outcome.answers is not None:
            lines.append(f"% SZS answers Tuple {outcome.answers} for {name}")
        print("\n".join(lines))
    return exit_codes.BY_SZS[outcome.status]


def _document(
    outcome: TptpOutcome,
    path: str,
    name: str,
    prover: object,
    args: argparse.Namespace,
    seconds: float,
) -> dict[str, Any]:
    """The ``--json`` document (``docs/output.md``): status, answers, statistics, and the
    attempts made with each one's phases (the prover's schedule)."""
    return {
        "schema": "strips-prove/1",
        "problem": path,
        "name": name,
        "status": outcome.status,
        "answers": outcome.answers,
        "prover": getattr(prover, "name", type(prover).__name__),
        "limits": {"time": args.time, "effort": args.effort},
        "statistics": {"cpu_seconds": round(seconds, 4), "effort_used": outcome.effort_used},
        "attempts": [
            {
                "attempt": what,
                "status": result.status,
                "effort_used": result.effort_used,
                "phases": [
                    {"calculus": calculus, "status": status, "effort_used": effort}
                    for calculus, status, effort in result.phases
                ],
            }
            for what, result in outcome.attempts
        ],
    }
