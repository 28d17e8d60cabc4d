"""The ROS 2 driver's tf is a tree as a real robot's; our node composes it into map poses.

No ROS process: the driver's transforms (``TfFrames``) go through the CDR bytes both
sides use and into what our ROS 2 node keeps of them (``LatestTransforms``); the map
poses it composes are judged against PyBullet's own link states.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pytest

from robocram.ros.latest_transforms import LatestTransforms
from robocram.ros.tf_cdr import read_tf_message, write_tf_message
from robocram.ros_driver.tf_frames import TfFrames
from robocram.scenes import tabletop_scene
from robocram.tf import Pose, TransformError
from robocram.tf import quaternion as quat
from robocram.world import World
from tests.bullet_links import link_frame, link_indices

SAME = 1e-9  # [m | -] rounding only
BULLET = 1e-6  # [m | -] PyBullet's link states against the URDF's kinematics
STAMP = (12, 345)


@pytest.fixture
def world() -> Iterator[World]:
    scene = tabletop_scene("pr2")
    scene.world.set_pose("pr2", Pose((0.3, -0.2, 0.0), quat.from_euler(0.0, 0.0, 0.7)))
    scene.world.set_joint_states(
        "pr2", {"torso_lift_joint": 0.2, "r_elbow_flex_joint": -1.1, "head_pan_joint": 0.4}
    )
    yield scene.world
    scene.world.close()


def _heard(*messages: bytes) -> LatestTransforms:
    """What our ROS 2 node keeps of the messages, in the order they arrived."""
    latest = LatestTransforms()
    for raw in messages:
        latest.update(read_tf_message(raw))
    return latest


def test_the_tree_composes_into_pybullets_link_frames_and_the_objects_poses(
    world: World,
) -> None:
    frames = TfFrames(world)
    static = write_tf_message(STAMP, frames.static_transforms())
    moving = frames.moving_transforms()
    heard = _heard(write_tf_message(STAMP, moving), static)  # /tf_static may come late
    body, client = world.object("pr2").body_id, world.physics.client()
    links = link_indices(body, client)
    assert len(links) > 80 and len(moving) < 50  # far fewer than every frame in map
    in_map = heard.lookups("map", [*links, "base_footprint"])
    for link in links:
        position, rotation = link_frame(body, client, link)
        assert np.asarray(in_map[link].position) == pytest.approx(position, abs=BULLET)
        assert quat.to_matrix(in_map[link].orientation) == pytest.approx(rotation, abs=BULLET)
    assert in_map["base_footprint"].distance_to(world.pose("pr2")) < SAME
    objects = [obj for obj in world.objects() if obj.name != "pr2"]  # a robot is its links
    in_map = heard.lookups("map", [obj.name for obj in objects])
    for obj in objects:
        assert in_map[obj.name].distance_to(world.pose(obj)) < SAME
    with pytest.raises(TransformError, match="unknown frame 'pr3'"):
        heard.lookups("map", ["pr3"])


def test_fixed_joints_stay_put_and_only_moving_frames_change(world: World) -> None:
    frames = TfFrames(world)
    static, moving = frames.static_transforms(), frames.moving_transforms()
    world.set_joint_states("pr2", {"l_shoulder_pan_joint": 0.5})
    world.set_pose("mug-1", Pose((0.1, 0.0, 0.0)) * world.pose("mug-1"))
    assert frames.static_transforms() == static
    changed = {
        child
        for (_, child, t0, q0), (_, _, t1, q1) in zip(
            moving, frames.moving_transforms(), strict=True
        )
        if np.abs(np.subtract((*t0, *q0), (*t1, *q1))).max() > SAME
    }
    assert changed == {"l_shoulder_pan_link", "mug-1"}
