"""Bad input to the world ends in a typed error and an unchanged world (issue 11).

Before: a 129-link robot failed with a raw ``pybullet.error`` and left a half-made body
(now it loads with its fixed links folded into their parents, kept as frames);
a broken URDF gave ``pybullet.error``; a restore kept a box named ``mug``; a robot added
inside ``stored_state`` left its facts; A on B on A recursed without end; a zero time step
divided by zero and a negative one simulated nothing; copying a closed world crashed.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from pathlib import Path

import pybullet
import pytest

from robocram.kinematics import forward_kinematics
from robocram.robots import RobotDescription
from robocram.robots.example_robot_data import example_robot_data_folder
from robocram.tf import Pose
from robocram.world import (
    AttachmentCycleError,
    BodyLoadError,
    TooManyLinksError,
    World,
    WorldClosedError,
    WorldValueError,
)


@pytest.fixture
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        w.add_item("mug", "mug", Pose((1, -0.2, 0.7)))
        yield w


def _bodies(world: World) -> int:
    return int(pybullet.getNumBodies(physicsClientId=world.physics.client()))


def _tiago_dual() -> Path:
    return next(example_robot_data_folder().rglob("tiago_dual.urdf"))


def test_a_free_body_with_too_many_links_is_refused_and_leaves_nothing(world: World) -> None:
    with pytest.raises(TooManyLinksError, match=r"129 links .* at most 127") as info:
        world.add_urdf("tiago", _tiago_dual(), fixed_base=False)  # a fixed base is cut
    assert info.value.source.endswith("tiago_dual.urdf")
    assert [o.name for o in world.objects()] == ["floor", "mug"] and _bodies(world) == 2


def test_a_robot_with_too_many_links_loads_with_its_fixed_links_folded(world: World) -> None:
    desc = RobotDescription("tiago_dual", _tiago_dual(), base_frame="base_footprint")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # its missing meshes
        robot = world.add_robot(desc)
    model = robot.description.model
    assert len(model.joints) == 129  # one more than PyBullet holds
    assert set(world.joint_states(robot)) == {j.name for j in model.movable_joints()}
    assert set(world.link_names(robot)) == set(model.links)  # folded links stay as frames
    world.set_joint_states(robot, {"arm_left_2_joint": 0.7, "torso_lift_joint": 0.2})
    joints = world.joint_states(robot)
    for link in model.links:
        expected = forward_kinematics(robot.description, joints, link)
        assert world.link_pose(robot, link).distance_to(expected) < 1e-6, link
        assert world.link_pose(robot, link).angle_to(expected) < 1e-5, link
    copy = world.copy()  # the folded frames travel with the body's spec
    frame = next(iter(robot.link_offset))
    assert copy.link_pose("tiago_dual", frame).distance_to(world.link_pose(robot, frame)) < 1e-9
    copy.close()


def test_a_robot_too_big_even_folded_is_refused_before_loading(
    world: World, tmp_path: Path
) -> None:
    links = "".join(f'<link name="l{i}"/>' for i in range(131))
    joints = "".join(
        f'<joint name="j{i}" type="revolute"><parent link="l{i}"/><child link="l{i + 1}"/>'
        '<limit lower="-1" upper="1" velocity="1" effort="1"/></joint>'
        for i in range(130)
    )
    urdf = tmp_path / "snake.urdf"
    urdf.write_text(f'<robot name="snake">{links}{joints}</robot>', encoding="utf-8")
    with pytest.raises(TooManyLinksError, match=r"130 links .* at most 127"):
        world.add_robot(RobotDescription("snake", urdf, base_frame="l0"))
    assert "snake" not in world and _bodies(world) == 2


def test_a_failed_load_names_the_file_and_leaves_the_world(world: World, tmp_path: Path) -> None:
    broken = tmp_path / "broken.urdf"
    broken.write_text("<robot name='r'><link name='a'>", encoding="utf-8")
    with pytest.raises(BodyLoadError, match=r"cannot add 'thing' from .*broken\.urdf"):
        world.add_urdf("thing", broken)
    with pytest.raises(BodyLoadError, match="does not exist"):
        world.add_urdf("thing", tmp_path / "nowhere.urdf")
    assert "thing" not in world and _bodies(world) == 2
    world.add_box("thing", (0.1, 0.1, 0.1))  # the name is still free


def test_restore_brings_back_the_object_not_a_namesake(world: World) -> None:
    mug = world.object("mug")
    with world.snapshots.stored_state():
        world.remove("mug")
        world.add_box("mug", (0.1, 0.1, 0.1), Pose((0, 0, 2)))
    assert world.object("mug") is mug and world.object("mug").type == "mug"
    assert world.pose("mug").position == pytest.approx((1, -0.2, 0.7), abs=1e-9)
    assert _bodies(world) == 2


def test_restore_takes_the_facts_of_a_robot_added_inside(world: World) -> None:
    with world.snapshots.stored_state():
        world.add_robot("hsrb")
        assert world.kb.first("robot(R)") == {"R": "hsrb"}
    assert "hsrb" not in world
    assert world.kb.first("robot(R)") is None


def test_a_robot_removed_inside_comes_back_with_its_facts() -> None:
    with World() as world:
        world.add_robot("hsrb")
        assert world.kb.first("robot(R)") == {"R": "hsrb"}
        with world.snapshots.stored_state():
            world.remove("hsrb")
            assert world.kb.first("robot(R)") is None
        assert world.kb.first("robot(R)") == {"R": "hsrb"}


def test_an_attachment_cycle_is_refused(world: World) -> None:
    world.add_box("tray", (0.3, 0.3, 0.02), Pose((1, 0, 0.7)))
    world.add_box("lid", (0.1, 0.1, 0.01), Pose((1, 0, 0.8)))
    root = {name: world.link_names(name)[0] for name in ("tray", "mug", "lid")}
    world.attach("mug", "tray", root["tray"])
    world.attach("lid", "mug", root["mug"])
    with pytest.raises(
        AttachmentCycleError, match="so 'tray' hangs from 'lid' hangs from 'mug' hangs from 'tray'"
    ):
        world.attach("tray", "lid", root["lid"])
    with pytest.raises(AttachmentCycleError):
        world.attach("tray", "mug", root["mug"])
    world.set_pose("tray", Pose((2, 0, 0.7)))  # no RecursionError: the chain is intact
    assert world.pose("lid").position == pytest.approx((2, 0, 0.8), abs=1e-6)


@pytest.mark.parametrize("step", [0.0, -0.01, float("nan"), float("inf")])
def test_a_time_step_must_be_positive_and_finite(step: float) -> None:
    with pytest.raises(WorldValueError, match="time_step must be a finite number"):
        World(time_step=step)


def test_copying_a_closed_world_says_it_is_closed(world: World) -> None:
    world.close()
    with pytest.raises(WorldClosedError):
        world.copy()
    with pytest.raises(WorldClosedError):
        world.view.ray_cast((0, 0, 1), (0, 0, -1))


def test_every_query_on_a_closed_world_says_it_is_closed(world: World) -> None:
    world.close()
    queries = [
        lambda: world.aabb("mug"),
        lambda: world.contacts.link_aabb("mug", world.link_names("mug")[0]),
        lambda: world.contacts.contact_points("mug"),
        lambda: world.contacts.collisions("mug"),
        lambda: world.view.visible_from(Pose((0, 0, 2)), "mug"),
        lambda: world.physics.stable(),
        lambda: world.pose("mug"),
    ]
    for query in queries:
        with pytest.raises(WorldClosedError):
            query()
