"""The grip check of a suction hand: its tool frame touches a mug's top, and holds it.

A hand without fingers (``GripperDescription.suction()``) holds what its tool frame
touches, so the check puts a mug with the top of its box at the tool the reach brought
down, over the mug's axis, as the grasp model's top grasp of a suction hand does. Then
it asks for what the pick-up plan needs: nothing of the hand more than the hand's 5 mm
bound into the mug (the tool frame is on the hand's tip), no other link of the robot
touching it, and gripping holding it. The mug takes each quarter turn, as the top grasps
do, until one is clear (fixed fingers beside the tool may meet its handle in some).
"""

from __future__ import annotations

import math

from robocram.execution import PlanFailure
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH
from robocram.projection.gripper import grip, release
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robot_check.report_card import CheckResult
from robocram.tf import Pose
from robocram.tf import quaternion as quat

AWAY = Pose((0.0, 0.0, -10.0))  # where the mug is measured before it is put in place


def _mug_at_tool(robot: ProjectedRobot, tool: Pose) -> tuple[str, list[Pose]]:
    """Add a mug; the poses where the tool, at ``tool``, touches the top of its box over
    its body's axis (its origin), upright, as the grasp model's top grasps of a suction
    hand put it: one per quarter turn (fixed fingers may meet the handle in some)."""
    world = robot.world
    probe = world.add_item("robot_check_mug", "mug", AWAY)
    top = world.aabb(probe)[1][2] - AWAY.position[2]
    x, y, z = tool.position
    turns = [quat.from_euler(0.0, 0.0, k * math.pi / 2) for k in range(4)]
    return probe.name, [Pose((x, y, z - top), turn) for turn in turns]


def _faults(robot: ProjectedRobot, key: str, mug: str) -> list[str]:
    """What touches the mug wrongly: a hand link deeper than the bound, any other link."""
    arm = robot.arm(key)
    hand = {*arm.hand_links, *arm.gripper_links, arm.end_effector_link}
    faults = []
    for point in robot.world.contacts.contact_points(robot.name, mug, distance=0.0):
        depth = -point.distance
        if point.link_a not in hand:
            faults.append(f"{point.link_a} touches the mug ({depth * 1000:.1f} mm in)")
        elif depth > HAND_CONTACT_DEPTH:
            faults.append(f"{point.link_a} goes {depth * 1000:.1f} mm into the mug")
    return sorted(set(faults))


def suction_grip(robot: ProjectedRobot, key: str, tool: Pose) -> CheckResult:
    """The tool, pointing down at ``tool``, touches a mug's top and holds it."""
    name = f"{key} arm: grip"
    mug, poses = _mug_at_tool(robot, tool)
    try:
        faults: list[str] = []
        for pose in poses:
            robot.world.set_pose(mug, pose)
            found = _faults(robot, key, mug)
            faults = faults or found
            if not found:
                faults = []
                break
        if faults:
            return CheckResult(
                name,
                False,
                f"with the tool frame on the mug's top, {'; '.join(faults[:3])}",
                f"put arms[{key!r}]'s tool frame on the tip of the hand, x out of it "
                "(a FrameSpec), so the hand touches what it holds there",
            )
        held = grip(robot, key)
        return CheckResult(name, True, f"the tool touches {held}'s top and holds it", "")
    except PlanFailure as failure:
        fix = f"put arms[{key!r}]'s tool frame on the tip of the hand, x out of it"
        return CheckResult(name, False, str(failure), fix)
    finally:
        release(robot, key)
        robot.world.remove(mug)
