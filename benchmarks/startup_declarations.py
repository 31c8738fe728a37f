"""Start-up cost of five ways to declare a value with three fields: each declares 40
classes in a fresh interpreter (its library's import included), median of 7 runs.

    env -u PYTHONDONTWRITEBYTECODE taskset -c 0 python benchmarks/startup_declarations.py

The measurement behind one way to declare values and options (``records.py``,
``options.py``), not attrs, NamedTuple or dataclasses: see ``docs/hooks.md``.
"""

from __future__ import annotations

import statistics
import subprocess
import sys

N = 40
BODIES = {
    "attrs (frozen, validators)": "import attrs\nfrom attrs.validators import instance_of, ge\n"
    + "".join(
        f"@attrs.frozen\nclass C{i}:\n"
        "    a: int = attrs.field(default=1, validator=[instance_of(int), ge(0)])\n"
        "    b: str = attrs.field(default='x', validator=instance_of(str))\n"
        "    c: float = attrs.field(default=1.0, validator=instance_of(float))\n"
        for i in range(N)
    ),
    "Configurable (options.py)": "from strips_framework.options import Configurable, Option\n"
    + "".join(
        f"class C{i}(Configurable):\n"
        "    options = (Option('a', int, 1, minimum=0), Option('b', str, 'x'), Option('c', float, 1.0))\n"
        for i in range(N)
    ),
    "Record (records.py)": "from strips_framework.records import Record\n"
    + "".join(
        f"class C{i}(Record):\n    __slots__ = ('a', 'b', 'c')\n"
        "    def __init__(self, a: int = 1, b: str = 'x', c: float = 1.0) -> None:\n"
        "        self.a = a\n        self.b = b\n        self.c = c\n"
        for i in range(N)
    ),
    "NamedTuple": "from typing import NamedTuple\n"
    + "".join(f"class C{i}(NamedTuple):\n    a: int = 1\n    b: str = 'x'\n    c: float = 1.0\n" for i in range(N)),
    "dataclass (frozen, slots)": "from dataclasses import dataclass\n"
    + "".join(
        f"@dataclass(frozen=True, slots=True)\nclass C{i}:\n    a: int = 1\n    b: str = 'x'\n    c: float = 1.0\n"
        for i in range(N)
    ),
}
#: Imported before the clock starts in every variant (the framework is loaded anyway).
BASE = "import strips_framework.records, strips_framework.options\nimport time\n"


def seconds(body: str) -> float:
    code = BASE + "started = time.perf_counter()\n" + body + "\nprint(time.perf_counter() - started)"
    runs = [
        float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout)
        for _ in range(7)
    ]
    return statistics.median(runs)


if __name__ == "__main__":
    for name, body in BODIES.items():
        print(f"{name:30} {seconds(body) * 1000:7.2f} ms for {N} classes")
