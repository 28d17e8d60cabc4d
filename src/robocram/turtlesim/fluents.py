"""Fluents over the turtle world: its pose, and whether it left the field."""

from __future__ import annotations

from robocram.execution.fluent import Fluent, derive
from robocram.turtlesim.world import TurtlePose, TurtleWorld


def pose_fluent(world: TurtleWorld) -> Fluent:
    """Return a fluent that follows the turtle's pose (updated on every step)."""
    fluent = Fluent(world.pose, name="turtle_pose")
    world.add_listener(fluent.set)
    return fluent


def out_of_bounds_fluent(world: TurtleWorld, pose: Fluent | None = None) -> Fluent:
    """Return a fluent that is true while the turtle is off the field."""

    def outside(p: TurtlePose) -> bool:
        return not world.in_field(p.x, p.y)

    return derive(outside, pose or pose_fluent(world), name="turtle_out_of_bounds")
