"""A worked example of a strips-framework plugin distribution (see
``docs/writing-plugins.md``): the prover ``facts`` and the evaluator ``goals-left``."""
