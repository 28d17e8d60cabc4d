"""IK along nearby tool poses with the base moving as part of the arm: whole-body steps.

An arm with fewer than six joints (the HSR's five, the Stretch's lift and telescope) cannot
keep a tool on a curve by itself: wiping a strip sideways needs the base to slide with
the hand. :func:`track_ik` solves each pose with the arm alone; here the planar base's
virtual joints (:mod:`~robocram.kinematics.planar_base`) are variables of the same chain,
solved together from the pose before, so base and arm move at once, in small steps.

A holonomic base moves in ``x``, ``y`` and ``yaw``. A differential one only drives along
its heading (``x``): turning while it drives along a fixed line would slide it sideways,
which its wheels cannot do. The variables' values are relative to where the base stands
when the path starts (:data:`~robocram.kinematics.planar_base.BASE_JOINTS` at zero).
"""

from __future__ import annotations

import time
from collections.abc import Iterable, Iterator, Mapping

import numpy as np

from robocram.kinematics.arm_chain import ArmChain, FloatArray
from robocram.kinematics.arm_selection import arm_description, arm_joints, loaded
from robocram.kinematics.descent import Best, IKSettings, descend
from robocram.kinematics.ik_result import IKResult
from robocram.kinematics.kinematics_cache import KinematicsCache
from robocram.kinematics.planar_base import (
    BASE_JOINTS,
    BASE_X_JOINT,
    PlanarBase,
    for_robot,
)
from robocram.kinematics.robot_kinematics import pose_to_se3, robot_kinematics
from robocram.kinematics.track_ik import descended
from robocram.robots import RobotDescription
from robocram.tf import Pose

WHOLE_BODY_ITERATIONS = 30  # descent steps per pose (a pose 2 cm on converges in a few)


def whole_body_base_joints(base: PlanarBase) -> tuple[str, ...]:
    """The virtual base joints a whole-body step moves: x, y, yaw; a differential base's
    drive along its heading only."""
    return (BASE_X_JOINT,) if base.differential else BASE_JOINTS


def whole_body_chain(description: RobotDescription, arm: str, base: PlanarBase) -> ArmChain:
    """``arm``'s chain behind the base's virtual joints that a whole-body step moves
    (kept with the model: one per arm, base and drive)."""
    desc, model = loaded(description)
    cache = KinematicsCache.of(model)
    base = for_robot(desc, base)
    frame = arm_description(desc, arm).tool_frame
    key = ("whole-body", model, arm, base, frame)
    chain = cache.solvers.get(key)
    if isinstance(chain, ArmChain):
        return chain
    kin = robot_kinematics(cache.planar_model(model, base))
    joints = (*whole_body_base_joints(base), *arm_joints(desc, arm))
    built = ArmChain(kin, joints, frame)
    cache.solvers.put(key, built)
    return built


def track_whole_body(
    description: RobotDescription,
    arm: str,
    targets: Iterable[Pose],
    seed: Mapping[str, float],
    base: PlanarBase,
    goal: Mapping[str, float] | None = None,
) -> Iterator[IKResult]:
    """Lazily, the answer for each of ``targets`` (the root link where the base stands at
    the start, in order), base and arm solved together from the answer before.

    ``seed`` holds the robot's joints now (the base's virtual joints, absent, start at
    zero). The answers' ``joint_positions`` hold the arm's joints and the virtual base
    joints of :func:`whole_body_base_joints`. Stop asking after a failure.

    ``goal``: a solution for the last target (virtual base joints and the arm's, as a
    collision-checked IK query found it). Each descent then starts from the answer before
    moved its share of the way to it, so base and arm share the motion as that solution
    does (a base kept off a wall) while the tool stays on the targets.
    """
    chain = whole_body_chain(description, arm, base)
    settings = IKSettings(max_restarts=0, max_iterations=WHOLE_BODY_ITERATIONS)
    values = dict(seed)
    b = chain.offsets(values)  # the other virtual joints and the torso stay where they are
    x = _start(chain, values)
    poses = list(targets)
    toward = None if goal is None else _start(chain, {**values, **goal})
    for k, pose in enumerate(poses):
        t0 = time.perf_counter()
        if toward is not None:
            x = x + (toward - x) / (len(poses) - k)
        best = Best(x)
        run = descend(chain, x, pose_to_se3(pose), b, settings, best)
        if not run.converged:
            yield IKResult(
                success=False,
                position_error=best.position_error,
                orientation_error=best.orientation_error,
                iterations=run.iterations,
                elapsed=time.perf_counter() - t0,
            )
            return
        x = chain.wrap_continuous(run.x, x)
        yield descended(chain, x, best, run.iterations, t0)


def _start(chain: ArmChain, values: Mapping[str, float]) -> FloatArray:
    """The chain's variables at ``values`` (the base's at zero: where it stands)."""
    x = np.array([float(values.get(v, 0.0)) for v in chain.variables])
    return np.minimum(np.maximum(x, chain.lower), chain.upper)
