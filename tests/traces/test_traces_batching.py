"""When the tracer writes: one transaction per motion boundary and one at the run's end."""

from __future__ import annotations

from pathlib import Path

import pytest
from sqlalchemy import select

from robocram.designators import a
from robocram.execution import Task, TaskListener, TaskStatus, listening, par, perform
from robocram.execution import run_top_level as run_top
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from robocram.tf import PoseStamped
from robocram.traces import TraceDatabase, task_tree, trace_to
from robocram.traces.schema import TASKS_PER_RUN, TaskRow, task_key


class Watcher(TaskListener):
    """At every task start, reads which tasks the database holds as ended, by path."""

    def __init__(self, db_path: Path) -> None:
        self.db_path = db_path
        self.seen: list[tuple[str, set[str]]] = []

    def task_started(self, task: Task) -> None:
        with TraceDatabase(self.db_path, create=False) as db, db.read() as session:
            ended = session.scalars(select(TaskRow.path).where(TaskRow.end.is_not(None)))
            self.seen.append((task.path, set(ended)))


def test_every_task_ended_before_a_motion_boundary_is_readable_at_the_next_start(
    tmp_path: Path,
) -> None:
    db_path = tmp_path / "boundaries.db"
    scene = tabletop_scene("pr2")
    watcher = Watcher(db_path)
    goal = PoseStamped("base_footprint", (0.05, 0.0, 0.0))
    with (
        trace_to(db_path, world=scene.world) as tracer,
        listening(watcher),
        simulated_robot(scene.world, "pr2", name="three-motions"),
    ):
        perform(a.motion(type="moving-torso", joint_angle=0.1))
        perform(a.motion(type="going", target=goal))
        perform(a.motion(type="moving-torso", joint_angle=0.2))
    scene.world.close()
    torso, going = "three-motions/perform moving-torso", "three-motions/perform going"
    assert dict(watcher.seen)[going] == {torso}
    assert dict(watcher.seen)[f"{torso}#2"] == {torso, going}
    with TraceDatabase(db_path, create=False) as db:
        tree = task_tree(db, tracer.runs[0])
    assert [t.status for t in tree.walk()] == [TaskStatus.SUCCEEDED] * 4


def test_a_run_without_motions_is_written_once_at_its_end(tmp_path: Path) -> None:
    db_path = tmp_path / "plain.db"
    watcher = Watcher(db_path)
    with trace_to(db_path) as tracer, listening(watcher):
        run_top(lambda: par(("a", lambda: 1), ("b", lambda: 2)), name="plain")
        with TraceDatabase(db_path, create=False) as db:
            tree = task_tree(db, tracer.runs[0])
    assert all(ended == set() for _, ended in watcher.seen)  # nothing before the end
    assert [t.name for t in tree.walk()] == ["plain", "par", "a", "b"]
    run = tracer.runs[0]
    with TraceDatabase(db_path, create=False) as db, db.read() as session:
        ids = list(session.scalars(select(TaskRow.id).order_by(TaskRow.id)))
    assert ids == [task_key(run, order) for order in range(4)]  # start order within the run


def test_task_keys_leave_room_for_every_task_of_a_run() -> None:
    assert task_key(3, 0) == 3 * TASKS_PER_RUN
    assert task_key(3, 5) + 1 == task_key(3, 6)
    with pytest.raises(ValueError, match="at most"):
        task_key(3, TASKS_PER_RUN)
