"""A suction hand in projection: it holds what its tool frame touches, and lets go.

A hand described by ``GripperDescription.suction()`` has no finger to move: opening only
releases what it holds, closing moves nothing, and gripping attaches the movable object
the hand touches (within :data:`SEAL`), the one touched nearest the tool frame (the grasp
put the tool frame on its surface; PyBullet reports one point of a flat contact, maybe
at its edge, so the touch is not required at the tool frame's origin). Touching
nothing, gripping fails with ``GripperClosedCompletely`` as a gripper closing on nothing
does. A handle is held on its front face (:func:`on_the_face`), not round its bar.
"""

from __future__ import annotations

import itertools
import math

from robocram.execution.failures import GripperClosedCompletely
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat
from robocram.world import WorldObject

SEAL = HAND_CONTACT_DEPTH  # [m] the hand this near an object (or this deep in it) holds it
NEAR = 0.1  # [m] objects whose box comes this near the tool frame are tried


def _near(robot: ProjectedRobot, tool: Vector3, held: set[str]) -> list[WorldObject]:
    """Movable objects, not held, whose box comes within :data:`NEAR` of ``tool``."""
    world = robot.world
    found = []
    for obj in world.objects():
        if obj.name == robot.name or obj.is_static or obj.name in held:
            continue
        low, high = world.aabb(obj)
        if all(low[k] - NEAR <= tool[k] <= high[k] + NEAR for k in range(3)):
            found.append(obj)
    return found


def touched(robot: ProjectedRobot, arm: str) -> WorldObject | None:
    """The movable object ``arm``'s hand touches nearest its tool frame; None if none."""
    spec = robot.arm(arm)
    world = robot.world
    links = {*spec.gripper_links, *spec.hand_links, spec.end_effector_link}
    tool = world.link_pose(robot.name, spec.tool_frame).position
    best: tuple[float, WorldObject] | None = None
    for obj in _near(robot, tool, set(world.bodies.attachments(robot.name))):
        for point in world.contacts.contact_points(robot.name, obj, distance=SEAL):
            away = math.dist(point.position_on_b, tool)
            touches = point.link_a in links and point.distance <= SEAL
            if touches and (best is None or away < best[0]):
                best = (away, obj)
    return None if best is None else best[1]


def suction_grip(robot: ProjectedRobot, arm: str) -> str:
    """Attach the object ``arm``'s suction hand touches at its tool frame; its name.

    Raises:
        GripperClosedCompletely: the hand touches no movable object at its tool frame.
    """
    obj = touched(robot, arm)
    spec = robot.arm(arm)
    if obj is None:
        raise GripperClosedCompletely(
            f"{robot.name}'s {arm} suction hand touches no movable object at its tool frame "
            f"{spec.tool_frame!r} (within {SEAL * 1000:.0f} mm): bring the tool frame onto "
            "the object's surface",
            gripper=arm,
            position=0.0,
        )
    robot.world.attach(obj, robot.name, spec.end_effector_link)
    return obj.name


def on_the_face(robot: ProjectedRobot, part: str, handle: str, pull: Pose) -> Pose:
    """``pull`` (the frame a hand holds ``handle`` of ``part`` in, x out of the front)
    moved out to the handle's front face: a suction hand holds the face it touches, where
    fingers close round the bar (:mod:`~robocram.projection.articulation`)."""
    world = robot.world
    frame = world.link_pose(part, handle) * pull
    low, high = world.contacts.link_aabb(part, handle)
    out = quat.rotate(frame.orientation, (1.0, 0.0, 0.0))
    corners = itertools.product(*zip(low, high, strict=True))
    front = max(
        sum((c - o) * a for c, o, a in zip(corner, frame.position, out, strict=True))
        for corner in corners
    )
    return pull * Pose((max(front, 0.0), 0.0, 0.0))
