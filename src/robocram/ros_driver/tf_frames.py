"""The driver's world as a real robot's tf: a tree, as robot_state_publisher shapes it.

A robot's links hang from their parent links: the frames of fixed joints never move
relative to their parent, so they go once on ``/tf_static``; the frames of moving joints
go parent -> child on ``/tf`` at the joints' values, with the robot's base (``map`` ->
root link) and every other object in ``map``. A PR2 then sends ~40 transforms per state
instead of ~90, read from its joint values without asking PyBullet for a link, and a
client composes the map poses as it must for a real robot.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.robots import Joint, joint_transform
from robocram.ros.tf_cdr import Transform
from robocram.tf import Pose
from robocram.world import World

MAP = "map"


@dataclass(frozen=True)
class _RobotJoints:
    name: str
    root: str
    fixed: tuple[Joint, ...]
    moving: tuple[Joint, ...]


class TfFrames:
    """Which of the world's frames are static and which move, and their transforms now."""

    def __init__(self, world: World) -> None:
        self.world = world
        self._robots: list[_RobotJoints] = []
        self._taken: set[str] = set()  # robots and their links: a frame of that name is theirs
        for robot in world.robots():
            model = robot.description.model
            self._taken.update((robot.name, *model.links))
            joints = model.joints.values()
            fixed = tuple(j for j in joints if j.type == "fixed")
            moving = tuple(j for j in joints if j.type != "fixed")
            self._robots.append(_RobotJoints(robot.name, model.root_link, fixed, moving))

    def static_transforms(self) -> list[Transform]:
        """The fixed joints' transforms, parent -> child (they hold while the robot moves)."""
        return [
            _transform(j.parent, j.child, joint_transform(j)) for r in self._robots for j in r.fixed
        ]

    def moving_transforms(self) -> list[Transform]:
        """The robots' bases in ``map``, their moving joints' transforms parent -> child
        and every object (not a robot) in ``map``, now (call holding the world's lock)."""
        world = self.world
        out: list[Transform] = []
        for robot in self._robots:
            out.append(_transform(MAP, robot.root, world.pose(robot.name)))
            values = world.joint_states(robot.name)
            out += [
                _transform(j.parent, j.child, joint_transform(j, values[j.name]))
                for j in robot.moving
            ]
        out += [
            _transform(MAP, obj.name, world.pose(obj))
            for obj in world.objects()
            if obj.name not in self._taken
        ]
        return out


def _transform(parent: str, child: str, pose: Pose) -> Transform:
    return (parent, child, pose.position, pose.orientation)
