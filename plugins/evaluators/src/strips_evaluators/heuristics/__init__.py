"""State heuristics for forward search over ground tasks.

Each module holds one heuristic: a :class:`~strips_framework.options.Configurable` class
(options declared, no attrs: the PDDL solve path's start-up does not pay for it) whose
``for_task`` does the per-task precomputation and returns an estimator that forward
strategies call for every state. :mod:`strips_evaluators.plugin` registers them through
the ``strips_register_heuristics`` hook; ``docs/heuristics.md`` compares them.
"""
