"""A drafted trunk whose joint cannot start at 0 stands as its URDF draws it at zero.

Rollin' Justin's ``torso3_joint`` starts at its lower limit, 0.1745 rad; the draft turns
``torso2_joint`` back by as much (its ``stance``), so its upper trunk stands upright, and
with it Justin picks the tabletop mug (it did not: its hands met the parked other one or
missed the handle). Judged on the world's link poses and contacts, not on the draft.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import pytest

from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.robots import draft_description
from robocram.robots.draft.trunk_stance import upright_trunk
from robocram.robots.robot_model import RobotModel
from robocram.scenes import tabletop_scene
from robocram.tf import quaternion as quat
from robocram.world import World

JUSTIN = (
    Path(__file__).resolve().parents[1] / "data" / "zoo" / "rollin_justin" / "rollin_justin.urdf"
)
TORSO3_LOWER = 0.174533  # [rad] torso3_joint's lower limit in the URDF
TORSO2_ORIGIN_RPY = (-1.57079, -1.57079, 0.0)  # torso2_joint's origin; torso1 at 0 turns none


@pytest.fixture(scope="module")
def justin(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Rollin' Justin drafted into a module, once for the file's tests."""
    module = tmp_path_factory.mktemp("justin_trunk") / "rollin_justin.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        module.write_text(draft_description(JUSTIN).source(module), "utf-8")
    return module


def test_justins_upper_trunk_stands_upright_and_clear(justin: Path) -> None:
    world = World()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            robot = world.add_robot(str(justin)).name
        joints = world.joint_states(robot)
        assert joints["torso3_joint"] == pytest.approx(TORSO3_LOWER, abs=1e-5)
        assert joints["torso2_joint"] == pytest.approx(-TORSO3_LOWER, abs=1e-5)
        # upright: torso4 (the arms' base) turned only by torso2_joint's origin, as at zero,
        # and straight above torso3 (0.3 m), not 10 degrees forward of it
        top = world.link_pose(robot, "torso4")
        assert quat.angle_between(top.orientation, quat.from_euler(*TORSO2_ORIGIN_RPY)) < 1e-3
        below = world.link_pose(robot, "torso3").position
        assert math.dist(top.position[:2], below[:2]) < 1e-3
        assert top.position[2] - below[2] == pytest.approx(0.3, abs=1e-3)
        # the trunk, so turned, touches none of the robot's other links but its neighbours
        # (torso1 has no length: torso2 turns where it sits on base_link, and touches it)
        links = ["base_link", "torso1", "torso2", "torso3", "torso4"]
        trunk_pairs = [(a, b) for i, a in enumerate(links) for b in links[i + 2 :]]
        trunk_pairs.remove(("base_link", "torso2"))
        arm_links = ["left_arm1", "left_arm2", "right_arm1", "right_arm2", "head2"]
        pairs = trunk_pairs + [(a, b) for a in links[:-1] for b in arm_links]
        assert world.contacts.self_contacts(robot, pairs) == []
    finally:
        world.close()


def test_justin_picks_the_tabletop_mug(justin: Path) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = tabletop_scene(str(justin))
    world = scene.world
    try:
        before = world.pose("mug-1").position[2]
        with simulated_robot(world, scene.robot):
            pick_up(scene.look_target)
        assert world.pose("mug-1").position[2] > before + 0.05  # lifted, off the table
        table_top = world.aabb("table")[1][2]
        assert world.contacts.contact_points("mug-1", "table") == []
        assert world.aabb("mug-1")[0][2] > table_top + 0.05
    finally:
        world.close()


def _two_pitch_joints(first: str, second: tuple[float, float], axis: str = "0 1 0") -> RobotModel:
    """A base, two revolute joints one above the other (the second's limits given) and a top."""
    link = '<link name="{0}"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>'  # noqa: E501
    joint = (
        '<joint name="{0}" type="revolute"><parent link="{1}"/><child link="{2}"/>'
        '<origin xyz="0 0 0.3"/><axis xyz="{3}"/>'
        '<limit lower="{4}" upper="{5}" effort="1" velocity="1"/></joint>'
    )
    xml = (
        '<robot name="trunk">'
        + "".join(link.format(n) for n in ("base", "mid", "top"))
        + joint.format("j1", "base", "mid", first, -1.0, 1.0)
        + joint.format("j2", "mid", "top", axis, *second)
        + "</robot>"
    )
    return RobotModel.from_string(xml)


def test_a_joint_starting_off_zero_is_made_up_for_by_a_parallel_one_else_left() -> None:
    stance = upright_trunk(_two_pitch_joints("0 1 0", (0.2, 1.0)), ["j1", "j2"])
    assert stance is not None and stance.values == {"j1": -0.2}
    flipped = upright_trunk(_two_pitch_joints("0 -1 0", (0.2, 1.0)), ["j1", "j2"])
    assert flipped is not None and flipped.values == {"j1": 0.2}
    assert upright_trunk(_two_pitch_joints("0 1 0", (-1.0, 1.0)), ["j1", "j2"]) is None
    assert upright_trunk(_two_pitch_joints("0 0 1", (0.2, 1.0)), ["j1", "j2"]) is None
    assert upright_trunk(_two_pitch_joints("0 1 0", (1.2, 1.5)), ["j1", "j2"]) is None
