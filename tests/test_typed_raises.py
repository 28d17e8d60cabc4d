"""Library code raises its own typed errors, never a bare built-in (issue 39, item 5).

Each package's errors carry a ``summary`` and a ``hint`` and still derive from the built-in
they replaced, so a caller's ``except ValueError`` keeps working. Read with Python's own
parser, independent of tools/house_measures.py.
"""

from __future__ import annotations

import ast
import importlib
import inspect
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "robocram"
BARE = {"ValueError", "TypeError", "KeyError", "RuntimeError", "Exception"}


def _bare_raises() -> list[str]:
    found = []
    for path in sorted(SRC.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call):
                name = node.exc.func
                if isinstance(name, ast.Name) and name.id in BARE:
                    found.append(f"{path.relative_to(SRC)}:{node.lineno} {name.id}")
    return found


def test_no_bare_built_in_raises() -> None:
    assert _bare_raises() == []


USAGE_ERRORS = [
    ("robocram.execution.errors", "ExecutionUsageError", TypeError),
    ("robocram.designators.errors", "DesignatorUnknownKey", KeyError),
    ("robocram.logic.usage_errors", "LogicArgumentError", ValueError),
    ("robocram.traces.errors", "TraceStateError", RuntimeError),
    ("robocram.world.errors", "WorldValueError", ValueError),
    ("robocram.turtlesim.errors", "TurtleArgumentError", ValueError),
]


@pytest.mark.parametrize(("module", "name", "builtin"), USAGE_ERRORS)
def test_typed_errors_keep_their_built_in(module: str, name: str, builtin: type) -> None:
    cls = getattr(importlib.import_module(module), name)
    assert issubclass(cls, builtin)
    assert cls.summary and cls.hint and inspect.getdoc(cls)


def test_a_bad_limit_names_itself_and_stays_a_value_error() -> None:
    from robocram.logic import KnowledgeBase, LogicArgumentError

    kb = KnowledgeBase()
    with pytest.raises(LogicArgumentError, match="max_inferences must be >= 0, got -1"):
        kb.query("true", max_inferences=-1)
    with pytest.raises(ValueError, match="time_limit"):
        kb.query("true", time_limit=float("nan"))
