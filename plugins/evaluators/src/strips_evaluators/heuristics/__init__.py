"""State heuristics for forward search over ground tasks.

Each module holds one heuristic: a frozen attrs class (its options are its fields) whose
``for_task`` does the per-task precomputation and returns an estimator that forward
strategies call for every state. :mod:`strips_evaluators.plugin` registers them through
the ``strips_register_heuristics`` hook; ``docs/heuristics.md`` compares them.
"""
