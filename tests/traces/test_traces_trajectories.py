"""Executed trajectories in the trace: stored exactly, in order, with their task and time."""

from __future__ import annotations

import sqlite3
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from robocram.execution import top_level
from robocram.motion import ContactAllowance, report_executed, still
from robocram.scenes import tabletop_scene
from robocram.traces import (
    SCHEMA_VERSION,
    ReplayClock,
    TraceDatabase,
    TraceError,
    UnknownRun,
    build_scene,
    replay_frames,
    require_run,
    run_ids,
    run_trajectories,
    trace_to,
    world_state_at,
    world_state_times,
)

TOL = 1e-9
CLOCK_TOL = 1e-6  # [s] replay starts come from wall-clock stamps (~2e-7 s apart in 2026)


def _by_task(trajectories: list[Any], suffix: str) -> Any:
    (found,) = [t for t in trajectories if (t.task_path or "").endswith(suffix)]
    return found


def test_trajectories_round_trip_exactly_in_order(trajectory_run: Any) -> None:
    stored = run_trajectories(trajectory_run.db_path, trajectory_run.run)  # a path works too
    arm = _by_task(stored, "/move-arm")
    base = _by_task(stored, "/move-base")
    assert [t.index for t in stored] == list(range(len(stored)))
    assert arm.index < base.index
    for kept, made in ((arm, trajectory_run.arm), (base, trajectory_run.base)):
        assert kept.trajectory() == made  # names, kind, robot and every point, bit for bit
        assert kept.robot == "pr2" and kept.joint_names == made.joint_names
        assert kept.points[3].velocities == made.points[3].velocities
        assert kept.duration == pytest.approx(made.duration, abs=TOL)
    assert (arm.kind, base.kind) == ("arm", "base")
    assert base.joint_names == ("x", "y", "yaw")


def test_trajectories_sit_between_the_states_of_their_motions(trajectory_run: Any) -> None:
    with TraceDatabase(trajectory_run.db_path, create=False) as db:
        stored = run_trajectories(db, trajectory_run.run)
        states = world_state_times(db, trajectory_run.run)
        run_start = require_run(db, trajectory_run.run).start
    arm, base = _by_task(stored, "/move-arm"), _by_task(stored, "/move-base")
    (torso,) = [t for t in stored if t.kind == "torso"]  # the torso moves along its own
    assert torso.joint_names == ("torso_lift_joint",)
    assert torso.trajectory().end["torso_lift_joint"] == pytest.approx(0.1, abs=TOL)
    torso_state = next(t for _, t, path in states if path and path.endswith("moving-torso"))
    assert states[0][1] < arm.time < torso.time <= torso_state < base.time
    # projection takes no wall time: on the replay clock each one starts when the last ended
    assert arm.start == pytest.approx(0.0, abs=0.05)
    for before, after in ((arm, torso), (torso, base)):
        assert after.start >= before.end - CLOCK_TOL
        assert after.start - before.end < 0.05
    clock = ReplayClock(
        run_start, [(t.time, t.duration) for t in stored], [t for _, t, _ in states]
    )
    assert clock.since_start(torso_state) >= torso.end - CLOCK_TOL  # its state after it
    assert clock.since_start(torso_state) <= base.start + CLOCK_TOL


