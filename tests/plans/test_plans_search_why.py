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
