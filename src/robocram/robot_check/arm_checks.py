"""Drive each arm once: parking, the tool frame's convention, the gripper, a reach and a grip.

The reach goes to a point ahead of the shoulder along the arm's working direction
(straight ahead, or sideways for an arm such as Stretch's), tool pointing down as the
pick-up plan holds it; a mug then appears between the fingers and the gripper must close
on it, which fails if the tool frame is not between the fingertips. A hand the mug is too
wide for (a small one-sided jaw) closes on a short cylinder sized to its opening instead,
centred on the tool frame; it passes saying that plans cannot pick mugs with it. A suction
hand touches a mug's top instead (``suction_checks.py``).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from itertools import combinations

import numpy as np

from robocram.execution import PlanFailure
from robocram.execution.failures import GripperMetOneSide
from robocram.kinematics import base_in_ik
from robocram.motion.self_collision_matrix import SelfCollisionMatrix
from robocram.projection.arm import move_joints, move_tcp
from robocram.projection.gripper import (
    close_gripper,
    grip,
    open_gripper,
    release,
)
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robot_check.report_card import CheckResult
from robocram.robot_check.suction_checks import suction_grip
from robocram.robots import ArmDescription
from robocram.robots.arm_envelope import arm_reach, working_yaw
from robocram.robots.arm_slice import slice_advice
from robocram.robots.link_centre import link_centre
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat
from robocram.world import World, WorldObject

APPROACH_AGREEMENT = math.cos(math.radians(30.0))  # tool x vs the wrist-to-tool direction
MIN_OPENING = 0.005  # [m] the fingers must move apart at least this much when opening
REACH_SHARES = (0.65, 0.5, 0.8, 0.95)  # of the shoulder-to-wrist length: the wrist ahead
WRISTS_BELOW = (0.10, -0.10)  # [m] the wrist below the shoulder, the tool a hand lower
GRASP_HEIGHT = 0.05  # [m] above a mug's bottom, where the pick-up plan grasps it
YAWS = (0.0, math.pi / 2, math.pi, -math.pi / 2)  # [rad] tool turns about the vertical
PROBE = "robot_check_mug"  # the object the grip closes on
FIT_SHARE = 2 / 3  # of the widest opening: a probe for a hand the mug is too wide for
FIT_HEIGHT = 0.03  # [m] the probe's height, centred on the tool frame: within short jaws
FIT_MASS = 0.1  # [kg] the probe is movable, as a grasped object is


def parking(robot: ProjectedRobot, key: str, arm: ArmDescription) -> CheckResult:
    """The arm reaches its parking pose without touching the floor or the robot itself."""
    name = f"{key} arm: parking"
    try:
        move_joints(robot, key, dict(arm.parking))
    except PlanFailure as failure:
        return CheckResult(name, False, str(failure), f"parking values of arms[{key!r}] in limits")
    inside = _self_contacts(robot, arm)
    if inside:
        return CheckResult(
            name, False, f"parked, the robot is in itself: {', '.join(inside)}",
            f"parking values of arms[{key!r}] that keep the arm clear of the robot",
        )  # fmt: skip
    floors = [o for o in robot.world.objects() if o.type == "floor"]
    low = [
        p.link_a
        for floor in floors
        for p in robot.world.contacts.contact_points(robot.name, floor)
        if p.link_a in arm.links or p.link_a in arm.hand_links
    ]
    if low:
        return CheckResult(
            name, False, f"{sorted(set(low))} touch the floor", "park the arm higher"
        )
    return CheckResult(name, True, f"{len(arm.parking)} joints set", "")


def _self_contacts(robot: ProjectedRobot, arm: ArmDescription) -> list[str]:
    """The self-collision matrix's pairs with a link of ``arm`` that touch now."""
    world = robot.world
    mine = {*arm.links, *arm.hand_links, *arm.gripper_links}
    pairs = [p for p in SelfCollisionMatrix.of(robot.handle).checked if mine & set(p)]
    gaps = world.contacts.self_distances(robot.name, pairs, 0.0)
    return [
        f"{a} in {b} ({-gap * 1000:.1f} mm)"
        for (a, b), gap in zip(pairs, gaps.tolist(), strict=True)
        if gap < 0.0
    ]


