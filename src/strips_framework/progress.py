"""A long search's progress on stderr, as Fast Downward's log and pyperplan's do: how
many states (or nodes) were scored, the best score so far, and the time.

The searches are not touched: the planner wraps the heuristic's estimator (or the node
evaluator) in a counter, and a daemon thread prints a line a second from the counts, so
a run without progress (not a terminal, a library call) pays nothing.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Sequence
from typing import IO, Any, ClassVar

#: Seconds between two progress lines.
INTERVAL = 1.0


class Progress:
    """Counts and the best score of one run, shown on ``stream`` while it is entered."""

    def __init__(self, stream: IO[str], interval: float | None = None) -> None:
        self.stream = stream
        self.interval = INTERVAL if interval is None else interval
        self.scored = 0
        self.best = math.inf
        self.what = "states evaluated"
        self._started = time.perf_counter()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._shown = False

    def note(self, score: float) -> float:
        """Count one score (called for every state or node the search scores)."""
        self.scored += 1
        if score < self.best:
            self.best = score
        return score

    def line(self) -> str:
        best = "-" if math.isinf(self.best) else f"{self.best:g}"
        seconds = time.perf_counter() - self._started
        return f"strips: {self.scored} {self.what}, best {best}, {seconds:.1f} s"

    def estimator(self, inner: Any) -> CountingEstimator:
        self.what = "states evaluated"
        return CountingEstimator(inner, self)

    def evaluator(self, inner: Any) -> CountingEvaluator:
        self.what = "nodes scored"
        return CountingEvaluator(inner, self)

    def __enter__(self) -> Progress:
        self._started = time.perf_counter()
        self._thread = threading.Thread(target=self._show, name="strips-progress", daemon=True)
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
        if self._shown:
            self.stream.write("\n")
            self.stream.flush()

    def _show(self) -> None:
        while not self._stop.wait(self.interval):
            if not self.scored:
                continue  # still reading or grounding: nothing to show yet
            self.stream.write("\r" + self.line())
            self.stream.flush()
            self._shown = True


class CountingEstimator:
    """A state estimator that counts its calls and the best estimate for :class:`Progress`."""

    def __init__(self, inner: Any, progress: Progress) -> None:
        self.inner = inner
        self.progress = progress

    def estimate(self, state: int) -> float:
        return self.progress.note(self.inner.estimate(state))

    def estimate_with_preferred(self, state: int) -> tuple[float, Sequence[int]]:
        method = getattr(self.inner, "estimate_with_preferred", None)  # optional
        value, preferred = method(state) if method is not None else (self.inner.estimate(state), ())
        return self.progress.note(value), preferred


class CountingEvaluator:
    """A node evaluator that counts its calls and the best score for :class:`Progress`."""

    name: ClassVar[str] = "progress"

    def __init__(self, inner: Any, progress: Progress) -> None:
        self.inner = inner
        self.progress = progress

    @property
    def admissible(self) -> bool:
        return bool(getattr(self.inner, "admissible", False))

    def for_problem(self, operators: Any, initial: Any) -> CountingEvaluator:
        """The inner evaluator prepared for the problem when it needs it (``relaxed-plan``
        scores nothing unprepared), still counted."""
        prepare = getattr(self.inner, "for_problem", None)
        return self if prepare is None else CountingEvaluator(prepare(operators, initial), self.progress)

    def evaluate(self, node: Any) -> float:
        return self.progress.note(self.inner.evaluate(node))
