"""CRAM's collision modes for arm motions, as IK collision checks on the projected world.

``avoid_all``: no link of the robot may touch anything (the floor and objects the robot
holds excepted). ``allow_hand``: the moving arm's hand and gripper links may touch (for
grasping). ``allow_all``: no check. A candidate configuration is tried on the world and the
joints are put back before the check returns, so IK never leaves the robot moved.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from robocram.kinematics import split_base_motion
from robocram.projection.errors import ProjectionError
from robocram.projection.navigation import base_moved_by
from robocram.projection.projected_robot import ProjectedRobot

COLLISION_MODES = ("avoid_all", "allow_hand", "allow_all")
CONTACT_DISTANCE = 0.0  # [m] closer than this is a collision (touching counts)


def collision_check(
    robot: ProjectedRobot, arm: str, mode: str
) -> Callable[[Mapping[str, float]], list[tuple[str, str]]] | None:
    """An IK ``collision_check`` for ``mode`` (None for ``allow_all``).

    It returns the colliding ``(robot link, object)`` pairs, so a failure can name them.
    """
    mode = mode.replace("-", "_")
    if mode not in COLLISION_MODES:
        raise ProjectionError(
            f"unknown collision mode {mode!r} for the {arm} arm; use one of {COLLISION_MODES}"
        )
    if mode == "allow_all":
        return None
    spec = robot.arm(arm)
    allowed = set(spec.hand_links) | set(spec.gripper_links) if mode == "allow_hand" else set()
    if mode == "allow_hand":
        allowed |= {spec.end_effector_link, spec.tool_frame}

    def collides(candidate: Mapping[str, float]) -> list[tuple[str, str]]:
        joints, motion = split_base_motion(candidate)  # IK that moves the base too
        with base_moved_by(robot, motion):
            return colliding_pairs(robot, joints, allowed)

    return collides


def colliding_pairs(
    robot: ProjectedRobot, joints: Mapping[str, float], allowed_links: set[str]
) -> list[tuple[str, str]]:
    """``(robot link, object)`` pairs in contact at ``joints``, ``allowed_links`` excepted.

    The object is named by itself, or as ``object/link`` when it has several links.
    """
    world = robot.world
    model = robot.description.model
    before = {
        joint: value
        for joint, value in world.joint_states(robot.name).items()
        if model.joints[joint].mimic is None  # followers come back with their masters
    }
    world.set_joint_states(robot.name, dict(joints))
    try:
        held = set(world.attachments(robot.name))
        ignore = [o for o in world.objects() if o.name in held or o.type == "floor"]
        hits: dict[tuple[str, str], None] = {}
        for link, obj, other_link in world.link_pairs_in_contact(
            robot.name, ignore, CONTACT_DISTANCE
        ):
            if link not in allowed_links:
                several = len(world.link_names(obj)) > 1
                hits[(link, f"{obj.name}/{other_link}" if several else obj.name)] = None
        return list(hits)
    finally:
        world.set_joint_states(robot.name, before)