def test_replay_frames_follow_the_trajectories(trajectory_run: Any) -> None:
    with TraceDatabase(trajectory_run.db_path, create=False) as db:
        run = require_run(db, trajectory_run.run)
        assert run.scene is not None
        with build_scene(run.scene) as world:
            frames = []
            for frame in replay_frames(db, trajectory_run.run, world, period=0.25):
                joints, pose = world.joint_states("pr2"), world.pose("pr2")
                frames.append((frame, joints, pose, world.pose("mug-1")))
    arm, base = trajectory_run.arm, trajectory_run.base
    arm_frames = [f for f in frames if f[0].trajectory and f[0].trajectory.kind == "arm"]
    assert [round(f[0].sample_time, 9) for f in arm_frames[:3]] == [0.0, 0.25, 0.5]
    assert arm_frames[-1][0].sample_time == pytest.approx(arm.duration, abs=TOL)
    for frame, joints, _, _ in arm_frames:
        expected = arm.at(frame.sample_time)
        got = [joints[n] for n in arm.joint_names]
        assert np.allclose(got, expected, atol=1e-6)  # pybullet keeps joints as doubles
    base_frames = [f for f in frames if f[0].trajectory and f[0].trajectory.kind == "base"]
    mug_in_base = [pose.inverse() * mug for _, _, pose, mug in base_frames]
    for (frame, _, pose, _), held in zip(base_frames, mug_in_base, strict=True):
        x, y, yaw = base.at(frame.sample_time)
        assert pose.position[:2] == pytest.approx((x, y), abs=1e-6)
        assert 2 * np.arctan2(pose.orientation[2], pose.orientation[3]) == pytest.approx(
            yaw, abs=1e-6
        )
        assert held.position == pytest.approx(mug_in_base[0].position, abs=1e-6)  # rides along
    times = [f[0].time for f in frames]
    assert times == sorted(times)
    final = frames[-1][3]
    assert final.position == pytest.approx(trajectory_run.world.pose("mug-1").position, abs=1e-6)


def test_replay_clock_stretches_only_where_motion_outlasts_the_wall_clock() -> None:
    # projection: reported 0.1 s apart, lasting 2 s and 3 s -> back to back
    clock = ReplayClock(100.0, [(100.1, 2.0), (100.2, 3.0)])
    assert clock.at(100.05) == pytest.approx(100.05, abs=TOL)  # before any: the wall time
    assert clock.at(100.15) == pytest.approx(102.05, abs=TOL)  # after the first: +1.9 s
    assert clock.at(100.3) == pytest.approx(105.1, abs=TOL)  # after both ended at 105.0
    # a state between them: the second starts at the state, not at the first one's end
    with_state = ReplayClock(100.0, [(100.1, 2.0), (100.2, 3.0)], [100.15])
    assert with_state.at(100.15) == pytest.approx(102.05, abs=TOL)
    assert with_state.at(100.3) == pytest.approx(105.15, abs=TOL)
    # a real robot: each took its duration of wall time -> no stretch
    real = ReplayClock(100.0, [(102.0, 2.0), (105.5, 3.0)])
    assert real.at(106.0) == pytest.approx(106.0, abs=TOL)


def test_a_trajectory_outside_any_traced_run_is_not_kept(tmp_path: Path) -> None:
    db_path = tmp_path / "runs.db"
    with trace_to(db_path) as tracer:
        report_executed(still("pr2", ["torso_lift_joint"], [0.1]))  # no run yet
        with top_level(name="only"):
            report_executed(still("pr2", ["torso_lift_joint"], [0.2]))
    (run,) = tracer.runs
    (kept,) = run_trajectories(db_path, run)
    assert kept.points[0].positions == (0.2,) and kept.task_path == "only"


def test_a_version_3_file_opens_and_gains_the_trajectories_table(tmp_path: Path) -> None:
    db_path = tmp_path / "old.db"
    with trace_to(db_path), top_level(name="old run"):
        pass
    with sqlite3.connect(db_path) as con:  # what robocram wrote before trajectories
        con.execute("DROP TABLE trajectories")
        con.execute("UPDATE schema_info SET version = 3")
    with TraceDatabase(db_path, create=False) as db:
        (run,) = run_ids(db)
        assert run_trajectories(db, run) == []
    with sqlite3.connect(db_path) as con:
        assert con.execute("SELECT version FROM schema_info").fetchone() == (SCHEMA_VERSION,)


def test_unknown_run_lists_the_runs(trajectory_run: Any) -> None:
    with pytest.raises(UnknownRun, match=f"runs stored: {trajectory_run.run}"):
        run_trajectories(trajectory_run.db_path, trajectory_run.run + 5)


