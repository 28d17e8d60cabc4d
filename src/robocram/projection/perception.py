"""Perception in projection: the world objects the camera sees that fit a designator.

An object designator's ``type`` and ``name`` properties filter the world's objects (the
robot and floors are never perceived); the robot's camera must see at least 90 % of an
object (``World.view.visible``). The answer is a new object designator carrying the object's
name, type and pose in the robot's base frame, equated with the one asked for; with
``all_.objects(...)`` every visible match is returned, nearest first, as fresh designators
(they describe different things, so they are not equated with the question).
When nothing fits and the robot's own link hides an object that would have, the failure
(:class:`PerceptionBlockedByRobot`) names the link and suggests parking the arms.
"""

from __future__ import annotations

import math
from collections import Counter
from itertools import product

import numpy as np

from robocram.designators import ObjectDesignator, Quantifier
from robocram.designators.perceived_object import PerceivedObject
from robocram.execution import checkpoint
from robocram.execution.failures import PerceptionBlockedByRobot, PerceptionObjectNotFound
from robocram.projection.errors import ProjectionUsageError
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.view_blocker import blocking_fix
from robocram.tf import PoseStamped, Vector3
from robocram.world import Camera, WorldObject

FILTER_KEYS = ("type", "name")
BLOCK_SAMPLES = (0.2, 0.5, 0.8)  # share of an object's bounds per axis the rays aim at


def _matches(designator: ObjectDesignator, obj: WorldObject) -> bool:
    for key in FILTER_KEYS:
        wanted = designator.get(key)
        if wanted is not None and str(wanted) != getattr(obj, key):
            return False
    return True


def visible_matches(robot: ProjectedRobot, designator: ObjectDesignator) -> list[WorldObject]:
    """The objects fitting ``designator`` that the robot sees, nearest to the camera first."""
    world = robot.world
    camera = world.view.camera(robot.name).pose
    found = [
        o
        for o in world.objects()
        if o.name != robot.name and o.type != "floor" and _matches(designator, o)
    ]
    seen = []
    for obj in found:
        checkpoint()  # a stopped task ends here, between one object's rays and the next's
        if world.view.visible(robot.name, obj):
            seen.append(obj)
    return sorted(seen, key=lambda o: world.pose(o).distance_to(camera))


def _in_view(camera: Camera, point: list[float]) -> bool:
    x, y, z = camera.to_optical(np.array([point]))[0]
    th, tv = camera.tan_half
    return bool(z > camera.near and abs(x / z) <= th and abs(y / z) <= tv)


def _near(camera: Vector3, point: Vector3, near: float) -> Vector3:
    """The point ``near`` [m] from ``camera`` towards ``point``."""
    share = near / (math.dist(camera, point) or 1.0)
    x, y, z = (c + share * (p - c) for c, p in zip(camera, point, strict=True))
    return (x, y, z)


def own_link_blocking(
    robot: ProjectedRobot, designator: ObjectDesignator
) -> tuple[str, str] | None:
    """``(link, object)``: the robot's link most rays from its camera to a fitting object hit.

    Rays go from the camera's near plane (as the world's visibility rays do: the camera's
    own housing, Stretch's ``camera_link`` box, holds its optical frame) to 27 points
    inside each fitting object's bounds; None when no ray meets the robot before the object.
    """
    world = robot.world
    cam = world.view.camera(robot.name)
    camera = cam.pose.position
    hits: Counter[tuple[str, str]] = Counter()
    for obj in world.objects():
        if obj.name == robot.name or obj.type == "floor" or not _matches(designator, obj):
            continue
        low, high = world.aabb(obj)
        if not _in_view(cam, [(lo + hi) / 2 for lo, hi in zip(low, high, strict=True)]):
            continue  # out of the picture: the robot's body behind the camera is no blocker
        points: list[Vector3] = [
            (
                low[0] + sx * (high[0] - low[0]),
                low[1] + sy * (high[1] - low[1]),
                low[2] + sz * (high[2] - low[2]),
            )
            for sx, sy, sz in product(BLOCK_SAMPLES, repeat=3)
        ]
        starts = [_near(camera, point, cam.near) for point in points]
        for hit in world.view.ray_cast_batch(starts, points):
            if hit is not None and hit.obj.name == robot.name and hit.link is not None:
                hits[(hit.link, obj.name)] += 1
    return hits.most_common(1)[0][0] if hits else None


def hidden_by(
    robot: ProjectedRobot, designator: ObjectDesignator
) -> tuple[str, tuple[str, ...]] | None:
    """``(object, occluders)``: the first fitting object in view that movable objects hide,
    and those objects. The robot's own links are :func:`own_link_blocking`'s; an environment
    (a counter's edge) is no occluder to move. None when no such object is in view. Only
    asked when nothing fitting was seen."""
    world = robot.world
    cam = world.view.camera(robot.name)
    for obj in world.objects():
        if obj.name == robot.name or obj.type == "floor" or not _matches(designator, obj):
            continue
        low, high = world.aabb(obj)
        if not _in_view(cam, [(lo + hi) / 2 for lo, hi in zip(low, high, strict=True)]):
            continue
        names = world.view.visibility_from(cam, obj).occluders
        others = [world.object(n) for n in names if n not in (robot.name, obj.name)]
        movable = tuple(o.name for o in others if o.type != "environment")
        if movable:
            return obj.name, movable
    return None


def _listed(names: tuple[str, ...]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


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
        PerceptionBlockedByRobot: the robot's own link hides the object that fits.
        PerceptionObjectNotFound: no visible object fits the designator.
    """
    if not isinstance(designator, ObjectDesignator):
        raise ProjectionUsageError(
            f"detecting needs an object designator (an.object(type=...)), got {designator!r}"
        )
    seen = visible_matches(robot, designator)
    blocked = None if seen else own_link_blocking(robot, designator)
    if blocked is not None:
        link, target = blocked
        fix, parked = blocking_fix(robot, link)
        raise PerceptionBlockedByRobot(
            f"{robot.name} sees no object fitting {designator.description}: its own link "
            f"{link!r} blocks the view of {target!r}; {fix}",
            object_designator=designator,
            link=link,
            target=target,
            arm_parked=parked,
        )
    if not seen:
        hidden = hidden_by(robot, designator)
        text = f"{robot.name} sees no object fitting {designator.description}"
        if hidden is not None:
            name, occluders = hidden
            listed = _listed(occluders)
            text += f": {name} is hidden by {listed}; move {listed} or look from elsewhere"
        raise PerceptionObjectNotFound(
            text, object_designator=designator, occluded_by=hidden[1] if hidden else None
        )
    if designator.quantifier is Quantifier.ALL:
        return [perceive(robot, obj, None) for obj in seen]
    return perceive(robot, seen[0], designator)
