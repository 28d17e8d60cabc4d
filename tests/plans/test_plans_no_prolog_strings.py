"""Plans ask the knowledge base through the predicate table's typed queries, never in Prolog.

Every string literal of a plan module that reads as a Prolog goal (``name(..., Var, ...)``
or a rule ``:-``), and every ``query``/``first``/``holds`` call on a string, is refused,
except in the modules listed in :data:`EXCEPTIONS` with the reason.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

PLANS = Path(__file__).resolve().parents[2] / "src" / "robocram" / "plans"

# module -> why it may hold Prolog text
EXCEPTIONS: dict[str, str] = {
    "action_table.py": "writes the action_grounding/2 rule for users' reasoning, from the table",
}

GOAL = re.compile(r"\b[a-z]\w*\([^()]*\b(?:[A-Z]\w*|_)\b[^()]*\)|:-")
ASKING = {"query", "first", "holds", "consult"}


def _docstrings(tree: ast.Module) -> set[int]:
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                found.add(id(body[0].value))
    return found


def prolog_in(source: str) -> list[str]:
    """The Prolog-looking literals and string queries of a module's source."""
    tree = ast.parse(source)
    docs = _docstrings(tree)
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docs:
            if GOAL.search(node.value):
                found.append(node.value)
        elif (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr in ASKING
            and node.args
            and isinstance(node.args[0], ast.Constant | ast.JoinedStr)
        ):
            found.append(ast.unparse(node))
    return found


@pytest.mark.parametrize("path", sorted(PLANS.glob("*.py")), ids=lambda p: p.name)
def test_plan_modules_hold_no_prolog(path: Path) -> None:
    if path.name in EXCEPTIONS:
        return
    assert prolog_in(path.read_text(encoding="utf-8")) == []


def test_the_check_sees_a_query_and_a_goal_literal() -> None:
    source = (
        'Q = "arm(R, A), robot_arms_parking_joint_states(R, A, S)"\n'
        'kb.first(f"{limit}(R, J, V)")\n'
        'message = "run it inside simulated_robot(world, robot)"\n'
    )
    assert prolog_in(source) == [
        "arm(R, A), robot_arms_parking_joint_states(R, A, S)",
        "kb.first(f'{limit}(R, J, V)')",
    ]


def test_each_exception_exists() -> None:
    assert all((PLANS / name).exists() for name in EXCEPTIONS)
