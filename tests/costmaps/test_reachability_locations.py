"""``reachable_for``: poses from which the PR2, the HSR and Boxy reach a grasp of the mug."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from robocram.costmaps import CostmapLocations, ReachabilityMaps, build_reachability_map
from robocram.costmaps.batch_fk import batch_frame_poses
from robocram.costmaps.validators import reach_object
from robocram.designators import a
from robocram.kinematics import forward_kinematics
from robocram.kinematics.robot_kinematics import robot_kinematics
from robocram.robots import load_description
from robocram.scenes import tabletop_scene


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy"])
def test_first_five_poses_reach_a_grasp_of_the_mug(robot: str) -> None:
    scene = tabletop_scene(robot)
    world = scene.world
    body = world.robot(scene.robot)
    mug = world.object("mug-1")
    locs = CostmapLocations(world, seed=0)
    poses = list(itertools.islice(locs.poses(a.location(reachable_for=robot, object="mug-1")), 5))
    assert len({p.position for p in poses}) == 5
    desc = body.description
    for pose in poses:
        reach = reach_object(world, body, mug, pose)
        assert reach is not None, pose
        tool = forward_kinematics(desc, reach.joint_positions, desc.arms[reach.arm].tool_frame)
        moved = pose if reach.base_motion is None else pose * reach.base_motion.pose()
        reached_in_map = moved * tool  # an arm that reaches with the base adjusts it first
        grasp_in_map = pose * reach.tool_in_base
        assert reached_in_map.distance_to(grasp_in_map) < 0.01
        low, high = world.aabb(mug)
        x, y, _ = reached_in_map.position
        assert low[0] <= x <= high[0] and low[1] <= y <= high[1]  # over the mug
        with world.snapshots.stored_state():
            world.set_pose(body, pose)
            for name, arm in desc.arms.items():  # it arrives with its arms parked
                if name != desc.neck_arm:
                    world.set_joint_states(body, dict(arm.parking))
            assert not world.contacts.in_collision(body)
    world.close()


def test_arm_key_limits_the_arm() -> None:
    scene = tabletop_scene("pr2")
    locs = CostmapLocations(scene.world, seed=0)
    designator = a.location(reachable_for="pr2", object="mug-1", arm="right")
    body = scene.world.robot("pr2")
    for pose in itertools.islice(locs.poses(designator), 2):
        reach = reach_object(scene.world, body, scene.world.object("mug-1"), pose, "right")
        assert reach is not None and reach.arm == "right"
    scene.world.close()


def test_batch_fk_matches_pinocchio() -> None:
    desc = load_description("pr2")
    kin = robot_kinematics(desc.model)
    rng = np.random.default_rng(3)
    joints = ["torso_lift_joint", *desc.arms["left"].joints]
    values = {}
    for name in joints:
        info = kin.joint(name)
        low, high = (-math.pi, math.pi) if info.continuous else (info.lower, info.upper)
        values[name] = rng.uniform(low, high, 4)
    rotations, positions = batch_frame_poses(kin, "l_gripper_tool_frame", values)
    for i in range(4):
        fk = forward_kinematics(desc, {n: float(v[i]) for n, v in values.items()},
                                "l_gripper_tool_frame").matrix()  # fmt: skip
        assert np.allclose(fk[:3, 3], positions[i], atol=1e-9)
        assert np.allclose(fk[:3, :3], rotations[i], atol=1e-9)


def test_reachability_maps_are_cached_on_disk(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path))
    desc = load_description("hsrb")
    first = ReachabilityMaps(samples=20_000)
    built = first.get(desc, "arm")
    assert first.build_seconds > 0
    assert list(tmp_path.glob("reachability/*.arrays"))
    second = ReachabilityMaps(samples=20_000)
    loaded = second.get(desc, "arm")
    assert second.build_seconds == 0  # read from disk, not built
    assert np.array_equal(built.scores, loaded.scores)
    fresh = build_reachability_map(desc, "arm", samples=20_000)
    assert np.array_equal(fresh.scores, built.scores)  # seeded: the same map every time


def test_a_new_resolver_reads_no_file_for_a_map_already_read(tmp_path, monkeypatch) -> None:
    """Each batch variant makes a new resolver; the maps stay with the robot model."""
    monkeypatch.setenv("ROBOCRAM_CACHE_DIR", str(tmp_path))
    desc = load_description("hsrb")
    built = ReachabilityMaps(samples=20_000).get(desc, "arm")
    for path in tmp_path.glob("reachability/*.arrays"):
        path.unlink()  # a read would now have to build again
    again = ReachabilityMaps(samples=20_000)
    assert again.get(desc, "arm") is built and again.build_seconds == 0
    assert not list(tmp_path.glob("reachability/*.arrays"))
