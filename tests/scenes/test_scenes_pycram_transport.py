"""The same plans, unchanged, in other people's kitchens (issue 25, item 6).

tests/data/pycram/kitchen_env.py and apartment_env.py are what `robocram env draft` wrote
for PyCRAM's kitchen.urdf and apartment.urdf, then edited: the table's size (its mesh is
not shipped; 1.6 x 0.8 x 0.72 m, the size of iai_kitchen's big_table_1), its top's
height, and where bowls are kept. The transport opens the drawer the bowl is kept in,
takes the bowl out, puts it on the table and closes the drawer again.
"""

from __future__ import annotations

import difflib
import math
import warnings
from collections.abc import Iterator
from pathlib import Path

import pytest

from robocram.designators import a
from robocram.plans.transport import TransportResult, transport
from robocram.projection import simulated_robot
from robocram.scenes import EnvironmentScene, draft_environment, environment_scene
from robocram.scenes.environment_check import check_environment, environment_from
from robocram.scenes.environment_scene import ItemPlace
from robocram.tf import Pose
from robocram.tf import quaternion as quat

DATA = Path(__file__).resolve().parents[1] / "data"
PYCRAM = DATA / "pycram"
FETCH = DATA / "fetch" / "fetch.py"
KITCHEN_DRAWER = "kitchen_island_left_upper_drawer_main"
APARTMENT_DRAWER = "cabinet10_drawer_top"
TABLE = "table_area_main"
TABLE_TOP = 0.72  # [m] as edited into both kept drafts


@pytest.fixture(autouse=True)
def _no_mesh_warnings() -> None:
    warnings.filterwarnings("ignore", message=".*mesh.*")


def _edits(name: str) -> int:
    """Blocks of lines changed between a fresh draft and the kept, edited one."""
    kept = PYCRAM / f"{name}_env.py"
    fresh = draft_environment(PYCRAM / f"{name}.urdf").source(kept)
    matcher = difflib.SequenceMatcher(
        None, fresh.splitlines(), kept.read_text("utf-8").splitlines(), autojunk=False
    )
    return sum(tag != "equal" for tag, *_ in matcher.get_opcodes())


@pytest.mark.parametrize(("name", "checks"), [("kitchen", 19), ("apartment", 36)])
def test_the_kept_drafts_are_three_edits_from_fresh_ones_and_pass_the_check(
    name: str, checks: int
) -> None:
    assert _edits(name) == 3  # the table's stand-in, its surface height, usual_locations
    desc = environment_from(PYCRAM / f"{name}_env.py")
    assert desc.surface(TABLE) is not None and desc.surface(TABLE).height == TABLE_TOP  # type: ignore[union-attr]
    card = check_environment(desc)
    assert card.passed, card.render()
    assert len(card.lines) == checks


def _scene(
    name: str, robot: str, drawer: str, xy: tuple[float, float], start: tuple[float, float, float]
) -> EnvironmentScene:
    desc = environment_from(PYCRAM / f"{name}_env.py")
    x, y, yaw = start
    pose = Pose((x, y, 0.0), quat.from_euler(0.0, 0.0, yaw))
    return environment_scene(desc, robot, [ItemPlace("bowl-1", "bowl", drawer, xy)], pose)


@pytest.fixture()
def kitchen(request: pytest.FixtureRequest) -> Iterator[EnvironmentScene]:
    scene = _scene("kitchen", request.param, KITCHEN_DRAWER, (0.1, 0.0), (0.4, 0.0, math.pi))
    yield scene
    scene.world.close()


def _transport(scene: EnvironmentScene, surface: str) -> TransportResult:
    with simulated_robot(scene.world, scene.robot):
        return transport("bowl", a.location(on=(scene.environment, surface), for_="bowl-1"))


def _rests_on(scene: EnvironmentScene, surface: str, height: float) -> None:
    """The bowl stands on ``surface``: its bottom within 2 cm of the top, its middle
    inside the top's outline, touching that link, held by nobody."""
    world, env = scene.world, scene.environment
    low, high = world.aabb("bowl-1")
    assert low[2] == pytest.approx(height, abs=0.02)
    top_low, top_high = world.contacts.link_aabb(env, surface)
    middle = ((low[0] + high[0]) / 2, (low[1] + high[1]) / 2)
    assert top_low[0] < middle[0] < top_high[0] and top_low[1] < middle[1] < top_high[1]
    assert surface in {p.link_b for p in world.contacts.contact_points("bowl-1", env)}
    assert world.bodies.attached_to("bowl-1") is None


def _went_as_planned(result: TransportResult, drawer: str) -> None:
    assert [o.container.link for o in result.opened] == [drawer]
    stages = [at.stage for at in result.log.attempts if at.succeeded]
    assert stages == ["open", "fetch", "deliver", "close"]


@pytest.mark.parametrize(
    "kitchen",
    ["pr2", str(FETCH)],
    indirect=True,
    ids=["pr2", "fetch"],
)
def test_the_bowl_goes_from_a_drawer_to_the_table_in_pycrams_kitchen(
    kitchen: EnvironmentScene,
) -> None:
    result = _transport(kitchen, TABLE)
    _went_as_planned(result, KITCHEN_DRAWER)
    joints = kitchen.world.joint_states(kitchen.environment)
    assert joints[f"{KITCHEN_DRAWER}_joint"] == pytest.approx(0.0, abs=0.01)
    _rests_on(kitchen, TABLE, TABLE_TOP)


def test_the_pr2_takes_the_bowl_from_a_drawer_to_the_counter_in_pycrams_apartment() -> None:
    scene = _scene("apartment", "pr2", APARTMENT_DRAWER, (-0.1, 0.0), (1.3, 2.25, 0.0))
    try:
        result = _transport(scene, "countertop")
        _went_as_planned(result, APARTMENT_DRAWER)
        joints = scene.world.joint_states(scene.environment)
        assert joints[f"{APARTMENT_DRAWER}_joint"] == pytest.approx(0.0, abs=0.01)
        counter = scene.world.contacts.link_aabb(scene.environment, "countertop")[1][2]
        _rests_on(scene, "countertop", counter)
    finally:
        scene.world.close()


def test_the_pr2_takes_the_bowl_from_a_drawer_to_the_table_in_pycrams_apartment() -> None:
    scene = _scene("apartment", "pr2", APARTMENT_DRAWER, (-0.1, 0.0), (1.3, 2.25, 0.0))
    try:
        result = _transport(scene, TABLE)
        _went_as_planned(result, APARTMENT_DRAWER)
        joints = scene.world.joint_states(scene.environment)
        assert joints[f"{APARTMENT_DRAWER}_joint"] == pytest.approx(0.0, abs=0.01)
        _rests_on(scene, TABLE, TABLE_TOP)
    finally:
        scene.world.close()
