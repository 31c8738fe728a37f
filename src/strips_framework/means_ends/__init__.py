"""Means-ends analysis and model-A* over world models: proof attempts, differences,
relevant operators, nodes and the search tree (Fikes & Nilsson, II-III)."""
