"""The projection world: a PyBullet scene of objects and robots, and reasoning over it.

Each :class:`World` is its own headless physics client (a GUI window on request); there is
no global "current world". Close a world (or use it as a context manager) when done.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, TypeVar, cast

from robocram.robots import RobotDescription, install_description, load_description
from robocram.tf import PoseLike, Vector3
from robocram.world import visibility
from robocram.world.bodies import Bodies
from robocram.world.body_spec import GREY, Rgba, ShapeSpec, UrdfSpec
from robocram.world.catalogue import catalogue_item
from robocram.world.contacts import Contacts
from robocram.world.physics import Physics
from robocram.world.robot_urdf import robot_body_spec
from robocram.world.snapshots import Snapshots
from robocram.world.view import View
from robocram.world.world_core import ORIGIN, ObjectRef, WorldCore
from robocram.world.world_object import RobotObject, WorldObject
from robocram.world.world_state import WorldState

if TYPE_CHECKING:
    from robocram.logic import KnowledgeBase

T = TypeVar("T")


class World(WorldCore):
    """A scene of named objects and robots in one PyBullet client: the everyday methods,
    and the rest in parts (``world.bodies``, ``world.contacts``, ``world.physics``,
    ``world.snapshots``, ``world.view``)."""

    def __init__(self, gui: bool = False, gravity: float = -9.81, time_step: float = 1 / 240):
        super().__init__(gui, gravity, time_step)
        self._gui = gui
        self._kb: KnowledgeBase | None = None
        self._derived: dict[Callable[[World], object], object] = {}
        self.bodies = Bodies(self)
        self.contacts = Contacts(self)
        self.physics = Physics(self)
        self.snapshots = Snapshots(self)
        self.view = View(self)

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
        desc = load_description(robot)
        spec = robot_body_spec(name or desc.name, desc)
        handle = RobotObject(name or desc.name, "robot", -1, spec, description=desc)
        self.insert(handle, pose)
        self.set_held_joints(handle, dict.fromkeys(self.joint_states(handle), 0.0))
        self._start_within_limits(handle)
        return handle

    def _inserted(self, handle: WorldObject) -> None:
        """A robot's facts join the knowledge base."""
        if isinstance(handle, RobotObject) and self._kb is not None:
            self._install_description(handle.description)

    def _removed(self, handle: WorldObject) -> None:
        """A robot's facts leave the knowledge base (when no robot of its kind is left)."""
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