def tool_frame(robot: ProjectedRobot, key: str, arm: ArmDescription) -> CheckResult:
    """The tool frame's x points from the wrist towards the tool (the approach)."""
    name = f"{key} arm: tool frame"
    wrist = robot.world.link_pose(robot.name, arm.end_effector_link)
    tool = robot.world.link_pose(robot.name, arm.tool_frame)
    out = np.subtract(tool.position, wrist.position)
    suction = arm.gripper is not None and arm.gripper.is_suction
    if suction and np.linalg.norm(out) < 0.02:
        # a bare flange holds with its face, at the wrist frame: out of the wrist's body
        middle = wrist * Pose(link_centre(robot.description.model.link(arm.end_effector_link)))
        out = np.subtract(tool.position, middle.position)
    if np.linalg.norm(out) < (0.005 if suction else 0.02):
        return CheckResult(
            name,
            False,
            f"{arm.tool_frame} is {np.linalg.norm(out):.3f} m from the wrist",
            "put the tool frame between the fingertips (x = approach, y = opening)",
        )
    x_axis = tool.matrix()[:3, 0]
    agreement = float(x_axis @ out / np.linalg.norm(out))
    if agreement < APPROACH_AGREEMENT:
        angle = math.degrees(math.acos(max(-1.0, min(1.0, agreement))))
        return CheckResult(
            name,
            False,
            f"{arm.tool_frame}'s x is {angle:.0f} deg off the wrist-to-tool direction",
            "turn the tool frame (a FrameSpec) so that x points out of the hand",
        )
    return CheckResult(name, True, f"{arm.tool_frame}: x points out of the hand", "")


def _finger_span(robot: ProjectedRobot, arm: ArmDescription) -> float:
    """How far apart [m] the fingers and the tool frame lie along its y (the opening).

    The tool frame counts as a point too, so a single jaw closing on a fixed one is seen;
    each finger counts with its frame and the middle of its collision shapes, since a
    turning jaw's frame sits on its pivot.
    """
    tool = robot.world.link_pose(robot.name, arm.tool_frame)
    opening = tool.matrix()[:3, 1]
    model = robot.description.model
    links = [link for link in arm.gripper_links if link in robot.body.link_index]
    frames = [robot.world.link_pose(robot.name, link) for link in links]
    middles = [f * Pose(link_centre(model.link(k))) for f, k in zip(frames, links, strict=True)]
    points = [tool.position, *(p.position for p in (*frames, *middles))]
    along = [float(opening @ point) for point in points]
    return max(along, default=0.0) - min(along, default=0.0)


def gripper(robot: ProjectedRobot, key: str, arm: ArmDescription) -> CheckResult:
    """Opening moves the fingers apart, closing brings them together."""
    name = f"{key} arm: gripper"
    try:
        opened = (open_gripper(robot, key), _finger_span(robot, arm))[1]
        closed = (close_gripper(robot, key), _finger_span(robot, arm))[1]
        open_gripper(robot, key)
    except PlanFailure as failure:
        return CheckResult(name, False, str(failure), f"check gripper_joints of arms[{key!r}]")
    if opened - closed < MIN_OPENING:
        return CheckResult(
            name,
            False,
            f"the fingers span {opened:.3f} m open and {closed:.3f} m closed",
            "give the arm a gripper (GripperDescription) opening its joints where the fingers "
            "part, or list the finger joints in gripper_joints",
        )
    return CheckResult(name, True, f"fingers span {opened:.3f} m open, {closed:.3f} m closed", "")


