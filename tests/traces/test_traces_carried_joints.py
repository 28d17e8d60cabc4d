"""A trajectory's carried joints (a drawer the hand pulls) are stored, read back and
replayed: a projected trajectory reports the joints its robot moves along."""

from __future__ import annotations

import sqlite3
from dataclasses import replace
from pathlib import Path

import pytest

from robocram.execution import top_level
from robocram.motion import CarriedJoint, report_executed, still, trajectory_listener
from robocram.motion.joint_trajectory import JointTrajectory
from robocram.projection import ProjectedRobot
from robocram.projection.trajectory_follower import follow
from robocram.scenes import tabletop_scene
from robocram.traces import SCHEMA_VERSION, TraceDatabase, run_ids, run_trajectories, trace_to

DRAWER = CarriedJoint("kitchen", "drawer_unit_drawer_3_joint", 0.1, 0.15)


def test_carried_joints_round_trip_and_older_files_read_none(tmp_path: Path) -> None:
    db_path = tmp_path / "runs.db"
    moved = replace(still("pr2", ["torso_lift_joint"], [0.2]), carried=(DRAWER,))
    with trace_to(db_path), top_level(name="carried"):
        report_executed(moved)
        report_executed(still("pr2", ["torso_lift_joint"], [0.2]))
    with TraceDatabase(db_path, create=False) as db:
        (run,) = run_ids(db)
        kept, plain = run_trajectories(db, run)
    assert kept.carried == (DRAWER,) and kept.trajectory() == moved
    assert plain.carried == ()
    with sqlite3.connect(db_path) as con:  # what robocram wrote before carried joints
        con.execute("ALTER TABLE trajectories DROP COLUMN carried")
        con.execute("UPDATE schema_info SET version = 6")
    with TraceDatabase(db_path, create=False) as db:
        assert [t.carried for t in run_trajectories(db, run)] == [(), ()]
    with sqlite3.connect(db_path) as con:
        assert con.execute("SELECT version FROM schema_info").fetchone() == (SCHEMA_VERSION,)


def test_a_followed_trajectory_reports_what_its_robot_carries_as_far_as_it_got() -> None:
    scene = tabletop_scene("pr2")
    robot = ProjectedRobot.of(scene.world, "pr2")
    heard: list[JointTrajectory] = []
    lift = still("pr2", ["torso_lift_joint"], [0.0])
    with trajectory_listener(heard.append):
        robot.carried[:] = [DRAWER]
        follow(robot, lift)
        robot.carried.clear()
        follow(robot, lift)
    scene.world.close()
    assert heard[0].carried == (DRAWER,) and heard[1].carried == ()


def test_a_carried_joint_is_finite_and_moves_in_proportion() -> None:
    assert DRAWER.at(0.5) == pytest.approx(0.125) and DRAWER.at(2.0) == DRAWER.end
    with pytest.raises(ValueError, match="finite"):
        CarriedJoint("kitchen", "j", 0.0, float("nan"))


ALONG = CarriedJoint(
    "kitchen", "fridge_door_joint", 1.2, 1.0, "l_gripper_tool_frame",
    ((1.0, 0.0, 1.0), (1.0, 0.2, 1.0)),
)  # fmt: skip


def test_a_joint_moved_along_a_line_goes_where_the_holding_link_is(tmp_path: Path) -> None:
    assert ALONG.share((1.0, 0.05, 1.0)) == pytest.approx(0.25)
    assert ALONG.share((1.3, 0.05, 0.7)) == pytest.approx(0.25)  # off the line: its foot
    assert ALONG.share((1.0, -0.3, 1.0)) == 0.0 and ALONG.share((1.0, 0.9, 1.0)) == 1.0
    assert ALONG.at(ALONG.share((1.0, 0.1, 1.0))) == pytest.approx(1.1)
    db_path = tmp_path / "runs.db"
    moved = replace(still("pr2", ["torso_lift_joint"], [0.2]), carried=(ALONG, DRAWER))
    with trace_to(db_path), top_level(name="along"):
        report_executed(moved)
    with TraceDatabase(db_path, create=False) as db:
        (stored,) = run_trajectories(db, run_ids(db)[0])
    assert stored.carried == (ALONG, DRAWER)  # the line kept, and a joint by time beside it
