"""A search that saw nothing says why where it can: a camera below every place searched,
a container that stayed shut."""

from __future__ import annotations

from dataclasses import replace

import pytest

from robocram.execution.failures import EnvironmentManipulationImpossible
from robocram.plans.known_robot import current_robot
from robocram.plans.search import Place, SearchLog, _stayed_shut, camera_below
from robocram.projection import simulated_robot
from robocram.robots import load_description
from robocram.scenes import kitchen_scene
from robocram.world.pybullet_backend import pybullet
from tests.bullet_links import link_indices

PLACES = [Place("kitchen", "counter_top_north"), Place("kitchen", "table_top")]


@pytest.mark.parametrize("camera_top", [None, 0.5])
def test_a_camera_lower_than_every_place_is_named(camera_top: float | None) -> None:
    desc = load_description("pr2")
    if camera_top is not None:  # Alex's head was 0.71 m up; a counter's top 0.83 m
        cameras = tuple(
            replace(c, minimal_height=camera_top - 0.1, maximal_height=camera_top)
            for c in desc.cameras
        )
        desc = replace(desc, cameras=cameras)
    scene = kitchen_scene(desc)
    try:
        kitchen = scene.world.object("kitchen").body_id
        client = scene.world.physics.client()
        index = link_indices(kitchen, client)["table_top"]
        table = pybullet.getLinkState(kitchen, index, physicsClientId=client)[4][2]
        with simulated_robot(scene.world, scene.robot):
            clause = camera_below(current_robot(), PLACES)
        if camera_top is None:  # the PR2's own camera, over 1.2 m up, sees onto both
            assert clause == ""
        else:
            assert f"{camera_top:.2f} m up at most" in clause
            assert f"from {table:.2f} m" in clause  # the lower place, the table
    finally:
        scene.world.close()


def test_a_container_that_stayed_shut_is_named_with_why() -> None:
    log = SearchLog()
    assert _stayed_shut(log) == ""
    why = "no arm of ['right'] could open 'drawer_3': the palm meets the counter's top"
    log.shut.append((Place("kitchen", "drawer_3"), EnvironmentManipulationImpossible(why)))
    clause = _stayed_shut(log)
    assert clause.startswith(" (drawer_3 stayed shut: EnvironmentManipulationImpossible: ")
    assert "the palm meets the counter's top" in clause


def test_a_camera_is_measured_over_the_floor_from_a_raised_base_frame() -> None:
    """Centauro's base frame, its pelvis, stands 1.03 m up: its camera 0.55 m over it is
    1.58 m over the floor, over every place, and was said to be below them all."""
    desc = load_description("pr2")
    cameras = tuple(replace(c, minimal_height=0.4, maximal_height=0.5) for c in desc.cameras)
    scene = kitchen_scene(replace(desc, cameras=cameras))
    try:
        robot = scene.world.robot(scene.robot)
        pose = scene.world.pose(robot)
        x, y, _ = pose.position
        with simulated_robot(scene.world, scene.robot):
            assert "0.50 m up at most" in camera_below(current_robot(), PLACES)
            scene.world.set_pose(robot, replace(pose, position=(x, y, 0.6)))
            body = robot.body_id
            client = scene.world.physics.client()
            raised = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)[0]
            assert raised[2] == pytest.approx(0.6, abs=1e-6)
            assert camera_below(current_robot(), PLACES) == ""  # 1.10 m: over the table
    finally:
        scene.world.close()
