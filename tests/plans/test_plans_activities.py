"""Everyday activities on the PR2: breakfast for two (two-armed), then clearing the table.

Judged by raw PyBullet queries, not by the plans' own results: where each body is, how
far it is tilted, which joint stands where, what touches what.
"""

from __future__ import annotations

import contextlib
import io
import math
from collections.abc import Iterator
from dataclasses import dataclass

import pybullet
import pytest

import robocram.plans
from robocram.designators import Designator
from robocram.plans import ACTIONS, perform
from robocram.plans.activity_failures import ActivityIncomplete
from robocram.plans.setting_table import TableSetting
from robocram.plans.table_arrangement import TOLERANCE
from robocram.scenes import EnvironmentScene
from robocram.scenes.breakfast_scene import BREAKFAST_PLACES
from robocram.world import World
from tests.doc_blocks import DOCS, runnable_blocks

UPRIGHT = 0.05  # [rad] how far a thing may lean and still stand
TABLE_TOP = 0.75  # [m] the kitchen table's top (tools/make_kitchen_urdf.py)


Placed = tuple[tuple[float, float, float], float, float]  # where, tilt [rad], bottom [m]


@dataclass
class Breakfast:
    world: World
    robot: str
    setting: TableSetting
    set_at: dict[str, Placed]  # after setting
    closed: dict[str, float]  # opened container joints after setting [m | rad]
    clearing: ActivityIncomplete | None  # what clearing left undone, if anything
    closed_after: dict[str, float]  # the same joints after clearing [m | rad]


def _body(world: World, name: str) -> int:
    return world.object(name).body_id


def _position(world: World, name: str) -> tuple[float, float, float]:
    position, _ = pybullet.getBasePositionAndOrientation(
        _body(world, name), physicsClientId=world.physics.client()
    )
    return (position[0], position[1], position[2])


def _tilt(world: World, name: str) -> float:
    """The angle [rad] between the body's z axis and the vertical."""
    _, orientation = pybullet.getBasePositionAndOrientation(
        _body(world, name), physicsClientId=world.physics.client()
    )
    matrix = pybullet.getMatrixFromQuaternion(orientation)
    return math.acos(max(-1.0, min(1.0, matrix[8])))


def _bottom(world: World, name: str) -> float:
    low, _ = pybullet.getAABB(_body(world, name), physicsClientId=world.physics.client())
    return float(low[2])


def _joint(world: World, body: str, joint: str) -> float:
    bid = _body(world, body)
    for index in range(pybullet.getNumJoints(bid, physicsClientId=world.physics.client())):
        info = pybullet.getJointInfo(bid, index, physicsClientId=world.physics.client())
        if info[1].decode() == joint:
            return float(
                pybullet.getJointState(bid, index, physicsClientId=world.physics.client())[0]
            )
    raise KeyError(joint)


def _touches_link(world: World, name: str, body: str, link: str) -> bool:
    bid = _body(world, body)
    for index in range(pybullet.getNumJoints(bid, physicsClientId=world.physics.client())):
        if (
            pybullet.getJointInfo(bid, index, physicsClientId=world.physics.client())[12].decode()
            == link
        ):
            points = pybullet.getClosestPoints(
                _body(world, name),
                bid,
                0.005,
                linkIndexB=index,
                physicsClientId=world.physics.client(),
            )
            return bool(points)
    raise KeyError(link)


@pytest.fixture(scope="module")
def breakfast() -> Iterator[Breakfast]:
    """docs/activities.md's block run as written (it has no test of its own: the same
    breakfast twice cost a minute of CPU), watched through the ``perform`` it imports:
    where things stand and which containers are open once the table is set."""
    (block,) = runnable_blocks((DOCS / "activities.md").read_text(encoding="utf-8"))
    namespace: dict[str, object] = {"__name__": "__main__"}
    set_table: list[tuple[TableSetting, dict[str, Placed], dict[str, float]]] = []

    def watched(designator: Designator[object]) -> object:
        result = perform(designator)
        if isinstance(result, TableSetting):  # the table is set: see it before clearing
            world = _scene(namespace).world
            set_at = {n: _placed(world, n) for n in _scene(namespace).items}
            joints = {
                row["J"]: _joint(world, "kitchen", row["J"])
                for link in result.opened
                for row in world.kb.query("container(kitchen, L, J, _)", L=link)
            }
            set_table.append((result, set_at, joints))
        return result

    clearing = None
    with pytest.MonkeyPatch.context() as patch, contextlib.redirect_stdout(io.StringIO()):
        patch.setattr(robocram.plans, "perform", watched)
        try:
            exec(compile(block, "activities.md block 1", "exec"), namespace)  # noqa: S102
        except ActivityIncomplete as failure:  # clearing left something undone
            clearing = failure
    scene = _scene(namespace)
    ((setting, set_at, joints),) = set_table
    after = {joint: _joint(scene.world, "kitchen", joint) for joint in joints}
    yield Breakfast(scene.world, scene.robot, setting, set_at, joints, clearing, after)
    scene.world.close()


