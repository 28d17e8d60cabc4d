"""All links' resting poses at once are :func:`link_pose`'s, bit for bit (the reachability
maps' lowest point reads them; a changed bit could move a map's height bins)."""

from __future__ import annotations

import pytest

from robocram.robots import link_pose, load_description
from robocram.robots.model_pose import resting_link_poses


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy"])
def test_every_link_s_resting_pose_is_link_pose_s(robot: str) -> None:
    model = load_description(robot).model
    assert model is not None
    poses = resting_link_poses(model)
    assert set(poses) == set(model.links)
    for name, pose in poses.items():
        alone = link_pose(model, name)
        assert pose.position == alone.position and pose.orientation == alone.orientation, name
