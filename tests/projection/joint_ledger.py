"""The joint ledger: a trajectory listener, independent of the planner, that reads the
robot's joint states and base pose before the first motion and at each reported trajectory.

Between two trajectories only the joints the later one names (and their mimic followers),
or for a base trajectory only the base, may change; a joint trajectory starts where its
joints were and ends where they are; after a motion nothing has changed since its last
trajectory. Shared by the no-teleport tests and the session's kitchen transports
(``tests/kitchen_transports.py``).
"""

from __future__ import annotations

from typing import Any

import pytest

from robocram.execution import perform
from robocram.motion import BASE_JOINTS, JointTrajectory
from robocram.world import World

TOL = 1e-9  # [m | rad] a trajectory's ends against the joints read


class Ledger:
    """A trajectory listener keeping the robot's joint states at each trajectory."""

    def __init__(self, world: World, robot: str) -> None:
        self.world, self.robot = world, robot
        self.model = world.robot(robot).description.model
        self.last = dict(world.joint_states(robot))
        self.pose = world.pose(robot)
        self.seen: list[JointTrajectory] = []

    def followers(self, joints: tuple[str, ...]) -> set[str]:
        """``joints`` and every joint that mimics one of them, transitively."""
        found = set(joints)
        grew = True
        while grew:
            more = {
                j.name for j in self.model.joints.values() if j.mimic and j.mimic.joint in found
            }
            grew = not more <= found
            found |= more
        return found

    def __call__(self, trajectory: JointTrajectory) -> None:
        now, pose = dict(self.world.joint_states(self.robot)), self.world.pose(self.robot)
        base = trajectory.joint_names == BASE_JOINTS
        assert base or pose.distance_to(self.pose) == 0.0, "the base moved off its trajectory"
        self.pose = pose
        moving = set() if base else self.followers(trajectory.joint_names)
        jumped = {
            j: (self.last[j], v) for j, v in now.items() if j not in moving and v != self.last[j]
        }
        assert not jumped, f"joints {jumped} changed outside the {trajectory.kind} trajectory"
        for joint in () if base else trajectory.joint_names:
            assert trajectory.start[joint] == pytest.approx(self.last[joint], abs=TOL)
            assert trajectory.end[joint] == pytest.approx(now[joint], abs=TOL)
        self.seen.append(trajectory)
        self.last = now

    def assert_still(self) -> None:
        """Nothing moved since the last trajectory."""
        now = dict(self.world.joint_states(self.robot))
        changed = {j for j, v in now.items() if v != self.last[j]}
        assert not changed, f"joints {changed} changed after the last trajectory"
        assert self.world.pose(self.robot).distance_to(self.pose) == 0.0

    def perform(self, motion: Any) -> tuple[Any, list[JointTrajectory]]:
        """Perform ``motion``; its answer and the trajectories it reported."""
        first = len(self.seen)
        try:
            return perform(motion), self.seen[first:]
        finally:
            self.assert_still()
