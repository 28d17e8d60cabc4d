"""A hand narrower than the mug takes it by its handle, from above, and carries it so.

The Panda's hand opens 80 mm, the mug's body is 88 mm: the tabletop pick-up takes the
handle from above, the fingers on both sides of its bar. A PR2 allowed only the handle
(``object_grasps(mug, [handle])``) carries the mug so from the counter to the table. Both
are checked with raw PyBullet, not with the planner's own account. In the kitchen the
Panda's wrist camera, parked under the counter's top, rises over it to find the mug.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import pybullet
import pytest

from robocram.designators import a
from robocram.plans import perform, pick_up
from robocram.plans.deliver import deliver
from robocram.plans.fetch import fetch
from robocram.plans.pick_object import Held
from robocram.plans.search import search
from robocram.projection import simulated_robot
from robocram.robot_check import description_from
from robocram.scenes import kitchen_scene, tabletop_scene
from robocram.tf import Pose, PoseStamped
from tests.bullet_links import link_indices

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")
PANDA = Path(__file__).resolve().parents[2] / "examples" / "robots" / "panda.py"
PANDA_HAND = ("panda_hand", "panda_leftfinger", "panda_rightfinger")
BODY_RADIUS = 0.044  # [m] the mug's body, its collision margin included; the handle beyond


def _in_frame(client: int, body: int, point: tuple[float, ...]) -> tuple[float, ...]:
    """``point`` (map) in ``body``'s base frame."""
    position, orientation = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)
    inverse = pybullet.invertTransform(position, orientation)
    return tuple(pybullet.multiplyTransforms(*inverse, point, (0, 0, 0, 1))[0])


def test_the_panda_lifts_the_mug_by_its_handle_from_above() -> None:
    """The mug rose at least 5 cm, each finger touches the handle's bar on its own side
    (the bar's mid-plane is the mug's x = 0), and the hand touches nothing but the mug,
    no more than the 5 mm bound in."""
    scene = tabletop_scene(str(PANDA))
    world = scene.world
    try:
        # the handle to the left, unturned: the scene turns it to face a handle-only arm's
        # shoulder (``scenes/handle_turn.py``), where the Panda takes it from the side
        world.set_pose("mug-1", Pose(world.pose("mug-1").position))
        client = world.physics.client()
        mug = world.object("mug-1").body_id
        robot = world.object(scene.robot).body_id
        before = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)[0][2]
        with simulated_robot(world, scene.robot):
            result = pick_up(scene.look_target)
        after = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)[0][2]
        links = link_indices(robot, client)
        sides = {}
        for finger in PANDA_HAND[1:]:
            near = pybullet.getClosestPoints(
                robot, mug, 0.002, linkIndexA=links[finger], physicsClientId=client
            )
            assert near, f"{finger} does not touch the mug"
            on_mug = [_in_frame(client, mug, p[6]) for p in near]
            assert all(math.hypot(x, y) > BODY_RADIUS for x, y, _ in on_mug)  # the handle
            sides[finger] = {math.copysign(1.0, x) for x, _, _ in on_mug}
        others = [o.body_id for o in world.objects() if o.body_id not in (mug, robot)]
        touched = [
            (name, other)
            for name in PANDA_HAND
            for other in others
            if pybullet.getClosestPoints(
                robot, other, 0.0, linkIndexA=links[name], physicsClientId=client
            )
        ]
        gaps = [p[8] for p in pybullet.getClosestPoints(robot, mug, 0.01, physicsClientId=client)]
    finally:
        world.close()
    assert result.held.grasp == "handle" and _approach_down(result.held)
    assert after - before >= 0.05
    assert sides["panda_leftfinger"] | sides["panda_rightfinger"] == {-1.0, 1.0}
    assert len(sides["panda_leftfinger"]) == len(sides["panda_rightfinger"]) == 1
    assert not touched
    assert min(gaps) >= -0.005


def _approach_down(held: Held) -> bool:
    """Whether the tool's approach axis (x) pointed down at the grasp."""
    return pybullet.getMatrixFromQuaternion(held.grasp_pose.orientation)[6] < -0.99


