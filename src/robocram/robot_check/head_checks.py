"""Drive the torso and the head once: up and down, look ahead, look at a point, detect.

The torso must lift the arms' bases and its range must match the camera heights the
description gives; the camera's optical axis (z) must look forward with the neck parked
(or down onto what lies ahead), turn onto a point when looking at it, and see a mug put
there.
"""

from __future__ import annotations

import math

import numpy as np

from robocram.designators import an
from robocram.execution import PlanFailure
from robocram.projection.neck import look_at
from robocram.projection.perception import detect
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.torso import move_torso
from robocram.robot_check.report_card import CheckResult
from robocram.robots.draft.cameras import LOOKS_AHEAD
from robocram.robots.looking_means import looking_means
from robocram.tf import Pose

HEIGHT_TOLERANCE = 0.05  # [m] between a camera height given and one measured
LIFT_SHARE = 0.5  # of the torso's range the arms' bases must rise at least
LOOK_TOLERANCE = math.radians(5.0)  # [rad] between the optical axis and the look target
FORWARD = LOOKS_AHEAD  # x share in the base frame of an optical axis that looks ahead (the
# draft's threshold: a camera the draft doubts is one this check fails)
LOOK_AHEAD = 1.0  # [m] ahead of the camera to look and detect at, at least (a fixed
# camera's: nearer, on the robot's own body where its optical axis meets it first)
DOWN_ONTO = math.radians(45.0)  # [rad] below the horizon: a fixed camera that looks down at
# least this steeply onto what lies ahead looks ahead, whatever its x share
LOOK_DOWN = math.radians(20.0)  # [rad] at most: a neck arm's own links hide steeper views
LOOK_HEIGHT = 0.75  # [m] over the floor: a table top
LOOK_ASIDE = math.radians(25.0)  # [rad] a camera on an arm or a pan-only head turns this far
LOOK_FIX = {
    "pan_tilt": "check pan_tilt joints",
    "neck_arm": "check neck_arm joints",
    "arm": "check the arm carrying the camera: its joints and limits must turn the camera",
    "pan": "check the joint turning the camera (the head's pan joint) and its limits",
}


def torso(robot: ProjectedRobot) -> list[CheckResult]:
    """Torso down, then up: the arms rise with it; the camera heights match both ends."""
    desc, world = robot.description, robot.world
    joint = desc.torso_joint
    if joint is None:
        return []
    limits = world.bodies.joint_limits(robot.name, joint)
    bases = [arm.links[0] for key, arm in desc.arms.items() if key != desc.neck_arm and arm.links]
    heights = {}
    try:
        for end in (limits.lower, limits.upper):
            move_torso(robot, end)
            heights[end] = (
                [world.link_pose(robot.name, link).position[2] for link in bases],
                [world.link_pose(robot.name, c.frame).position[2] for c in desc.cameras],
            )
    except PlanFailure as failure:
        return [CheckResult("torso", False, str(failure), f"check torso_joint {joint!r}")]
    rise = [
        high - low
        for low, high in zip(*(heights[e][0] for e in (limits.lower, limits.upper)), strict=True)
    ]
    span = limits.upper - limits.lower
    results = []
    if rise and min(rise) < LIFT_SHARE * span:
        results.append(
            CheckResult(
                "torso",
                False,
                f"{joint} moves the arms' bases by {min(rise):.3f} m over its {span:.3f} m range",
                "name the vertical joint that lifts the arms as torso_joint",
            )
        )
    else:
        results.append(
            CheckResult("torso", True, f"{joint} moves over [{limits.lower}, {limits.upper}]")
        )
    return results + _camera_heights(robot, heights[limits.lower][1], heights[limits.upper][1])


