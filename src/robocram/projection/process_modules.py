"""The projected robot's process modules: one per resource, each calling low-level functions.

Commands are the terms of ``common_motions.pl`` (and ``flying.pl`` for flying robots):

- navigation: ``move_base(Pose)``; torso: ``move_torso(Value)``
- ptu: ``move_head(pose, P)``, ``move_head(frame, F)``, ``move_head(direction, D)`` where
  ``D`` is a vector in the robot's base frame (or a PoseStamped whose position is one)
- perception: ``detect(ObjectDesig)`` -> the perceived designator
- grippers: ``move_gripper_joint(Arm, open | close | grip | Position, Effort)``
- arms: ``move_tcp(Arm, Pose, Mode)``, ``move_tcp_both(Left, Right, Mode)``,
  ``move_joints(Arm, Config)``, ``move_joints_both(Left, Right)``
- flying: ``fly(Pose)``; distance sensor: ``sense_distance(Direction)`` [body frame]
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, ClassVar

import numpy as np

from robocram.execution import ProcessModule
from robocram.logic import Term
from robocram.projection.arm import move_joints, move_tcp
from robocram.projection.errors import ProjectionError
from robocram.projection.flying import fly, sense_distance
from robocram.projection.gripper import close_gripper, grip, open_gripper, set_gripper
from robocram.projection.navigation import drive
from robocram.projection.neck import look_at
from robocram.projection.perception import detect
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.torso import move_torso
from robocram.tf import PoseStamped, Vector3

Handler = Callable[..., Any]
DIRECTION_REACH = 100.0  # [m] looking along a direction aims at a point this far away


class ProjectionProcessModule(ProcessModule):
    """A process module of a projected robot: dispatches command terms to handlers."""

    name: ClassVar[str] = ""

    def __init__(self, robot: ProjectedRobot) -> None:
        super().__init__()
        self.robot = robot

    def handlers(self) -> dict[str, Handler]:
        """Map ``name/arity`` of each command this module executes to its handler."""
        raise NotImplementedError

    def execute(self, command: Any) -> Any:
        """Run the low-level function matching ``command``."""
        table = self.handlers()
        if isinstance(command, Term):
            handler = table.get(f"{command.name}/{command.arity}")
            if handler is not None:
                return handler(*command.args)
        raise self.unsupported(command, table)


class NavigationPM(ProjectionProcessModule):
    """The base: ``move_base(Pose)``."""

    name = "projection_navigation"

    def handlers(self) -> dict[str, Handler]:
        """Command table."""
        return {"move_base/1": lambda pose: drive(self.robot, pose)}


class TorsoPM(ProjectionProcessModule):
    """The torso: ``move_torso(Value)``."""

    name = "projection_torso"

    def handlers(self) -> dict[str, Handler]:
        """Command table."""
        return {"move_torso/1": lambda value: move_torso(self.robot, value)}


class PtuPM(ProjectionProcessModule):
    """The head (pan-tilt unit or neck arm): ``move_head(pose | frame | direction, X)``."""

    name = "projection_ptu"

    def handlers(self) -> dict[str, Handler]:
        """Command table."""
        return {"move_head/2": self._move_head}

    def _move_head(self, mode: str, goal: Any) -> dict[str, float]:
        robot = self.robot
        if mode == "pose":
            point = robot.in_map(goal).position
        elif mode == "frame":
            point = robot.frame_pose(str(goal)).position
        elif mode == "direction":
            point = self._along(goal)
        else:
            raise ProjectionError(f"move_head mode {mode!r} is none of pose, frame, direction")
        return look_at(robot, point)

    def _along(self, direction: Any) -> Vector3:
        vector = direction.position if isinstance(direction, PoseStamped) else direction
        d = np.asarray(vector, float)
        if d.shape != (3,) or np.linalg.norm(d) < 1e-9:
            raise ProjectionError(f"looking direction must be a non-zero 3-D vector, got {vector}")
        base = self.robot.base_pose()
        camera = self.robot.world.camera(self.robot.name).pose.position
        rotated = base.matrix()[:3, :3] @ (d / np.linalg.norm(d))
        far = np.asarray(camera) + DIRECTION_REACH * rotated
        return (float(far[0]), float(far[1]), float(far[2]))


class PerceptionPM(ProjectionProcessModule):
    """The camera: ``detect(ObjectDesig)``."""

    name = "projection_perception"

    def handlers(self) -> dict[str, Handler]:
        """Command table."""
        return {"detect/1": lambda desig: detect(self.robot, desig)}


class GripperPM(ProjectionProcessModule):
    """The grippers: ``move_gripper_joint(Arm, open | close | grip | Position, Effort)``."""

    name = "projection_grippers"

    def handlers(self) -> dict[str, Handler]:
        """Command table."""
        return {"move_gripper_joint/3": self._move}

    def _move(self, arm_name: str, action: Any, effort: Any) -> Any:
        if action == "open":
            return open_gripper(self.robot, arm_name)
        if action == "close":
            return close_gripper(self.robot, arm_name)
        if action == "grip":
            return grip(self.robot, arm_name)
        if isinstance(action, int | float):
            return set_gripper(self.robot, arm_name, float(action))
        raise ProjectionError(
            f"gripper goal {action!r} is none of open, close, grip or a position [rad | m]"
        )


class ArmPM(ProjectionProcessModule):
    """The arms: ``move_tcp`` and ``move_joints``, one arm or both."""

    name = "projection_arms"

    def handlers(self) -> dict[str, Handler]:
        """Command table."""
        r = self.robot
        return {
            "move_tcp/3": lambda a, pose, mode: move_tcp(r, a, pose, mode),
            "move_tcp_both/3": lambda left, right, mode: (
                move_tcp(r, "left", left, mode),
                move_tcp(r, "right", right, mode),
            ),
            "move_joints/2": lambda a, config: move_joints(r, a, config),
            "move_joints_both/2": lambda left, right: (
                move_joints(r, "left", left),
                move_joints(r, "right", right),
            ),
        }


class FlyingPM(ProjectionProcessModule):
    """The body of a flying robot: ``fly(Pose)``."""

    name = "projection_flying"

    def handlers(self) -> dict[str, Handler]:
        """Command table."""
        return {"fly/1": lambda pose: fly(self.robot, pose)}


class DistanceSensorPM(ProjectionProcessModule):
    """The range sensor of a flying robot: ``sense_distance(Direction)``."""

    name = "projection_distance_sensor"

    def handlers(self) -> dict[str, Handler]:
        """Command table."""
        return {"sense_distance/1": lambda d: sense_distance(self.robot, tuple(d))}