def test_a_traced_scene_with_a_trajectory_of_an_unknown_robot_names_the_robots(
    tmp_path: Path,
) -> None:
    scene = tabletop_scene("pr2")
    db_path = tmp_path / "runs.db"
    try:
        with trace_to(db_path, world=scene.world) as tracer, top_level(name="stray"):
            report_executed(still("hsrb", ["arm_lift_joint"], [0.1]))
    finally:
        scene.world.close()
    with TraceDatabase(db_path, create=False) as db:
        run = require_run(db, tracer.runs[0])
        assert run.scene is not None
        with build_scene(run.scene) as world, pytest.raises(TraceError, match=r"robots: \['pr2'\]"):
            list(replay_frames(db, run.id, world))


def test_a_traced_pick_up_keeps_each_motions_trajectory(pick_up_trace: Any) -> None:
    with TraceDatabase(pick_up_trace.db_path, create=False) as db:
        stored = run_trajectories(db, pick_up_trace.run)
        states = {path: t for _, t, path in world_state_times(db, pick_up_trace.run)}
        after = {path: world_state_at(db, pick_up_trace.run, time) for path, time in states.items()}
    assert {"arm", "cartesian"} <= {t.kind for t in stored}
    for trajectory in stored:
        assert trajectory.task_path is not None and "/perform " in trajectory.task_path
        state = after[trajectory.task_path]  # the world when its motion ended
        last = [t for t in stored if t.task_path == trajectory.task_path][-1]
        if trajectory is not last or not trajectory.points:
            continue
        end = trajectory.trajectory().end
        if trajectory.kind == "base":
            x, y, _ = state.poses["pr2"].position
            assert (end["x"], end["y"]) == pytest.approx((x, y), abs=1e-9)
        else:
            joints = state.joints["pr2"]
            assert [joints[n] for n in end] == pytest.approx(list(end.values()), abs=1e-9)


def test_allowed_contacts_round_trip_and_old_files_read_none(tmp_path: Path) -> None:
    db_path = tmp_path / "runs.db"
    allowance = ContactAllowance("r_gripper_palm_link", "kitchen/handle", 0.004)
    moved = replace(still("pr2", ["torso_lift_joint"], [0.2]), allowed_contacts=(allowance,))
    with trace_to(db_path), top_level(name="allowed"):
        report_executed(moved)
        report_executed(still("pr2", ["torso_lift_joint"], [0.2]))
    with TraceDatabase(db_path, create=False) as db:
        (run,) = run_ids(db)
        kept, plain = run_trajectories(db, run)
    assert kept.allowed_contacts == (allowance,) and kept.trajectory() == moved
    assert plain.allowed_contacts == ()
    with sqlite3.connect(db_path) as con:  # what robocram wrote before allowed contacts
        con.execute("ALTER TABLE trajectories DROP COLUMN allowed_contacts")
        con.execute("UPDATE schema_info SET version = 5")
    with TraceDatabase(db_path, create=False) as db:
        assert [t.allowed_contacts for t in run_trajectories(db, run)] == [(), ()]
    with sqlite3.connect(db_path) as con:
        assert con.execute("SELECT version FROM schema_info").fetchone() == (SCHEMA_VERSION,)


def test_a_contact_allowance_refuses_a_negative_depth() -> None:
    with pytest.raises(ValueError, match="depth is a bound in metres"):
        ContactAllowance("r_gripper_palm_link", "kitchen", -0.001)


def test_a_contact_allowance_names_an_object_a_link_of_it_or_any_object() -> None:
    """A hand contact naming no object (``allow_hand`` with ``touching`` none) is ``*``."""
    mug = ContactAllowance("r_gripper_palm_link", "mug-1", 0.005)
    handle = ContactAllowance("r_gripper_palm_link", "kitchen/handle", 0.005)
    anything = ContactAllowance("r_gripper_palm_link", "*", 0.005)
    assert mug.covers("r_gripper_palm_link", "mug-1", "base_link")
    assert not mug.covers("r_gripper_palm_link", "kitchen", "handle")
    assert handle.covers("r_gripper_palm_link", "kitchen", "handle")
    assert not handle.covers("r_gripper_palm_link", "kitchen", "counter")
    assert anything.covers("r_gripper_palm_link", "kitchen", "counter")
    assert not anything.covers("r_forearm_link", "kitchen", "counter")  # the hand's link only
