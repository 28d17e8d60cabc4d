"""The built-in robots' stored self-collision matrices are what sampling works out now.

A stored matrix saves each process ~0.4 s per robot; it is trusted only under the digest of
what it was worked out from. Here each is worked out anew and compared pair by pair, so a
changed URDF, parking pose or sampling rule fails here (run tools/store_self_collision.py)
rather than leaving a stale matrix unused or, worse, used.
"""

from __future__ import annotations

from dataclasses import replace

import pytest

from robocram.motion.self_collision_matrix import SelfCollisionMatrix
from robocram.motion.stored_self_collision import read_stored
from robocram.robots import load_description
from robocram.world import RobotHandle, World


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy"])
def test_the_stored_matrix_is_the_one_worked_out_now(robot: str) -> None:
    with World() as world:
        handle = world.add_robot(robot)
        fresh, digest = SelfCollisionMatrix.worked_out(RobotHandle.of(world, handle.name))
    stored = read_stored(robot, digest)
    assert stored is not None, (
        f"no current matrix stored: run tools/store_self_collision.py {robot}"
    )
    matrix = SelfCollisionMatrix.from_data(stored)
    assert matrix.checked == fresh.checked
    assert matrix.skipped == fresh.skipped
    assert matrix.rest_depths.keys() == fresh.rest_depths.keys()
    for pair, depth in fresh.rest_depths.items():
        assert matrix.rest_depths[pair] == pytest.approx(depth, abs=1e-12)


def test_a_description_that_changes_what_the_matrix_reads_finds_no_stored_one() -> None:
    desc = load_description("pr2")
    arm = desc.arms["right"]
    parking = dict(arm.parking) | {"r_elbow_flex_joint": arm.parking["r_elbow_flex_joint"] - 0.1}
    changed = replace(desc, arms={**desc.arms, "right": replace(arm, parking=parking)})
    with World() as world:
        world.add_robot(changed)
        _, digest = SelfCollisionMatrix.worked_out(RobotHandle.of(world, "pr2"))
        _, same = SelfCollisionMatrix.worked_out(RobotHandle.of(world, "pr2"))
    assert digest == same  # the digest is a function of what the matrix reads
    assert read_stored("pr2", digest) is None  # so the PR2's stored matrix is not used
