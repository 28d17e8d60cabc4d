"""No joint jumps: the torso, the head and the grippers move along checked, timed
trajectories, reported to listeners (issue 35, item 2; issue 42, item 5).

The ledger (``joint_ledger.py``) is independent of the planner: it reads the world's
joint states and the base pose before the first motion and at each reported trajectory.
Between two of them only the joints the trajectory names (and their mimic followers), or
for a base trajectory only the base, may change; a joint trajectory starts where its
joints were and ends where they are; and after a motion nothing has changed since its
last trajectory. A joint set or a base placed directly by a motion breaks one of these.
The kitchen transports are the session's runs, the ledger watching them as they ran
(``tests/kitchen_transports.py``).
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pytest

from robocram.designators import a
from robocram.execution.failures import PtuPathBlocked, TorsoGoalNotReached, TorsoPathBlocked
from robocram.motion import JointTrajectory, joint_limits, trajectory_listener
from robocram.projection import simulated_robot
from robocram.scenes import TabletopScene, tabletop_scene
from robocram.tf import PoseStamped
from robocram.world import World
from tests.kitchen_transports import SHARED, Transports
from tests.projection.joint_ledger import Ledger

PERIOD = 0.05  # [s] the trajectories' sampling period
TORSO_GOAL = {"pr2": 0.2, "hsrb": 0.1}  # [m] within the lift's limits; the HSR looks down to
# the mug past its parked hand only this low (higher, the hand meets the turning head)
TOL = 1e-9


def assert_timed(world: World, robot: str, trajectory: JointTrajectory) -> None:
    """Points every period at most, no joint faster than its limit between two of them."""
    limits = joint_limits(world.robot(robot).description, trajectory.joint_names)
    times, positions = trajectory.times(), trajectory.positions()
    assert len(times) >= 3
    steps = np.diff(times)
    assert np.all(steps > 0.0) and np.all(steps <= PERIOD + TOL)
    speeds = np.array([lim.velocity for lim in limits])
    moved = np.abs(np.diff(positions, axis=0))
    assert np.all(moved <= speeds * steps[:, None] * (1 + 1e-6) + TOL)


@pytest.fixture(params=["pr2", "hsrb"])
def scene(request: pytest.FixtureRequest) -> Iterator[TabletopScene]:
    made = tabletop_scene(request.param)
    yield made
    made.world.close()


def test_torso_head_and_gripper_motions_are_timed_trajectories(scene: TabletopScene) -> None:
    world, robot = scene.world, scene.robot
    desc = world.robot(robot).description
    arm = next(iter(desc.arms))
    gripper = desc.arms[arm].gripper
    assert gripper is not None and desc.torso_joint is not None and desc.pan_tilt is not None
    world.set_joint_states(robot, gripper.at(0.5))  # half open: closing and opening move it
    ledger = Ledger(world, robot)
    with trajectory_listener(ledger), simulated_robot(world, robot):
        goal = TORSO_GOAL[robot]
        reached, (torso,) = ledger.perform(a.motion(type="moving-torso", joint_angle=goal))
        assert torso.kind == "torso" and torso.joint_names == (desc.torso_joint,)
        assert reached == pytest.approx(goal, abs=TOL) == torso.end[desc.torso_joint]
        mug = PoseStamped("map", world.pose("mug-1").position)
        aimed, (head,) = ledger.perform(a.motion(type="looking", target=mug))
        assert head.kind == "head"
        assert set(head.joint_names) == {desc.pan_tilt.pan_joint, desc.pan_tilt.tilt_joint}
        assert head.end == pytest.approx(aimed, abs=TOL)
        trajectories = [torso, head]
        for motion in ("closing", "opening"):
            values, (moved,) = ledger.perform(a.motion(type=motion, gripper=arm))
            assert moved.kind == "gripper" and moved.joint_names[0] == gripper.names[0]
            assert moved.end == pytest.approx({j: values[j] for j in moved.joint_names}, abs=TOL)
            side = gripper.joints[0].closed if motion == "closing" else gripper.joints[0].open
            assert values[gripper.names[0]] == pytest.approx(side, abs=1e-6)
            trajectories.append(moved)
    for trajectory in trajectories:
        assert_timed(world, robot, trajectory)


def test_a_gripper_closing_on_a_can_stops_on_it_along_its_trajectory() -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    ledger = Ledger(world, "pr2")
    with trajectory_listener(ledger), simulated_robot(world, "pr2"):
        ledger.perform(a.motion(type="opening", gripper="right"))
        tool = world.link_pose("pr2", "r_gripper_tool_frame").position
        world.bodies.add_cylinder("can", 0.02, 0.1, pose=tool, mass=0.1)  # 4 cm across
        held, (closing,) = ledger.perform(a.motion(type="gripping", gripper="right"))
    assert held == "can" and world.bodies.attached_to("can") is not None
    finger = closing.end["r_gripper_l_finger_joint"]
    assert finger == pytest.approx(world.joint_states("pr2")["r_gripper_l_finger_joint"], abs=TOL)
    assert 0.05 < finger < 0.4  # on the can: neither open (0.548) nor closed (0)
    assert closing.kind == "gripper"
    assert_timed(world, "pr2", closing)
    world.close()


def test_a_torso_goal_beyond_the_limit_moves_to_it_then_fails() -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    ledger = Ledger(world, "pr2")
    with (
        trajectory_listener(ledger),
        simulated_robot(world, "pr2"),
        pytest.raises(TorsoGoalNotReached) as info,
    ):
        ledger.perform(a.motion(type="moving-torso", joint_angle=0.5))
    (torso,) = ledger.seen
    upper = world.bodies.joint_limits("pr2", "torso_lift_joint").upper
    assert info.value.reached == pytest.approx(upper, abs=TOL)
    assert torso.end["torso_lift_joint"] == pytest.approx(upper, abs=TOL)
    assert world.joint_states("pr2")["torso_lift_joint"] == pytest.approx(upper, abs=TOL)
    world.close()


def test_a_torso_raised_under_a_board_fails_naming_it_and_nothing_moves() -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    tops = [world.contacts.link_aabb("pr2", link)[1][2] for link in world.link_names("pr2")]
    x, y, _ = world.pose("pr2").position
    world.add_box("board", (0.8, 0.8, 0.02), pose=(x, y, max(tops) + 0.06))  # 5 cm above it
    before, pose = dict(world.joint_states("pr2")), world.pose("pr2")
    ledger = Ledger(world, "pr2")
    with (
        trajectory_listener(ledger),
        simulated_robot(world, "pr2"),
        pytest.raises(TorsoPathBlocked, match="board") as info,
    ):
        ledger.perform(a.motion(type="moving-torso", joint_angle=0.3))
    assert any(other == "board" for _, other in info.value.colliding_pairs or ())
    assert 0.0 < (info.value.path_fraction or 0.0) <= 1.0
    assert ledger.seen == []
    assert world.joint_states("pr2") == before and world.pose("pr2") == pose
    world.close()


def test_a_head_turned_into_a_post_beside_it_fails_naming_it_and_nothing_moves() -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    world.bodies.add_cylinder(
        "post", 0.015, 0.3, pose=(-0.1, -0.22, 1.25)
    )  # behind the head's right
    before, pose = dict(world.joint_states("pr2")), world.pose("pr2")
    ledger = Ledger(world, "pr2")
    with (
        trajectory_listener(ledger),
        simulated_robot(world, "pr2"),
        pytest.raises(PtuPathBlocked, match="post") as info,
    ):  # to the right: the pan cannot go round the other way (its limits are +-3 rad)
        ledger.perform(a.motion(type="looking", target=PoseStamped("map", (0.0, -2.0, 1.2))))
    assert ("head_pan_link", "post") in (info.value.colliding_pairs or ())
    assert ledger.seen == []
    assert world.joint_states("pr2") == before and world.pose("pr2") == pose
    world.close()


@SHARED  # the session's kitchen transports: one worker runs their modules
@pytest.mark.parametrize(("robot", "kind"), [("pr2", "bowl"), ("hsrb", "mug")])
def test_a_kitchen_transport_moves_the_robot_only_along_its_trajectories(
    robot: str, kind: str, kitchen_transports: Transports
) -> None:
    """The session's run (``tests/kitchen_transports.py``), the ledger watching it: the
    PR2's bowl is in a drawer, opened and closed again."""
    ledger = kitchen_transports(robot, kind).ledgered  # it found nothing, after the run too
    assert {"base", "arm", "head", "gripper"} <= {t.kind for t in ledger.seen}
