"""Opening stands face the container's front from the KB, not the way its handle frame points.

The kitchen's description is kept (its drafted fronts) but one handle frame is turned a
quarter about z in a copy of the URDF, and the whole kitchen is turned in the world: the
stands must face the drafted front turned with the kitchen.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path

import pytest

from robocram.plans.container_access import front_in_map, opening_stands
from robocram.plans.containers import container
from robocram.plans.stands import yaw_of
from robocram.projection import simulated_robot
from robocram.scenes import EnvironmentScene, environment_scene, kitchen_urdf
from robocram.scenes.kitchen_scene import kitchen_description
from robocram.tf import Pose
from robocram.tf import quaternion as quat

HANDLE = "drawer_unit_drawer_3_handle"
DRAFTED_FRONT = -math.pi / 2  # [rad] the drawer unit's front faces south in the kitchen
KITCHEN_TURN = math.pi / 6  # [rad] the kitchen's yaw in the world
ROBOT_AWAY = Pose((5.0, 5.0, 0.0))  # [m] out of the turned kitchen's way


def _wrapped(angle: float) -> float:
    return math.atan2(math.sin(angle), math.cos(angle))


@pytest.fixture()
def turned_handle_kitchen(tmp_path: Path) -> Iterator[EnvironmentScene]:
    text = kitchen_urdf().read_text("utf-8")
    joint = f'<joint name="{HANDLE}_joint" type="fixed">\n    <origin xyz="0.04 0 0.1766666667"'
    assert text.count(f'{joint} rpy="0 0 0"/>') == 1
    urdf = tmp_path / "kitchen.urdf"
    urdf.write_text(text.replace(f'{joint} rpy="0 0 0"/>', f'{joint} rpy="0 0 1.5708"/>'))
    scene = environment_scene(replace(kitchen_description(), urdf=urdf), "pr2", (), ROBOT_AWAY)
    scene.world.set_pose(scene.environment, Pose(orientation=quat.from_euler(0, 0, KITCHEN_TURN)))
    yield scene
    scene.world.close()


def test_container_stands_face_the_kb_front_turned_with_the_environment(
    turned_handle_kitchen: EnvironmentScene,
) -> None:
    world, robot = turned_handle_kitchen.world, turned_handle_kitchen.robot
    handle = world.link_pose("kitchen", HANDLE)
    front = DRAFTED_FRONT + KITCHEN_TURN  # [rad] in map
    # The handle's x axis points a quarter turn off the front: the old guess would be wrong.
    assert _wrapped(yaw_of(handle) - front) == pytest.approx(math.pi / 2, abs=1e-3)
    with simulated_robot(world, robot):
        part = container(HANDLE)
        part_front = front_in_map(part)
        stands = list(opening_stands(part))
    assert part_front == pytest.approx(front, abs=1e-3)
    assert part.opened == pytest.approx(0.4, abs=1e-6)
    out = (math.cos(front), math.sin(front))
    ahead = [
        (s.pose.position[0] - handle.position[0]) * out[0]
        + (s.pose.position[1] - handle.position[1]) * out[1]
        for s in stands
    ]
    assert [s.arm for s in stands] == ["left"] * 3 + ["right"] * 3
    # opening + clearances in front of the handle, for each arm
    assert ahead == pytest.approx([0.9, 1.0, 0.8] * 2, abs=1e-6)
    for stand in stands:
        assert _wrapped(yaw_of(stand.pose) - front - math.pi) == pytest.approx(0.0, abs=1e-3)


def test_without_a_front_fact_the_container_stands_face_the_handle_frame(
    turned_handle_kitchen: EnvironmentScene,
) -> None:
    world, robot = turned_handle_kitchen.world, turned_handle_kitchen.robot
    facts = kitchen_description().facts().splitlines()
    unfronted = [f for f in facts if not f.startswith("container_front(")]
    world.kb.consult("\n".join(unfronted), group="kitchen_semantics")  # as before the fact
    handle = world.link_pose("kitchen", HANDLE)
    with simulated_robot(world, robot):
        part = container(HANDLE)
        part_front = front_in_map(part)
        stands = list(opening_stands(part))
    assert part_front is None
    assert len(stands) == 6
    for stand in stands:
        assert _wrapped(yaw_of(stand.pose) - yaw_of(handle) - math.pi) == pytest.approx(
            0.0, abs=1e-3
        )