def _camera_heights(
    robot: ProjectedRobot, at_lower: list[float], at_upper: list[float]
) -> list[CheckResult]:
    results = []
    for camera, low, high in zip(robot.description.cameras, at_lower, at_upper, strict=True):
        measured = (min(low, high), max(low, high))
        given = camera.height_range()
        if measured[1] - measured[0] < HEIGHT_TOLERANCE:  # the torso does not carry it
            ok = given[0] - HEIGHT_TOLERANCE <= measured[0] <= given[1] + HEIGHT_TOLERANCE
        else:
            ok = given[0] <= given[1] and all(
                abs(m - g) <= HEIGHT_TOLERANCE for m, g in zip(measured, given, strict=True)
            )
        detail = (
            f"given [{given[0]:.3f}, {given[1]:.3f}] m, "
            f"at the torso's limits [{measured[0]:.3f}, {measured[1]:.3f}] m"
        )
        fix = f"minimal_height={measured[0]:.3f}, maximal_height={measured[1]:.3f}"
        results.append(CheckResult(f"camera {camera.frame}: heights", ok, detail, fix))
    return results


def camera_forward(robot: ProjectedRobot) -> CheckResult:
    """With the neck parked, the camera's optical axis (z) looks ahead of the robot."""
    desc = robot.description
    camera = desc.cameras[0]
    name = f"camera {camera.frame}: looks ahead"
    if desc.neck_parking:
        robot.world.set_joint_states(robot.name, dict(desc.neck_parking))
    axes = (robot.base_pose().inverse() * robot.world.link_pose(robot.name, camera.frame)).matrix()
    forward = float(axes[0, 2])
    means = looking_means(desc)
    if forward < FORWARD and means is not None and means.kind == "arm":
        return _arm_camera_forward(name, axes[:3, 2], means.arm)
    if forward < FORWARD and _looks_down_ahead(axes[:3, 2]):
        down = math.degrees(math.asin(min(1.0, -float(axes[2, 2]))))
        return CheckResult(
            name, True, f"z looks down onto what lies ahead ({down:.0f} deg down, x share "
            f"{forward:.2f})",
        )  # fmt: skip
    if forward < FORWARD:
        seen = "backwards" if forward < -FORWARD else "sideways, up or down"
        return CheckResult(
            name,
            False,
            f"its z axis looks {seen} (x share {forward:.2f}) with the neck parked",
            "use the optical frame (z forward, x right, y down), or add one with a FrameSpec",
        )
    return CheckResult(name, True, f"z looks ahead (x share {forward:.2f})")


def _arm_camera_forward(name: str, axis: np.ndarray, arm: str | None) -> CheckResult:
    """An arm's camera looks where the arm points it (the look check turns it): parked,
    its optical ``axis`` (base frame) must only not look back at the robot or up, away
    from where the arm works (Baxter's wrist camera, parked over its table: 60 degrees
    down, its x share 0.24)."""
    forward, down = float(axis[0]), math.degrees(math.asin(max(-1.0, min(1.0, -float(axis[2])))))
    carried = f"its {arm} arm points it" if arm else "an arm points it"
    if forward >= 0.0 and down > 0.0:
        return CheckResult(
            name, True, f"{carried}; parked, z looks {down:.0f} deg down, not back (x share "
            f"{forward:.2f})",
        )  # fmt: skip
    seen = "backwards" if forward < 0.0 else "up"
    return CheckResult(
        name,
        False,
        f"{carried}, but parked its z axis looks {seen} (x share {forward:.2f}, {down:.0f} deg "
        "down)",
        f"park the {arm or 'carrying'} arm so its camera looks ahead and down, or use the "
        "camera's optical frame (z forward, x right, y down)",
    )


def _looks_down_ahead(axis: np.ndarray) -> bool:
    """Whether an optical ``axis`` (base frame) looks at least :data:`DOWN_ONTO` below the
    horizon, its horizontal part ahead (an x share of it of :data:`FORWARD` at least): a
    fixed camera over a workspace in front of the robot (Tracy's, 72 degrees down)."""
    across = math.hypot(float(axis[0]), float(axis[1]))
    return -float(axis[2]) >= math.sin(DOWN_ONTO) and float(axis[0]) >= FORWARD * across > 0.0


