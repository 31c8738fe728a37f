"""Heuristics for lifted search: the delete relaxation of a PDDL task evaluated per state
as a Datalog program over the state's facts, never grounding the task."""
