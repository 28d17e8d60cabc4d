"""A robot in a world, looked up once: the value the layers pass instead of ``(world, "pr2")``.

A name is accepted only at the public edges (scenes, the command line,
``simulated_robot``); they make a :class:`RobotHandle` with one lookup and hand it down.
The handle holds the world and the robot's body; everything else it offers (the checked
description, the model, the arms, grippers, camera and base) is read from the body's
description, which never changes while the body is in the world.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

from robocram.robots import (
    ArmDescription,
    BaseType,
    CameraDescription,
    GripperDescription,
    LoadedDescription,
    RobotModel,
)
from robocram.world.world import World
from robocram.world.world_object import RobotObject, WorldObject


@dataclass(frozen=True)
class RobotHandle:
    """One robot of one world: its body, description and model, with cheap accessors.

    Made by :meth:`of`; immutable. Two handles are equal when they hold the same world and
    the same body. The body is the one in the world when the handle was made: a robot
    removed and added again under the same name needs a new handle.
    """

    world: World
    body: RobotObject

    @classmethod
    def of(cls, world: World, robot: str | WorldObject | RobotHandle) -> RobotHandle:
        """The handle of ``robot`` (its name, body, or a handle, returned as it is).

        Raises:
            UnknownObjectError: no object of ``world`` has that name.
            NotARobotError: the object is not a robot.
        """
        if isinstance(robot, RobotHandle):
            return robot
        return cls(world, world.robot(robot))

    @property
    def name(self) -> str:
        """The robot's name in the world (its body's)."""
        return self.body.name

    @property
    def description(self) -> LoadedDescription:
        """The robot's checked description."""
        return self.body.description

    @property
    def model(self) -> RobotModel:
        """The robot's parsed URDF (``description.model``)."""
        return self.body.description.model

    @property
    def arms(self) -> Mapping[str, ArmDescription]:
        """Every kinematic chain with a tool frame, by key (the neck too, if it has one)."""
        return self.body.description.arms

    @property
    def grippers(self) -> Mapping[str, GripperDescription]:
        """The hands of the arms that have one, by arm key."""
        return MappingProxyType(
            {key: arm.gripper for key, arm in self.arms.items() if arm.gripper is not None}
        )

    @property
    def camera(self) -> CameraDescription | None:
        """The first camera (the one perception uses by default), None if it has none."""
        cameras = self.body.description.cameras
        return cameras[0] if cameras else None

    @property
    def base_frame(self) -> str:
        """The frame plans place the robot by (``base_footprint`` for the PR2)."""
        return self.body.description.base_frame

    @property
    def drive(self) -> BaseType:
        """How the base moves: holonomic, differential, ..."""
        return self.body.description.drive

    def joint_states(self) -> dict[str, float]:
        """The robot's joint values now [rad | m]."""
        return self.world.joint_states(self.body)

    def holding(self) -> tuple[str, ...]:
        """What the robot holds, and what that holds, recursively (they move with it)."""
        found: list[str] = []
        frontier = [self.name]
        while frontier:
            held = list(self.world.bodies.attachments(frontier.pop()))
            found += held
            frontier += held
        return tuple(found)

    def __repr__(self) -> str:
        return f"RobotHandle({self.name!r}, {self.description.name!r})"
