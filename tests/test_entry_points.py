"""The entry-point and registry caches: a run with unchanged installs imports neither
importlib.metadata nor pluggy nor any plugin module, and installing a distribution or
editing a plugin's module is seen by the next run."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

from strips_framework.plugin import entry_points

SCRIPT = """
import sys
from strips_framework.plugin.manager import get_plugin_manager
from strips_framework.plugin.registry import Registry
registry = Registry(get_plugin_manager(load_entrypoints=True))
print(",".join(registry.names("heuristic")))
print(registry.get("evaluator", "goal-count").distribution)
print("importlib.metadata" in sys.modules)
"""


#: Through the cached registry, as the CLI and ``Planner.create`` build it.
CACHED = """
import sys
from strips_framework.plugin.registry import Registry
registry = Registry.from_plugins()
print(",".join(registry.names("heuristic")))
print(registry.get("heuristic", sys.argv[1]).cls.__name__)
print(registry.get("evaluator", "goal-count").distribution)
print("pluggy" in sys.modules, "strips_evaluators.heuristics.lmcut" in sys.modules)
"""


def run(
    tmp_path: Path, extra_path: Path | None = None, script: str = SCRIPT, *args: str
) -> list[str]:
    env = {**os.environ, entry_points.CACHE_ENV: str(tmp_path / "cache")}
    env.pop("STRIPS_DISABLE_PLUGIN_AUTOLOAD", None)
    if extra_path is not None:
        env["PYTHONPATH"] = os.pathsep.join([str(extra_path), env.get("PYTHONPATH", "")])
    done = subprocess.run(
        [sys.executable, "-c", script, *args], env=env, capture_output=True, text=True, check=True
    )
    return done.stdout.split()


def fake_distribution(folder: Path) -> None:
    """A distribution 'fake-heuristics' with one entry point whose plugin registers a
    heuristic named 'fake' (a class in a module of its own, imported by the hook)."""
    folder.mkdir()
    (folder / "fake_heuristics.py").write_text(
        textwrap.dedent(
            """
            from strips_framework.plugin.hookspecs import hookimpl

            @hookimpl
            def strips_register_heuristics():
                from fake_heuristic import Fake

                return [Fake]
            """
        )
    )
    (folder / "fake_heuristic.py").write_text(
        textwrap.dedent(
            """
            class Fake:
                name = "fake"
            """
        )
    )
    info = folder / "fake_heuristics-0.1.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: fake-heuristics\nVersion: 0.1\n")
    (info / "entry_points.txt").write_text("[strips_framework]\nfake = fake_heuristics\n")


def test_a_second_run_reads_the_cache_instead_of_the_metadata(tmp_path):
    first = run(tmp_path)
    assert first[-1] == "True" and first[1] == "strips-evaluators"
    second = run(tmp_path)
    assert second == [*first[:-1], "False"]
    assert len(list((tmp_path / "cache" / "strips-framework").iterdir())) == 1


def test_a_newly_installed_distribution_is_found(tmp_path):
    before = run(tmp_path)
    assert "fake" not in before[0].split(",")
    fake_distribution(tmp_path / "site")
    after = run(tmp_path, tmp_path / "site")
    assert "fake" in after[0].split(",") and after[-1] == "True"
    again = run(tmp_path, tmp_path / "site")
    assert again[0] == after[0] and again[-1] == "False"
    assert len(list((tmp_path / "cache" / "strips-framework").iterdir())) == 1


def test_an_edited_entry_points_file_is_read_again(tmp_path):
    fake_distribution(tmp_path / "site")
    assert "fake" in run(tmp_path, tmp_path / "site")[0].split(",")
    declared = tmp_path / "site" / "fake_heuristics-0.1.dist-info" / "entry_points.txt"
    declared.write_text("[other_group]\nfake = fake_heuristics\n")
    assert "fake" not in run(tmp_path, tmp_path / "site")[0].split(",")


def test_each_installation_has_its_own_cache_file(tmp_path, monkeypatch):
    monkeypatch.setenv(entry_points.CACHE_ENV, str(tmp_path))
    here = entry_points.cache_file("entry-points-strips_framework")
    monkeypatch.setattr(sys, "prefix", str(tmp_path / "another-venv"))
    assert entry_points.cache_file("entry-points-strips_framework") not in (here, None)


def test_entry_point_values_name_modules_or_attributes():
    assert entry_points.load("os.path") is os.path
    assert entry_points.load("os.path:join") is os.path.join


def test_a_second_run_reads_the_registry_from_the_cache(tmp_path):
    first = run(tmp_path, None, CACHED, "ff")
    assert first[1:] == ["FFHeuristic", "strips-evaluators", "True", "True"]
    second = run(tmp_path, None, CACHED, "ff")
    # No pluggy, and of the heuristics only the one looked up is imported.
    assert second == [*first[:3], "False", "False"]
    assert run(tmp_path, None, CACHED, "lmcut")[1:] == ["LMCutHeuristic", "strips-evaluators", "False", "True"]


def test_the_registry_cache_sees_installs_and_edited_plugins(tmp_path):
    site = tmp_path / "site"
    run(tmp_path, None, CACHED, "ff")
    fake_distribution(site)
    installed = run(tmp_path, site, CACHED, "fake")
    assert "fake" in installed[0].split(",") and installed[1] == "Fake" and installed[3] == "True"
    assert run(tmp_path, site, CACHED, "fake")[3] == "False"
    module = site / "fake_heuristic.py"
    module.write_text(module.read_text().replace('name = "fake"', 'name = "renamed"'))
    edited = run(tmp_path, site, CACHED, "renamed")
    assert "renamed" in edited[0].split(",") and "fake" not in edited[0].split(",")
    assert edited[3] == "True"  # built through pluggy again


def test_a_plugin_that_fails_to_load_is_not_cached_and_warns_every_run(tmp_path):
    site = tmp_path / "site"
    fake_distribution(site)
    (site / "fake_heuristics.py").write_text("raise RuntimeError('broken')\n")
    env = {**os.environ, entry_points.CACHE_ENV: str(tmp_path / "cache"), "PYTHONPATH": str(site)}
    env.pop("STRIPS_DISABLE_PLUGIN_AUTOLOAD", None)
    for _ in range(2):
        done = subprocess.run([sys.executable, "-c", CACHED, "ff"], env=env, capture_output=True,
                              text=True, check=True)
        assert "plugin 'fake' (from fake-heuristics) failed to load" in done.stderr
        assert done.stdout.split()[3] == "True"
