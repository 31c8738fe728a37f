"""Pages opened in headless Chromium, for the tests and for the pictures in docs/: the
tests call these functions (into a temporary folder), and

    .venv/bin/python tests/explore/figures.py docs/images

makes the docs' screenshots with the same code. Chromium is Debian's ``chromium``
driven by Playwright, with no browser download and no network."""

from __future__ import annotations

import atexit
import shutil
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(Path(__file__).parent))

ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
        "--disable-component-update", "--disable-sync", "--no-first-run"]


def chromium() -> str | None:
    """Debian's chromium, if installed."""
    return shutil.which("chromium") or (
        "/usr/bin/chromium" if Path("/usr/bin/chromium").exists() else None)


def unavailable() -> str | None:
    """Why the browser tests cannot run here, or None when they can."""
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        return "playwright is not installed (pip install playwright)"
    if chromium() is None:
        return "Debian's chromium is not installed (apt-get install chromium)"
    return None


_shared: list[Any] = []


def shared_browser() -> Any:
    """One headless Chromium for the whole test process (Playwright's sync API allows one
    driver per thread, so the tests and the benchmarks share it), closed at exit."""
    if not _shared:
        from playwright.sync_api import sync_playwright

        driver = sync_playwright().start()
        _shared[:] = [driver, driver.chromium.launch(executable_path=chromium(), args=ARGS)]
        atexit.register(_close_shared)
    return _shared[1]


def _close_shared() -> None:
    driver, launched = _shared
    launched.close()
    driver.stop()


@contextmanager
def browser() -> Iterator[Any]:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as driver:
        launched = driver.chromium.launch(executable_path=chromium(), args=ARGS)
        try:
            yield launched
        finally:
            launched.close()


def open_page(launched: Any, path: Path, width: int = 1300, height: int = 800) -> tuple[Any, list[str]]:
    """``path`` opened from file://; every request that is not a file:// one is refused
    and listed, with the page's errors, in the list returned beside the page."""
    page = launched.new_page(viewport={"width": width, "height": height})
    problems: list[str] = []
    page.on("pageerror", lambda error: problems.append(f"page error: {error}"))

    def refuse(route: Any) -> None:
        if route.request.url.startswith("file://"):
            route.continue_()
        else:
            problems.append(f"network request: {route.request.url}")
            route.abort()

    page.route("**/*", refuse)
    page.goto(path.resolve().as_uri())
    return page, problems


def screenshot(page: Any, path: Path, full_page: bool = False) -> Path:
    """``page`` as a PNG in a palette of 256 colours (pages of flat colours lose nothing
    visible and the file shrinks by half or more; pillow comes with matplotlib, the
    bench extra); ``full_page`` takes what lies beyond the viewport too."""
    page.screenshot(path=str(path), full_page=full_page)
    try:
        from PIL import Image
    except ImportError:
        return path
    with Image.open(path) as image:
        small = image.convert("RGB").quantize(colors=256)
    small.save(path, optimize=True)
    return path


def solve(arguments: list[str]) -> None:
    from strips_framework.cli.main import main

    assert main(arguments) == 0


def _explorer_shot(launched: Any, folder: Path, task: str, node: int, height: int) -> Path:
    """The explorer of ``task`` (a robot-world example), the whole tree fitted and
    ``node`` clicked, as a screenshot."""
    page_file = folder / f"{task}.html"
    solve(["solve", str(ROOT / f"examples/robot-world/{task}.strips"), "--explore", str(page_file)])
    page, problems = open_page(launched, page_file, 1300, height)
    page.wait_for_function("window.explorer && window.explorer.ready")
    page.click("#fit")
    x, y = page.evaluate(f"window.explorer.position({node})")
    page.mouse.click(x, y)
    shot = screenshot(page, folder / f"explorer-{task}.png")
    assert not problems, problems
    return shot


def explorer_light(launched: Any, folder: Path) -> Path:
    return _explorer_shot(launched, folder, "light", 5, 800)


def explorer_five_goals(launched: Any, folder: Path) -> Path:
    return _explorer_shot(launched, folder, "five-goals", 40, 1000)


def triangle_table_light(launched: Any, folder: Path) -> Path:
    plan, table = folder / "light.plan", folder / "light-table.html"
    solve(["solve", str(ROOT / "examples/robot-world/light.strips"), "--plan-file", str(plan)])
    solve(["table", str(ROOT / "examples/robot-world/light.strips"), str(plan), "--html", str(table)])
    page, problems = open_page(launched, table, 1500, 560)
    page.click("#kernels button[data-kernel='all']")
    shot = screenshot(page, folder / "triangle-table-light.png", full_page=True)
    assert not problems, problems
    return shot


def report_16(launched: Any, folder: Path) -> Path:
    import synthetic_bench

    results = synthetic_bench.write(folder / "runs16.jsonl")
    solve(["bench", "report", str(results), "-o", str(folder / "report16")])
    page, problems = open_page(launched, folder / "report16" / "report.html", 1300, 1700)
    page.wait_for_selector("#tasks tbody tr")
    shot = screenshot(page, folder / "report-16-configs.png")
    assert not problems, problems
    return shot


FIGURES = (explorer_light, explorer_five_goals, triangle_table_light, report_16)


if __name__ == "__main__":
    import tempfile

    target = Path(sys.argv[1])
    target.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as scratch, browser() as launched:
        for make in FIGURES:
            made = make(launched, Path(scratch))
            shutil.copy(made, target / made.name)
            print(target / made.name)
