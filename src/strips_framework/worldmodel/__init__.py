"""World models (Fikes & Nilsson, III.D): the problem as written, M0 and the models that
operators derive from it by ADDITIONS and DELETIONS, operator application, the prover
interface that answers questions about a model, and plan simulation."""
