"""The audit of a run (``robocram runs audit``) finds what a judge replaying it would.

Planted faults, each traced into a real SQLite store and replayed on real PyBullet: the
base driven into a low wall (world penetration, and an allowed contact deeper than its
bound), the right arm swung into the left shoulder (self penetration), an elbow
accelerated at twice its limit, stored velocities that disagree with the positions, a
torso set between two trajectories and by ``moving-torso`` (jumps). Each is found with
its kind, culprit and depth or excess; a real PR2 kitchen transport is audited as it is
today.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
import pytest

from robocram.cli import main
from robocram.designators import a
from robocram.execution import perform, sub_task, top_level
from robocram.motion import (
    ContactAllowance,
    JointTrajectory,
    TrajectoryPoint,
    joint_limits,
    report_executed,
    time_parameterize,
)
from robocram.projection import simulated_robot
from robocram.tf import Pose
from robocram.tf.quaternion import from_euler
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.audit_bounds import AuditBounds, adjacent_pairs_of
from robocram.traces.audit_findings import AuditFinding, AuditReport, FindingKind
from robocram.traces.trajectory_audit import audit_runs
from robocram.world import World
from tests.kitchen_transports import SHARED, Transports

WALL_X = 0.5  # [m] the low wall's centre in map, in front of the PR2
DRIVE = 0.1  # [m] how far the base drives into it
ELBOW = "r_elbow_flex_joint"
ELBOW_ACCELERATION = 3.0  # [rad/s^2] twice the PR2 elbow's default limit of 1.5
SWING_PAN = 0.3  # [rad] the right shoulder's pan that puts the right hand in the left shoulder
DEPTH_TOLERANCE = 0.001  # [m]
pytestmark = SHARED  # its PR2 and HSR kitchen transports: tests/kitchen_transports.py


@dataclass
class PlantedRun:
    """The store, the run, and what was measured on the world while planting."""

    db_path: Path
    run: int
    wall_gap: float  # [m] base link to wall before driving
    swing_pair: tuple[str, str]  # the deepest right-hand / left-arm pair at the swing's end
    swing_depth: float  # [m]


def _execute(world: World, task_name: str, trajectory: JointTrajectory) -> None:
    """In a task ``task_name``: put the robot at the trajectory's end and report it."""
    with sub_task(task_name):
        end = trajectory.end
        if trajectory.kind == "base":
            world.set_pose("pr2", Pose((end["x"], end["y"], 0.0), from_euler(0, 0, end["yaw"])))
        else:
            world.set_joint_states("pr2", end)
        report_executed(trajectory)


def _timed(
    world: World, names: tuple[str, ...], path: list[list[float]], kind: str = "arm"
) -> JointTrajectory:
    limits = joint_limits(world.robot("pr2").description, names)
    return time_parameterize("pr2", names, path, limits, kind=kind)


def _elbow_profile(start: float, travel: float, period: float) -> JointTrajectory:
    """``q = start + travel (s - sin(2 pi s) / 2 pi)``, ``s = t / period``: at rest at both
    ends, the acceleration at most ``2 pi travel / period^2``; exact velocities stored."""
    points = []
    for t in np.linspace(0.0, period, int(round(period / 0.01)) + 1):
        s = t / period
        q = start + travel * (s - math.sin(math.tau * s) / math.tau)
        v = travel / period * (1.0 - math.cos(math.tau * s))
        acc = travel * math.tau / period**2 * math.sin(math.tau * s)
        points.append(TrajectoryPoint((q,), (v,), (acc,), float(t)))
    return JointTrajectory("pr2", (ELBOW,), tuple(points))


def _deepest_pair(world: World, mine: str, theirs: str) -> tuple[tuple[str, str], float]:
    """The deepest pair of the robot's links named ``mine*`` and ``theirs*`` now."""
    found = [
        (p.distance, (p.link_a, p.link_b))
        for p in world.contacts.contact_points("pr2", "pr2")
        if p.link_a.startswith(mine) and p.link_b.startswith(theirs)
    ]
    distance, pair = min(found)
    return pair, -distance


