"""What a coal clearance checker is made of beyond the robot's pose, kept per world.

A checker tests the parts its judge asks about (its moving links but the allowed ones,
and held objects) against the obstacle pieces they can come near
(:mod:`~robocram.motion.clearance_pairs`). Making those pairs costs more than a motion's
checks, so :class:`SetupCache` (kept with the world, ``World.derived``) keeps the setups
of the last checkers, which the motions at one stand share; and, for the setups a new
stand or a grasp needs, what outlives them: the rules' answers per (labels, objects) and
a held object's parts per grip.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import partial
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.kinematics.robot_kinematics import pose_to_se3
from robocram.motion.allowed_contacts import Other
from robocram.motion.bullet_scene import CLEARANCE_REACH, BulletScene
from robocram.motion.clearance_pairs import ClearancePairs, PairRules, PartArrays, ReachBalls
from robocram.motion.coal_shapes import coal_geometries
from robocram.motion.joint_trajectory import FloatArray
from robocram.motion.obstacle_shapes import DRIFT, StackedShapes, obstacle_cache
from robocram.motion.robot_geometry import Part, RobotGeometry, part
from robocram.robots.lazy_library import LazyLibrary
from robocram.tf import Pose
from robocram.world import Derived, World, WorldObject

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

KEPT_SETUPS = 8  # checker setups kept per world (a stand's motions use a few)
KEPT_ANSWERS = 64  # rule answer tables kept per world (one per judge, held set, objects)
KEPT_PARTS = 8  # part arrays kept per world (one per asked links and held parts)
GRIP_DIGITS = 9  # a held object's parts are reused while its grip is the same to 1e-9


@dataclass(frozen=True)
class Setup:
    """What a checker reads per check: the joints whose placements it needs and its
    pairs (they hold the focus of the checks made so far)."""

    joints: list[int]
    pairs: ClearancePairs
    obstacles: StackedShapes  # kept so that its id in the key is never reused


@dataclass
class SetupCache:
    """The setups of one world's last checkers, and what outlives them."""

    world: World
    _kept: Derived[tuple[object, ...], Setup] = field(
        default_factory=lambda: Derived(size=KEPT_SETUPS)
    )
    _answers: Derived[tuple[object, ...], NDArray[np.bool_]] = field(
        default_factory=lambda: Derived(size=KEPT_ANSWERS)
    )
    _held: dict[tuple[str, str, str], tuple[WorldObject, tuple[float, ...], list[Part]]] = field(
        default_factory=dict
    )
    # per the ids of the part groups (the links' kept tuple, held objects' kept lists):
    # the groups (held, so the ids are not reused while kept) and their arrays
    _arrays: Derived[tuple[int, ...], tuple[tuple[Sequence[Part], ...], PartArrays]] = field(
        default_factory=lambda: Derived(size=KEPT_PARTS)
    )
    # per (rules, object name, type): whether a "*" rule lets every link touch it
    _anywhere: dict[tuple[tuple[tuple[str, str], ...], str, str], bool] = field(
        default_factory=dict
    )

    def setup(
        self,
        judge: BulletScene,
        geometry: RobotGeometry,
        data: pin.Data,
        base: pin.SE3,
        margin: float,
    ) -> Setup:
        """The setup of a checker of ``judge`` with the robot's base at ``base`` and its
        joints as ``data`` is posed: a kept one if everything it depends on is as it was."""
        obstacles = self._obstacles(judge)
        key = (id(obstacles), margin, *_setup_key(judge, geometry, data, base))
        # a kept setup holds its obstacles, so their id in its key is not reused
        build = partial(self._made, judge, geometry, data, base, obstacles, margin)
        return self._kept.get(key, build)

    def _obstacles(self, judge: BulletScene) -> StackedShapes:
        """The shapes of every object the judge checks against: all but the robot, what
        it holds and what any link may touch (the floor, as ``judge.anywhere``; the
        answers are kept per rules and object)."""
        world = self.world
        skip = {judge.robot, *world.bodies.attachments(judge.robot)}
        rules = judge.rules
        anywhere = self._anywhere
        cache = obstacle_cache(world)
        shapes = []
        for obj in world.objects():
            if obj.name in skip:
                continue
            key = (rules.rules, obj.name, obj.type)
            free = anywhere.get(key)
            if free is None:
                free = anywhere[key] = rules.allows_any_link(Other(obj.name, obj.type))
            if not free:
                shapes.append(cache.shapes(world, obj))
        return cache.stacked(shapes)

    def _made(
        self,
        judge: BulletScene,
        geometry: RobotGeometry,
        data: pin.Data,
        base: pin.SE3,
        obstacles: StackedShapes,
        margin: float,
    ) -> Setup:
        arrays = self._parts(judge, geometry)
        parts = arrays.parts
        carriers = {geometry.frame(link)[0] for link in judge.moving_links}
        joints = sorted({p.joint for p in parts} | carriers)
        rows = {j: k for k, j in enumerate(joints)}
        balls = _reach_balls(geometry, judge.joints, parts, data, base)
        labels = tuple(dict.fromkeys(p.label for p in parts))
        checked = self._checked(judge, labels, obstacles)
        within = CLEARANCE_REACH + margin + DRIFT + judge.distance
        pairs = ClearancePairs.of(
            arrays, rows, balls, obstacles, checked, judge.allowed_pairs, within
        )
        return Setup(joints, pairs, obstacles)

    def _checked(
        self, judge: BulletScene, labels: tuple[str, ...], obstacles: StackedShapes
    ) -> NDArray[np.bool_]:
        """``[label, object]``: whether the judge's rules check them (asked once per
        judge's rules, held objects, labels and objects)."""
        held = frozenset(self.world.bodies.attachments(judge.robot))
        objects = tuple((s.obj.name, s.obj.type) for s in obstacles.shapes)
        key = (judge.robot, judge.allowed_links, held, labels, objects)
        rules = partial(PairRules, judge.rules, held)
        return self._answers.get(key, lambda: rules().matrix(labels, obstacles.shapes))

    def _parts(self, judge: BulletScene, geometry: RobotGeometry) -> PartArrays:
        """The parts the judge asks about: its moving links but the allowed ones (named
        as PyBullet names their link), and every held object (named by the object); kept
        while the same groups of parts come again."""
        world = self.world
        handle = world.robot(judge.robot)
        names = handle.index_names()
        asked = {
            handle.link_index[link]
            for link in judge.moving_links
            if link not in judge.allowed_links
        } & handle.colliders
        labels = tuple(
            (link, names[index])
            for link in geometry.parts
            if (index := handle.link_index.get(link, -2)) in asked
        )
        groups: list[Sequence[Part]] = [geometry.named_parts(labels)]
        for obj, link in world.bodies.attachments(handle).items():
            groups.append(self.held_parts(geometry, handle, obj, link))
        key = tuple(id(group) for group in groups)

        def made() -> tuple[tuple[Sequence[Part], ...], PartArrays]:
            return tuple(groups), PartArrays.of([p for group in groups for p in group])

        return self._arrays.get(key, made)[1]  # the groups kept: their ids are not reused

    def held_parts(
        self, geometry: RobotGeometry, robot: WorldObject, name: str, link: str
    ) -> list[Part]:
        """The parts of ``name`` held by ``link`` of ``robot``: kept while it is the same
        object held the same way (a grip is kept from grasp to release)."""
        world = self.world
        obj = world.object(name)
        attachment = world.bodies.attached_to(obj)
        grip = _pose_key(attachment.link_T_obj) if attachment is not None else None
        kept = self._held.get((robot.name, name, link))
        if grip is not None and kept is not None and kept[0] is obj and kept[1] == grip:
            return kept[2]
        joint, frame = geometry.frame(link)
        link_T_map = world.link_pose(robot, link).inverse()
        parts = []
        for shape in world.contacts.collision_shapes(obj):
            placement = pin.SE3(frame) * pose_to_se3(link_T_map * shape.pose)
            for piece in coal_geometries(shape.kind, shape.extents, shape.mesh):
                parts.append(part(name, joint, placement, piece))
        if grip is not None:
            self._held[(robot.name, name, link)] = (obj, grip, parts)
        return parts


