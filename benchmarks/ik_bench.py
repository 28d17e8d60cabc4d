"""IK benchmark: PR2 right arm, reachable and unreachable targets, ours beside pybullet's IK.

Reachable targets: forward kinematics of ``r_gripper_tool_frame`` for uniformly random
in-limit arm configurations (continuous joints in [-pi, pi]; torso and everything else at
0). Every query starts from the same configuration, the middle of the arm's joint ranges
(0 for continuous joints), which differs from the one that made the target. Success:
position error < 1 cm and orientation error < 0.05 rad, checked by our FK of the returned
joints. Times are wall clock and CPU time of this process (the CPU column is the one to
trust on a shared machine).

Unreachable targets, which must fail fast:
- PR2 beyond reach: reachable targets pushed away from the shoulder until they are 5 to
  50 cm beyond the sum of the arm's link lengths;
- HSR arm without its lift (four joints), at poses of random configurations that raise
  the lift: a four-joint arm reaches a four-dimensional set of tool poses, so random
  six-dimensional targets are out of its reach.

Then the descents IK spends in the HSR's pick-up plan in the tabletop scene.

Last, "HSR base-in-IK": the pick-up plan's success rate on the HSR over seeded mug
placements on the tabletop scene's table (the half nearest the robot), with the arm alone
(``ArmDescription.base_in_ik=False``, as before) and reaching with the base (the default
for its five-joint arm), and top grasps at random turns the five-joint arm misses alone.

Usage: ``python benchmarks/ik_bench.py [count=1000] [random_seed=0] [placements=20]``
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

from robocram.kinematics import IKOptions, IKResult, IKSolver, forward_kinematics, solve_ik
from robocram.robots import RobotDescription, RobotModel, load_description
from robocram.tf import Pose

ARM, FRAME = "right", "r_gripper_tool_frame"
POSITION_OK, ORIENTATION_OK = 0.01, 0.05  # [m], [rad]
HEADER = "{:<30} {:>9} {:>8} {:>8} {:>8} {:>8} {:>9} {:>9} {:>9}"
ROW = "{:<30} {:>9} {:8.3f} {:8.3f} {:8.3f} {:8.3f} {:9.2f} {:>9} {:>9}"
Solver = Callable[[Pose], Mapping[str, float]]


def random_configs(solver: IKSolver, count: int, rng: np.random.Generator) -> list[dict]:
    lo = np.where(np.isfinite(solver.chain.lower), solver.chain.lower, -math.pi)
    hi = np.where(np.isfinite(solver.chain.upper), solver.chain.upper, math.pi)
    return [dict(zip(solver.variables, rng.uniform(lo, hi), strict=True)) for _ in range(count)]


def targets(desc: RobotDescription, solver: IKSolver, count: int, seed: int) -> list[Pose]:
    configs = random_configs(solver, count, np.random.default_rng(seed))
    return [forward_kinematics(desc, c, FRAME) for c in configs]


def beyond_reach(desc: RobotDescription, poses: list[Pose], seed: int) -> list[Pose]:
    """``poses`` pushed radially from the shoulder to 5-50 cm beyond the arm's length."""
    rng = np.random.default_rng(seed + 1)
    shoulder = np.array(forward_kinematics(desc, {}, "r_shoulder_pan_link").position)
    reach = IKSolver.cached(desc, ARM).reach.radius
    out = []
    for pose in poses:
        away = np.array(pose.position) - shoulder
        away /= np.linalg.norm(away)
        position = shoulder + away * (reach + rng.uniform(0.05, 0.5))
        out.append(Pose(tuple(position), pose.orientation))
    return out


def header(title: str) -> None:
    print(f"\n{title}")
    print(
        HEADER.format(
            "solver",
            "success",
            "mean ms",
            "median",
            "p95",
            "max",
            "cpu ms",
            "in limits",
            "descents",
        )
    )


def run(name: str, desc: RobotDescription, arm: str, poses: list[Pose], solve: Solver) -> None:
    frame = desc.arms[arm].tool_frame
    limits = {
        j: (desc.model.joints[j].lower, desc.model.joints[j].upper) for j in desc.arms[arm].joints
    }  # type: ignore[union-attr]
    times, ok, inside, descents = [], 0, 0, []
    cpu0 = time.process_time()
    for target in poses:
        t0 = time.perf_counter()
        joints = solve(target)
        times.append((time.perf_counter() - t0) * 1e3)
        if isinstance(joints, IKResult):
            descents.append(joints.restarts + 1 if joints.iterations else 0)
            joints = joints.joint_positions
        reached = forward_kinematics(desc, joints, frame)
        ok += (
            reached.distance_to(target) < POSITION_OK and reached.angle_to(target) < ORIENTATION_OK
        )
        inside += all(
            lo - 1e-9 <= joints[j] <= hi + 1e-9 for j, (lo, hi) in limits.items() if j in joints
        )  # type: ignore[operator]
    cpu = (time.process_time() - cpu0) * 1e3 / len(poses)  # includes the FK checks (~0.02 ms)
    n, q = len(poses), statistics.quantiles(times, n=20)
    mean, median = statistics.fmean(times), statistics.median(times)
    mean_descents = f"{statistics.fmean(descents):.2f}" if descents else "-"
    print(
        ROW.format(
            name,
            f"{100 * ok / n:.2f} %",
            mean,
            median,
            q[-1],
            max(times),
            cpu,
            f"{100 * inside / n:.2f} %",
            mean_descents,
        )
    )