def planted_run(db_path: Path) -> PlantedRun:
    """Trace a PR2 at a low wall through the planted faults (see the module docstring)."""
    world = World()
    world.bodies.add_floor()
    world.add_robot("pr2")
    desc = world.robot("pr2").description
    for arm in desc.arms.values():
        world.set_joint_states("pr2", dict(arm.parking))
    world.add_box("wall", (0.2, 1.0, 0.2), ((WALL_X, 0.0, 0.2), (0.0, 0.0, 0.0, 1.0)))
    (gap,) = [
        p.distance for p in world.contacts.contact_points("pr2", "wall", "base_link", distance=0.5)
    ]
    base = ("x", "y", "yaw")
    right = desc.arms["right"].joints
    parked = [desc.arms["right"].parking[j] for j in right]
    swung = [
        SWING_PAN if j == "r_shoulder_pan_joint" else v for j, v in zip(right, parked, strict=True)
    ]
    tight = ContactAllowance("base_link", "wall", 0.01)
    loose = ContactAllowance("base_link", "wall", 0.1)
    with trace_to(db_path, world=world) as tracer, simulated_robot(world, "pr2", name="planted"):
        _execute(world, "into-wall", _timed(world, base, [[0, 0, 0], [DRIVE, 0, 0]], "base"))
        out = _timed(world, base, [[DRIVE, 0, 0], [0, 0, 0]], "base")
        _execute(world, "out-tight", replace(out, allowed_contacts=(tight,)))
        in_out = _timed(world, base, [[0, 0, 0], [DRIVE, 0, 0], [0, 0, 0]], "base")
        _execute(world, "in-out-loose", replace(in_out, allowed_contacts=(loose,)))
        _execute(world, "swing", _timed(world, right, [parked, swung]))
        swing_pair, swing_depth = _deepest_pair(world, "r_", "l_")
        _execute(world, "swing-back", _timed(world, right, [swung, parked]))
        elbow = desc.arms["right"].parking[ELBOW]
        travel = ELBOW_ACCELERATION * 2.0**2 / math.tau  # period 2 s: 1.91 rad
        _execute(world, "elbow-fast", _elbow_profile(elbow, travel, 2.0))
        slow = _elbow_profile(elbow + travel, -travel, 4.0)
        frozen = tuple(replace(p, velocities=(0.0,)) for p in slow.points)
        _execute(world, "elbow-velocities-zero", replace(slow, points=frozen))
        world.set_joint_states("pr2", {"torso_lift_joint": 0.05})  # no trajectory
        _execute(world, "torso-up", _timed(world, ("torso_lift_joint",), [[0.05], [0.1]]))
        perform(a.motion(type="moving-torso", joint_angle=0.2))
    world.close()
    return PlantedRun(db_path, tracer.runs[0], gap, swing_pair, swing_depth)


@pytest.fixture(scope="module")
def planted(tmp_path_factory: pytest.TempPathFactory) -> PlantedRun:
    return planted_run(tmp_path_factory.mktemp("audit") / "runs.db")


@pytest.fixture(scope="module")
def planted_report(planted: PlantedRun) -> AuditReport:
    with TraceDatabase(planted.db_path, create=False) as db:
        return audit_runs(db, planted.run)


def _in_task(report: AuditReport, task: str, kind: FindingKind) -> list[AuditFinding]:
    return [f for f in report.of(kind) if (f.task_path or "").endswith(task)]


def test_a_drive_into_a_wall_is_a_world_penetration_as_deep_as_it_went(
    planted: PlantedRun, planted_report: AuditReport
) -> None:
    (found,) = _in_task(planted_report, "into-wall", FindingKind.WORLD_PENETRATION)
    assert found.what == "pr2:base_link / wall"
    assert found.amount == pytest.approx(DRIVE - planted.wall_gap, abs=DEPTH_TOLERANCE)
    assert found.bound == pytest.approx(0.001)
    assert found.trajectory == 0 and found.samples > 1