def _scene(namespace: dict[str, object]) -> EnvironmentScene:
    scene = namespace["scene"]
    assert isinstance(scene, EnvironmentScene)
    return scene


def _placed(world: World, name: str) -> Placed:
    return _position(world, name), _tilt(world, name), _bottom(world, name)


def test_the_activities_are_action_types() -> None:
    assert ACTIONS["setting-table"].keys == ("people", "setting", "shared", "table", "two_arms")
    assert ACTIONS["clearing-table"].keys == ("objects", "table")
    assert ACTIONS["facing"].required == ("target",)
    assert ACTIONS["carrying"].keys == ("arm", "target")


def test_breakfast_for_two_puts_each_thing_at_its_seat(breakfast: Breakfast) -> None:
    setting = breakfast.setting
    kinds = sorted(spot.type for spot in setting.placed.values())
    assert kinds == ["bowl", "bowl", "cup", "cup", "milk", "spoon", "spoon"]
    assert sorted(spot.seat for spot in setting.placed.values()) == [0, 1, 1, 1, 2, 2, 2]
    for name, spot in setting.placed.items():
        (x, y, _), tilt, bottom = breakfast.set_at[name]
        sx, sy, _ = spot.pose.position
        assert math.hypot(x - sx, y - sy) <= TOLERANCE, name
        assert tilt <= UPRIGHT, name
        assert bottom == pytest.approx(TABLE_TOP, abs=0.01), name


def test_two_arms_carry_two_things_per_trip_where_they_can(breakfast: Breakfast) -> None:
    trips = breakfast.setting.trips  # the PR2 has two arms: two_arms is the default
    assert sorted(n for trip in trips for n in trip) == sorted(breakfast.setting.placed)
    assert any(len(trip) == 2 for trip in trips)
    assert len(trips) < len(breakfast.setting.placed)  # fewer drives to the table than things


def test_every_container_opened_is_closed_again(breakfast: Breakfast) -> None:
    assert set(breakfast.setting.opened) == {
        "drawer_unit_drawer_3",
        "cutlery_unit_drawer_3",
        "cutlery_unit_drawer_4",
        "fridge_body",
    }
    assert breakfast.closed  # the fridge door, the drawers
    for joint, value in breakfast.closed.items():
        assert value == pytest.approx(0.0, abs=0.01), joint


def test_nothing_fell(breakfast: Breakfast) -> None:
    for name, ((_, _, z), tilt, _) in breakfast.set_at.items():
        assert z > 0.4, name  # on a counter, shelf, drawer or the table; never the floor
        assert tilt <= UPRIGHT, name


def test_clearing_puts_things_back_where_they_are_kept(breakfast: Breakfast) -> None:
    world = breakfast.world
    left = set(breakfast.clearing.missing or ()) if breakfast.clearing else set()
    usual = {p.name: p.link for p in BREAKFAST_PLACES}
    back = [n for n in breakfast.setting.placed if n not in left]
    assert len(back) == len(breakfast.setting.placed)
    for name in back:
        assert _touches_link(world, name, "kitchen", usual[name]), name
        assert _tilt(world, name) <= UPRIGHT, name


def test_clearing_brings_everything_back_and_closes_what_it_opened(
    breakfast: Breakfast,
) -> None:
    assert breakfast.clearing is None
    for joint, value in breakfast.closed_after.items():
        assert value == pytest.approx(0.0, abs=0.01), joint
