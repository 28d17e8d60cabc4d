"""Handles the driver's robot holds, so a drawer or door moves with the hand that pulls it.

A real drawer follows the hand holding its handle; the driver simulates no dynamics, so
it does this kinematically: a gripper closing with a handle of an articulated environment
(a link of a non-robot object with joints) at its tool frame holds it, and after every
step of an arm trajectory the handle's joint is set so that the handle stays where the
hand holds it (a few Gauss-Newton steps along the joint, within its limits). Objects
resting in the moving link (a bowl in a drawer) ride along, as in projection. Opening
the gripper lets go.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from robocram.projection import ProjectedRobot
from robocram.projection.articulation import moving_link, resting_in
from robocram.tf import Pose
from robocram.world import RobotObject

HANDLE_REACH = 0.03  # [m] a handle link this close to the closing tool frame is held
PROBE = 1e-3  # [m | rad] joint change used to see which joint moves a handle
FOLLOW_STEPS = 4  # Gauss-Newton steps per update


@dataclass(frozen=True)
class HeldHandle:
    """A handle ``link`` of ``part`` held by ``arm``: ``joint`` moves it; ``in_tool`` is
    the handle's pose in the tool frame when the gripper closed; ``riders`` move along."""

    arm: str
    part: str
    joint: str
    link: str
    in_tool: Pose
    riders: tuple[str, ...]


class HeldHandles:
    """The handles the robot's grippers hold now (one driver, all goals; under its lock)."""

    def __init__(self) -> None:
        self.held: list[HeldHandle] = []

    def grasp(self, robot: ProjectedRobot, arm: str) -> HeldHandle | None:
        """Hold the handle at ``arm``'s tool frame, if there is one; return it."""
        world = robot.world
        tool = world.link_pose(robot.name, robot.arm(arm).tool_frame)
        near = [
            (math.dist(tool.position, world.link_pose(obj, link).position), obj.name, link)
            for obj in world.objects()
            if not isinstance(obj, RobotObject) and world.joint_states(obj)
            for link in world.link_names(obj)
        ]
        close = [entry for entry in near if entry[0] <= HANDLE_REACH]
        if not close:
            return None
        _, part, link = min(close)
        joint = _moving_joint(robot, part, link)
        if joint is None:
            return None
        riders = tuple(resting_in(robot, part, moving_link(robot, part, joint)))
        for rider in riders:
            world.attach(rider, part, moving_link(robot, part, joint))
        in_tool = tool.inverse() * world.link_pose(part, link)
        held = HeldHandle(arm, part, joint, link, in_tool, riders)
        self.held.append(held)
        return held

    def release(self, robot: ProjectedRobot, arm: str) -> None:
        """Let go of what ``arm`` holds; riders stay where the part took them."""
        for held in [h for h in self.held if h.arm == arm]:
            for rider in held.riders:
                robot.world.detach(rider)
            self.held.remove(held)

    def follow(self, robot: ProjectedRobot) -> None:
        """Move each held part's joint so its handle is where the hand holds it now."""
        world = robot.world
        for held in self.held:
            tool = world.link_pose(robot.name, robot.arm(held.arm).tool_frame)
            wanted = np.asarray((tool * held.in_tool).position)
            limits = world.bodies.joint_limits(held.part, held.joint)
            value = world.joint_states(held.part)[held.joint]
            for _ in range(FOLLOW_STEPS):
                here = _handle_at(robot, held, value)
                rate = (_handle_at(robot, held, value + PROBE) - here) / PROBE
                norm = float(rate @ rate)
                if norm < 1e-12:
                    break
                value = limits.clamp(value + float((wanted - here) @ rate) / norm)
            world.set_joint_states(held.part, {held.joint: value})


def _handle_at(robot: ProjectedRobot, held: HeldHandle, value: float) -> np.ndarray:
    robot.world.set_joint_states(held.part, {held.joint: value})
    return np.asarray(robot.world.link_pose(held.part, held.link).position)


def _moving_joint(robot: ProjectedRobot, part: str, link: str) -> str | None:
    """The joint of ``part`` that moves ``link`` (None if none does)."""
    world = robot.world
    start = world.joint_states(part)
    before = world.link_pose(part, link).position
    for joint, value in start.items():
        limits = world.bodies.joint_limits(part, joint)
        probe = value + PROBE if value + PROBE <= limits.upper else value - PROBE
        world.set_joint_states(part, {joint: probe})
        moved = math.dist(before, world.link_pose(part, link).position) > PROBE / 10
        world.set_joint_states(part, {joint: value})
        if moved:
            return joint
    return None
