"""``setting-gripper`` (CRAM's, PyCRAM's SetGripperAction): open, close, or a joint value."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.designators import DesignatorPropertyError, an
from robocram.plans import perform
from robocram.plans.errors import PlanSetupError
from robocram.projection import simulated_robot
from robocram.scenes import TabletopScene, tabletop_scene

FINGER = "r_gripper_l_finger_joint"  # the PR2's right gripper's master joint


@pytest.fixture(scope="module")
def pr2() -> Iterator[TabletopScene]:
    scene = tabletop_scene("pr2")
    yield scene
    scene.world.close()


def test_open_close_and_a_value_move_the_fingers_there(pr2: TabletopScene) -> None:
    world = pr2.world
    limits = world.bodies.joint_limits("pr2", FINGER)
    with simulated_robot(world, "pr2"):
        perform(an.action(type="setting-gripper", gripper="right", motion="open"))
        assert world.joint_states("pr2")[FINGER] == pytest.approx(limits.upper, abs=1e-3)
        perform(an.action(type="setting-gripper", gripper="right", motion="close"))
        assert world.joint_states("pr2")[FINGER] == pytest.approx(limits.lower, abs=1e-3)
        perform(an.action(type="setting-gripper", gripper="right", motion=0.2))
        assert world.joint_states("pr2")[FINGER] == pytest.approx(0.2, abs=1e-3)


def test_a_motion_that_is_neither_names_the_valid_ones(pr2: TabletopScene) -> None:
    with simulated_robot(pr2.world, "pr2"), pytest.raises(PlanSetupError) as err:
        perform(an.action(type="setting-gripper", gripper="right", motion="half"))
    assert "'half'" in str(err.value) and "['close', 'open']" in str(err.value)
    with simulated_robot(pr2.world, "pr2"), pytest.raises(DesignatorPropertyError) as missing:
        perform(an.action(type="setting-gripper", gripper="right"))
    assert "motion" in str(missing.value)


def test_a_misspelled_action_type_names_the_closest_and_every_known_one(
    pr2: TabletopScene,
) -> None:
    from robocram.execution.failures import DesignatorReferenceFailure
    from robocram.plans import ACTIONS

    with simulated_robot(pr2.world, "pr2"), pytest.raises(DesignatorReferenceFailure) as err:
        perform(an.action(type="transportng", object="mug"))
    message = str(err.value)
    assert message.startswith("no action type 'transportng'; did you mean 'transporting'? ")
    assert all(name in message for name in ACTIONS)  # not "none", as it was


def test_grasping_closes_on_the_object_where_it_stands() -> None:
    from robocram.designators import a

    scene = tabletop_scene("pr2")
    world = scene.world
    before = world.pose("mug-1").position
    with simulated_robot(world, "pr2"):
        perform(an.action(type="looking", target=a.location(pose=scene.look_target)))
        seen = perform(an.action(type="detecting", object=an.object(type="mug")))
        held = perform(an.action(type="grasping", object=seen))
    assert "mug-1" in world.bodies.attachments("pr2") and held.object_name == "mug-1"  # in the hand
    assert world.pose("mug-1").position[2] == pytest.approx(before[2], abs=0.01)  # not lifted
    assert held.lifted == held.grasp_pose
    world.close()
