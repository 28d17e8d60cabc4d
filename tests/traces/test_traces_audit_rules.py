"""The audit's rules on their own: divided differences against limits, adjacency, density."""

from __future__ import annotations

import ast
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from robocram.motion import (
    JointLimits,
    TrajectoryPoint,
    joint_limits,
    time_parameterize,
)
from robocram.robots import load_description
from robocram.tf import Pose
from robocram.traces import StoredTrajectory, set_robot_joints
from robocram.traces.audit_bounds import AuditBounds
from robocram.traces.audit_findings import FindingKind, FindingPlace
from robocram.traces.dense_samples import Levers, dense_configurations
from robocram.traces.limit_audit import limit_findings
from robocram.traces.link_adjacency import adjacent_links
from robocram.world import RobotHandle, World

LIMIT = JointLimits("j", -10.0, 10.0, velocity=1.0, acceleration=2.0, jerk=20.0)
PLACE = FindingPlace(run=1, trajectory=0, task_path="t", start=10.0)


def _stored(
    times: np.ndarray,
    positions: np.ndarray,
    velocities: np.ndarray | None = None,
    accelerations: np.ndarray | None = None,
) -> StoredTrajectory:
    v = np.zeros_like(positions) if velocities is None else velocities
    acc = np.zeros_like(positions) if accelerations is None else accelerations
    points = tuple(
        TrajectoryPoint((float(q),), (float(dq),), (float(ddq),), float(t))
        for t, q, dq, ddq in zip(times, positions, v, acc, strict=True)
    )
    return StoredTrajectory(0, "r", ("j",), points, "arm", "t", 0.0, 0.0)


def _findings(trajectory: StoredTrajectory) -> dict[FindingKind, float]:
    return {f.kind: f.amount for f in limit_findings(trajectory, (LIMIT,), AuditBounds(), PLACE)}


def test_a_ruckig_trajectory_at_its_limits_shows_none() -> None:
    desc = load_description("pr2")
    names = ("r_elbow_flex_joint", "r_wrist_flex_joint")
    timed = time_parameterize(
        "pr2", names, [[-0.2, -0.1], [-1.9, -1.6], [-0.5, -0.3]], joint_limits(desc, names)
    )
    stored = StoredTrajectory(0, "pr2", names, tuple(timed.points), "arm", "t", 0.0, 0.0)
    assert list(limit_findings(stored, joint_limits(desc, names), AuditBounds(), PLACE)) == []


def test_a_smooth_move_within_the_limits_shows_none_and_its_stored_velocities_agree() -> None:
    times = np.linspace(0.0, 4.0, 401)
    s = times / 4.0
    positions = 1.0 * (s - np.sin(math.tau * s) / math.tau)  # a max 0.39, jerk 0.62, v 0.5
    velocities = 1.0 / 4.0 * (1.0 - np.cos(math.tau * s))
    accelerations = math.tau / 16.0 * np.sin(math.tau * s)
    assert _findings(_stored(times, positions, velocities, accelerations)) == {}
    wrong = _findings(_stored(times, positions, velocities))  # accelerations left at zero
    assert wrong == {FindingKind.ACCELERATION_MISMATCH: pytest.approx(math.tau / 16.0, rel=0.01)}


def test_a_start_at_full_speed_is_an_acceleration_and_a_jerk_from_rest() -> None:
    times = np.linspace(0.0, 1.0, 101)
    found = _findings(_stored(times, 0.5 * times, np.full_like(times, 0.5)))
    # from rest to 0.5 rad/s within the first 10 ms: 2 * 0.5 / 0.01 = 100 rad/s^2
    assert found[FindingKind.ACCELERATION] == pytest.approx(100.0, rel=1e-6)
    assert found[FindingKind.JERK] == pytest.approx(6 * 0.005 / 0.01**3, rel=1e-6)
    assert FindingKind.VELOCITY not in found


def test_a_velocity_five_percent_over_is_tolerated_ten_percent_is_not() -> None:
    times = np.linspace(0.0, 100.0, 10001)  # slow ends: the start's acceleration is small
    for speed, found in ((1.04, False), (1.1, True)):
        ramp = np.clip(times, 0.0, 100.0) * speed
        cruise = _findings(_stored(times, ramp, np.full_like(times, speed)))
        assert (FindingKind.VELOCITY in cruise) is found


def test_the_worst_finding_carries_its_time_on_the_run_clock() -> None:
    times = np.linspace(0.0, 2.0, 201)
    positions = np.where(times < 1.0, 0.0, 0.3 * (times - 1.0))  # starts at 1 s, stops at 2 s
    (acceleration,) = [
        f
        for f in limit_findings(_stored(times, positions), (LIMIT,), AuditBounds(), PLACE)
        if f.kind is FindingKind.ACCELERATION
    ]
    # stopping at once (to rest within half a step) is worse than starting at once
    assert acceleration.amount == pytest.approx(2 * 0.3 / 0.01)
    assert acceleration.time == pytest.approx(PLACE.start + 2.0, abs=0.01)
    assert acceleration.what == "joint j" and acceleration.bound == 2.0
    assert acceleration.samples == 2  # the start, and the stop


