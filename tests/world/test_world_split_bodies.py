"""A fixed model with more links than one PyBullet body holds loads as several bodies
(issue 37, item 1), cut at subtrees hung on fixed joints from its root, and answers by the
same link and joint names as one body would.

The big kitchen (``tools/make_kitchen_urdf.py --big``: robocram's kitchen with a west run
of five drawer units and five wall cupboards, 140 links) is the example; what the world
says is judged against forward kinematics of the URDF and against PyBullet's own bodies.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pybullet
import pytest

from robocram.robots import RobotModel, link_pose
from robocram.tf import Pose
from robocram.world import World
from robocram.world.robot_urdf import MAX_LINKS

BIG = Path(__file__).resolve().parents[1] / "data" / "big_kitchen" / "big_kitchen.urdf"
AT = Pose((0.3, -0.2, 0.0), (0.0, 0.0, 0.2588190451, 0.9659258263))  # 30 degrees about z
DRAWER = "west_drawers_1_drawer_4"  # in a part of its own (its unit is cut off)


@pytest.fixture(scope="module")
def model() -> RobotModel:
    return RobotModel.from_file(BIG)


@pytest.fixture
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        w.add_urdf("kitchen", BIG, pose=AT)
        yield w


def test_the_big_kitchen_loads_as_several_bodies_under_one_name(
    world: World, model: RobotModel
) -> None:
    kitchen = world.object("kitchen")
    assert len(model.joints) > MAX_LINKS
    assert len(kitchen.bodies) >= 2
    assert pybullet.getNumBodies(physicsClientId=world.physics.client()) == 1 + len(kitchen.bodies)
    assert all(
        pybullet.getNumJoints(b, physicsClientId=world.physics.client()) <= MAX_LINKS
        for b in kitchen.bodies
    )
    assert set(world.link_names(kitchen)) == set(model.links)
    assert set(world.joint_states(kitchen)) == {j.name for j in model.movable_joints()}


def test_links_lie_where_forward_kinematics_puts_them(world: World, model: RobotModel) -> None:
    values = {f"{DRAWER}_joint": 0.3, "drawer_unit_drawer_1_joint": 0.2,
              "west_cupboard_2_door_joint": 1.0}  # fmt: skip
    world.set_joint_states("kitchen", values)
    for link in model.links:
        expected = AT * link_pose(model, link, values)
        assert world.link_pose("kitchen", link).distance_to(expected) < 1e-5, link
        assert world.link_pose("kitchen", link).angle_to(expected) < 1e-5, link
    assert world.joint_states("kitchen")[f"{DRAWER}_joint"] == pytest.approx(0.3, abs=1e-9)


def test_contacts_rays_and_states_name_the_links_of_every_part(world: World) -> None:
    world.set_joint_states("kitchen", {f"{DRAWER}_joint": 0.4})
    inside = world.link_pose("kitchen", DRAWER) * Pose((-0.26, 0.0, 0.1))
    world.add_item("bowl", "bowl", inside)
    world.physics.simulate(1.0)
    assert {p.link_b for p in world.contacts.contact_points("bowl", "kitchen")} == {DRAWER}
    x, y, _ = world.pose("bowl").position
    hit = world.view.ray_cast((x, y, 1.2), (x, y, 0.0))
    assert hit is not None and hit.obj.name == "bowl"
    floor = world.link_pose("kitchen", DRAWER) * Pose((-0.05, 0.15, 0.0))
    fx, fy, _ = floor.position
    hit = world.view.ray_cast((fx, fy, 1.2), (fx, fy, 0.0))
    assert hit is not None and (hit.obj.name, hit.link) == ("kitchen", DRAWER)
    before = world.joint_states("kitchen")
    with world.snapshots.stored_state():
        world.set_joint_states("kitchen", {f"{DRAWER}_joint": 0.0})
    assert world.joint_states("kitchen") == before
    copy = world.copy()
    try:
        for link in (DRAWER, "table_top", "kitchen_root"):
            mine, theirs = world.link_pose("kitchen", link), copy.link_pose("kitchen", link)
            assert mine.distance_to(theirs) < 1e-9, link
    finally:
        copy.close()
