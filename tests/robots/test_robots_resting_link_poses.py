"""Links posed together are :func:`link_pose`'s, bit for bit (the reachability
maps' lowest point reads them; a changed bit could move a map's height bins)."""

from __future__ import annotations

import pytest

from robocram.robots import link_pose, load_description
from robocram.robots.model_pose import link_poses, resting_link_poses


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy"])
def test_every_link_s_resting_pose_is_link_pose_s(robot: str) -> None:
    model = load_description(robot).model
    assert model is not None
    poses = resting_link_poses(model)
    assert set(poses) == set(model.links)
    for name, pose in poses.items():
        alone = link_pose(model, name)
        assert pose.position == alone.position and pose.orientation == alone.orientation, name


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy"])
def test_links_posed_together_are_link_pose_s_for_the_joints_given(robot: str) -> None:
    desc = load_description(robot)
    model = desc.model
    assert model is not None
    hands = [arm for arm in desc.arms.values() if arm.gripper is not None]  # Boxy's neck: none
    assert hands
    for arm in hands:
        assert arm.gripper is not None
        for opening in (0.0, 1.0):
            joints = arm.gripper.at(opening)
            names = [arm.tool_frame, *arm.gripper_links]
            poses = link_poses(model, names, joints)
            assert list(poses) == names
            for name in names:
                alone = link_pose(model, name, joints)
                assert poses[name].position == alone.position, (name, opening)
                assert poses[name].orientation == alone.orientation, (name, opening)
