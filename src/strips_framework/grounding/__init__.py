"""Grounding: from a lifted PDDL task to the numbered facts and operators forward search
works on (:class:`~strips_framework.grounding.task.GroundTask`)."""

from strips_framework.grounding.grounder import ground

__all__ = ["ground"]
