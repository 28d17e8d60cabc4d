"""Top levels (decorate, run, a block), sub tasks, and the task tree's text and JSON."""

from __future__ import annotations

import importlib
import json
import sys
import threading
from collections.abc import Callable
from pathlib import Path

import pytest

from robocram.execution import (
    NotInTopLevel,
    TaskStatus,
    TopLevel,
    checkpoint,
    current_task,
    par,
    run_top_level,
    seq,
    sleep,
    sub_task,
    tag,
    top_level,
)
from robocram.execution.failures import TorsoGoalNotReached


def test_function_form_returns_the_value_and_binds_the_root() -> None:
    assert run_top_level(lambda a, b: a + b, 2, 3) == 5
    assert run_top_level(lambda: current_task().path, name="demo") == "demo"  # type: ignore[union-attr]
    assert current_task() is None


def test_decorator_form_keeps_the_last_tree() -> None:
    runner = top_level(name="plan")

    @runner
    def plan(x: int) -> int:
        return seq(lambda: x, lambda: x * 2)  # type: ignore[no-any-return]

    assert plan(21) == 42
    assert runner.tree.find("plan/seq").result == 42
    assert runner.task.status is TaskStatus.SUCCEEDED


def test_with_form_records_failure_and_re_raises() -> None:
    failure = TorsoGoalNotReached(goal=0.5, limits=(0.0, 0.33), reached=0.33)
    with pytest.raises(TorsoGoalNotReached), top_level(name="plan") as tl:
        seq(lambda: 1, ("lift", lambda: (_ for _ in ()).throw(failure)))
    assert tl.task.status is TaskStatus.FAILED
    assert tl.task.failure is failure
    assert tl.tree.find("plan/seq/lift").failure is failure
    assert current_task() is None


def test_a_top_level_run_keeps_value_and_tree() -> None:
    tl = TopLevel("both")
    value, tree = tl.run(lambda: par(lambda: 1, lambda: 2)), tl.tree
    assert value == [1, 2]
    assert [t.path for t in tree.tasks()] == [
        "both",
        "both/par",
        "both/par/par[0]",
        "both/par/par[1]",
    ]


def test_nested_top_level_becomes_a_child_task() -> None:
    def outer() -> int:
        return run_top_level(lambda: 7, name="inner") + 1

    tl = TopLevel("outer")
    value, tree = tl.run(outer), tl.tree
    assert value == 8
    assert tree.find("outer/inner").result == 7


def test_sub_task_records_result_failure_and_times() -> None:
    with top_level(name="plan") as tl:
        with sub_task("perform looking") as task:
            sleep(0.01)
            task.result = "looked"
        with pytest.raises(ValueError), sub_task("perform going"):
            raise ValueError("bad target")
    looking = tl.tree.find("plan/perform looking")
    assert (looking.status, looking.result) == (TaskStatus.SUCCEEDED, "looked")
    assert looking.duration is not None and looking.duration >= 0.009
    going = tl.tree.find("plan/perform going")
    assert going.status is TaskStatus.FAILED and isinstance(going.failure, ValueError)


def test_sub_task_and_checkpoint_outside_a_top_level() -> None:
    with pytest.raises(NotInTopLevel, match="sub_task"), sub_task("perform"):
        pass
    checkpoint()  # nothing to stop: a no-op


def test_duplicate_sibling_names_get_numbered_paths() -> None:
    tl = TopLevel("p")
    tl.run(lambda: seq(("move", lambda: 1), ("move", lambda: 2)))
    tree = tl.tree
    assert [c.path for c in tree.find("p/seq").children] == ["p/seq/move", "p/seq/move#2"]


def test_render_shows_statuses_durations_values_and_failures() -> None:
    failure = TorsoGoalNotReached(goal=0.5, reached=0.3)
    runner = TopLevel("plan")
    with pytest.raises(TorsoGoalNotReached):
        runner.run(
            lambda: par(
                ("ok", lambda: 42),
                ("lift", lambda: (sleep(0.01), (_ for _ in ()).throw(failure))),
                ("wait", lambda: sleep(5.0)),
            )
        )
    lines = runner.tree.render(verbose=True).splitlines()
    assert lines[0].startswith("✗ plan failed ")
    assert lines[1].startswith("└── ✗ par failed")
    assert lines[2].startswith("    ├── ✓ ok succeeded") and lines[2].endswith("→ 42")
    assert lines[3].startswith("    ├── ✗ lift failed")
    assert lines[3].endswith(": TorsoGoalNotReached: " + str(failure))
    assert lines[0].endswith(" ms: TorsoGoalNotReached from par/lift")
    assert lines[4].startswith("    └── ○ wait evaporated")
    assert " ms" in lines[0]


