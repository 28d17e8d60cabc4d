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
