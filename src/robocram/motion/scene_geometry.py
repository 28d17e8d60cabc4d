"""The pinocchio geometry of a collision scene and the pairs it checks, built once.

Geometry objects: the robot's links (URDF collision shapes, meshes as convex hulls), what
it holds (on the carrier link's frame) and the static world (on the universe, i.e. the
robot's root link). Pairs: moving geometry against the static geometry it can reach
(:mod:`~robocram.motion.reach_bounds`), and the self-collision pairs
(:mod:`~robocram.motion.self_collision`); pairs the description's allowed contacts permit
are left out. What is left is tested in C++ through a broadphase, never pair by pair here.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.kinematics.robot_kinematics import RobotKinematics, pose_to_se3, robot_kinematics
from robocram.motion.allowed_contacts import AllowedContacts, Other
from robocram.motion.coal_shapes import coal_geometries
from robocram.motion.hand_contact import HandContact
from robocram.motion.reach_bounds import Sphere, Spheres, reach_sphere, shape_sphere
from robocram.motion.scene_snapshot import PlacedShape, SceneSnapshot
from robocram.motion.self_collision import (
    active_joints,
    adjacent_pairs,
    moving_group,
)
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")


@dataclass(frozen=True)
class Owner:
    """Who a geometry object belongs to: a robot link, a held object or a static one."""

    kind: str  # "robot" | "held" | "static"
    label: str  # the robot link, or the object label results use
    link: str  # the robot link it moves with ("" for static geometry)
    other: Other | None = None  # for held and static geometry


@dataclass
class SceneGeometry:
    """A scene's pinocchio models, the owner of every geometry object and pair labels."""

    kinematics: RobotKinematics
    geometry: pin.GeometryModel
    owners: list[Owner]
    q0: NDArray[np.float64]  # the full configuration at the snapshot
    pair_labels: list[tuple[str, str]]  # per collision pair: (robot link or held, other)
    skipped_static: int  # static shapes out of reach, left out
    moving: list[bool]  # per geometry object: whether a planned joint moves it
    _sides: tuple[pin.GeometryModel, pin.GeometryModel] | None = None

    def sides(self) -> tuple[pin.GeometryModel, pin.GeometryModel]:
        """Copies of the geometry with only the moving, and only the fixed, side enabled
        (same indices and pairs, so one callback serves both broadphase trees)."""
        if self._sides is None:
            moving, fixed = self.geometry.copy(), self.geometry.copy()
            for i, is_moving in enumerate(self.moving):
                moving.geometryObjects[i].disableCollision = not is_moving
                fixed.geometryObjects[i].disableCollision = is_moving
            self._sides = (moving, fixed)
        return self._sides

    def forget_sides(self) -> None:
        """Drop the side copies after the pairs changed."""
        self._sides = None


def build_geometry(snap: SceneSnapshot) -> SceneGeometry:
    """Geometry objects and candidate pairs of ``snap`` (snapshot contacts not yet dropped)."""
    kin = robot_kinematics(snap.description.model)
    q0 = kin.configuration(dict(snap.joint_values))
    data = kin.model.createData()
    pin.forwardKinematics(kin.model, data, q0)
    geometry = pin.GeometryModel()
    owners: list[Owner] = []
    _add_robot(kin, geometry, owners)
    _add_held(kin, snap, geometry, owners)
    active = active_joints(snap.description.model, snap.joints)
    group = moving_group(snap.description.model, active)
    spheres = [
        reach_sphere(kin, data, geometry.geometryObjects[i], active, snap.margin)
        if owners[i].link and group[owners[i].link]
        else None
        for i in range(len(owners))
    ]
    skipped = _add_static(snap, geometry, owners, spheres)
    rules = AllowedContacts.of(snap.description, snap.allowed_links)
    labels = _add_pairs(snap, geometry, owners, spheres, group, rules)
    moving = [bool(o.link and group[o.link]) for o in owners]
    return SceneGeometry(kin, geometry, owners, q0, labels, skipped, moving)


