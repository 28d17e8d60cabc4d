"""The quadrotor in projection: flights to waypoints, a collision, and the range sensor."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import FlyingGoalInCollision, NoMatchingProcessModule
from robocram.projection import simulated_robot
from robocram.tf import Pose, PoseStamped
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.audit_findings import FindingKind
from robocram.traces.trajectory_audit import audit_runs
from robocram.traces.trajectory_record import run_trajectories
from robocram.world import World


@pytest.fixture
def world() -> Iterator[World]:
    w = World()
    w.bodies.add_floor()
    w.add_robot("quadrotor", pose=Pose((0.0, 0.0, 0.2)))
    w.add_box("crate", (1.0, 1.0, 1.0), pose=Pose((3.0, 0.0, 0.5)))
    yield w
    w.close()


def _distance_down() -> float:
    return float(perform(a.motion(type="distance-sensing", direction=(0.0, 0.0, -1.0))))


def test_flies_three_waypoints_and_senses_the_floor(world: World) -> None:
    waypoints = [(0.0, 0.0, 1.0), (1.5, 1.0, 1.5), (1.5, -1.0, 0.8)]
    heights = []
    with simulated_robot(world, "quadrotor"):
        for point in waypoints:
            perform(a.motion(type="flying", target=a.location(pose=PoseStamped("map", point))))
            reached = world.pose("quadrotor")
            assert reached.distance_to(Pose(point)) < 0.01
            heights.append(_distance_down())
    assert heights == pytest.approx([1.0, 1.5, 0.8], abs=0.01)


def test_senses_the_crate_ahead(world: World) -> None:
    with simulated_robot(world, "quadrotor"):
        perform(a.motion(type="flying", target=a.location(pose=PoseStamped("map", (0, 0, 0.5)))))
        ahead = perform(a.motion(type="distance-sensing", direction=(1.0, 0.0, 0.0)))
    assert ahead == pytest.approx(2.5, abs=0.01)  # the crate's near face is at x = 2.5


def test_flying_through_the_crate_fails_and_stays(world: World) -> None:
    with simulated_robot(world, "quadrotor"):
        perform(a.motion(type="flying", target=a.location(pose=PoseStamped("map", (0, 0, 0.5)))))
        start = world.pose("quadrotor")
        beyond = PoseStamped("map", (5.0, 0.0, 0.5))
        with pytest.raises(FlyingGoalInCollision) as info:
            perform(a.motion(type="flying", target=a.location(pose=beyond)))
    assert info.value.colliding == ["crate"]
    assert world.pose("quadrotor").distance_to(start) < 1e-9


def test_a_quadrotor_has_no_torso_module(world: World) -> None:
    with simulated_robot(world, "quadrotor"), pytest.raises(NoMatchingProcessModule):
        perform(a.motion(type="moving-torso", joint_angle=0.1))


def test_flights_are_traced_trajectories_the_audit_finds_clean_and_a_jump_is_found(
    world: World, tmp_path: Path
) -> None:
    """Each flight is a timed trajectory of the body (x, y, z, roll, pitch, yaw): the trace
    stores it, the independent audit replays it on raw PyBullet and finds no penetration,
    no limit exceeded and no jump; a body put 0.5 m higher with no flight is a jump."""
    db = tmp_path / "flights.db"
    waypoints = [(0.0, 0.0, 1.0), (1.5, 1.0, 1.5), (1.5, -1.0, 0.8)]
    with trace_to(db, world=world), simulated_robot(world, "quadrotor", name="flights"):
        for point in waypoints:
            perform(a.motion(type="flying", target=a.location(pose=PoseStamped("map", point))))
        x, y, z = world.pose("quadrotor").position
        world.set_pose("quadrotor", Pose((x, y, z + 0.5)))  # a jump: no trajectory
        perform(a.motion(type="flying", target=a.location(pose=PoseStamped("map", (0, 0, 1)))))
    flights = run_trajectories(db, 1)
    assert [t.kind for t in flights] == ["flight"] * 4
    assert flights[0].joint_names == ("x", "y", "z", "roll", "pitch", "yaw")
    assert flights[0].points[-1].positions[:3] == pytest.approx(waypoints[0], abs=1e-9)
    with TraceDatabase(db, create=False) as opened:
        report = audit_runs(opened)
    jumps = report.of(FindingKind.TELEPORT)
    assert [f.kind for f in report.findings] == [FindingKind.TELEPORT]
    assert "base z" in jumps[0].what and jumps[0].amount == pytest.approx(0.5, abs=1e-6)
