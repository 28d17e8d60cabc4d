"""A drive that starts touching something may leave it, never push in deeper, and its
trajectory says how deep the start contact was allowed to be (issue 35: fingers round a
handle went 5.95 mm into it while the base left)."""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pybullet
import pytest

from robocram.execution.failures import NavigationPoseUnreachable
from robocram.motion.base_collision import CONTACT, blockers_at
from robocram.motion.base_path import plan_base_path
from robocram.motion.hand_contact import KEEP_DEPTH
from robocram.tf import Pose
from robocram.world import RobotHandle, World

START_DEPTH = 0.003  # [m] how far the base starts inside the crate


@pytest.fixture
def pressed(kitchen: World) -> Iterator[tuple[World, float]]:
    """The PR2 facing +x with its base ~3 mm into a crate ahead, and that depth [m]."""
    with kitchen.snapshots.stored_state():
        kitchen.add_box("crate", (0.4, 0.8, 0.5), (0.0, 0.2, 0.25))
        kitchen.set_pose("pr2", Pose((-1.0, 0.2, 0.0)))
        gap = _gap(kitchen)
        kitchen.set_pose("pr2", Pose((-1.0 + gap + START_DEPTH, 0.2, 0.0)))
        yield kitchen, -_gap(kitchen)


def _gap(world: World) -> float:
    """The PR2's distance [m] to the crate (negative: inside it), by PyBullet."""
    found = world.contacts.link_distances("pr2", distance=1.0)
    return min(d for _, other, _, d in found if other.name == "crate")


def _x(world: World) -> float:
    return float(world.pose("pr2").position[0])


def test_a_drive_leaving_a_start_contact_stores_its_depth(pressed: tuple[World, float]) -> None:
    world, depth = pressed
    assert depth == pytest.approx(START_DEPTH, abs=5e-4)
    path = plan_base_path(RobotHandle.of(world, "pr2"), Pose((_x(world) - 0.3, 0.2, 0.0)))
    (allowance,) = [a for a in path.trajectory.allowed_contacts if a.other == "crate"]
    assert allowance.depth == pytest.approx(depth + KEEP_DEPTH, abs=1e-6)
    assert allowance.robot_side in world.robot("pr2").description.model.links


def test_a_drive_never_pushes_a_start_contact_deeper(pressed: tuple[World, float]) -> None:
    world, _ = pressed
    deeper = Pose((_x(world) + 0.02, 0.2, 0.0))  # within the first 10 cm of travel
    with pytest.raises(NavigationPoseUnreachable) as raised:
        plan_base_path(RobotHandle.of(world, "pr2"), deeper)
    assert "crate" in (raised.value.colliding or [])


def test_a_plainly_blocked_goal_names_what_pybullet_finds_there(
    pressed: tuple[World, float],
) -> None:
    """The one exact check of a goal (the kept obstacle bounds, not a broadphase query
    per link) names every object PyBullet finds within touching distance there."""
    world, _ = pressed
    robot = RobotHandle.of(world, "pr2")
    goal = np.array([_x(world) + 0.02, 0.2, 0.0])  # deeper into the crate
    named = blockers_at(robot, goal)
    cid, body = world.physics.client(), world.object("pr2").body_id
    world.set_pose("pr2", Pose((float(goal[0]), 0.2, 0.0)))
    raw = {
        other.name for other in world.objects()
        if other.type != "floor" and other.name != "pr2"
        and pybullet.getClosestPoints(body, other.body_id, CONTACT, physicsClientId=cid)
    }  # fmt: skip
    world.set_pose("pr2", Pose((float(goal[0]) - 0.02, 0.2, 0.0)))
    assert "crate" in raw
    assert {name.split("/")[0] for name in named} == raw
