"""Issue 37: IAI's Kevin, a SCARA arm (a column that lifts, three joints turning about the
vertical) on a mobile base, its camera fixed on a mast, drafted with no edit.

Its hand hangs 7 cm below the wrist, so the wrist-to-tool line is 23 degrees off the
fingers: the draft keeps the URDF's tool link (x along the fingers), the grasp model takes
the tool's x as the approach, ``robot check`` reaches with the tool level (it can never
point down), looking checks the fixed camera's view, and the tabletop pick-up lifts the
mug from the side. Judged with raw PyBullet: the mug rose, only the mug touches the hand.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.robot_check import check_robot, description_from
from robocram.robots import draft_description, load_description
from robocram.scenes import tabletop_scene

URDF = Path(__file__).resolve().parents[1] / "data" / "zoo" / "kevin" / "kevin.urdf"
LIFTED = 0.05  # [m] the mug rises at least this much
TOUCH = 0.002  # [m] nearer than this counts as touching

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")


@pytest.fixture(scope="module")
def module(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("kevin") / "kevin.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        path.write_text(draft_description(URDF).source(path), encoding="utf-8")
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


def _links(body: int, client: int) -> dict[str, int]:
    count = pybullet.getNumJoints(body, physicsClientId=client)
    return {
        pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode(): i for i in range(count)
    }


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
        links = _links(robot, client)
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