def _reaches(
    robot: ProjectedRobot, arm: ArmDescription
) -> Iterator[tuple[Vector3, quat.Quaternion, bool]]:
    """Targets and tool orientations to try: tool down first at every target and yaw,
    then level (a side grasp: approach along the working direction, the wrist where the
    tool was, turned either way about the approach), marked True."""
    targets = reach_targets(robot, arm)
    for target in targets:
        for yaw in YAWS:
            yield target, _down(yaw), False
    heading = quat.to_euler(robot.world.pose(robot.name).orientation)[2]
    heading += working_yaw(robot.description.model, arm)
    for x, y, z in targets:
        for roll in (0.0, math.pi):
            yield (x, y, z), quat.from_euler(roll, 0.0, heading), True


def _down(yaw: float) -> quat.Quaternion:
    """A tool orientation with its approach axis (x) pointing down, turned by ``yaw``."""
    pitch = quat.from_euler(0.0, math.pi / 2, 0.0)
    return quat.multiply(quat.from_euler(0.0, 0.0, yaw), pitch)


def reach_targets(robot: ProjectedRobot, arm: ArmDescription) -> list[Vector3]:
    """Points [m, map] ahead of the shoulder where the tool, pointing down, may be.

    As the tabletop scene places its mug: the wrist a share of the arm's length ahead of
    the shoulder, along its working direction, and a little below it, the tool a hand's
    length under the wrist; a few shares and heights, since arms with few joints reach
    only some of them. An arm that slides (a telescope) counts its length extended.
    """
    world = robot.world
    model = robot.description.model
    links = [*dict.fromkeys((*arm.links, arm.end_effector_link))]
    points = [world.link_pose(robot.name, link).position for link in links]
    length = sum(math.dist(p, q) for p, q in zip(points, points[1:], strict=False))
    if any(model.joints[j].type == "prismatic" for j in arm.joints):
        length = max(length, arm_reach(model, arm))
    hand = math.dist(points[-1], world.link_pose(robot.name, arm.tool_frame).position)
    base = world.pose(robot.name).orientation
    heading = quat.to_euler(base)[2] + working_yaw(model, arm)
    x, y, z = points[0]
    c, s = math.cos(heading), math.sin(heading)
    return [
        (x + c * share * length, y + s * share * length, z - below - hand)
        for below in WRISTS_BELOW
        for share in REACH_SHARES
    ]


def reach_and_grip(robot: ProjectedRobot, key: str, arm: ArmDescription) -> list[CheckResult]:
    """Reach ahead, tool down; then close the gripper on a mug put where plans grasp one.

    An arm whose tool cannot point down anywhere (a SCARA arm's wrist turns about the
    vertical only: IAI's Kevin) reaches with its tool level instead, as a side grasp."""
    errors: list[str] = []
    for target, orientation, level in _reaches(robot, arm):
        try:
            reached = move_tcp(robot, key, Pose(target, orientation))
        except PlanFailure as failure:
            errors.append(str(failure))
            continue
        detail = f"tool at {_fmt(reached.position)} (map)" + (", level" if level else "")
        gripper = arm.gripper
        touch = gripper is not None and gripper.is_suction
        held = suction_grip(robot, key, reached) if touch else _grip(robot, key, reached)
        return [CheckResult(f"{key} arm: reach", True, detail, ""), held]
    fix = "check the arm's joints and base_link, and that the tool frame is at the fingers"
    planar = slice_advice(robot.description, arm, base_in_ik(robot.description, key))
    return [CheckResult(f"{key} arm: reach", False, errors[0], planar or fix)]


def _grip(robot: ProjectedRobot, key: str, tool: Pose) -> CheckResult:
    name = f"{key} arm: grip"
    fix = "put the tool frame between the fingertips (where an object is held)"
    x, y, z = tool.position
    turned = quat.from_euler(0.0, 0.0, _opening_yaw(robot, key))  # the handle out of the way
    mug = Pose((x, y, z - GRASP_HEIGHT), turned)
    held, detail, width = _grip_on(
        robot, key, tool, mug, lambda w: w.add_item(PROBE, "mug", mug.position)
    )
    if held:
        return CheckResult(name, True, detail, "")
    opening = _widest_opening(robot, key)
    if opening is None or width <= opening:
        return CheckResult(name, False, detail, fix)
    try:  # the hand may have moved to centre itself on the mug
        move_tcp(robot, key, tool)
    except PlanFailure:
        return CheckResult(name, False, detail, fix)
    radius = FIT_SHARE * opening / 2
    held, small, _ = _grip_on(
        robot, key, tool, Pose(tool.position),
        lambda w: w.bodies.add_cylinder(PROBE, radius, FIT_HEIGHT, tool.position, mass=FIT_MASS),
    )  # fmt: skip
    too_wide = (
        f"the mug is {width * 1000:.0f} mm across, wider than the hand opens "
        f"({opening * 1000:.0f} mm): plans cannot pick mugs with it"
    )
    if not held:
        return CheckResult(name, False, f"{too_wide}; a {radius * 2000:.0f} mm probe: {small}", fix)
    return CheckResult(name, True, f"{small} ({radius * 2000:.0f} mm across); {too_wide}", "")


