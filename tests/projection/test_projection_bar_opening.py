"""A hand opened only as wide as a bar handle needs: the gap it opens to, measured by
PyBullet, and that it is tried only when no hold with the hand fully open moved the part."""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator

import pybullet
import pytest

from robocram.execution.failures import EnvironmentManipulationImpossible
from robocram.projection import ProjectedRobot, bar_opening
from robocram.projection.articulation import move_part
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

DRAWER = "drawer_unit_drawer_3"  # the bowl's drawer, its bar handle 2 cm thick
FACING_NORTH = quat.from_euler(0.0, 0.0, math.pi / 2)


@pytest.fixture()
def pr2_at_drawer() -> Iterator[tuple[KitchenScene, ProjectedRobot]]:
    scene = kitchen_scene("pr2")
    world = scene.world
    desc = world.robot(scene.robot).description
    world.set_joint_states(
        scene.robot, {j: v for a in desc.arms.values() for j, v in a.parking.items()}
    )
    handle_x = world.link_pose("kitchen", f"{DRAWER}_handle").position[0]
    world.set_pose(scene.robot, Pose((handle_x - 0.19, 0.95, 0.0), FACING_NORTH))  # right arm
    yield scene, ProjectedRobot.of(world, scene.robot)
    world.close()


def _finger_growth(robot: ProjectedRobot, fraction: float) -> float:
    """[m] the largest growth, from closed to ``fraction`` open, of the distance between two
    of the right hand's finger link frames, read from PyBullet's link states."""
    world = robot.world
    body = world.object(robot.name)
    cid = world.physics.client()
    gripper = robot.arm("right").gripper
    assert gripper is not None
    fingers = robot.arm("right").gripper_links

    def frames(at: float) -> list[tuple[float, ...]]:
        world.set_joint_states(robot.name, gripper.at(at))
        return [
            tuple(pybullet.getLinkState(body.body_id, body.link_index[f], physicsClientId=cid)[4])
            for f in fingers
        ]

    closed, opened = frames(0.0), frames(fraction)
    return max(
        math.dist(opened[i], opened[j]) - math.dist(closed[i], closed[j])
        for i, j in itertools.combinations(range(len(fingers)), 2)
    )


def test_the_bar_opening_is_the_bars_thickness_and_the_margin(
    pr2_at_drawer: tuple[KitchenScene, ProjectedRobot],
) -> None:
    scene, robot = pr2_at_drawer
    world = scene.world
    kitchen = world.object("kitchen")
    low, high = pybullet.getAABB(
        kitchen.body_id,
        kitchen.link_index[f"{DRAWER}_handle"],
        physicsClientId=world.physics.client(),
    )
    thickness = min(h - lo for lo, h in zip(low, high, strict=True))
    assert thickness == pytest.approx(0.02, abs=0.003)  # the kitchen's 2 cm bar
    fraction = bar_opening.bar_opening(robot, "right", "kitchen", f"{DRAWER}_handle")
    assert fraction is not None
    assert 0.0 < fraction < 1.0
    assert _finger_growth(robot, fraction) == pytest.approx(
        thickness + bar_opening.BAR_MARGIN, abs=0.001
    )
    gripper = robot.arm("right").gripper
    assert gripper is not None
    bar_opening.set_open(robot, "right", fraction)  # a checked motion of the fingers
    master = gripper.names[0]
    assert world.joint_states(robot.name)[master] == pytest.approx(
        gripper.at(fraction)[master], abs=1e-6
    )


def test_a_hand_fully_open_that_holds_the_handle_never_narrows(
    pr2_at_drawer: tuple[KitchenScene, ProjectedRobot], monkeypatch: pytest.MonkeyPatch
) -> None:
    _, robot = pr2_at_drawer
    asked: list[str] = []
    monkeypatch.setattr(bar_opening, "bar_opening", lambda *a: asked.append(a[3]) or 0.4)
    result = move_part(robot, "right", "kitchen", f"{DRAWER}_joint", f"{DRAWER}_handle", 0.3)
    assert result.reached == pytest.approx(0.3, abs=1e-9)
    assert asked == []


def _far_and_spied(
    scene: KitchenScene, robot: ProjectedRobot, monkeypatch: pytest.MonkeyPatch
) -> tuple[list[str], list[float]]:
    """The PR2 2.4 m from the drawer (no hold reaches it); the handles the bar opening is
    asked for (it says 0.4) and the fractions the fingers are set to."""
    scene.world.set_pose(robot.name, Pose((-1.6, -0.5, 0.0), FACING_NORTH))
    asked: list[str] = []
    opened: list[float] = []
    monkeypatch.setattr(bar_opening, "bar_opening", lambda *a: asked.append(a[3]) or 0.4)
    real = bar_opening.set_open

    def set_open(robot: ProjectedRobot, arm: str, fraction: float) -> None:
        opened.append(fraction)
        real(robot, arm, fraction)

    monkeypatch.setattr(bar_opening, "set_open", set_open)
    return asked, opened


def test_a_narrower_hand_that_frees_no_hold_moves_nothing(
    pr2_at_drawer: tuple[KitchenScene, ProjectedRobot], monkeypatch: pytest.MonkeyPatch
) -> None:
    scene, robot = pr2_at_drawer
    asked, opened = _far_and_spied(scene, robot, monkeypatch)
    with pytest.raises(EnvironmentManipulationImpossible):
        move_part(robot, "right", "kitchen", f"{DRAWER}_joint", f"{DRAWER}_handle", 0.3)
    assert asked == [f"{DRAWER}_handle"]  # once, after the fully open holds
    assert opened == []  # narrowing freed no hold (IK puts the hand nowhere): no finger moved


def test_the_narrower_hand_is_tried_where_it_frees_the_hold(
    pr2_at_drawer: tuple[KitchenScene, ProjectedRobot], monkeypatch: pytest.MonkeyPatch
) -> None:
    scene, robot = pr2_at_drawer
    asked, opened = _far_and_spied(scene, robot, monkeypatch)
    monkeypatch.setattr(bar_opening, "narrowing_frees", lambda *a: True)
    with pytest.raises(EnvironmentManipulationImpossible):
        move_part(robot, "right", "kitchen", f"{DRAWER}_joint", f"{DRAWER}_handle", 0.3)
    assert asked == [f"{DRAWER}_handle"]
    assert opened and set(opened) == {0.4}  # each hold again, the hand opened that far
    assert scene.world.joint_states("kitchen")[f"{DRAWER}_joint"] == pytest.approx(0.0)
