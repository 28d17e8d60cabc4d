"""The projection world: a PyBullet scene of objects and robots, and reasoning over it.

Each :class:`World` is its own headless physics client (a GUI window on request); there is
no global "current world". Close a world (or use it as a context manager) when done.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterable, Iterator, Sequence
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Literal, TypeVar, cast

import numpy as np
from numpy.typing import NDArray

from robocram.robots import RobotDescription, install_description, load_description
from robocram.tf import Pose, PoseLike, Vector3
from robocram.world import contacts, link_contacts, spatial_relations, visibility
from robocram.world.body_spec import GREY, BodySpec, MeshSpec, Rgba, ShapeSpec, UrdfSpec
from robocram.world.camera import Camera
from robocram.world.catalogue import catalogue_item
from robocram.world.collision_shapes import CollisionShape, collision_shapes
from robocram.world.contact_point import ContactPoint
from robocram.world.derived import Derived
from robocram.world.errors import NoCameraError, WorldValueError
from robocram.world.obstacle_boxes import KeptObstacleBoxes, ObstacleBoxes
from robocram.world.png import write_png
from robocram.world.pybullet_backend import pybullet
from robocram.world.ray_hit import RayHit, cast_rays
from robocram.world.robot_urdf import robot_body_spec
from robocram.world.versions import Versions
from robocram.world.visibility import Visibility
from robocram.world.world_core import ORIGIN, ObjectRef, WorldCore
from robocram.world.world_object import RobotObject, WorldObject
from robocram.world.world_state import WorldState

if TYPE_CHECKING:
    from robocram.logic import KnowledgeBase

VisibilityMethod = Literal["ray", "render"]
T = TypeVar("T")
DEFAULT_VISIBILITY: VisibilityMethod = "ray"


class World(WorldCore):
    """A scene of named objects and robots in one PyBullet client, with reasoning."""

    def __init__(self, gui: bool = False, gravity: float = -9.81, time_step: float = 1 / 240):
        super().__init__(gui, gravity, time_step)
        self._gui = gui
        self._kb: KnowledgeBase | None = None
        self._radii: Derived[str, dict[str, float]] = Derived(Versions.created)  # link -> [m]
        self._derived: dict[Callable[[World], object], object] = {}

    def derived(self, make: Callable[[World], T]) -> T:
        """``make(self)``, built on first use and kept with this world, one per ``make``.

        Upper layers keep what they derive from a world here (the motion layer its coal
        obstacle shapes), so it lives exactly as long as the world and no module holds a
        cache. Unlike a robot model a world changes: what is kept is a
        :class:`~robocram.world.derived.Derived` store (or made of them) that declares
        what its values depend on, and builds again when the world's
        :attr:`versions` say that changed (a copy of the world starts with none).
        """
        found = self._derived.get(make)
        if found is None:
            found = self._derived.setdefault(make, make(self))
        return cast(T, found)

    def __enter__(self) -> World:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __del__(self) -> None:
        with contextlib.suppress(Exception):
            self.close()

    def add_object(
        self, name: str, type: str, spec: BodySpec, pose: PoseLike = ORIGIN
    ) -> WorldObject:  # noqa: A002
        """Add a body made from ``spec``, called ``name``, of type ``type``, at ``pose``."""
        handle = WorldObject(name, type, -1, spec)
        self.insert(handle, pose)
        return handle

    def add_floor(self, name: str = "floor") -> WorldObject:
        """Add the static ground plane z = 0 (type ``floor``)."""
        return self.add_object(name, "floor", ShapeSpec("plane"))

    def add_box(
        self,
        name: str,
        size: Vector3,
        pose: PoseLike = ORIGIN,
        mass: float = 0.0,
        color: Rgba = GREY,
    ) -> WorldObject:
        """Add a box of extents ``size`` [m] centred at ``pose``; ``mass`` [kg] 0 is static."""
        return self.add_object(name, "box", ShapeSpec("box", size, mass, color), pose)

    def add_cylinder(
        self,
        name: str,
        radius: float,
        height: float,
        pose: PoseLike = ORIGIN,
        mass: float = 0.0,
        color: Rgba = GREY,
    ) -> WorldObject:
        """Add an upright cylinder [m] centred at ``pose``."""
        spec = ShapeSpec("cylinder", (2 * radius, 2 * radius, height), mass, color)
        return self.add_object(name, "cylinder", spec, pose)

    def add_sphere(
        self,
        name: str,
        radius: float,
        pose: PoseLike = ORIGIN,
        mass: float = 0.0,
        color: Rgba = GREY,
    ) -> WorldObject:
        """Add a sphere of ``radius`` [m] centred at ``pose``."""
        spec = ShapeSpec("sphere", (2 * radius, 2 * radius, 2 * radius), mass, color)
        return self.add_object(name, "sphere", spec, pose)

    def add_mesh(
        self,
        name: str,
        path: str | Path,
        pose: PoseLike = ORIGIN,
        mass: float = 0.0,
        scale: float = 1.0,
        color: Rgba = GREY,
        type: str = "mesh",  # noqa: A002
    ) -> WorldObject:
        """Add a body from an OBJ/STL mesh file."""
        return self.add_object(name, type, MeshSpec(Path(path), scale, mass, color), pose)

    def add_urdf(
        self,
        name: str,
        path: str | Path,
        pose: PoseLike = ORIGIN,
        fixed_base: bool = True,
        type: str = "urdf",  # noqa: A002
    ) -> WorldObject:
        """Add an articulated or rigid object (a kitchen, a drawer) from a URDF file."""
        return self.add_object(name, type, UrdfSpec(Path(path), fixed_base), pose)

    def add_item(self, name: str, kind: str, pose: PoseLike = ORIGIN) -> WorldObject:
        """Add a household item from the catalogue (mug, pot, bottle, ...); type = ``kind``."""
        canonical, spec = catalogue_item(kind)
        return self.add_object(name, canonical, spec, pose)

    def add_robot(
        self, robot: str | RobotDescription, pose: PoseLike = ORIGIN, name: str | None = None
    ) -> RobotObject:
        """Add a robot (fixed base, joints held) by built-in name or description.

        A model with more links than PyBullet holds is loaded with its fixed links folded
        into their parents; they stay usable as frames (``link_pose``, ``link_names``).

        Raises:
            TooManyLinksError: even folded, the model has too many links (before loading).
        """
        desc = load_description(robot)
        spec = robot_body_spec(name or desc.name, desc)
        handle = RobotObject(name or desc.name, "robot", -1, spec, description=desc)
        self.insert(handle, pose)
        self.set_held_joints(handle, dict.fromkeys(self.joint_states(handle), 0.0))
        self._start_within_limits(handle)
        return handle

    def insert(self, handle: WorldObject, pose: PoseLike = ORIGIN) -> WorldObject:
        """Add ``handle``'s body (see :meth:`WorldCore.insert`); a robot's facts join the KB."""
        super().insert(handle, pose)
        if isinstance(handle, RobotObject) and self._kb is not None:
            self._install_description(handle.description)
        return handle

    def remove(self, obj: ObjectRef) -> None:
        """Take ``obj`` out (see :meth:`WorldCore.remove`); a robot's facts leave the KB."""
        handle = self.object(obj)
        super().remove(handle)
        if isinstance(handle, RobotObject) and self._kb is not None:
            name = handle.description.name
            if not any(r.description.name == name for r in self.robots()):
                self._kb.add_fact_group(f"{name}_description", [])

    def _start_within_limits(self, robot: RobotObject) -> None:
        """Put every joint at its in-limit value nearest 0 (some grippers exclude 0), and
        mimic joints where their masters put them (the HSR's finger tips follow its hand
        motor with an offset: left at 0, the first motion would snap them there)."""
        model = robot.description.model
        masters = {j.mimic.joint for j in model.joints.values() if j.mimic is not None}
        start = {
            name: self.joint_limits(robot, name).clamp(0.0)
            for name in self.joint_states(robot)
            if model.joints[name].mimic is None
        }
        self.set_joint_states(
            robot, {name: v for name, v in start.items() if v != 0.0 or name in masters}
        )

    def _install_description(self, desc: RobotDescription) -> None:
        install_description(self.kb, desc)

    @contextlib.contextmanager
    def stored_state(self) -> Iterator[WorldState]:
        """Restore the world exactly on leaving the block (objects added/removed included)."""
        state = WorldState.capture(self)
        try:
            yield state
        finally:
            state.restore(self)

    def copy(self, gui: bool = False) -> World:
        """An independent world (its own client) with the same objects and state."""
        state = WorldState.capture(self)  # a closed world raises WorldClosedError here
        other = World(gui=gui, gravity=self.gravity, time_step=self.time_step)
        state.recreate(other)
        return other

    def aabb(self, obj: ObjectRef) -> tuple[Vector3, Vector3]:
        """World-aligned bounds ``(lower, upper)`` [m] of ``obj`` (all links)."""
        low, high = visibility.aabb(self, self.object(obj))
        return (float(low[0]), float(low[1]), float(low[2])), (
            float(high[0]),
            float(high[1]),
            float(high[2]),
        )

    def link_aabb(self, obj: ObjectRef, link: str) -> tuple[Vector3, Vector3]:
        """World-aligned bounds ``(lower, upper)`` [m] of one link of ``obj``."""
        handle = self.object(obj)
        low, high = visibility.link_aabb(self, handle, self._link_index(handle, link))
        return (low[0], low[1], low[2]), (high[0], high[1], high[2])

    def collision_shapes(self, obj: ObjectRef) -> list[CollisionShape]:
        """The collision shapes of ``obj`` at their current poses in map (a snapshot)."""
        return collision_shapes(self, self.object(obj))

    def link_aabbs(self, obj: ObjectRef) -> dict[str, tuple[Vector3, Vector3]]:
        """World-aligned bounds ``(lower, upper)`` [m] of every link of ``obj``, by link name.

        One entry per body part (a frame folded into its host link is not repeated); a
        single-shape body has one, under the object's name.
        """
        handle = self.object(obj)
        names: dict[int, str] = {}
        for name, index in handle.link_index.items():
            names.setdefault(index, name)
        names.setdefault(-1, handle.name)
        return {name: visibility.link_aabb(self, handle, i) for i, name in sorted(names.items())}

    def collisions(
        self, obj: ObjectRef, ignore: Iterable[ObjectRef] = (), distance: float = 0.002
    ) -> list[WorldObject]:
        """Objects touching or penetrating ``obj`` within ``distance`` [m].

        A robot and the objects attached to it never collide with each other.
        """
        skip = [self.object(o) for o in ignore]
        touched = {
            name
            for _, name in link_contacts.link_contacts(self, self.object(obj), None, skip, distance)
        }
        return [o for o in self.objects() if o.name in touched]  # the world's order

    def in_collision(
        self, obj: ObjectRef, ignore: Iterable[ObjectRef] = (), ignore_floor: bool = True
    ) -> bool:
        """Whether ``obj`` touches anything but ``ignore`` and what it carries.

        Objects of type ``floor`` are ignored unless ``ignore_floor`` is False: robot bases
        (HSR, Boxy) stand on it.
        """
        skip = list(ignore) + (self.objects(type="floor") if ignore_floor else [])
        return bool(self.collisions(obj, skip))

    def link_pairs_in_contact(
        self,
        obj: ObjectRef,
        ignore: Iterable[ObjectRef] = (),
        distance: float = 0.0,
        links: Iterable[str] | None = None,
        obstacles: ObstacleBoxes | None = None,
    ) -> list[tuple[str, WorldObject, str]]:
        """``(link of obj, other object, its link)`` triples within ``distance`` [m].

        Found through Bullet's broadphase, so a robot in a kitchen of hundreds of links
        costs only the pairs whose bounds overlap. Nothing is skipped but ``ignore``;
        ``links`` limits the links of ``obj`` asked about (default: all). ``obstacles``
        (:meth:`obstacle_boxes`, read since only ``obj`` moved) replaces the broadphase.
        """
        skip = [self.object(o) for o in ignore]
        return link_contacts.link_pairs_in_contact(
            self, self.object(obj), skip, distance, links, obstacles
        )

    def obstacle_boxes(self, ignore: Iterable[ObjectRef] = ()) -> ObstacleBoxes:
        """The bounds of every link of every object but ``ignore``, read now: pass them to
        :meth:`link_distances` and :meth:`link_pairs_in_contact` while nothing else moves."""
        names = [self.object(o).name for o in ignore]
        return self.derived(_kept_obstacle_boxes).boxes(self, names)

    def link_radii(self, obj: ObjectRef) -> dict[str, float]:
        """Per link of ``obj``: a radius [m] about the link's frame that holds its shapes.

        Taken once per body from its world-aligned bounds at the pose it is in (such a box
        holds the link's shapes whatever its orientation, so the radius bounds them
        forever: the shapes are rigid in the link's frame).
        """
        handle = self.object(obj)
        return dict(self._radii.get(handle.name, partial(self._link_radii, handle), self.versions))

    def _link_radii(self, handle: WorldObject) -> dict[str, float]:
        radii = {}
        for link in self.link_names(handle):
            origin = np.array(self.link_pose(handle, link).position)
            low, high = self.link_aabb(handle, link)
            far = np.maximum(np.abs(np.subtract(low, origin)), np.abs(np.subtract(high, origin)))
            radii[link] = float(np.linalg.norm(far))
        return radii

    def link_distances(
        self,
        obj: ObjectRef,
        ignore: Iterable[ObjectRef] = (),
        distance: float = 0.05,
        links: Iterable[str] | None = None,
        obstacles: ObstacleBoxes | None = None,
    ) -> list[tuple[str, WorldObject, str, float]]:
        """``(link of obj, other object, its link, distance [m])`` nearer than ``distance``.

        The distance is the smallest between the two links (negative: penetration); a
        planner steps as far as the nearest one allows. Nothing is skipped but ``ignore``.
        """
        skip = [self.object(o) for o in ignore]
        return link_contacts.link_distances(
            self, self.object(obj), skip, distance, links, obstacles
        )

    def self_contacts(
        self, obj: ObjectRef, pairs: Iterable[tuple[str, str]], distance: float = 0.0
    ) -> list[tuple[str, str]]:
        """The pairs of ``obj``'s own links among ``pairs`` nearer than ``distance`` [m]."""
        return link_contacts.self_contacts(self, self.object(obj), pairs, distance)

    def self_distances(
        self,
        obj: ObjectRef,
        pairs: Sequence[tuple[str, str]],
        reach: float,
        exact: Callable[[NDArray[np.float64]], Iterable[int]] | None = None,
    ) -> NDArray[np.float64]:
        """Per pair of ``obj``'s own links: a lower bound [m] on their distance, exact
        (negative: penetration depth) where their bounds come within ``reach`` or for
        the pairs ``exact`` picks from the bounds' gaps."""
        return link_contacts.self_distances(self, self.object(obj), pairs, reach, exact)

    def contact_points(
        self,
        a: ObjectRef,
        b: ObjectRef | None = None,
        link_a: str | None = None,
        link_b: str | None = None,
        distance: float = 0.0,
    ) -> list[ContactPoint]:
        """Points where ``a`` (or its ``link_a``) comes within ``distance`` [m] of ``b``.

        ``b`` None means every other object. ``distance`` 0 gives touching and penetrating
        points; a larger one also gives near misses (``ContactPoint.distance`` > 0).
        Attachments are not skipped here: this is the raw geometry.
        """
        first = self.object(a)
        others = [self.object(b)] if b is not None else [o for o in self if o is not first]
        return [
            point
            for other in others
            for point in contacts.closest_points(self, first, other, distance, link_a, link_b)
        ]

    def contact(self, a: ObjectRef, b: ObjectRef) -> bool:
        """Whether ``a`` and ``b`` touch (within 2 mm)."""
        return contacts.contact(self, self.object(a), self.object(b))

    def stable(self, obj: ObjectRef | Sequence[ObjectRef] | None = None) -> bool:
        """Whether ``obj`` (default: all free objects) stays within 5 mm / 0.15 rad."""
        if obj is None:
            return spatial_relations.stable(self)
        refs = [obj] if isinstance(obj, str | WorldObject) else list(obj)
        return spatial_relations.stable(self, [self.object(o) for o in refs])

    def supported_by(self, obj: ObjectRef, support: ObjectRef) -> bool:
        """Whether ``obj`` touches ``support`` and is above it."""
        return spatial_relations.supported_by(self, self.object(obj), self.object(support))

    def above(self, a: ObjectRef, b: ObjectRef) -> bool:
        """Whether ``a`` is over ``b`` (x-y overlap, a's centre above b's top)."""
        return spatial_relations.above(self, self.object(a), self.object(b))

    def below(self, a: ObjectRef, b: ObjectRef) -> bool:
        """Whether ``a`` is under ``b``."""
        return spatial_relations.below(self, self.object(a), self.object(b))

    def camera(self, robot: ObjectRef, camera: str | None = None) -> Camera:
        """The robot's camera (by name; default the first) at its current pose."""
        handle = self.robot(robot)
        cams = handle.description.cameras
        chosen = [c for c in cams if camera is None or c.name == camera]
        if not chosen:
            raise NoCameraError(handle.name, camera, [c.name for c in cams])
        c = chosen[0]
        return Camera(self.link_pose(handle, c.frame), c.horizontal_fov, c.vertical_fov)

    def visibility_from(
        self, camera: Camera, obj: ObjectRef, method: VisibilityMethod = DEFAULT_VISIBILITY
    ) -> Visibility:
        """Seen fraction and occluders of ``obj`` from ``camera`` by rays or by a render."""
        handle = self.object(obj)
        if method == "ray":
            return visibility.ray_visibility(self, camera, handle)
        if method == "render":
            return visibility.render_visibility(self, camera, handle)
        raise WorldValueError(f"unknown visibility method {method!r}; use 'ray' or 'render'")

    def visibility_fraction(
        self,
        robot: ObjectRef,
        obj: ObjectRef,
        camera: str | None = None,
        method: VisibilityMethod = DEFAULT_VISIBILITY,
    ) -> float:
        """Share (0..1) of ``obj`` the robot's camera sees, occlusion and image edges counted."""
        return self.visibility_from(self.camera(robot, camera), obj, method).fraction

    def visible(
        self,
        robot: ObjectRef,
        obj: ObjectRef,
        camera: str | None = None,
        threshold: float = 0.9,
        method: VisibilityMethod = DEFAULT_VISIBILITY,
    ) -> bool:
        """Whether the robot's camera sees at least ``threshold`` of ``obj``."""
        return self.visibility_fraction(robot, obj, camera, method) >= threshold

    def visible_from(
        self,
        camera: Camera | PoseLike,
        obj: ObjectRef,
        threshold: float = 0.9,
        method: VisibilityMethod = DEFAULT_VISIBILITY,
    ) -> bool:
        """Whether a camera (a :class:`Camera`, or an optical-frame pose) sees ``obj``."""
        cam = camera if isinstance(camera, Camera) else Camera(Pose.coerce(camera))
        return self.visibility_from(cam, obj, method).fraction >= threshold

    def occluding_objects(
        self,
        robot: ObjectRef,
        obj: ObjectRef,
        camera: str | None = None,
        method: VisibilityMethod = DEFAULT_VISIBILITY,
    ) -> list[WorldObject]:
        """Objects between the robot's camera and ``obj`` (the robot itself may be one)."""
        names = self.visibility_from(self.camera(robot, camera), obj, method).occluders
        return [self.object(n) for n in names]

    def render(
        self, camera: Camera | PoseLike, width: int = 640, height: int = 480
    ) -> NDArray[np.uint8]:
        """An ``height x width x 3`` RGB image from ``camera`` (TINY renderer, no window)."""
        cam = camera if isinstance(camera, Camera) else Camera(Pose.coerce(camera))
        cam = cam.with_aspect(width / height)
        _, _, rgba, _, _ = pybullet.getCameraImage(
            width, height, cam.view_matrix(), cam.projection_matrix(),
            renderer=pybullet.ER_TINY_RENDERER, physicsClientId=self.physics_client(),
        )  # fmt: skip
        return np.reshape(np.asarray(rgba, dtype=np.uint8), (height, width, 4))[:, :, :3].copy()

    def save_png(
        self, path: str | Path, camera: Camera | PoseLike, width: int = 640, height: int = 480
    ) -> Path:
        """Render from ``camera`` and write the image to ``path`` as PNG."""
        return write_png(path, self.render(camera, width, height))

    def ray_cast(self, start: Vector3, end: Vector3) -> RayHit | None:
        """The first object on the segment ``start``..``end`` [m], or None."""
        return self.ray_cast_batch([start], [end])[0]

    def ray_cast_batch(
        self, starts: Sequence[Vector3], ends: Sequence[Vector3]
    ) -> list[RayHit | None]:
        """:meth:`ray_cast` for many rays in one pybullet call."""
        if len(starts) != len(ends):
            raise WorldValueError(f"{len(starts)} ray starts but {len(ends)} ends")
        return cast_rays(self, starts, ends)

    @property
    def kb(self) -> KnowledgeBase:
        """This world's knowledge base: world predicates and the robots' descriptions."""
        if self._kb is None:
            from robocram.world.predicates import world_knowledge_base

            self._kb = world_knowledge_base(self)
            for robot in self.robots():
                self._install_description(robot.description)
        return self._kb

    def __repr__(self) -> str:
        names = ", ".join(o.name for o in self.objects())
        return f"World(client={self.client}, objects=[{names}])"


def _kept_obstacle_boxes(world: World) -> KeptObstacleBoxes:
    """The obstacle bounds a world keeps (the key under which :meth:`World.derived` keeps them)."""
    return KeptObstacleBoxes()
