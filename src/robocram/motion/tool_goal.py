"""What "reached" means for a tool frame, and how an arm configuration is read.

Shared by every environment that moves arms (projection, a robot behind ROS), so a motion
succeeds or fails for the same reasons in both.
"""

from __future__ import annotations

from collections.abc import Mapping

from robocram.execution.failures import ManipulationGoalNotReached
from robocram.motion.errors import MotionError
from robocram.tf import Pose

POSITION_TOLERANCE = 0.01  # [m] between the reached tool frame and the target
ORIENTATION_TOLERANCE = 0.05  # [rad]
IK_RANDOM_SEED = 0  # seeds IK's random restarts in every move_tcp without its own seed


def ensure_reached(
    robot_name: str, arm: str, reached: Pose, target: object, target_in_map: Pose
) -> Pose:
    """Return ``reached`` if it is within tolerance of ``target_in_map``, else raise.

    Shared by every environment that moves a tool (projection, ROS), so "reached" means the
    same everywhere.

    Raises:
        ManipulationGoalNotReached: the tool frame stopped too far from the target.
    """
    error = (reached.distance_to(target_in_map), reached.angle_to(target_in_map))
    if error[0] > POSITION_TOLERANCE or error[1] > ORIENTATION_TOLERANCE:
        raise ManipulationGoalNotReached(
            f"{robot_name}'s {arm} tool frame stopped {error[0]:.3f} m / {error[1]:.3f} rad "
            "from its target",
            arm=arm,
            target=target,
            reached=reached,
            error=error,
        )
    return reached


def joint_values(configuration: object) -> dict[str, float]:
    """Read ``{joint: value}`` from a mapping or a list of ``[joint, value]`` pairs."""
    if isinstance(configuration, Mapping):
        return {str(k): float(v) for k, v in configuration.items()}
    if isinstance(configuration, list | tuple) and all(
        isinstance(p, list | tuple) and len(p) == 2 for p in configuration
    ):
        return {str(k): float(v) for k, v in configuration}
    raise MotionError(
        f"an arm configuration is a {{joint: value}} mapping or [[joint, value], ...], "
        f"got {configuration!r}"
    )
