"""Cyclic garbage collection paused while a task's structures are built.

Grounding a task and setting up its successor generator and relaxed heuristics allocate
millions of objects that all live as long as the task and none of which is garbage.
CPython's cyclic collector still runs on them: every few hundred allocations it scans
the young ones, and every full collection (one each time the heap grows by a quarter)
walks the whole heap, so with the collector on, set-up pays a traversal of everything
built so far many times over, and pays it more per object the larger the task
(blocks with 400 blocks: grounding 10.3 s with the collector, 6.5 s without; see
``benchmarks/setup_scaling.py``). Set-up makes no reference cycles worth collecting
early, so the collector waits until it is done; the next collection after that finds
whatever garbage there is.
"""

from __future__ import annotations

import gc
from collections.abc import Iterator
from contextlib import contextmanager


@contextmanager
def collection_paused() -> Iterator[None]:
    """Run the block (or, as ``@collection_paused()``, the function) with the cyclic
    collector off, and turn it back on afterwards if it was on before (so nested pauses
    and a caller's own ``gc.disable()`` are left as they were)."""
    if not gc.isenabled():
        yield
        return
    gc.disable()
    try:
        yield
    finally:
        gc.enable()
