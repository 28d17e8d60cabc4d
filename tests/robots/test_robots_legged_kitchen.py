"""Issue 37: legged robots in the kitchen. ANYmal's and B1's root link is their trunk,
0.58 and 0.71 m over their feet: the kitchen stands them on the floor (not with their legs
in it), their stands are at that height, and they face a counter no nearer than their legs
reach ahead. The B1's drafted stance puts its feet under its hips (at its URDF's rest they
stood 0.20 m ahead of them, 0.58 m ahead of its origin). Judged with raw PyBullet: the
links' bounds and frames, the mug's place on the table.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterator
from pathlib import Path

import pybullet
import pytest

from robocram.costmaps.occupancy import facing_radius
from robocram.designators import a, an
from robocram.plans import perform
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.container_access import OpenedContainer, close_again
from robocram.plans.containers import container
from robocram.plans.stands import HandleStand
from robocram.projection import simulated_robot
from robocram.robots import draft_description
from robocram.robots.example_robot_data import example_robot_data_folder
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

ROBOTS = example_robot_data_folder()
ANYMAL = ROBOTS / "anymal_b_simple_description" / "robots" / "anymal-kinova.urdf"
B1 = ROBOTS / "b1_description" / "urdf" / "b1-z1.urdf"
ON_THE_FLOOR = 0.01  # [m] the lowest point's height, Bullet's margin allowed
LEGS = ("FR_", "FL_", "RR_", "RL_")  # the B1's legs' link name prefixes
DRAWER = "drawer_unit_drawer_3"  # the bowl's
OPENED_FROM = (-1.4, 0.96)  # [m] map: where the B1's transport opens it from, facing it

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")


def _drafted(urdf: Path, folder: Path) -> str:
    path = folder / f"{urdf.stem.replace('-', '_')}.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        path.write_text(draft_description(urdf).source(path), encoding="utf-8")
    return str(path)


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("legged")


@pytest.fixture(scope="module")
def b1(folder: Path) -> str:
    """The B1's draft, written once for the module's tests (drafting it took ~0.8 s)."""
    return _drafted(B1, folder)


@pytest.fixture(scope="module")
def b1_kitchen(b1: str) -> Iterator[KitchenScene]:
    """The B1's kitchen as built (~2.3 s), for the module's B1 tests: what one turns or
    runs it puts back exactly (``stored_state``)."""
    scene = kitchen_scene(b1)
    yield scene
    scene.world.close()


def _bounds(body: int, client: int) -> list[tuple[str, tuple[float, ...], tuple[float, ...]]]:
    """Each link's name and PyBullet bounds (the base's too, as ``""``)."""
    count = pybullet.getNumJoints(body, physicsClientId=client)
    names = [""] + [
        pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode() for i in range(count)
    ]
    return [
        (name, *pybullet.getAABB(body, i, physicsClientId=client))
        for i, name in zip(range(-1, count), names, strict=True)
    ]


def test_anymal_stands_on_the_floor_and_brings_the_mug_to_the_table(folder: Path) -> None:
    scene = kitchen_scene(_drafted(ANYMAL, folder))
    world = scene.world
    try:
        client = world.physics.client()
        robot = world.object(scene.robot).body_id
        lowest = min(low[2] for _, low, _ in _bounds(robot, client))
        trunk = pybullet.getBasePositionAndOrientation(robot, physicsClientId=client)[0][2]
        with simulated_robot(world, scene.robot):
            target = a.location(on=("kitchen", "table_top"), for_="mug-1")
            perform(an.action(type="transporting", object="mug", target=target))
        kitchen = world.object("kitchen").body_id
        table = next(b for b in _bounds(kitchen, client) if b[0] == "table_top")
        mug_low, mug_high = pybullet.getAABB(world.object("mug-1").body_id, physicsClientId=client)
    finally:
        world.close()
    assert abs(lowest) <= ON_THE_FLOOR and trunk > 0.4
    _, low, high = table
    middle = [(mug_low[k] + mug_high[k]) / 2 for k in range(2)]
    assert low[0] <= middle[0] <= high[0] and low[1] <= middle[1] <= high[1]
    assert mug_low[2] == pytest.approx(high[2], abs=0.01)  # standing on it


def test_b1_faces_a_counter_no_nearer_than_its_legs_reach(b1_kitchen: KitchenScene) -> None:
    """Its facing radius covers its legs' reach ahead (PyBullet, the robot turned to the
    map's x), which lies beyond its trunk's front: its hips, its feet under them."""
    world = b1_kitchen.world
    with world.snapshots.stored_state():  # the scene is the module's: turned back after
        client = world.physics.client()
        robot = world.object(b1_kitchen.robot)
        x, y, z = world.pose(robot).position
        world.set_pose(robot, Pose((x, y, z)))
        bounds = _bounds(robot.body_id, client)
        legs = max(high[0] for name, _, high in bounds if name[:3] in LEGS) - x
        trunk = next(high[0] for name, _, high in bounds if name == "trunk") - x
        radius = facing_radius(world, robot)
    assert legs > trunk + 0.03
    assert radius == pytest.approx(legs, abs=0.02)


def test_b1_drafted_stands_with_its_feet_under_its_hips(b1_kitchen: KitchenScene) -> None:
    """Each foot's frame stands within 3 cm (horizontally) of its thigh joint's (PyBullet
    link frames in the kitchen), the lowest part on the floor, the trunk 0.71 m up."""
    world = b1_kitchen.world
    client = world.physics.client()
    body = world.object(b1_kitchen.robot).body_id
    index = {
        pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode(): i
        for i in range(pybullet.getNumJoints(body, physicsClientId=client))
    }

    def frame(link: str) -> tuple[float, ...]:
        state = pybullet.getLinkState(
            body, index[link], computeForwardKinematics=True, physicsClientId=client
        )
        return tuple(state[4])

    offsets = [math.dist(frame(f"{leg}foot")[:2], frame(f"{leg}thigh")[:2]) for leg in LEGS]
    lowest = min(low[2] for _, low, _ in _bounds(body, client))
    trunk = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)[0][2]
    assert max(offsets) < 0.03
    assert abs(lowest) <= ON_THE_FLOOR and trunk == pytest.approx(0.71, abs=0.02)


def test_b1_closes_the_open_drawer_from_beside_its_handle(b1_kitchen: KitchenScene) -> None:
    """From where it opened the bowl's drawer the B1 does not take the open handle; from a
    stand aside of it, it pushes the drawer shut (the drawer's joint read from PyBullet).
    In the module's kitchen, put back exactly after (``stored_state``)."""
    scene = b1_kitchen
    world = scene.world
    with world.snapshots.stored_state():
        client = world.physics.client()
        kitchen = world.object("kitchen")
        joint = kitchen.joint_index[f"{DRAWER}_joint"]
        world.set_joint_states("kitchen", {f"{DRAWER}_joint": 0.4})
        height = world.pose(scene.robot).position[2]
        stand = Pose((*OPENED_FROM, height), quat.from_euler(0.0, 0.0, math.pi / 2))
        world.set_pose(scene.robot, stand)
        log = AttemptLog()
        with simulated_robot(world, scene.robot):
            close_again(OpenedContainer(container(DRAWER), HandleStand(stand, "arm")), log)
        shut = pybullet.getJointState(kitchen.body_id, joint, physicsClientId=client)[0]
    assert shut == pytest.approx(0.0, abs=0.005)
    tries = log.of("close")
    assert tries[0].failure is not None and tries[-1].failure is None
    closed_from = tries[-1].stand
    assert closed_from is not None
    assert abs(closed_from.position[0] - OPENED_FROM[0]) == pytest.approx(0.2, abs=1e-3)
