"""Perception in projection: the world objects the camera sees that fit a designator.

An object designator's ``type`` and ``name`` properties filter the world's objects (the
robot and floors are never perceived); the robot's camera must see at least 90 % of an
object (``World.visible``). The answer is a new object designator carrying the object's
name, type and pose in the robot's base frame, equated with the one asked for; with
``all_.objects(...)`` every visible match is returned, nearest first, as fresh designators
(they describe different things, so they are not equated with the question).
"""

from __future__ import annotations

from robocram.designators import ObjectDesignator, Quantifier
from robocram.designators.perceived_object import PerceivedObject
from robocram.execution.failures import PerceptionObjectNotFound
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import PoseStamped
from robocram.world import WorldObject

FILTER_KEYS = ("type", "name")


def _matches(designator: ObjectDesignator, obj: WorldObject) -> bool:
    for key in FILTER_KEYS:
        wanted = designator.get(key)
        if wanted is not None and str(wanted) != getattr(obj, key):
            return False
    return True


def visible_matches(robot: ProjectedRobot, designator: ObjectDesignator) -> list[WorldObject]:
    """The objects fitting ``designator`` that the robot sees, nearest to the camera first."""
    world = robot.world
    camera = world.camera(robot.name).pose
    found = [
        o
        for o in world.objects()
        if o.name != robot.name and o.type != "floor" and _matches(designator, o)
    ]
    seen = [o for o in found if world.visible(robot.name, o)]
    return sorted(seen, key=lambda o: world.pose(o).distance_to(camera))


def perceive(
    robot: ProjectedRobot, obj: WorldObject, asked: ObjectDesignator | None
) -> ObjectDesignator:
    """A designator for ``obj`` with its pose in the base frame, equated with ``asked``.

    With ``asked`` None the designator stands alone (one of several answers to ``all``).
    """
    pose = PoseStamped.from_pose(robot.base_frame, robot.in_base(robot.world.pose(obj)))
    data = PerceivedObject(obj.name, obj.type, pose)
    if asked is None:
        return ObjectDesignator(type=obj.type, name=obj.name, pose=pose, data=data)
    return asked.make_effective(data, type=obj.type, name=obj.name, pose=pose)


def detect(
    robot: ProjectedRobot, designator: ObjectDesignator
) -> ObjectDesignator | list[ObjectDesignator]:
    """Perceive the object(s) ``designator`` describes.

    Raises:
        PerceptionObjectNotFound: no visible object fits the designator.
    """
    if not isinstance(designator, ObjectDesignator):
        raise TypeError(
            f"detecting needs an object designator (an.object(type=...)), got {designator!r}"
        )
    seen = visible_matches(robot, designator)
    if not seen:
        raise PerceptionObjectNotFound(
            f"{robot.name} sees no object fitting {designator.description}",
            object_designator=designator,
        )
    if designator.quantifier is Quantifier.ALL:
        return [perceive(robot, obj, None) for obj in seen]
    return perceive(robot, seen[0], designator)
