"""Macro learners are a plugin kind: another learner is registered through the hook and
chosen by the config, like a prover or an evaluator."""

from __future__ import annotations

from typing import ClassVar

from strips_framework.learning import learn_sequence
from strips_framework.macrops.macrop import Library, Macrop
from strips_framework.macrops.table import TriangleTable
from strips_framework.options import Configurable
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config
from strips_framework.plugin.hookspecs import hookimpl

from .conftest import ROBOT_WORLD


class UngeneralizedLearner(Configurable):
    """Keeps each plan as it is, ground (a learner that does not generalize)."""

    name: ClassVar[str] = "ground-plans"
    capabilities: ClassVar[frozenset[str]] = frozenset()

    def learn(self, problem, plan, library):
        table = TriangleTable(plan)
        return Library((*library.macrops, Macrop(library.fresh_name(), table))), "kept as is"


class Plugin:
    @hookimpl
    def strips_register_macro_learners(self):
        return [UngeneralizedLearner]


def test_a_registered_learner_is_chosen_by_the_config():
    planner = Planner.create(Config.from_dict({"learner": "ground-plans"}), [Plugin()])
    learner = planner.config.build(planner.registry, "learner")
    assert isinstance(learner, UngeneralizedLearner)
    library, lessons = learn_sequence(
        planner, [(None, ROBOT_WORLD / "boxes.strips")], Library(), learner
    )
    assert lessons[0].note == "kept as is"
    assert [str(s) for s in library.macrops[0].table.steps][0] == "goto2(BOX1)"


def test_the_builtin_learner_is_listed_with_its_options():
    planner = Planner.create()
    registration = planner.registry.get("learner", "triangle-table")
    assert dict(registration.options()) == {"eliminate": True, "min_steps": 2, "max_macrops": 50}
