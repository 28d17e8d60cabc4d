"""Motion planning in the kitchen: what each kind of motion costs, and the transport.

Run: ``.venv/bin/python benchmarks/motion_bench.py [transports] [shelf_runs] [--before]``
(defaults 5 and 20). CPU time of this process throughout (pybullet and coal run in it).

1. The PR2 transports the mug ``transports`` times (seeded spots, as kitchen_bench); every
   motion is timed from its planning call to its trajectory: straight joint segments,
   Cartesian tool lines, OMPL fallbacks and base paths (median, p95, count).
2. The OMPL fallback on its own: the PR2's arm round a box on the counter
   (tests/projection/test_projection_arm_paths.py), ``shelf_runs`` seeds: median and p95 of
   the planning alone (``plan_joint_path`` on the snapshot: RRTConnect, simplification and
   the re-check), with the snapshot's build apart; the path's length against the straight
   line, in joint space and along the tool frame; and how long a query that cannot
   succeed (its goal enclosed in joint space) takes to give up.
3. Collision checks per second: coal snapshot (``CollisionScene.is_free``), PyBullet
   contact check (``BulletScene.colliding``), PyBullet clearance and coal clearance
   (``CoalClearance.clearance``, what the straight segments' conservative advancement
   uses; random configurations jump, so each refocuses its pairs).
4. With ``--before``: the transport before (commit ``BEFORE``: motions jump to their
   goals) and after, in the same run: the old commit is checked out into a temporary
   worktree and timed there.
"""

from __future__ import annotations

import contextlib
import itertools
import json
import math
import statistics
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from transport_timing import transport_times

import robocram.projection.arm as projected_arm
import robocram.projection.navigation as projected_navigation
from robocram.execution.failures import ManipulationPathBlocked
from robocram.kinematics import forward_kinematics, solve_ik
from robocram.motion import CollisionScene
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.coal_clearance import CoalClearance
from robocram.motion.joint_limits import joint_limits
from robocram.motion.joint_path import plan_joint_path
from robocram.motion.path_simplification import path_length
from robocram.motion.travel_bound import TravelBound
from robocram.plans.basic_actions import move_torso, navigate, park_arms
from robocram.projection import simulated_robot
from robocram.projection.collision_mode import collision_check
from robocram.projection.projected_robot import ProjectedRobot
from robocram.scenes import kitchen_scene
from robocram.tf import PoseStamped
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle

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


@dataclass
class Fallback:
    """OMPL round the box, per seed: CPU ms with and without the snapshot's build, checks,
    and the path's length against the straight line (joint space and the tool's)."""

    with_build: list[float] = field(default_factory=list)
    planning: list[float] = field(default_factory=list)
    checks: list[int] = field(default_factory=list)
    joint_ratio: list[float] = field(default_factory=list)
    tool_ratio: list[float] = field(default_factory=list)


def ompl_fallback(runs: int) -> Fallback:
    """Round the shelf: ``plan_joint_path`` on a fresh coal snapshot per seed."""
    world, robot, start, goal, joints = _shelf_setup()
    limits = joint_limits(robot.description, joints)
    box = ([lim.lower for lim in limits], [lim.upper for lim in limits])
    bound = TravelBound.of(RobotHandle.of(world, "pr2"), joints)
    tool = _tool_length(robot, joints)
    straight = float(np.linalg.norm(np.subtract(goal, start)))
    out = Fallback()
    for seed in range(runs):
        t0 = time.process_time()
        scene = CollisionScene.of(RobotHandle.of(world, "pr2"), joints)
        t1 = time.process_time()
        path = plan_joint_path(scene, start, goal, bound, box, seed=seed)
        t2 = time.process_time()
        assert path.planner == "rrt_connect"
        out.with_build.append((t2 - t0) * 1e3)
        out.planning.append((t2 - t1) * 1e3)
        out.checks.append(path.checks)
        out.joint_ratio.append(path_length(path.waypoints) / straight)
        out.tool_ratio.append(tool(path.waypoints) / tool((start, goal), straight=True))
    world.close()
    return out


def _tool_length(robot: ProjectedRobot, joints: tuple[str, ...]) -> Callable[..., float]:
    """The length [m] of the tool frame's path along joint-space waypoints (each segment
    cut in 50), or of the straight line between its ends (``straight``)."""
    frame = robot.description.arms["right"].tool_frame
    rest = robot.world.joint_states("pr2")

    def at(q: np.ndarray) -> np.ndarray:
        values = {**rest, **dict(zip(joints, q.tolist(), strict=True))}
        return np.array(forward_kinematics(robot.description, values, frame).position)

    def length(waypoints: Any, straight: bool = False) -> float:
        points = [np.asarray(w, dtype=float) for w in waypoints]
        if straight:
            return float(np.linalg.norm(at(points[-1]) - at(points[0])))
        dense = [a + (b - a) * k / 50 for a, b in itertools.pairwise(points) for k in range(50)]
        tips = np.array([at(q) for q in [*dense, points[-1]]])
        return float(np.linalg.norm(np.diff(tips, axis=0), axis=1).sum())

    return length


