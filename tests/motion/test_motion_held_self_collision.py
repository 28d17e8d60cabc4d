"""An arm motion keeps what its hand holds out of the robot's own body.

The PR2 holds a 0.7 m stick upright in its right hand, away from everything else. For
seeded goals whose straight joint path swings the stick into the robot (found and judged
by raw PyBullet closest points between the stick and the robot's links, the hand's own
links left out), the motion goes round (every configuration along the planned path,
40 per segment, keeps the stick apart) or fails naming the stick; a goal with the stick
in the base is refused before planning. Before, the world's checks skipped the robot's
body for held things and the self walk knew only links: the straight paths ran the stick
up to 12 cm into the base.
"""

from __future__ import annotations

import numpy as np
import pybullet
import pytest

from robocram.execution.failures import ManipulationPathBlocked
from robocram.motion.arm_motion import plan_arm_motion
from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from robocram.world import RobotHandle, World

REACH = 0.05  # [m] closest points asked this far
FREE = 0.005  # [m] a goal's stick at least this far from the robot
INTO = -0.03  # [m] a straight path whose stick goes this deep is a case
TOUCH = -0.001  # [m] the deepest the stick may go along a planned path (PyBullet's noise)


class _Stick:
    """The PR2 away from the table with a stick in its right hand, and the raw judge."""

    def __init__(self) -> None:
        scene = tabletop_scene("pr2")
        self.world: World = scene.world
        self.world.set_pose("pr2", Pose((-3.0, 0.0, 0.0)))
        self.robot = RobotHandle.of(self.world, "pr2")
        arm = self.robot.description.arms["right"]
        self.joints = tuple(arm.joints)
        x, y, z = self.world.link_pose("pr2", arm.tool_frame).position
        self.world.add_box("stick", (0.03, 0.03, 0.7), (x, y, z - 0.3))
        self.world.attach("stick", "pr2", arm.end_effector_link)
        body = self.world.object("pr2")
        self.body = body.body_id
        self.names = body.index_names()
        self.hand = {
            i for i, n in self.names.items()
            if n.startswith("r_gripper") or n in ("r_wrist_roll_link", "r_wrist_flex_link")
        }  # fmt: skip
        self.start = self.now()

    def now(self) -> np.ndarray:
        states = self.world.joint_states("pr2")
        return np.array([states[j] for j in self.joints])

    def depth(self, q: np.ndarray) -> tuple[float, str]:
        """The stick's least distance [m] to a robot link but the hand's, with the arm at
        ``q``, from PyBullet's own closest points, and that link."""
        self.world.set_joint_states("pr2", dict(zip(self.joints, q.tolist(), strict=True)))
        points = pybullet.getClosestPoints(
            self.world.object("stick").body_id, self.body, REACH,
            physicsClientId=self.world.physics.client(),
        )  # fmt: skip
        found = [(p[8], self.names[p[4]]) for p in points if p[4] not in self.hand]
        return min(found, default=(REACH, ""))

    def swinging_goal(self, seed: int) -> tuple[np.ndarray, np.ndarray]:
        """A goal with the stick clear whose straight path takes it into the robot, and
        the deepest configuration on that path."""
        model = self.robot.description.model
        lows = np.array([max(model.joints[j].lower or -3.0, -3.0) for j in self.joints]) + 0.01
        highs = np.array([min(model.joints[j].upper or 3.0, 3.0) for j in self.joints]) - 0.01
        rng = np.random.default_rng(seed)
        try:
            for _ in range(400):
                goal = np.clip(self.start + rng.normal(scale=0.6, size=7), lows, highs)
                if self.depth(goal)[0] < FREE:
                    continue
                path = [self.start + (goal - self.start) * s for s in np.linspace(0, 1, 30)]
                depths = [self.depth(q)[0] for q in path]
                if min(depths) < INTO:
                    return goal, path[int(np.argmin(depths))]
        finally:
            self.depth(self.start)
        raise AssertionError(f"seed {seed}: no swinging goal in 400 tries")


@pytest.fixture(scope="module")
def stick() -> _Stick:
    return _Stick()


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_a_held_stick_is_taken_round_the_robot_or_refused(stick: _Stick, seed: int) -> None:
    goal, _ = stick.swinging_goal(seed)
    try:
        motion = plan_arm_motion(stick.robot, dict(zip(stick.joints, goal.tolist(), strict=True)))
    except ManipulationPathBlocked as failure:
        assert any("stick" in pair for pair in failure.colliding_pairs or ()), failure
        return
    points = [np.array(w) for w in motion.path.waypoints]
    try:
        deepest = min(
            stick.depth(a + (b - a) * s)
            for a, b in zip(points, points[1:], strict=False)
            for s in np.linspace(0.0, 1.0, 40)
        )
    finally:
        stick.depth(stick.start)
    assert deepest[0] > TOUCH, deepest
    assert np.allclose(points[-1], goal, atol=1e-6)


def test_a_goal_with_the_held_stick_in_the_base_is_refused(stick: _Stick) -> None:
    _, goal = stick.swinging_goal(1)
    depth, link = stick.depth(goal)
    stick.depth(stick.start)
    assert depth < INTO and link == "base_link"
    with pytest.raises(ManipulationPathBlocked) as failure:
        plan_arm_motion(stick.robot, dict(zip(stick.joints, goal.tolist(), strict=True)))
    assert ("stick", "base_link") in (failure.value.colliding_pairs or ())
    assert "into itself" in str(failure.value)
