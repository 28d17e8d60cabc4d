"""Refusing a process batch started at a script's top level, outside its main guard.

The ``processes`` backend spawns its workers, and a spawned worker imports the script that
started the batch (to find plans defined in it). A script that calls
``project_variants(...)`` at its top level, with no ``if __name__ == "__main__":`` round it,
starts the batch again in every worker: each worker dies, and every variant came back
``LOST WorkerDied`` with pages of tracebacks (issue 41). Before any worker starts, the
caller's frames are read: a call made from the ``__main__`` script's top-level code, on a
line outside a main guard, is refused with one line saying where and what to write.
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path
from types import FrameType

from robocram.batch.errors import UnguardedBatch


def require_main_guard(frame: FrameType | None = None) -> None:
    """Raise :class:`UnguardedBatch` when the batch is started from the ``__main__``
    script's top-level code outside ``if __name__ == "__main__":`` (``frame``: where to
    start looking up the stack; default the caller's)."""
    frame = frame if frame is not None else sys._getframe(1)
    while frame is not None:
        if frame.f_code.co_name == "<module>" and frame.f_globals.get("__name__") == "__main__":
            script = frame.f_globals.get("__file__")
            if isinstance(script, str) and script.endswith(".py"):
                line = frame.f_lineno
                if not _guarded(Path(script), line):
                    raise UnguardedBatch(script, line)
            return
        frame = frame.f_back


def _guarded(script: Path, line: int) -> bool:
    """Whether ``line`` of ``script`` lies inside a top-level main guard (unreadable
    sources are given the benefit of the doubt)."""
    try:
        tree = ast.parse(script.read_text(encoding="utf-8"))
    except (OSError, SyntaxError, ValueError):
        return True
    for node in tree.body:
        if isinstance(node, ast.If) and _is_main_test(node.test):
            end = node.end_lineno or node.lineno
            if node.lineno <= line <= end:
                return True
    return False


def _is_main_test(test: ast.expr) -> bool:
    """Whether ``test`` is ``__name__ == "__main__"`` (either way round)."""
    if not (isinstance(test, ast.Compare) and len(test.ops) == 1):
        return False
    if not isinstance(test.ops[0], ast.Eq):
        return False
    sides = [test.left, test.comparators[0]]
    names = [s for s in sides if isinstance(s, ast.Name) and s.id == "__name__"]
    texts = [s for s in sides if isinstance(s, ast.Constant) and s.value == "__main__"]
    return bool(names and texts)
