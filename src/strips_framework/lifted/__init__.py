"""Search without grounding: states are sets of ground atoms over the task's objects, and
successors and heuristic values are computed from the lifted (schematic) actions by
answering their preconditions as conjunctive queries, never by enumerating every instance
of every action up front (the paper's III.A: the prover finds the instances that hold)."""
