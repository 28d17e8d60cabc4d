"""Motion planning in the kitchen: what each kind of motion costs, and the transport.

Run: ``.venv/bin/python benchmarks/motion_bench.py [transports] [shelf_runs]`` (defaults
20 and 10). CPU time of this process throughout (pybullet and coal run in it).

1. The PR2 transports the mug ``transports`` times (seeded spots, as kitchen_bench); every
   motion is timed from its planning call to its trajectory: straight joint segments,
   Cartesian tool lines, OMPL fallbacks and base paths (median, p95, count).
2. The OMPL fallback on its own: the PR2's arm round a box on the counter
   (tests/projection/test_projection_arm_paths.py), ``shelf_runs`` seeds, with and without
   the coal snapshot's build.
3. Collision checks per second: coal snapshot (``CollisionScene.is_free``), PyBullet
   contact check (``BulletScene.colliding``), PyBullet clearance and coal clearance
   (``CoalClearance.clearance``, what the straight segments' conservative advancement
   uses; random configurations jump, so each refocuses its pairs).
4. The transport before (commit ``BEFORE``: motions jump to their goals) and after, in the
   same run: the old commit is checked out into a temporary worktree and timed there.
"""

from __future__ import annotations

import json
import math
import statistics
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
from transport_timing import transport_times

import robocram.projection.arm as projected_arm
import robocram.projection.navigation as projected_navigation
from robocram.kinematics import solve_ik
from robocram.motion import CollisionScene
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.coal_clearance import CoalClearance
from robocram.motion.joint_limits import joint_limits
from robocram.motion.joint_path import plan_joint_path
from robocram.motion.travel_bound import TravelBound
from robocram.plans.basic_actions import move_torso, navigate, park_arms
from robocram.projection import simulated_robot
from robocram.projection.collision_mode import collision_check
from robocram.projection.projected_robot import ProjectedRobot
from robocram.scenes import kitchen_scene
from robocram.tf import PoseStamped
from robocram.tf import quaternion as quat

BEFORE = "d35812c"  # the last commit before robocram.motion: arms and base jump to goals
ROOT = Path(__file__).resolve().parents[1]
SHELF = ((0.12, 0.12, 0.36), (-0.97, 2.02, 1.04))  # size, centre [m]
GOALS = {"straight": 5.0, "cartesian": 5.0, "rrt_connect": 50.0, "base": 10.0}  # [ms]


def _p95(values: list[float]) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, math.ceil(0.95 * len(ordered)) - 1)]


def _timed_by_kind(record: dict[str, list[float]]) -> Callable[[], None]:
    """Wrap projection's planning calls to record CPU ms by the kind of path; undo fn."""
    arm, line, base = (
        projected_arm.plan_arm_motion,
        projected_arm.plan_tool_line,
        projected_navigation.plan_base_path,
    )

    def wrap(fn: Callable[..., Any], kind: Callable[[Any], str]) -> Callable[..., Any]:
        def timed(*args: Any, **kwargs: Any) -> Any:
            start = time.process_time()
            result = fn(*args, **kwargs)
            record[kind(result)].append((time.process_time() - start) * 1e3)
            return result

        return timed

    projected_arm.plan_arm_motion = wrap(arm, lambda m: m.path.planner)
    projected_arm.plan_tool_line = wrap(line, lambda m: "cartesian")
    projected_navigation.plan_base_path = wrap(base, lambda p: "base")

    def undo() -> None:
        projected_arm.plan_arm_motion = arm
        projected_arm.plan_tool_line = line
        projected_navigation.plan_base_path = base

    return undo


def motion_kinds(transports: int) -> tuple[dict[str, list[float]], list[float], int]:
    """Per kind of motion the planning times [ms]; the transport times [ms]; successes."""
    record: dict[str, list[float]] = defaultdict(list)
    undo = _timed_by_kind(record)
    try:
        times = transport_times("pr2", transports)
    finally:
        undo()
    return record, times.totals, times.succeeded


def _shelf_setup() -> tuple[Any, ProjectedRobot, list[float], list[float], tuple[str, ...]]:
    scene = kitchen_scene("pr2")
    world = scene.world
    x = world.pose("mug-1").position[0]
    with simulated_robot(world, "pr2"):
        park_arms()
        move_torso("upper")
        navigate(PoseStamped("map", (x, 1.43, 0.0), quat.from_euler(0.0, 0.0, math.pi / 2)))
        grasp = world.kb.first("object_grasp(O, R, A, N, G, P, L)", O="mug-1", R="pr2", A="right")
    robot = ProjectedRobot(world, "pr2")
    world.add_box("shelf", *SHELF)
    current = world.joint_states("pr2")
    check = collision_check(robot, "right", "avoid_all")
    goal = solve_ik(robot.description, "right", robot.in_base(grasp["P"]), seed=current,
                    collision_check=check)  # fmt: skip
    joints = robot.description.arms["right"].joints
    return (
        world, robot, [current[j] for j in joints],
        [goal.joint_positions[j] for j in joints], tuple(joints),
    )  # fmt: skip


