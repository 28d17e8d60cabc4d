"""Transform tree: chained lookups, inverses, re-parenting, cycles, sources, context binding."""

from __future__ import annotations

import math
from collections.abc import Mapping

import pytest

from robocram.tf import (
    Pose,
    PoseStamped,
    TfError,
    TransformError,
    TransformSource,
    TransformStamped,
    TransformTree,
    current_transform_tree,
    transform_pose,
    using_transform_tree,
)
from robocram.tf import quaternion as quat


def _close(a: Pose, b: Pose, tol: float = 1e-9) -> bool:
    return a.distance_to(b) < tol and a.angle_to(b) < 1e-7


@pytest.fixture
def robot_tree() -> TransformTree:
    """map -> odom -> base_footprint -> torso -> {r_wrist, head}, plus map -> table."""
    tree = TransformTree()
    tree.set_transform("map", "odom", Pose((0.5, 0, 0)))
    tree.set_transform("odom", "base_footprint", Pose.from_xyz_rpy((1, 2, 0), (0, 0, math.pi / 2)))
    tree.set_transform(TransformStamped("base_footprint", "torso", (0, 0, 0.8), stamp=3.5))
    tree.set_transform("torso", "r_wrist", Pose.from_xyz_rpy((0.6, -0.2, 0), (0.3, 0.2, -0.1)))
    tree.set_transform("torso", "head", Pose((0, 0, 0.5)))
    tree.set_transform("map", "table", Pose((3, 0, 0.75)))
    return tree


def test_lookup_composes_the_chain(robot_tree: TransformTree) -> None:
    wrist_in_map = robot_tree.lookup("map", "r_wrist")
    # base faces +y in map, so the wrist's +x offset of 0.6 m in torso becomes +y in map.
    assert wrist_in_map.position == pytest.approx((1.5 + 0.2, 2.0 + 0.6, 0.8), abs=1e-12)
    expected_q = quat.multiply(quat.from_euler(0, 0, math.pi / 2), quat.from_euler(0.3, 0.2, -0.1))
    assert quat.angle_between(wrist_in_map.orientation, expected_q) < 1e-9


def test_lookup_between_two_robot_links_and_its_inverse(robot_tree: TransformTree) -> None:
    head_in_wrist = robot_tree.lookup("r_wrist", "head")
    wrist_in_head = robot_tree.lookup("head", "r_wrist")
    assert _close(head_in_wrist * wrist_in_head, Pose())
    assert _close(
        robot_tree.lookup("map", "r_wrist") * head_in_wrist, robot_tree.lookup("map", "head")
    )
    assert _close(robot_tree.lookup("torso", "torso"), Pose())


def test_transform_pose_between_links_round_trips(robot_tree: TransformTree) -> None:
    grasp = PoseStamped("r_wrist", (0.1, 0, 0), quat.from_euler(0, 0.4, 0), stamp=7.0)
    in_head = robot_tree.transform_pose(grasp, "head")
    assert in_head.frame_id == "head" and in_head.stamp == 7.0
    # the point 0.1 m along the wrist's x axis, in the head frame, by hand:
    wrist_in_head = robot_tree.lookup("head", "r_wrist")
    assert in_head.position == pytest.approx(wrist_in_head.transform_point((0.1, 0, 0)), abs=1e-12)
    back = transform_pose(in_head, "r_wrist", robot_tree)
    assert _close(back.pose, grasp.pose)


def test_transform_and_stamp(robot_tree: TransformTree) -> None:
    t = robot_tree.transform("base_footprint", "head")
    assert (t.frame_id, t.child_frame_id) == ("base_footprint", "head")
    assert t.translation == pytest.approx((0, 0, 1.3))
    assert robot_tree.stamp("torso") == 3.5
    assert robot_tree.parent("torso") == "base_footprint" and robot_tree.parent("map") is None


def test_unknown_frame_names_close_frames(robot_tree: TransformTree) -> None:
    with pytest.raises(TransformError, match=r"unknown frame 'r_wirst'.*'r_wrist'") as info:
        robot_tree.lookup("map", "r_wirst")
    assert info.value.frame == "r_wirst"
    assert "r_wrist" in info.value.known_frames
    assert not robot_tree.can_transform("map", "r_wirst")


def test_disconnected_trees(robot_tree: TransformTree) -> None:
    robot_tree.set_transform("camera_world", "marker", Pose((1, 0, 0)))
    assert not robot_tree.can_transform("map", "marker")
    with pytest.raises(TransformError, match="not connected"):
        robot_tree.lookup("map", "marker")


def test_cycles_are_rejected_and_reparenting_works(robot_tree: TransformTree) -> None:
    with pytest.raises(TransformError, match="cycle"):
        robot_tree.set_transform("r_wrist", "base_footprint", Pose())
    # the tree is unchanged by the rejected call
    assert robot_tree.parent("base_footprint") == "odom"
    # re-parenting an object (grasping the table leg, say) is fine
    robot_tree.set_transform("r_wrist", "table", Pose((0.1, 0, 0)))
    assert robot_tree.lookup("r_wrist", "table").position == pytest.approx((0.1, 0, 0))


def test_bad_set_transform_arguments() -> None:
    tree = TransformTree()
    with pytest.raises(TypeError, match="TransformStamped or"):
        tree.set_transform("map")  # type: ignore[call-overload]
    with pytest.raises(ValueError, match="itself"):
        tree.set_transform("map", "map", Pose())


class _FakeWorld:
    """A TransformSource: a dict of frame poses in map, as the world would give them."""

    def __init__(self, poses: dict[str, Pose]) -> None:
        self.poses = poses

    def frame_poses(self) -> Mapping[str, Pose]:
        return self.poses


def test_update_from_source_replaces_and_prunes() -> None:
    world = _FakeWorld({"map": Pose(), "cup": Pose((1, 0, 0)), "bowl": Pose((0, 1, 0))})
    assert isinstance(world, TransformSource)
    tree = TransformTree.from_source(world)
    tree.set_transform("cup", "cup_handle", Pose((0.05, 0, 0)))
    assert tree.lookup("bowl", "cup_handle").position == pytest.approx((1.05, -1, 0))
    world.poses = {"cup": Pose((2, 0, 0))}
    tree.update_from(world)
    assert "bowl" not in tree.frames()
    assert tree.lookup("map", "cup_handle").position == pytest.approx((2.05, 0, 0))


def test_context_binding() -> None:
    outer, inner = TransformTree(), TransformTree()
    outer.set_transform("map", "a", Pose((1, 0, 0)))
    inner.set_transform("map", "a", Pose((5, 0, 0)))
    with pytest.raises(TfError, match="using_transform_tree"):
        current_transform_tree()
    with using_transform_tree(outer):
        with using_transform_tree(inner):
            assert transform_pose(PoseStamped("a"), "map").position[0] == 5.0
        assert transform_pose(PoseStamped("a"), "map").position[0] == 1.0
    with pytest.raises(TfError):
        transform_pose(PoseStamped("a"), "map")
