"""The projected robot's process modules: one per motion table resource.

Each module executes the commands the motion table (``robocram.designators.MOTION_TYPES``)
grounds for its resource, one method per command, dispatched by
:class:`~robocram.execution.MotionProcessModule`:

- navigation: ``move_base(Pose)``; torso: ``move_torso(Value)``
- ptu: ``move_head(pose, P)``, ``move_head(frame, F)``, ``move_head(direction, D)`` where
  ``D`` is a vector in the robot's base frame (or a PoseStamped whose position is one),
  ``move_head(joints, C)``: the head's joints to ``C`` (its parking configuration)
- perception: ``detect(ObjectDesig)`` and ``inspect(ObjectDesig)`` -> the perceived
  designator (the simulated camera reports all it knows of an object at once, so
  inspecting answers what detecting does)
- grippers: ``move_gripper_joint(Arm, open | close | grip | Position, Effort)``
- arms: ``move_tcp(Arm, Pose, Mode, Touching)``, ``move_tcp_both(Left, Right, Mode)``,
  ``move_joints(Arm, Config, Mode, Touching)``, ``move_joints_both(Left, Right, Mode)``,
  ``move_part(Arm, Part, Joint, Handle, Goal)`` (open or close a drawer or door)
- tools: ``move_tool_path(Arm, Path, Tool, Point, Contacts, Needed)``,
  ``pour(Arm, Path, Source, Point, Target, Amount, Needed)``,
  ``cut(Arm, Path, Tool, Point, Contacts, Object, Cuts, Needed)`` (docs/tool_actions.md;
  a path planned to less than the ``Needed`` share is refused before it is followed)
- flying: ``fly(Pose)``; distance sensor: ``sense_distance(Direction)`` [body frame]
- legs: ``crouch(Depth)``: the body ``Depth`` [m] below standing (0: standing up)

Arm and gripper words are the robot's arm names or the sides ``left``/``right``
(``RobotDescription.arm_called``), so the modules serve any robot's arms.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import ClassVar, cast

import numpy as np

from robocram.designators import SIDES, ObjectDesignator
from robocram.designators.tool_answers import CuttingAnswer, PouringAnswer, ToolPathAnswer
from robocram.execution import MotionProcessModule
from robocram.projection.arm import move_joints, move_tcp
from robocram.projection.articulation import move_part
from robocram.projection.crouching import crouch
from robocram.projection.cutting import cut
from robocram.projection.errors import ProjectionError
from robocram.projection.flying import fly, sense_distance
from robocram.projection.gripper import close_gripper, grip, open_gripper, set_gripper
from robocram.projection.head_joints import turn_head_joints
from robocram.projection.navigation import drive
from robocram.projection.neck import look_at
from robocram.projection.perception import detect
from robocram.projection.pouring import pour
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.tool_motion import PathPose, follow_tool_path
from robocram.projection.torso import move_torso
from robocram.tf import Pose, PoseLike, PoseStamped, Vector3

Target = PoseStamped | PoseLike  # a goal pose: stamped (any known frame) or in map
Perceived = ObjectDesignator | list[ObjectDesignator]
DIRECTION_REACH = 100.0  # [m] looking along a direction aims at a point this far away


class ProjectionProcessModule(MotionProcessModule):
    """A process module of a projected robot, for one resource of the motion table."""

    name: ClassVar[str] = ""

    def __init__(self, robot: ProjectedRobot) -> None:
        super().__init__()
        self.robot = robot


class NavigationPM(ProjectionProcessModule):
    """The base: ``move_base(Pose)``."""

    name = "projection_navigation"
    resource = "navigation"

    def move_base(self, pose: Target) -> Pose:
        """Drive the base to ``pose``."""
        return drive(self.robot, pose)


class TorsoPM(ProjectionProcessModule):
    """The torso: ``move_torso(Value)``."""

    name = "projection_torso"
    resource = "torso"

    def move_torso(self, value: float) -> float:
        """Set the torso joint to ``value`` [m | rad]."""
        return move_torso(self.robot, value)


class PtuPM(ProjectionProcessModule):
    """The head (pan-tilt unit or neck arm): ``move_head(pose | frame | direction | joints, X)``."""

    name = "projection_ptu"
    resource = "ptu"

    def move_head(self, mode: str, goal: object) -> dict[str, float]:
        """Point the camera at a pose, a frame, or along a direction; or turn the head's
        joints to a configuration (``joints``)."""
        robot = self.robot
        if mode == "joints":
            return turn_head_joints(robot, goal)
        if mode == "pose":
            if isinstance(goal, str | Mapping):
                raise ProjectionError(f"looking at a pose needs a pose, got {goal!r}")
            point = robot.in_map(cast(Target, goal)).position
        elif mode == "frame":
            point = robot.frame_pose(str(goal)).position
        elif mode == "direction":
            point = self._along(goal)
        else:
            raise ProjectionError(
                f"move_head mode {mode!r} is none of pose, frame, direction, joints"
            )
        return look_at(robot, point)

    def _along(self, direction: object) -> Vector3:
        vector = direction.position if isinstance(direction, PoseStamped) else direction
        d = np.asarray(vector, float)
        if d.shape != (3,) or np.linalg.norm(d) < 1e-9:
            raise ProjectionError(f"looking direction must be a non-zero 3-D vector, got {vector}")
        base = self.robot.base_pose()
        camera = self.robot.world.view.camera(self.robot.name).pose.position
        rotated = base.matrix()[:3, :3] @ (d / np.linalg.norm(d))
        far = np.asarray(camera) + DIRECTION_REACH * rotated
        return (float(far[0]), float(far[1]), float(far[2]))


class PerceptionPM(ProjectionProcessModule):
    """The camera: ``detect(ObjectDesig)`` and ``inspect(ObjectDesig)``."""

    name = "projection_perception"
    resource = "perception"

    def detect(self, desig: ObjectDesignator) -> Perceived:
        """The perceived designator(s) fitting ``desig``."""
        return detect(self.robot, desig)

    def inspect(self, desig: ObjectDesignator) -> Perceived:
        """Inspect one object: the simulated camera sees all there is when it detects."""
        return detect(self.robot, desig)


class GripperPM(ProjectionProcessModule):
    """The grippers: ``move_gripper_joint(Arm, open | close | grip | Position, Effort)``."""

    name = "projection_grippers"
    resource = "grippers"

    def move_gripper_joint(
        self, gripper: str, action: str | float, effort: float | str
    ) -> dict[str, float] | str:
        """Open, close or grip with ``gripper``'s hand, or set it to a position [rad | m]."""
        arm_name = self.robot.description.arm_called(gripper)
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
    """The arms: ``move_tcp`` and ``move_joints``, one arm or both sides."""

    name = "projection_arms"
    resource = "arms"

    def _arm(self, word: str) -> str:
        return self.robot.description.arm_called(word)

    def move_tcp(self, arm: str, pose: Target, mode: str, touching: str = "none") -> Pose:
        """Put ``arm``'s tool frame at ``pose``, avoiding collisions as ``mode`` says (an
        ``allow_hand`` hand may touch ``touching`` only; ``none``: any object)."""
        named = None if touching == "none" else str(touching)
        return move_tcp(self.robot, self._arm(arm), pose, mode, touching=named)

    def move_tcp_both(self, left: Target, right: Target, mode: str) -> tuple[Pose, ...]:
        """Move the tool frames of the arms on the left and the right side."""
        goals = zip(SIDES, (left, right), strict=True)
        return tuple(move_tcp(self.robot, self._arm(side), pose, mode) for side, pose in goals)

    def move_joints(
        self, arm: str, configuration: object, mode: str = "avoid_all", touching: str = "none"
    ) -> dict[str, float]:
        """Set ``arm``'s joints, the way there checked as ``mode`` says (an ``allow_hand``
        hand may touch ``touching`` only; ``none``: any object)."""
        return move_joints(self.robot, self._arm(arm), configuration, mode, _named(touching))

    def move_joints_both(
        self, left: object, right: object, mode: str = "avoid_all"
    ) -> tuple[dict[str, float], ...]:
        """Set the joints of the arms on the left and the right side."""
        goals = zip(SIDES, (left, right), strict=True)
        return tuple(
            move_joints(self.robot, self._arm(side), config, mode) for side, config in goals
        )

    def move_part(self, arm: str, part: str, joint: str, handle: str, goal: float) -> float:
        """Hold ``handle`` of ``part`` and move its ``joint`` to ``goal`` (a drawer, a door)."""
        return move_part(self.robot, self._arm(arm), part, joint, handle, float(goal)).reached


