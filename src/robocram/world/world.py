"""The projection world: a PyBullet scene of objects and robots, and reasoning over it.

Each :class:`World` is its own headless physics client (a GUI window on request); there is
no global "current world". Close a world (or use it as a context manager) when done.
:class:`World` is a facade: the everyday questions and changes (poses, joints,
attachments, adding and removing bodies) are answered by its
:class:`~robocram.world.world_tables.WorldTables`, which no caller reaches, and the rest
by its parts.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path
from typing import TYPE_CHECKING, TypeVar, cast

from robocram.robots import RobotDescription, load_description
from robocram.tf import Pose, PoseLike, Vector3
from robocram.world import visibility
from robocram.world.bodies import Bodies
from robocram.world.body_spec import GREY, BodySpec, Rgba, ShapeSpec, UrdfSpec
from robocram.world.catalogue import catalogue_item
from robocram.world.contacts import Contacts
from robocram.world.convex_parts import decomposed
from robocram.world.joint_state import ClampedJoint
from robocram.world.physics import Physics
from robocram.world.robot_facts import RobotFacts
from robocram.world.robot_urdf import robot_body_spec
from robocram.world.snapshots import Snapshots
from robocram.world.versions import Versions
from robocram.world.view import View
from robocram.world.world_object import RobotObject, WorldObject
from robocram.world.world_tables import ORIGIN, ObjectRef, WorldTables

if TYPE_CHECKING:
    from robocram.logic import KnowledgeBase

T = TypeVar("T")


class World:
    """A scene of named objects and robots in one PyBullet client: the everyday methods,
    and the rest in parts (``world.bodies``, ``world.contacts``, ``world.physics``,
    ``world.snapshots``, ``world.view``)."""

    def __init__(self, gui: bool = False, gravity: float = -9.81, time_step: float = 1 / 240):
        self._facts = RobotFacts()
        self._tables = WorldTables(gui, gravity, time_step, self._facts)
        self.gravity = gravity  # [m/s^2] along z
        self.time_step = time_step  # [s] per physics step
        self._gui = gui
        self._kb: KnowledgeBase | None = None
        self._derived: dict[Callable[[World], object], object] = {}
        self.bodies = Bodies(self, self._tables)
        self.contacts = Contacts(self, self._tables)
        self.physics = Physics(self, self._tables)
        self.snapshots = Snapshots(self, self._tables)
        self.view = View(self, self._tables)

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
        desc = decomposed(load_description(robot))  # its decomposed_links as convex parts
        spec = robot_body_spec(name or desc.name, desc)
        handle = RobotObject(name or desc.name, "robot", -1, spec, description=desc)
        self._tables.insert(handle, pose)
        self._tables.set_held_joints(handle, dict.fromkeys(self.joint_states(handle), 0.0))
        self._start_within_limits(handle)
        return handle

    def _start_within_limits(self, robot: RobotObject) -> None:
        """Put every joint at its in-limit value nearest 0 (some grippers exclude 0), the
        legs as the description's ``stance`` has them (a B1's feet under its hips), and
        mimic joints where their masters put them (the HSR's finger tips follow its hand
        motor with an offset: left at 0, the first motion would snap them there)."""
        model = robot.description.model
        masters = {j.mimic.joint for j in model.joints.values() if j.mimic is not None}
        start = {
            name: self._tables.joint_limits(robot, name).clamp(0.0)
            for name in self.joint_states(robot)
            if model.joints[name].mimic is None
        }
        start.update({j: v for j, v in robot.description.stance.items() if j in start})
        self.set_joint_states(
            robot, {name: v for name, v in start.items() if v != 0.0 or name in masters}
        )

    def copy(self, gui: bool = False) -> World:
        """An independent world (its own client) with the same objects and state."""
        state = self.snapshots.capture()  # a closed world raises WorldClosedError
        other = World(gui=gui, gravity=self.gravity, time_step=self.time_step)
        other.snapshots.recreate(state)
        return other

    def aabb(self, obj: ObjectRef) -> tuple[Vector3, Vector3]:
        """World-aligned bounds ``(lower, upper)`` [m] of ``obj`` (all links)."""
        low, high = visibility.aabb(self, self.object(obj))
        return (float(low[0]), float(low[1]), float(low[2])), (
            float(high[0]),
            float(high[1]),
            float(high[2]),
        )

    @property
    def kb(self) -> KnowledgeBase:
        """This world's knowledge base: world predicates and the robots' descriptions."""
        if self._kb is None:
            from robocram.world.predicates import world_knowledge_base

            self._kb = world_knowledge_base(self)
            self._facts.start(self._kb, self.robots())
        return self._kb

    def __repr__(self) -> str:
        names = ", ".join(o.name for o in self.objects())
        return f"World(client={self._tables.client}, objects=[{names}])"

    # The everyday questions and changes, answered by the tables.

    @property
    def versions(self) -> Versions:
        """The world's change counters: per body its pose and joints, and the structure
        (what a cache compares instead of states; see :mod:`robocram.world.derived`)."""
        return self._tables.versions

    def close(self) -> None:
        """Disconnect the physics client; the world is unusable afterwards."""
        self._tables.close()

    @property
    def closed(self) -> bool:
        """Whether :meth:`close` was called."""
        return self._tables.closed

    def add_object(
        self, name: str, type: str, spec: BodySpec, pose: PoseLike = ORIGIN
    ) -> WorldObject:  # noqa: A002
        """Add a body made from ``spec``, called ``name``, of type ``type``, at ``pose``."""
        return self._tables.add_object(name, type, spec, pose)

    def object(self, name: ObjectRef) -> WorldObject:
        """The object called ``name`` (a handle is checked to still belong to this world)."""
        return self._tables.object(name)

    def robot(self, name: ObjectRef) -> RobotObject:
        """The robot called ``name``."""
        return self._tables.robot(name)

    def objects(self, type: str | None = None) -> list[WorldObject]:  # noqa: A002
        """All objects in creation order, or those of one ``type``."""
        return self._tables.objects(type)

    def robots(self) -> list[RobotObject]:
        """All robots in creation order."""
        return self._tables.robots()

    def __contains__(self, name: ObjectRef) -> bool:
        return name in self._tables

    def __iter__(self) -> Iterator[WorldObject]:
        return iter(self._tables)

    def remove(self, obj: ObjectRef) -> None:
        """Take ``obj`` out of the world, with its attachments (either end)."""
        self._tables.remove(obj)

    def pose(self, obj: ObjectRef) -> Pose:
        """Pose of the object's root link frame in the world."""
        return self._tables.pose(obj)

    def set_pose(self, obj: ObjectRef, pose: PoseLike) -> None:
        """Teleport ``obj`` (at rest) to ``pose``; its attached objects follow.

        Placing an attached object moves it relative to its link; it stays attached.
        """
        self._tables.set_pose(obj, pose)

    def link_pose(self, obj: ObjectRef, link: str) -> Pose:
        """Pose of ``link`` (a URDF link or a frame added in code) in the world."""
        return self._tables.link_pose(obj, link)

    def link_names(self, obj: ObjectRef) -> list[str]:
        """Names of all links and frames of ``obj``, the root first."""
        return self._tables.link_names(obj)

    def joint_states(self, obj: ObjectRef) -> dict[str, float]:
        """Every movable joint's value [rad | m] by name."""
        return self._tables.joint_states(obj)

    def set_joint_states(
        self, obj: ObjectRef, values: Mapping[str, float], carry: bool = True
    ) -> list[ClampedJoint]:
        """Set joints by name, clamped to their limits; mimic joints follow their masters.

        Returns the joints whose requested value was outside the limits (empty if none).
        The values are held during simulation; attached objects follow unless ``carry`` is
        False: a check that puts the joints back before anything else looks, and ignores
        what the robot holds, saves moving it there and back.
        """
        return self._tables.set_joint_states(obj, values, carry)

    def attach(self, obj: ObjectRef, robot: ObjectRef, link: str) -> None:
        """Fix ``obj`` to ``link`` of ``robot`` at their current relative pose."""
        self._tables.attach(obj, robot, link)

    def detach(self, obj: ObjectRef) -> None:
        """Let ``obj`` go; it stays where it is. Detaching a free object is an error."""
        self._tables.detach(obj)
