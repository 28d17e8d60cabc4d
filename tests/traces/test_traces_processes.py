"""Runs that die half-way stay readable; several processes append to one database."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

from robocram.execution import TaskStatus
from robocram.traces import TraceDatabase, runs, task_tree

KILLED_AT_DETECTING = """
    import os, signal, sys
    from robocram.execution import TaskListener, listening
    from robocram.plans import pick_up
    from robocram.projection import simulated_robot
    from robocram.traces import trace_to
    from robocram.scenes import tabletop_scene

    class KillAtDetecting(TaskListener):
        def task_started(self, task):
            if task.name == "perform detecting":
                os.kill(os.getpid(), signal.SIGKILL)

    scene = tabletop_scene("pr2")
    with trace_to(sys.argv[1], world=scene.world), listening(KillAtDetecting()):
        with simulated_robot(scene.world, "pr2", name="pick-mug"):
            pick_up(scene.look_target)
"""

APPEND_RUNS = """
    import sys
    from robocram.execution import par, run_top_level
    from robocram.traces import trace_to

    with trace_to(sys.argv[1]):
        for i in range(int(sys.argv[2])):
            run_top_level(lambda: par(("a", lambda: 1), ("b", lambda: 2), ("c", lambda: 3)),
                          name=f"{sys.argv[3]}-{i}")
"""


def _python(script: str, *args: str) -> subprocess.Popen[bytes]:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    code = textwrap.dedent(script)
    return subprocess.Popen([sys.executable, "-c", code, *args], env=env)


def test_run_killed_half_way_keeps_every_finished_task(tmp_path: Path) -> None:
    db_path = tmp_path / "killed.db"
    process = _python(KILLED_AT_DETECTING, str(db_path))
    assert process.wait(timeout=300) == -signal.SIGKILL
    with TraceDatabase(db_path, create=False) as db:
        (run,) = runs(db)
        tree = task_tree(db, run.id)
    assert run.status == "running" and run.end is None
    done = [t for t in tree.children if t.status is TaskStatus.SUCCEEDED]
    assert [t.name for t in done] == [
        "perform moving-arm-joints",
        "perform moving-arm-joints#2",
        "perform looking",
        "perform moving-torso",
        "perform looking#2",
    ]
    assert all(t.end_time is not None and t.result is not None for t in done)
    assert [t.name for t in tree.children if t.status is TaskStatus.RUNNING] == [
        "perform detecting"
    ]
    assert run.world_states == 1 + len(done)


def test_processes_append_runs_to_one_database(tmp_path: Path) -> None:
    db_path = tmp_path / "batch.db"
    per_process = 12
    processes = [_python(APPEND_RUNS, str(db_path), str(per_process), f"p{i}") for i in range(3)]
    assert [p.wait(timeout=300) for p in processes] == [0, 0, 0]
    with TraceDatabase(db_path, create=False) as db:
        stored = runs(db)
        trees = [task_tree(db, r.id) for r in stored]
    assert len(stored) == 3 * per_process
    assert sorted(r.name for r in stored) == sorted(
        f"p{i}-{k}" for i in range(3) for k in range(per_process)
    )
    for tree in trees:
        assert [t.name for t in tree.children[0].children] == ["a", "b", "c"]
        assert [t.result for t in tree.children[0].children] == ["1", "2", "3"]
        assert all(t.status is TaskStatus.SUCCEEDED for t in tree.walk())
