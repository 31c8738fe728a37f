"""STRIPS that learns (Fikes, Hart & Nilsson, "Learning and executing generalized robot
plans", 1972): plans as triangle tables, generalized into MACROPs, kept in a library,
used by later searches, and executed under monitoring by PLANEX."""
