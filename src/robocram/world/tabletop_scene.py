"""A small tabletop scene: a robot, a table and a mug it can pick from above.

Used by the demo, the pick-up example and the projection tests. Only placement differs per
robot (table height, mug position); the plan that runs in it is the same for all.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.robots import load_description
from robocram.tf import Pose, PoseStamped
from robocram.world.world import World

# robot -> (table height [m], mug (x, y) [m] in map); the robot stands at the origin
_PLACEMENT: dict[str, tuple[float, tuple[float, float]]] = {
    "pr2": (0.70, (0.62, -0.15)),
    "hsrb": (0.42, (0.46, 0.078)),
    "boxy": (0.55, (0.75, -0.25)),
}


@dataclass(frozen=True)
class TabletopScene:
    """A robot and a table with a mug, and the point on the table to look at (map)."""

    world: World
    robot: str
    look_target: PoseStamped


def tabletop_scene(robot: str, world: World | None = None) -> TabletopScene:
    """Floor, ``robot`` at the origin, a table with a mug and a bottle in front of it."""
    name = load_description(robot).name
    if name not in _PLACEMENT:
        raise ValueError(f"no tabletop placement for robot {robot!r}; known: {sorted(_PLACEMENT)}")
    table_height, mug_xy = _PLACEMENT[name]
    world = world if world is not None else World()
    world.add_floor()
    world.add_robot(name, pose=Pose((0.0, 0.0, 0.0)))
    table_x = mug_xy[0] + 0.2
    world.add_box("table", (0.6, 1.0, table_height), pose=Pose((table_x, 0.0, table_height / 2)))
    world.add_item("mug-1", "mug", pose=Pose((*mug_xy, table_height)))
    world.add_item("bottle-1", "bottle", pose=Pose((table_x + 0.15, 0.3, table_height + 0.125)))
    look = PoseStamped("map", (mug_xy[0], mug_xy[1], table_height))
    return TabletopScene(world, name, look)
