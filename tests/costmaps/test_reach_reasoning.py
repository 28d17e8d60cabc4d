"""reachable/2, pose_reachable/2 and /3, blocking/4 and lift_clearance/4, in Python and in
the world's knowledge base."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.costmaps import CostmapLocations, blocking, pose_reachable, reachable
from robocram.costmaps.reach_reasoning import LIFT_MARGIN, lift_clearance
from robocram.scenes import TabletopScene, tabletop_scene
from robocram.tf import Pose, PoseStamped


@pytest.fixture(scope="module")
def scene() -> Iterator[TabletopScene]:
    made = tabletop_scene("pr2")
    CostmapLocations(made.world)  # installs the predicates in world.kb
    yield made
    made.world.close()


def test_the_pr2_reaches_the_mug_not_the_far_bottle_from_above(scene: TabletopScene) -> None:
    world = scene.world
    assert reachable(world, "pr2", "mug-1")
    assert reachable(world, "pr2", "bottle-1")  # from the front, the grasp model's side grasp
    world.kb.consult("object_grasps(bottle, [top]).", group="bottle_from_above")
    try:
        bottle_distance = world.pose("bottle-1").distance_to(world.pose("pr2"))
        assert not reachable(world, "pr2", "bottle-1"), bottle_distance
        assert [a["O"] for a in world.kb.query("reachable(pr2, O)")] == ["mug-1"]
    finally:
        world.kb.consult("", group="bottle_from_above")


def test_pose_reachable_near_and_far(scene: TabletopScene) -> None:
    world = scene.world
    x, y, z = world.pose("mug-1").position
    over_the_mug = Pose((x, y, z + 0.2))
    assert pose_reachable(world, "pr2", over_the_mug)
    assert world.kb.holds("pose_reachable(pr2, P)", P=PoseStamped.from_pose("map", over_the_mug))
    assert not pose_reachable(world, "pr2", Pose((3.0, 0.0, 1.0)))
    assert not world.kb.holds("pose_reachable(pr2, P)", P=Pose((3.0, 0.0, 1.0)))


def test_blocking_names_what_the_arm_would_hit(scene: TabletopScene) -> None:
    world = scene.world
    joints = world.joint_states("pr2")
    assert blocking(world, "pr2", "right", "mug-1") == []
    x, y, z = world.pose("mug-1").position
    with world.snapshots.stored_state():
        world.add_box("obstacle", (0.1, 0.1, 0.1), Pose((x - 0.1, y, z + 0.3)))
        assert blocking(world, "pr2", "right", "mug-1") == ["obstacle"]
        answer = world.kb.first("blocking(pr2, right, 'mug-1', B)")
        assert answer == {"B": ["obstacle"]}
    assert world.joint_states("pr2") == pytest.approx(joints)  # the arm is put back
    assert blocking(world, "pr2", "right", "bottle-1") is None  # out of reach


def test_pose_reachable_by_one_arm(scene: TabletopScene) -> None:
    world = scene.world
    x, y, z = world.pose("mug-1").position
    over_the_mug = PoseStamped.from_pose("map", Pose((x, y, z + 0.2)))
    arms = [str(a["A"]) for a in world.kb.query("pose_reachable(pr2, A, P)", P=over_the_mug)]
    one_by_one = [
        arm for arm in ("left", "right") if pose_reachable(world, "pr2", over_the_mug, arm)
    ]
    assert sorted(arms) == one_by_one
    assert arms  # the mug is in front of the robot
    assert not world.kb.holds("pose_reachable(pr2, elbow, P)", P=over_the_mug)  # no such arm
    far = Pose((3.0, 0.0, 1.0))
    assert not world.kb.holds("pose_reachable(pr2, A, P)", P=far)


def test_lift_clearance_is_the_rise_over_the_top_of_what_holds_it(scene: TabletopScene) -> None:
    world = scene.world
    x, y, _ = world.pose("mug-1").position
    table_top = world.contacts.link_aabbs("table")["link0"][1][2]
    mug_bottom = world.contacts.link_aabbs("mug-1")["base_link"][0][2]
    on_table = lift_clearance(world, "mug-1", "table", "link0")
    assert on_table == pytest.approx(LIFT_MARGIN + (table_top - mug_bottom), abs=1e-9)
    assert on_table < 0.03  # resting on it: only the margin
    with world.snapshots.stored_state():
        world.add_box("bin", (0.3, 0.3, 0.2), Pose((x, y, table_top + 0.1)))  # walls round it
        rise = lift_clearance(world, "mug-1", "bin", "link0")
        assert rise == pytest.approx(0.2 + LIFT_MARGIN, abs=0.005)
        answer = world.kb.first("lift_clearance('mug-1', bin, link0, R)")
        assert answer is not None and float(str(answer["R"])) == pytest.approx(rise)
