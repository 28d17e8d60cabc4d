"""A followed trajectory is checked again when the world changed since it was planned.

A trajectory was checked against the world as it stood when it was planned. Following
it, the robot stops at each point, and another task (or whoever planned it earlier) may
have added or moved a body meanwhile. The world's change counters say whether anything
was written at all (one comparison per point) and which bodies to look at; those that
really stand otherwise are checked against the rest of the path: the robot and what it
carries are put at each remaining point, and a contact with a changed body they did not
have where they stand stops the motion before that point, with ``NavigationPathBlocked``,
``TorsoPathBlocked``, ``PtuPathBlocked``, ``GripperPathBlocked`` or ``ManipulationPathBlocked``
(by the motion's kind) naming the body.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.execution.failures import (
    GripperPathBlocked,
    ManipulationPathBlocked,
    NavigationPathBlocked,
    PtuPathBlocked,
    TorsoPathBlocked,
)
from robocram.execution.failures.plan_failure import PlanFailure
from robocram.motion import BASE_JOINTS, BODY_JOINTS, JointTrajectory
from robocram.motion.crouch_path import CROUCH_KIND, is_height_and_joints, put_height_and_joints
from robocram.motion.whole_body_scene import is_whole_body, put_base_and_joints
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import BodyStamps, World, WorldObject, body_stamps, changed_bodies

# the failure a blocked motion of each kind raises (CRAM's, as the planners raise them)
BLOCKED_BY_KIND: dict[str, type[PlanFailure]] = {
    "torso": TorsoPathBlocked,
    "head": PtuPathBlocked,
    "gripper": GripperPathBlocked,
    CROUCH_KIND: TorsoPathBlocked,  # the body's way down or up
}


def planned_against(robot: ProjectedRobot) -> BodyStamps:
    """What a motion of ``robot`` planned now is checked against: every other body."""
    return body_stamps(robot.world, _others(robot))


@dataclass
class PathWatch:
    """The bodies a trajectory was checked against, watched while it is followed."""

    robot: ProjectedRobot
    trajectory: JointTrajectory
    checked: BodyStamps
    seen: int = -1  # the world's clock when it was last looked at (-1: the check's)

    def blocked(self, reached: int) -> tuple[int, PlanFailure] | None:
        """If a body changed since the check and a remaining point (from index
        ``reached``) touches it: that point's index and the failure naming the body."""
        world = self.robot.world
        tick = world.versions.tick
        if tick == (self.checked.tick if self.seen < 0 else self.seen):
            return None  # nothing was written since: nothing to look at
        self.seen = tick
        changed = changed_bodies(world, self.checked, _others(self.robot))
        if not changed:
            return None
        hit = self._first_contact(reached, set(changed))
        self.checked = planned_against(self.robot)  # checked again from here on
        self.seen = world.versions.tick
        if hit is None:
            return None
        index, part, body = hit
        return index, self._failure(index, part, body)

    def _first_contact(self, start: int, watched: set[str]) -> tuple[int, str, str] | None:
        """The first point from ``start`` where the robot or what it carries touches one
        of ``watched`` as it does not where it stands: ``(index, its link, the body)``."""
        world = self.robot.world
        moving = [self.robot.name, *self.robot.handle.holding()]
        ignore = [o for o in world.objects() if o.name not in watched or o.name in moving]
        before = _contacts(world, moving, ignore)
        names = self.trajectory.joint_names
        points = self.trajectory.points
        pose, joints = world.pose(self.robot.name), world.joint_states(self.robot.name)
        try:
            for index in range(start, len(points)):
                _pose(self.robot, names, tuple(points[index].positions))
                new = _contacts(world, moving, ignore) - before
                if new:
                    part, body = min(new)
                    return index, part, body
        finally:
            if names in (BASE_JOINTS, BODY_JOINTS):
                world.set_pose(self.robot.name, pose)
            elif is_whole_body(names):
                world.set_pose(self.robot.name, pose)
                world.set_joint_states(self.robot.name, {n: joints[n] for n in names[3:]})
            elif is_height_and_joints(names):
                world.set_pose(self.robot.name, pose)
                world.set_joint_states(self.robot.name, {n: joints[n] for n in names[1:]})
            else:
                world.set_joint_states(self.robot.name, {n: joints[n] for n in names})
        return None

    def _failure(self, index: int, part: str, body: str) -> PlanFailure:
        count = len(self.trajectory.points)
        fraction = index / max(count - 1, 1)
        message = (
            f"{body!r} changed after {self.robot.name}'s {self.trajectory.kind} motion was "
            f"planned and now blocks it at point {index} of {count} ({part} would touch it); "
            "the robot stopped before it"
        )
        if self.trajectory.joint_names in (BASE_JOINTS, BODY_JOINTS):
            return NavigationPathBlocked(message, colliding=[body], path_fraction=fraction)
        blocked: type[PlanFailure] = BLOCKED_BY_KIND.get(
            self.trajectory.kind, ManipulationPathBlocked
        )
        return blocked(message, colliding_pairs=((part, body),), path_fraction=fraction)


def _others(robot: ProjectedRobot) -> list[str]:
    """Every body but the robot and what it carries."""
    skip = {robot.name, *robot.handle.holding()}
    return [o.name for o in robot.world.objects() if o.name not in skip]


def _contacts(world: World, moving: list[str], ignore: list[WorldObject]) -> set[tuple[str, str]]:
    """``(robot link or carried object, body)`` pairs in contact, ``ignore`` left out."""
    found = set()
    for name in moving:
        for link, other, _ in world.contacts.link_pairs_in_contact(name, ignore):
            found.add((link if name == moving[0] else name, other.name))
    return found


def _pose(robot: ProjectedRobot, names: tuple[str, ...], values: tuple[float, ...]) -> None:
    """Put the robot at ``values`` of ``names`` (what it carries follows)."""
    world, name = robot.world, robot.name
    named = dict(zip(names, values, strict=True))
    if names == BODY_JOINTS:
        turn = quat.from_euler(named["roll"], named["pitch"], named["yaw"])
        world.set_pose(name, Pose((named["x"], named["y"], named["z"]), turn))
    elif names == BASE_JOINTS:
        height = world.pose(name).position[2]
        turn = quat.from_euler(0.0, 0.0, named["yaw"])
        world.set_pose(name, Pose((named["x"], named["y"], height), turn))
    elif is_whole_body(names):
        put_base_and_joints(robot.handle, named)
    elif is_height_and_joints(names):
        put_height_and_joints(robot.handle, named)
    else:
        world.set_joint_states(name, named)