def _setup_key(
    judge: BulletScene, geometry: RobotGeometry, data: pin.Data, base: pin.SE3
) -> tuple[object, ...]:
    """What a setup depends on beyond the obstacles: the judge's rules, what the robot
    holds and how, and where the anchors of the parts' reach balls are."""
    world = judge.world
    kin = geometry.kinematics
    held = []
    carriers = [kin.joint(j).pin_id for j in judge.joints]
    for obj, link in sorted(world.bodies.attachments(judge.robot).items()):
        attachment = world.bodies.attached_to(obj)
        grip = _pose_key(attachment.link_T_obj) if attachment is not None else None
        held.append((obj, link, grip))
        carriers.append(geometry.frame(link)[0])
    anchors = sorted({geometry.anchor(j, judge.joints)[0] for j in carriers})
    places = tuple(tuple((base * data.oMi[a]).translation.tolist()) for a in anchors)
    return (
        judge.robot, judge.joints, judge.allowed_links, judge.allowed_pairs, judge.distance,
        tuple(held), places,
    )  # fmt: skip


def _pose_key(pose: Pose) -> tuple[float, ...]:
    """``pose`` rounded to :data:`GRIP_DIGITS`, its quaternion's sign made unique (a grip
    read again after a base move differs by float noise, or is the same rotation as -q)."""
    values = np.array((*pose.position, *pose.orientation), dtype=float)
    if next(v for v in pose.orientation if abs(v) > 1e-6) < 0.0:
        values[3:] = -values[3:]
    return tuple(np.round(values, GRIP_DIGITS).tolist())


def _reach_balls(
    geometry: RobotGeometry,
    planned: Sequence[str],
    parts: Sequence[Part],
    data: pin.Data,
    base: pin.SE3,
) -> ReachBalls:
    """Per part: a ball (map) it stays in for any values of the planned joints, about
    the topmost planned joint above it (its anchor: parts share a few)."""
    anchors: dict[int, int] = {}
    centres: list[FloatArray] = []
    owners: list[int] = []
    radii: list[float] = []
    chains: dict[int, tuple[int, float]] = {}  # per joint: its anchor (parts share joints)
    for p in parts:
        chain = chains.get(p.joint)
        if chain is None:
            chain = chains[p.joint] = geometry.anchor(p.joint, planned)
        anchor, reach = chain
        if anchor not in anchors:
            anchors[anchor] = len(centres)
            centres.append(np.asarray((base * data.oMi[anchor]).translation, dtype=float))
        owners.append(anchors[anchor])
        radii.append(reach + p.extent)
    return ReachBalls(
        np.array(centres, dtype=float).reshape(-1, 3),
        np.array(owners, dtype=np.intp),
        np.array(radii, dtype=float),
    )