def _mug_in_tool(client: int, robot: int, tool: int, mug: int) -> tuple[tuple[float, ...], ...]:
    """The mug's pose in the tool link's frame, read from PyBullet."""
    state = pybullet.getLinkState(robot, tool, computeForwardKinematics=1, physicsClientId=client)
    inverse = pybullet.invertTransform(state[4], state[5])
    at, turned = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)
    position, orientation = pybullet.multiplyTransforms(*inverse, at, turned)
    return tuple(position), tuple(orientation)


def _turned(a_quat: tuple[float, ...], b_quat: tuple[float, ...]) -> float:
    """[rad] between two orientations."""
    dot = abs(sum(x * y for x, y in zip(a_quat, b_quat, strict=True)))
    return 2.0 * math.acos(min(1.0, dot))


def test_a_mug_held_by_its_handle_keeps_its_pose_in_the_hand_and_is_put_down() -> None:
    """The mug's pose in the tool frame is the same after a drive across the kitchen as
    when lifted (1 mm, 0.01 rad), and it stands upright on the table afterwards."""
    scene = kitchen_scene("pr2")
    world = scene.world
    world.kb.consult("object_grasps(mug, [handle]).", group="handle_only")
    try:
        client = world.physics.client()
        mug = world.object("mug-1").body_id
        robot = world.object(scene.robot).body_id
        start = world.pose(world.robot(scene.robot))
        with simulated_robot(world, scene.robot):
            held = fetch(search("mug"))
            tool = link_indices(robot, client)[held.tool_frame]
            lifted = _mug_in_tool(client, robot, tool, mug)
            back = PoseStamped("map", start.position, start.orientation)
            perform(a.motion(type="going", target=a.location(pose=back)))
            driven = _mug_in_tool(client, robot, tool, mug)
            deliver(held, a.location(on=("kitchen", "table_top"), for_="mug-1"))
        upright = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)[1]
        low, high = pybullet.getAABB(mug, physicsClientId=client)
        kitchen = world.object("kitchen").body_id
        table_index = link_indices(kitchen, client)["table_top"]
        table_low, table_high = pybullet.getAABB(kitchen, table_index, physicsClientId=client)
    finally:
        world.close()
    assert held.grasp == "handle" and _approach_down(held)
    assert math.dist(lifted[0], driven[0]) < 0.001
    assert _turned(lifted[1], driven[1]) < 0.01
    axis_z = pybullet.getMatrixFromQuaternion(upright)[8]  # the mug's z axis, up
    assert axis_z > math.cos(0.05)
    assert low[2] == pytest.approx(table_high[2], abs=0.01)  # standing on the table's top
    middle = ((low[0] + high[0]) / 2, (low[1] + high[1]) / 2)
    assert all(table_low[i] < middle[i] < table_high[i] for i in (0, 1))


def test_the_pandas_wrist_camera_rises_over_the_counter_to_find_the_mug() -> None:
    """Parked, the Panda's wrist camera is under the kitchen counter's top (0.85 m): from
    there the counter hides the place it looks at. It looks from its maximal height
    instead and finds the mug; the camera link's height is PyBullet's own. Its draft is a
    fixed arm (zoo13): here it rides on a mobile base, as its draft's doubt offers."""
    mobile = dataclasses.replace(description_from(str(PANDA)), base_type="holonomic")
    scene = kitchen_scene(mobile)
    world = scene.world
    try:
        client = world.physics.client()
        robot = world.object(scene.robot).body_id
        camera = link_indices(robot, client)["panda_link7"]
        with simulated_robot(world, scene.robot):
            seen = search("mug")
        state = pybullet.getLinkState(robot, camera, computeForwardKinematics=1,
                                      physicsClientId=client)  # fmt: skip
        counter = world.link_pose("kitchen", "counter_top_north").position[2]
    finally:
        world.close()
    assert seen.get("name") == "mug-1"
    assert state[4][2] > counter + 0.1
