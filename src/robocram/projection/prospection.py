"""Prospection: what a plan would do, found by projecting it, with the world left as it was.

CRAM projects a plan to choose between plans and parameters before the robot commits to
one: which grasp, which placing location, which of two ways to clear a table. Here
``prospect(robot, plan)`` runs ``plan`` on the projected robot exactly as
``simulated_robot`` would, then puts the world back (objects, poses, velocities, joints,
attachments; ``world.snapshots.stored_state``) and returns a :class:`Prospect`:
the outcome, the task tree, the trajectories that would be executed and where every
object would end up.

It runs in a fresh execution context, so it may be called from inside a running plan
(the running robot's process modules, task tree and trace listeners are not seen; the
running plan waits while the world is borrowed), and nothing it does is traced into the
caller's trace. Performing the chosen plan afterwards gives the same trajectories, bit for
bit, as its prospect (every random choice is seeded).
"""

from __future__ import annotations

import contextvars
from collections.abc import Callable
from dataclasses import dataclass
from typing import Generic, TypeVar

from robocram.costmaps import CostmapLocations
from robocram.execution import TaskTree
from robocram.execution.failures import PlanFailure
from robocram.motion import JointTrajectory, MotionSettings, trajectory_listener
from robocram.projection.simulated_robot import simulated_robot
from robocram.tf import Pose
from robocram.world import RobotHandle

T = TypeVar("T")


@dataclass(frozen=True)
class Prospect(Generic[T]):
    """What projecting a plan showed: its result or its failure, its task tree, the
    trajectories it would execute and every object's pose at its end (in map)."""

    result: T | None
    failure: PlanFailure | None
    tree: TaskTree
    trajectories: tuple[JointTrajectory, ...]
    poses: dict[str, Pose]

    @property
    def succeeded(self) -> bool:
        """Whether the plan ended without a failure."""
        return self.failure is None

    @property
    def motion_time(self) -> float:
        """How long [s] the robot would move: the trajectories' durations summed."""
        return sum(t.duration for t in self.trajectories)


def prospect(
    robot: RobotHandle,
    plan: Callable[[], T],
    *,
    name: str = "prospection",
    locations: CostmapLocations | None = None,
    motion: MotionSettings | None = None,
) -> Prospect[T]:
    """Project ``plan`` on ``robot`` in its world; the world is as before when it returns.

    A plan failure is the prospect's outcome (:attr:`Prospect.failure`); any other error
    is a fault of the plan or its set-up and is raised (the world put back first).
    """
    world = robot.world
    found: list[JointTrajectory] = []

    def projected() -> Prospect[T]:
        with world.snapshots.stored_state(), trajectory_listener(found.append):
            result: T | None = None
            failure: PlanFailure | None = None
            with simulated_robot(world, robot.name, name, locations, motion) as run:
                try:
                    result = plan()
                except PlanFailure as caught:
                    failure = caught
            poses = {o.name: world.pose(o) for o in world.objects()}
        return Prospect(result, failure, run.tree, tuple(found), poses)

    return contextvars.Context().run(projected)
