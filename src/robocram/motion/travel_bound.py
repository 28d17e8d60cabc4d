"""How densely a joint-space segment must be checked: a bound on how far any point moves.

"At most 1 cm of travel of any link and 0.02 rad of any joint between checks" needs the
largest distance any point of the moving links (and what they hold) can travel when the
joints change by ``dq``. For a revolute joint that is its change times the largest distance
from the joint's origin to a point below it; that distance is bounded, whatever the other
joints do, by the lengths of the rigid links between (joint origin to joint origin, fixed)
plus the radius of the far link's geometry about its own frame. A prismatic joint moves
every point below it by its change. The sum over the joints bounds the travel, so checks
``resolution`` apart never skip more than ``resolution`` of any link's path. The sum
cannot see joints undoing each other (a hand's 2 cm step turns the elbow and the wrist
opposite ways: 0.13 m by the sum); a walk posed at a segment's start bounds it from the
levers there too (:func:`~robocram.motion.segment_check.start_travel`, ~3.5x tighter).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import partial

import numpy as np

from robocram.logic.lru import LRUCache
from robocram.motion.errors import MotionError
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.mimic_family import mimic_family
from robocram.robots import RobotModel
from robocram.world import Derived, RobotHandle, Versions, World

MAX_LINK_TRAVEL = 0.01  # [m] between two checked configurations
MAX_JOINT_STEP = 0.02  # [rad | m] of any joint between two checked configurations
KEPT_BOUNDS = 32  # bounds a world keeps (robots, joint sets, what they hold)


@dataclass(frozen=True)
class TravelBound:
    """Per joint: metres any point below it moves per unit change of the joint."""

    joints: tuple[str, ...]
    lever: FloatArray  # [m/rad] (1 for prismatic joints)
    max_link_travel: float = MAX_LINK_TRAVEL
    max_joint_step: float = MAX_JOINT_STEP
    link_lever: dict[str, FloatArray] = field(default_factory=dict)  # per moving link
    carriers: dict[str, str] = field(default_factory=dict)  # held object -> its link
    mimicked: bool = False  # a joint has mimic followers (local levers do not see them)

    def link_travel(self, link: str, qa: FloatArray, qb: FloatArray) -> float:
        """The most [m] a point of ``link`` (or of a held object) travels from qa to qb."""
        lever = self.link_lever.get(self.carriers.get(link, link), self.lever)
        dq = np.abs(np.asarray(qb, dtype=float) - np.asarray(qa, dtype=float))
        return float(lever @ dq)

    def travel(self, qa: FloatArray, qb: FloatArray) -> float:
        """The most [m] any point of the moving links can travel from ``qa`` to ``qb``."""
        dq = np.abs(np.asarray(qb, dtype=float) - np.asarray(qa, dtype=float))
        return float(self.lever @ dq)

    def steps(self, qa: FloatArray, qb: FloatArray) -> int:
        """Segments between checks on the straight line ``qa`` -> ``qb`` (at least 1)."""
        dq = np.abs(np.asarray(qb, dtype=float) - np.asarray(qa, dtype=float))
        travel = float(self.lever @ dq)
        step = float(dq.max()) if dq.size else 0.0
        return max(
            1, math.ceil(travel / self.max_link_travel), math.ceil(step / self.max_joint_step)
        )

    @classmethod
    def of(
        cls,
        robot: RobotHandle,
        joints: Sequence[str],
        max_link_travel: float = MAX_LINK_TRAVEL,
        max_joint_step: float = MAX_JOINT_STEP,
        held: bool = True,
    ) -> TravelBound:
        """The bound for ``joints`` of ``robot`` as it stands (held objects included
        unless ``held`` is False: the robot's own links alone)."""
        world = robot.world
        if max_link_travel <= 0.0 or max_joint_step <= 0.0:
            raise MotionError(
                f"check resolution must be positive, got {max_link_travel} m and "
                f"{max_joint_step} rad"
            )
        radius = link_radii(robot) if held else world.contacts.link_radii(robot.name)
        carriers = dict(world.bodies.attachments(robot.name)) if held else {}
        key = (
            robot.name, tuple(joints), max_link_travel, max_joint_step,
            tuple(sorted(carriers.items())),
            tuple((link, radius.get(link)) for link in sorted(set(carriers.values()))),
        )  # fmt: skip
        made = partial(_made_once, robot, key[1], radius, carriers, max_link_travel, max_joint_step)
        return world.derived(_kept_bounds).get(key, made, world.versions)


def _made_once(
    robot: RobotHandle,
    joints: tuple[str, ...],
    radius: dict[str, float],
    carriers: dict[str, str],
    max_link_travel: float,
    max_joint_step: float,
) -> TravelBound:
    """:func:`_made`, or the bound made from the same inputs in any world: kept with the
    model (a new scene's robot asks again for bounds that follow from its model and the
    same radii)."""
    key = (joints, tuple(radius.items()), tuple(carriers.items()), max_link_travel, max_joint_step)
    kept = robot.description.model.derived(_bounds_of_model)
    found = kept.get(key)
    if found is None:
        found = _made(robot, joints, radius, carriers, max_link_travel, max_joint_step)
        kept.put(key, found)
    return found


def _bounds_of_model(model: RobotModel) -> LRUCache[tuple[object, ...], TravelBound]:
    """The bounds a model keeps by all they are made from (bounds are never changed)."""
    return LRUCache(KEPT_BOUNDS)


def _made(
    robot: RobotHandle,
    joints: tuple[str, ...],
    radius: dict[str, float],
    carriers: dict[str, str],
    max_link_travel: float,
    max_joint_step: float,
) -> TravelBound:
    """:meth:`TravelBound.of` from the links' radii and what the robot holds."""
    model = robot.description.model
    children = model.derived(_children)
    lever = []
    per_link: dict[str, FloatArray] = {}
    mimicked = False
    for i, name in enumerate(joints):
        joint = model.joints.get(name)
        if joint is None or not joint.movable:
            raise MotionError(f"{name!r} is not a movable joint of {robot.name}")
        reach = _family_reaches(model, name, children, radius)
        mimicked = mimicked or len(mimic_family(model, name)) > 1
        for link, value in reach.items():
            row = per_link.get(link)
            if row is None:
                row = per_link[link] = np.zeros(len(joints))
            row[i] = value
        lever.append(max(reach.values(), default=0.0))
    return TravelBound(
        joints, np.array(lever), max_link_travel, max_joint_step, per_link, carriers, mimicked
    )


def _kept_bounds(world: World) -> Derived[tuple[object, ...], TravelBound]:
    """Bounds kept with the world while the robot's body is the same: they follow from
    its model, its links' radii (read once per body) and what it holds at which radius
    (in the key); every checked motion asks for one."""
    return Derived(_robot_created, size=KEPT_BOUNDS)


def _robot_created(versions: Versions, key: tuple[object, ...]) -> int:
    return versions.created(str(key[0]))


def _family_reaches(
    model: RobotModel,
    name: str,
    children: dict[str, list[tuple[str, float]]],
    radius: dict[str, float],
) -> dict[str, float]:
    """Per link that joint ``name`` moves, itself or through the joints mimicking it: the
    most [m] a point of it moves per unit change of ``name``. A link below a follower
    moves by the follower's turn (``multiplier`` times ``name``'s) too: the sum bounds
    both (a finger tip turns with its finger and on its own joint)."""
    reach: dict[str, float] = {}
    for member, multiplier, _ in mimic_family(model, name):
        joint = model.joints[member]
        scale = abs(multiplier)
        for link, value in _reaches(joint.child, 0.0, children, radius).items():
            moved = scale * (1.0 if joint.type == "prismatic" else value)
            reach[link] = reach.get(link, 0.0) + moved
    return reach


def _children(model: RobotModel) -> dict[str, list[tuple[str, float]]]:
    """Per link: its child links with the length [m] of the joint offset to each. Kept
    with the model (``RobotModel.derived``): every checked motion asks."""
    children: dict[str, list[tuple[str, float]]] = {}
    for each in model.joints.values():
        offset = float(np.linalg.norm(each.origin.position))
        children.setdefault(each.parent, []).append((each.child, offset))
    return children


def _reaches(
    link: str,
    so_far: float,
    children: dict[str, list[tuple[str, float]]],
    radius: dict[str, float],
) -> dict[str, float]:
    """Per link at or below ``link``: the largest distance from the joint above ``link``
    to a point of it (the rigid lengths between, plus its radius)."""
    found = {link: so_far + radius.get(link, 0.0)}
    for child, offset in children.get(link, ()):
        found.update(_reaches(child, so_far + offset, children, radius))
    return found


def link_radii(robot: RobotHandle) -> dict[str, float]:
    """Per link: a radius about its frame holding its shapes (and what it holds now)."""
    world = robot.world
    radii = world.contacts.link_radii(robot.name)
    for obj, link in world.bodies.attachments(robot.name).items():
        origin = np.array(world.link_pose(robot.name, link).position)
        radii[link] = max(radii.get(link, 0.0), _corner_distance(origin, world.aabb(obj)))
    return radii


def _corner_distance(origin: FloatArray, box: tuple[Sequence[float], Sequence[float]]) -> float:
    low, high = np.asarray(box[0], dtype=float), np.asarray(box[1], dtype=float)
    far = np.maximum(np.abs(low - origin), np.abs(high - origin))
    return float(np.linalg.norm(far))
