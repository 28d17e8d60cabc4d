"""A robot built on a table works on it: Tracy's fixed camera looks down onto its own top.

Tracy (tests/data/zoo, drafted): two arms on a table, a camera on a pole looking 72
degrees down onto it. `robot check` takes that camera as looking ahead (down onto what lies
ahead) and puts its probe mug on the table where the optical axis meets it; the tabletop
scene lays its mug there and adds no table, and the pick-up lifts it, its IK not counting
the mug resting on the robot's own top as a collision. Its workcell's table is a thin
plate a hair above that top, round the items' spots, and it carries the mug to its spot
(and then the bowl). Judged by PyBullet: a ray down onto the mug's spot meets the
robot's own link, the mug rises; the plate lies a hair over the robot, touching it
nowhere, the mug and its spot lie near the optical axis, and the mug ends at its spot,
upright, nothing of the robot touching it or the plate. Its bowl, carried next (its
Robotiq's pads end behind its tool frame: deep rim grasps), ends at its spot as high as
it lay, the robot not touching it.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import pybullet
import pytest

from robocram.designators import an
from robocram.plans import perform, pick_up
from robocram.projection import simulated_robot
from robocram.robot_check import check_robot, description_from
from robocram.scenes import tabletop_scene, workcell_scene, workcell_spots
from tests.drafts import drafted_module

TRACY = Path(__file__).resolve().parents[1] / "data" / "zoo" / "tracy" / "tracy.urdf"
LIFTED = 0.03  # [m] the mug rises at least this much
HAIR = 0.005  # [m] the workcell's plate lies less than this above the robot's top
IN_VIEW = math.radians(20)  # the mug and its spot lie this near the camera's optical axis
PLACED = 0.02  # [m] the mug put down lies this near its spot
SETTLED = 0.01  # [m] and as high as it rested before


@pytest.fixture(scope="module")
def tracy(tmp_path_factory: pytest.TempPathFactory) -> str:
    module = tmp_path_factory.mktemp("tracy") / "tracy.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(TRACY, module)
    return str(module)


def test_its_check_passes_with_the_camera_looking_down_onto_its_table(tracy: str) -> None:
    card = check_robot(description_from(tracy))
    assert card.passed, card.failures()
    ahead = next(r for r in card.results if r.name.endswith("looks ahead"))
    assert "down onto what lies ahead" in ahead.detail


def test_its_mug_lies_on_its_own_top_and_it_lifts_it(tracy: str) -> None:
    scene = tabletop_scene(description_from(tracy))
    world = scene.world
    try:
        client, body = world.physics.client(), world.object(scene.robot).body_id
        mug = world.object("mug-1").body_id
        assert "table" not in {o.name for o in world.objects()}
        start, _ = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)
        pybullet.resetBasePositionAndOrientation(
            mug, (start[0], start[1], 5.0), (0, 0, 0, 1), physicsClientId=client
        )  # out of the way of the ray, then back
        hit = pybullet.rayTest(
            (start[0], start[1], 3.0), (start[0], start[1], 0.0), physicsClientId=client
        )[0]
        pybullet.resetBasePositionAndOrientation(mug, start, (0, 0, 0, 1), physicsClientId=client)
        assert hit[0] == body and hit[3][2] == pytest.approx(start[2], abs=0.005)
        with simulated_robot(world, scene.robot):
            pick_up(scene.look_target)
        end, _ = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)
        assert end[2] > start[2] + LIFTED
    finally:
        world.close()


def _optical_link(client: int, body: int) -> int:
    names = [
        pybullet.getJointInfo(body, j, physicsClientId=client)[12].decode()
        for j in range(pybullet.getNumJoints(body, physicsClientId=client))
    ]
    return names.index("camera_link_optical")


def test_its_workcell_lies_on_its_own_top_in_view_and_it_carries_the_mug_and_bowl(
    tracy: str,
) -> None:
    scene = workcell_scene(description_from(tracy))
    world, spots = scene.world, workcell_spots(scene)  # the bowl's: where the mug lay
    try:
        client, body = world.physics.client(), world.object(scene.robot).body_id
        plate = world.object(scene.environment).body_id
        mug = world.object("mug-1").body_id
        low, high = pybullet.getAABB(plate, -1, physicsClientId=client)
        below = pybullet.rayTest(  # the robot's own top, a hair under the plate
            (low[0] - 0.01, low[1] - 0.01, high[2] + 1.0),
            (low[0] - 0.01, low[1] - 0.01, 0.0),
            physicsClientId=client,
        )[0]
        assert below[0] == body and 0.0 < low[2] - below[3][2] < HAIR
        assert not pybullet.getClosestPoints(plate, body, 0.0, physicsClientId=client)
        eye, turn = pybullet.getLinkState(
            body, _optical_link(client, body), physicsClientId=client
        )[4:6]
        axis = pybullet.getMatrixFromQuaternion(turn)[2::3]  # the optical z, in the world
        spot = spots["mug-1"].position
        for name, target in {"mug": _position(client, mug), "spot": spot}.items():
            to = [t - e for t, e in zip(target, eye, strict=True)]
            cos = sum(a * b for a, b in zip(axis, to, strict=True)) / math.dist(target, eye)
            assert cos > math.cos(IN_VIEW), name  # near the middle of its view
            assert low[0] < target[0] < high[0] and low[1] < target[1] < high[1], name
        start = _position(client, mug)
        with simulated_robot(world, scene.robot):
            perform(an.action(type="transporting", object="mug", target=spots["mug-1"]))
        x, y, z = _position(client, mug)
        assert math.hypot(x - spot[0], y - spot[1]) < PLACED and math.dist(start, spot) > 0.1
        assert z == pytest.approx(start[2], abs=SETTLED)
        for other in (plate, mug):  # nothing of the robot touches the plate or the mug
            assert not pybullet.getContactPoints(body, other, physicsClientId=client)
        assert not pybullet.getClosestPoints(plate, body, 0.0, physicsClientId=client)
        bowl = world.object("bowl-1").body_id  # its Robotiq's pads end 18 mm behind its
        start, spot = _position(client, bowl), spots["bowl-1"].position
        with simulated_robot(world, scene.robot):  # tool frame: a deep rim grasp holds it
            perform(an.action(type="transporting", object="bowl", target=spots["bowl-1"]))
        x, y, z = _position(client, bowl)
        assert math.hypot(x - spot[0], y - spot[1]) < PLACED and math.dist(start, spot) > 0.1
        assert z == pytest.approx(start[2], abs=SETTLED)
        assert not pybullet.getContactPoints(body, bowl, physicsClientId=client)
    finally:
        world.close()


def _position(client: int, body: int) -> tuple[float, float, float]:
    position, _ = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)
    return (float(position[0]), float(position[1]), float(position[2]))
