"""Issue 37: a suction hand's side grasp. The bare UR5 (drafted with a suction gripper)
touches the tabletop mug's side at half height, lifts it while drawing it back, and holds
it; its grasp list starts with the top grasps it had before the side grasp came."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import pybullet
import pytest

from robocram.grasping import grasp_candidates
from robocram.plans.basic_actions import park_arms
from robocram.plans.fetch import _suction
from robocram.plans.flank_stands import FLANK_DISTANCES, flank_stands
from robocram.plans.known_robot import current_robot
from robocram.plans.pick_object import pick_up_object
from robocram.plans.stands import yaw_of
from robocram.projection import simulated_robot
from robocram.robots import example_robot_data_folder
from robocram.scenes import tabletop_scene
from robocram.tf import PoseStamped
from tests.drafts import drafted_module

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")

BEFORE = ("top", "front", "left", "right", "rim", "handle")  # the grasp names before `side`


@pytest.fixture(scope="module")
def module(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The bare UR5 of example-robot-data (no gripper), drafted to a module file."""
    urdf = example_robot_data_folder() / "ur_description" / "urdf" / "ur5_robot.urdf"
    path = tmp_path_factory.mktemp("ur5_side") / "ur5_robot.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(urdf, path)
    return path


def test_the_grasp_list_starts_with_what_it_had(module: Path) -> None:
    scene = tabletop_scene(str(module))
    world = scene.world
    try:
        robot, mug = world.robot(scene.robot), world.object("mug-1")
        (arm,) = robot.description.arms
        now = grasp_candidates(world, mug, robot, arm)
        had = grasp_candidates(world, mug, robot, arm, BEFORE)
    finally:
        world.close()
    assert [c.grasp for c in now[: len(had)]] == [c.grasp for c in had]
    assert {c.grasp.name for c in had} == {"top"}
    assert [c.grasp.name for c in now[len(had) :]] == ["side"] * 12  # 3 sides, 4 turns


def test_the_side_grasp_holds_the_mug_by_its_side(module: Path) -> None:
    """Checked with raw PyBullet: the mug rose by the side grasp's 5 cm and came 10 cm
    towards the arm, and the hand touches it (within its 5 mm bound) on its side, at half
    height, not on its top."""
    scene = tabletop_scene(str(module))
    world = scene.world
    world.kb.consult("object_grasps(mug, [side]).", group="side_only")
    try:
        client = world.physics.client()
        mug = world.object("mug-1").body_id
        robot = world.object(scene.robot).body_id
        before, _ = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)
        low, high = pybullet.getAABB(mug, physicsClientId=client)
        with simulated_robot(world, scene.robot):
            park_arms()
            held = pick_up_object("mug-1")
        after, _ = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)
        points = pybullet.getClosestPoints(robot, mug, 0.01, physicsClientId=client)
        touch = min(points, key=lambda p: p[8])
    finally:
        world.close()
    assert held.grasp == "side"
    assert after[2] - before[2] == pytest.approx(0.05, abs=0.005)
    assert ((after[0] - before[0]) ** 2 + (after[1] - before[1]) ** 2) ** 0.5 == pytest.approx(
        0.10, abs=0.005
    )
    assert -0.005 <= touch[8] <= 0.005
    rise = after[2] - before[2]
    on_mug = touch[6][2] - rise  # the touch on the mug, where the mug stood
    height = high[2] - low[2]
    assert low[2] + 0.3 * height < on_mug < low[2] + 0.7 * height  # its side, half-way up


def test_only_a_suction_hand_gets_flank_stands_on_its_side_of_the_object(module: Path) -> None:
    """The fetch's last flank stands are a suction hand's (the PR2's fingers have side
    grasps of their own); they stand at the flank distances from the object, on the
    robot's side of it, the base turned a quarter from facing it."""
    for robot_name, suction in ((str(module), True), ("pr2", False)):
        scene = tabletop_scene(robot_name)
        world = scene.world
        try:
            with simulated_robot(world, scene.robot):
                robot = current_robot()
                assert _suction(robot, None) is suction
                mug = world.pose("mug-1")
                where = PoseStamped("map", mug.position, mug.orientation)
                stands = list(flank_stands(robot, where, None))
                base = world.pose(scene.robot).position
        finally:
            world.close()
        assert len(stands) == len(FLANK_DISTANCES) * 2
        mx, my, _ = where.pose.position
        distances = [d for d in FLANK_DISTANCES for _ in (0, 1)]
        for (pose, _), distance in zip(stands, distances, strict=True):
            sx, sy, _ = pose.position
            assert math.hypot(sx - mx, sy - my) == pytest.approx(distance, abs=1e-9)
            facing = math.atan2(my - sy, mx - sx)
            turn = (yaw_of(pose) - facing + math.pi) % (2 * math.pi) - math.pi
            assert abs(turn) == pytest.approx(math.pi / 2, abs=1e-9)
            # on the robot's side of the object (a bare table: no axes to square it to)
            assert math.atan2(sy - my, sx - mx) == pytest.approx(
                math.atan2(base[1] - my, base[0] - mx), abs=1e-9
            )
