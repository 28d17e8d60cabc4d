"""IK benchmark: PR2 right arm, random reachable targets, ours beside pybullet's IK.

Targets: forward kinematics of ``r_gripper_tool_frame`` for uniformly random in-limit arm
configurations (continuous joints in [-pi, pi]; torso and everything else at 0). Every
query starts from the same configuration, the middle of the arm's joint ranges (0 for
continuous joints), which differs from the one that made the target. Success: position
error < 1 cm and orientation error < 0.05 rad, checked by our FK of the returned joints.

Usage: ``python benchmarks/ik_bench.py [count=1000] [random_seed=0]``
"""

from __future__ import annotations

import contextlib
import math
import os
import statistics
import sys
import tempfile
import time
from collections.abc import Callable, Iterator, Mapping
from dataclasses import replace
from pathlib import Path

import numpy as np
import pybullet as pb

from robocram.kinematics import IKSolver, forward_kinematics, solve_ik
from robocram.robots import RobotDescription, RobotModel, load_description
from robocram.tf import Pose

ARM, FRAME = "right", "r_gripper_tool_frame"
POSITION_OK, ORIENTATION_OK = 0.01, 0.05  # [m], [rad]
HEADER = "{:<28} {:>10} {:>9} {:>9} {:>9} {:>9} {:>11}"
ROW = "{:<28} {:>10} {:9.3f} {:9.3f} {:9.3f} {:9.3f} {:>11}"
Solver = Callable[[Pose], Mapping[str, float]]


def targets(desc: RobotDescription, solver: IKSolver, count: int, seed: int) -> list[Pose]:
    rng = np.random.default_rng(seed)
    lo = np.where(np.isfinite(solver.chain.lower), solver.chain.lower, -math.pi)
    hi = np.where(np.isfinite(solver.chain.upper), solver.chain.upper, math.pi)
    configs = (dict(zip(solver.variables, rng.uniform(lo, hi), strict=True)) for _ in range(count))
    return [forward_kinematics(desc, c, FRAME) for c in configs]


def run(name: str, desc: RobotDescription, poses: list[Pose], solve: Solver) -> None:
    limits = {
        j: (desc.model.joints[j].lower, desc.model.joints[j].upper) for j in desc.arms[ARM].joints
    }  # type: ignore[union-attr]
    times, ok, inside = [], 0, 0
    for target in poses:
        t0 = time.perf_counter()
        joints = solve(target)
        times.append((time.perf_counter() - t0) * 1e3)
        reached = forward_kinematics(desc, joints, FRAME)
        ok += (
            reached.distance_to(target) < POSITION_OK and reached.angle_to(target) < ORIENTATION_OK
        )
        inside += all(lo - 1e-9 <= joints[j] <= hi + 1e-9 for j, (lo, hi) in limits.items())  # type: ignore[operator]
    n = len(poses)
    q = statistics.quantiles(times, n=20)
    mean, median = statistics.fmean(times), statistics.median(times)
    print(
        ROW.format(
            name,
            f"{100 * ok / n:.2f} %",
            mean,
            median,
            q[-1],
            max(times),
            f"{100 * inside / n:.2f} %",
        )
    )


def ours(desc: RobotDescription, start: dict[str, float]) -> Solver:
    return lambda target: solve_ik(desc, ARM, target, seed=start).joint_positions


def arm_only_urdf(desc: RobotDescription, folder: str) -> Path:
    """The PR2 with every joint but the arm's fixed, so pybullet's IK cannot use the torso."""
    model = desc.model
    assert model is not None
    arm = set(desc.arms[ARM].joints)
    joints = {
        n: j if n in arm or not j.movable else replace(j, type="fixed", lower=None, upper=None)
        for n, j in model.joints.items()
    }
    path = Path(folder) / "pr2_arm_only.urdf"
    RobotModel(model.name, model.links, joints, model.source).to_urdf(path)
    return path


def pybullet_ik(desc: RobotDescription, start: dict[str, float], null_space: bool) -> Solver:
    """pybullet's damped least squares; with ``null_space`` its limit-aware variant."""
    client = pb.connect(pb.DIRECT)
    with tempfile.TemporaryDirectory() as folder, quiet_stdout():
        robot = pb.loadURDF(
            str(arm_only_urdf(desc, folder)), useFixedBase=True, physicsClientId=client
        )
    info = [
        pb.getJointInfo(robot, i, physicsClientId=client)
        for i in range(pb.getNumJoints(robot, physicsClientId=client))
    ]
    movable = [j for j in info if j[2] != pb.JOINT_FIXED]
    names = [j[1].decode() for j in movable]
    lower = [j[8] if j[8] <= j[9] else -math.pi for j in movable]
    upper = [j[9] if j[8] <= j[9] else math.pi for j in movable]
    rest = [start.get(n, 0.0) for n in names]
    limits = {
        "lowerLimits": lower,
        "upperLimits": upper,
        "jointRanges": [hi - lo for lo, hi in zip(lower, upper, strict=True)],
        "restPoses": rest,
    }
    link = next(j[0] for j in info if j[12].decode() == FRAME)

    def solve(target: Pose) -> Mapping[str, float]:
        for j, value in zip(movable, rest, strict=True):
            pb.resetJointState(robot, j[0], value, physicsClientId=client)
        values = pb.calculateInverseKinematics(
            robot,
            link,
            target.position,
            target.orientation,
            maxNumIterations=100,
            residualThreshold=1e-6,
            physicsClientId=client,
            **(limits if null_space else {}),
        )
        return dict(zip(names, values, strict=True))

    return solve


@contextlib.contextmanager
def quiet_stdout() -> Iterator[None]:
    """Silence the C-level warnings pybullet prints while it reads the URDF."""
    sys.stdout.flush()
    saved = os.dup(1)
    with open(os.devnull, "w") as null:
        os.dup2(null.fileno(), 1)
        try:
            yield
        finally:
            os.dup2(saved, 1)
            os.close(saved)


def main(count: int, seed: int) -> None:
    desc = load_description("pr2")
    solver = IKSolver.cached(desc, ARM)
    start = dict(zip(solver.variables, solver.start({}), strict=True))
    poses = targets(desc, solver, count, seed)
    print(f"PR2 {ARM} arm, {FRAME}: {count} FK targets (seed {seed}), start = mid-range config")
    print(HEADER.format("solver", "success", "mean ms", "median", "p95", "max", "in limits"))
    run("robocram (pinocchio LM)", desc, poses, ours(desc, start))
    run("pybullet calculateIK", desc, poses, pybullet_ik(desc, start, null_space=False))
    run("pybullet IK, null space", desc, poses, pybullet_ik(desc, start, null_space=True))
    print(HEADER.format("TRAC-IK (published)", "99.95 %", "0.380", "-", "-", "-", "-"))


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 1000,
        int(sys.argv[2]) if len(sys.argv) > 2 else 0,
    )