def _named(word: str) -> str | None:
    return None if word == "none" else str(word)


def _point(point: object) -> PoseLike | None:
    if point == "none":
        return None
    return Pose.coerce(point)  # type: ignore[arg-type]  # a pose or its tuples; Pose says


def _share(needed: object) -> float:
    """The share of a tool path a motion asks for (``none``: any, 0)."""
    if needed == "none":
        return 0.0
    if isinstance(needed, bool) or not isinstance(needed, int | float) or not 0 <= needed <= 1:
        raise ProjectionError(f"a tool path's needed share is a number in [0, 1], got {needed!r}")
    return float(needed)


class ToolPM(ProjectionProcessModule):
    """Held tools along paths: ``move_tool_path``, ``pour`` and ``cut``."""

    name = "projection_tools"
    resource = "tools"

    def _arm(self, word: str) -> str:
        return self.robot.description.arm_called(word)

    def move_tool_path(
        self,
        arm: str,
        path: Sequence[PathPose],
        tool: str,
        point: object,
        contacts: object,
        needed: object = "none",
    ) -> ToolPathAnswer:
        """Move the held ``tool``'s ``point`` along ``path``, touching only ``contacts``."""
        robot, named, arm_name = self.robot, _named(tool), self._arm(arm)
        share = _share(needed)
        return follow_tool_path(robot, arm_name, path, named, _point(point), contacts, share)

    def pour(
        self,
        arm: str,
        path: Sequence[PathPose],
        source: str,
        point: object,
        target: str,
        amount: float,
        needed: object = "none",
    ) -> PouringAnswer:
        """Tilt the held ``source`` along ``path`` over ``target``, pouring ``amount`` [ml]."""
        arm_name, share = self._arm(arm), _share(needed)
        return pour(self.robot, arm_name, path, source, _point(point), target, amount, share)

    def cut(
        self,
        arm: str,
        path: Sequence[PathPose],
        tool: str,
        point: object,
        contacts: object,
        obj: str,
        cuts: Sequence[float],
        needed: object = "none",
    ) -> CuttingAnswer:
        """Saw ``obj`` with the held ``tool`` along ``path``, at ``cuts`` along its axis."""
        arm_name, share = self._arm(arm), _share(needed)
        return cut(self.robot, arm_name, path, tool, _point(point), contacts, obj, cuts, share)


