"""Issue 37: IAI's Kevin, a SCARA arm (a column that lifts, three joints turning about the
vertical) on a mobile base, its camera fixed on a mast, drafted with no edit.

Its hand hangs 7 cm below the wrist, so the wrist-to-tool line is 23 degrees off the
fingers: the draft keeps the URDF's tool link (x along the fingers), the grasp model takes
the tool's x as the approach, ``robot check`` reaches with the tool level (it can never
point down), looking checks the fixed camera's view, and the tabletop pick-up lifts the
mug from the side. Judged with raw PyBullet: the mug rose, only the mug touches the hand.
Its fingers stop 59 mm apart closed: it opens 124 mm (the gap between the open fingers),
not the 65 mm they move apart, so the kitchen's mug fits its hand from the side, and the
stand's check opens the gripper at the pre-grasp, as the pick does (closed, the fingers
reach 11 cm past the tool frame, into the mug).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.designators import a, an
from robocram.plans import perform, pick_up
from robocram.projection import simulated_robot
from robocram.robot_check import check_robot, description_from
from robocram.robots import load_description
from robocram.scenes import kitchen_scene, tabletop_scene
from tests.bullet_links import link_indices
from tests.drafts import drafted_module

URDF = Path(__file__).resolve().parents[1] / "data" / "zoo" / "kevin" / "kevin.urdf"
LIFTED = 0.05  # [m] the mug rises at least this much
TOUCH = 0.002  # [m] nearer than this counts as touching

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")


@pytest.fixture(scope="module")
def module(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("kevin") / "kevin.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(URDF, path)
    return path


def test_the_draft_keeps_the_urdf_tool_link_along_the_fingers(module: Path) -> None:
    loaded = load_description(description_from(str(module)))
    (arm,) = loaded.arms.values()
    assert arm.tool_frame == "robot_arm_tool_link"  # the URDF's, nothing turned or added
    assert "arm_standard_tool_frame" not in module.read_text(encoding="utf-8")


def test_the_check_passes_reaching_with_the_tool_level(module: Path) -> None:
    card = check_robot(description_from(str(module)))
    assert card.passed, card.failures()
    reach = next(r for r in card.results if r.name.endswith("arm: reach"))
    assert reach.detail.endswith(", level")
    grip = next(r for r in card.results if r.name.endswith("arm: grip"))
    assert "closed on" in grip.detail


def test_the_tabletop_pick_up_lifts_the_mug_from_the_side(module: Path) -> None:
    """The mug rose 5 cm; the hand touches nothing but the mug; its approach (the tool's x,
    read from PyBullet's link state) is level."""
    scene = tabletop_scene(str(module))
    world = scene.world
    try:
        client = world.physics.client()
        mug = world.object("mug-1").body_id
        robot = world.object(scene.robot).body_id
        before = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)[0][2]
        with simulated_robot(world, scene.robot):
            held = pick_up(scene.look_target)
        after = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)[0][2]
        arm = world.robot(scene.robot).description.arms[held.arm]
        links = link_indices(robot, client)
        hand = [links[name] for name in arm.hand_links if name in links]
        others = [o.body_id for o in world.objects() if o.body_id not in (mug, robot)]
        touched = [
            (index, other)
            for index in hand
            for other in others
            if pybullet.getClosestPoints(
                robot, other, TOUCH, linkIndexA=index, physicsClientId=client
            )
        ]
        on_mug = [
            index
            for index in hand
            if pybullet.getClosestPoints(
                robot, mug, TOUCH, linkIndexA=index, physicsClientId=client
            )
        ]
        orientation = pybullet.getLinkState(
            robot, links[arm.tool_frame], computeForwardKinematics=True, physicsClientId=client
        )[5]
        approach = np.asarray(pybullet.getMatrixFromQuaternion(orientation)).reshape(3, 3)[:, 0]
    finally:
        world.close()
    assert after - before >= LIFTED
    assert on_mug and not touched
    assert abs(float(approach[2])) < np.sin(np.radians(5.0))  # level: a side grasp


def _finger_gap(value: float) -> float:
    """The gap [m] between Kevin's finger boxes with its gripper joint (and the mimic) at
    ``value``, by PyBullet's closest points on the URDF alone."""
    client = pybullet.connect(pybullet.DIRECT)
    try:
        body = pybullet.loadURDF(str(URDF), useFixedBase=True, physicsClientId=client)
        links = link_indices(body, client)
        count = pybullet.getNumJoints(body, physicsClientId=client)
        joints = {
            pybullet.getJointInfo(body, i, physicsClientId=client)[1].decode(): i
            for i in range(count)
        }
        for joint in ("robot_arm_gripper_joint", "robot_arm_gripper_mirror_joint"):
            pybullet.resetJointState(body, joints[joint], value, physicsClientId=client)
        left, right = links["robot_arm_left_finger_link"], links["robot_arm_right_finger_link"]
        points = pybullet.getClosestPoints(
            body, body, 1.0, linkIndexA=left, linkIndexB=right, physicsClientId=client
        )
        return min(p[8] for p in points)
    finally:
        pybullet.disconnect(client)


def test_its_opening_is_the_gap_between_its_open_fingers(module: Path) -> None:
    """124 mm between the open fingers' boxes (PyBullet), within 1 mm; closed, 59 mm."""
    (arm,) = load_description(description_from(str(module))).arms.values()
    assert arm.gripper is not None and arm.gripper.max_opening is not None
    assert arm.gripper.max_opening == pytest.approx(_finger_gap(0.0675), abs=1e-3)
    assert _finger_gap(0.035) == pytest.approx(0.059, abs=1e-3)  # stopped apart, closed


def test_it_brings_the_kitchen_mug_to_the_table(module: Path) -> None:
    """The mug, taken from the counter from the side, ends on the table's top (PyBullet)."""
    scene = kitchen_scene(str(module))
    world = scene.world
    try:
        with simulated_robot(world, scene.robot):
            target = a.location(on=("kitchen", "table_top"), for_="mug-1")
            perform(an.action(type="transporting", object="mug", target=target))
        client = world.physics.client()
        kitchen = world.object("kitchen").body_id
        table = link_indices(kitchen, client)["table_top"]
        low, high = pybullet.getAABB(kitchen, table, physicsClientId=client)
        mug_low, mug_high = pybullet.getAABB(world.object("mug-1").body_id, physicsClientId=client)
    finally:
        world.close()
    middle = [(mug_low[k] + mug_high[k]) / 2 for k in range(2)]
    assert low[0] <= middle[0] <= high[0] and low[1] <= middle[1] <= high[1]
    assert mug_low[2] == pytest.approx(high[2], abs=0.01)  # standing on it