def test_adjacency_merges_fixed_joints_and_looks_through_links_without_shapes() -> None:
    model = load_description("pr2").model
    adjacent = adjacent_links(model)
    assert not model.links["r_wrist_roll_link"].collisions
    assert frozenset(("r_gripper_palm_link", "r_wrist_flex_link")) in adjacent  # through the roll
    assert frozenset(("r_forearm_link", "r_elbow_flex_link")) in adjacent  # one joint
    assert frozenset(("r_forearm_link", "r_upper_arm_link")) not in adjacent  # two joints
    assert frozenset(("r_shoulder_pan_link", "l_shoulder_pan_link")) not in adjacent
    assert all(model.links[link].collisions for pair in adjacent for link in pair)


@pytest.mark.parametrize("motion", ["arm-and-torso", "base"])
def test_dense_samples_move_no_point_more_than_five_mm(motion: str) -> None:
    """Points at each link's radius from its frame, along its axes, move <= 5 mm a step."""
    world = World()
    world.add_robot("pr2")
    desc = world.robot("pr2").description
    if motion == "base":
        names: tuple[str, ...] = ("x", "y", "yaw")
        path = [[0.0, 0.0, 0.0], [0.4, -0.2, 1.5]]
    else:
        names = (*desc.arms["right"].joints, "torso_lift_joint")
        start = [desc.arms["right"].parking[j] for j in names[:-1]] + [0.0]
        path = [start, [0.3, 0.5, -1.0, -0.4, 1.0, -0.5, 2.0, 0.2]]
    timed = time_parameterize("pr2", names, path, joint_limits(desc, names))
    pr2 = RobotHandle.of(world, "pr2")
    levers = Levers.of(pr2, desc.model, {})
    radii = world.contacts.link_radii("pr2")
    links = [link for link in desc.model.links if desc.model.links[link].collisions]
    offsets = [
        Pose(tuple(radii[link] * e for e in axis))
        for link in links
        for axis in ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1))
    ]
    before, before_q = None, None
    steps = 0
    for _, q in dense_configurations(names, timed.times(), timed.positions(), levers, 0.005, 0.005):
        set_robot_joints(pr2, dict(zip(names, q.tolist(), strict=True)))
        frames = [world.link_pose("pr2", link) for link in links]
        now = np.array([(frames[k // 4] * o).position for k, o in enumerate(offsets)])
        if before is not None and before_q is not None:
            assert np.max(np.linalg.norm(now - before, axis=1)) <= 0.005 + 1e-9
            assert np.max(np.abs(q - before_q)) <= 0.005 + 1e-9
        before, before_q = now, q
        steps += 1
    world.close()
    assert steps > (2.0 if motion != "base" else 1.5) / 0.005  # the largest joint move


def test_a_yaw_through_pi_is_unwrapped_a_position_is_not() -> None:
    times = np.linspace(0.0, 4.0, 401)
    s = times / 4.0
    turn = 3.0 + 0.3 * (s - np.sin(math.tau * s) / math.tau)  # 3.0 -> 3.3 rad, slowly
    stored = np.where(turn > math.pi, turn - math.tau, turn)  # as a wrapped yaw
    velocities = 0.3 / 4.0 * (1.0 - np.cos(math.tau * s))
    accelerations = 0.3 * math.tau / 16.0 * np.sin(math.tau * s)
    trajectory = _stored(times, stored, velocities, accelerations)
    yaw = replace(LIMIT, name="j")
    wrapped = list(limit_findings(trajectory, (yaw,), AuditBounds(), PLACE, wrapping={"j"}))
    assert wrapped == []
    as_position = {f.kind for f in limit_findings(trajectory, (yaw,), AuditBounds(), PLACE)}
    assert FindingKind.VELOCITY in as_position  # a jump of 2 pi in 10 ms


AUDIT_MODULES = (
    "audit_bounds", "audit_findings", "dense_samples", "limit_audit", "link_adjacency",
    "penetration_audit", "relative_motion", "teleport_audit", "trajectory_audit",
)  # fmt: skip
PLANNER_CHECKS = (
    "robocram.motion.bullet_scene", "robocram.motion.coal_clearance",
    "robocram.motion.segment_check", "robocram.motion.self_collision",
    "robocram.motion.collision_scene", "robocram.motion.travel_bound",
    "robocram.world.link_contacts", "robocram.world.closest_points",
    "robocram.world.obstacle_boxes",
)  # fmt: skip


@pytest.mark.parametrize("name", AUDIT_MODULES)
def test_the_audit_uses_none_of_the_planners_checks(name: str) -> None:
    path = Path(__file__).resolve().parents[2] / "src" / "robocram" / "traces" / f"{name}.py"
    tree = ast.parse(path.read_text(encoding="utf-8"))
    imported = {n.module or "" for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)} | {
        a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names
    }
    assert not imported & set(PLANNER_CHECKS)
    called = {n.attr for n in ast.walk(tree) if isinstance(n, ast.Attribute)}
    shortcuts = {"link_distances", "link_pairs_in_contact", "self_contacts", "obstacle_boxes"}
    assert not called & (shortcuts | {"in_collision", "contact_points", "contact"})
