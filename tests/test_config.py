"""The TOML config: defaults, choices, options and errors with key paths."""

from pathlib import Path

import pytest

from strips_framework.errors import ConfigError
from strips_framework.means_ends.strategy import MeansEndsSearch
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config
from strips_framework.plugin.manager import get_plugin_manager
from strips_framework.plugin.registry import Registry


@pytest.fixture(scope="module")
def registry():
    return Registry(get_plugin_manager(load_entrypoints=False))


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "strips.toml"
    path.write_text(text)
    return path


def test_defaults():
    config = Config.default()
    assert config.choices["strategy"].name == "means-ends"
    assert config.choices["prover"].name == "resolution"
    assert config.limits.effort > 0


def test_choice_with_options_and_limits(tmp_path, registry):
    config = Config.from_file(write(tmp_path, """
[strategy]
name = "means-ends"
max_goals = 5
[limits]
time = 10
nodes = 50
"""))
    assert config.build(registry, "strategy") == MeansEndsSearch(max_goals=5)
    assert config.limits.time == 10.0 and config.limits.nodes == 50


def test_string_shorthand(tmp_path):
    config = Config.from_file(write(tmp_path, 'evaluator = "breadth-first"\n'))
    assert config.choices["evaluator"].name == "breadth-first"


@pytest.mark.parametrize(("text", "message"), [
    ("[provr]\nname = 'x'\n",
     r"unknown key 'provr'; did you mean 'prover'\? \(expected one of: strategy, prover"),
    ("[strategy]\nmax_goal = 3\n",
     r"unknown key 'strategy.max_goal': search strategy 'means-ends' has no option 'max_goal'; "
     r"did you mean 'max_goals'\? \(options: achiever_loops, goal_agenda, goal_loops, max_goals\)"),
    ("[macrops]\ninstance = 3\n",
     r"strips.toml:2: unknown key 'macrops.instance': 'macrops' has no option 'instance'; did you mean 'instances'"),
    ("[execution]\nfailure = 2\n", r"strips.toml:2: bad value for 'execution.failure': expected a value <= 1"),
    ("[strategy]\nmax_goals = 0\n", r"bad value for 'strategy.max_goals': .*> 0.* \(got 0\)"),
    ("[strategy]\nmax_goals = 'many'\n",
     r"bad value for 'strategy.max_goals': expected an integer, got a string 'many'"),
    ("[limits]\ntime = 'long'\n",
     r"bad value for 'limits.time': expected an integer or a float, got a string 'long'"),
    ("[limits]\nnodes = -1\n", r"bad value for 'limits.nodes'"),
    ("[limits]\nspeed = 1\n", r"unknown key 'limits.speed'"),
    ("limits = 3\n", r"'limits' must be a table, got an integer"),
    ("[limits]\ntime = 1e12\n", r"bad value for 'limits.time': expected a value <= 1000000000 \(got 1000000000000.0\)"),
    ("[limits]\ntime = inf\n", r"bad value for 'limits.time'"),
    ("[limits]\nmemory = 18446744073709551616\n", r"bad value for 'limits.memory'"),
])
def test_errors_name_the_file_and_key_path(tmp_path, registry, text, message):
    path = write(tmp_path, text)
    with pytest.raises(ConfigError, match=message) as error:
        Config.from_file(path).build(registry, "strategy")
    assert str(error.value).startswith(str(path))


@pytest.mark.parametrize("path", sorted((Path(__file__).resolve().parents[1] / "examples" / "configs").glob("*.toml")), ids=lambda p: p.name)
def test_example_configs_are_valid(path):
    planner = Planner.create(Config.from_file(path))
    assert str(planner.config.source) == str(path)


def test_choices_and_configs_hash_and_share_no_default():
    """``Choice``'s options and ``Config``'s sections were one shared ``{}`` default: a
    change to one changed every later default, and ``hash`` raised on the dict."""
    from strips_framework.plugin.config import Choice

    first = Choice("prover", "resolution")
    first.options["effort"] = 1
    assert Choice("prover", "resolution").options == {}
    assert hash(Choice("prover", "z3", {"tactics": ["a"]})) == hash(Choice("prover", "z3", {"tactics": ["a"]}))
    default = Config.default()
    default.sections["macrops"] = {"instances": 1}
    assert Config.default().sections == {"execution": {}, "macrops": {}}
    assert hash(Config.default()) == hash(Config.default())
