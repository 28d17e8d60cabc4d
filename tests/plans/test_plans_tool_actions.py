"""The tool actions on the PR2, Boxy and the drafted Fetch, judged by raw PyBullet and the
trace audit.

Pouring lands most particles in the bowl and a covered bowl fails naming its cover;
wiping covers the region (cells marked under the sponge's own bounds, read from PyBullet,
where it touches the table); cutting gives the slices asked for, of even widths; the
spoon never comes nearer the bowl than it may; every traced run passes the audit (the
grains poured and the slices cut are stored with the world states and replayed). Boxy
reaches none of the paths from where the tabletop puts it: it carries the tool to stands
that reach the work (``plans/tool_stands.py``) and works from there.
"""

from __future__ import annotations

import json
import math
import sqlite3
import sys
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.designators import an
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.plans import perform
from robocram.plans.tool_failures import TargetCovered
from robocram.plans.tool_results import CuttingResult, PouringResult, WipingResult
from robocram.projection import simulated_robot
from robocram.scenes.tool_objects import add_tool_object
from robocram.tf import Pose
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.trajectory_audit import audit_runs
from robocram.world import World

sys.path.insert(0, str(Path(__file__).resolve().parent))
from tool_setup import tool_scene  # noqa: E402

FETCH = str(Path(__file__).resolve().parents[1] / "data" / "fetch" / "fetch.py")
STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
ROBOTS = ["pr2", "boxy", FETCH]
# arms that reach with their base follow the paths with base and arm in one trajectory
# (motion/whole_body_tool_path.py): the HSR (holonomic) and the Stretch (differential)
WHOLE_BODY = ["hsrb", STRETCH]
ALL = [*ROBOTS, *WHOLE_BODY]
ALL_IDS = ["pr2", "boxy", "fetch", "hsrb", "stretch"]
# Boxy's pour (14 s of particles) is left to the bench. Its stir carries the 16 cm spoon
# round to the path's start: before held things joined the self walk
# (motion/held_self_pairs.py), the audit found the spoon 27 mm in Boxy's base there
BOWL_INSIDE = 0.074  # [m] the catalogue bowl's radius within its wall
BOWL_RIM = 0.06  # [m]


def _raw_position(world: World, name: str) -> tuple[float, float, float]:
    pos, _ = pybullet.getBasePositionAndOrientation(
        world.object(name).body_id, physicsClientId=world.physics.client()
    )
    return (pos[0], pos[1], pos[2])


def _added_in_last_state(db_path: Path) -> tuple[set[str], set[str]]:
    """Of the run's last stored world state, read with raw SQL: the bodies it stores with
    their recipe (added mid-run) and the bodies it has."""
    with sqlite3.connect(db_path) as con:
        added, poses = con.execute(
            "SELECT added, poses FROM world_states ORDER BY time DESC, id DESC LIMIT 1"
        ).fetchone()
    return set(json.loads(added or "{}")), set(json.loads(poses))


@pytest.mark.parametrize("robot", ["pr2", FETCH, "hsrb"], ids=["pr2", "fetch", "hsrb"])
def test_pouring_lands_the_particles_in_the_bowl(robot: str, tmp_path: Path) -> None:
    scene = tool_scene(robot, "cup")
    x, y, h = scene.spot
    add_tool_object(scene.world, "bowl-1", "bowl", Pose((x + 0.05, y - 0.1, h)))
    with (
        trace_to(tmp_path / "pour.db", world=scene.world),
        simulated_robot(scene.world, scene.robot),
    ):
        result = perform(an.action(type="pouring", source="cup-1", target="bowl-1", amount=60))
    assert isinstance(result, PouringResult)
    world = scene.world
    bowl = _raw_position(world, "bowl-1")
    grains = [o.name for o in world.objects("particle")]
    inside = 0
    for name in grains:
        px, py, pz = _raw_position(world, name)
        if math.hypot(px - bowl[0], py - bowl[1]) < BOWL_INSIDE and pz < bowl[2] + BOWL_RIM:
            inside += 1
    assert len(grains) == result.particles == 30
    assert inside == result.landed and inside >= 0.9 * len(grains)
    assert result.spilled == len(grains) - inside
    assert result.fraction == 1.0
    added, present = _added_in_last_state(tmp_path / "pour.db")
    assert added == set(grains) and added <= present  # the grains, stored with their recipe
    with TraceDatabase(tmp_path / "pour.db") as db:
        report = audit_runs(db)  # replays the grains poured mid-run
    assert report.clean, report.summary_lines()


def test_pouring_into_a_covered_bowl_fails_naming_the_cover() -> None:
    scene = tool_scene("pr2", "cup")
    x, y, h = scene.spot
    world = scene.world
    add_tool_object(world, "bowl-1", "bowl", Pose((x + 0.05, y - 0.1, h)))
    world.add_item("plate-1", "plate", Pose((x + 0.05, y - 0.1, h + BOWL_RIM + 0.0105)))
    before = world.joint_states(scene.robot)
    with simulated_robot(world, scene.robot), pytest.raises(TargetCovered) as caught:
        perform(an.action(type="pouring", source="cup-1", target="bowl-1", amount=60))
    assert (caught.value.target, caught.value.cover) == ("bowl-1", "plate-1")
    assert world.joint_states(scene.robot) == before  # refused before anything moved


