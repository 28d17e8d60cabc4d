"""Top levels in their three forms, sub tasks, and the task tree's text and JSON."""

from __future__ import annotations

import json
import threading

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
    assert top_level(lambda a, b: a + b, 2, 3) == 5
    assert top_level(lambda: current_task().path, name="demo") == "demo"  # type: ignore[union-attr]
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


def test_run_top_level_returns_value_and_tree() -> None:
    value, tree = run_top_level(lambda: par(lambda: 1, lambda: 2), name="both")
    assert value == [1, 2]
    assert [t.path for t in tree.tasks()] == [
        "both",
        "both/par",
        "both/par/par[0]",
        "both/par/par[1]",
    ]


def test_nested_top_level_becomes_a_child_task() -> None:
    def outer() -> int:
        return top_level(lambda: 7, name="inner") + 1

    value, tree = run_top_level(outer, name="outer")
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
    _, tree = run_top_level(lambda: seq(("move", lambda: 1), ("move", lambda: 2)), name="p")
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
    lines = runner.tree.render().splitlines()
    assert lines[0].startswith("✗ plan failed ")
    assert lines[1].startswith("└── ✗ par failed")
    assert lines[2].startswith("    ├── ✓ ok succeeded") and lines[2].endswith("→ 42")
    assert lines[3].startswith("    ├── ✗ lift failed")
    assert lines[3].endswith(": TorsoGoalNotReached: " + str(failure))
    assert lines[0].endswith(" ms: TorsoGoalNotReached from par/lift")
    assert lines[4].startswith("    └── ○ wait evaporated")
    assert " ms" in lines[0]


def test_to_json_round_trips_through_json() -> None:
    _, tree = run_top_level(lambda: seq(tag("nav", lambda: "there")), name="plan")
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
        top_level(plan)
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


def test_top_level_of_an_existing_function_still_runs_it_at_once() -> None:
    def plan() -> int:
        return 5

    assert top_level(plan) == 5
    one_liner = top_level(lambda: 6)
    assert one_liner == 6