def ours(
    desc: RobotDescription, arm: str, start: dict[str, float], use_torso: bool = False
) -> Callable[[Pose], IKResult]:
    return lambda target: solve_ik(
        desc, arm, target, seed=start, options=IKOptions(use_torso=use_torso)
    )


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


def hsr_without_lift(count: int, seed: int) -> None:
    hsr = load_description("hsrb")
    with_lift = IKSolver.cached(hsr, "arm", use_torso=True)
    configs = random_configs(with_lift, count, np.random.default_rng(seed + 2))
    poses = [forward_kinematics(hsr, c, "hand_tool_frame") for c in configs]
    start = {"arm_lift_joint": 0.0}
    solve_ik(hsr, "arm", poses[0], seed=start)  # samples the start table
    run("robocram, HSR arm w/o lift", hsr, "arm", poses, ours(hsr, "arm", start))


def hsr_pick_up_descents() -> None:
    """Count the descents of every IK query the HSR's pick-up plan makes (a measuring
    wrapper around the real solver)."""
    from robocram.plans import pick_up
    from robocram.projection import simulated_robot
    from robocram.scenes import tabletop_scene

    answers: list[IKResult] = []
    solve = IKSolver.solve

    def counted(self: IKSolver, *args: object, **kwargs: object) -> IKResult:
        answers.append(solve(self, *args, **kwargs))  # type: ignore[arg-type]
        return answers[-1]

    IKSolver.solve = counted  # type: ignore[method-assign]
    try:
        scene = tabletop_scene("hsrb")
        with simulated_robot(scene.world, "hsrb"):
            pick_up(scene.look_target)
    finally:
        IKSolver.solve = solve  # type: ignore[method-assign]
    counts = [a.restarts + 1 if a.iterations else 0 for a in answers]
    per_query = ", ".join(
        f"{n}{'' if a.success else ' (failed)'}" for n, a in zip(counts, answers, strict=True)
    )
    total = sum(counts)
    print(f"\nHSR pick-up plan: {len(answers)} IK queries, {total} descents [{per_query}]")


def hsr_variant(base_in_ik: bool | None) -> RobotDescription:
    """The HSR with its arm's ``base_in_ik`` flag set (None: the default)."""
    hsr = load_description("hsrb")
    arm = replace(hsr.arms["arm"], base_in_ik=base_in_ik)
    return replace(hsr, arms={"arm": arm})


def hsr_pick_success(count: int, seed: int, base_in_ik: bool | None) -> None:
    """Pick up a mug placed at ``count`` seeded spots of the table's near half."""
    from robocram.execution.failures import PlanFailure
    from robocram.plans import pick_up
    from robocram.projection import simulated_robot
    from robocram.scenes import tabletop_scene
    from robocram.scenes.placement import TABLE_DEPTH
    from robocram.tf import PoseStamped

    scene = tabletop_scene(hsr_variant(base_in_ik))
    world = scene.world
    height = world.pose("mug-1").position[2]
    front = world.pose("table").position[0] - TABLE_DEPTH / 2
    rng = np.random.default_rng(seed + 3)
    held, moves, times = 0, [], []
    for _ in range(count):
        x, y = rng.uniform(front + 0.05, front + TABLE_DEPTH / 2), rng.uniform(-0.4, 0.4)
        with world.snapshots.stored_state():
            world.set_pose("mug-1", Pose((x, y, height)))
            t0 = time.perf_counter()
            with contextlib.suppress(PlanFailure), simulated_robot(world, scene.robot):
                pick_up(PoseStamped("map", (x, y, height)))
            times.append((time.perf_counter() - t0) * 1e3)
            if world.bodies.attached_to("mug-1") is not None:
                held += 1
                moves.append(math.hypot(*world.pose(scene.robot).position[:2]))
    label = "arm alone (base_in_ik=False)" if base_in_ik is False else "arm and base (default)"
    moved = f"{statistics.median(moves):.3f} m" if moves else "-"
    median = statistics.median(times)
    print(f"{label:<30} {100 * held / count:6.1f} % picked   median plan {median:7.0f} ms", end="")
    print(f"   median base move {moved}")
    world.close()


