"""IK along a sequence of nearby tool poses, each solved from the previous solution.

A straight tool line (``motion/cartesian_path.py``) asks IK every 2 cm with no
restarts. A descent from the previous waypoint's joints converges there in one or two
steps; the full query (:func:`~robocram.kinematics.solve_ik`) spends two to three times as
long around that descent: the start table's nearest samples, the seed's pose distance, the
result's bookkeeping. So each pose is first descended to from the previous solution, and
only a pose that descent misses gets the full query. Where the full query would start from
the seed anyway (the seed nearest the target, as it nearly always is 2 cm away), the
answers are the same, bit for bit; otherwise the tracked one stays on the arm's branch.
"""

from __future__ import annotations

import time
from collections.abc import Iterable, Iterator, Mapping

from robocram.kinematics.arm_chain import ArmChain, FloatArray
from robocram.kinematics.descent import Best, IKSettings, descend
from robocram.kinematics.ik_result import IKResult
from robocram.kinematics.ik_solver import IKSolver
from robocram.kinematics.robot_kinematics import pose_to_se3
from robocram.robots import RobotDescription
from robocram.tf import Pose


def track_ik(
    description: RobotDescription,
    arm: str,
    targets: Iterable[Pose],
    seed: Mapping[str, float],
    *,
    frame: str | None = None,
    random_seed: int = 0,
) -> Iterator[IKResult]:
    """Lazily, the answer for each of ``targets`` (root link, in order), solved from the
    answer before (the first from ``seed``), as ``solve_ik`` would with
    ``IKOptions(max_restarts=0)``.

    The torso and every joint not of the arm stay at their ``seed`` values. Stop asking
    after a failure: the next pose would start from the failed answer.
    """
    solver = IKSolver.cached(description, arm, False, frame)
    chain = solver.chain
    settings = IKSettings(max_restarts=0)
    values = dict(seed)
    b = chain.offsets(values)  # the held joints (the torso) do not change along the line
    x = solver.start(values)
    for pose in targets:
        t0 = time.perf_counter()
        best = Best(x)
        run = descend(chain, x, pose_to_se3(pose), b, settings, best)
        if run.converged:
            x = chain.wrap_continuous(run.x, x)
            result = descended(chain, x, best, run.iterations, t0)
        else:
            result = solver.solve(pose, values, settings, random_seed=random_seed)
            x = solver.start({**values, **result.joint_positions})
        values.update(result.joint_positions)
        yield result


def descended(chain: ArmChain, x: FloatArray, best: Best, iterations: int, t0: float) -> IKResult:
    """The answer of a descent that converged at ``x`` (started at ``t0``, perf counter)."""
    return IKResult(
        success=True,
        joint_positions=chain.joint_positions(x),
        position_error=best.position_error,
        orientation_error=best.orientation_error,
        iterations=iterations,
        elapsed=time.perf_counter() - t0,
    )
