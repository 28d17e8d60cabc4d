"""The failure of a look whose head or arm motion runs into something."""

from __future__ import annotations

from robocram.execution.failures import ManipulationPathBlocked, PtuPathBlocked
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Vector3


def look_blocked(
    robot: ProjectedRobot, target_in_map: Vector3, blocked: ManipulationPathBlocked, part: str
) -> PtuPathBlocked:
    """``PtuPathBlocked`` naming the target, what collides and where: ``part`` did not move."""
    return PtuPathBlocked(
        f"{robot.name} cannot turn its {part} to look at {tuple(target_in_map)}: {blocked}; "
        f"the {part} did not move",
        target=tuple(target_in_map),
        colliding_pairs=blocked.colliding_pairs,
        path_fraction=blocked.path_fraction,
    )