def ompl_fallback(runs: int) -> tuple[list[float], list[float], list[int]]:
    """Round the shelf: planning times [ms] with and without the snapshot build; checks."""
    world, robot, start, goal, joints = _shelf_setup()
    limits = joint_limits(robot.description, joints)
    box = ([lim.lower for lim in limits], [lim.upper for lim in limits])
    bound = TravelBound.of(world, "pr2", joints)
    with_build, planning, checks = [], [], []
    for seed in range(runs):
        t0 = time.process_time()
        scene = CollisionScene.of(world, "pr2", joints)
        t1 = time.process_time()
        path = plan_joint_path(scene, start, goal, bound, box, seed=seed)
        t2 = time.process_time()
        assert path.planner == "rrt_connect"
        with_build.append((t2 - t0) * 1e3)
        planning.append((t2 - t1) * 1e3)
        checks.append(path.checks)
    world.close()
    return with_build, planning, checks


def checks_per_second(samples: int = 2000) -> dict[str, float]:
    """Rates of the four checks on random right-arm configurations at the counter."""
    world, robot, start, goal, joints = _shelf_setup()
    rng = np.random.default_rng(0)
    limits = joint_limits(robot.description, joints)
    low = np.array([max(lim.lower, -math.pi) for lim in limits])
    high = np.array([min(lim.upper, math.pi) for lim in limits])
    qs = [low + rng.random(len(joints)) * (high - low) for _ in range(samples)]
    coal = CollisionScene.of(world, "pr2", joints)
    bullet = BulletScene(world, "pr2", joints)
    clearance = CoalClearance(bullet)
    rates = {}
    for name, fn in (
        ("coal is_free", coal.is_free),
        ("pybullet colliding", bullet.colliding),
        ("pybullet clearance", bullet.clearance),
        ("coal clearance", clearance.clearance),
    ):
        start_time = time.process_time()
        for q in qs:
            fn(q)
        rates[name] = samples / (time.process_time() - start_time)
    world.close()
    return rates


def transport_before(transports: int) -> dict[str, float] | None:
    """Median transport time [ms] and successes at commit BEFORE, in a temporary worktree."""
    script = (
        "import json, statistics, sys; sys.path.insert(0, 'benchmarks');"
        "from transport_timing import transport_times;"
        f"t = transport_times('pr2', {transports});"
        "print(json.dumps({'median': statistics.median(t.totals), 'ok': t.succeeded}))"
    )
    with tempfile.TemporaryDirectory() as tmp:
        tree = Path(tmp) / "before"
        try:
            subprocess.run(
                ["git", "-C", str(ROOT), "worktree", "add", "--detach", str(tree), BEFORE],
                check=True, capture_output=True,
            )  # fmt: skip
        except (OSError, subprocess.CalledProcessError):
            return None
        try:
            done = subprocess.run(
                [sys.executable, "-c", script], cwd=tree, capture_output=True, text=True,
                env={"PYTHONPATH": str(tree / "src"), "PATH": "/usr/bin:/bin"},
            )  # fmt: skip
            lines = [ln for ln in done.stdout.splitlines() if ln.startswith("{")]
            return json.loads(lines[-1]) if lines else None
        finally:
            subprocess.run(
                ["git", "-C", str(ROOT), "worktree", "remove", "--force", str(tree)],
                capture_output=True,
            )  # fmt: skip


def main() -> None:
    """Print the figures."""
    transports = int(sys.argv[1]) if len(sys.argv) > 1 else 20
    shelf_runs = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    print(f"motion_bench: PR2 in the kitchen; CPU time of this process; {transports} transports")
    record, totals, succeeded = motion_kinds(transports)
    for kind in ("straight", "cartesian", "rrt_connect", "base"):
        values = record.get(kind, [])
        if not values:
            print(f"  {kind:12s} none in these transports")
            continue
        print(
            f"  {kind:12s} n={len(values):4d}  median {statistics.median(values):6.1f} ms  "
            f"p95 {_p95(values):6.1f} ms   (goal: {'median' if kind == 'rrt_connect' else 'p95'}"
            f" <= {GOALS[kind]:.0f} ms)"
        )
    with_build, planning, checks = ompl_fallback(shelf_runs)
    print(
        f"  OMPL round the shelf ({shelf_runs} seeds): median {statistics.median(with_build):6.1f}"
        f" ms with the coal snapshot's build, {statistics.median(planning):6.1f} ms planning "
        f"alone, p95 {_p95(with_build):6.1f} ms; median {statistics.median(checks):.0f} checks"
        f"   (goal: median <= {GOALS['rrt_connect']:.0f} ms)"
    )
    for name, rate in checks_per_second().items():
        print(f"  {name:20s} {rate:10.0f} checks/s")
    before = transport_before(transports)
    after = statistics.median(totals)
    shown = (
        f"{before['median']:7.1f} ms ({before['ok']:.0f}/{transports} ok)"
        if before else "n/a (no git worktree)"
    )  # fmt: skip
    print(
        f"  transport before ({BEFORE}, motions jump): {shown};  after: {after:7.1f} ms "
        f"({succeeded}/{transports} ok)   (goal: median <= 150 ms)"
    )


if __name__ == "__main__":
    main()
