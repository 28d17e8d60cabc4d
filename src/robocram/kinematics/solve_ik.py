"""IK and FK for the arms of robot descriptions: the layer's public entry points.

Targets and results are in the robot's URDF root link (``base_footprint`` for the PR2 and
HSR), i.e. relative to the robot base, not the map: transform map poses first.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from robocram.kinematics.arm_selection import loaded
from robocram.kinematics.base_ik_solver import BaseIKSolver
from robocram.kinematics.described_robot import RobotRef, description_of
from robocram.kinematics.ik_options import DEFAULT_IK, IKOptions
from robocram.kinematics.ik_result import IKResult
from robocram.kinematics.ik_solver import CollisionCheck, IKSolver
from robocram.kinematics.kinematics_cache import KinematicsCache
from robocram.kinematics.robot_kinematics import robot_kinematics
from robocram.robots import RobotDescription
from robocram.tf import Pose, PoseStamped


def solve_ik(
    robot: RobotRef,
    arm: str,
    target: Pose | PoseStamped,
    *,
    seed: Mapping[str, float] | None = None,
    options: IKOptions = DEFAULT_IK,
    collision_check: CollisionCheck | None = None,
    stop_check: Callable[[], None] | None = None,
    cache: KinematicsCache | None = None,
) -> IKResult:
    """Joint values that put ``options.frame`` (default: the arm's tool frame) at ``target``.

    Args:
        robot: a loaded description, a built-in robot's name ("pr2", "hsrb", ...), or a
            robot carrying its description (the world's ``RobotHandle``).
        arm: a key of ``description.arms`` ("left", "right", "arm", "neck").
        target: a Pose in the URDF root link (``base_footprint``), or a PoseStamped in the
            root link or any other link/frame of the robot (placed by FK of ``seed``).
        seed: current joint values [rad | m]; the start of the search, and the value of
            every joint IK does not move (the torso unless ``options.use_torso``).
        options: the chain (frame, torso, base), tolerances, budget and random seed
            (:class:`IKOptions`); the same query and options give bit-identical answers.
        collision_check: called with each converged solution; True rejects it (restart).
        stop_check: called before every descent (a few milliseconds apart); it ends the
            search by raising, e.g. a task's ``checkpoint``. It never changes the answer.
        cache: where the solver and its start table are kept; by default the cache of the
            description's model (built on the first query of an arm, kept with the model).

    Returns:
        An IKResult; ``success`` False when no solution was found within the budget.
    """
    solver = _solver(description_of(robot), arm, options, cache)
    return solver.solve(
        target,
        dict(seed or {}),
        options.settings(),
        collision_check,
        options.random_seed,
        stop_check,
    )


def forward_kinematics(robot: RobotRef, joint_positions: Mapping[str, float], frame: str) -> Pose:
    """Pose of ``frame`` in the URDF root link for the given joint values [rad | m].

    Joints not given sit at the value nearest 0 within their limits; mimic joints follow
    their masters.
    """
    return robot_kinematics(loaded(description_of(robot))[1]).frame_pose(frame, joint_positions)


def reachable(
    robot: RobotRef,
    arm: str,
    target: Pose | PoseStamped,
    *,
    seed: Mapping[str, float] | None = None,
    options: IKOptions = DEFAULT_IK,
    cache: KinematicsCache | None = None,
) -> bool:
    """Whether ``target`` may be reachable: False only when it is certainly out of reach.

    A cheap pre-check (tens of microseconds, no descent) for callers that try many
    targets, such as a costmap looking for where to stand: the target position lies
    beyond the sum of the arm's link lengths (plus the torso's travel when
    ``options.use_torso``) from its first joint. True says only "maybe": :func:`solve_ik`
    decides. Arguments are those of :func:`solve_ik`; only the options' chain counts.
    """
    solver = _solver(description_of(robot), arm, options, cache)
    return solver.reachable(target, dict(seed or {}))


def _solver(
    description: RobotDescription,
    arm: str,
    options: IKOptions,
    cache: KinematicsCache | None,
) -> IKSolver:
    """The cached solver for a query, with the base in the chain when the options move it."""
    use_torso, frame, base = options.use_torso, options.frame, options.base
    if base is None:
        return IKSolver.cached(description, arm, use_torso, frame, cache=cache)
    return BaseIKSolver.cached(description, arm, use_torso, frame, base, cache=cache)
