"""Seed 001 end to end: poses from which Boxy sees the pot on the table."""

from __future__ import annotations

import itertools
from collections.abc import Iterator

import numpy as np
import pytest

from robocram.costmaps import CostmapLocations
from robocram.designators import LocationDesignator, a, using_location_resolver
from robocram.projection.neck import look_at
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Pose
from robocram.world import World

TABLE_TOP = 1.0  # [m] seed 001's table
WALL_X = 2.3  # [m] a wall put behind the table, beyond the pot
SHADOW = (3.1, 0.35)  # [m] x beyond this (and the wall's footprint), |y| under this: hidden


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        w.add_robot("boxy", pose=Pose((0.0, 0.0, 0.0)))
        w.add_box("table", (0.7, 1.5, TABLE_TOP), Pose((1.6, 0.0, TABLE_TOP / 2)))
        w.add_item("pot", "pot", Pose((1.6, 0.0, 1.4)))
        w.physics.simulate(2.0)  # the pot falls onto the table and comes to rest
        assert w.physics.supported_by("pot", "table")
        yield w


def park_arms(world: World, robot: str) -> None:
    """Put the robot's arms (not its neck) at their parking values from its description."""
    desc = world.robot(robot).description
    for name, arm in desc.arms.items():
        if name != desc.neck_arm:
            world.set_joint_states(robot, dict(arm.parking))


def _visible_for_boxy() -> LocationDesignator:
    return a.location(visible_for="boxy", object="pot")


def test_boxy_sees_the_pot_from_each_of_ten_lazy_poses(world: World) -> None:
    locs = CostmapLocations(world, seed=1)
    with using_location_resolver(locs.resolver()):
        designator = _visible_for_boxy()
        poses = [designator.reference()]
        successor = designator.next_solution()
        while successor is not None and len(poses) < 10:
            poses.append(successor.reference())
            successor = successor.next_solution()
    assert len({p.position for p in poses}) == 10
    robot = ProjectedRobot.of(world, "boxy")
    pot = world.pose("pot").position
    for pose in poses:
        with world.snapshots.stored_state():
            world.set_pose("boxy", pose)
            park_arms(world, "boxy")  # Boxy arrives as it drives, arms parked
            assert not world.contacts.in_collision("boxy"), pose
            look_at(robot, pot)
            assert world.view.visible("boxy", "pot"), (
                pose,
                world.view.visibility_fraction("boxy", "pot"),
            )


def _in_shadow(x: float, y: float) -> bool:
    return x > SHADOW[0] and abs(y) < SHADOW[1]


def test_a_wall_between_removes_the_poses_behind_it(world: World) -> None:
    locs = CostmapLocations(world, seed=2)
    before = locs.costmap(_visible_for_boxy())
    x, y = before.grid.centres()
    shadow = (x > SHADOW[0]) & (np.abs(y) < SHADOW[1])
    assert np.count_nonzero(before.weights[shadow]) > 0.9 * np.count_nonzero(shadow)
    with world.snapshots.stored_state():
        world.add_box("wall", (0.1, 1.6, 2.5), Pose((WALL_X, 0.0, 1.25)))
        after = locs.costmap(_visible_for_boxy())
        assert np.count_nonzero(after.weights[shadow]) == 0
        poses = list(itertools.islice(locs.poses(_visible_for_boxy()), 10))
    assert len(poses) == 10
    assert not any(_in_shadow(p.position[0], p.position[1]) for p in poses)


def test_same_seed_same_poses(world: World) -> None:
    def first_five(seed: int) -> list[tuple[float, float, float]]:
        poses = CostmapLocations(world, seed=seed).poses(_visible_for_boxy())
        return [p.position for p in itertools.islice(poses, 5)]

    assert first_five(11) == first_five(11)
    assert first_five(11) != first_five(12)
