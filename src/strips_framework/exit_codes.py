"""The ``strips`` command's exit codes, for every strategy and for ``strips bench``'s runs.

Ours, not Fast Downward's, though chosen near them: 0, 11, 12, 22, 23 and 32 mean what
they do in FD's search component (32: its "critical error"); 1 and 2 do not (FD: a plan
found, then out of memory or time; its input errors are 31, 33 and 36), and 130 is the
shell's code for Ctrl-C.

===  ==========================================================================
0    a plan was found
1    ``strips validate``: the plan is not valid
2    bad input, config or usage (the message names the file, line or key)
11   unsolvable: a complete search visited every reachable state
12   search ended without a plan and without proof (an incomplete strategy such as
     ``ehc`` or ``means-ends`` ran out of nodes, or a node or expansion limit was hit)
22   out of memory (``[limits] memory``)
23   out of time (``[limits] time``)
32   a plugin raised an exception (a bug in it): the message names the implementation,
     its distribution and where in its code (Fast Downward's "critical error")
130  interrupted (Ctrl-C): the statistics so far are printed first (128 + SIGINT, as a
     shell reports it)
===  ==========================================================================

``strips prove`` exits by the SZS status it prints (:data:`BY_SZS`), as E does for the
first two: 0 ``Theorem``/``Unsatisfiable`` (a proof), 1 ``CounterSatisfiable``/
``Satisfiable`` (saturated: no proof exists), 12 ``GaveUp`` (the effort bound was spent
without deciding), 13 ``Inappropriate`` (a defined symbol such as ``$sum`` that no prover
interprets), 22 ``MemoryOut``, 23 ``Timeout`` (the ``--time`` CPU limit), 130 ``User``
(Ctrl-C); a syntax error is 2 and a plugin's exception 32, as for every command.
"""

from __future__ import annotations

from strips_framework.result import Status

SOLVED = 0
INVALID_PLAN = 1
INPUT_ERROR = 2
UNSOLVABLE = 11
UNSOLVED_INCOMPLETE = 12
OUT_OF_MEMORY = 22
OUT_OF_TIME = 23
PLUGIN_ERROR = 32
INTERRUPTED = 130

#: The exit code of a search that ended with each status.
BY_STATUS: dict[Status, int] = {
    Status.SOLVED: SOLVED,
    Status.UNSOLVABLE: UNSOLVABLE,
    Status.EXHAUSTED: UNSOLVED_INCOMPLETE,
    Status.NODE_LIMIT: UNSOLVED_INCOMPLETE,
    Status.EXPANSION_LIMIT: UNSOLVED_INCOMPLETE,
    Status.MEMORY_LIMIT: OUT_OF_MEMORY,
    Status.TIME_LIMIT: OUT_OF_TIME,
    Status.INTERRUPTED: INTERRUPTED,
}


DISPROVED = 1
INAPPROPRIATE = 13

#: The exit code of ``strips prove`` for each SZS status it prints.
BY_SZS: dict[str, int] = {
    "Theorem": SOLVED,
    "Unsatisfiable": SOLVED,
    "CounterSatisfiable": DISPROVED,
    "Satisfiable": DISPROVED,
    "GaveUp": UNSOLVED_INCOMPLETE,
    "Inappropriate": INAPPROPRIATE,
    "MemoryOut": OUT_OF_MEMORY,
    "Timeout": OUT_OF_TIME,
    "User": INTERRUPTED,
}


def for_status(status: Status) -> int:
    """The exit code of a search that ended with ``status``."""
    return BY_STATUS[status]