def _add_robot(kin: RobotKinematics, geometry: pin.GeometryModel, owners: list[Owner]) -> None:
    for link in kin.robot_model.links.values():
        frame_id = kin.frame_id(link.name)
        frame = kin.model.frames[frame_id]
        for i, collision in enumerate(link.collisions):
            shape = collision.geometry
            extents = shape.scale if shape.kind == "mesh" else shape.extents()
            placement = frame.placement * pose_to_se3(collision.origin)
            parts = coal_geometries(shape.kind, extents or (1.0, 1.0, 1.0), shape.filename)
            for k, part in enumerate(parts):
                name = f"{link.name}/{i}/{k}"
                geometry.addGeometryObject(
                    pin.GeometryObject(name, frame.parentJoint, frame_id, placement, part)
                )
                owners.append(Owner("robot", link.name, link.name))


def _add_held(
    kin: RobotKinematics, snap: SceneSnapshot, geometry: pin.GeometryModel, owners: list[Owner]
) -> None:
    for n, placed in enumerate(snap.held):
        carrier = placed.carrier or ""
        frame_id = kin.frame_id(carrier)
        frame = kin.model.frames[frame_id]
        placement = frame.placement * pose_to_se3(placed.frame_T_shape)
        other = Other(placed.label.split("/")[0], placed.type, placed.held_by)
        for k, part in enumerate(_parts(placed)):
            geometry.addGeometryObject(
                pin.GeometryObject(
                    f"held/{placed.label}/{n}/{k}", frame.parentJoint, frame_id, placement, part
                )
            )
            owners.append(Owner("held", other.name, carrier, other))


def _parts(placed: PlacedShape) -> tuple[object, ...]:
    shape = placed.shape
    return coal_geometries(shape.kind, shape.extents, shape.mesh)


def _add_static(
    snap: SceneSnapshot,
    geometry: pin.GeometryModel,
    owners: list[Owner],
    spheres: list[Sphere | None],
) -> int:
    """Add the static shapes some moving geometry can reach; return how many were not.

    ``spheres`` gets the bounding ball of each static geometry added.
    """
    moving = Spheres.of([s for s in spheres if s is not None])
    shapes = [
        (n, placed, placement, k, part)
        for n, placed in enumerate(snap.static)
        for placement in (pose_to_se3(placed.frame_T_shape),)
        for k, part in enumerate(_parts(placed))
    ]
    bounds = [shape_sphere(part, placement) for _, _, placement, _, part in shapes]
    reached = moving.meet_each(bounds)  # one comparison of all shapes with all balls
    skipped = 0
    for (n, placed, placement, k, part), bound, meets in zip(shapes, bounds, reached, strict=True):
        if not meets:
            skipped += 1
            continue
        geometry.addGeometryObject(
            pin.GeometryObject(f"static/{placed.label}/{n}/{k}", 0, 0, placement, part)
        )
        owners.append(
            Owner("static", placed.label, "", Other(placed.label.split("/")[0], placed.type))
        )
        spheres.append(bound)
    return skipped


