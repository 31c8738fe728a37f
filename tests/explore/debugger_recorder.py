"""A stand-in for the VS Code PDDL extension's search debugger: an HTTP server on
127.0.0.1 that answers the debugger's endpoints as the extension does (``GET /about``
200; ``POST /state/initial`` and ``/state`` 201; ``/state/heuristic`` and ``/plan``
200) and records every message, and a checker of a recorded sequence against the
protocol of the wiki page "Search tree debugger API" (jan-dolejsi/vscode-pddl)."""

from __future__ import annotations

import json
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any

STATUS = {"/state/initial": 201, "/state": 201, "/state/visitedOrWorse": 201,
          "/state/heuristic": 200, "/plan": 200}
KINDS = {"START", "END", "INSTANTANEOUS", "TIMED"}


class _Handler(BaseHTTPRequestHandler):
    protocol_version = "HTTP/1.1"  # keep-alive, as express answers

    def log_message(self, *args: object) -> None:  # quiet
        pass

    def _answer(self, status: int, body: bytes = b"") -> None:
        self.send_response(status)
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def do_GET(self) -> None:  # noqa: N802
        self.server.messages.append(("GET", self.path, None))  # type: ignore[attr-defined]
        if self.path == "/about":
            self._answer(200, b"Visual search debugger.")
        else:
            self._answer(404)

    def do_POST(self) -> None:  # noqa: N802
        length = int(self.headers.get("Content-Length", 0))
        body = json.loads(self.rfile.read(length)) if length else None
        self.server.messages.append(("POST", self.path, body))  # type: ignore[attr-defined]
        self._answer(STATUS.get(self.path, 404))


@contextmanager
def recorder() -> Iterator[tuple[int, list[tuple[str, str, Any]]]]:
    """A running recorder: its port and the list its messages go into."""
    server = ThreadingHTTPServer(("127.0.0.1", 0), _Handler)
    server.messages = []  # type: ignore[attr-defined]
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield server.server_address[1], server.messages  # type: ignore[attr-defined]
    finally:
        server.shutdown()
        server.server_close()


def _happening(item: Any, where: str) -> list[str]:
    problems = []
    if not isinstance(item, dict):
        return [f"{where}: not an object"]
    for key, kind in (("actionName", str), ("shotCounter", int), ("kind", str)):
        if not isinstance(item.get(key), kind):
            problems.append(f"{where}: {key} missing or not {kind.__name__}")
    if not isinstance(item.get("earliestTime"), (int, float)):
        problems.append(f"{where}: earliestTime missing or not a number")
    if item.get("kind") not in KINDS:
        problems.append(f"{where}: kind {item.get('kind')!r} not one of {sorted(KINDS)}")
    return problems


def protocol_problems(messages: list[tuple[str, str, Any]]) -> list[str]:
    """Everything in ``messages`` the protocol does not allow (empty when it conforms):
    /about first, the initial state before any other, each state added once under a
    parent already added, heuristics only for added states (with relaxedPlan and
    helpfulActions when h is given), /plan last and for an added state."""
    problems: list[str] = []
    if not messages or messages[0][:2] != ("GET", "/about"):
        problems.append("the first message is not GET /about")
    added: dict[str, dict[str, Any]] = {}
    posts = [(path, body) for method, path, body in messages if method == "POST"]
    for number, (path, body) in enumerate(posts):
        where = f"message {number} ({path})"
        if path not in STATUS:
            problems.append(f"{where}: no such endpoint")
            continue
        if not isinstance(body, dict) or not isinstance(body.get("id"), str):
            problems.append(f"{where}: no string id")
            continue
        if path == "/state/initial":
            if added:
                problems.append(f"{where}: an initial state after other states")
            if body.get("parentId") is not None or body.get("g") != 0:
                problems.append(f"{where}: the initial state has a parent or g != 0")
            added[body["id"]] = body
        elif path in ("/state", "/plan", "/state/visitedOrWorse"):
            for key in ("g", "earliestTime"):
                if not isinstance(body.get(key), (int, float)):
                    problems.append(f"{where}: {key} missing or not a number")
            head = body.get("planHead")
            if not isinstance(head, list):
                problems.append(f"{where}: planHead is not a list")
            else:
                for k, item in enumerate(head):
                    problems += _happening(item, f"{where} planHead[{k}]")
            if body.get("appliedAction") is not None:
                problems += _happening(body["appliedAction"], f"{where} appliedAction")
            if path == "/state":
                if body["id"] in added:
                    problems.append(f"{where}: state {body['id']} added twice")
                if body.get("parentId") not in added:
                    problems.append(f"{where}: parent {body.get('parentId')!r} not added before")
                added[body["id"]] = body
            elif body["id"] not in added:
                problems.append(f"{where}: state {body['id']} was never added")
            if path == "/plan" and number != len(posts) - 1:
                problems.append(f"{where}: /plan is not the last message")
        else:  # /state/heuristic
            if body["id"] not in added:
                problems.append(f"{where}: heuristic for state {body['id']} never added")
            if "h" in body:
                if not isinstance(body["h"], (int, float)):
                    problems.append(f"{where}: h is not a number")
                for key in ("relaxedPlan", "helpfulActions"):
                    if not isinstance(body.get(key), list):
                        problems.append(f"{where}: {key} is not a list")
                for k, action in enumerate(body.get("helpfulActions") or []):
                    if not isinstance(action, dict) or action.get("kind") not in KINDS \
                            or not isinstance(action.get("actionName"), str):
                        problems.append(f"{where}: helpfulActions[{k}] malformed")
    return problems