def _put(world: World, robot: str, names: tuple[str, ...], values: object) -> None:
    """The robot at a trajectory point: a whole-body point's ``x``, ``y``, ``yaw`` put as
    its pose in map (what it holds rides along), the rest as joints."""
    named = dict(zip(names, (float(v) for v in values), strict=True))  # type: ignore[attr-defined]
    if "yaw" in named:
        height = world.pose(robot).position[2]
        turn = (0.0, 0.0, math.sin(named["yaw"] / 2), math.cos(named["yaw"] / 2))
        world.set_pose(robot, Pose((named.pop("x"), named.pop("y"), height), turn))
        named.pop("yaw")
    world.set_joint_states(robot, named)


def _replayed_cells(
    world: World,
    robot: str,
    trajectories: list[JointTrajectory],
    region: tuple[float, ...],
    top: float,
) -> float:
    """The share of the region's 5 mm cells under the sponge's PyBullet bounds at a
    trajectory point where the bounds reach the table top."""
    x, y, sx, sy = region
    xs = np.arange(x - sx / 2 + 0.0025, x + sx / 2, 0.005)
    ys = np.arange(y - sy / 2 + 0.0025, y + sy / 2, 0.005)
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    marked = np.zeros(gx.shape, dtype=bool)
    body, cid = world.object("sponge-1").body_id, world.physics.client()
    for trajectory in trajectories:
        for point in trajectory.points:
            _put(world, robot, trajectory.joint_names, point.positions)
            low, high = pybullet.getAABB(body, physicsClientId=cid)
            if low[2] <= top + 0.001:
                marked |= (gx >= low[0]) & (gx <= high[0]) & (gy >= low[1]) & (gy <= high[1])
    return float(marked.mean())


@pytest.mark.parametrize("robot", ALL, ids=ALL_IDS)
def test_wiping_covers_the_region_and_touches_only_the_table(robot: str, tmp_path: Path) -> None:
    scene = tool_scene(robot, "sponge")
    x, y, h = scene.spot
    seen: list[JointTrajectory] = []
    region = ((x, y), (0.2, 0.14))
    with (
        trace_to(tmp_path / "wipe.db", world=scene.world),
        trajectory_listener(seen.append),
        simulated_robot(scene.world, scene.robot),
    ):
        result = perform(an.action(type="wiping", surface="table", region=region, tool="sponge-1"))
    assert isinstance(result, WipingResult) and result.fraction == 1.0
    paths = [t for t in seen if t.kind == "tool-path"]
    covered = _replayed_cells(scene.world, scene.robot, paths, (x, y, 0.2, 0.14), h)
    assert covered >= 0.9 and result.covered >= 0.9
    assert abs(covered - result.covered) < 0.1
    with TraceDatabase(tmp_path / "wipe.db") as db:
        report = audit_runs(db)
    assert not report.findings, report.summary_lines()


@pytest.mark.parametrize("robot", ALL, ids=ALL_IDS)
def test_cutting_gives_the_slices_of_even_widths(robot: str, tmp_path: Path) -> None:
    scene = tool_scene(robot, "knife")
    x, y, h = scene.spot
    world = scene.world
    add_tool_object(world, "bread-1", "bread", Pose((x, y, h + 0.04)))
    with trace_to(tmp_path / "cut.db", world=world), simulated_robot(world, scene.robot):
        result = perform(an.action(type="cutting", object="bread-1", tool="knife-1", slices=4))
    assert isinstance(result, CuttingResult) and len(result.slices) == 4
    assert "bread-1" not in [o.name for o in world.objects()]
    cid = world.physics.client()
    widths = []
    for name in result.slices:
        low, high = pybullet.getAABB(world.object(name).body_id, physicsClientId=cid)
        widths.append(high[1] - low[1])  # the loaf lies along map y
    assert max(widths) <= 1.2 * min(widths)
    assert sum(widths) == pytest.approx(0.24, abs=0.02)
    added, present = _added_in_last_state(tmp_path / "cut.db")
    assert added == set(result.slices) and "bread-1" not in present  # the loaf removed
    with TraceDatabase(tmp_path / "cut.db") as db:
        report = audit_runs(db)  # replays the loaf's removal and the slices' adding
    assert report.clean, report.summary_lines()


@pytest.mark.parametrize("robot", ALL, ids=ALL_IDS)
def test_mixing_keeps_the_spoon_clear_of_the_rim(robot: str, tmp_path: Path) -> None:
    scene = tool_scene(robot, "spoon")
    x, y, h = scene.spot
    world = scene.world
    add_tool_object(world, "bowl-1", "bowl", Pose((x, y, h)))
    seen: list[JointTrajectory] = []
    with (
        trace_to(tmp_path / "mix.db", world=world),
        trajectory_listener(seen.append),
        simulated_robot(world, scene.robot),
    ):
        result = perform(an.action(type="mixing", container="bowl-1", tool="spoon-1"))
    assert result.fraction == 1.0
    cid = world.physics.client()
    spoon, bowl = world.object("spoon-1").body_id, world.object("bowl-1").body_id
    nearest = math.inf
    for trajectory in (t for t in seen if t.kind == "tool-path"):
        points = np.array([p.positions for p in trajectory.points])
        for a, b in zip(points, points[1:], strict=False):
            for s in np.linspace(0.0, 1.0, 4, endpoint=False):  # between the points too
                q = a + (b - a) * s
                _put(world, scene.robot, trajectory.joint_names, q)
                found = pybullet.getClosestPoints(spoon, bowl, 0.05, physicsClientId=cid)
                nearest = min([nearest, *(p[8] for p in found)])
    assert nearest > 0.0
    with TraceDatabase(tmp_path / "mix.db") as db:
        report = audit_runs(db)
    assert not report.findings, report.summary_lines()
