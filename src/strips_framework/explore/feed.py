"""A live feed of the search to the VS Code PDDL extension's search debugger
(``strips solve --search-debugger PORT``).

The debugger (jan-dolejsi/vscode-pddl, wiki page "Search tree debugger API") listens on
127.0.0.1 and takes JSON over HTTP: ``GET /about`` answers when it is up;
``POST /state/initial`` adds the root; ``POST /state`` adds a state under its
``parentId`` with its ``g``, ``earliestTime``, ``appliedAction`` and ``planHead`` (the
happenings from the root); ``POST /state/heuristic`` evaluates a known state (``h``,
``totalMakespan``, ``relaxedPlan``, ``helpfulActions``; no ``h`` marks a dead end);
``POST /plan`` takes the goal state, in the ``/state`` form, and draws the plan.

Forward search sends each state when it is numbered and its estimate when it is made
(eager search estimates a state before numbering it; the estimate then follows the
state at once). World-model strategies send a node when the evaluator scores it, after
any ancestor not sent yet (nodes made by applying a proved precondition are not
scored), and the rest of the tree when the search ends. Plans here are classical:
every happening is ``INSTANTANEOUS`` and its ``earliestTime`` is the number of steps
before it, so the debugger's time axis counts steps.
"""

from __future__ import annotations

import http.client
import json
import math
import urllib.parse
import warnings
from collections.abc import Mapping, Sequence
from typing import Any

from strips_framework.errors import StripsError
from strips_framework.explore.watch import NO_PARENT, Watcher, path_numbers

KIND = "INSTANTANEOUS"


def _action(name: str, time: float) -> dict[str, Any]:
    """A happening: ``(pick-up a)`` is sent as ``pick-up a``, as the API's examples write it."""
    return {"actionName": name.strip("()"), "shotCounter": 0, "earliestTime": time, "kind": KIND}


def _number(value: float) -> float | int:
    """A whole number as an int (the plans' costs usually are)."""
    return int(value) if value.is_integer() else value


class DebuggerFeed(Watcher):
    """Posts the search's states to the search debugger at ``url``."""

    def __init__(self, url: str, timeout: float = 5.0) -> None:
        super().__init__()
        parts = urllib.parse.urlsplit(url)
        self.url = url
        self.host, self.port = parts.hostname or "127.0.0.1", parts.port or 80
        self.base = parts.path.rstrip("/")
        self.connection = http.client.HTTPConnection(self.host, self.port, timeout=timeout)
        self.broken: str | None = None
        self.sent_nodes: set[int] = set()

    @classmethod
    def connect(cls, where: str) -> DebuggerFeed:
        """The feed to ``where`` (a port of 127.0.0.1, or an ``http://`` URL), after
        checking that the debugger answers ``GET /about``."""
        url = f"http://127.0.0.1:{where}" if where.isdigit() else where
        if not url.startswith("http://"):
            raise StripsError(f"--search-debugger: expected a port or an http:// URL, got {where!r}")
        feed = cls(url)
        try:
            feed.connection.request("GET", feed.base + "/about")
            response = feed.connection.getresponse()
            response.read()
        except OSError as error:
            raise StripsError(
                f"--search-debugger: no search debugger answers at {url} ({error}); start it "
                "in VS Code (command 'PDDL: Start search debugger') and give its port"
            ) from None
        if response.status >= 300:
            raise StripsError(f"--search-debugger: {url}/about answered HTTP {response.status}")
        return feed

    def post(self, path: str, payload: Mapping[str, Any]) -> None:
        """Send one message; after a failure, warn once and send nothing more (a debugger
        closed mid-search must not end the search)."""
        if self.broken is not None:
            return
        body = json.dumps(payload).encode("utf-8")
        try:
            self.connection.request("POST", self.base + path, body,
                                    {"Content-Type": "application/json"})
            response = self.connection.getresponse()
            response.read()
        except OSError as error:
            self.broken = str(error)
        else:
            if response.status > 204:
                self.broken = f"HTTP {response.status} for {path}"
        if self.broken is not None:
            warnings.warn(f"--search-debugger: stopped sending ({self.broken})", stacklevel=2)

    # Forward search.
    def _forward_state(self, number: int) -> dict[str, Any]:
        space, operators = self.run.space, self.task.operators
        steps = []
        at = number
        while space.parents[at] != NO_PARENT:
            steps.append(operators[space.operators[at]].name)
            at = space.parents[at]
        steps.reverse()
        head = [_action(name, time) for time, name in enumerate(steps)]
        parent = space.parents[number]
        return {
            "id": str(number),
            "parentId": None if parent == NO_PARENT else str(parent),
            "g": _number(self.g[number]),
            "earliestTime": len(steps),
            "appliedAction": head[-1] if head else None,
            "planHead": head,
        }

    def state_reached(self, number: int, parent: int, operator: int) -> None:
        state = self._forward_state(number)
        self.post("/state/initial" if parent == NO_PARENT else "/state", state)

    def state_estimated(self, number: int, h: float, preferred: Sequence[int]) -> None:
        message: dict[str, Any] = {"id": str(number), "relaxedPlan": [], "helpfulActions": []}
        if math.isfinite(h):
            operators = self.task.operators
            message["h"] = h
            message["totalMakespan"] = _number(self.g[number] + h)
            message["helpfulActions"] = [
                {"actionName": operators[op].name.strip("()"), "kind": KIND} for op in preferred
            ]
        self.post("/state/heuristic", message)

    # World-model strategies.
    def _node_state(self, node: Any) -> dict[str, Any]:
        head = [_action(step.ipc(), time) for time, step in enumerate(node.plan)]
        return {
            "id": str(node.id),
            "parentId": None if node.parent is None else str(node.parent.id),
            "g": node.cost,
            "earliestTime": len(head),
            "appliedAction": _action(node.applied.ipc(), len(head) - 1) if node.applied is not None else None,
            "planHead": head,
        }

    def _send_node(self, node: Any) -> None:
        waiting = []
        while node is not None and id(node) not in self.sent_nodes:
            waiting.append(node)
            node = node.parent
        for ancestor in reversed(waiting):
            self.sent_nodes.add(id(ancestor))
            path = "/state/initial" if ancestor.parent is None else "/state"
            self.post(path, self._node_state(ancestor))

    def node_scored(self, node: Any, score: float, parts: Mapping[str, float] | None) -> None:
        self._send_node(node)
        message: dict[str, Any] = {"id": str(node.id), "relaxedPlan": [], "helpfulActions": []}
        if math.isfinite(score):
            message |= {"h": score, "totalMakespan": node.cost + score}
        self.post("/state/heuristic", message)

    def finished(self, result: Any) -> None:
        if result.tree is not None:
            for node in result.tree.nodes:
                self._send_node(node)
            if result.tree.solution is not None:
                self.post("/plan", self._node_state(result.tree.solution))
        elif result.plan is not None and self.run is not None:
            path = path_numbers(self.run.space, self.task, result.plan)
            if path:
                self.post("/plan", self._forward_state(path[-1]))
        self.connection.close()
