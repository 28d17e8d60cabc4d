"""What the tool actions ask the knowledge base: which hand holds a tool, and the pose,
box and opening of the objects they act on (typed calls on the predicate table)."""

from __future__ import annotations

from dataclasses import dataclass

from robocram.knowledge import grasp_predicates as gp
from robocram.knowledge import robot_predicates as rp
from robocram.knowledge.world_predicates import ATTACHED, OBJECT_POSE, SUPPORTED_BY
from robocram.logic import current_kb
from robocram.plans.known_robot import current_robot
from robocram.plans.tool_failures import TargetCovered, ToolNotHeld, UnknownToolObject
from robocram.tf import Pose, Vector3

WALL = 0.006  # [m] a container's wall and bottom, as the tool actions assume them


@dataclass(frozen=True)
class ObjectBox:
    """An object's pose in ``map`` and its box ``low``/``high`` [m] in its own frame."""

    name: str
    pose: Pose
    low: Vector3
    high: Vector3

    @property
    def size(self) -> Vector3:
        """Extents [m] along the object's x, y and z."""
        return (
            self.high[0] - self.low[0],
            self.high[1] - self.low[1],
            self.high[2] - self.low[2],
        )

    @property
    def middle(self) -> Vector3:
        """The box's middle, in the object's frame."""
        return (
            0.5 * (self.low[0] + self.high[0]),
            0.5 * (self.low[1] + self.high[1]),
            0.5 * (self.low[2] + self.high[2]),
        )

    def inner_radius(self) -> float:
        """[m] within the walls of a round container (the box's narrower half, less a wall)."""
        return 0.5 * min(self.size[0], self.size[1]) - WALL

    def point(self, x: float, y: float, z: float) -> Vector3:
        """The point ``(x, y, z)`` of the object's frame, in ``map``."""
        return self.pose.transform_point((x, y, z))


def object_box(action: str, name: str) -> ObjectBox:
    """The pose and box of object ``name``.

    Raises:
        UnknownToolObject: the knowledge base knows no pose or no box of it.
    """
    kb = current_kb()
    pose = OBJECT_POSE.first(kb, object=name)
    extent = gp.OBJECT_EXTENT.first(kb, object=name)
    if pose is None or extent is None:
        raise UnknownToolObject(
            f"{action}: the knowledge base knows no pose or box of {name!r}",
            action=action,
            object=name,
        )
    low, high = extent.low, extent.high
    return ObjectBox(name, pose.pose, (low[0], low[1], low[2]), (high[0], high[1], high[2]))


def holding_arm(action: str, tool: str, arm: str | None = None) -> str:
    """The arm whose hand holds ``tool`` (``arm`` if given, checked).

    Raises:
        ToolNotHeld: no hand of the robot (or not ``arm``'s) holds it.
    """
    kb = current_kb()
    robot = current_robot()
    held = ATTACHED.first(kb, robot=robot.name, object=tool)
    for candidate in robot.arms() if arm is None else [arm]:
        link = rp.END_EFFECTOR_LINK.first(kb, robot=robot.name, arm=candidate)
        if held is not None and link is not None and link.link == held.link:
            return candidate
    raise ToolNotHeld(
        f"{action}: {robot.name}'s {arm or 'hands'} do not hold {tool!r}",
        action=action,
        tool=tool,
        robot=robot.name,
    )


def ensure_uncovered(action: str, target: str) -> None:
    """Fail when something rests on ``target`` above its rim (a lid, a plate on a bowl).

    Raises:
        TargetCovered: naming the first such object.
    """
    kb = current_kb()
    box = object_box(action, target)
    rim = box.point(0.0, 0.0, box.high[2])[2]
    for row in SUPPORTED_BY.answers(kb, other=target):
        above = OBJECT_POSE.first(kb, object=row.object)
        if above is not None and above.pose.position[2] >= rim - WALL:
            raise TargetCovered(
                f"{action}: {row.object!r} lies on the opening of {target!r}",
                action=action,
                target=target,
                cover=row.object,
            )