def _add_pairs(
    snap: SceneSnapshot,
    geometry: pin.GeometryModel,
    owners: list[Owner],
    spheres: list[Sphere | None],
    group: dict[str, str],
    rules: AllowedContacts,
) -> list[tuple[str, str]]:
    """Add the pairs a check tests, per moving geometry ``i`` its partners ``j`` in
    ascending order; return their labels. Whether a pair is checked follows from who owns
    the two geometries (:func:`_checked`), so it is decided once per kind of owner on each
    side and spread over the geometries as masks (a kitchen scene has thousands of pairs)."""
    with_geometry = {o.link for o in owners if o.kind == "robot"}
    model = snap.description.model
    adjacent = adjacent_pairs(model, with_geometry) | set(snap.skipped_self)
    labels: list[tuple[str, str]] = []
    hand = snap.hand  # its links may touch what it acts on: not checked against it here
    near = _sphere_overlaps(spheres)
    n = len(owners)
    static = np.array([o.kind == "static" for o in owners], dtype=bool)
    moving = np.array([bool(o.kind != "static" and group[o.link]) for o in owners], dtype=bool)
    plain: dict[tuple[object, ...], int] = {}  # owner kinds as a partner: one per class
    plain_of = np.array(
        [plain.setdefault((o.kind, o.link, o.other), len(plain)) for o in owners], dtype=np.intp
    )
    labelled: dict[tuple[object, ...], int] = {}  # for a touching hand: statics by label
    labelled_of = np.array(
        [labelled.setdefault((o.kind, o.link, o.other, o.label), len(labelled)) for o in owners],
        dtype=np.intp,
    )
    firsts = {k: j for j, k in reversed(list(enumerate(plain_of.tolist())))}
    firsts_labelled = {k: j for j, k in reversed(list(enumerate(labelled_of.tolist())))}
    masks: dict[tuple[object, ...], np.ndarray] = {}  # per moving owner kind: checked partners
    index = np.arange(n)
    for i, a in enumerate(owners):
        if a.kind == "static" or not group[a.link]:
            continue  # pairs are made from the moving side
        touch = hand is not None and a.kind == "robot" and a.link in hand.links
        side = (a.kind, a.link, a.other, touch)
        checked = masks.get(side)
        if checked is None:
            checked = masks[side] = _checked_mask(
                a, owners, touch, hand, group, adjacent, rules,
                (plain_of, firsts), (labelled_of, firsts_labelled), static,
            )  # fmt: skip
        keep = checked & (index != i)
        keep &= ~((index < i) & moving)  # two moving geometries: the pair was made from j's side
        keep &= ~(static & ~near[i])
        for j in np.flatnonzero(keep).tolist():
            geometry.addCollisionPair(pin.CollisionPair(i, j))
            labels.append((a.label, owners[j].label))
    return labels


def _checked_mask(
    a: Owner,
    owners: list[Owner],
    touch: bool,
    hand: HandContact | None,
    group: dict[str, str],
    adjacent: set[frozenset[str]],
    rules: AllowedContacts,
    plain: tuple[np.ndarray, dict[int, int]],
    labelled: tuple[np.ndarray, dict[int, int]],
    static: np.ndarray,
) -> np.ndarray:
    """Per geometry ``j``: whether moving geometry ``a`` is checked against it
    (:func:`_checked`, and a touching hand not against what it acts on), decided once per
    class of partners (the first geometry of each class stands for it)."""
    classes, firsts = plain
    answers = np.array(
        [_checked(a, owners[firsts[k]], group, adjacent, rules) for k in range(len(firsts))],
        dtype=bool,
    )
    mask = answers[classes]
    if touch and hand is not None:
        label_classes, label_firsts = labelled
        covered = np.array(
            [hand.covers(a.link, owners[label_firsts[k]].label) for k in range(len(label_firsts))],
            dtype=bool,
        )
        mask &= ~(covered[label_classes] & static)
    return mask


def _sphere_overlaps(spheres: list[Sphere | None]) -> np.ndarray:
    """Whether the reach spheres of geometries i and j meet (True where either has none)."""
    n = len(spheres)
    centres = np.zeros((n, 3))
    radii = np.full(n, np.inf)
    for k, sphere in enumerate(spheres):
        if sphere is not None:
            centres[k] = sphere.centre
            radii[k] = sphere.radius
    gaps = np.linalg.norm(centres[:, None, :] - centres[None, :, :], axis=2)
    with np.errstate(invalid="ignore"):
        return ~(gaps > radii[:, None] + radii[None, :])


def _checked(
    a: Owner,
    b: Owner,
    group: dict[str, str],
    adjacent: set[frozenset[str]],
    rules: AllowedContacts,
) -> bool:
    """Whether moving geometry ``a`` is checked against ``b``."""
    if b.other is not None and b.kind == "static":
        if a.kind == "held":
            return not rules.allows_any_link(b.other)
        return not rules.allows(a.link, b.other)
    if group[a.link] == group[b.link]:
        return False  # they never move relative to each other
    if a.kind == "held" or b.kind == "held":
        held, robot = (a, b) if a.kind == "held" else (b, a)
        if robot.kind == "held" or held.other is None:
            return False
        return not rules.allows(robot.link, held.other)
    if frozenset((a.link, b.link)) in adjacent:
        return False
    return not (
        rules.allows(a.link, Other(b.link, "robot")) or rules.allows(b.link, Other(a.link, "robot"))
    )
