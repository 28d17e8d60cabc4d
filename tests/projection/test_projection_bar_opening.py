"""A hand opened only as wide as a bar handle needs: the gap it opens to, measured by
PyBullet, and that it is tried only when no hold with the hand fully open moved the part."""

from __future__ import annotations

import itertools
import math
import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.execution.failures import EnvironmentManipulationImpossible
from robocram.grasping.palm import palm_of
from robocram.projection import ProjectedRobot, bar_opening
from robocram.projection.articulation import move_part
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from tests.drafts import drafted_module
from tests.projection.drawer_stand import DRAWER, FACING_NORTH, pr2_before_drawer

ARMAR6 = Path(__file__).resolve().parents[1] / "data" / "zoo" / "armar6" / "armar6.urdf"


@pytest.fixture()
def pr2_at_drawer() -> Iterator[tuple[KitchenScene, ProjectedRobot]]:
    scene, robot = pr2_before_drawer(0.19, 0.95)
    yield scene, robot
    scene.world.close()


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


def _probe_clearance(
    robot: ProjectedRobot, fraction: float, width: float, length: float, shift: float = 0.0
) -> float:
    """[m] how far the right hand's fingers ``fraction`` open clear a box ``width`` square
    and ``length`` long, across the fingers at the palm hold of a bar ``width`` thick
    (``shift`` [m] further out along the fingers): raw PyBullet's closest points between
    the box and each finger link's collision shapes."""
    world = robot.world
    cid = world.physics.client()
    body = world.object(robot.name)
    palm = palm_of(robot.description, "right")
    assert palm is not None
    gripper = robot.arm("right").gripper
    assert gripper is not None
    world.set_joint_states(robot.name, gripper.at(fraction))
    tool = world.link_pose(robot.name, robot.arm("right").tool_frame)
    axes = quat.from_matrix(np.column_stack([palm.curl, palm.along, palm.across]))
    held = np.add(palm.holding(width / 2, width / 2, flat=False), np.multiply(shift, palm.along))
    at = tool * Pose((float(held[0]), float(held[1]), float(held[2])), axes)
    shape = pybullet.createCollisionShape(
        pybullet.GEOM_BOX, halfExtents=[width / 2, width / 2, length / 2], physicsClientId=cid
    )
    box = pybullet.createMultiBody(
        0.0, shape, basePosition=at.position, baseOrientation=at.orientation, physicsClientId=cid
    )
    try:
        return min(
            p[8]
            for finger in robot.arm("right").gripper_links
            for p in pybullet.getClosestPoints(
                body.body_id, box, 0.05, linkIndexA=body.link_index[finger], physicsClientId=cid
            )
        )
    finally:
        pybullet.removeBody(box, physicsClientId=cid)


def test_a_palm_hands_bar_opening_leaves_the_bar_and_margin_between_its_finger_surfaces(
    tmp_path: Path,
) -> None:
    """Armar6's fingers opened as the bar needs clear it with the margin, measured on their
    shapes: the widest such opening (a little wider, they enter it). Its palm's stand-in is
    a plate (``robots/stand_in_palm.py``), which puts the bar at the knuckles, where even
    the fist's phalanges lie in it: the bar is held out along the fingers, at the nearest
    place the fist clears it (zoo28; the palm box, 7 cm out, had held it there)."""
    module = tmp_path / "armar6.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(ARMAR6, module)
        scene = kitchen_scene(str(module))
    world = scene.world
    try:
        robot = ProjectedRobot.of(world, scene.robot)
        handle = f"{DRAWER}_handle"
        low, high = pybullet.getAABB(
            world.object("kitchen").body_id,
            world.object("kitchen").link_index[handle],
            physicsClientId=world.physics.client(),
        )
        extents = sorted(h - lo for lo, h in zip(low, high, strict=True))
        thickness, length = extents[0], extents[-1]
        width = thickness + bar_opening.BAR_MARGIN
        assert bar_opening.bar_opening(robot, "right", "kitchen", handle) is None
        assert _probe_clearance(robot, 0.0, width, length) < 0.0  # the fist in the bar
        found = bar_opening.fingers_hold(robot, "right", "kitchen", handle)
        assert found is not None
        back, fraction = found
        shift = math.dist(back.position, (0.0, 0.0, 0.0))
        assert 0.0 < shift < 0.08  # on the first phalanges
        assert _probe_clearance(robot, 0.0, width, length, shift - 0.005) < 0.0  # the nearest
        assert 0.0 <= fraction < 0.3  # a curled hand
        clear = _probe_clearance(robot, fraction, width, length, shift)
        assert clear == pytest.approx(0.0, abs=0.001)
        assert _probe_clearance(robot, fraction + 0.03, width, length, shift) < -0.001
    finally:
        world.close()
