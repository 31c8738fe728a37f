"""Watching a search from outside it: what the explorer page (``--explore``) and the live
feed to the VS Code PDDL search debugger (``--search-debugger``) plug into.

The searches are not changed for them. As :mod:`strips_framework.progress` does, the
planner wraps the node evaluator (world-model strategies) or the state estimator
(forward search) of a run in each observer's wrapper, so a run without observers pays
nothing. A wrapper sees every node or state the search scores; a forward estimator's
wrapper may also define ``watch(run)``, which the forward search calls once with its
:class:`~strips_framework.forward.base.SearchRun` before it starts, so that it can see
the states as they are numbered and the expansions as they begin (see
:func:`watch_run`).
"""

from __future__ import annotations

from typing import Any, Protocol


class SearchObserver(Protocol):
    """Something that watches searches: it wraps what scores their nodes or states."""

    def evaluator(self, inner: Any) -> Any:
        """A node evaluator that scores as ``inner`` does and sees every node scored."""
        ...

    def estimator(self, inner: Any, task: Any) -> Any:
        """A state estimator for ``task`` that estimates as ``inner`` does and sees
        every state estimated; it may define ``watch(run)`` (see the module docstring)."""
        ...

    def finished(self, result: Any) -> None:
        """The search ended with ``result`` (a :class:`~strips_framework.result.Result`)."""
        ...


def watch_run(estimator: Any, run: Any) -> None:
    """Let an observing estimator see ``run`` (a no-op for any other estimator)."""
    watch = getattr(estimator, "watch", None)
    if watch is not None:
        watch(run)
