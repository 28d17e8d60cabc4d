"""Looking without a pan-tilt head: a wrist camera's arm moves, a pan-only head pans.

The Panda carries its camera on the wrist and has no neck; Baxter's head only pans. After
each look, PyBullet's own link state of the camera frame (``getLinkState``, not the
world's bookkeeping) judges whether the target projects inside the camera's image.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import PtuGoalNotReached
from robocram.projection import simulated_robot
from robocram.projection.look_by_arm import _sight_blocked
from robocram.projection.neck import look_at
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robot_check import description_from
from robocram.robots import CameraDescription, RobotDescription, load_description
from robocram.robots.looking_means import looking_means, with_looking
from robocram.tf import Pose
from robocram.world import World
from tests.bullet_links import link_frame

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "robots"


def _example(name: str) -> RobotDescription:
    """An example's description; Baxter's with its head's camera, which only pans (its
    draft takes its wrist camera since zoo33: the head's cannot see its arms' reach)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        desc = description_from(str(EXAMPLES / f"{name}.py"))
    if name != "baxter":
        return desc
    head = CameraDescription(
        "head_camera_link", horizontal_fov=math.radians(60), vertical_fov=math.radians(45)
    )
    return dataclasses.replace(desc, cameras=(head,))


def _world(name: str) -> World:
    desc = _example(name)
    world = World()
    world.bodies.add_floor()
    world.add_robot(desc)
    return world


@pytest.fixture(scope="module")
def panda() -> Iterator[World]:
    world = _world("panda")
    yield world
    world.close()


@pytest.fixture(scope="module")
def baxter() -> Iterator[World]:
    world = _world("baxter")
    yield world
    world.close()


def _image_angles(world: World, robot: str, target: tuple[float, float, float]) -> tuple:
    """[rad] the target's angles right of and below the optical axis, and its depth [m],
    from PyBullet's link state of the camera frame."""
    position, rotation = link_frame(
        world.object(robot).body_id,
        world.physics.client(),
        world.robot(robot).description.cameras[0].frame,
    )
    x, y, z = rotation.T @ (np.asarray(target) - position)
    return math.atan2(x, z), math.atan2(y, z), z


def test_the_means_follow_the_joints_that_turn_the_camera() -> None:
    kinds = {}
    for name in ("pr2", "boxy", "panda", "baxter"):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            spec = description_from(name) if name in ("pr2", "boxy") else _example(name)
            desc = load_description(spec)
        means = looking_means(desc)
        assert means is not None
        kinds[name] = (means.kind, means.arm, means.joint)
        resources = desc.resources()
        if means.kind in ("pan_tilt", "neck_arm"):
            assert with_looking(desc, resources) == resources  # built-ins: as before
        else:
            assert "ptu" not in resources and "ptu" in with_looking(desc, resources)
    assert kinds == {
        "pr2": ("pan_tilt", None, None),
        "boxy": ("neck_arm", None, None),
        "panda": ("arm", "arm", None),
        "baxter": ("pan", None, "head_pan"),
    }


@pytest.mark.parametrize("target", [(0.55, 0.0, 0.1), (0.3, -0.45, 0.25)])
def test_a_wrist_camera_looks_by_moving_its_arm(
    panda: World, target: tuple[float, float, float]
) -> None:
    robot = ProjectedRobot.of(panda, "panda")
    before = panda.joint_states("panda")
    with simulated_robot(panda, "panda"):
        perform(a.motion(type="looking", target=a.location(pose=Pose(target))))
    moved = panda.joint_states("panda")
    assert any(abs(moved[j] - before[j]) > 1e-3 for j in robot.arm("arm").joints)
    right, down, depth = _image_angles(panda, "panda", target)
    assert depth > 0.05
    assert math.hypot(right, down) < 0.02  # [rad] on the optical axis (IK's tolerance)


def test_a_five_joint_arm_aims_its_wrist_camera_joint_by_joint() -> None:
    """The SO-101's five joints cannot hold a whole camera pose; its joints are aimed."""
    world = _world("so101")
    try:
        name = world.robots()[0].name
        camera = world.robot(name).description.cameras[0].frame
        eye = world.link_pose(name, camera)
        target = eye.transform_point((0.3, 0.0, 0.8))  # ahead of the camera, to its right
        with simulated_robot(world, name):
            perform(a.motion(type="looking", target=a.location(pose=Pose(target))))
        right, down, depth = _image_angles(world, name, target)
        assert depth > 0.5 and math.hypot(right, down) < math.radians(1.0)
    finally:
        world.close()


def test_a_pan_only_head_pans_onto_a_target_in_its_view(baxter: World) -> None:
    robot = ProjectedRobot.of(baxter, "baxter")
    x, y, z = baxter.link_pose("baxter", robot.description.cameras[0].frame).position
    target = (x + 2.0, y + 1.2, z - 0.35)  # ahead, to the left, a little below the camera
    set_to = look_at(robot, target)
    assert set(set_to) == {"head_pan"} and set_to["head_pan"] > 0.2
    right, down, depth = _image_angles(baxter, "baxter", target)
    camera = robot.description.cameras[0]
    assert depth > 1.0
    assert abs(right) < 0.01  # the pan put it in the middle of the image, left to right
    assert abs(down) < camera.vertical_fov / 2  # and the fixed tilt leaves it in view


def test_a_pan_only_head_says_where_a_target_it_cannot_tilt_to_lies(baxter: World) -> None:
    robot = ProjectedRobot.of(baxter, "baxter")
    target = (0.7, -0.3, 0.0)  # on the floor just in front: far below a level camera
    with pytest.raises(PtuGoalNotReached, match=r"only pans \(head_pan\).*below it"):
        look_at(robot, target)
    right, down, _ = _image_angles(baxter, "baxter", target)
    assert abs(right) < 0.01  # it panned towards it all the same
    assert abs(down) > robot.description.cameras[0].vertical_fov / 2


def test_a_view_through_the_robots_own_hand_counts_as_hidden(panda: World) -> None:
    """The Panda's wrist camera looks across its hand's axis: a target beyond the hand is
    hidden by it, one ahead along the optical axis is not (rays cast in PyBullet)."""
    robot = ProjectedRobot.of(panda, "panda")
    before = panda.joint_states("panda")
    joints = {j: v for j, v in before.items() if j in robot.arm("arm").joints}
    camera = panda.link_pose("panda", robot.description.cameras[0].frame)
    hand = np.asarray(panda.link_pose("panda", "panda_hand").position)
    beyond = hand + 0.3 * (hand - np.asarray(camera.position)) / np.linalg.norm(
        hand - np.asarray(camera.position)
    )
    ahead = np.asarray(camera.transform_point((0.0, 0.0, 0.6)))
    assert _sight_blocked(robot, joints, beyond)
    assert not _sight_blocked(robot, joints, ahead)
    assert panda.joint_states("panda") == before  # the world is as it was
