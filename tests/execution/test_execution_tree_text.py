"""Task trees read at a glance: recovered tries fold into one line with a count (issue 27/5).

Before: a successful kitchen demo printed 12-15 failed ``going`` tries, each a 570-character
line that dumped the target pose and the process module's command.
"""

from __future__ import annotations

from collections.abc import Callable

import pytest

from robocram.execution import TaskTree, TopLevel, seq, try_in_order
from robocram.execution.failures import NavigationPoseUnreachable, TorsoGoalNotReached
from robocram.execution.failures.failure_line import LINE_WIDTH, failure_line

TARGET = "Pose(position=(-0.6898247307262457, -0.9550718645102443, 0.0), " * 6  # a long dump


def _blocked(x: float) -> Callable[[], object]:
    def go() -> object:
        raise NavigationPoseUnreachable(
            f"pr2 at ({x:.3f}, -0.955, -1.034) would collide with ['kitchen/table_top']",
            target=TARGET,
            colliding=["kitchen/table_top"],
        )

    return go


def _tree() -> TaskTree:
    runner = TopLevel("plan")
    runner.run(
        lambda: try_in_order(
            ("going", _blocked(-0.690)),
            ("going", _blocked(-1.028)),
            ("detecting", lambda: (_ for _ in ()).throw(TorsoGoalNotReached(goal=0.5))),
            ("going", _blocked(-0.294)),
            ("going", lambda: "there"),
            name="delivering",
        )
    )
    return runner.tree


def test_recovered_tries_of_one_kind_fold_into_one_line_with_a_count() -> None:
    lines = _tree().render().splitlines()
    assert lines[2] == (
        "    ├── ✗ going ×3: NavigationPoseUnreachable: pr2 at (…) would collide with "
        "['kitchen/table_top']"
    )
    assert lines[3].startswith("    ├── ✗ detecting failed ")
    assert lines[3].endswith(" ms: TorsoGoalNotReached: the torso did not reach its goal")
    assert lines[4].startswith("    └── ✓ going#4 succeeded ") and lines[4].endswith("'there'")
    assert len(lines) == 5
    assert max(len(line) for line in lines) <= LINE_WIDTH + 30  # the branch and the timing


def test_verbose_shows_every_task_with_its_full_failure_text() -> None:
    text = _tree().render(verbose=True)
    lines = text.splitlines()
    assert len(lines) == 7
    assert [line.split()[2] for line in lines[2:]] == [
        "going",
        "going#2",
        "detecting",
        "going#3",
        "going#4",
    ]
    assert text.count(TARGET) == 3  # each try's data, as traces keep it
    assert "[process_module" not in text  # nothing is added either


def test_a_failure_that_ended_the_plan_keeps_its_subtree() -> None:
    runner = TopLevel("plan")
    with pytest.raises(NavigationPoseUnreachable):
        runner.run(lambda: seq(("fetching", lambda: seq(("going", _blocked(0.5))))))
    lines = runner.tree.render().splitlines()
    assert [line.split("── ")[-1].split()[:2] for line in lines[1:]] == [
        ["✗", "seq"],
        ["✗", "fetching"],
        ["✗", "seq"],
        ["✗", "going"],
    ]
    assert lines[-1].endswith(
        "NavigationPoseUnreachable: pr2 at (…) would collide with ['kitchen/table_top']"
    )


def test_a_failure_line_is_type_and_cause_within_the_width() -> None:
    failure = NavigationPoseUnreachable("x " * 200, target=TARGET)
    line = failure_line(type(failure).__name__, str(failure))
    assert len(line) <= LINE_WIDTH and line.endswith("x x…")
    assert line.startswith("NavigationPoseUnreachable: x x")
    assert failure_line("FetchExhausted", "") == "FetchExhausted"
    assert failure_line("E", "first line\nsecond") == "E: first line"