class FlyingPM(ProjectionProcessModule):
    """The body of a flying robot: ``fly(Pose)``."""

    name = "projection_flying"
    resource = "flying"

    def fly(self, pose: Target) -> Pose:
        """Fly straight to ``pose``."""
        return fly(self.robot, pose)


class LegsPM(ProjectionProcessModule):
    """The legs of a legged robot: ``crouch(Depth)``."""

    name = "projection_legs"
    resource = "legs"

    def crouch(self, depth: float) -> float:
        """Bend the legs until the body stands ``depth`` [m] below standing (0: stand up)."""
        return crouch(self.robot, float(depth))


class DistanceSensorPM(ProjectionProcessModule):
    """The range sensor of a flying robot: ``sense_distance(Direction)``."""

    name = "projection_distance_sensor"
    resource = "distance_sensor"

    def sense_distance(self, direction: Sequence[float]) -> float:
        """The range [m] along ``direction`` (body frame)."""
        return sense_distance(self.robot, direction)


PROJECTION_MODULES: dict[str, type[ProjectionProcessModule]] = {
    cls.resource: cls
    for cls in (
        NavigationPM,
        TorsoPM,
        PtuPM,
        PerceptionPM,
        GripperPM,
        ArmPM,
        ToolPM,
        FlyingPM,
        LegsPM,
        DistanceSensorPM,
    )
}