def test_an_allowed_contact_is_held_to_its_own_bound(
    planted: PlantedRun, planted_report: AuditReport
) -> None:
    (too_deep,) = _in_task(planted_report, "out-tight", FindingKind.ALLOWED_CONTACT_TOO_DEEP)
    assert too_deep.what == "pr2:base_link / wall"
    assert too_deep.amount == pytest.approx(DRIVE - planted.wall_gap, abs=DEPTH_TOLERANCE)
    assert too_deep.bound == pytest.approx(0.01)
    assert not _in_task(planted_report, "out-tight", FindingKind.WORLD_PENETRATION)
    loose = [f for kind in FindingKind for f in _in_task(planted_report, "in-out-loose", kind)]
    assert not [f for f in loose if "wall" in f.what]


def test_an_arm_swung_into_the_other_shoulder_is_a_self_penetration(
    planted: PlantedRun, planted_report: AuditReport
) -> None:
    found = {f.what: f for f in _in_task(planted_report, "/swing", FindingKind.SELF_PENETRATION)}
    a_link, b_link = planted.swing_pair
    deepest = found[f"pr2:{a_link} / pr2:{b_link}"]
    assert deepest.amount == pytest.approx(planted.swing_depth, abs=DEPTH_TOLERANCE)
    assert planted.swing_depth > 0.03
    # the skipped pairs are a parameter: skipping this one, it is not found
    skip = frozenset({a_link, b_link})
    bounds = AuditBounds(skipped_self_pairs=lambda robot: adjacent_pairs_of(robot) | {skip})
    with TraceDatabase(planted.db_path, create=False) as db:
        again = audit_runs(db, planted.run, bounds)
    assert deepest.what not in {
        f.what for f in _in_task(again, "/swing", FindingKind.SELF_PENETRATION)
    }


def test_an_elbow_at_twice_its_acceleration_limit_is_found_and_nothing_else(
    planted_report: AuditReport,
) -> None:
    (found,) = _in_task(planted_report, "elbow-fast", FindingKind.ACCELERATION)
    assert found.what == f"joint {ELBOW}"
    assert found.bound == pytest.approx(1.5)
    assert found.amount == pytest.approx(ELBOW_ACCELERATION, rel=0.01)
    limits = (FindingKind.VELOCITY, FindingKind.JERK, FindingKind.VELOCITY_MISMATCH)
    assert not [f for kind in limits for f in _in_task(planted_report, "elbow-fast", kind)]
    assert not _in_task(planted_report, "elbow-fast", FindingKind.ACCELERATION_MISMATCH)


def test_stored_velocities_that_disagree_with_the_positions_are_found(
    planted_report: AuditReport,
) -> None:
    (found,) = _in_task(planted_report, "elbow-velocities-zero", FindingKind.VELOCITY_MISMATCH)
    assert found.what.startswith(f"joint {ELBOW} stored 0")
    peak = 2 * ELBOW_ACCELERATION * 2.0**2 / math.tau / 4.0  # 2 travel / period
    assert found.amount == pytest.approx(peak, rel=0.01)
    assert not _in_task(planted_report, "elbow-velocities-zero", FindingKind.ACCELERATION)


def test_a_torso_set_without_a_trajectory_is_a_jump(planted_report: AuditReport) -> None:
    """A joint set between two trajectories jumps; ``moving-torso`` moves along its own
    trajectory now, so it jumps no more (it did: the torso was set)."""
    jumps = planted_report.of(FindingKind.TELEPORT)
    (between,) = [f for f in jumps if (f.task_path or "").endswith("torso-up")]
    assert between.what.startswith("pr2 joint torso_lift_joint 0.0000 -> 0.0500")
    assert between.amount == pytest.approx(0.05, abs=1e-9)
    assert not [f for f in jumps if (f.task_path or "").endswith("moving-torso")]
    assert len(jumps) == 1  # nothing else jumped


