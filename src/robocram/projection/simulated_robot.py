"""``with simulated_robot(world, "pr2"):`` — CRAM's ``with-simulated-robot``.

The block switches PERFORM to the projection process modules of the robot, binds a
transform tree read live from the world (so ``transform_pose`` works in plans) and is a
top level itself, so plans and PERFORM run directly inside it. The task tree of the block
is available as ``run.tree`` afterwards.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

from robocram.costmaps import CostmapLocations
from robocram.execution import Environment, TaskTree, TopLevel, top_level
from robocram.motion import MotionSettings
from robocram.projection.robot_environment import projection_environment
from robocram.projection.world_frames import LiveTransformTree, WorldFrames
from robocram.tf import using_transform_tree
from robocram.world import RobotObject, World


@dataclass(frozen=True)
class SimulatedRun:
    """What a ``simulated_robot`` block yields: its environment, top level and frames."""

    environment: Environment
    top_level: TopLevel
    transforms: LiveTransformTree

    @property
    def tree(self) -> TaskTree:
        """The task tree of the block (complete once the block has ended)."""
        return self.top_level.tree


@contextmanager
def simulated_robot(
    world: World,
    robot: str | RobotObject | None = None,
    name: str = "simulated-robot",
    locations: CostmapLocations | None = None,
    motion: MotionSettings | None = None,
) -> Iterator[SimulatedRun]:
    """Run the block as a top level on the projected ``robot`` of ``world``.

    Location designators resolve through ``locations`` (default: costmaps on ``world``);
    ``motion`` says how motions are planned (``MotionSettings(plan=False)``: straight
    joint-space segments only, a blocked one fails).
    """
    environment = projection_environment(world, robot, locations, motion)
    transforms = LiveTransformTree(WorldFrames(world))
    runner = top_level(name=name)
    with using_transform_tree(transforms), environment, runner:
        yield SimulatedRun(environment, runner, transforms)
