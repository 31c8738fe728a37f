"""Node evaluators for strips-framework's search strategies.

Each evaluator scores a search node (lower is expanded first); :mod:`strips_evaluators.plugin`
registers them through the ``strips_register_evaluators`` hook.
"""