def _grip_on(
    robot: ProjectedRobot,
    key: str,
    tool: Pose,
    pose: Pose,
    add: Callable[[World], WorldObject],
) -> tuple[bool, str, float]:
    """Open the hand, ``add`` an object (unturned), put it at ``pose`` and grip it centred:
    whether it held, what happened in words, and the object's width [m] across (the
    narrower side of its box, unturned)."""
    open_gripper(robot, key)
    probe = add(robot.world)
    low, high = robot.world.aabb(probe.name)
    width = min(high[0] - low[0], high[1] - low[1])
    robot.world.set_pose(probe.name, pose)
    try:
        held, moved = _centred_grip(robot, key, tool)
        where = (
            "at the tool frame" if moved < 1e-4 else f"with the hand centred {moved * 1000:.0f} mm"
        )
        return True, f"closed on {held} {where}", width
    except PlanFailure as failure:
        return False, str(failure), width
    finally:
        release(robot, key)
        robot.world.remove(probe)
        open_gripper(robot, key)


def _widest_opening(robot: ProjectedRobot, key: str) -> float | None:
    """[m] how wide ``key``'s hand opens, as its gripper says (None: not known)."""
    gripper = robot.arm(key).gripper
    return gripper.max_opening if gripper is not None else None


def _centred_grip(robot: ProjectedRobot, key: str, tool: Pose) -> tuple[str, float]:
    """Grip as the pick-up plan does: where the fingers meet the object on one side only,
    move the hand by the shift the failure names and grip again (twice at most). What was
    gripped and how far [m] the hand moved."""
    for _ in range(2):
        try:
            return grip(robot, key), float(
                np.linalg.norm(np.subtract(tool.position, _at(robot, key)))
            )
        except GripperMetOneSide as one_sided:
            if one_sided.shift is None:
                raise
            x, y, z = _at(robot, key)
            dx, dy, dz = one_sided.shift
            move_tcp(robot, key, Pose((x + dx, y + dy, z + dz), tool.orientation))
    return grip(robot, key), float(np.linalg.norm(np.subtract(tool.position, _at(robot, key))))


def _at(robot: ProjectedRobot, key: str) -> tuple[float, float, float]:
    """Where ``key``'s tool frame is [m, map]."""
    position = robot.world.link_pose(robot.name, robot.arm(key).tool_frame).position
    return (float(position[0]), float(position[1]), float(position[2]))


def _opening_yaw(robot: ProjectedRobot, key: str) -> float:
    """[rad] the heading of the line through the two gripper links farthest apart: a mug
    turned so that its x axis lies along it keeps its handle (+y) clear of the fingers, as
    the grasp model's top grasps do."""
    arm = robot.arm(key)
    links = [link for link in arm.gripper_links if link in robot.body.link_index]
    points = [np.asarray(robot.world.link_pose(robot.name, link).position) for link in links]
    if len(points) < 2:
        return 0.0
    a, b = max(combinations(points, 2), key=lambda p: float(np.linalg.norm(p[0] - p[1])))
    return math.atan2(float(a[1] - b[1]), float(a[0] - b[0]))


def _fmt(point: tuple[float, float, float]) -> str:
    return "(" + ", ".join(f"{v:.2f}" for v in point) + ")"