def look_and_detect(robot: ProjectedRobot) -> list[CheckResult]:
    """Look at a point ahead of the camera, then detect a mug put there.

    A camera turned by the arm carrying it or by a head that only pans looks at a point
    turned aside from its optical axis (``looking_means.py``); one nothing turns gets the
    mug on its optical axis.
    """
    world, desc = robot.world, robot.description
    camera = desc.cameras[0]
    eye = world.link_pose(robot.name, camera.frame)
    means = looking_means(desc)
    if means is None:
        target = eye.transform_point((0.0, 0.0, LOOK_AHEAD))
        hit = world.view.ray_cast(eye.position, target)
        if hit is not None and hit.obj.name == robot.name:  # onto its own table: the mug on it
            return [_detect(robot, hit.position, hit.distance)]
        return [_detect(robot, target, LOOK_AHEAD)]
    if means.kind in ("arm", "pan"):
        distance = _clear_ahead(robot, eye)
        target = _aside(eye, distance, LOOK_ASIDE)
    else:
        base = robot.base_pose()
        distance = max(LOOK_AHEAD, (eye.position[2] - LOOK_HEIGHT) / math.tan(LOOK_DOWN))
        ahead = base.transform_point((distance, 0.0, 0.0))
        shift = np.subtract(eye.position, base.position)
        target = (ahead[0] + shift[0], ahead[1] + shift[1], LOOK_HEIGHT)
    try:
        look_at(robot, target)
    except PlanFailure as failure:
        return [CheckResult("look", False, str(failure), LOOK_FIX[means.kind])]
    pose = world.link_pose(robot.name, camera.frame)
    wanted = np.subtract(target, pose.position)
    off = math.acos(min(1.0, float(pose.matrix()[:3, 2] @ wanted / np.linalg.norm(wanted))))
    look = CheckResult(
        "look",
        off <= LOOK_TOLERANCE,
        f"optical axis {math.degrees(off):.1f} deg off the target",
        "the camera frame must be optical (z forward) and turned by the pan-tilt or neck",
    )
    return [look, _detect(robot, target, distance)]


def _clear_ahead(robot: ProjectedRobot, eye: Pose) -> float:
    """How far [m] along the optical axis a turned camera looks and detects: :data:`LOOK_AHEAD`,
    or nearer where the axis meets something else first, the floor say (Baxter's wrist
    camera, parked 1.2 m over the floor, looks 60 degrees down): the mug stands there."""
    hit = robot.world.view.ray_cast(eye.position, eye.transform_point((0.0, 0.0, LOOK_AHEAD)))
    if hit is None or hit.obj.name == robot.name:
        return LOOK_AHEAD
    return hit.distance


def _aside(eye: Pose, distance: float, turn: float) -> tuple[float, float, float]:
    """The point ``distance`` [m] along the optical axis turned by ``turn`` [rad] about
    the vertical through the camera: what a look must turn to, at the height it sees."""
    ahead = np.subtract(eye.transform_point((0.0, 0.0, distance)), eye.position)
    c, s = math.cos(turn), math.sin(turn)
    turned = (c * ahead[0] - s * ahead[1], s * ahead[0] + c * ahead[1], ahead[2])
    x, y, z = (float(v) for v in np.add(eye.position, turned))
    return (x, y, z)


def _detect(
    robot: ProjectedRobot, target: tuple[float, float, float], distance: float
) -> CheckResult:
    """Put a mug at ``target`` [m, map] and detect it."""
    mug = robot.world.add_item("robot_check_mug", "mug", pose=target)
    try:
        seen = detect(robot, an.object(type="mug"))
        name = seen.get("name") if not isinstance(seen, list) else seen[0].get("name")
        return CheckResult("detect", True, f"saw {name} {distance:.2f} m ahead")
    except PlanFailure as failure:
        fix = "check the camera frame and its fields of view"
        return CheckResult("detect", False, str(failure), fix)
    finally:
        robot.world.remove(mug)
