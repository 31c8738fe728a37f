"""Seeing a search: the explorer page of a search tree (``strips solve --explore``) and
the live feed to the VS Code PDDL extension's search debugger
(``strips solve --search-debugger``). Both watch a search through the planner's
observers (:mod:`strips_framework.observer`)."""
