"""strips-framework as a Unified Planning engine: ``import up_strips`` registers the
one-shot planner ``strips`` with the default UP environment, after which
``OneshotPlanner(name="strips")`` (or a kind-based ``OneshotPlanner(problem_kind=...)``)
finds it. Unified Planning has no plugin entry points, so the import is what registers
it; :func:`register` does the same for another environment."""

from __future__ import annotations

from unified_planning.environment import Environment, get_environment

from up_strips.engine import StripsEngine

ENGINE_NAME = "strips"

__all__ = ["ENGINE_NAME", "StripsEngine", "register"]


def register(environment: Environment | None = None) -> None:
    """Add the ``strips`` engine to ``environment``'s factory (default: UP's global
    environment); registering it again is a no-op."""
    factory = (environment or get_environment()).factory
    if ENGINE_NAME not in factory.engines:
        factory.add_engine(ENGINE_NAME, "up_strips.engine", "StripsEngine")


register()
