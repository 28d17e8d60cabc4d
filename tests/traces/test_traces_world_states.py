"""World states at motion boundaries restore the world exactly (1e-9)."""

from __future__ import annotations

from typing import Any

import numpy as np

from robocram.traces import (
    StoredWorldState,
    TraceDatabase,
    build_scene,
    require_run,
    world_state_at,
    world_state_times,
)

TOL = 1e-9  # [m], [rad] and quaternion components


def assert_same_state(a: StoredWorldState, b: StoredWorldState) -> None:
    assert set(a.poses) == set(b.poses)
    for name, pose in a.poses.items():
        other = b.poses[name]
        assert np.allclose(pose.position, other.position, atol=TOL, rtol=0), name
        assert np.allclose(pose.orientation, other.orientation, atol=TOL, rtol=0), name
    assert a.joints.keys() == b.joints.keys()
    for name, joints in a.joints.items():
        assert joints.keys() == b.joints[name].keys()
        diff = max(abs(v - b.joints[name][j]) for j, v in joints.items())
        assert diff <= TOL, name
    assert {(x.obj, x.robot, x.link) for x in a.attachments} == {
        (x.obj, x.robot, x.link) for x in b.attachments
    }


def test_one_state_per_motion_and_the_start(pick_up_trace: Any) -> None:
    motions = [t for t in pick_up_trace.tree.walk() if t.name.startswith("perform ")]
    with TraceDatabase(pick_up_trace.db_path, create=False) as db:
        times = world_state_times(db, pick_up_trace.run)
    assert len(times) == 1 + len(motions)
    assert [p for _, _, p in times[1:]] == sorted(
        (m.path for m in motions), key=lambda p: next(m.end_time for m in motions if m.path == p)
    )


def test_last_state_rebuilds_the_final_world_in_a_new_client(pick_up_trace: Any) -> None:
    with TraceDatabase(pick_up_trace.db_path, create=False) as db:
        run = require_run(db, pick_up_trace.run)
        stored = world_state_at(db, pick_up_trace.run, float("inf"))
    assert run.scene is not None
    with build_scene(run.scene) as world:
        stored.apply(world)
        assert_same_state(StoredWorldState.capture(world, 0.0), pick_up_trace.final)
        assert world.attached_to("mug-1") is not None  # the lifted mug hangs from the hand


def test_mid_run_state_restores_the_live_world(pick_up_trace: Any) -> None:
    world = pick_up_trace.world
    with TraceDatabase(pick_up_trace.db_path, create=False) as db:
        times = world_state_times(db, pick_up_trace.run)
        (state_id, time, path) = next(t for t in times if t[2] and "opening" in t[2])
        stored = world_state_at(db, pick_up_trace.run, time)
        first = world_state_at(db, pick_up_trace.run, times[0][1])
    stored.apply(world)
    assert_same_state(StoredWorldState.capture(world, 0.0), stored)
    assert world.attached_to("mug-1") is None  # the gripper opened, the mug is on the table
    torso = "torso_lift_joint"
    assert stored.joints["pr2"][torso] > first.joints["pr2"][torso] + 0.1  # torso was raised
    pick_up_trace.final.apply(world)  # leave the shared world as the run left it