def hsr_top_grasps(count: int, seed: int) -> None:
    """Top grasps at random positions and turns: the arm alone against arm and base."""
    from robocram.kinematics import PlanarBase
    from robocram.tf import quaternion as quat

    hsr = load_description("hsrb")
    rng = np.random.default_rng(seed + 4)
    down = quat.from_euler(0.0, math.pi / 2, 0.0)
    poses = [
        Pose(
            (rng.uniform(0.3, 0.7), rng.uniform(-0.4, 0.4), rng.uniform(0.4, 1.0)),
            quat.multiply(quat.from_euler(0.0, 0.0, rng.uniform(-math.pi, math.pi)), down),
        )
        for _ in range(count)
    ]
    for base in (None, PlanarBase()):
        answers, cpu = [], time.process_time()
        for target in poses:
            answers.append(
                solve_ik(hsr, "arm", target, options=IKOptions(use_torso=True, base=base))
            )
        cpu = (time.process_time() - cpu) * 1e3 / count
        ok = sum(a.success for a in answers)
        label = "arm alone" if base is None else "arm and base (+-0.5 m, +-pi)"
        print(f"{label:<30} {100 * ok / count:6.1f} % reached   {cpu:6.2f} ms cpu per query")


def hsr_base_in_ik(placements: int, seed: int) -> None:
    print(f"\nHSR base-in-IK: {5 * placements} top grasps at random turns (torso free)")
    hsr_top_grasps(5 * placements, seed)
    print(f"HSR base-in-IK: pick-up plan over {placements} seeded mug placements (tabletop)")
    for flag in (False, None):
        hsr_pick_success(placements, seed, flag)


def reaches(desc: RobotDescription, result: IKResult, target: Pose) -> bool:
    """Success, confirmed by our FK of the returned joints."""
    tool = forward_kinematics(desc, result.joint_positions, FRAME)
    close = tool.distance_to(target) < POSITION_OK and tool.angle_to(target) < ORIENTATION_OK
    return result.success and close


def timed(work: Callable[[], object]) -> tuple[float, float]:
    """Wall and CPU time of ``work()`` [ms]."""
    t0, c0 = time.perf_counter(), time.process_time()
    work()
    return (time.perf_counter() - t0) * 1e3, (time.process_time() - c0) * 1e3


def machine_speed() -> str:
    """How busy this machine is: a fixed piece of Python work, timed."""
    wall, cpu = timed(lambda: [sum(range(1_000_000)) for _ in range(10)])
    return (
        f"machine: sum(range(1e6)) takes {wall / 10:.1f} ms wall, {cpu / 10:.1f} ms cpu "
        "(about 10 ms on an idle desktop core); load average "
        + " ".join(f"{x:.1f}" for x in os.getloadavg())
    )


def main(count: int, seed: int, placements: int) -> None:
    desc = load_description("pr2")
    solver = IKSolver.cached(desc, ARM)
    start = dict(zip(solver.variables, solver.start({}), strict=True))
    poses = targets(desc, solver, count, seed)
    print(machine_speed())
    wall, cpu = timed(lambda: solve_ik(desc, ARM, poses[0], seed=start))
    print(f"first query (samples the start table): {wall:.0f} ms wall, {cpu:.0f} ms cpu")
    header(f"PR2 {ARM} arm, {FRAME}: {count} reachable FK targets (seed {seed}), start = mid-range")
    run("robocram (pinocchio LM)", desc, ARM, poses, ours(desc, ARM, start))
    run("pybullet calculateIK", desc, ARM, poses, pybullet_ik(desc, start, null_space=False))
    run("pybullet IK, null space", desc, ARM, poses, pybullet_ik(desc, start, null_space=True))
    print(HEADER.format("TRAC-IK (published)", "99.95 %", "0.380", "-", "-", "-", "-", "-", "-"))
    many = targets(desc, solver, 10 * count, seed + 100)
    solved = sum(reaches(desc, solve_ik(desc, ARM, t, seed=start), t) for t in many)
    print(f"robocram on {len(many)} more targets: {100 * solved / len(many):.3f} % success")
    far = beyond_reach(desc, poses[: max(count // 5, 20)], seed)
    header(f"unreachable: {len(far)} PR2 targets beyond reach; {len(far)} HSR targets w/o lift")
    run("robocram, PR2 beyond reach", desc, ARM, far, ours(desc, ARM, start))
    run("pybullet calculateIK", desc, ARM, far, pybullet_ik(desc, start, null_space=False))
    hsr_without_lift(len(far), seed)
    hsr_pick_up_descents()
    hsr_base_in_ik(placements, seed)


if __name__ == "__main__":
    main(
        int(sys.argv[1]) if len(sys.argv) > 1 else 1000,
        int(sys.argv[2]) if len(sys.argv) > 2 else 0,
        int(sys.argv[3]) if len(sys.argv) > 3 else 20,
    )
