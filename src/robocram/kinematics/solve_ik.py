"""IK and FK for the arms of robot descriptions: the layer's public entry points.

Targets and results are in the robot's URDF root link (``base_footprint`` for the PR2 and
HSR), i.e. relative to the robot base, not the map: transform map poses first.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from robocram.kinematics.arm_selection import loaded
from robocram.kinematics.base_ik_solver import BaseIKSolver
from robocram.kinematics.ik_result import IKResult
from robocram.kinematics.ik_solver import CollisionCheck, IKSettings, IKSolver
from robocram.kinematics.kinematics_cache import KinematicsCache
from robocram.kinematics.planar_base import PlanarBase
from robocram.kinematics.robot_kinematics import robot_kinematics
from robocram.robots import RobotDescription
from robocram.tf import Pose, PoseStamped


def solve_ik(
    description: RobotDescription | str,
    arm: str,
    target: Pose | PoseStamped,
    *,
    seed: Mapping[str, float] | None = None,
    frame: str | None = None,
    use_torso: bool = False,
    max_restarts: int = 100,
    max_iterations: int = 60,
    collision_check: CollisionCheck | None = None,
    position_tolerance: float = 1e-3,
    orientation_tolerance: float = 1e-2,
    random_seed: int = 0,
    stop_check: Callable[[], None] | None = None,
    base: PlanarBase | None = None,
    cache: KinematicsCache | None = None,
) -> IKResult:
    """Joint values that put ``frame`` (default: the arm's tool frame) at ``target``.

    Args:
        description: a loaded description, or a built-in robot's name ("pr2", "hsrb", ...).
        arm: a key of ``description.arms`` ("left", "right", "arm", "neck").
        target: a Pose in the URDF root link (``base_footprint``), or a PoseStamped in the
            root link or any other link/frame of the robot (placed by FK of ``seed``).
        seed: current joint values [rad | m]; the start of the search, and the value of
            every joint IK does not move (the torso when ``use_torso`` is False).
        use_torso: also move ``description.torso_joint``.
        max_restarts: descents after the first one (from the seed); with
            ``max_iterations`` steps per descent, the whole budget. It is counted, not
            timed, so the answer does not depend on the machine's load.
        collision_check: called with each converged solution; True rejects it (restart).
        position_tolerance: [m]. orientation_tolerance: [rad].
        random_seed: seeds the random restarts (default 0): the same query and seed
            give bit-identical joint values.
        stop_check: called before every descent (a few milliseconds apart); it ends the
            search by raising, e.g. a task's ``checkpoint``. It never changes the answer.
        base: also move the base within this travel (planar x, y, yaw before the root
            link); the move comes back in ``IKResult.base_motion``. None keeps it still;
            :func:`~robocram.kinematics.base_in_ik` says whether the description wants it.
        cache: where the solver and its start table are kept; by default the cache of the
            description's model (built on the first query of an arm, kept with the model).

    Returns:
        An IKResult; ``success`` False when no solution was found within the budget.
    """
    solver = _solver(description, arm, use_torso, frame, base, cache)
    settings = IKSettings(
        position_tolerance=position_tolerance,
        orientation_tolerance=orientation_tolerance,
        max_restarts=max_restarts,
        max_iterations=max_iterations,
    )
    return solver.solve(
        target, dict(seed or {}), settings, collision_check, random_seed, stop_check
    )


def forward_kinematics(
    description: RobotDescription | str, joint_positions: Mapping[str, float], frame: str
) -> Pose:
    """Pose of ``frame`` in the URDF root link for the given joint values [rad | m].

    Joints not given sit at the value nearest 0 within their limits; mimic joints follow
    their masters.
    """
    return robot_kinematics(loaded(description)[1]).frame_pose(frame, joint_positions)


def reachable(
    description: RobotDescription | str,
    arm: str,
    target: Pose | PoseStamped,
    *,
    seed: Mapping[str, float] | None = None,
    frame: str | None = None,
    use_torso: bool = False,
    base: PlanarBase | None = None,
    cache: KinematicsCache | None = None,
) -> bool:
    """Whether ``target`` may be reachable: False only when it is certainly out of reach.

    A cheap pre-check (tens of microseconds, no descent) for callers that try many
    targets, such as a costmap looking for where to stand: the target position lies
    beyond the sum of the arm's link lengths (plus the torso's travel when ``use_torso``)
    from its first joint. True says only "maybe": :func:`solve_ik` decides. Arguments are
    those of :func:`solve_ik`.
    """
    solver = _solver(description, arm, use_torso, frame, base, cache)
    return solver.reachable(target, dict(seed or {}))


def _solver(
    description: RobotDescription | str,
    arm: str,
    use_torso: bool,
    frame: str | None,
    base: PlanarBase | None,
    cache: KinematicsCache | None,
) -> IKSolver:
    """The cached solver for a query, with the base in the chain when ``base`` is given."""
    if base is None:
        return IKSolver.cached(description, arm, use_torso, frame, cache=cache)
    return BaseIKSolver.cached(description, arm, use_torso, frame, base, cache=cache)
