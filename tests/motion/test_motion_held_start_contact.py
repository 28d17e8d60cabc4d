"""A held thing touching something where a motion starts is not pushed into it.

The PR2 holds a 0.1 m tall box hanging under its level hand, its bottom resting on a
stand. Rolling the forearm turns the box about an axis above it: its bottom edge swings
down, about 4 mm at 0.5 rad (the HSR's lift of a gripped milk carton turned it so, 1.06 mm
into the table). The motion starts in that contact, which it may keep but not deepen: the
planned path, judged by raw PyBullet at 40 configurations per segment, never has the box
more than 1 mm in the stand, or the motion is refused naming the pair. Before, a start
contact of a held thing was kept at any depth and the straight roll went through.
"""

from __future__ import annotations

import numpy as np
import pybullet
import pytest

from robocram.execution.failures import ManipulationPathBlocked
from robocram.motion.arm_motion import MotionSettings, plan_arm_motion
from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from robocram.world import RobotHandle

BOX = (0.06, 0.06, 0.10)  # [m]
DEEPEST = 0.001  # [m] the box in the stand at most (the audit's bound)
ROLL = "r_forearm_roll_joint"


@pytest.mark.parametrize("plan", [False, True])
def test_a_held_box_resting_at_the_start_is_not_rolled_into_its_stand(plan: bool) -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    world.set_pose("pr2", Pose((-3.0, 0.0, 0.0)))
    robot = RobotHandle.of(world, "pr2")
    arm = robot.description.arms["right"]
    x, y, z = world.link_pose("pr2", arm.tool_frame).position
    world.add_box("box", BOX, (x, y, z - BOX[2] / 2))
    world.add_box("stand", (0.2, 0.2, 0.02), (x, y, z - BOX[2] - 0.01))
    world.attach("box", "pr2", arm.end_effector_link)
    cid = world.physics.client()
    box, stand = world.object("box").body_id, world.object("stand").body_id

    def depth(q: dict[str, float]) -> float:
        world.set_joint_states("pr2", q)
        points = pybullet.getClosestPoints(box, stand, 0.0, physicsClientId=cid)
        return max((-p[8] for p in points), default=0.0)

    start = world.joint_states("pr2")[ROLL]
    joints = list(arm.joints)
    now = world.joint_states("pr2")
    straight = [
        depth({**{j: now[j] for j in joints}, ROLL: start + 0.5 * s}) for s in np.linspace(0, 1, 30)
    ]
    depth({j: now[j] for j in joints})
    assert max(straight) > 0.003  # the straight roll pushes the box 3 mm or more in
    try:
        motion = plan_arm_motion(robot, {ROLL: start + 0.5}, settings=MotionSettings(plan=plan))
    except ManipulationPathBlocked as failure:
        assert ("box", "stand") in (failure.colliding_pairs or ()), failure
        return
    names = motion.path.joints
    points = [np.array(w) for w in motion.path.waypoints]
    deepest = max(
        depth(dict(zip(names, (a + (b - a) * s).tolist(), strict=True)))
        for a, b in zip(points, points[1:], strict=False)
        for s in np.linspace(0.0, 1.0, 40)
    )
    assert deepest <= DEEPEST
