"""A joint write of the values the tables last wrote (nothing else moved the joints
since) spares PyBullet, and still counts as a write; after physics, a restored state or
new holds, the write reaches PyBullet again."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.scenes import kitchen_scene
from robocram.world import World

JOINT = "torso_lift_joint"


@pytest.fixture(scope="module")
def kitchen() -> Iterator[World]:
    world = kitchen_scene("pr2").world
    yield world
    world.close()


def _resets(world: World, monkeypatch: pytest.MonkeyPatch) -> list[dict[int, float]]:
    """The slot values of every PyBullet joint write from now on."""
    from robocram.world import world_tables

    seen: list[dict[int, float]] = []
    reset = world_tables.reset_slots

    def counted(handle: object, values: dict[int, float], cid: int) -> None:
        seen.append(dict(values))
        reset(handle, values, cid)  # type: ignore[arg-type]

    monkeypatch.setattr(world_tables, "reset_slots", counted)
    return seen


def test_a_write_of_what_stands_spares_pybullet(
    kitchen: World, monkeypatch: pytest.MonkeyPatch
) -> None:
    resets = _resets(kitchen, monkeypatch)
    kitchen.set_joint_states("pr2", {JOINT: 0.1})
    stamp = kitchen.versions.joints("pr2")
    kitchen.set_joint_states("pr2", {JOINT: 0.1})  # the same again
    assert len(resets) == 1  # only the first reached PyBullet
    assert kitchen.versions.joints("pr2") != stamp  # but both count as writes
    assert kitchen.joint_states("pr2")[JOINT] == 0.1
    kitchen.set_joint_states("pr2", {JOINT: 0.2})  # another value: written
    assert len(resets) == 2 and kitchen.joint_states("pr2")[JOINT] == 0.2


def test_physics_or_new_holds_make_the_write_reach_pybullet(
    kitchen: World, monkeypatch: pytest.MonkeyPatch
) -> None:
    resets = _resets(kitchen, monkeypatch)
    kitchen.set_joint_states("pr2", {JOINT: 0.15})
    kitchen.physics.step()  # physics may have moved the joints
    kitchen.set_joint_states("pr2", {JOINT: 0.15})
    assert len(resets) == 2
    kitchen.snapshots.set_held_joints("pr2", {JOINT: 0.15})  # holds set, nothing moved
    kitchen.set_joint_states("pr2", {JOINT: 0.15})
    assert len(resets) == 3
    with kitchen.snapshots.stored_state():
        kitchen.set_joint_states("pr2", {JOINT: 0.25})
    # the restored state wrote PyBullet itself: the next write of its values reaches it
    kitchen.set_joint_states("pr2", {JOINT: 0.15})
    assert len(resets) == 5
    assert abs(kitchen.joint_states("pr2")[JOINT] - 0.15) < 1e-12