def test_a_held_object_driven_into_a_shelf_is_found_and_a_base_put_aside_jumps(
    tmp_path: Path,
) -> None:
    world = World()
    world.bodies.add_floor()
    world.add_robot("pr2")
    for arm in world.robot("pr2").description.arms.values():
        world.set_joint_states("pr2", dict(arm.parking))
    low, high = world.contacts.link_aabb("pr2", "r_gripper_palm_link")
    y, z = (low[1] + high[1]) / 2, (low[2] + high[2]) / 2
    front = max(world.contacts.link_aabb("pr2", link)[1][0] for link in world.link_names("pr2"))
    world.add_box("stick", (0.3, 0.03, 0.03), ((front + 0.16, y, z), (0.0, 0.0, 0.0, 1.0)))
    world.attach("stick", "pr2", "r_gripper_tool_frame")
    world.add_box("shelf", (0.1, 0.3, 0.3), ((front + 0.4, y, z), (0.0, 0.0, 0.0, 1.0)))
    (gap,) = [p.distance for p in world.contacts.contact_points("stick", "shelf", distance=0.5)]
    db_path = tmp_path / "held.db"
    with trace_to(db_path, world=world), simulated_robot(world, "pr2", name="held"):
        _execute(
            world, "push", _timed(world, ("x", "y", "yaw"), [[0, 0, 0], [DRIVE, 0, 0]], "base")
        )
        world.set_pose("pr2", Pose((DRIVE, 0.05, 0.0)))  # put aside: no trajectory
        perform(a.motion(type="moving-torso", joint_angle=0.0))  # a stored state, no change
    world.close()
    with TraceDatabase(db_path, create=False) as db:
        report = audit_runs(db)
    (pushed,) = _in_task(report, "push", FindingKind.WORLD_PENETRATION)
    assert pushed.what == "stick / shelf"
    assert pushed.amount == pytest.approx(DRIVE - gap, abs=DEPTH_TOLERANCE)
    assert not _in_task(report, "push", FindingKind.ALLOWED_CONTACT_TOO_DEEP)
    (aside,) = report.of(FindingKind.TELEPORT)
    assert aside.what.startswith("pr2 base y 0.0000 -> 0.0500") and aside.trajectory is None
    assert aside.amount == pytest.approx(0.05, abs=1e-9)


def test_the_cli_exits_1_on_findings_and_prints_one_line_each(
    planted: PlantedRun, planted_report: AuditReport, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["runs", "audit", str(planted.db_path), "--run", str(planted.run)]) == 1
    lines = capsys.readouterr().out.splitlines()
    assert lines[: len(planted_report.findings)] == [f.line() for f in planted_report.findings]
    assert lines[len(planted_report.findings)].startswith(f"audited run(s) {planted.run}:")
    assert any(line.strip().startswith("teleport") for line in lines)


def _traced_drive(db_path: Path, robot: str) -> World:
    """Trace ``robot`` driving 0.3 m on an empty floor; the world is returned open."""
    world = World()
    world.bodies.add_floor()
    world.add_robot(robot)
    names = ("x", "y", "yaw")
    limits = joint_limits(world.robot(robot).description, names)
    path = [[0.0, 0.0, 0.0], [0.3, 0.1, 0.2]]
    drive = time_parameterize(robot, names, path, limits, kind="base")
    with trace_to(db_path, world=world), top_level(name="drive"):
        world.set_pose(robot, Pose((0.3, 0.1, 0.0), from_euler(0.0, 0.0, 0.2)))
        report_executed(drive)
    return world


