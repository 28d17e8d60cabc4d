"""A reach map covers heights below a base frame held up over the robot's feet.

Centauro's base frame is its pelvis, 1.03 m over the floor when it stands; the counter's
mug lies below it. The map's heights started at the base frame, so it scored the mug 0
from every cell and the fetch fell back to stands too far away. The map now starts at
the robot's lowest point (checked against raw PyBullet bounds); a robot whose base frame
is on the floor keeps its map as it was.
"""

from __future__ import annotations

import warnings

import pybullet
import pytest

from robocram.costmaps.reachability_map import HEIGHT_STEP, base_bottom, build_reachability_map
from robocram.robots import (
    RobotDescription,
    example_robot_data_folder,
    load_description,
)
from tests.drafts import drafted

URDF = example_robot_data_folder() / "centauro_description" / "urdf" / "centauro.urdf"


@pytest.fixture(scope="module")
def centauro() -> RobotDescription:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_description(drafted(URDF).description)


def test_the_map_starts_at_the_robots_lowest_point(centauro: RobotDescription) -> None:
    client = pybullet.connect(pybullet.DIRECT)
    try:
        body = pybullet.loadURDF(str(centauro.urdf), useFixedBase=True, physicsClientId=client)
        centre = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)[0][2]
        inertial = pybullet.getDynamicsInfo(body, -1, physicsClientId=client)[3][2]
        base = centre - inertial  # the pelvis's frame, not its centre of mass
        lowest = min(
            pybullet.getAABB(body, i, physicsClientId=client)[0][2]
            for i in range(-1, pybullet.getNumJoints(body, physicsClientId=client))
        )
    finally:
        pybullet.disconnect(client)
    bottom = base_bottom(centauro)
    assert lowest - base - HEIGHT_STEP - 0.01 <= bottom <= lowest - base + 0.01
    assert base_bottom(load_description("pr2")) == 0.0  # on the floor: as before


def test_the_counters_mug_below_the_pelvis_is_in_reach(centauro: RobotDescription) -> None:
    reach = build_reachability_map(centauro, "right", samples=20_000)
    below = -0.17  # [m] the kitchen counter's mug under the standing pelvis
    assert reach.radius_at(below) > 0.5
