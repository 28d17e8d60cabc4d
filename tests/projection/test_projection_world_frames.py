"""The live transform tree inside simulated_robot reads the world as it is now."""

from __future__ import annotations

import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.projection import LiveTransformTree, WorldFrames, simulated_robot
from robocram.tf import Pose, PoseStamped, TransformError, transform_pose
from robocram.world import World


def test_transform_pose_follows_the_robot() -> None:
    with World() as world:
        world.bodies.add_floor()
        world.add_robot("pr2")
        world.add_box("crate", (0.2, 0.2, 0.2), pose=Pose((3.0, 1.0, 0.1)))
        with simulated_robot(world, "pr2"):
            crate = PoseStamped("crate", (0.0, 0.0, 0.0))
            assert transform_pose(crate, "base_footprint").position == pytest.approx((3, 1, 0.1))
            target = PoseStamped("map", (1.0, 0.0, 0.0))
            perform(a.motion(type="going", target=a.location(pose=target)))
            assert transform_pose(crate, "base_footprint").position == pytest.approx((2, 1, 0.1))
        frames = WorldFrames(world).frame_poses()
        assert frames["crate"].position == pytest.approx((3.0, 1.0, 0.1))
        assert frames["base_footprint"].position == pytest.approx((1.0, 0.0, 0.0))
        assert "r_gripper_tool_frame" in frames


def test_the_live_tree_reads_a_frame_when_it_is_first_named() -> None:
    with World() as world:
        world.bodies.add_floor()
        world.add_robot("pr2")
        world.add_box("crate", (0.2, 0.2, 0.2), pose=Pose((3.0, 1.0, 0.1)))
        tree = LiveTransformTree(WorldFrames(world))
        assert "crate" in tree and "no_such_frame" not in tree
        assert tree.parent("base_footprint") == "map"
        same = tree.transform_pose(
            PoseStamped("r_gripper_tool_frame", (0, 0, 0)), "torso_lift_link"
        )
        assert same.frame_id == "torso_lift_link"
        assert tree.transform_pose(PoseStamped("map", (1, 2, 3)), "map").position == (1, 2, 3)
        assert "crate" in tree.frames() and "l_gripper_tool_frame" in tree.frames()
        with pytest.raises(TransformError, match="no_such_frame"):
            tree.lookup("map", "no_such_frame")
