"""CRAM's collision modes for arm motions, and an IK collision check on a world for them.

``avoid_all``: no link of the robot may touch anything. ``allow_hand``: the moving arm's
hand and gripper links may touch (for grasping). ``allow_all``: no check. Projection and
the ROS layer (with a world) read the modes the same way from here.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from robocram.kinematics import split_base_motion
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.configuration_checker import LinkPair
from robocram.motion.errors import MotionError
from robocram.motion.hand_contact import HandContact
from robocram.robots import ArmDescription
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle

COLLISION_MODES = ("avoid_all", "allow_hand", "allow_all")
IKCollisionCheck = Callable[[Mapping[str, float]], list[LinkPair]]


def collision_mode(mode: str) -> str:
    """``mode`` with dashes as underscores; a MotionError naming the modes if unknown."""
    normal = mode.replace("-", "_")
    if normal not in COLLISION_MODES:
        raise MotionError(f"unknown collision mode {mode!r}; use one of {COLLISION_MODES}")
    return normal


def hand_links(spec: ArmDescription) -> set[str]:
    """The links of ``spec``'s hand: hand, gripper, end effector and tool frame."""
    return (
        set(spec.hand_links) | set(spec.gripper_links) | {spec.end_effector_link, spec.tool_frame}
    )


def allowed_links(spec: ArmDescription, mode: str) -> set[str]:
    """The links that may touch things in ``mode``: the hand's for ``allow_hand``."""
    return hand_links(spec) if collision_mode(mode) == "allow_hand" else set()


def hand_bound(spec: ArmDescription, mode: str, touching: str | None) -> HandContact | None:
    """The contact ``allow_hand`` lets ``spec``'s hand make: ``touching`` (an object or
    ``object/link``; None or ``"none"``: any object), within the bound; None in the other
    modes. Projection and the ROS planner both bound the hand by it."""
    if collision_mode(mode) != "allow_hand":
        return None
    named = None if touching in (None, "none") else touching
    return HandContact.of(hand_links(spec), named)


def ik_collision_check(
    robot: RobotHandle, spec: ArmDescription, joints: tuple[str, ...], mode: str
) -> IKCollisionCheck | None:
    """An IK ``collision_check`` on the robot's world for ``joints`` in ``mode`` (None: allow_all).

    It returns the colliding ``(robot link, other)`` pairs, so a failure can name them;
    contacts the robot has now (a held object on its table) stay allowed, as in planning.
    """
    world = robot.world
    if collision_mode(mode) == "allow_all":
        return None
    allowed = allowed_links(spec, mode)
    scene = BulletScene(robot, joints, allowed)
    now = world.joint_states(robot.name)
    touching = scene.colliding([now[j] for j in joints])
    if touching:
        scene = BulletScene(robot, joints, allowed, allowed_pairs=touching)

    def colliding(candidate: Mapping[str, float]) -> list[LinkPair]:
        values, motion = split_base_motion(candidate)  # IK that moves the base too
        arm = {j: values[j] for j in joints if j in values}
        if motion is None:
            return scene.colliding_at(arm)
        start = world.pose(robot.name)
        moved = start * motion.pose()
        yaw = quat.to_euler(moved.orientation)[2]
        where = (moved.position[0], moved.position[1], start.position[2])
        world.set_pose(robot.name, Pose(where, quat.from_euler(0.0, 0.0, yaw)))
        try:
            return scene.colliding_at(arm)
        finally:
            world.set_pose(robot.name, start)

    return colliding