def impossible_query() -> tuple[float, int]:
    """CPU ms and checks until RRTConnect gives up on a goal enclosed in joint space
    (every configuration 0.05-0.3 rad from it collides), snapshot build included."""
    world, robot, start, goal, joints = _shelf_setup()
    limits = joint_limits(robot.description, joints)
    box = ([lim.lower for lim in limits], [lim.upper for lim in limits])
    bound = TravelBound.of(RobotHandle.of(world, "pr2"), joints)
    begin = time.process_time()
    scene = CollisionScene.of(RobotHandle.of(world, "pr2"), joints)
    caged = _Caged(scene, np.array(goal))
    with contextlib.suppress(ManipulationPathBlocked):  # it must fail: the goal is caged
        plan_joint_path(caged, start, goal, bound, box)
    spent = (time.process_time() - begin) * 1e3
    world.close()
    return spent, caged.asked


class _Caged:
    """A snapshot whose goal is enclosed: a shell round it in joint space collides."""

    def __init__(self, scene: CollisionScene, goal: np.ndarray) -> None:
        self.scene, self.goal, self.asked, self.joints = scene, goal, 0, scene.joints

    def _caged(self, q: Any) -> bool:
        self.asked += 1
        return 0.05 < float(np.abs(np.asarray(q, dtype=float) - self.goal).max()) < 0.3

    def is_free(self, q: Any) -> bool:
        return not self._caged(q) and self.scene.is_free(q)

    def colliding(self, q: Any, first_only: bool = False) -> list[tuple[str, str]]:
        return [("cage", "cage")] if self._caged(q) else self.scene.colliding(q, first_only)


def checks_per_second(samples: int = 2000) -> dict[str, float]:
    """Rates of the four checks on random right-arm configurations at the counter."""
    world, robot, start, goal, joints = _shelf_setup()
    rng = np.random.default_rng(0)
    limits = joint_limits(robot.description, joints)
    low = np.array([max(lim.lower, -math.pi) for lim in limits])
    high = np.array([min(lim.upper, math.pi) for lim in limits])
    qs = [low + rng.random(len(joints)) * (high - low) for _ in range(samples)]
    coal = CollisionScene.of(RobotHandle.of(world, "pr2"), joints)
    bullet = BulletScene(RobotHandle.of(world, "pr2"), joints)
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
    numbers = [int(a) for a in sys.argv[1:] if a.isdigit()]
    transports = numbers[0] if numbers else 5
    shelf_runs = numbers[1] if len(numbers) > 1 else 20
    print(f"motion_bench: PR2 in the kitchen; CPU time of this process; {transports} transports")
    record, totals, succeeded = motion_kinds(transports)
    for kind in [*GOALS, *sorted(set(record) - set(GOALS))]:
        values = record.get(kind, [])
        if not values:
            print(f"  {kind:12s} none in these transports")
            continue
        goal = (
            f"   (goal: {'median' if kind == 'rrt_connect' else 'p95'} <= {GOALS[kind]:.0f} ms)"
            if kind in GOALS else ""
        )  # fmt: skip
        print(
            f"  {kind:12s} n={len(values):4d}  median {statistics.median(values):6.1f} ms  "
            f"p95 {_p95(values):6.1f} ms{goal}"
        )
    f = ompl_fallback(shelf_runs)
    print(
        f"  OMPL round the shelf ({shelf_runs} seeds), planning alone (plan_joint_path on the "
        f"snapshot): median {statistics.median(f.planning):6.1f} ms  p95 {_p95(f.planning):6.1f}"
        f" ms   (goal: median <= {GOALS['rrt_connect']:.0f} ms); with the snapshot's build: "
        f"median {statistics.median(f.with_build):6.1f} ms; "
        f"median {statistics.median(f.checks):.0f} checks"
    )
    print(
        f"  OMPL path length / straight line: joint space median "
        f"{statistics.median(f.joint_ratio):.2f} (max {max(f.joint_ratio):.2f}), tool frame "
        f"median {statistics.median(f.tool_ratio):.2f} (max {max(f.tool_ratio):.2f})"
    )
    spent, asked = impossible_query()
    print(
        f"  an impossible query (goal enclosed): gives up after {spent:6.1f} ms, {asked} checks"
        f"   (goal: <= 500 ms)"
    )
    for name, rate in checks_per_second().items():
        print(f"  {name:20s} {rate:10.0f} checks/s")
    after = statistics.median(totals)
    if "--before" not in sys.argv:
        print(f"  transport: median {after:7.1f} ms ({succeeded}/{transports} ok); --before: "
              "against the commit before robocram.motion")  # fmt: skip
        return
    before = transport_before(transports)
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