def test_a_clean_run_exits_0(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    _traced_drive(tmp_path / "clean.db", "quadrotor").close()
    assert main(["runs", "audit", str(tmp_path / "clean.db")]) == 0
    (line,) = capsys.readouterr().out.splitlines()
    assert line.startswith("audited run(s) 1: 1 trajectories, ") and line.endswith("; clean")
    assert int(line.split(", ")[1].split()[0]) > 0.3 / 0.005  # 5 mm steps at least


def test_the_matrix_skips_the_hulls_a_pr2_overlaps_at_rest_and_its_drive_is_clean(
    tmp_path: Path,
) -> None:
    """The PR2's convex hulls overlap at rest (the base and the shoulders, ...): judged on
    adjacency alone its drive sinks them 258 mm; the self-collision matrix the audit
    skips by default (adjacent, always, default, chained, never) makes it clean."""
    world = _traced_drive(tmp_path / "pr2.db", "pr2")
    world.close()
    with TraceDatabase(tmp_path / "pr2.db", create=False) as db:
        plain = audit_runs(db, bounds=AuditBounds(skipped_self_pairs=adjacent_pairs_of))
        matrix = audit_runs(db)
    assert set(plain.counts()) == {FindingKind.SELF_PENETRATION}
    worst = plain.worst(FindingKind.SELF_PENETRATION)
    assert worst is not None and worst.what == "pr2:base_link / pr2:r_shoulder_pan_link"
    assert worst.amount == pytest.approx(0.258, abs=0.002)
    assert matrix.clean and matrix.configurations == plain.configurations


def test_a_run_traced_without_its_world_is_not_audited_and_says_so(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    db_path = tmp_path / "tree-only.db"
    with trace_to(db_path), top_level(name="no world"):
        pass
    assert main(["runs", "audit", str(db_path)]) == 0
    out = capsys.readouterr().out
    assert "  not audited: run 1: run 1 stores no scene" in out
    assert main(["runs", "audit", str(db_path), "--run", "1"]) == 3
    assert "run 1 stores no scene" in capsys.readouterr().err


def test_a_missing_database_or_run_is_one_line_of_bad_input(
    planted: PlantedRun, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["runs", "audit", str(tmp_path / "none.db")]) == 3
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "no trace database at" in err
    assert main(["runs", "audit", str(planted.db_path), "--run", "99"]) == 3
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "has no run 99" in err


@pytest.fixture(scope="module")
def kitchen_report(kitchen_transports: Transports) -> AuditReport:
    """The audit of a PR2 kitchen mug transport (test_traces_audit_hand.py's too)."""
    return kitchen_transports("pr2", "mug").report


def test_a_pr2_kitchen_transport_moves_its_head_and_grippers_only_along_trajectories(
    kitchen_report: AuditReport,
) -> None:
    """The head and the grippers used to jump at every look and opening."""
    assert kitchen_report.of(FindingKind.TELEPORT) == []
    assert kitchen_report.of(FindingKind.SELF_PENETRATION) == []


def test_a_pr2_kitchen_transport_keeps_its_fingers_out_of_the_mug(
    kitchen_report: AuditReport,
) -> None:
    """Its top grasp put the finger links 6.5 mm into the mug's wall (issue 35): the grasp
    now straddles 4 cm under the top; the hand's contacts are bounded (5 mm) and stored."""
    assert kitchen_report.of(FindingKind.WORLD_PENETRATION) == []  # drives included
    assert kitchen_report.of(FindingKind.ALLOWED_CONTACT_TOO_DEEP) == []
    assert kitchen_report.clean, kitchen_report.summary_lines()


def test_a_pr2_kitchen_transport_keeps_every_limit(kitchen_report: AuditReport) -> None:
    """Tool lines used to pass their corners at speed (20x the acceleration limit); every
    path kind is now timed within velocity, acceleration and jerk."""
    for kind in (
        FindingKind.VELOCITY, FindingKind.ACCELERATION, FindingKind.JERK,
        FindingKind.VELOCITY_MISMATCH, FindingKind.ACCELERATION_MISMATCH,
    ):  # fmt: skip
        assert kitchen_report.of(kind) == []


def test_an_hsr_kitchen_transport_is_clean(kitchen_transports: Transports) -> None:
    report = kitchen_transports("hsrb", "mug").report  # test_traces_audit_hand.py's too
    # it used to jump its head and hand, and open its hand into its base (6.6 mm) parked
    assert report.clean, report.summary_lines()