def test_to_json_round_trips_through_json() -> None:
    tl = TopLevel("plan")
    tl.run(lambda: seq(tag("nav", lambda: "there")))
    tree = tl.tree
    data = json.loads(json.dumps(tree.to_json()))
    assert data["name"] == "plan" and data["status"] == "succeeded"
    nav = data["children"][0]["children"][0]["children"][0]
    assert nav == {
        "name": "nav",
        "path": "plan/seq/tag_nav/nav",
        "status": "succeeded",
        "start": pytest.approx(nav["start"]),
        "end": pytest.approx(nav["end"]),
        "duration": pytest.approx(nav["end"] - nav["start"]),
        "result": "'there'",
        "failure": None,
        "tags": ["nav"],
        "children": [],
    }
    assert tree.find_tag("nav")[0].result == "there"


def test_no_thread_outlives_a_top_level() -> None:
    before = threading.active_count()

    def plan() -> None:
        par(*[lambda: sleep(0.2) for _ in range(20)], lambda: (sleep(0.01), 1 / 0))

    with pytest.raises(ZeroDivisionError):
        run_top_level(plan)
    assert threading.active_count() == before


def test_a_bare_top_level_decorator_makes_each_call_a_top_level_run() -> None:
    calls: list[int] = []

    @top_level
    def plan(x: int) -> int:
        calls.append(x)
        return current_task().path  # type: ignore[union-attr,return-value]

    assert calls == []  # decorating did not run the plan
    assert plan(3) == "plan" and plan(4) == "plan"  # type: ignore[operator]
    assert calls == [3, 4]


def test_a_call_that_could_decorate_or_run_is_a_type_error_naming_both() -> None:
    def plan() -> int:
        return 5

    for call in (lambda: top_level(plan), lambda: top_level(lambda: 6), lambda: top_level(plan, 1)):
        with pytest.raises(TypeError, match=r"@top_level.*run_top_level\(plan, \*args\)"):
            call()
    assert run_top_level(plan) == 5


def test_top_level_from_another_file_on_the_plan_def_line_does_not_decorate(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The old rule took a call from the line of ``plan``'s ``def`` for a decorator."""
    (tmp_path / "tl_regression_plans.py").write_text(
        '"""Plans."""\n\n\ndef plan(x=1):\n    return 40 + x\n', encoding="utf-8"
    )
    (tmp_path / "tl_regression_caller.py").write_text(
        "from robocram.execution import run_top_level, top_level\n"
        "import tl_regression_plans as plans\n"
        "\n"
        "def wrap(): return top_level(plans.plan)\n"  # line 4, as plan's def
        "def run(): return run_top_level(plans.plan, 2)\n",
        encoding="utf-8",
    )
    monkeypatch.syspath_prepend(str(tmp_path))
    caller = importlib.import_module("tl_regression_caller")
    plans = importlib.import_module("tl_regression_plans")
    assert plans.plan.__code__.co_firstlineno == 4
    with pytest.raises(TypeError, match="top_level\\(plan\\) could decorate or run"):
        caller.wrap()
    assert caller.run() == 42
    for name in ("tl_regression_caller", "tl_regression_plans"):
        monkeypatch.delitem(sys.modules, name)


def test_a_method_and_a_nested_plan_decorate_too() -> None:
    class Robot:
        @top_level
        def plan(self) -> str:
            return current_task().path  # type: ignore[union-attr,return-value]

    def make() -> Callable[[], str]:
        @top_level(name="made")
        def plan() -> str:
            return current_task().path  # type: ignore[union-attr,return-value]

        return plan

    assert Robot().plan() == "plan"
    assert make()() == "made"
